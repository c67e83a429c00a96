//! TEST `depth_step_monotone` (driver-only: not a Kani proof) — G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST, G78.DEPTHMODE.
//!
//! **Property.** For all legal parameters (Δd = `first_cut` 1…N, Δdmin = `min_cut` 0…N,
//! T = `target` = k − d 1…N, N = 999 999 999, degressive or constant) and every reachable rough
//! pass `prev` at any pass number n (1 ≤ n < 2^32 − 1), `next(p, prev)`
//!
//! - is `None` exactly when `prev` is the last pass;
//! - otherwise is pass n + 1 with depth ≥ `prev.depth`, strictly greater when Δdmin ≥ 1
//!   (or in constant mode), depth ≤ T, `last` exactly when depth = T;
//! - and equals the register's closed form at n + 1 (below), including the rule it names
//!   (G76.DEPTH.1 before the switch, G76.DEPTH.MIN from it, G78.DEPTHMODE in constant mode,
//!   G76.DEPTH.LAST when clamped) — so the whole `Rough` is determined, which the induction
//!   below needs.
//!
//! **How `prev` at an arbitrary n is built without iterating.** The register's closed form of
//! pass n (docs/INTERPRETATION.md, "Depth schedule"): with s the switch pass of G76.DEPTH.MIN
//! ([`crate::model::switch_pass`], closed form, computed here independently), the exact depth is
//! √n·Δd for n < s and √(s−1)·Δd + (n − s + 1)·Δdmin from s on (n·Δd in constant mode), rounded
//! half up, clamped to T where it reaches T. Before the switch (and in constant mode)
//! `cycle_impl::schedule::Schedule::next` depends on `prev.n` only (documented: "before the switch the
//! depth is recomputed from n"), so pass n is taken from the API itself — `first(p)` for n = 1,
//! else `next(p, ·)` of a pass n − 1 — and the harness *checks* it against the exact bracket of
//! √n·Δd (no root taken: r(r−1) < n·Δd² ≤ r(r+1)). From the switch on, pass n is the closed
//! form. Reachability (pass n − 1 was not the last) is an assumption.
//!
//! **Induction.** Base: pass 1 is `first(p)`, checked against the closed form (case n = 1, in
//! every regime: before the switch, from the switch when Δd < Δdmin, constant).
//! Step: if the API's pass n equals the closed form at n, the API's pass n + 1 is
//! `next(p, closed form at n)`, which this harness checks against the closed form at n + 1
//! and for monotonicity. Hence every reachable pass equals the closed form, and every step of
//! every schedule is monotone — for all n, not only the first few.
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 ran out of memory (10–13 GB) in symbolic execution (3 M steps, issue #25): the closed form it checks rests on nonlinear identities of 30- to 120-bit values (squares, a²/c²) that no SAT encoding decides in useful time. `depth_step_clamp` (the shape of every step, also a TEST) did not finish under Kani either; the closed form and monotonicity are z3's (smt/ lemmas 01–12) and this body's drivers'. The body runs under `cargo test` (bounded-exhaustive and random
//! drivers); its Kani harness (the scope named `KANI` below) is a proof harness only with the
//! feature `kani-attempts`.
//!
//! **Kani bounds of the attempt.** Everything is symbolic over the full legal ranges. The loops are the
//! switch pass's binary search in `cycle_impl::schedule` (at most 33 iterations, and only for
//! words beyond 2^31) and the root's walk over at most 4 candidates, so `#[kani::unwind(65)]`.
//! Our own model is loop-free.

use crate::model::{depth_square, is_sqrt_round, sqrt_round_at_least, switch_pass};
use crate::schedule::Schedule;
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::schedule::{Rough, ScheduleParams};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::Rule;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest Δd, Δdmin, T (N for the proof).
    pub max_len: i64,
    /// Largest pass number n of `prev`.
    pub max_n: u32,
}

/// The legal ranges: what Kani proves and the random driver samples.
pub const FULL: Scope = Scope { max_len: MAX_LENGTH, max_n: u32::MAX - 1 };

/// Pass n as the API makes it from pass number alone (valid before the switch and in constant
/// mode, where `next` reads only `prev.n`).
fn api_pass<Sch: Schedule>(sch: &Sch, p: &ScheduleParams, n: u32) -> Option<Rough> {
    if n == 1 {
        Some(sch.first(p))
    } else {
        let before = Rough { n: n - 1, depth: 0, last: false, rule: Rule::G76Depth1 };
        sch.next(p, &before)
    }
}

