//! How one case is judged: the reference and the candidate on it (a panic is the engine's
//! failure), then the conformance relation on the two traces.

use super::{Error, Options};
use crate::candidate::CandidateEngine;
use crate::conformance::{self, Divergence};
use crate::engine::{Engine, Failure, FailureKind, ImplEngine};
use cycle_vocab::text::Trace;
use cycle_vocab::Config;
use std::panic::{catch_unwind, AssertUnwindSafe};

/// How a case ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CaseResult {
    Conform,
    Diverge(Box<Divergence>),
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
            CaseResult::Failure { engine, failure } => format!("FAIL ({engine} {})", failure.kind),
        }
    }
}

fn panic_message(p: Box<dyn std::any::Any + Send>) -> String {
    match p.downcast::<String>() {
        Ok(s) => *s,
        Err(p) => p.downcast_ref::<&str>().map_or_else(|| "panic".to_string(), |s| s.to_string()),
    }
}

/// One engine on one case; a panic becomes a [`FailureKind::Panic`] failure.
pub(super) fn try_engine(engine: &dyn Engine, program: &[u8], config: &Config) -> Result<Trace, Failure> {
    catch_unwind(AssertUnwindSafe(|| engine.try_expand(program, config)))
        .unwrap_or_else(|p| Err(Failure { kind: FailureKind::Panic, message: panic_message(p) }))
}

/// Runs one case through the reference and the candidate: both traces (when produced) and the
/// result.
pub fn judge(reference: &dyn Engine, candidate: &dyn Engine, program: &[u8], config: &Config) -> (Option<Trace>, Option<Trace>, CaseResult) {
    let r = match try_engine(reference, program, config) {
        Ok(t) => t,
        Err(failure) => return (None, None, CaseResult::Failure { engine: reference.name().to_string(), failure }),
    };
    match try_engine(candidate, program, config) {
        Err(failure) => (Some(r), None, CaseResult::Failure { engine: candidate.name().to_string(), failure }),
        Ok(c) => {
            let result = match conformance::check(&r, &c) {
                Ok(()) => CaseResult::Conform,
                Err(d) => CaseResult::Diverge(Box::new(d)),
            };
            (Some(r), Some(c), result)
        }
    }
}

/// The candidate engine of a run.
pub fn candidate_engine(options: &Options) -> Result<Box<dyn Engine>, Error> {
    match &options.candidate {
        None => Ok(Box::new(ImplEngine::default())),
        Some(cmd) => Ok(Box::new(CandidateEngine::new(cmd, options.limits).map_err(|e| Error(format!("--candidate: {e}")))?)),
    }
}

