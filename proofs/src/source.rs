//! Where a harness body gets its values, and how its verdicts are reported.
//!
//! The plumbing — [`Source`], [`Stop`], [`Outcome`], `check!`, `cover!`, the [`exhaustive`] and
//! [`random`] drivers — lives in `cycle-harness`, shared with the `impl_invariants` fuzz target
//! and the replay of its regressions; it is re-exported here, with Kani's symbolic source
//! (`KaniSource`, `cfg(kani)`): under Kani, `check!` is `kani::assert` with a literal message
//! and each draw is `kani::any` + `kani::assume` (an offset from the low end, in the narrowest
//! type that holds the range), so one run of the body covers every value.

pub use cycle_harness::{
    exhaustive, random, random_cases, Exhaustive, Failure, Outcome, Random, Report, Source, Stop, DEFAULT_RANDOM_CASES,
};

#[cfg(kani)]
pub use cycle_harness::KaniSource;

/// A value in `lo..=hi`, where `hi ≤ cap` and `cap` is a constant of the harness's scope.
///
/// Under Kani it is drawn in `lo..=cap` and assumed ≤ `hi`: a symbolic `hi` would make
/// [`KaniSource`]'s draw 128 bits wide (the narrowest type is chosen from the span, which would
/// then be symbolic), while `cap` keeps it as narrow as the scope. Under the drivers it is drawn
/// in `lo..=hi` directly, so no case is discarded. The same set of values either way.
pub fn bounded_i64_upto<S: Source>(src: &mut S, lo: i64, hi: i64, cap: i64) -> Result<i64, Stop> {
    if cfg!(kani) {
        let v = src.bounded_i64(lo, cap);
        src.assume(v <= hi)?;
        Ok(v)
    } else {
        Ok(src.bounded_i64(lo, hi))
    }
}
