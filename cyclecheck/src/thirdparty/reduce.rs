//! A reproducer per kind of candidate failure: the first failed case of that kind, and — for a
//! crash, garbage output, an oversized answer or a panic, which a shorter program can show as
//! well — that program minimized by deleting lines while the candidate still fails the same
//! way. Timeouts (each try costs the whole limit), spawn failures and refusals are listed, not
//! minimized.

use crate::certify::{CaseRecord, CaseResult, Run};
use cycle_kernel::engine::{Engine, FailureKind, SpecEngine};
use cycle_kernel::judge::judge;
use cycle_vocab::Config;
use std::collections::BTreeMap;

/// At most this many candidate runs per minimized failure.
pub const STEPS: usize = 60;

/// One kind of failure: how many cases, the first one, and its minimized program.
#[derive(Clone, Debug)]
pub struct Reproducer {
    pub kind: FailureKind,
    pub count: usize,
    pub first: String,
    pub message: String,
    pub program: Vec<u8>,
    pub config: Config,
    /// The minimized program and the candidate runs spent, where the minimizer applies.
    pub minimized: Option<(Vec<u8>, usize)>,
}

/// Whether deleting lines is worth trying for this kind.
pub fn minimizable(kind: FailureKind) -> bool {
    matches!(kind, FailureKind::Crash | FailureKind::Garbage | FailureKind::OutputTooLarge | FailureKind::Panic)
}

fn fails_as(engine: &dyn Engine, program: &[u8], config: &Config, kind: FailureKind) -> bool {
    matches!(judge(&SpecEngine, engine, program, config).result, CaseResult::Failure { engine: e, failure } if e != "spec" && failure.kind == kind)
}

/// `program` with lines deleted, last first, while `engine` still fails with `kind`.
pub fn minimize(engine: &dyn Engine, program: &[u8], config: &Config, kind: FailureKind) -> (Vec<u8>, usize) {
    let mut lines: Vec<Vec<u8>> = program.split_inclusive(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    let (mut steps, mut changed) = (0, true);
    while changed && steps < STEPS {
        changed = false;
        for i in (0..lines.len()).rev() {
            if steps >= STEPS || lines.len() <= 1 {
                break;
            }
            let mut shorter = lines.clone();
            shorter.remove(i);
            steps += 1;
            if fails_as(engine, &shorter.concat(), config, kind) {
                lines = shorter;
                changed = true;
            }
        }
    }
    (lines.concat(), steps)
}

/// The reproducers of a run's candidate failures, one per kind (refusals aside: they are
/// grouped by reason).
pub fn reproducers(engine: &dyn Engine, run: &Run) -> Vec<Reproducer> {
    let mut firsts: BTreeMap<FailureKind, &CaseRecord> = BTreeMap::new();
    for r in &run.failures {
        if let CaseResult::Failure { engine: e, failure } = &r.result {
            if e != "spec" && failure.kind != FailureKind::Refused {
                firsts.entry(failure.kind).or_insert(r);
            }
        }
    }
    firsts
        .into_iter()
        .map(|(kind, r)| {
            let message = match &r.result {
                CaseResult::Failure { failure, .. } => failure.message.clone(),
                _ => String::new(),
            };
            let minimized = minimizable(kind).then(|| minimize(engine, &r.program, &r.config, kind));
            Reproducer {
                kind,
                count: run.tally.failures_by_kind.get(&kind).copied().unwrap_or(0),
                first: r.name.clone(),
                message,
                program: r.program.clone(),
                config: r.config,
                minimized,
            }
        })
        .collect()
}
