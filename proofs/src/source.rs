//! Where a harness body gets its values, and how its verdicts are reported.
//!
//! The plumbing — [`Source`], [`Stop`], [`Outcome`], `check!`, `cover!`, the [`exhaustive`] and
//! [`random`] drivers — lives in `cycle-harness`, shared with the `impl_invariants` fuzz target
//! and the replay of its regressions; it is re-exported here. Kani's symbolic source is here,
//! next to the `kani` dependency: under Kani, `check!` is `kani::assert` with a literal message
//! and each draw of [`KaniSource`] is `kani::any` + `kani::assume`, so one run of the body covers
//! every value.

pub use cycle_harness::{
    exhaustive, random, random_cases, Exhaustive, Failure, Outcome, Random, Report, Source, Stop, DEFAULT_RANDOM_CASES,
};

/// Symbolic values under Kani.
#[cfg(kani)]
pub struct KaniSource;

#[cfg(kani)]
impl Source for KaniSource {
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128 {
        let v: i128 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    fn bounded_i64(&mut self, lo: i64, hi: i64) -> i64 {
        let v: i64 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    fn bounded_u64(&mut self, lo: u64, hi: u64) -> u64 {
        let v: u64 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    fn bounded_u32(&mut self, lo: u32, hi: u32) -> u32 {
        let v: u32 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    fn any_u128(&mut self) -> u128 {
        kani::any()
    }

    fn bool(&mut self) -> bool {
        kani::any()
    }

    fn assume(&mut self, cond: bool) -> Outcome {
        kani::assume(cond);
        Ok(())
    }

    fn verdict(&mut self, _ok: bool, _msg: &'static str) -> Outcome {
        // The assertion itself was emitted by `check!` with a literal message.
        Ok(())
    }
}
