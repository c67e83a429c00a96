//! The traceability matrix: each rule of the catalogue (`docs/RULES.md`) → the spec code that
//! states it, the production code that implements it, the tests, proofs and fuzz targets that
//! check it, and its result in a run. Rows are grouped by cycle family
//! ([`cycle_kernel::registry::rule_group`]): each family's rules, then the rules common to all (COM,
//! PRJ), then those of no family yet; catalogue order within a group.
//!
//! The citations are found at build time (`cyclecheck/build/main.rs` scans the workspace for rule IDs
//! and `Rule::` variants) and compiled in, so an installed `cyclecheck` needs no source tree.
//! A citation in a module's documentation (`//!`, outside any item) is a *mention*: shown apart,
//! it neither implements nor checks the rule.
//!
//! A rule is *exercised* in a run when a case's reference trace or alarm carries its tag, or
//! when a built-in program that illustrates it ([`cycle_kernel::corpus::Program::rules`]) ran and
//! conformed.

use super::Run;
use cycle_kernel::catalogue;
use cycle_kernel::registry::{self, RuleGroup};
use cycle_vocab::Rule;
use serde::Serialize;

/// What kind of code a citation is in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Kind {
    /// The executable reference spec (`spec/src`).
    Spec,
    /// The production expander (`impl/src`).
    Impl,
    /// Code both engines share (`vocab/src`: lexer, word values, trace).
    Shared,
    /// Unit, snapshot, property and differential tests; the corpus and the generators.
    Test,
    /// Proof harnesses (`proofs/src`).
    Proof,
    /// Fuzz targets and their drivers.
    Fuzz,
}

impl Kind {
    pub const ALL: [Kind; 6] = [Kind::Spec, Kind::Impl, Kind::Shared, Kind::Test, Kind::Proof, Kind::Fuzz];

    pub const fn name(self) -> &'static str {
        match self {
            Kind::Spec => "spec",
            Kind::Impl => "impl",
            Kind::Shared => "shared (vocab)",
            Kind::Test => "tests",
            Kind::Proof => "proofs",
            Kind::Fuzz => "fuzz",
        }
    }

    /// Whether citations of this kind check a rule (rather than state or implement it).
    pub const fn is_check(self) -> bool {
        matches!(self, Kind::Test | Kind::Proof | Kind::Fuzz)
    }
}

/// One place that cites a rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub struct Citation {
    pub rule: &'static str,
    pub kind: Kind,
    /// Path from the repository root.
    pub file: &'static str,
    /// 1-based line of the first citation of the rule in this item.
    pub line: u32,
    /// The enclosing item: `fn name`, `test name`, `proof name`, `corpus program name`, …
    pub item: &'static str,
}

impl Citation {
    /// Whether it is a mention in a module's documentation rather than code or a check.
    pub fn is_mention(&self) -> bool {
        self.item == MODULE_DOCS
    }
}

/// The item of a citation outside any item: a module's documentation.
pub const MODULE_DOCS: &str = "module docs";

include!(concat!(env!("OUT_DIR"), "/citations.rs"));

/// A rule's result in a run.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(tag = "result", rename_all = "snake_case")]
pub enum Outcome {
    /// Exercised — by `cases` cases whose trace or alarm carries it, and by `programs` built-in
    /// programs that illustrate it and conformed — and no divergence names it.
    Pass { cases: usize, programs: usize },
    /// `divergences` divergent cases name it (of `cases` exercising it).
    Fail { cases: usize, divergences: usize },
    /// Implemented, but no reference trace of this run carries its tag and no conforming
    /// built-in program illustrates it (rules such as COM.AXES shape every trace without tagging
    /// a move: see the citations for their checks).
    NotExercised,
    /// The catalogue does not mark it implemented (`later`, `unsupported`).
    NotImplemented,
}

