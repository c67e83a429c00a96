//! Where a harness body gets its values, and how its verdicts are reported.
//!
//! The plumbing — [`Source`], [`Stop`], [`Outcome`], `check!`, `cover!`, the [`exhaustive`] and
//! [`random`] drivers — lives in `cycle-harness`, shared with the `impl_invariants` fuzz target
//! and the replay of its regressions; it is re-exported here. Kani's symbolic source is here,
//! next to the `kani` dependency: under Kani, `check!` is `kani::assert` with a literal message
//! and each draw of [`KaniSource`] is `kani::any` + `kani::assume` (an offset from the low end,
//! in the narrowest type that holds the range), so one run of the body covers every value.

pub use cycle_harness::{
    exhaustive, random, random_cases, Exhaustive, Failure, Outcome, Random, Report, Source, Stop, DEFAULT_RANDOM_CASES,
};

/// Symbolic values under Kani.
#[cfg(kani)]
pub struct KaniSource;

/// A symbolic offset in `0..=span`, drawn in the narrowest unsigned type that holds `span`.
/// `span` is a constant of the harness's scope, so the choice of type is made before the
/// solver runs, and every bit above the type's width is a constant 0: products and quotients
/// of small ranges bit-blast to small circuits instead of full 64- or 128-bit ones.
#[cfg(kani)]
fn offset(span: u128) -> u128 {
    let v = if span <= u128::from(u8::MAX) {
        u128::from(kani::any::<u8>())
    } else if span <= u128::from(u16::MAX) {
        u128::from(kani::any::<u16>())
    } else if span <= u128::from(u32::MAX) {
        u128::from(kani::any::<u32>())
    } else if span <= u128::from(u64::MAX) {
        u128::from(kani::any::<u64>())
    } else {
        kani::any::<u128>()
    };
    kani::assume(v <= span);
    v
}

#[cfg(kani)]
impl Source for KaniSource {
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128 {
        let v: i128 = kani::any();
        kani::assume(lo <= v && v <= hi);
        v
    }

    fn bounded_i64(&mut self, lo: i64, hi: i64) -> i64 {
        // hi − lo < 2^64 and the sum lies in lo..=hi: no overflow in i128.
        (i128::from(lo) + offset(hi.abs_diff(lo).into()) as i128) as i64
    }

    fn bounded_u64(&mut self, lo: u64, hi: u64) -> u64 {
        (u128::from(lo) + offset((hi - lo).into())) as u64
    }

    fn bounded_u32(&mut self, lo: u32, hi: u32) -> u32 {
        (u128::from(lo) + offset((hi - lo).into())) as u32
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
