//! Reading a shard's bundle back: a `cases.jsonl` line as the run's [`CaseRecord`], and the
//! divergences, minimized inputs and family runs of its `evidence.json` — the inverses of
//! [`super::super::tally::case_line`], [`cycle_kernel::conformance::to_json`] and the evidence writer.

use super::super::cases::FamilyRun;
use super::super::{CaseRecord, Minimized, Origin};
use cycle_kernel::conformance::{Divergence, DivergenceKind, Level};
use cycle_kernel::corpus;
use cycle_kernel::engine::{Failure, FailureKind};
use cycle_kernel::judge::CaseResult;
use cycle_kernel::registry::{self, CycleRun, FAMILIES};
use cycle_vocab::{Config, Rule};
use serde_json::Value;
use std::sync::Mutex;

/// Every failure kind, for reading their names back.
const FAILURE_KINDS: [FailureKind; 7] = [
    FailureKind::Panic,
    FailureKind::Spawn,
    FailureKind::Timeout,
    FailureKind::Crash,
    FailureKind::Garbage,
    FailureKind::OutputTooLarge,
    FailureKind::Refused,
];

/// The minimization methods [`super::super::minimize`] names.
const METHODS: [&str; 2] = ["proptest shrinking, line deletion", "line deletion"];

fn str_of<'v>(v: &'v Value, key: &str) -> Result<&'v str, String> {
    v[key].as_str().ok_or_else(|| format!("no string {key:?}"))
}

fn usize_of(v: &Value, key: &str) -> Result<usize, String> {
    v[key].as_u64().map(|n| n as usize).ok_or_else(|| format!("no number {key:?}"))
}

fn opt_string(v: &Value) -> Option<String> {
    v.as_str().map(str::to_string)
}

/// A divergence's field name as the `&'static str` the conformance relation uses: the names
/// are few, each is kept once for the process.
fn field_name(name: &str) -> &'static str {
    static NAMES: Mutex<Vec<&'static str>> = Mutex::new(Vec::new());
    let mut names = NAMES.lock().unwrap_or_else(|e| e.into_inner());
    if let Some(n) = names.iter().find(|n| **n == name) {
        return n;
    }
    let n: &'static str = Box::leak(name.to_string().into_boxed_str());
    names.push(n);
    n
}

fn rule(id: &str) -> Result<Rule, String> {
    Rule::from_id(id).ok_or_else(|| format!("unknown rule {id:?}"))
}

/// A divergence from its JSON ([`cycle_kernel::conformance::to_json`]).
pub fn divergence(v: &Value) -> Result<Divergence, String> {
    let kind_name = str_of(v, "kind")?;
    let kind = DivergenceKind::ALL.into_iter().find(|k| k.name() == kind_name).ok_or_else(|| format!("unknown divergence kind {kind_name:?}"))?;
    let values = match &v["values"] {
        Value::Null => None,
        vals => Some((str_of(vals, "reference")?.to_string(), str_of(vals, "candidate")?.to_string())),
    };
    let context = v["context"]
        .as_array()
        .ok_or("no context")?
        .iter()
        .map(|c| Ok((usize_of(c, "index")?, str_of(c, "line")?.to_string())))
        .collect::<Result<Vec<_>, String>>()?;
    Ok(Divergence {
        index: usize_of(v, "index")?,
        kind,
        field: v["field"].as_str().map(field_name),
        reference: str_of(v, "reference")?.to_string(),
        candidate: str_of(v, "candidate")?.to_string(),
        values,
        rule: v["rule"].as_str().map(rule).transpose()?,
        context,
        lengths: (usize_of(&v["lengths"], "reference")?, usize_of(&v["lengths"], "candidate")?),
        alarms: (opt_string(&v["alarms"]["reference"]), opt_string(&v["alarms"]["candidate"])),
        level: v["level"].as_str().map_or(Ok(Level::Full), Level::parse)?,
    })
}

/// A program from its JSON: the text, or `{"hex": …}` ([`super::super::tally::program_text`]).
pub fn program(v: &Value) -> Result<Vec<u8>, String> {
    if let Some(text) = v.as_str() {
        return Ok(text.as_bytes().to_vec());
    }
    let hex = str_of(v, "hex")?;
    (0..hex.len())
        .step_by(2)
        .map(|i| hex.get(i..i + 2).and_then(|b| u8::from_str_radix(b, 16).ok()).ok_or_else(|| format!("bad hex program {hex:?}")))
        .collect()
}

fn config(v: &Value) -> Result<Config, String> {
    serde_json::from_value(v.clone()).map_err(|e| format!("bad config: {e}"))
}