impl Outcome {
    pub fn label(self) -> String {
        match self {
            Outcome::Pass { cases, programs: 0 } => format!("pass ({cases} cases)"),
            Outcome::Pass { cases: 0, programs } => format!("pass ({programs} built-in programs)"),
            Outcome::Pass { cases, programs } => format!("pass ({cases} cases; {programs} built-in programs)"),
            Outcome::Fail { cases, divergences } => format!("FAIL ({divergences} of {cases} cases)"),
            Outcome::NotExercised => "not exercised in this run".to_string(),
            Outcome::NotImplemented => "not implemented".to_string(),
        }
    }
}

/// One row of the matrix.
#[derive(Clone, Debug)]
pub struct Row {
    pub id: &'static str,
    /// The family group the rule stands in.
    pub group: RuleGroup,
    pub source: &'static str,
    pub text: &'static str,
    /// The catalogue's status column.
    pub status: &'static str,
    /// Whether the status starts with `impl`.
    pub implemented: bool,
    pub citations: Vec<Citation>,
    pub outcome: Outcome,
}

impl Row {
    /// The citations of one kind, mentions aside.
    pub fn of(&self, kind: Kind) -> impl Iterator<Item = &Citation> {
        self.citations.iter().filter(move |c| c.kind == kind && !c.is_mention())
    }

    /// The mentions in module documentation.
    pub fn mentions(&self) -> impl Iterator<Item = &Citation> {
        self.citations.iter().filter(|c| c.is_mention())
    }

    /// Whether it points at code: the spec, the production expander, or code they share.
    pub fn has_code(&self) -> bool {
        Kind::ALL.iter().any(|&k| matches!(k, Kind::Spec | Kind::Impl | Kind::Shared) && self.of(k).next().is_some())
    }

    /// Whether a test, proof or fuzz target checks it (a mention is no check).
    pub fn has_check(&self) -> bool {
        Kind::ALL.iter().any(|&k| k.is_check() && self.of(k).next().is_some())
    }

    /// Whether the run exercised it.
    pub fn exercised(&self) -> bool {
        matches!(self.outcome, Outcome::Pass { .. } | Outcome::Fail { .. })
    }
}

/// The citations of `rule`, by kind, then file and line.
pub fn citations(rule: Rule) -> Vec<Citation> {
    let mut c: Vec<Citation> = CITATIONS.iter().filter(|c| c.rule == rule.id()).copied().collect();
    c.sort_by(|a, b| (a.kind, a.file, a.line).cmp(&(b.kind, b.file, b.line)));
    c
}

/// The matrix: one row per catalogue rule, by group, in catalogue order within a group, with
/// results from `run` (when given: otherwise every implemented rule is `NotExercised`).
pub fn rows(run: Option<&Run>) -> Vec<Row> {
    let by_rule = run.map(Run::by_rule).unwrap_or_default();
    let illustrated = run.map(Run::illustrated).unwrap_or_default();
    let mut rows: Vec<Row> = Rule::ALL
        .iter()
        .map(|&rule| {
            let entry = catalogue::entry(rule);
            let status = entry.map_or("missing from docs/RULES.md", |e| e.status);
            let implemented = status.starts_with("impl");
            let (cases, divergences) = by_rule.get(&rule).copied().unwrap_or((0, 0));
            let programs = illustrated.get(&rule).copied().unwrap_or(0);
            let outcome = match (implemented, cases + programs, divergences) {
                (_, _, d) if d > 0 => Outcome::Fail { cases, divergences: d },
                (false, _, _) => Outcome::NotImplemented,
                (true, 0, _) => Outcome::NotExercised,
                (true, _, _) => Outcome::Pass { cases, programs },
            };
            Row {
                id: rule.id(),
                group: registry::rule_group(rule),
                source: entry.map_or("", |e| e.source),
                text: entry.map_or("", |e| e.text),
                status,
                implemented,
                citations: citations(rule),
                outcome,
            }
        })
        .collect();
    rows.sort_by_key(|r| r.group);
    rows
}

/// Rules exercised in the run, and rules implemented.
pub fn coverage(rows: &[Row]) -> (usize, usize) {
    let implemented = rows.iter().filter(|r| r.implemented);
    (implemented.clone().filter(|r| r.exercised()).count(), implemented.count())
}

#[cfg(test)]
mod tests;
