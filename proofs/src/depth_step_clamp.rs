//! TEST `depth_step_clamp` (driver-only: not a Kani proof) — G76.DEPTH.LAST, G76.DEPTH.MIN,
//! G78.DEPTHMODE, PRJ.MAXPASS: the shape of every step of the production depth schedule, over
//! the full legal ranges.
//!
//! **Not a Kani proof.** Written for Kani (the stubs below), but Kani 0.61.0 / CBMC 6.4.0 reached
//! no verdict here: with the pass count, none in 300 s (1.55 M variables, 8.2 M clauses); without
//! it ([`KANI`]), none in 480 s (0.85 M variables, 4.4 M clauses). So its Kani harness is a proof
//! harness only with `kani-attempts`; the drivers run it, and the stubs are kept for the next attempt (e.g. contracts on `Schedule::new`).
//!
//! **Property.** For all legal Δd (1…N), Δdmin (0…N), T = k − d (1…N), N = 999 999 999,
//! degressive or constant, and every pass `prev` the schedule can be asked about — any pass
//! number n (1 ≤ n ≤ 2^32 − 1), any depth 0 ≤ depth < T, not last — or the first pass:
//!
//! - `next(prev)` is `None` exactly when n + 1 does not fit a pass number (n = 2^32 − 1), and
//!   `None` after a last pass (any depth);
//! - otherwise pass n + 1 with 1 ≤ depth ≤ T and `last` ⇔ depth = T ⇔ rule G76.DEPTH.LAST (the
//!   clamp at T = k − d);
//! - a G76.DEPTH.MIN step adds exactly Δdmin to the previous depth (Δdmin ≥ 1, degressive
//!   mode): the running form of √(s−1)·Δd + (n − s + 1)·Δdmin;
//! - a G78.DEPTHMODE step (constant mode only, the only rule there besides the clamp) is
//!   exactly (n + 1)·Δd; a G76.DEPTH.1 step occurs in degressive mode only;
//! - `first` is pass 1 of the same shape, from depth 0;
//! - `rough_pass_count(limit)` is at most `limit` when `Some`, and the same count for every
//!   larger limit.
//!
//! **What this harness does not prove (left to the z3 lemmas in `smt/` and to the drivers).**
//! Which rule applies at which n (the closed-form switch pass s and the pass `reach` where the
//! root reaches T) and the value of a G76.DEPTH.1 depth (the rounded root of n·Δd²) rest on
//! nonlinear identities (squares, products and quotients of 30- to 120-bit values) that a SAT
//! solver cannot bit-blast in useful time (measured here: x ≤ y ⇒ x² − x ≤ y² + y for 31-bit
//! x, y did not finish in 600 s; (r + 1)² = r² + 2r + 1 for 32-bit r not in 90 s). z3 proves
//! them over the integers (smt/ lemmas 01–13); `depth_step_monotone`, `depth_bounds` and
//! `schedule_spec` run them against the production code under `cargo test`.
//!
//! **Stubs.** `cycle_impl::fixed::isqrt` (core's integer square root, whose staged algorithm
//! bit-blasts to millions of clauses) is replaced by its specification [`isqrt_spec`]: any r
//! with r² ≤ n < (r + 1)². That is a trusted assumption about core (tested by the drivers and
//! `impl`'s unit tests), not a Kani proof. `cycle_impl::schedule::switch_search` (the binary
//! search of the switch pass for words beyond 2^31, a 33-step loop over 256-bit products) is
//! replaced by [`unreachable_for_legal_words`], which *asserts* that it is never called: the
//! verdict SUCCESSFUL would therefore also prove that the stub loses nothing on the legal ranges.
//!
//! **Intended Kani bounds.** All symbolic over the full legal ranges. The loops left are the root's walk
//! over at most 4 candidates and `u32::try_from`-style helpers: `#[kani::unwind(5)]`.

use crate::schedule::Schedule;
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::schedule::{Rough, ScheduleParams};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::Rule;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest Δd, Δdmin, T.
    pub max_len: i64,
    /// Largest pass number of `prev`.
    pub max_n: u32,
    /// Whether to check `rough_pass_count` too (the drivers do; under Kani its subtraction
    /// T − round(√((s−1)·Δd²)) can only be shown not to underflow by the nonlinear lemma
    /// smt/11, so Kani leaves it out).
    pub count: bool,
}

/// What the drivers check: the legal ranges, every pass number, the count.
pub const FULL: Scope = Scope { max_len: MAX_LENGTH, max_n: u32::MAX, count: true };

/// What Kani proves: the same without the count.
pub const KANI: Scope = Scope { count: false, ..FULL };

/// Whether `r` has the shape every pass must have: pass `n`, depth in 1…T, last exactly at T
/// and then named G76.DEPTH.LAST; a G76.DEPTH.MIN depth is `before` + Δdmin; a G78.DEPTHMODE
/// depth n·Δd; G76.DEPTH.1 and G76.DEPTH.MIN only in degressive mode, G78.DEPTHMODE only in
/// constant mode.
fn shaped(r: &Rough, n: u32, before: i64, p: &ScheduleParams) -> [bool; 5] {
    let t = p.target;
    let rule_ok = match r.rule {
        Rule::G76DepthLast => r.last,
        Rule::G76DepthMin => !p.constant && p.min_cut >= 1 && !r.last && r.depth == before + p.min_cut,
        Rule::G78DepthMode => p.constant && !r.last && i128::from(r.depth) == i128::from(n) * i128::from(p.first_cut),
        Rule::G76Depth1 => !p.constant && !r.last,
        _ => false,
    };
    [r.n == n, 1 <= r.depth && r.depth <= t, r.last == (r.depth == t), r.last == (r.rule == Rule::G76DepthLast), rule_ok]
}

