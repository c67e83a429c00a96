//! The bounded-exhaustive driver: an odometer over the draws of one run of the body.

use crate::report::{Record, Report};
use crate::source::{Outcome, Source};

/// Bounded-exhaustive values.
///
/// Draw `i` of a run reads digit `i`. A range of at most `2·width` values is enumerated whole;
/// a larger one contributes its `width` smallest and `width` largest values (the small scope
/// and the overflow edge). After each run the last digit that can still advance does so and the
/// digits after it are forgotten (later draws may depend on earlier values), so every path
/// through the body's draws is run exactly once.
pub struct Exhaustive {
    width: u64,
    /// (digit, radix) of each draw made so far in this run or kept from the previous one.
    digits: Vec<(u64, u64)>,
    pos: usize,
    record: Record,
}

impl Exhaustive {
    fn new(width: u64) -> Exhaustive {
        assert!(width >= 1);
        Exhaustive { width, digits: Vec::new(), pos: 0, record: Record::default() }
    }

    /// Moves to the next combination; false when all have been run.
    fn advance(&mut self) -> bool {
        self.digits.truncate(self.pos);
        while let Some((digit, radix)) = self.digits.pop() {
            if digit + 1 < radix {
                self.digits.push((digit + 1, radix));
                return true;
            }
        }
        false
    }

    fn begin(&mut self) {
        self.pos = 0;
        self.record.draws.clear();
    }

    /// A draw in `lo..=hi` enumerating at most `span` values (all when the range is smaller,
    /// else the `span / 2` smallest and largest).
    fn draw(&mut self, lo: i128, hi: i128, span: u64) -> i128 {
        assert!(lo <= hi, "empty range {lo}..={hi}");
        let half = span / 2;
        // hi − lo + 1 ≤ 2^128 for the ranges used (each within i64/u64); saturate otherwise.
        let size = (hi.abs_diff(lo)).saturating_add(1);
        let span = u128::from(span);
        let radix = size.min(span) as u64;
        let digit = match self.digits.get(self.pos) {
            Some(&(d, r)) => {
                debug_assert_eq!(r, radix, "a draw's range changed under the same prefix");
                d
            }
            None => {
                self.digits.push((0, radix));
                0
            }
        };
        self.pos += 1;
        let v = if size <= span || digit < half {
            lo + i128::from(digit)
        } else {
            hi - i128::from(2 * half - 1 - digit)
        };
        self.record.draws.push(v);
        v
    }
}

impl Source for Exhaustive {
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128 {
        self.draw(lo, hi, 2 * self.width)
    }

    fn every_u32(&mut self, lo: u32, hi: u32) -> u32 {
        self.draw(i128::from(lo), i128::from(hi), u64::from(u32::MAX) + 1) as u32
    }

    fn cover(&mut self, cond: bool, msg: &'static str) {
        self.record.cover(cond, msg);
    }
}

/// Runs `body` on every combination of draws (each draw limited to `width` values at each end
/// of its range), at most `budget` cases; stops at the first failure.
pub fn exhaustive(width: u64, budget: u64, mut body: impl FnMut(&mut Exhaustive) -> Outcome) -> Report {
    let mut src = Exhaustive::new(width);
    let mut report = Report::new("exhaustive");
    loop {
        if report.cases == budget {
            report.incomplete = true;
            break;
        }
        src.begin();
        let out = body(&mut src);
        if report.count(out, &src.record) || !src.advance() {
            break;
        }
    }
    report.finish(src.record)
}

#[cfg(test)]
mod tests;
