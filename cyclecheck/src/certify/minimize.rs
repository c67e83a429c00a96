//! Divergence groups — the cases of one signature (kind, field, rule), built as the run goes —
//! and the minimization of a group's first case: a generated case by proptest's shrinking of its
//! knobs, then, like a corpus program, by deleting lines while the same divergence stays.

use super::cases::Pending;
use super::{CaseRecord, MAX_MINIMIZED, SHRINK_STEPS};
use cycle_kernel::conformance::{Divergence, DivergenceKind};
use cycle_kernel::engine::{Engine, SpecEngine};
use cycle_kernel::judge::{judge, CaseResult};
use cycle_vocab::{Config, Rule};

/// A group lists the names of at most this many of its cases (`cases.jsonl` has them all).
pub const MAX_NAMES: usize = 100;

/// The identity of a divergence for grouping: kind, field, the reference's rule.
pub type Signature = (DivergenceKind, Option<&'static str>, Option<Rule>);

pub fn signature(d: &Divergence) -> Signature {
    (d.kind, d.field, d.rule)
}

/// A minimized divergent input.
#[derive(Clone, Debug)]
pub struct Minimized {
    pub program: Vec<u8>,
    pub config: Config,
    pub divergence: Divergence,
    /// `proptest shrinking, line deletion` or `line deletion`.
    pub method: &'static str,
    /// Engine runs spent.
    pub steps: usize,
}

/// The cases with one divergence signature.
pub struct Group {
    pub signature: Signature,
    /// How many cases diverge so.
    pub count: usize,
    /// The names of the first [`MAX_NAMES`] of them, in run order.
    pub names: Vec<String>,
    /// The first case.
    pub first: CaseRecord,
    /// The first case minimized (the first [`MAX_MINIMIZED`] groups only).
    pub minimized: Option<Minimized>,
    /// The first case as drawn, kept for its minimization.
    pending: Option<Pending>,
}

/// Adds a judged case to the groups: its group's index when it diverges. `pending` (the case
/// as drawn) is kept for minimization when the case opens one of the first groups.
pub(super) fn add(groups: &mut Vec<Group>, record: &CaseRecord, pending: Option<Pending>) -> Option<usize> {
    let CaseResult::Diverge(d) = &record.result else { return None };
    let sig = signature(d);
    if let Some(g) = groups.iter().position(|g| g.signature == sig) {
        let group = &mut groups[g];
        group.count += 1;
        if group.names.len() < MAX_NAMES {
            group.names.push(record.name.clone());
        }
        return Some(g);
    }
    let first = CaseRecord { traces: None, ..record.clone() };
    let pending = pending.filter(|_| groups.len() < MAX_MINIMIZED);
    groups.push(Group { signature: sig, count: 1, names: vec![record.name.clone()], first, minimized: None, pending });
    Some(groups.len() - 1)
}

/// Minimizes the first case of each group that kept it, reporting progress.
pub(super) fn minimize_groups(engine: &dyn Engine, groups: &mut [Group], progress: &mut dyn FnMut(usize, usize)) {
    let total = groups.iter().filter(|g| g.pending.is_some()).count();
    for (n, g) in groups.iter_mut().filter(|g| g.pending.is_some()).enumerate() {
        progress(n, total);
        if let Some(mut p) = g.pending.take() {
            g.minimized = minimize(engine, &g.first, &mut p, g.signature);
        }
    }
    if total > 0 {
        progress(total, total);
    }
}

/// The divergence of `program` if it has signature `sig`.
fn diverges_as(engine: &dyn Engine, program: &[u8], config: &Config, sig: Signature) -> Option<Divergence> {
    match judge(&SpecEngine, engine, program, config).result {
        CaseResult::Diverge(d) if signature(&d) == sig => Some(*d),
        _ => None,
    }
}

/// The smallest input found that diverges with the same signature.
fn minimize(engine: &dyn Engine, record: &CaseRecord, pending: &mut Pending, sig: Signature) -> Option<Minimized> {
    let CaseResult::Diverge(first) = &record.result else { return None };
    let mut best = Minimized {
        program: record.program.clone(),
        config: record.config,
        divergence: (**first).clone(),
        method: "line deletion",
        steps: 0,
    };
    let (params, dialect) = (pending.params, pending.dialect);
    if let Some(tree) = pending.tree.as_mut() {
        // proptest's shrinking: simplify while the case fails, complicate when it passes.
        best.method = "proptest shrinking, line deletion";
        let mut failing = true;
        while best.steps < SHRINK_STEPS {
            let moved = if failing { tree.simplify() } else { tree.complicate() };
            if !moved {
                break;
            }
            best.steps += 1;
            let case = tree.current();
            let mut config = case.config;
            config.dialect = dialect.unwrap_or(config.dialect);
            super::set_params(&params, &mut config);
            match diverges_as(engine, &case.program, &config, sig) {
                Some(d) => {
                    failing = true;
                    best.program = case.program;
                    best.config = config;
                    best.divergence = d;
                }
                None => failing = false,
            }
        }
    }
    // Delete one line at a time, last first, while the same divergence stays.
    let mut lines: Vec<Vec<u8>> = best.program.split_inclusive(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    let budget = best.steps + SHRINK_STEPS;
    let mut changed = true;
    while changed && best.steps < budget {
        changed = false;
        for i in (0..lines.len()).rev() {
            if best.steps >= budget || lines.len() <= 1 {
                break;
            }
            let mut shorter = lines.clone();
            shorter.remove(i);
            let program = shorter.concat();
            best.steps += 1;
            if let Some(d) = diverges_as(engine, &program, &best.config, sig) {
                lines = shorter;
                best.program = program;
                best.divergence = d;
                changed = true;
            }
        }
    }
    Some(best)
}

#[cfg(test)]
mod tests;
