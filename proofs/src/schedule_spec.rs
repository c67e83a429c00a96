//! Harness `schedule_spec` (a TEST: driver-only) — G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST,
//! G78.DEPTHMODE, PRJ.MAXPASS, over the **spec's** depth schedule
//! (`cycle_spec::multipass::schedule::rough_passes`, the executable reference).
//!
//! The differential test compares every candidate with the spec; these properties of the spec
//! itself are what that comparison then carries to every candidate (as a reference's own
//! properties are proved once and inherited by everything checked against it).
//!
//! **Property.** For Δd (1…N), Δdmin (0…N), T = k − d (1…N, with a finishing allowance d),
//! degressive or constant, and a pass limit:
//!
//! - `rough_passes` is `TooMany` exactly when the schedule has more passes than the limit
//!   (the count found by the register's closed form, [`crate::model`]), else the passes;
//! - pass n is the register's closed form: round(√n·Δd) before the switch pass s
//!   ([`crate::model::switch_pass`], checked by its exact bracket, no root taken),
//!   round(√(s−1)·Δd) + (n − s + 1)·Δdmin from s on, n·Δd in constant mode — clamped to T,
//!   named by its rule (G76.DEPTH.LAST when clamped);
//! - depths lie in 1…T, never decrease, strictly increase when Δdmin ≥ 1 or in constant mode;
//!   every cut but the last is ≥ Δdmin (= Δd in constant mode); exactly the last pass is at T.
//!
//! **Why not Kani.** The spec computes in `BigInt` (heap-allocated digit vectors, loops over
//! digits, a Newton square root): Kani would have to unroll allocation and arbitrary-precision
//! loops, and the nonlinear identities involved are beyond a SAT solver at these widths even
//! in fixed-width code (see `depth_step_clamp`). The drivers run it; z3 (smt/) proves the
//! register's arithmetic the spec transcribes.

use crate::model::{depth_square, is_sqrt_round, switch_pass};
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::MAX_LENGTH;
use cycle_spec::multipass::schedule::{rough_passes, DepthMode, TooMany};
use cycle_vocab::Rule;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest Δd, Δdmin, T.
    pub max_len: i64,
    /// Largest pass limit (the spec computes up to limit + 1 passes).
    pub max_limit: u64,
}

/// The legal lengths, limits up to 200 passes.
pub const WIDE: Scope = Scope { max_len: MAX_LENGTH, max_limit: 200 };

