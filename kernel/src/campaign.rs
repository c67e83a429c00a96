//! Differential campaigns: many programs through two engines, the first as the reference, each
//! pair of traces judged by the conformance relation in lockstep ([`crate::judge`]).
//!
//! A campaign never stops at a divergence: it records every case's outcome, counts cases per
//! cycle and per ending (clean or which alarm), and keeps each divergent case whole (name,
//! program, configuration, divergence) for the report. An engine that panics is recorded as
//! such, not propagated.

use crate::conformance::{alarm_short, Divergence};
use crate::engine::{Engine, FailureKind};
use crate::judge::{CaseResult, Seen};
use crate::registry::{self, CycleRun};
use cycle_vocab::{Alarm, Config};
use std::collections::BTreeMap;

/// How a case ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Verdict {
    /// The candidate conforms; the reference's alarm, if it ended in one.
    Conform(Option<Alarm>),
    /// The first divergence.
    Diverge(Box<Divergence>),
    /// An engine panicked (never acceptable: both promise not to).
    Panic { engine: String, message: String },
}

impl Verdict {
    /// One-line form: `conform`, `conform (alarm 2002 P G78.MODE)`, `DIVERGE (…)`, `PANIC (…)`.
    pub fn short(&self) -> String {
        match self {
            Verdict::Conform(None) => "conform".to_string(),
            Verdict::Conform(Some(a)) => format!("conform ({})", alarm_short(a)),
            Verdict::Diverge(d) => {
                let field = d.field.map(|f| format!(", field {f}")).unwrap_or_default();
                format!("DIVERGE ({} at event {}{field})", d.kind, d.index)
            }
            Verdict::Panic { engine, .. } => format!("PANIC ({engine})"),
        }
    }

    pub fn conforms(&self) -> bool {
        matches!(self, Verdict::Conform(_))
    }
}

/// One case of a campaign.
#[derive(Clone, Debug)]
pub struct Outcome {
    pub name: String,
    /// The cycle the program runs ([`registry::sight`]).
    pub cycle: CycleRun,
    /// Events and pass headers of the reference trace.
    pub events: usize,
    pub passes: usize,
    pub verdict: Verdict,
}

/// A case that did not conform, kept whole.
#[derive(Clone, Debug)]
pub struct Finding {
    pub name: String,
    pub program: Vec<u8>,
    pub config: Config,
    pub verdict: Verdict,
}

impl std::fmt::Display for Finding {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        writeln!(f, "case {} ({:?}, {:?})", self.name, self.config.dialect, self.config.grid)?;
        match &self.verdict {
            Verdict::Diverge(d) => writeln!(f, "{d}")?,
            Verdict::Panic { engine, message } => writeln!(f, "PANIC in {engine}: {message}")?,
            Verdict::Conform(_) => writeln!(f, "conform")?,
        }
        writeln!(f, "program:")?;
        f.write_str(&String::from_utf8_lossy(&self.program))
    }
}

/// The result of a campaign.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// The engines' names: reference, candidate.
    pub engines: (String, String),
    /// Every case, in order.
    pub outcomes: Vec<Outcome>,
    /// Cases per cycle run.
    pub by_cycle: BTreeMap<CycleRun, usize>,
    /// Cases per ending of the reference trace: `clean` or `alarm 2002 P G78.MODE`.
    pub by_ending: BTreeMap<String, usize>,
    /// The cases that diverged or panicked.
    pub findings: Vec<Finding>,
}

impl Report {
    pub fn cases(&self) -> usize {
        self.outcomes.len()
    }

    pub fn conforming(&self) -> usize {
        self.outcomes.iter().filter(|o| o.verdict.conforms()).count()
    }

    /// Whether every case conformed.
    pub fn all_conform(&self) -> bool {
        self.findings.is_empty()
    }

    /// The divergences found, with their cases.
    pub fn divergences(&self) -> impl Iterator<Item = (&Finding, &Divergence)> {
        self.findings.iter().filter_map(|f| match &f.verdict {
            Verdict::Diverge(d) => Some((f, &**d)),
            _ => None,
        })
    }

    /// One-paragraph summary: counts, per cycle, per ending.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "{} vs {}: {} cases, {} conform, {} diverge",
            self.engines.0,
            self.engines.1,
            self.cases(),
            self.conforming(),
            self.cases() - self.conforming()
        );
        s.push_str(&format!("\n  by cycle: {}", registry::counts_line(&self.by_cycle)));
        let endings: Vec<String> = self.by_ending.iter().map(|(k, v)| format!("{k} {v}")).collect();
        s.push_str(&format!("\n  by ending: {}", endings.join(", ")));
        s
    }
}

/// Runs one case: both engines in lockstep, judged by the relation; what the reference showed,
/// and the cycle the case runs (the judge's one read of the program).
pub fn judge(engines: (&dyn Engine, &dyn Engine), program: &[u8], config: &Config) -> (Option<Seen>, Verdict, CycleRun) {
    let j = crate::judge::judge(engines.0, engines.1, program, config);
    let verdict = match j.result {
        CaseResult::Conform => Verdict::Conform(j.reference.as_ref().and_then(|r| r.alarm)),
        // No declarations here: a campaign judges spec against impl.
        CaseResult::Diverge(d) | CaseResult::Deviate { divergence: d, .. } => Verdict::Diverge(d),
        CaseResult::Failure { engine, failure } if failure.kind == FailureKind::Panic => Verdict::Panic { engine, message: failure.message },
        CaseResult::Failure { engine, failure } => Verdict::Panic { engine, message: format!("candidate failure: {failure}") },
    };
    (j.reference, verdict, j.sighting.cycle)
}

/// Runs every case through both engines (`engines.0` the reference) and collects the report.
pub fn run(engines: (&dyn Engine, &dyn Engine), cases: impl Iterator<Item = (String, Vec<u8>, Config)>) -> Report {
    let mut report = Report { engines: (engines.0.name().to_string(), engines.1.name().to_string()), ..Report::default() };
    for (name, program, config) in cases {
        let (reference, verdict, cycle) = judge(engines, &program, &config);
        let (events, passes) = reference.as_ref().map_or((0, 0), |r| (r.events, r.passes));
        *report.by_cycle.entry(cycle).or_default() += 1;
        let ending = match reference.as_ref().map(|t| t.alarm) {
            Some(None) => "clean".to_string(),
            Some(Some(a)) => alarm_short(&a),
            None => "reference panicked".to_string(),
        };
        *report.by_ending.entry(ending).or_default() += 1;
        if !verdict.conforms() {
            report.findings.push(Finding { name: name.clone(), program, config, verdict: verdict.clone() });
        }
        report.outcomes.push(Outcome { name, cycle, events, passes, verdict });
    }
    report
}

#[cfg(test)]
mod tests;