/// The harness body (see the module documentation).
pub fn body<S: Source, Sch: Schedule>(src: &mut S, sch: &Sch, scope: &Scope) -> Outcome {
    let first_cut = src.bounded_i64(1, scope.max_len);
    let min_cut = src.bounded_i64(0, scope.max_len);
    let target = src.bounded_i64(1, scope.max_len);
    let constant = src.bool();
    let p = ScheduleParams { first_cut, min_cut, target, constant };

    let (got, n, before) = match src.choose(3) {
        0 => (Some(sch.first(&p)), 1, 0),
        1 => {
            // After a last pass: nothing, whatever its number and depth.
            let n = src.bounded_u32(1, scope.max_n);
            let depth = src.bounded_i64(0, scope.max_len);
            let prev = Rough { n, depth, last: true, rule: Rule::G76DepthLast };
            check!(src, sch.next(&p, &prev).is_none(), "G76.DEPTH.LAST: no rough pass after the last one");
            return Ok(());
        }
        _ => {
            let n = src.bounded_u32(1, scope.max_n);
            let depth = src.bounded_i64(0, target - 1);
            let rule = if constant { Rule::G78DepthMode } else { Rule::G76Depth1 };
            let prev = Rough { n, depth, last: false, rule };
            let got = sch.next(&p, &prev);
            if n == u32::MAX {
                check!(src, got.is_none(), "no pass after pass number 2^32 − 1");
                return Ok(());
            }
            check!(src, got.is_some(), "a pass that is not the last has a successor");
            (got, n + 1, depth)
        }
    };
    let Some(r) = got else { return Ok(()) };
    let [number, range, last, named, rule] = shaped(&r, n, before, &p);
    check!(src, number, "pass numbers count up by one from 1");
    check!(src, range, "G76.DEPTH.LAST: every rough depth lies in 1…k − d");
    check!(src, last, "G76.DEPTH.LAST: last exactly at depth k − d (the clamp)");
    check!(src, named, "G76.DEPTH.LAST names exactly the clamped pass");
    check!(src, rule, "G76.DEPTH.MIN adds Δdmin; G78.DEPTHMODE is n·Δd; each rule in its mode only");
    if r.rule == Rule::G76DepthMin {
        check!(src, r.depth > before, "G76.DEPTH.MIN: a minimum-cut step strictly deepens");
    }
    cover!(src, r.rule == Rule::G76DepthMin, "a minimum-cut step");
    cover!(src, r.rule == Rule::G76Depth1, "a square-root step");
    cover!(src, r.rule == Rule::G78DepthMode, "a constant step");
    cover!(src, r.last, "a clamped step");

    if !scope.count {
        return Ok(());
    }
    let limit = src.bounded_u32(0, u32::MAX);
    let count = sch.rough_pass_count(&p, limit);
    check!(src, count.is_none_or(|c| 1 <= c && c <= limit), "PRJ.MAXPASS: a count is at most the limit");
    if let Some(c) = count {
        let wider = src.bounded_u32(c, u32::MAX);
        check!(src, sch.rough_pass_count(&p, wider) == Some(c), "PRJ.MAXPASS: the count does not depend on the limit");
    }

    cover!(src, count.is_some(), "a count within the limit");
    Ok(())
}

/// `isqrt`'s specification, as a Kani stub: any r with r² ≤ n < (r + 1)² (r < 2^64).
#[cfg(kani)]
pub fn isqrt_spec(n: u128) -> u128 {
    let r = u128::from(kani::any::<u64>());
    kani::assume(r * r <= n && (r + 1).checked_mul(r + 1).is_none_or(|sq| sq > n));
    r
}

/// The switch-pass search, as a Kani stub that fails when it is called: for legal words the
/// closed form decides the switch pass (a, c < 2^64), so the search must be unreachable.
#[cfg(kani)]
pub fn unreachable_for_legal_words(_a: u128, _c: u128) -> u64 {
    kani::assert(false, "the switch-pass search is unreachable for legal words");
    u64::MAX
}

cycle_harness::property! {
    pub const PROPERTY = depth_step_clamp in crate::PROPERTIES {
        rules: ["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        states: "Every step of the production depth schedule (first, or next of any pass): numbered n + 1, depth in 1…k − d, last exactly at k − d and named G76.DEPTH.LAST, a minimum-cut step adds exactly Δdmin, a constant step is n·Δd, nothing after the last or past pass 2^32 − 1; the pass count is at most the limit and does not depend on it.",
        body: |src, scope| body(src, &crate::schedule::Production, &scope),
        /// The Kani attempt with the two stubs above (a TEST: no verdict; a harness only with `kani-attempts`).
        kani: test(KANI) { unwind: 5, stubs: [cycle_impl::fixed::isqrt => isqrt_spec, cycle_impl::schedule::switch_search => unreachable_for_legal_words], why: "no verdict in 300 s with `rough_pass_count` (1.55 M variables, 8.2 M clauses), none in 480 s without it (0.85 M variables, 4.4 M clauses), `isqrt` and the switch search stubbed" },
        tests {
            /// Δd, Δdmin, T ≤ 6 whole, pass numbers, depths and limits their 3 smallest and largest
            /// values.
            fn depth_step_clamp_exhaustive_small = exhaustive(3, 2_000_000) on Scope { max_len: 6, max_n: 40, count: true };
            /// The edges of the legal ranges.
            fn depth_step_clamp_exhaustive_edges = exhaustive(2, 2_000_000) on FULL;
            fn depth_step_clamp_random = random(0x5eed_0010, 2) on FULL;
        }
    }
}
