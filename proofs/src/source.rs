//! Where a harness body gets its values, and how its verdicts are reported.
//!
//! One body, three uses: every harness body is generic over [`Source`]. Under Kani,
//! `KaniSource` makes each draw symbolic (`kani::any` + `kani::assume`), so one run of the body
//! covers every value. Under `cargo test`, [`Exhaustive`] enumerates every combination of draws
//! within a small scope (an odometer over the draws), and [`Random`] samples the full legal
//! ranges with a fixed-seed xorshift generator.
//!
//! Verdicts go through the [`check!`](crate::check) macro: under Kani it is `kani::assert` with
//! a literal message (Kani wants a constant message); under the test drivers the body returns
//! [`Stop::Failed`] and the driver reports the message with the draws that led to it. Nothing
//! panics on purpose, so a failing harness is an ordinary `Err`, not a caught panic.

use std::collections::BTreeMap;

/// Why a body stopped early.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// An assumption did not hold: the case is outside the harness's domain (not a failure).
    Rejected,
    /// A checked property did not hold.
    Failed(&'static str),
}

/// What a harness body returns.
pub type Outcome = Result<(), Stop>;

/// Values for a harness body, and the place its verdicts go.
pub trait Source {
    /// A value in `lo..=hi` (`lo <= hi`). Every other draw is made from this one, except under
    /// Kani, where each width draws natively.
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128;

    /// A value in `lo..=hi` (`lo <= hi`).
    fn bounded_i64(&mut self, lo: i64, hi: i64) -> i64 {
        self.bounded_i128(i128::from(lo), i128::from(hi)) as i64
    }

    /// A value in `lo..=hi` (`lo <= hi`).
    fn bounded_u64(&mut self, lo: u64, hi: u64) -> u64 {
        self.bounded_i128(i128::from(lo), i128::from(hi)) as u64
    }

    /// A value in `lo..=hi` (`lo <= hi`).
    fn bounded_u32(&mut self, lo: u32, hi: u32) -> u32 {
        self.bounded_i128(i128::from(lo), i128::from(hi)) as u32
    }

    /// Any `u128`, as two 64-bit halves (high half drawn first).
    fn any_u128(&mut self) -> u128 {
        let hi = self.bounded_u64(0, u64::MAX);
        let lo = self.bounded_u64(0, u64::MAX);
        (u128::from(hi) << 64) | u128::from(lo)
    }

    /// A value in `lo..=hi` from a small finite domain (an angle, a mode, a choice) that the
    /// exhaustive driver enumerates whole, whatever its width.
    fn every_u32(&mut self, lo: u32, hi: u32) -> u32 {
        self.bounded_u32(lo, hi)
    }

    /// Either boolean.
    fn bool(&mut self) -> bool {
        self.every_u32(0, 1) == 1
    }

    /// An index in `0..n` (`n >= 1`): which of `n` alternatives.
    fn choose(&mut self, n: u32) -> u32 {
        self.every_u32(0, n - 1)
    }

    /// Restricts the harness to cases where `cond` holds; a concrete driver discards the case.
    fn assume(&mut self, cond: bool) -> Outcome;

    /// The verdict of one checked property (use [`check!`](crate::check), which also emits the
    /// Kani assertion).
    fn verdict(&mut self, ok: bool, msg: &'static str) -> Outcome;

    /// Records that a cover condition was evaluated (use [`cover!`](crate::cover)).
    fn cover(&mut self, cond: bool, msg: &'static str);
}

/// Checks a property: `check!(src, cond, "message")`. Under Kani this is
/// `kani::assert(cond, "message")`; under the test drivers a false `cond` returns
/// `Err(Stop::Failed("message"))` from the enclosing body.
#[macro_export]
macro_rules! check {
    ($src:expr, $cond:expr, $msg:literal) => {{
        let ok: bool = $cond;
        #[cfg(kani)]
        kani::assert(ok, $msg);
        $crate::source::Source::verdict($src, ok, $msg)?;
    }};
}

/// A cover property: `cover!(src, cond, "message")`. Kani reports whether `cond` can hold; the
/// exhaustive driver fails a harness whose cover condition never held (a vacuous harness).
#[macro_export]
macro_rules! cover {
    ($src:expr, $cond:expr, $msg:literal) => {{
        let c: bool = $cond;
        #[cfg(kani)]
        kani::cover!(c, $msg);
        $crate::source::Source::cover($src, c, $msg);
    }};
}

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

    fn cover(&mut self, _cond: bool, _msg: &'static str) {}
}

/// The record every concrete driver keeps: the draws of the current case and cover counts.
#[derive(Default)]
struct Record {
    draws: Vec<i128>,
    covers: BTreeMap<&'static str, u64>,
}

impl Record {
    fn cover(&mut self, cond: bool, msg: &'static str) {
        *self.covers.entry(msg).or_insert(0) += u64::from(cond);
    }
}

fn verdict(ok: bool, msg: &'static str) -> Outcome {
    if ok { Ok(()) } else { Err(Stop::Failed(msg)) }
}

fn assumption(cond: bool) -> Outcome {
    if cond { Ok(()) } else { Err(Stop::Rejected) }
}

/// Bounded-exhaustive values: an odometer over the draws of one run of the body.
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
}

impl Exhaustive {
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

