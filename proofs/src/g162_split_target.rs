//! Harness `g162_split_target` — G162.SPLIT: the lemma on the G162 split's targets that
//! `g162_split_tail` uses in place of their arithmetic.
//!
//! **Property.** For every Q (1…N), remainder D (1…Q − 1) and base kQ (P = kQ + D ≤ N), and
//! every stage s = 0…3 of the pass before: `next` from a pass of stage s at depth kQ, numbered
//! k (so not a full pass before the last), is pass k + 1 at split target s + 1 — the depth
//! kQ + ⌊(D·e + 4)/8⌋ with e = 4, 6, 7, 8 (D/2, 3D/4, 7D/8, D rounded once half up), rule
//! G162.SPLIT, stage s + 1, last exactly at P. Every target is deeper than kQ (D·e ≥ 4), so the
//! first target after stage s deeper than the previous pass is target s + 1 itself: this is the
//! value of the private `cycle_impl::g162::split::target(norm, s + 1)`, observed through `next`.
//!
//! **The stub it establishes** ([`target_spec`]): `target` of stage 1…4 is
//! (P − D) + ⌊(D·e + 4)/8⌋, written with shifts (no multiplier). `g162_split_tail` stubs
//! `target` by it, as `#[kani::stub_verified]` would use a verified contract (a contract needs
//! an attribute in impl); `target` is only ever called with stages 1…4 (`split_after` ranges
//! over from + 1…4, `pass_count` over 1…4), the stages this lemma covers. Under Kani `norm` is
//! stubbed as in `g162_split_tail` (`free_base`: nothing lost, see there).

use crate::g162_split::{model, TailScope};
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::g162::{next, Norm, SplitParams, Step};
use cycle_vocab::Rule;

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &TailScope) -> Outcome {
    let (q, k, d, kq, p) = crate::g162_split::draw_pkd(src, scope)?;
    src.assume(d > 0)?;
    let sp = SplitParams { depth: p, allowance: q };
    for (s, e) in model::EIGHTHS.into_iter().enumerate() {
        let prev = Step { n: k as u32, depth: kq, last: false, rule: Rule::G162Split, stage: s as u8 };
        let want = model::target(kq, d, e);
        let nx = next(&sp, &prev);
        check!(
            src,
            nx == Some(Step { n: k as u32 + 1, depth: want, last: want == p, rule: Rule::G162Split, stage: s as u8 + 1 }),
            "G162.SPLIT: after stage s at kQ comes target s + 1, kQ + ⌊(D·e + 4)/8⌋"
        );
        check!(src, model::is_rounded_target(want, kq, d, e), "each target is its exact value rounded once half up");
        check!(src, target_spec(&Norm { p: p as u64, q: q as u64, k: k as u64, d: d as u64 }, s as u8 + 1) == Some(want as u64), "the stub's value is the target");
    }
    cover!(src, k == 0, "Q > P");
    cover!(src, k > 0, "after full passes");
    Ok(())
}

/// `cycle_impl::g162::split::target` of stages 1…4 as this lemma establishes it: (P − D) +
/// ⌊(D·e + 4)/8⌋, e·D by shifts (D < 2^30: nothing overflows); `None` for other stages, as the
/// real function (never asked for them).
pub fn target_spec(q: &Norm, stage: u8) -> Option<u64> {
    let d = q.d;
    let ed = match stage {
        1 => d << 2,
        2 => (d << 2) + (d << 1),
        3 => (d << 3) - d,
        4 => d << 3,
        _ => return None,
    };
    Some((q.p - q.d) + ((ed + 4) >> 3))
}

cycle_harness::property! {
    pub const PROPERTY = g162_split_target in crate::PROPERTIES {
        rules: ["G162.SPLIT"],
        states: "The G162 split's targets (the lemma g162_split_tail's stub of `target` rests on): after a pass of stage s at kQ comes target s + 1 at kQ + ⌊(D·e + 4)/8⌋, e = 4, 6, 7, 8 (rounded once half up), last exactly at P.",
        body: |src, scope| body(src, &scope),
        /// The Kani proof (`-Z stubbing`: `norm` as in `g162_split_tail`).
        kani: proof(crate::g162_split::TAIL_KANI) { unwind: 5, stubs: [cycle_impl::g162::split::norm => crate::g162_split::stubs::norm_spec], measured: "SUCCESSFUL (602 checks, 2 unreachable; 2/2 covers), 103.0 s, 0.91 GB" },
        tests {
            /// P, Q ≤ 40 (k ≤ 40 / Q); each draw's 6 smallest and largest values.
            fn g162_split_target_exhaustive = exhaustive(6, 2_000_000) on TailScope { max_len: 40, k_below_quotient: true };
            fn g162_split_target_random = random(0x5eed_0165, 2) on crate::g162_split::TAIL_FULL;
        }
    }
}
