//! How one case is judged: the reference pushes its trace event by event
//! ([`Engine::push`]) and each event is compared at once with the candidate's next one, pulled
//! from its stream ([`Engine::pull`]) — the conformance relation in lockstep
//! ([`crate::conformance::Lockstep`]). Neither trace is collected (unless asked to, for the
//! plots: [`judge_keeping`]), so a case's memory does not grow with its trace, and no trace is
//! cut: both engines run to their ends.
//!
//! A panic of either engine is that engine's [`Failure`], never a pass.
//!
//! The judge also reads the program once ([`registry::sight`]), when the reference's run has
//! ended: the cycle the case runs and the G codes of the alarm's block travel in its result
//! ([`Judged::sighting`]), for the per-cycle counts and the hints ([`crate::hint`]).

use crate::conformance::{Divergence, Lockstep};
use crate::engine::{stream_of, Engine, Failure, FailureKind};
use crate::registry::{self, Sighting};
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, Config, Event, Rule};
use std::collections::BTreeSet;
use std::ops::ControlFlow;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// How a case ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CaseResult {
    Conform,
    Diverge(Box<Divergence>),
    /// The first divergence is one the candidate declared (`certify --deviations`): declaration
    /// `declaration` of the run's list. Not a conformance: the rest of the case was not compared.
    Deviate { divergence: Box<Divergence>, declaration: usize },
    /// An engine produced no trace (`engine` is `spec` or the candidate's name).
    Failure { engine: String, failure: Failure },
}

impl CaseResult {
    pub fn conforms(&self) -> bool {
        matches!(self, CaseResult::Conform)
    }

    /// One line: `conform`, `DIVERGE (field mismatch at event 5, field x, rule G92.PULLOUT)`,
    /// `FAIL (timeout: …)`.
    pub fn short(&self) -> String {
        match self {
            CaseResult::Conform => "conform".to_string(),
            CaseResult::Diverge(d) => {
                let field = d.field.map(|f| format!(", field {f}")).unwrap_or_default();
                let rule = d.rule.map(|r| format!(", rule {r}")).unwrap_or_default();
                format!("DIVERGE ({} at event {}{field}{rule})", d.kind, d.index)
            }
            CaseResult::Deviate { divergence, declaration } => {
                let rule = divergence.rule.map(|r| format!(", rule {r}")).unwrap_or_default();
                format!("DEVIATES as declared (declaration {}: {} at event {}{rule})", declaration + 1, divergence.kind, divergence.index)
            }
            CaseResult::Failure { engine, failure } => format!("FAIL ({engine} {})", failure.kind),
        }
    }
}

/// What the reference's trace showed, without the trace.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Seen {
    /// Events, of them pass headers.
    pub events: usize,
    pub passes: usize,
    /// The alarm that ended it.
    pub alarm: Option<Alarm>,
    /// The rule tags of its events and its alarm.
    pub rules: BTreeSet<Rule>,
}

impl Seen {
    fn note(&mut self, e: &Event) {
        self.events += 1;
        self.passes += usize::from(matches!(e, Event::Pass(_)));
        self.rules.insert(e.rule());
    }

    fn end(&mut self, alarm: Option<Alarm>) {
        self.alarm = alarm;
        self.rules.extend(alarm.map(|a| a.rule));
    }
}

/// One judged case.
#[derive(Clone, Debug)]
pub struct Judged {
    /// The reference's trace in summary; `None` when the reference failed.
    pub reference: Option<Seen>,
    pub result: CaseResult,
    /// Both traces when kept ([`judge_keeping`]): the reference's, and the candidate's when it
    /// produced one.
    pub traces: Option<(Trace, Option<Trace>)>,
    /// The program as read once against the reference's alarm (without a reference trace, to
    /// its end): the cycle it runs, the alarm block's G codes.
    pub sighting: Sighting,
}

impl Judged {
    /// The reference's alarm, when it ran and alarmed.
    pub fn alarm(&self) -> Option<&Alarm> {
        self.reference.as_ref().and_then(|r| r.alarm.as_ref())
    }
}

fn panic_message(p: Box<dyn std::any::Any + Send>) -> String {
    match p.downcast::<String>() {
        Ok(s) => *s,
        Err(p) => p.downcast_ref::<&str>().map_or_else(|| "panic".to_string(), |s| s.to_string()),
    }
}