    fn assume(&mut self, cond: bool) -> Outcome {
        assumption(cond)
    }

    fn verdict(&mut self, ok: bool, msg: &'static str) -> Outcome {
        verdict(ok, msg)
    }

    fn cover(&mut self, cond: bool, msg: &'static str) {
        self.record.cover(cond, msg);
    }
}

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

    fn assume(&mut self, cond: bool) -> Outcome {
        assumption(cond)
    }

    fn verdict(&mut self, ok: bool, msg: &'static str) -> Outcome {
        verdict(ok, msg)
    }

    fn cover(&mut self, cond: bool, msg: &'static str) {
        self.record.cover(cond, msg);
    }
}

/// The first failing case of a driver run.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    pub message: &'static str,
    /// The values drawn in the failing case, in draw order.
    pub draws: Vec<i128>,
    /// 0-based number of the failing case.
    pub case: u64,
}

/// What a driver run did.
#[derive(Clone, Debug)]
pub struct Report {
    pub driver: &'static str,
    /// Cases run (including rejected ones).
    pub cases: u64,
    /// Cases whose assumptions did not hold.
    pub rejected: u64,
    /// Per cover message: in how many cases its condition held.
    pub covers: BTreeMap<&'static str, u64>,
    pub failure: Option<Failure>,
    /// True when the exhaustive driver stopped at its case budget before finishing.
    pub incomplete: bool,
}

impl Report {
    /// `Ok` when no property failed, the enumeration (if exhaustive) finished, at least one
    /// case passed its assumptions, and (exhaustive only) every cover condition held somewhere.
    pub fn verdict(&self) -> Result<(), String> {
        if let Some(f) = &self.failure {
            return Err(format!(
                "{} driver: property failed in case {}: {} (draws {:?})",
                self.driver, f.case, f.message, f.draws
            ));
        }
        if self.incomplete {
            return Err(format!("{} driver: case budget exhausted after {} cases", self.driver, self.cases));
        }
        if self.cases == self.rejected {
            return Err(format!("{} driver: all {} cases rejected (vacuous)", self.driver, self.cases));
        }
        if self.driver == "exhaustive" {
            let never: Vec<_> = self.covers.iter().filter(|(_, n)| **n == 0).map(|(m, _)| *m).collect();
            if !never.is_empty() {
                return Err(format!("exhaustive driver: cover conditions never satisfied: {never:?}"));
            }
        }
        Ok(())
    }

    /// Panics with the verdict's message unless it is `Ok`; returns the report for printing.
    #[track_caller]
    pub fn assert_ok(self) -> Report {
        if let Err(e) = self.verdict() {
            panic!("{e}");
        }
        self
    }
}

impl std::fmt::Display for Report {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {} cases, {} rejected", self.driver, self.cases, self.rejected)?;
        for (m, n) in &self.covers {
            write!(f, "; cover {m:?}: {n}")?;
        }
        Ok(())
    }
}

