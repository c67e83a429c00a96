//! Kani proofs `g162_split_start`, `g162_split_step`, `g162_split_last` (issue #33) — G162.PQ,
//! G162.SPLIT, PRJ.MAXPASS: the passes of the production G162 cycle (`cycle_impl::g162::cycle`,
//! `Cycle::next_event`, which steps its full passes itself and asks `split::next` for the rest)
//! by induction over its passes, one harness per kind of state.
//!
//! **Property.** For every P (thread depth) and Q (allowance) 1…N with P = kQ + D, 0 ≤ D < Q,
//! and every `max_passes` (1…10^6): the register's passes are the full passes 1…k at m·Q (rule
//! G162.PQ, stage 0), then the split targets t(s) = kQ + ⌊(D·e + 4)/8⌋, e = 4, 6, 7, 8 for
//! stages s = 1…4 (D/2, 3D/4, 7D/8, D rounded once half up; t(4) = P), each kept when deeper
//! than the last kept pass (rule G162.SPLIT), numbered on; K = k + (kept targets).
//!
//! - **start** (`g162_split_start`): `cycle` refuses with TOO MANY PASSES on Q (PRJ.MAXPASS)
//!   exactly when K > `max_passes`; `pass_count` is K; an accepted cycle's first event is the
//!   header of pass 1 (index 1, 2·depth on diameter, its rule), and its pass is the register's
//!   pass 1 (Q when k ≥ 1, else t(1)), last exactly when its depth is P;
//! - **step** (`g162_split_step`): from **any** register pass r that is not at P — full pass n
//!   (1 ≤ n ≤ k, symbolic) or kept target s — with its five moves done (`Cycle::at_pass`), the
//!   next event is the header of the register's pass r.n + 1: full pass n + 1 at (n + 1)·Q, or
//!   the first kept target after r; its number is r.n + 1 ≤ K, it is **strictly deeper** than r
//!   and **not past P**, last exactly when at P;
//! - **last** (`g162_split_last`): from the register's pass at P, numbered K, the cycle ends
//!   (`None`, twice).
//!
//! By induction from pass 1 the cycle's passes are the register's 1…K: depths strictly
//! increase, the last is exactly P, and their number K is within `max_passes`.
//!
//! **Two ways through, one body.** The drivers run it through the cycle (`Scope::cycle`:
//! `cycle`, `Cycle::at_pass`, `next_event`, whose own fast path steps the full passes) and
//! through the split's functions (`pass_count`, which `cycle` refuses on, `first`, which it
//! begins with, and `next`). The Kani harnesses take the second: through the cycle, the start
//! alone was 2.5 M variables and 12.2 M clauses (the `Cycle` behind the `Result` of `cycle`,
//! its pass points) and reached no verdict in 900 s (proofs/README.md). The cycle's use of the
//! split — the same passes, its fast path for full passes included — is left to these drivers
//! and impl's `at_pass_is_the_state_after_a_pass`.
//!
//! **Stubs (Kani, `-Z stubbing`).** `split::norm` by the drawn k and D, with the base kQ drawn
//! free of the product (`g162_split::draw_pkd`, `free_base`: a superset of the real (P, Q));
//! `split::target` by `g162_split_target::target_spec` (a Kani proof); `split::full_depth`
//! (m·Q) by a table o(n), o(n + 1) = o(n) + Q ([`full_table`], smt/ lemma 17:
//! `17_g162_full_pass.smt2`; assumed under Kani, checked by the drivers on exact products).
//! The geometry is one fixed accepted G162 block (A = 0, so no tangent product): the passes
//! depend only on P, Q and `max_passes` (the cycle reads them through `split` and `norm` only),
//! and the moves of a pass do not change its pass (`Cycle::at_pass` is that state: impl's
//! `at_pass_is_the_state_after_a_pass`).

use crate::g162_split::{draw_pkd, TailScope};
use crate::peck_parts::trusted;
use crate::source::{bounded_i64_upto, Outcome, Source, Stop};
use crate::{check, cover};
use cycle_impl::g162::{cycle, first, next, pass_count, SplitParams, Step, Words};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{AlarmCode, Config, Event, Pass, PassKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest P and Q.
    pub max_len: i64,
    /// Which states: 0 the start, 1 a pass not at P, 2 the pass at P, 3 any of them.
    pub case: u32,
    /// Through the cycle (`cycle`, `Cycle::at_pass`, `next_event`: the drivers) or through the
    /// split's own functions (`pass_count`, `first`, `next`: the Kani harnesses).
    pub cycle: bool,
}

