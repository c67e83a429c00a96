//! The engines under comparison, behind one trait (in the style of wasmtime's fuzzing oracles:
//! each engine turns the same input into a comparable result, the oracle compares results).
//!
//! - [`SpecEngine`]: the executable reference, `cycle_spec::expand`; it pushes its events into
//!   a sink as it emits them (`cycle_spec::expand_into`, [`Engine::push`]).
//! - [`ImplEngine`]: the production expander, `cycle_impl::Expander`, a pull iterator of events
//!   ([`Engine::pull`]), read to its end: no bound on the events taken.
//!
//! - [`crate::candidate::CandidateEngine`]: a vendor's expander run as a child process that
//!   reads programs and configurations and answers JSON traces (`docs/CANDIDATE.md`).
//!
//! An engine that can fail outside the program — a child process that times out, crashes or
//! answers garbage — says so through [`Engine::try_expand`] with a classified [`Failure`]; a
//! campaign records it as that case's finding, never as a pass.
//!
//! Nothing here collects a trace unless asked to ([`Engine::expand`]): the comparison
//! ([`crate::judge`]) runs the reference's push against the candidate's pull in lockstep, so
//! memory does not grow with the trace.

use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, Config, Event};
use std::ops::ControlFlow;

/// Where a pushed trace goes, event by event; `Break` asks for no more events.
pub type Sink<'s> = &'s mut dyn FnMut(Event) -> ControlFlow<()>;

/// A trace as a pull stream: its events, then its alarm as `Err` (the form of
/// `cycle_impl::Expander`).
pub type Stream<'a> = Box<dyn Iterator<Item = Result<Event, Alarm>> + 'a>;

/// A whole trace as a [`Stream`].
pub fn stream_of(trace: Trace) -> Stream<'static> {
    Box::new(trace.events.into_iter().map(Ok).chain(trace.alarm.map(Err)))
}

/// An expander of programs into traces.
pub trait Engine {
    /// A short name for reports (`spec`, `impl`).
    fn name(&self) -> &str;
    /// The whole trace of `program` under `config`, ending at the first alarm.
    fn expand(&self, program: &[u8], config: &Config) -> Trace;

    /// The trace, or why the engine could not produce one. In-process engines cannot fail this
    /// way (the default); the candidate engine can (timeout, crash, garbage, …).
    fn try_expand(&self, program: &[u8], config: &Config) -> Result<Trace, Failure> {
        Ok(self.expand(program, config))
    }

    /// What its traces hold, so what the relation compares ([`crate::conformance::Level`]):
    /// in-process engines emit whole traces (`full`, the default); a candidate declares its
    /// level in the greeting. Read after [`Engine::pull`] or [`Engine::try_expand`] of a case.
    fn level(&self) -> crate::conformance::Level {
        crate::conformance::Level::Full
    }

    /// A hint: `program` under `config` will be asked for after the cases hinted before it, so
    /// an engine that works beside the caller (a candidate child) can start on it. Callers hint
    /// a bounded window ahead and then ask for those cases in order. By default nothing.
    fn prefetch(&self, _program: &[u8], _config: &Config) {}

    /// Pushes the trace into `sink` event by event and returns its alarm (the trace's grid is
    /// the configuration's). After `Break` the sink gets no more events and the result says
    /// nothing of the rest. By default the trace is expanded whole, then pushed.
    fn push(&self, program: &[u8], config: &Config, sink: Sink) -> Result<Option<Alarm>, Failure> {
        let trace = self.try_expand(program, config)?;
        for e in trace.events {
            if sink(e).is_break() {
                return Ok(None);
            }
        }
        Ok(trace.alarm)
    }

    /// The trace as a pull stream, with its grid. By default the trace is expanded whole.
    fn pull<'a>(&'a self, program: &'a [u8], config: &'a Config) -> Result<(cycle_vocab::Grid, Stream<'a>), Failure> {
        let trace = self.try_expand(program, config)?;
        Ok((trace.grid, stream_of(trace)))
    }
}

/// Why an engine produced no trace for a case.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum FailureKind {
    /// The engine panicked (in-process engines promise not to).
    Panic,
    /// The candidate command could not be started.
    Spawn,
    /// No answer within the per-case timeout.
    Timeout,
    /// The candidate exited (or closed its output) before answering.
    Crash,
    /// The answer is not a protocol response: not JSON, wrong id, not a trace.
    Garbage,
    /// The answer exceeded the output cap.
    OutputTooLarge,
    /// The candidate answered with an error instead of a trace.
    Refused,
}