/// The register's pass n before the switch: `depth` is round(√n·Δd) clamped to T, named
/// G76.DEPTH.1 (G76.DEPTH.LAST when clamped).
fn matches_sqrt_form(r: &Rough, n: u32, p: &ScheduleParams) -> bool {
    let sq = depth_square(n, p.first_cut);
    let t = p.target as u128;
    let reaches = sqrt_round_at_least(sq, t);
    r.n == n
        && r.last == reaches
        && if reaches {
            r.depth == p.target && r.rule == Rule::G76DepthLast
        } else {
            r.depth >= 0 && is_sqrt_round(r.depth as u128, sq) && r.rule == Rule::G76Depth1
        }
}

/// The register's pass with exact (integer) depth `exact`: clamped to T; named `rule`
/// (G76.DEPTH.LAST when clamped).
fn matches_exact(r: &Rough, n: u32, exact: u128, t: i64, rule: Rule) -> bool {
    let reaches = exact >= t as u128;
    r.n == n
        && r.last == reaches
        && if reaches { r.depth == t && r.rule == Rule::G76DepthLast } else { r.depth as u128 == exact && r.rule == rule }
}

/// The harness body (see the module documentation).
pub fn body<S: Source, Sch: Schedule>(src: &mut S, sch: &Sch, scope: &Scope) -> Outcome {
    let first_cut = src.bounded_i64(1, scope.max_len);
    let min_cut = src.bounded_i64(0, scope.max_len);
    let target = src.bounded_i64(1, scope.max_len);
    let constant = src.bool();
    let p = ScheduleParams { first_cut, min_cut, target, constant };
    let t = target as u128;
    let s = if constant { None } else { switch_pass(first_cut, min_cut) };

    // Which n: small, around the switch, or anywhere. All three are subsets of 1..=max_n; the
    // split only steers the concrete drivers towards reachable passes.
    let n = match src.choose(3) {
        0 => src.bounded_u32(1, scope.max_n.min(64)),
        1 => {
            let sw = s.unwrap_or(0);
            src.assume(sw != 0)?;
            let off = src.bounded_u32(0, 3);
            (i64::from(sw) + i64::from(off) - 2).clamp(1, i64::from(scope.max_n)) as u32
        }
        _ => src.bounded_u32(1, scope.max_n),
    };

    // prev: the reachable pass n.
    let prev = if constant {
        // G78.DEPTHMODE 0: exact depth n·Δd.
        src.assume(n == 1 || u128::from(n - 1) * (first_cut as u128) < t)?;
        let r = api_pass(sch, &p, n);
        check!(src, r.is_some(), "the API makes pass n from n alone (constant mode)");
        let r = r.unwrap_or(Rough { n, depth: 0, last: false, rule: Rule::G78DepthMode });
        check!(src, matches_exact(&r, n, u128::from(n) * first_cut as u128, target, Rule::G78DepthMode), "G78.DEPTHMODE: pass n has depth n·Δd clamped to T");
        r
    } else if s.is_none_or(|s| n < s) {
        // Before the switch: round(√n·Δd), from the API, checked against the bracket.
        if n > 1 {
            let before = api_pass(sch, &p, n - 1);
            src.assume(before.is_some_and(|b| !b.last))?;
        }
        let r = api_pass(sch, &p, n);
        check!(src, r.is_some(), "the API makes pass n from n alone (before the switch)");
        let r = r.unwrap_or(Rough { n, depth: 0, last: false, rule: Rule::G76Depth1 });
        check!(src, matches_sqrt_form(&r, n, &p), "G76.DEPTH.1: pass n has depth round(√n·Δd) clamped to T");
        r
    } else {
        // From the switch pass s on: round(√(s−1)·Δd) + (n − s + 1)·Δdmin.
        let s = s.unwrap_or(1);
        let base = if s == 1 {
            0
        } else {
            let b = api_pass(sch, &p, s - 1);
            src.assume(b.is_some_and(|b| !b.last))?;
            let b = b.unwrap_or(Rough { n: s - 1, depth: 0, last: false, rule: Rule::G76Depth1 });
            check!(src, matches_sqrt_form(&b, s - 1, &p), "G76.DEPTH.1: the pass before the switch has depth round(√(s−1)·Δd)");
            b.depth as u128
        };
        let dmin = min_cut as u128;
        // Pass n − 1 (if at or after s) was not the last.
        src.assume(n == s || base + u128::from(n - s) * dmin < t)?;
        let exact = base + u128::from(n - s + 1) * dmin;
        let last = exact >= t;
        let depth = if last { target } else { exact as i64 };
        let rule = if last { Rule::G76DepthLast } else { Rule::G76DepthMin };
        let r = Rough { n, depth, last, rule };
        if n == 1 {
            // The induction's base when the minimum applies from the first pass (Δd < Δdmin).
            check!(src, sch.first(&p) == r, "G76.DEPTH.MIN: with Δd < Δdmin the first pass is Δdmin deep");
        }
        r
    };

    let next = sch.next(&p, &prev);
    if prev.last {
        check!(src, next.is_none(), "G76.DEPTH.LAST: no rough pass after the last one");
        cover!(src, true, "prev is the last rough pass");
        return Ok(());
    }
    check!(src, next.is_some(), "G76.DEPTH.LAST: a pass that is not the last has a successor");
    let Some(next) = next else { return Ok(()) };

    check!(src, next.n == prev.n + 1, "pass numbers count up by one");
    check!(src, next.depth >= prev.depth, "G76.DEPTH: rough depths never decrease");
    if min_cut >= 1 || constant {
        check!(src, next.depth > prev.depth, "G76.DEPTH.MIN: with Δdmin ≥ 1 rough depths strictly increase");
    }
    check!(src, next.depth <= target, "G76.DEPTH.LAST: no rough depth beyond k − d");
    check!(src, next.last == (next.depth == target), "G76.DEPTH.LAST: the last rough pass is exactly the one at k − d");

    // The closed form at n + 1.
    let m = n + 1;
    let ok = if constant {
        matches_exact(&next, m, u128::from(m) * first_cut as u128, target, Rule::G78DepthMode)
    } else {
        match s {
            Some(s) if m >= s => {
                // At or after the switch: the base is pass s − 1's unclamped depth.
                let base = if s == 1 {
                    0
                } else if m == s {
                    prev.depth as u128
                } else {
                    // prev (= pass m − 1 ≥ s) is base + (m − 1 − s + 1)·Δdmin.
                    (prev.depth as u128) - u128::from(m - s) * min_cut as u128
                };
                matches_exact(&next, m, base + u128::from(m - s + 1) * min_cut as u128, target, Rule::G76DepthMin)
            }
            _ => matches_sqrt_form(&next, m, &p),
        }
    };
    check!(src, ok, "G76.DEPTH.1/.MIN/.LAST, G78.DEPTHMODE: pass n + 1 is the register's closed form, naming its rule");

    cover!(src, !constant && s.is_some_and(|s| m == s), "the step into the minimum-cut regime");
    cover!(src, !constant && s.is_some_and(|s| m > s), "a step within the minimum-cut regime");
    cover!(src, !constant && s.is_none_or(|s| m < s), "a step before the switch");
    cover!(src, next.last, "a step onto the last rough pass");
    cover!(src, constant, "constant depth mode");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = depth_step_monotone in crate::PROPERTIES {
        rules: ["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE"],
        states: "Every reachable pass n of the production schedule is the register's closed form (round(√n·Δd) before the switch pass, + Δdmin from it, n·Δd in constant mode, clamped at k − d), and each step is monotone.",
        body: |src, scope| body(src, &crate::schedule::Production, &scope),
        /// The Kani attempt (a TEST: out of memory; built as a harness only with `kani-attempts`).
        kani: test(FULL) { unwind: 65, why: "out of memory (10–13 GB) in symbolic execution, 3 M steps" },
        tests {
            /// Small scope: Δd, Δdmin, T take their 4 smallest and 4 largest legal values, n its
            /// smallest and largest; every combination.
            fn depth_step_monotone_exhaustive = exhaustive(4, 200_000) on FULL;
            /// The whole small cube Δd, Δdmin, T ≤ 12, n ≤ 64 (all values, no edge sampling).
            fn depth_step_monotone_exhaustive_small_cube = exhaustive(64, 2_000_000) on Scope { max_len: 12, max_n: 64 };
            fn depth_step_monotone_random = random(0x5eed_0001, 1) on FULL;
        }
    }
}