/// The register's exact (unclamped) depth of pass n, with the rule that sets it.
fn closed_form(n: u64, dd: i64, constant: bool, s: Option<u32>) -> (Option<i128>, Rule) {
    if constant {
        return (Some(i128::from(n as u32) * i128::from(dd)), Rule::G78DepthMode);
    }
    match s {
        Some(s) if n >= u64::from(s) => {
            // The base round(√(s−1)·Δd) is checked through the bracket by the caller.
            (None, Rule::G76DepthMin)
        }
        _ => (None, Rule::G76Depth1),
    }
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let dd = src.bounded_i64(1, scope.max_len);
    let dmin = src.bounded_i64(0, scope.max_len);
    let t = src.bounded_i64(1, scope.max_len);
    let d = src.bounded_i64(0, 3);
    let constant = src.bool();
    let limit = src.bounded_u64(0, scope.max_limit);
    let mode = if constant { DepthMode::Constant } else { DepthMode::Degressive };
    let s = if constant { None } else { switch_pass(dd, dmin) };

    // The model's passes, up to limit + 1 of them: (depth, rule), the exact depths from the
    // bracket (before s) or from the base (from s on).
    let got = rough_passes(t + d, d, dd, dmin, mode, limit);
    let mut base: Option<i128> = None; // round(√(s−1)·Δd), from the spec's pass s − 1 (checked)
    let mut prev = 0i64;
    let mut n = 0u64;
    let passes = match &got {
        Ok(p) => p.clone(),
        Err(TooMany) => Vec::new(),
    };
    check!(src, got.as_ref().map_or(true, |p| !p.is_empty() && p.len() as u64 <= limit), "PRJ.MAXPASS: 1…limit passes");
    for (i, r) in passes.iter().enumerate() {
        n += 1;
        let is_last = i + 1 == passes.len();
        check!(src, 1 <= r.depth && r.depth <= t, "G76.DEPTH.LAST: every rough depth lies in 1…k − d");
        check!(src, (r.depth == t) == is_last, "G76.DEPTH.LAST: exactly the last pass is at k − d");
        check!(src, (r.rule == Rule::G76DepthLast) == is_last, "G76.DEPTH.LAST names exactly the last pass");
        check!(src, r.depth >= prev, "rough depths never decrease");
        if dmin >= 1 || constant {
            check!(src, r.depth > prev, "G76.DEPTH.MIN, G78.DEPTHMODE: rough depths strictly increase");
        }
        if !is_last {
            let cut = r.depth - prev;
            check!(src, if constant { cut == dd } else { cut >= dmin }, "G76.DEPTH.MIN: every cut but the last ≥ Δdmin (= Δd in constant mode)");
        }
        let (exact, rule) = closed_form(n, dd, constant, s);
        let unclamped_ok = match (exact, rule) {
            (Some(e), _) => (is_last && e >= i128::from(t)) || (!is_last && e == i128::from(r.depth)),
            (None, Rule::G76Depth1) => {
                let sq = depth_square(n as u32, dd);
                // Clamped: the root reaches T (r(r − 1) < n·Δd² for r = T); else the bracket.
                if is_last { sq > (t as u128) * (t as u128 - 1) } else { is_sqrt_round(r.depth as u128, sq) }
            }
            (None, _) => {
                let s = u64::from(s.unwrap_or(1));
                let b = if s == 1 { Some(0) } else { base };
                match b {
                    Some(b) => {
                        let e = b + i128::from((n - s + 1) as u32) * i128::from(dmin);
                        (is_last && e >= i128::from(t)) || (!is_last && e == i128::from(r.depth))
                    }
                    None => false,
                }
            }
        };
        check!(src, unclamped_ok, "G76.DEPTH.1/.MIN/.LAST, G78.DEPTHMODE: pass n is the register's closed form");
        check!(src, is_last || r.rule == rule, "each pass names the rule of its closed form");
        if s.is_some_and(|s| n + 1 == u64::from(s)) {
            base = Some(i128::from(r.depth));
        }
        prev = r.depth;
    }
    if got.is_err() {
        // More than `limit` passes: the first `limit` exact depths all stay below T.
        let mut m = 1u64;
        let mut below = true;
        let mut b: Option<i128> = None;
        while m <= limit && below {
            let e = match closed_form(m, dd, constant, s) {
                (Some(e), _) => e,
                (None, Rule::G76Depth1) => {
                    let sq = depth_square(m as u32, dd);
                    below = sq <= (t as u128) * (t as u128 - 1);
                    if s.is_some_and(|s| m + 1 == u64::from(s)) {
                        // round(√(m·Δd²)), taken from the impl's helper and checked by its
                        // bracket here (an independent check, not a trust).
                        let r = cycle_impl::fixed::sqrt_round(sq);
                        check!(src, is_sqrt_round(r, sq), "the base of the minimum cuts is round(√((s−1)·Δd²))");
                        b = Some(r as i128);
                    }
                    m += 1;
                    continue;
                }
                (None, _) => {
                    let sv = u64::from(s.unwrap_or(1));
                    b.unwrap_or(0) + i128::from((m - sv + 1) as u32) * i128::from(dmin)
                }
            };
            below = e < i128::from(t);
            m += 1;
        }
        check!(src, below, "PRJ.MAXPASS: TooMany only when more than `limit` passes stay below k − d");
    }

    cover!(src, got.is_err(), "more passes than the limit");
    cover!(src, passes.len() >= 3, "three or more passes");
    cover!(src, passes.iter().any(|r| r.rule == Rule::G76DepthMin), "a minimum-cut pass");
    cover!(src, constant && !passes.is_empty(), "constant mode");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = schedule_spec in crate::PROPERTIES {
        rules: ["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        states: "The same depth-schedule properties over the spec's (BigInt) schedule: closed form, monotone steps, cuts ≥ Δdmin, last exactly at k − d, the count.",
        body: |src, scope| body(src, &scope),
        kani: none { why: "the spec's schedule computes in `BigInt` (heap digit vectors, Newton roots): not a Kani target" },
        tests {
            /// Every Δd, Δdmin, T ≤ 9, d ≤ 3, both modes, limits their 6 smallest and largest values
            /// up to 60 (the schedules have up to (T/Δd)² = 81 passes).
            fn schedule_spec_exhaustive_small = exhaustive(6, 2_000_000) on Scope { max_len: 9, max_limit: 60 };
            /// Legal lengths at random, and the edges.
            fn schedule_spec_random = random(0x5eed_5bec, 64) on WIDE, exhaustive(2, 200_000) on WIDE;
        }
    }
}
