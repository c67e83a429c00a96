//! Harness `schedule_step` — G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST, G78.DEPTHMODE: the
//! induction step of the depth schedule, on a *symbolic* schedule (`schedule_parts`).
//!
//! **Property.** For legal Δd (1…N), Δdmin (0…N), T = k − d (1…N), N = 999 999 999, either
//! mode, and a schedule with those words and any reach and switch passes related to the depths
//! as z3 proves (`schedule_parts::spec`), call a pass `prev` = (n, depth) *admissible* when it
//! is not last, 0 ≤ depth < T and, before the switch pass (n < s), n is below the reach pass
//! and depth is the unclamped depth u(n) (round(√(n·Δd²)), resp. n·Δd) — from s on any depth
//! below T. Then:
//!
//! - after a last pass `next` is `None`; from pass 2^32 − 1 it is `None`; else pass n + 1;
//! - its depth lies in 1…T; `last` ⇔ depth = T ⇔ rule G76.DEPTH.LAST (the clamp at k − d);
//! - it is never shallower than `prev`, strictly deeper when Δdmin ≥ 1, in constant mode, and
//!   when it is the last (G76.DEPTH.LAST);
//! - a cut that is not the last is ≥ Δdmin (degressive), exactly Δdmin from the switch pass on
//!   (G76.DEPTH.MIN, the running form), exactly Δd in constant mode (G78.DEPTHMODE);
//! - each rule only where it belongs (G76.DEPTH.MIN: degressive, Δdmin ≥ 1, n + 1 ≥ s;
//!   G76.DEPTH.1: degressive before s; G78.DEPTHMODE: constant mode);
//! - a pass that is not last is admissible again (the induction step), and `first` is pass 1,
//!   admissible unless last, of depth min(Δd, T) (min(Δdmin, T) when s = 1).
//!
//! Every pass the schedule produces is therefore admissible (induction from `first`), and the
//! step properties hold between any two consecutive passes of every schedule: never decreasing,
//! strictly increasing with Δdmin ≥ 1, never beyond k − d, the last exactly k − d, every cut but
//! the last ≥ Δdmin — what smt/ lemma 12 states of the register's model, here of the code.
//!
//! **What is trusted (Kani).** `Schedule::from_parts` replaces `Schedule::new`: that new's
//! parts have that shape and its switch pass is lemma 07's s is checked by the drivers here
//! (`schedule_parts::schedule`) and impl's tests; reach is tied to the depths only through the
//! table's assumptions. `root_depth` and `constant_depth` are stubbed by lookups in a table of
//! u(n₀), u(n₀ + 1) (`schedule_parts::stubs`, asserting that no other pass is asked for) whose
//! assumptions are z3 lemmas 01, 02–04, 05 + 11, 07, 09 (and (n + 1)·Δd = n·Δd + Δd); the
//! drivers check every one against the model's exact values. That root_depth is round(√(nΔd²))
//! for any guess: impl's `root_with_any_guess_is_the_rounded_root`, lemmas 01–02, the drivers.
//!
//! **Left to z3 and the drivers.** The values of the roots and of the reach and switch passes
//! (nonlinear: a bit-blasted product or root does not finish, proofs/README.md), the pass count
//! (`rough_pass_count`; smt/ lemma 11, `depth_bounds`), the running form's closed form (lemma 08).

use crate::schedule_parts::{schedule, table};
use crate::source::{bounded_i64_upto, Outcome, Source};
use crate::{check, cover};
use cycle_impl::schedule::{Parts, Rough};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::Rule;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest Δd, Δdmin, T.
    pub max_len: u64,
    /// Largest pass number of `prev`.
    pub max_n: u32,
}

