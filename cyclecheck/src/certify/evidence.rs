//! `evidence.json`: the machine-readable record of a certification run (schema [`SCHEMA`],
//! documented in docs/CERTIFY.md): the run's identity (time, build, host, candidate executable and
//! its SHA-256), tool and protocol versions, fingerprints of the catalogue and the register
//! compiled in, the candidate and its limits, parameters and seeds, counts per cycle run (each
//! with what it counts), per rule and per configuration, the failures listed, the divergence
//! groups with their minimized inputs, and the traceability matrix. Every case is in
//! `cases.jsonl`, one JSON object per line, written during the run. A shard's bundle names its
//! shard (`parameters.shard`, `K/N`); a merged bundle lists its shards (`merged_from`).

use super::matrix::{self, Row};
use super::tally::program_text;
use super::{CaseResult, Run, MAX_LISTED_FAILURES, MAX_MINIMIZED, SHRINK_STEPS};
use cycle_kernel::conformance;
use cycle_kernel::engine::FailureKind;
use cycle_vocab::Config;
use serde_json::{json, Value};
use std::collections::BTreeMap;

/// The evidence file's schema version (2: cases in `cases.jsonl`, the run's identity).
pub const SCHEMA: &str = "cyclecheck-evidence/2";

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

fn config(c: &Config) -> Value {
    serde_json::to_value(c).unwrap_or(Value::Null)
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
                "mentions": r.mentions().map(|c| json!({ "file": c.file, "line": c.line, "kind": c.kind.name() })).collect::<Vec<_>>(),
                "result": r.outcome.label(),
            })
        })
        .collect()
}

fn groups(run: &Run) -> Vec<Value> {
    run.groups
        .iter()
        .enumerate()
        .map(|(g, group)| {
            let (kind, field, rule) = group.signature;
            json!({
                "group": g,
                "signature": { "kind": kind.name(), "field": field, "rule": rule.map(|r| r.id()) },
                "count": group.count,
                "cases": group.names,
                "first": group.first.name,
                "minimized": group.minimized.as_ref().map(|m| json!({
                    "method": m.method,
                    "steps": m.steps,
                    "program": program_text(&m.program),
                    "config": config(&m.config),
                    "divergence": conformance::to_json(&m.divergence),
                })),
            })
        })
        .collect()
}

/// The failed cases listed (the first [`MAX_LISTED_FAILURES`]).
fn failures(run: &Run) -> Value {
    let listed: Vec<Value> = run
        .failures
        .iter()
        .filter_map(|r| match &r.result {
            CaseResult::Failure { engine, failure } => Some(json!({
                "name": r.name,
                "engine": engine,
                "kind": failure.kind.name(),
                "message": failure.message,
            })),
            _ => None,
        })
        .collect();
    let by_kind: BTreeMap<&str, usize> = run.failures_by_kind().into_iter().map(|(k, n)| (FailureKind::name(k), n)).collect();
    json!({ "by_kind": by_kind, "listed": listed, "listed_at_most": MAX_LISTED_FAILURES })
}

/// The declared deviations with the cases that deviate so; the unused ones listed apart.
fn deviations(run: &Run) -> Value {
    let declared: Vec<Value> = run
        .options
        .deviations
        .iter()
        .enumerate()
        .map(|(k, d)| {
            let mut v = d.json();
            v["declaration"] = json!(k);
            v["cases"] = json!(run.tally.by_declaration.get(&k).copied().unwrap_or(0));
            v
        })
        .collect();
    json!({
        "level": run.level.name(),
        "declared": declared,
        "unused": run.unused_deviations(),
        "note": "a case that deviates as declared is not compared past its first divergence",
    })
}

/// The whole evidence document.
pub fn document(run: &Run, rows: &[Row]) -> Value {
    let by_cycle: BTreeMap<&str, Value> = run
        .by_cycle()
        .into_iter()
        .map(|(c, [n, ok, dev, div, fail])| {
            let counts = json!({ "name": c.name(), "counts": c.describe(), "cases": n, "conform": ok, "deviate": dev, "diverge": div, "fail": fail });
            (c.label(), counts)
        })
        .collect();
    let illustrated = run.illustrated();
    let by_rule: BTreeMap<&str, Value> = run
        .by_rule()
        .into_iter()
        .map(|(r, (cases, divergences))| (r.id(), json!({ "cases": cases, "divergences": divergences, "programs": illustrated.get(&r).copied().unwrap_or(0) })))
        .collect();
    let (exercised, implemented) = matrix::coverage(rows);
    json!({
        "schema": SCHEMA,
        "identity": run.identity,
        "proofs": run.proofs.json(),
        "tool": { "name": "cyclecheck", "version": env!("CARGO_PKG_VERSION"), "build": super::identity::LONG_VERSION, "candidate_protocol": crate::candidate::SCHEMA },
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
            "max_failures": run.candidate_argv.as_ref().map(|_| run.options.max_failures),
            "process_starts": run.candidate_argv.as_ref().map(|_| run.candidate_starts),
            "level": run.level.name(),
        },
        "parameters": {
            "cycles": run.options.cycle_names(),
            "cases_per_family": run.options.cases,
            "seed": run.options.seed,
            "shard": run.options.shard.map(|s| s.to_string()),
            "readings": run.readings.json(),
            "shrink_steps": SHRINK_STEPS,
            "max_minimized_groups": MAX_MINIMIZED,
            "level": run.options.level.map(|l| l.name()),
            "dialect": run.options.dialect.map(super::deviations::dialect_name),
            "params": run.options.params,
            "deviations": run.options.deviations.iter().map(super::deviations::Deviation::json).collect::<Vec<_>>(),
        },
        "families": run.families.iter().map(|f| json!({ "family": f.family, "seed": f.seed, "drawn": f.drawn, "kept": f.kept })).collect::<Vec<_>>(),
        "configurations": run.tally.configurations(),
        "readings": run.readings.evidence(&run.tally.readings),
        "summary": {
            "passed": run.passed(),
            "verdict": run.verdict(),
            "level": run.level.name(),
            "cases": run.cases(),
            "conform": run.conforming(),
            "deviate": run.deviating(),
            "diverge": run.diverging(),
            "fail": run.failures(),
            "divergence_groups": run.groups.len(),
            "stopped": run.stopped.map(|s| json!({
                "reason": "max_failures",
                "consecutive_failures": s.consecutive_failures,
                "judged": s.judged,
                "planned": s.planned,
            })),
            "rules_exercised": exercised,
            "rules_implemented": implemented,
            "duration_s": (run.duration.as_secs_f64() * 1000.0).round() / 1000.0,
        },
        "by_cycle": by_cycle,
        "by_rule": by_rule,
        "failures": failures(run),
        "divergences": groups(run),
        "deviations": deviations(run),
        "cases": { "file": "cases.jsonl", "count": run.cases() },
        "matrix": matrix_json(rows),
        "merged_from": run.merged_from,
    })
}

#[cfg(test)]
mod tests;