impl FailureKind {
    /// A short name for reports: `timeout`, `output too large`.
    pub const fn name(self) -> &'static str {
        match self {
            FailureKind::Panic => "panic",
            FailureKind::Spawn => "spawn failed",
            FailureKind::Timeout => "timeout",
            FailureKind::Crash => "crash",
            FailureKind::Garbage => "garbage output",
            FailureKind::OutputTooLarge => "output too large",
            FailureKind::Refused => "refused",
        }
    }
}

impl std::fmt::Display for FailureKind {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// A classified engine failure and what was seen (exit status, a snippet of the output, …).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Failure {
    pub kind: FailureKind,
    pub message: String,
}

impl std::fmt::Display for Failure {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}: {}", self.kind, self.message)
    }
}

/// The executable reference spec (`cycle-spec`).
#[derive(Clone, Copy, Debug, Default)]
pub struct SpecEngine;

impl Engine for SpecEngine {
    fn name(&self) -> &str {
        "spec"
    }

    fn expand(&self, program: &[u8], config: &Config) -> Trace {
        cycle_spec::expand(program, config)
    }

    fn push(&self, program: &[u8], config: &Config, sink: Sink) -> Result<Option<Alarm>, Failure> {
        Ok(cycle_spec::expand_into(program, config, sink))
    }
}

/// The production expander (`cycle-impl`): its stream of events, read to the end. Nothing cuts
/// it: every cycle is bounded by `max_passes` (PRJ.MAXPASS) in both engines, and a program by
/// its length, so the whole trace is always there to compare.
#[derive(Clone, Copy, Debug, Default)]
pub struct ImplEngine;

impl Engine for ImplEngine {
    fn name(&self) -> &str {
        "impl"
    }

    fn expand(&self, program: &[u8], config: &Config) -> Trace {
        Trace::collect(config.grid, cycle_impl::Expander::new(program, *config))
    }

    fn push(&self, program: &[u8], config: &Config, sink: Sink) -> Result<Option<Alarm>, Failure> {
        for item in cycle_impl::Expander::new(program, *config) {
            match item {
                Ok(e) if sink(e).is_break() => return Ok(None),
                Ok(_) => {}
                Err(a) => return Ok(Some(a)),
            }
        }
        Ok(None)
    }

    fn pull<'a>(&'a self, program: &'a [u8], config: &'a Config) -> Result<(cycle_vocab::Grid, Stream<'a>), Failure> {
        Ok((config.grid, Box::new(cycle_impl::Expander::new(program, *config))))
    }
}

/// An engine by its CLI name: `spec` or `impl`.
pub fn by_name(name: &str) -> Option<Box<dyn Engine>> {
    match name {
        "spec" => Some(Box::new(SpecEngine)),
        "impl" => Some(Box::new(ImplEngine)),
        _ => None,
    }
}

/// Deliberately wrong engines for the harness's own tests (the kernel's, and the application's
/// through the `test-aids` feature): a harness that cannot tell them from the spec is broken.
#[cfg(any(test, feature = "test-aids"))]
pub mod wrong {
    use super::Engine;
    use cycle_vocab::text::Trace;
    use cycle_vocab::{Config, Event, Move};

    /// The spec with `fault` applied to every move (with its event index): a wrong candidate.
    pub struct SpecWith {
        pub name: &'static str,
        pub fault: fn(usize, &mut Move),
    }

    impl Engine for SpecWith {
        fn name(&self) -> &str {
            self.name
        }
        fn expand(&self, program: &[u8], config: &Config) -> Trace {
            let mut t = cycle_spec::expand(program, config);
            for (i, e) in t.events.iter_mut().enumerate() {
                if let Event::Move(m) = e {
                    (self.fault)(i, m);
                }
            }
            t
        }
    }

    /// An engine that panics on every program.
    pub struct Panics;

    impl Engine for Panics {
        fn name(&self) -> &str {
            "panics"
        }
        fn expand(&self, _: &[u8], _: &Config) -> Trace {
            panic!("boom")
        }
    }
}

#[cfg(test)]
mod tests;
