//! What a run keeps of its cases: counts — per result, cycle run, rule, failure kind and
//! configuration — and, for the bundle's `cases.jsonl`, one JSON line per case written as it is
//! judged ([`case_line`]). Nothing here grows with the number of cases but the counts' keys.

use super::{CaseRecord, Origin};
use cycle_kernel::conformance;
use cycle_kernel::engine::FailureKind;
use cycle_kernel::judge::CaseResult;
use cycle_kernel::registry::CycleRun;
use cycle_vocab::{Params, Rule};
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// At most this many refusal messages are counted apart.
pub const MAX_REASONS: usize = 64;
/// Where the refusals of later messages are counted.
pub const OTHER_REASONS: &str = "(other reasons)";

/// The counts of a run.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    pub cases: usize,
    pub conform: usize,
    /// Cases whose first divergence is a declared deviation ([`CaseResult::Deviate`]).
    pub deviate: usize,
    pub diverge: usize,
    pub fail: usize,
    /// Per cycle run: cases, conform, deviate as declared, diverge, fail.
    pub by_cycle: BTreeMap<CycleRun, [usize; 5]>,
    /// Per declared deviation (its index): the cases that deviate so.
    pub by_declaration: BTreeMap<usize, usize>,
    /// Per rule: cases whose reference trace carries it, divergences that name it.
    pub by_rule: BTreeMap<Rule, (usize, usize)>,
    pub failures_by_kind: BTreeMap<FailureKind, usize>,
    /// Per cycle run: the refusals among its failures.
    pub refused_by_cycle: BTreeMap<CycleRun, usize>,
    /// The candidate's refusals by their message (the first [`MAX_REASONS`] messages; later
    /// ones under [`OTHER_REASONS`]).
    pub refusal_reasons: BTreeMap<String, usize>,
    /// Cases per dialect and per grid (`metric isb`), with parameters set, with a start point.
    pub dialect: BTreeMap<String, usize>,
    pub grid: BTreeMap<String, usize>,
    pub with_parameters: usize,
    pub with_start: usize,
    /// Cases run with an operator script (OP.SCRIPT).
    pub with_operator_script: usize,
    /// Cases per declared reading and value.
    pub readings: cycle_kernel::readings::Counts,
}

impl Tally {
    pub fn add(&mut self, r: &CaseRecord) {
        self.cases += 1;
        let c = self.by_cycle.entry(r.cycle).or_default();
        c[0] += 1;
        match &r.result {
            CaseResult::Conform => {
                self.conform += 1;
                c[1] += 1;
            }
            CaseResult::Deviate { declaration, .. } => {
                self.deviate += 1;
                c[2] += 1;
                *self.by_declaration.entry(*declaration).or_default() += 1;
            }
            CaseResult::Diverge(d) => {
                self.diverge += 1;
                c[3] += 1;
                if let Some(rule) = d.rule {
                    self.by_rule.entry(rule).or_default().1 += 1;
                }
            }
            CaseResult::Failure { failure, .. } => {
                self.fail += 1;
                c[4] += 1;
                *self.failures_by_kind.entry(failure.kind).or_default() += 1;
                if failure.kind == FailureKind::Refused {
                    *self.refused_by_cycle.entry(r.cycle).or_default() += 1;
                    let known = self.refusal_reasons.contains_key(&failure.message) || self.refusal_reasons.len() < MAX_REASONS;
                    let reason = if known { failure.message.clone() } else { OTHER_REASONS.to_string() };
                    *self.refusal_reasons.entry(reason).or_default() += 1;
                }
            }
        }
        for &rule in &r.rules {
            self.by_rule.entry(rule).or_default().0 += 1;
        }
        *self.dialect.entry(format!("{:?}", r.config.dialect).to_lowercase()).or_default() += 1;
        *self.grid.entry(format!("{:?} {:?}", r.config.grid.units, r.config.grid.increment).to_lowercase()).or_default() += 1;
        self.with_parameters += usize::from(r.config.params != Params::default());
        self.with_start += usize::from((r.config.start_x, r.config.start_z) != (0, 0));
        self.with_operator_script += usize::from(!r.config.operator.is_empty());
        self.readings.add(&r.config.readings);
    }

    /// The configurations the cases ran under, for `evidence.json`.
    pub fn configurations(&self) -> Value {
        json!({
            "dialect": self.dialect,
            "grid": self.grid,
            "cases_with_parameters_set": self.with_parameters,
            "cases_with_a_start_point": self.with_start,
            "cases_with_an_operator_script": self.with_operator_script,
            "default_parameters": cycle_spec::config::DEFAULTS.as_set(),
        })
    }
}

/// A program as JSON: its text, or `{"hex": …}` when it is not UTF-8.
pub fn program_text(program: &[u8]) -> Value {
    match std::str::from_utf8(program) {
        Ok(t) => json!(t),
        Err(_) => json!({ "hex": program.iter().map(|b| format!("{b:02x}")).collect::<String>() }),
    }
}

fn origin(o: &Origin) -> Value {
    match o {
        Origin::Corpus { path } => json!({ "corpus": path }),
        Origin::Generated { family, index } => json!({ "generated": family, "index": index }),
    }
}

/// A case's result as JSON fields.
fn result(r: &CaseResult) -> Value {
    match r {
        CaseResult::Conform => json!({ "result": "conform" }),
        CaseResult::Diverge(d) => json!({ "result": "diverge", "divergence": conformance::to_json(d) }),
        CaseResult::Deviate { divergence, declaration } => {
            json!({ "result": "deviate", "declaration": declaration, "divergence": conformance::to_json(divergence) })
        }
        CaseResult::Failure { engine, failure } => json!({
            "result": "fail",
            "engine": engine,
            "kind": failure.kind.name(),
            "message": failure.message,
        }),
    }
}

/// One case as a line of `cases.jsonl` (without the newline): name, origin, cycle, events,
/// ending, rules, result; the program and configuration of a case that does not conform; its
/// divergence group.
pub fn case_line(r: &CaseRecord, group: Option<usize>) -> String {
    let mut v = json!({
        "name": r.name,
        "origin": origin(&r.origin),
        "cycle": r.cycle.label(),
        "events": r.events,
        "ending": r.ending,
        "rules": r.rules.iter().map(|r| r.id()).collect::<Vec<_>>(),
    });
    if let (Value::Object(m), Value::Object(res)) = (&mut v, result(&r.result)) {
        m.extend(res);
        if !r.result.conforms() {
            m.insert("program".into(), program_text(&r.program));
            m.insert("config".into(), serde_json::to_value(r.config).unwrap_or(Value::Null));
        }
        if let Some(g) = group {
            m.insert("group".into(), json!(g));
        }
    }
    v.to_string()
}