/// Runs `body` on every combination of draws (each draw limited to `width` values at each end
/// of its range), at most `budget` cases; stops at the first failure.
pub fn exhaustive(width: u64, budget: u64, mut body: impl FnMut(&mut Exhaustive) -> Outcome) -> Report {
    let mut src = Exhaustive::new(width);
    let mut report = Report {
        driver: "exhaustive",
        cases: 0,
        rejected: 0,
        covers: BTreeMap::new(),
        failure: None,
        incomplete: false,
    };
    loop {
        if report.cases == budget {
            report.incomplete = true;
            break;
        }
        src.begin();
        let out = body(&mut src);
        report.cases += 1;
        match out {
            Ok(()) => {}
            Err(Stop::Rejected) => report.rejected += 1,
            Err(Stop::Failed(message)) => {
                report.failure =
                    Some(Failure { message, draws: src.record.draws.clone(), case: report.cases - 1 });
                break;
            }
        }
        if !src.advance() {
            break;
        }
    }
    report.covers = std::mem::take(&mut src.record.covers);
    report
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
    let mut report = Report {
        driver: "random",
        cases: 0,
        rejected: 0,
        covers: BTreeMap::new(),
        failure: None,
        incomplete: false,
    };
    for case in 0..cases {
        src.record.draws.clear();
        let out = body(&mut src);
        report.cases += 1;
        match out {
            Ok(()) => {}
            Err(Stop::Rejected) => report.rejected += 1,
            Err(Stop::Failed(message)) => {
                report.failure = Some(Failure { message, draws: src.record.draws.clone(), case });
                break;
            }
        }
    }
    report.covers = std::mem::take(&mut src.record.covers);
    report
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn odometer_enumerates_every_path_once() {
        // Two dependent draws: a in 0..=3, then b in 0..=a. 1 + 2 + 3 + 4 = 10 paths.
        let mut seen = Vec::new();
        let r = exhaustive(8, 1000, |s| {
            let a = s.bounded_i64(0, 3);
            let b = s.bounded_i64(0, a);
            seen.push((a, b));
            Ok(())
        });
        assert_eq!(r.cases, 10);
        let mut sorted = seen.clone();
        sorted.sort();
        sorted.dedup();
        assert_eq!(sorted.len(), 10);
    }

    #[test]
    fn wide_ranges_take_both_ends() {
        let mut seen = Vec::new();
        let r = exhaustive(2, 1000, |s| {
            seen.push(s.bounded_i64(1, 999_999_999));
            Ok(())
        });
        assert_eq!(r.cases, 4);
        assert_eq!(seen, vec![1, 2, 999_999_998, 999_999_999]);
        let mut seen = Vec::new();
        exhaustive(2, 1000, |s| {
            seen.push(s.bounded_i64(i64::MIN, i64::MAX));
            Ok(())
        });
        assert_eq!(seen, vec![i64::MIN, i64::MIN + 1, i64::MAX - 1, i64::MAX]);
    }

    #[test]
    fn small_domains_are_enumerated_whole() {
        let r = exhaustive(1, 1000, |s| {
            s.every_u32(0, 178);
            s.bounded_u32(0, 178);
            Ok(())
        });
        assert_eq!(r.cases, 179 * 2);
    }

    #[test]
    fn failures_carry_their_draws_and_budget_is_enforced() {
        let r = exhaustive(8, 1000, |s| {
            let a = s.bounded_i64(0, 5);
            s.assume(a != 1)?;
            check!(s, a < 4, "a below 4");
            Ok(())
        });
        let f = r.failure.clone().unwrap();
        assert_eq!((f.message, f.draws), ("a below 4", vec![4]));
        assert_eq!(r.rejected, 1);
        assert!(r.verdict().is_err());

        let r = exhaustive(8, 3, |s| {
            s.bounded_i64(0, 5);
            Ok(())
        });
        assert!(r.incomplete && r.verdict().is_err());
    }

    #[test]
    fn uncovered_conditions_fail_the_exhaustive_driver() {
        let r = exhaustive(4, 100, |s| {
            let a = s.bounded_i64(0, 3);
            cover!(s, a == 2, "two");
            cover!(s, a == 9, "nine");
            Ok(())
        });
        assert_eq!(r.covers["two"], 1);
        assert!(r.verdict().unwrap_err().contains("nine"));
    }

    #[test]
    fn random_stays_in_range_and_hits_edges() {
        let (mut lo_hit, mut hi_hit) = (false, false);
        let r = random(7, 2000, |s| {
            let v = s.bounded_i64(-5, 999_999_999);
            check!(s, (-5..=999_999_999).contains(&v), "in range");
            lo_hit |= v == -5;
            hi_hit |= v == 999_999_999;
            Ok(())
        });
        r.assert_ok();
        assert!(lo_hit && hi_hit);
    }
}
