//! `mutant_schedule_is_caught`: the schedule harness bodies, run by their bounded drivers
//! against deliberately wrong schedules ([`crate::schedule::mutants`]), must fail — each
//! mutant caught by at least one harness, as an `Err` verdict (no panic is caught).

use crate::schedule::Schedule;
use crate::source::{exhaustive, Report};
use crate::{depth_bounds, depth_step_monotone};

/// Both schedule harnesses against `sch` with small bounded-exhaustive drivers; the verdicts.
pub fn run_schedule_harnesses<Sch: Schedule>(sch: &Sch) -> [(&'static str, Report); 2] {
    let step_scope = depth_step_monotone::Scope { max_len: 8, max_n: 40 };
    let bounds_scope = depth_bounds::Scope { max_len: 8, max_passes: 40 };
    [
        ("depth_step_monotone", exhaustive(64, 2_000_000, |s| depth_step_monotone::body(s, sch, &step_scope))),
        ("depth_bounds", exhaustive(8, 2_000_000, |s| depth_bounds::body(s, sch, &bounds_scope))),
    ]
}

/// The names of the harnesses whose verdict on `sch` is a failure.
pub fn failing<Sch: Schedule>(sch: &Sch) -> Vec<(&'static str, String)> {
    run_schedule_harnesses(sch)
        .into_iter()
        .filter_map(|(name, r)| r.verdict().err().map(|e| (name, e)))
        .collect()
}

#[cfg(test)]
mod tests;