/// The full legal ranges, every state.
pub const FULL: Scope = Scope { max_len: MAX_LENGTH, case: 3, cycle: true };

/// The Kani harnesses: one per kind of state, on the split's functions.
pub const START: Scope = Scope { case: 0, cycle: false, ..FULL };
pub const STEP: Scope = Scope { case: 1, cycle: false, ..FULL };
pub const LAST: Scope = Scope { case: 2, cycle: false, ..FULL };

/// The full passes' depths o(n) = n·Q and o(n + 1) for a full pass 1 ≤ n ≤ k: drawn under
/// Kani with lemma 17's facts assumed, exact under the drivers (which check those facts).
pub fn full_table<S: Source>(src: &mut S, (q, k, kq): (i64, i64, i64), n: i64, max_len: i64) -> Result<(i64, i64), Stop> {
    let (o0, o1) = if cfg!(kani) {
        let o0 = src.bounded_i64(1, max_len);
        (o0, o0 + q)
    } else {
        (n * q, (n + 1) * q)
    };
    trusted(src, o1 == o0 + q && o0 >= q && (n != 1 || o0 == q), "lemma 17: (m + 1)·Q = m·Q + Q, m·Q ≥ Q, 1·Q = Q")?;
    trusted(src, (o0 <= kq) == (n <= k) && (o1 <= kq) == (n < k), "lemma 17: m·Q ≤ kQ ⇔ m ≤ k")?;
    trusted(src, (o0 == kq) == (n == k) && (o1 == kq) == (n + 1 == k), "lemma 17: m·Q = kQ ⇔ m = k")?;
    Ok((o0, o1))
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let ts = TailScope { max_len: scope.max_len, k_below_quotient: !cfg!(kani) };
    let (q, k, d, kq, p) = draw_pkd(src, &ts)?;
    let max_passes = src.bounded_u32(1, 1_000_000);
    let sp = SplitParams { depth: p, allowance: q };

    // The register's targets t(s) = kQ + ⌊(D·e + 4)/8⌋ (t(0) = kQ), e a constant each.
    let part = |ed: i64| (ed + 4) >> 3;
    let t = [kq, kq + part(4 * d), kq + part(6 * d), kq + part(7 * d), kq + part(8 * d)];
    // Kept when deeper than the last kept pass; numbered on from k; K in all.
    let (mut kept, mut num, mut last_kept, mut count) = ([false; 5], [0i64; 5], kq, k);
    for s in 1..5 {
        kept[s] = d > 0 && t[s] > last_kept;
        if kept[s] {
            last_kept = t[s];
            count += 1;
        }
        num[s] = count;
    }
    if !cfg!(kani) {
        check!(src, (1..5).all(|s| t[s] == crate::g162_split::model::target(kq, d, crate::g162_split::model::EIGHTHS[s - 1])), "the targets are the model's");
    }

    // PRJ.MAXPASS at the cycle's start, on one fixed accepted geometry.
    let w = Words { x: 1000, z: -5000, incremental: false, h: 100, split: Some(sp), v: 10, taper: 40, a: 0, lead: 15_000, b: 0, i: 0, j: 360_000 };
    let mut params = cycle_impl::config::DEFAULTS;
    params.max_passes = max_passes;
    let (start, line) = ((2000, 0), 7);
    let too_many = count > i64::from(max_passes);
    let cy0 = if scope.cycle {
        match cycle(&Config::default(), &params, &w, start, line) {
            Err(al) => {
                check!(src, too_many && (al.code, al.word, al.rule, al.line) == (AlarmCode::TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, line), "PRJ.MAXPASS: refused exactly when K > max_passes, TOO MANY PASSES on Q");
                cover!(src, true, "refused: too many passes");
                return Ok(());
            }
            Ok(cy) => Some(cy),
        }
    } else {
        // What `cycle` refuses on (its step 5): `pass_count` against `max_passes`.
        let want = if too_many { None } else { u32::try_from(count).ok() };
        check!(src, pass_count(&sp, max_passes) == want, "PRJ.MAXPASS: pass_count is K when K ≤ max_passes, None above");
        cover!(src, too_many, "refused: too many passes");
        if too_many {
            return Ok(());
        }
        None
    };
    check!(src, !too_many, "PRJ.MAXPASS: accepted only when K ≤ max_passes");

    let header = |r: Step| Event::Pass(Pass { index: r.n, kind: PassKind::Rough, diameter_depth: r.depth.saturating_mul(2), rule: r.rule });
    let split = |s: usize, n: i64| Step { n: n as u32, depth: t[s], last: t[s] >= p, rule: Rule::G162Split, stage: s as u8 };
    let full = |n: i64, depth: i64| Step { n: n as u32, depth, last: depth >= p, rule: Rule::G162Pq, stage: 0 };
    let mut pos = start;
    let case = if scope.case < 3 { scope.case } else { src.choose(3) };
    if case == 0 {
        check!(src, pass_count(&sp, u32::MAX) == u32::try_from(count).ok(), "PRJ.MAXPASS: pass_count is K");
        let want = if k >= 1 { full(1, q) } else { split(1, 1) };
        let got = match cy0 {
            Some(mut cy) => {
                let got = cy.pass();
                check!(src, cy.next_event(&mut pos) == Some(header(want)), "the cycle begins with pass 1's header");
                got
            }
            None => first(&sp),
        };
        check!(src, got == want, "G162.PQ / G162.SPLIT: pass 1 is Q, or t(1) when Q > P");
        check!(src, want.last == (want.depth == p) && want.depth >= 1 && want.depth <= p, "pass 1 is within P, last exactly at P");
        cover!(src, k == 0, "Q > P: the first pass a split target");
        cover!(src, want.last, "a single pass");
        return Ok(());
    }

    // A register pass r, its five moves done: full pass n (1…k) or kept target s.
    let s = src.choose(5) as usize;
    let (r, o1) = if s == 0 {
        src.assume(k >= 1)?;
        let n = bounded_i64_upto(src, 1, k, scope.max_len)?;
        let (o0, o1) = full_table(src, (q, k, kq), n, scope.max_len)?;
        #[cfg(kani)]
        crate::g162_split::stubs::set_full(n as u32 + 1, q, o1);
        (full(n, o0), o1)
    } else {
        src.assume(kept[s])?;
        (split(s, num[s]), 0)
    };
    let mut cy = cy0.map(|c| c.at_pass(r));
    if case == 2 {
        src.assume(r.last)?;
        check!(src, i64::from(r.n) == count, "the pass at P is pass K");
        let ended = match &mut cy {
            Some(cy) => cy.next_event(&mut pos).is_none() && cy.next_event(&mut pos).is_none(),
            None => next(&sp, &r).is_none(),
        };
        check!(src, ended, "nothing after the pass at P");
        cover!(src, s == 0, "the last pass a full pass (D = 0)");
        cover!(src, (1..4).contains(&s), "the last pass an early target at P (a later one dropped)");
        return Ok(());
    }
    src.assume(!r.last)?;
    let nx = match &mut cy {
        Some(cy) => {
            let ev = cy.next_event(&mut pos);
            check!(src, ev == Some(header(cy.pass())), "the next pass begins with its header");
            Some(cy.pass())
        }
        None => next(&sp, &r),
    };
    check!(src, nx.is_some(), "a pass not at P has a successor");
    let Some(nx) = nx else { return Ok(()) };
    check!(src, nx.n == r.n + 1 && i64::from(nx.n) <= count, "pass numbers count up by one, within K");
    check!(src, nx.depth > r.depth && nx.depth <= p, "depths strictly increase and never pass P");
    check!(src, nx.last == (nx.depth == p), "last exactly at depth P");
    let s2 = usize::from(nx.stage);
    let register = if s2 == 0 {
        s == 0 && i64::from(r.n) < k && nx == full(i64::from(nx.n), o1)
    } else {
        s2 < 5 && s2 > s && kept[s2] && nx == split(s2, num[s2])
    };
    check!(src, register, "the next pass is the register's: full pass n + 1 at (n + 1)·Q, or the first kept target after r");
    cover!(src, s == 0 && s2 == 0, "a full pass to the next");
    cover!(src, s == 0 && s2 >= 1, "the last full pass to the split");
    cover!(src, s >= 1 && s2 > s + 1, "a target dropped");
    Ok(())
}

