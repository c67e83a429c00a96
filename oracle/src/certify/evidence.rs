//! `evidence.json`: the machine-readable record of a certification run (schema
//! [`SCHEMA`], documented in the README): tool and protocol versions, fingerprints of the
//! catalogue and the register compiled in, the candidate and its limits, parameters and seeds,
//! counts per cycle run (each with what it counts), per rule and per configuration, every non-conforming case (program,
//! configuration, divergence or failure), the divergence groups with their minimized inputs, and
//! the traceability matrix.

use super::matrix::{self, Row};
use super::{CaseRecord, CaseResult, Origin, Run, MAX_MINIMIZED, SHRINK_STEPS};
use crate::conformance;
use crate::engine::FailureKind;
use cycle_vocab::{Config, Params};
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// The evidence file's schema version.
pub const SCHEMA: &str = "cyclecheck-evidence/1";

/// The rule catalogue and the interpretation register, as compiled in.
pub const RULES_MD: &str = include_str!("../../../docs/RULES.md");
pub const INTERPRETATION_MD: &str = include_str!("../../../docs/INTERPRETATION.md");

/// FNV-1a 64 of a document: which catalogue and register a bundle was made with.
pub fn fingerprint(text: &str) -> String {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    for b in text.bytes() {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    }
    format!("fnv1a64:{h:016x}")
}

fn program_text(program: &[u8]) -> Value {
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

fn config(c: &Config) -> Value {
    serde_json::to_value(c).unwrap_or(Value::Null)
}

fn result(r: &CaseResult) -> Value {
    match r {
        CaseResult::Conform => json!({ "result": "conform" }),
        CaseResult::Diverge(d) => json!({ "result": "diverge", "divergence": conformance::to_json(d) }),
        CaseResult::Failure { engine, failure } => json!({
            "result": "fail",
            "engine": engine,
            "kind": failure.kind.name(),
            "message": failure.message,
        }),
    }
}

fn case(r: &CaseRecord, group: Option<usize>) -> Value {
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
            m.insert("config".into(), config(&r.config));
        }
        if let Some(g) = group {
            m.insert("group".into(), json!(g));
        }
    }
    v
}

/// Counts of the configurations the cases ran under.
fn configurations(run: &Run) -> Value {
    let mut dialect: BTreeMap<String, usize> = BTreeMap::new();
    let mut grid: BTreeMap<String, usize> = BTreeMap::new();
    let mut non_default_params = 0;
    let mut non_zero_start = 0;
    for r in &run.records {
        *dialect.entry(format!("{:?}", r.config.dialect).to_lowercase()).or_default() += 1;
        *grid.entry(format!("{:?} {:?}", r.config.grid.units, r.config.grid.increment).to_lowercase()).or_default() += 1;
        non_default_params += usize::from(r.config.params != Params::default());
        non_zero_start += usize::from((r.config.start_x, r.config.start_z) != (0, 0));
    }
    json!({
        "dialect": dialect,
        "grid": grid,
        "cases_with_parameters_set": non_default_params,
        "cases_with_a_start_point": non_zero_start,
        "default_parameters": cycle_spec::config::DEFAULTS.as_set(),
    })
}

fn matrix_json(rows: &[Row]) -> Value {
    rows.iter()
        .map(|r| {
            let mut by_kind = serde_json::Map::new();
            for k in matrix::Kind::ALL {
                let cites: Vec<Value> =
                    r.of(k).map(|c| json!({ "file": c.file, "line": c.line, "item": c.item })).collect();
                by_kind.insert(k.name().to_string(), Value::Array(cites));
            }
            json!({
                "id": r.id,
                "family": r.group.name(),
                "source": r.source,
                "text": r.text,
                "status": r.status,
                "implemented": r.implemented,
                "citations": by_kind,
                "outcome": r.outcome,
                "result": r.outcome.label(),
            })
        })
        .collect()
}