/// The legal words, every pass number: what Kani proves and the random driver samples.
pub const FULL: Scope = Scope { max_len: MAX_LENGTH as u64, max_n: u32::MAX };

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let dd = src.bounded_u64(1, scope.max_len);
    let dmin = src.bounded_u64(0, scope.max_len);
    let target = src.bounded_u64(1, scope.max_len);
    let constant = src.bool();
    let sch = schedule(src, dd, dmin, target, constant)?;
    let Parts { reach, switch, .. } = sch.parts();
    let t = target as i64;

    let (before, q, tab) = match src.choose(3) {
        0 => {
            let tab = table(src, &sch, 1)?;
            let q = sch.first();
            check!(src, q.n == 1, "the first pass is pass 1");
            let first = if switch == 1 { dmin } else { dd };
            check!(src, q.depth == first.min(target) as i64, "pass 1 is Δd deep (Δdmin when s = 1), clamped at k − d");
            (0, q, tab)
        }
        1 => {
            // After a last pass: nothing, whatever its number and depth.
            let n = src.bounded_u32(1, scope.max_n);
            let depth = src.bounded_i64(0, scope.max_len as i64);
            let prev = Rough { n, depth, last: true, rule: Rule::G76DepthLast };
            check!(src, sch.next(&prev).is_none(), "G76.DEPTH.LAST: no rough pass after the last one");
            return Ok(());
        }
        _ => {
            let n = src.bounded_u32(1, scope.max_n);
            let tab = table(src, &sch, n)?;
            // An admissible pass n (the schedule reads neither its rule nor, before the
            // switch, its depth other than as a guess).
            let depth = if u64::from(n) < switch {
                src.assume(u64::from(n) < reach)?;
                tab.depth(n, constant) as i64
            } else {
                bounded_i64_upto(src, 0, t - 1, scope.max_len as i64)?
            };
            src.assume(depth < t)?;
            let prev = Rough { n, depth, last: false, rule: Rule::G76Depth1 };
            let got = sch.next(&prev);
            let Some(m) = n.checked_add(1) else {
                check!(src, got.is_none(), "no pass after pass number 2^32 − 1");
                return Ok(());
            };
            let Some(q) = got else {
                check!(src, false, "a pass that is not the last has a successor");
                return Ok(());
            };
            check!(src, q.n == m, "pass numbers count up by one");
            (depth, q, tab)
        }
    };

    let at = u64::from(q.n);
    let cut = q.depth - before;
    check!(src, 1 <= q.depth && q.depth <= t, "G76.DEPTH.LAST: every rough depth lies in 1…k − d");
    check!(src, q.last == (q.depth == t), "G76.DEPTH.LAST: last exactly at depth k − d (the clamp)");
    check!(src, q.last == (q.rule == Rule::G76DepthLast), "G76.DEPTH.LAST names exactly the clamped pass");
    check!(src, cut >= 0, "the depth never decreases");
    check!(src, cut > 0 || !(constant || dmin >= 1 || q.last), "strictly deeper with Δdmin ≥ 1, in constant mode, and at the last pass");
    let least = if constant { dd } else { dmin };
    check!(src, q.last || cut >= least as i64, "every cut but the last is ≥ Δdmin (Δd in constant mode)");
    match q.rule {
        Rule::G76DepthMin => {
            check!(src, !constant && dmin >= 1 && at >= switch, "G76.DEPTH.MIN only in degressive mode with Δdmin ≥ 1, from the switch pass on");
            check!(src, cut == dmin as i64, "G76.DEPTH.MIN: a minimum cut adds exactly Δdmin");
        }
        Rule::G76Depth1 => check!(src, !constant && at < switch, "G76.DEPTH.1 only in degressive mode, before the switch pass"),
        Rule::G78DepthMode => check!(src, constant && cut == dd as i64, "G78.DEPTHMODE only in constant mode, each pass Δd deeper"),
        Rule::G76DepthLast => {}
        _ => check!(src, false, "a rough pass names a depth rule"),
    }
    // The induction step: a pass that is not last is admissible.
    let admissible = at >= switch || (at < reach && q.depth as u128 == tab.depth(q.n, constant));
    check!(src, q.last || admissible, "a pass that is not last is admissible (before s: below reach, depth u(n))");

    cover!(src, q.rule == Rule::G76DepthMin, "a minimum-cut step");
    cover!(src, q.rule == Rule::G76Depth1 && q.n >= 2, "a square-root step");
    cover!(src, q.rule == Rule::G76Depth1 && cut == 0, "a square-root step of no depth (Δdmin = 0)");
    cover!(src, q.rule == Rule::G78DepthMode && q.n >= 2, "a constant step");
    cover!(src, q.last && q.n >= 2, "a clamped step");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = schedule_step in crate::PROPERTIES {
        rules: ["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE"],
        states: "The induction step of the production depth schedule on a symbolic schedule (from_parts; root_depth and constant_depth stubbed by two depths whose assumptions are z3 lemmas 01-05, 07, 09, 11, checked by the drivers): the next pass of an admissible pass is pass n + 1, depth in 1…k − d, last exactly at k − d and named G76.DEPTH.LAST, never shallower, strictly deeper with Δdmin ≥ 1, in constant mode and at the last, every cut but the last ≥ Δdmin (exactly Δdmin from the switch pass, Δd in constant mode), admissible again; pass 1 is min(Δd, k − d).",
        body: |src, scope| body(src, &scope),
        /// Kani: the step over the legal words and every pass number, on a symbolic schedule. Unwind
        /// 10: the only loop is over `spec`'s eight assumptions.
        kani: proof(FULL) { unwind: 10, stubs: [cycle_impl::schedule::root_depth => crate::schedule_parts::stubs::root_depth_spec, cycle_impl::schedule::constant_depth => crate::schedule_parts::stubs::constant_depth_spec], measured: "SUCCESSFUL (684 checks, 2 unreachable; 5/5 covers), 12.2 s, 0.41 GB" },
        tests {
            /// Δd, Δdmin, T ≤ 6 whole, pass numbers ≤ 40 and depths their 4 smallest and largest.
            fn schedule_step_exhaustive_small = exhaustive(4, 2_000_000) on Scope { max_len: 6, max_n: 40 };
            /// The edges of the legal ranges and of the pass numbers.
            fn schedule_step_exhaustive_edges = exhaustive(2, 2_000_000) on FULL;
            /// The full ranges; and pass numbers ≤ 200, where most passes are before the switch.
            fn schedule_step_random = random(0x5eed_0031, 4) on FULL, random(0x5eed_0032, 4) on Scope { max_len: MAX_LENGTH as u64, max_n: 200 };
        }
    }
}
