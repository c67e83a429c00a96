//! The proofs' [`Source`] of values, fed by the fuzzer's bytes: the harness bodies of
//! `cycle-proofs` (written for Kani, run under `cargo test` by exhaustive and random drivers)
//! run unchanged under libFuzzer, which steers each draw by coverage.
//!
//! Each draw reads a mode byte, then the value: uniform over the range, or within 15 of either
//! end (the edges where overflow and off-by-one errors live). Past the end of the input every
//! draw is the range's low end, so short inputs are the plainest cases.

use arbitrary::Unstructured;
use cycle_proofs::source::{Outcome, Source, Stop};

/// Values drawn from fuzz input; records the draws for the report of a failing case.
pub struct FuzzSource<'a> {
    u: Unstructured<'a>,
    /// Every value drawn so far, in order.
    pub draws: Vec<i128>,
}

impl<'a> FuzzSource<'a> {
    pub fn new(data: &'a [u8]) -> FuzzSource<'a> {
        FuzzSource { u: Unstructured::new(data), draws: Vec::new() }
    }
}

impl Source for FuzzSource<'_> {
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128 {
        let mode = self.u.arbitrary::<u8>().unwrap_or(0) % 4;
        let near = |u: &mut Unstructured| i128::from(u.int_in_range(0u8..=15).unwrap_or(0));
        let v = match mode {
            1 => lo.saturating_add(near(&mut self.u)).min(hi),
            2 => hi.saturating_sub(near(&mut self.u)).max(lo),
            _ => self.u.int_in_range(lo..=hi).unwrap_or(lo),
        };
        self.draws.push(v);
        v
    }

    fn assume(&mut self, cond: bool) -> Outcome {
        if cond {
            Ok(())
        } else {
            Err(Stop::Rejected)
        }
    }

    fn verdict(&mut self, ok: bool, msg: &'static str) -> Outcome {
        if ok {
            Ok(())
        } else {
            Err(Stop::Failed(msg))
        }
    }

    fn cover(&mut self, _cond: bool, _msg: &'static str) {}
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn draws_stay_in_range_and_exhaustion_gives_the_low_end() {
        let data: Vec<u8> = (0..=255u8).cycle().take(4000).collect();
        let mut s = FuzzSource::new(&data);
        for (lo, hi) in [(0, 0), (-5, 5), (1, 999_999_999), (i128::from(i64::MIN), i128::from(i64::MAX))] {
            for _ in 0..50 {
                let v = s.bounded_i128(lo, hi);
                assert!(lo <= v && v <= hi, "{v} outside {lo}..={hi}");
            }
        }
        let mut empty = FuzzSource::new(&[]);
        assert_eq!(empty.bounded_i64(-3, 9), -3);
        assert_eq!(empty.draws, vec![-3]);
    }

    #[test]
    fn modes_reach_both_edges() {
        // Mode 2 (high end), offset 0; mode 1 (low end), offset 3.
        let mut s = FuzzSource::new(&[2, 0, 1, 3]);
        assert_eq!(s.bounded_i64(10, 1_000), 1_000);
        assert_eq!(s.bounded_i64(10, 1_000), 13);
    }
}