/// The whole evidence document.
pub fn document(run: &Run, rows: &[Row]) -> Value {
    let mut group_of = BTreeMap::new();
    for (g, group) in run.groups.iter().enumerate() {
        for &i in &group.cases {
            group_of.insert(i, g);
        }
    }
    let groups: Vec<Value> = run
        .groups
        .iter()
        .enumerate()
        .map(|(g, group)| {
            let (kind, field, rule) = group.signature;
            let first = &run.records[group.cases[0]];
            json!({
                "group": g,
                "signature": { "kind": kind.name(), "field": field, "rule": rule.map(|r| r.id()) },
                "count": group.cases.len(),
                "cases": group.cases.iter().map(|&i| run.records[i].name.as_str()).collect::<Vec<_>>(),
                "first": first.name,
                "minimized": group.minimized.as_ref().map(|m| json!({
                    "method": m.method,
                    "steps": m.steps,
                    "program": program_text(&m.program),
                    "config": config(&m.config),
                    "divergence": conformance::to_json(&m.divergence),
                })),
            })
        })
        .collect();
    let by_cycle: BTreeMap<&str, Value> = run
        .by_cycle()
        .into_iter()
        .map(|(c, [n, ok, div, fail])| {
            let counts = json!({ "name": c.name(), "counts": c.describe(), "cases": n, "conform": ok, "diverge": div, "fail": fail });
            (c.label(), counts)
        })
        .collect();
    let by_rule: BTreeMap<&str, Value> = run
        .by_rule()
        .into_iter()
        .map(|(r, (cases, divergences))| (r.id(), json!({ "cases": cases, "divergences": divergences })))
        .collect();
    let failures: BTreeMap<&str, usize> = run.failures_by_kind().into_iter().map(|(k, n)| (FailureKind::name(k), n)).collect();
    json!({
        "schema": SCHEMA,
        "tool": { "name": "cyclecheck", "version": env!("CARGO_PKG_VERSION"), "candidate_protocol": crate::candidate::SCHEMA },
        "documents": {
            "docs/RULES.md": fingerprint(RULES_MD),
            "docs/INTERPRETATION.md": fingerprint(INTERPRETATION_MD),
        },
        "reference": "spec",
        "candidate": {
            "name": run.candidate,
            "command": run.candidate_argv,
            "timeout_ms": run.candidate_argv.as_ref().map(|_| run.options.limits.timeout.as_millis() as u64),
            "max_output_bytes": run.candidate_argv.as_ref().map(|_| run.options.limits.max_output),
            "process_starts": run.candidate_argv.as_ref().map(|_| run.candidate_starts),
        },
        "parameters": {
            "cycles": run.options.cycles.iter().map(|f| f.name).collect::<Vec<_>>(),
            "cases_per_family": run.options.cases,
            "seed": run.options.seed,
            "shrink_steps": SHRINK_STEPS,
            "max_minimized_groups": MAX_MINIMIZED,
        },
        "families": run.families.iter().map(|f| json!({ "family": f.family, "seed": f.seed, "drawn": f.drawn, "kept": f.kept })).collect::<Vec<_>>(),
        "configurations": configurations(run),
        "summary": {
            "passed": run.passed(),
            "cases": run.cases(),
            "conform": run.conforming(),
            "diverge": run.diverging(),
            "fail": run.failures(),
            "divergence_groups": run.groups.len(),
            "duration_s": (run.duration.as_secs_f64() * 1000.0).round() / 1000.0,
        },
        "by_cycle": by_cycle,
        "by_rule": by_rule,
        "failures": failures,
        "divergences": groups,
        "cases": run.records.iter().enumerate().map(|(i, r)| case(r, group_of.get(&i).copied())).collect::<Vec<_>>(),
        "matrix": matrix_json(rows),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fingerprints_differ_and_are_stable() {
        assert_eq!(fingerprint(""), "fnv1a64:cbf29ce484222325");
        assert_ne!(fingerprint(RULES_MD), fingerprint(INTERPRETATION_MD));
    }
}
