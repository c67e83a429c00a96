//! TEST `depth_bounds` (driver-only: not a Kani proof) — G76.DEPTH.LAST, G76.DEPTH.MIN, G78.DEPTHMODE, PRJ.MAXPASS.
//!
//! **Property.** For all legal parameters (Δd 1…N, Δdmin 0…N, T = k − d 1…N, degressive or
//! constant) and every pass limit `limit` ≤ K, iterating the schedule from `first(p)` for up
//! to K + 1 passes:
//!
//! - pass numbers are 1, 2, 3, …; every rough depth is in 1…T (G76.DEPTH.LAST);
//! - a pass is `last` exactly when its depth is T, and `next` after it is `None`;
//! - depths never decrease, and every cut (depth minus the previous depth, the first cut
//!   measured from 0) except the last is ≥ Δdmin (G76.DEPTH.MIN; degressive mode) or exactly
//!   Δd (G78.DEPTHMODE 0);
//! - `rough_pass_count(p, limit)` is `Some(c)` where c is the number of passes iterated, when
//!   c ≤ limit, and `None` exactly when the schedule has more than `limit` passes (PRJ.MAXPASS).
//!
//! Whole schedules are unbounded (up to ~10^18 passes for Δdmin = 0), so the iteration stops
//! after K + 1 passes; since `limit` ≤ K, the count's `None` case is decided by then.
//! `depth_step_monotone` covers every pass number by induction; this harness adds the
//! whole-sequence view (cuts, the last depth, the count) over the first K + 1 passes.
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 ran out of memory (10–13 GB) in symbolic execution (issue #25), for the reasons of `depth_step_monotone`. The per-step shape is the TEST `depth_step_clamp`; the whole-sequence view and the pass count are z3's (smt/ lemmas 11, 12) and this body's drivers'. The body runs under `cargo test` (bounded-exhaustive and random
//! drivers); its Kani harness (the scope named `KANI` below) is a proof harness only with the
//! feature `kani-attempts`.
//!
//! **Kani bounds of the attempt.** K = [`KANI`]`.max_passes` = 4: the harness loop runs at most K + 1 = 5
//! times; the switch pass's binary search (only for words beyond 2^31, outside the legal
//! ranges) at most 33; `isqrt` is loop-free. So `#[kani::unwind(65)]` covers every loop. Parameters are symbolic over the full legal
//! ranges.

use crate::schedule::Schedule;
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::schedule::ScheduleParams;
use cycle_impl::MAX_LENGTH;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest Δd, Δdmin, T.
    pub max_len: i64,
    /// K: the largest `limit`; the iteration examines K + 1 passes.
    pub max_passes: u32,
}

/// What Kani proves: full legal ranges, K = 4.
pub const KANI: Scope = Scope { max_len: MAX_LENGTH, max_passes: 4 };

/// The harness body (see the module documentation).
pub fn body<S: Source, Sch: Schedule>(src: &mut S, sch: &Sch, scope: &Scope) -> Outcome {
    let first_cut = src.bounded_i64(1, scope.max_len);
    let min_cut = src.bounded_i64(0, scope.max_len);
    let target = src.bounded_i64(1, scope.max_len);
    let constant = src.bool();
    let limit = src.bounded_u32(0, scope.max_passes);
    let p = ScheduleParams { first_cut, min_cut, target, constant };

    let mut r = sch.first(&p);
    let mut previous_depth = 0i64;
    let mut count = 1u32;
    let mut finished = false;
    // At most K + 1 passes.
    while count <= scope.max_passes + 1 {
        check!(src, r.n == count, "pass numbers are 1, 2, 3, …");
        check!(src, r.depth >= 1 && r.depth <= target, "G76.DEPTH.LAST: every rough depth lies in 1…k − d");
        check!(src, r.last == (r.depth == target), "G76.DEPTH.LAST: last exactly at depth k − d");
        check!(src, r.depth >= previous_depth, "rough depths never decrease");
        let cut = r.depth - previous_depth;
        if !r.last {
            if constant {
                check!(src, cut == first_cut, "G78.DEPTHMODE 0: every cut but the last is Δd");
            } else {
                check!(src, cut >= min_cut, "G76.DEPTH.MIN: every cut but the last is at least Δdmin");
            }
        }
        let next = sch.next(&p, &r);
        if r.last {
            check!(src, next.is_none(), "G76.DEPTH.LAST: nothing after the last rough pass");
            finished = true;
            break;
        }
        check!(src, next.is_some(), "a pass that is not the last has a successor");
        let Some(n) = next else { return Ok(()) };
        previous_depth = r.depth;
        r = n;
        count += 1;
    }

    let counted = sch.rough_pass_count(&p, limit);
    if finished && count <= limit {
        check!(src, counted == Some(count), "PRJ.MAXPASS: rough_pass_count agrees with iterating");
    } else {
        // More than `limit` passes: either finished after `limit`, or not within K + 1 > limit.
        check!(src, counted.is_none(), "PRJ.MAXPASS: rough_pass_count is None above the limit");
    }

    cover!(src, finished && count == 1, "a single rough pass");
    cover!(src, finished && count >= 3, "three or more rough passes");
    cover!(src, !finished, "more passes than examined");
    cover!(src, finished && count == limit, "count exactly at the limit");
    cover!(src, finished && count == limit + 1, "count one above the limit");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = depth_bounds in crate::PROPERTIES {
        rules: ["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        states: "The first K + 1 passes of every schedule: numbered 1, 2, …, depths in 1…k − d and never decreasing, every cut but the last ≥ Δdmin (= Δd in constant mode), the closed-form pass count equal to the iterated one.",
        body: |src, scope| body(src, &crate::schedule::Production, &scope),
        /// The Kani attempt (a TEST: out of memory; built as a harness only with `kani-attempts`).
        kani: test(KANI) { unwind: 65, why: "out of memory (10–13 GB) in symbolic execution" },
        tests {
            /// Every Δd, Δdmin, T ≤ 16, both modes, every limit ≤ 200, iterating up to 201 passes of
            /// schedules of up to (T/Δd)² = 256 passes: most schedules are examined whole.
            fn depth_bounds_exhaustive = exhaustive(16, 2_000_000) on Scope { max_len: 16, max_passes: 200 };
            /// The edges of the legal ranges with K = 64.
            fn depth_bounds_exhaustive_edges = exhaustive(3, 1_000_000) on Scope { max_len: MAX_LENGTH, max_passes: 64 };
            fn depth_bounds_random = random(0x5eed_0002, 2) on Scope { max_len: MAX_LENGTH, max_passes: 200 };
        }
    }
}
