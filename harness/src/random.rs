//! The random driver: full ranges from a fixed-seed generator.

use crate::report::{Record, Report};
use crate::source::{Outcome, Source};

/// Random values over the full ranges: xorshift64* with a fixed seed. One draw in eight is an
/// edge value (`lo`, `lo + 1`, `hi − 1`, `hi`), one in eight a small one (`lo..lo + 16`), the
/// rest uniform.
pub struct Random {
    state: u64,
    record: Record,
}

impl Random {
    fn new(seed: u64) -> Random {
        Random { state: seed | 1, record: Record::default() }
    }

    fn next_u64(&mut self) -> u64 {
        let mut x = self.state;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.state = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }
}

impl Source for Random {
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128 {
        assert!(lo <= hi, "empty range {lo}..={hi}");
        let size = hi.abs_diff(lo).saturating_add(1);
        let r = self.next_u64();
        let pick = (u128::from(self.next_u64()) << 64) | u128::from(self.next_u64());
        let v = match r % 8 {
            0 => {
                let edges = [lo, lo.saturating_add(1), hi.saturating_sub(1), hi];
                edges[(pick % 4) as usize].clamp(lo, hi)
            }
            1 => lo + (pick % size.min(16)) as i128,
            // lo + offset ≤ hi, computed without overflow.
            _ => lo.wrapping_add((pick % size) as i128),
        };
        self.record.draws.push(v);
        v
    }

    fn cover(&mut self, cond: bool, msg: &'static str) {
        self.record.cover(cond, msg);
    }
}

/// The base number of random cases: `CYCLECHECK_PROOF_CASES`, else this.
///
/// Chosen so that all random drivers together take about 3 s of one core in the debug test
/// profile here (measured; the budget is 30 s on 2 cores).
pub const DEFAULT_RANDOM_CASES: u64 = 1_000_000;

/// Random cases for one driver: the base (`CYCLECHECK_PROOF_CASES`, default
/// [`DEFAULT_RANDOM_CASES`]) divided by the driver's `divisor` (1 for cheap bodies, 2 or 4 for
/// those that run whole schedules or the expander), at least 1.
pub fn random_cases(divisor: u64) -> u64 {
    let base = std::env::var("CYCLECHECK_PROOF_CASES")
        .ok()
        .and_then(|v| v.trim().parse().ok())
        .unwrap_or(DEFAULT_RANDOM_CASES);
    (base / divisor.max(1)).max(1)
}

/// Runs `body` on `cases` random cases from `seed`; stops at the first failure.
pub fn random(seed: u64, cases: u64, mut body: impl FnMut(&mut Random) -> Outcome) -> Report {
    let mut src = Random::new(seed);
    let mut report = Report::new("random");
    for _ in 0..cases {
        src.record.draws.clear();
        let out = body(&mut src);
        if report.count(out, &src.record) {
            break;
        }
    }
    report.finish(src.record)
}

#[cfg(test)]
mod tests;