fn cycle(label: &str) -> Result<CycleRun, String> {
    FAMILIES
        .iter()
        .map(CycleRun::Family)
        .chain([CycleRun::NoCycle, CycleRun::AlarmFirst])
        .find(|c| c.label() == label)
        .ok_or_else(|| format!("unknown cycle {label:?}"))
}

/// A generator's name as the run's `&'static str`: a registry family, `operator` or `garbage`.
pub fn generator(name: &str) -> Result<&'static str, String> {
    match registry::find(name) {
        Some(f) => Ok(f.name),
        None if name == "garbage" => Ok("garbage"),
        None if name == "operator" => Ok("operator"),
        None => Err(format!("unknown generator {name:?}")),
    }
}

fn origin(v: &Value) -> Result<(Origin, Option<&'static corpus::Program>), String> {
    if let Some(path) = v["corpus"].as_str() {
        let p = corpus::PROGRAMS.iter().find(|p| p.path == path).ok_or_else(|| format!("no corpus program {path:?} in this build"))?;
        return Ok((Origin::Corpus { path: p.path }, Some(p)));
    }
    let family = generator(str_of(v, "generated")?)?;
    let index = v["index"].as_u64().and_then(|i| u32::try_from(i).ok()).ok_or("no index")?;
    Ok((Origin::Generated { family, index }, None))
}

fn result(v: &Value) -> Result<CaseResult, String> {
    match str_of(v, "result")? {
        "conform" => Ok(CaseResult::Conform),
        "diverge" => Ok(CaseResult::Diverge(Box::new(divergence(&v["divergence"])?))),
        "deviate" => Ok(CaseResult::Deviate { divergence: Box::new(divergence(&v["divergence"])?), declaration: usize_of(v, "declaration")? }),
        "fail" => {
            let kind_name = str_of(v, "kind")?;
            let kind = FAILURE_KINDS.into_iter().find(|k| k.name() == kind_name).ok_or_else(|| format!("unknown failure kind {kind_name:?}"))?;
            let failure = Failure { kind, message: str_of(v, "message")?.to_string() };
            Ok(CaseResult::Failure { engine: str_of(v, "engine")?.to_string(), failure })
        }
        other => Err(format!("unknown result {other:?}")),
    }
}

/// A `cases.jsonl` line as the case's record, without traces. A conforming case's line has
/// no program nor configuration: a corpus program's are the built-in ones; a generated case
/// gets an empty program and the default configuration (the merge takes the configuration
/// counts from the shards' `evidence.json`).
pub fn record(v: &Value) -> Result<CaseRecord, String> {
    let (origin, built_in) = origin(&v["origin"])?;
    let program = match (&v["program"], built_in) {
        (Value::Null, Some(p)) => p.text.as_bytes().to_vec(),
        (Value::Null, None) => Vec::new(),
        (text, _) => self::program(text)?,
    };
    let config = match (&v["config"], built_in) {
        (Value::Null, Some(p)) => p.config(),
        (Value::Null, None) => Config::default(),
        (c, _) => config(c)?,
    };
    let rules = v["rules"].as_array().ok_or("no rules")?.iter().map(|r| rule(r.as_str().unwrap_or_default())).collect::<Result<_, _>>()?;
    Ok(CaseRecord {
        name: str_of(v, "name")?.to_string(),
        origin,
        cycle: cycle(str_of(v, "cycle")?)?,
        program,
        config,
        events: usize_of(v, "events")?,
        rules,
        ending: str_of(v, "ending")?.to_string(),
        result: result(v)?,
        traces: None,
    })
}

/// A divergence group's minimized input from `evidence.json` (`null`: none).
pub fn minimized(v: &Value) -> Result<Option<Minimized>, String> {
    if v.is_null() {
        return Ok(None);
    }
    let method_name = str_of(v, "method")?;
    let method = METHODS.into_iter().find(|m| *m == method_name).ok_or_else(|| format!("unknown method {method_name:?}"))?;
    Ok(Some(Minimized {
        program: program(&v["program"])?,
        config: config(&v["config"])?,
        divergence: divergence(&v["divergence"])?,
        method,
        steps: usize_of(v, "steps")?,
    }))
}

/// The family runs of `evidence.json`.
pub fn families(v: &Value) -> Result<Vec<FamilyRun>, String> {
    let u32_of = |f: &Value, key: &str| usize_of(f, key).and_then(|n| u32::try_from(n).map_err(|e| e.to_string()));
    v.as_array()
        .ok_or("no families")?
        .iter()
        .map(|f| {
            let seed = f["seed"].as_u64().ok_or("no seed")?;
            Ok(FamilyRun { family: generator(str_of(f, "family")?)?, seed, drawn: u32_of(f, "drawn")?, kept: u32_of(f, "kept")? })
        })
        .collect()
}
