//! What a driver run did: cases, rejections, cover counts and the first failure.

use crate::source::{Outcome, Stop};
use std::collections::BTreeMap;

/// The record every driver keeps: the draws of the current case and cover counts.
#[derive(Default)]
pub(crate) struct Record {
    pub(crate) draws: Vec<i128>,
    pub(crate) covers: BTreeMap<&'static str, u64>,
}

impl Record {
    pub(crate) fn cover(&mut self, cond: bool, msg: &'static str) {
        *self.covers.entry(msg).or_insert(0) += u64::from(cond);
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
    pub(crate) fn new(driver: &'static str) -> Report {
        Report { driver, cases: 0, rejected: 0, covers: BTreeMap::new(), failure: None, incomplete: false }
    }

    /// The report with the cover counts of the run.
    pub(crate) fn finish(mut self, record: Record) -> Report {
        self.covers = record.covers;
        self
    }

    /// Counts one case's outcome (its draws in `record`); true when it failed: the driver stops.
    pub(crate) fn count(&mut self, out: Outcome, record: &Record) -> bool {
        let case = self.cases;
        self.cases += 1;
        match out {
            Ok(()) => false,
            Err(Stop::Rejected) => {
                self.rejected += 1;
                false
            }
            Err(Stop::Failed(message)) => {
                self.failure = Some(Failure { message, draws: record.draws.clone(), case });
                true
            }
        }
    }

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
    /// For tests.
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