/// `f`, with a panic turned into a [`FailureKind::Panic`] failure.
fn guarded<T>(f: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    catch_unwind(AssertUnwindSafe(f)).unwrap_or_else(|p| Err(Failure { kind: FailureKind::Panic, message: panic_message(p) }))
}

/// One engine alone on one case: what its pushed trace shows, and the trace when `keep`.
pub fn observe(engine: &dyn Engine, program: &[u8], config: &Config, keep: bool) -> Result<(Seen, Option<Trace>), Failure> {
    let mut seen = Seen::default();
    let mut kept = keep.then(Vec::new);
    let alarm = guarded(|| {
        engine.push(program, config, &mut |e| {
            seen.note(&e);
            kept.iter_mut().for_each(|k| k.push(e));
            ControlFlow::Continue(())
        })
    })?;
    seen.end(alarm);
    Ok((seen, kept.map(|events| Trace { grid: config.grid, events, alarm })))
}

/// Judges one case: the reference against the candidate, in lockstep.
pub fn judge(reference: &dyn Engine, candidate: &dyn Engine, program: &[u8], config: &Config) -> Judged {
    run(reference, candidate, program, config, false)
}

/// [`judge`], keeping both traces (for a plot).
pub fn judge_keeping(reference: &dyn Engine, candidate: &dyn Engine, program: &[u8], config: &Config) -> Judged {
    run(reference, candidate, program, config, true)
}

fn failure(engine: &dyn Engine, failure: Failure) -> CaseResult {
    CaseResult::Failure { engine: engine.name().to_string(), failure }
}

/// The reference alone, after the candidate failed with `f`.
fn candidate_failed(reference: &dyn Engine, candidate: &dyn Engine, program: &[u8], config: &Config, keep: bool, f: Failure) -> Judged {
    match observe(reference, program, config, keep) {
        Err(rf) => Judged { reference: None, result: failure(reference, rf), traces: None, sighting: registry::sight(program, config, None) },
        Ok((seen, trace)) => {
            let sighting = registry::sight(program, config, seen.alarm.as_ref());
            Judged { reference: Some(seen), result: failure(candidate, f), traces: trace.map(|t| (t, None)), sighting }
        }
    }
}

fn run(reference: &dyn Engine, candidate: &dyn Engine, program: &[u8], config: &Config, keep: bool) -> Judged {
    let (grid, mut stream) = match guarded(|| candidate.pull(program, config)) {
        Ok(pulled) => pulled,
        Err(f) => return candidate_failed(reference, candidate, program, config, keep, f),
    };
    let mut candidate_trace = None;
    if keep {
        let trace = Trace::collect(grid, stream);
        candidate_trace = Some(trace.clone());
        stream = stream_of(trace);
    }
    // The level the candidate declared (its greeting precedes its first trace).
    let mut lockstep = Lockstep::new(config.grid, grid, stream).at_level(candidate.level());
    let mut seen = Seen::default();
    let mut kept = keep.then(Vec::new);
    let mut candidate_panic = None;
    let pushed = guarded(|| {
        reference.push(program, config, &mut |e| {
            seen.note(&e);
            kept.iter_mut().for_each(|k| k.push(e));
            match catch_unwind(AssertUnwindSafe(|| lockstep.reference(e))) {
                Ok(()) => ControlFlow::Continue(()),
                Err(p) => {
                    candidate_panic = Some(panic_message(p));
                    ControlFlow::Break(())
                }
            }
        })
    });
    let alarm = match pushed {
        Err(f) => return Judged { reference: None, result: failure(reference, f), traces: None, sighting: registry::sight(program, config, None) },
        Ok(alarm) => alarm,
    };
    if let Some(message) = candidate_panic {
        return candidate_failed(reference, candidate, program, config, keep, Failure { kind: FailureKind::Panic, message });
    }
    seen.end(alarm);
    let result = match guarded(|| Ok(lockstep.finish(alarm))) {
        Err(f) => failure(candidate, f),
        Ok(Ok(())) => CaseResult::Conform,
        Ok(Err(d)) => CaseResult::Diverge(Box::new(d)),
    };
    let traces = kept.map(|events| (Trace { grid: config.grid, events, alarm }, candidate_trace));
    let sighting = registry::sight(program, config, alarm.as_ref());
    Judged { reference: Some(seen), result, traces, sighting }
}

#[cfg(test)]
mod tests;