cycle_harness::property! {
    pub const START_PROPERTY = g162_split_start in crate::PROPERTIES {
        rules: ["G162.PQ", "G162.SPLIT", "PRJ.MAXPASS"],
        states: "The G162 cycle's start (the induction base of g162_split_step; stubs as there): refused with TOO MANY PASSES on Q exactly when K > max_passes, pass_count = K, the first pass the register's pass 1 (Q, or t(1) when Q > P), its header first.",
        body: |src, scope| body(src, &scope),
        /// The Kani proof of the start (`-Z stubbing`: `norm`, `target`, `full_depth`).
        kani: proof(START) { unwind: 6, stubs: [cycle_impl::g162::split::norm => crate::g162_split::stubs::norm_spec, cycle_impl::g162::split::target => crate::g162_split_target::target_spec, cycle_impl::g162::split::full_depth => crate::g162_split::stubs::full_depth_spec], measured: "SUCCESSFUL (1843 checks, 90 unreachable: the other states'; 3/9 covers, 6 unreachable: the other states'), 20.0 s, 0.92 GB" },
        tests {
            fn g162_split_start_random = random(0x5eed_1621, 4) on START, random(0x5eed_1622, 4) on Scope { max_len: 40, case: 0, cycle: true };
        }
    }
}

cycle_harness::property! {
    pub const PROPERTY = g162_split_step in crate::PROPERTIES {
        rules: ["G162.PQ", "G162.SPLIT", "PRJ.MAXPASS"],
        states: "The G162 cycle by induction over its passes (norm, target and m·Q stubbed: draw_pkd, g162_split_target, smt/ lemma 17): from any register pass not at P the next is the register's pass n + 1 (full pass at (n + 1)·Q, or the first kept target), strictly deeper, not past P, last exactly at P, numbered within K; the start and the pass at P (g162_split_start, g162_split_last).",
        body: |src, scope| body(src, &scope),
        /// The Kani proof of a pass not at P (START and LAST: above and below). Unwind 6: the
        /// body's four targets, `pass_count`'s and `split_after`'s ≤ 4, `next_event`'s two turns.
        kani: proof(STEP) { unwind: 6, stubs: [cycle_impl::g162::split::norm => crate::g162_split::stubs::norm_spec, cycle_impl::g162::split::target => crate::g162_split_target::target_spec, cycle_impl::g162::split::full_depth => crate::g162_split::stubs::full_depth_spec], measured: "SUCCESSFUL (1844 checks, 76 unreachable: the other states'; 4/9 covers, 5 unreachable: the other states'), 80.4 s, 0.26 GB" },
        tests {
            /// P, Q ≤ 30 (k ≤ 30 / Q), every state; each draw's 6 smallest and largest values.
            fn g162_split_step_exhaustive = exhaustive(6, 3_000_000) on Scope { max_len: 30, case: 3, cycle: true }, exhaustive(6, 3_000_000) on Scope { max_len: 30, case: 3, cycle: false };
            fn g162_split_step_random = random(0x5eed_1623, 4) on FULL, random(0x5eed_1624, 4) on Scope { max_len: 200, case: 3, cycle: true }, random(0x5eed_1627, 4) on Scope { cycle: false, ..FULL };
        }
    }
}

cycle_harness::property! {
    pub const LAST_PROPERTY = g162_split_last in crate::PROPERTIES {
        rules: ["G162.PQ", "G162.SPLIT", "PRJ.MAXPASS"],
        states: "The G162 cycle's pass at P (the end of g162_split_step's induction; stubs as there): it is pass K, and the cycle ends.",
        body: |src, scope| body(src, &scope),
        /// The Kani proof of the pass at P (unwind as `g162_split_step`).
        kani: proof(LAST) { unwind: 6, stubs: [cycle_impl::g162::split::norm => crate::g162_split::stubs::norm_spec, cycle_impl::g162::split::target => crate::g162_split_target::target_spec, cycle_impl::g162::split::full_depth => crate::g162_split::stubs::full_depth_spec], measured: "SUCCESSFUL (1844 checks, 84 unreachable: the other states'; 3/9 covers, 6 unreachable: the other states'), 23.1 s, 0.25 GB" },
        tests {
            fn g162_split_last_random = random(0x5eed_1625, 4) on LAST, random(0x5eed_1626, 4) on Scope { max_len: 40, case: 2, cycle: true };
        }
    }
}
