//! Kani's source: each draw is `kani::any` + `kani::assume`, so one run of a body covers every
//! value of its domain. Compiled only under `cfg(kani)`, where cargo-kani provides the `kani`
//! crate (or, for the type-check without Kani, `kani-stub/` under `cfg(kani_stub)`).

use crate::source::{Outcome, Source};

/// Symbolic values under Kani.
pub struct KaniSource;

/// A symbolic offset in `0..=span`, drawn in the narrowest unsigned type that holds `span`.
/// `span` is a constant of the harness's scope, so the choice of type is made before the
/// solver runs, and every bit above the type's width is a constant 0: products and quotients
/// of small ranges bit-blast to small circuits instead of full 64- or 128-bit ones.
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
