//! `cyclecheck merge`: joins the bundles of shards 1/N … N/N ([`super::shard`]) into the
//! bundle of the whole run — the same verdict, counts, divergence groups (numbered, listed and
//! minimized as the whole run has them), failures listed, traceability matrix and
//! `evidence.json`; the page regenerated, the corpus plots copied. What differs from the whole
//! run's bundle: the identity's start time (the earliest shard's) and host (the first shard's),
//! the duration (the longest shard's), the candidate's process starts (summed), the proofs
//! (the z3 lemmas run again by the merge), and `merged_from`, which lists the shards.
//!
//! The shards' `cases.jsonl` are merged as streams, in the whole run's order (corpus, then each
//! generator's cases by number), one line per shard in memory; the merge keeps what a run keeps
//! ([`super::tally`]), so its memory does not grow with the number of cases either.
//!
//! A shard stopped by `--max-failures` merges into a stopped bundle; where a whole run would
//! have stopped cannot be told from shards, so that bundle's counts are not the whole run's.

mod check;
pub mod read;

use super::bundle::Staging;
use super::shard::ShardRun;
use super::{kani, minimize, proofs, tally, CaseRecord, CaseResult, Options, Origin, Run, Stopped, MAX_LISTED_FAILURES, MAX_MINIMIZED};
use crate::candidate::Limits;
use cycle_kernel::corpus;
use cycle_kernel::registry::FAMILIES;
use serde_json::Value;
use std::collections::BTreeMap;
use std::io::{BufRead, BufReader, BufWriter, Lines, Write};
use std::path::{Path, PathBuf};
use std::time::Duration;

/// A case's place in the whole run: (source, number) — the corpus is source 0, each
/// generator the next, in run order (the registry's, then operator, garbage last).
type Key = (usize, usize);

fn key(record: &CaseRecord) -> Key {
    match record.origin {
        Origin::Corpus { path } => (0, corpus::PROGRAMS.iter().position(|p| p.path == path).unwrap_or(usize::MAX)),
        Origin::Generated { family, index } => {
            let source = match family {
                "operator" => FAMILIES.len(),
                "garbage" => FAMILIES.len() + 1,
                _ => FAMILIES.iter().position(|f| f.name == family).unwrap_or(FAMILIES.len() + 2),
            };
            (1 + source, index as usize)
        }
    }
}

/// One shard's `cases.jsonl`, read a line ahead.
struct Stream {
    shard: usize,
    path: PathBuf,
    lines: Lines<BufReader<std::fs::File>>,
    head: Option<(Key, CaseRecord, Value)>,
    read: usize,
}

impl Stream {
    fn open(shard: usize, dir: &Path) -> Result<Stream, String> {
        let path = dir.join("cases.jsonl");
        let file = std::fs::File::open(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        let mut s = Stream { shard, path, lines: BufReader::with_capacity(1 << 16, file).lines(), head: None, read: 0 };
        s.advance()?;
        Ok(s)
    }

    fn advance(&mut self) -> Result<(), String> {
        let previous = self.head.as_ref().map(|h| h.0);
        self.head = match self.lines.next() {
            None => None,
            Some(line) => {
                self.read += 1;
                let here = || format!("{} line {}", self.path.display(), self.read);
                let line = line.map_err(|e| format!("{}: {e}", here()))?;
                let v: Value = serde_json::from_str(&line).map_err(|e| format!("{}: not JSON: {e}", here()))?;
                let record = read::record(&v).map_err(|e| format!("{}: {e}", here()))?;
                let k = key(&record);
                if previous.is_some_and(|p| p >= k) {
                    return Err(format!("{}: case {} out of the run's order", here(), record.name));
                }
                Some((k, record, v))
            }
        };
        Ok(())
    }
}

/// What the merge was asked: the shard bundles, where the merged bundle goes, a Kani log.
pub struct Request {
    pub bundles: Vec<PathBuf>,
    pub out: PathBuf,
    pub kani_log: Option<kani::KaniLog>,
}

/// The options of the run the shards are slices of.
fn options(doc: &Value, kani_log: Option<kani::KaniLog>) -> Result<Options, String> {
    let p = &doc["parameters"];
    let names: Vec<&str> = p["cycles"].as_array().ok_or("no parameters.cycles")?.iter().filter_map(Value::as_str).collect();
    let c = &doc["candidate"];
    let defaults = Options::default();
    let limits = Limits {
        timeout: c["timeout_ms"].as_u64().map_or(defaults.limits.timeout, Duration::from_millis),
        max_output: c["max_output_bytes"].as_u64().map_or(defaults.limits.max_output, |n| n as usize),
    };
    let argv: Option<Vec<String>> = serde_json::from_value(c["command"].clone()).map_err(|e| format!("candidate.command: {e}"))?;
    Ok(Options {
        candidate: argv.map(|a| a.join(" ")),
        limits,
        cycles: Options::parse_cycles(&names.join(","))?,
        operator: Options::parse_operator(&names.join(",")),
        cases: p["cases_per_family"].as_u64().and_then(|n| u32::try_from(n).ok()).ok_or("no parameters.cases_per_family")?,
        seed: p["seed"].as_u64().ok_or("no parameters.seed")?,
        max_failures: c["max_failures"].as_u64().map_or(defaults.max_failures, |n| n as u32),
        kani_log,
        shard: None,
        readings: match super::readings_plan::Plan::from_json(&p["readings"])? {
            super::readings_plan::Plan::Drawn { pinned } | super::readings_plan::Plan::Declared { pinned, .. } => pinned,
        },
        deviations: p["deviations"].as_array().into_iter().flatten().map(super::deviations::Deviation::from_json).collect::<Result<_, _>>()?,
        level: p["level"].as_str().map(cycle_kernel::conformance::Level::parse).transpose()?,
        dialect: match p["dialect"].as_str() {
            None => None,
            Some(d) => Some(super::deviations::dialect(d).ok_or_else(|| format!("parameters.dialect: unknown dialect {d:?}"))?),
        },
        params: serde_json::from_value(p["params"].clone()).unwrap_or_default(),
    })
}

/// Sums the shards' configuration counts into `t` (a conforming case's line has no configuration).
fn add_configurations(t: &mut tally::Tally, doc: &Value) {
    let c = &doc["configurations"];
    for (field, counts) in [("dialect", &mut t.dialect), ("grid", &mut t.grid)] {
        for (k, n) in c[field].as_object().into_iter().flatten() {
            *counts.entry(k.clone()).or_default() += n.as_u64().unwrap_or(0) as usize;
        }
    }
    t.with_parameters += c["cases_with_parameters_set"].as_u64().unwrap_or(0) as usize;
    t.with_start += c["cases_with_a_start_point"].as_u64().unwrap_or(0) as usize;
    t.with_operator_script += c["cases_with_an_operator_script"].as_u64().unwrap_or(0) as usize;
    t.readings.add_json(&doc["readings"]["cases"]);
}

/// Merges the shards into `request.out`; the merged run, as its bundle says.
pub fn merge(request: &Request) -> Result<Run, String> {
    let mut bundles = request.bundles.iter().map(|d| check::read(d)).collect::<Result<Vec<_>, _>>()?;
    check::check(&mut bundles)?;
    let staging = Staging::create(&request.out).map_err(|e| format!("--out {}: {e}", request.out.display()))?;
    let first = &bundles[0].doc;
    let options = options(first, request.kani_log.clone())?;
    let identity_of = |doc: &Value| -> Result<super::identity::Identity, String> {
        let id = &doc["identity"];
        Ok(super::identity::Identity {
            started_utc: id["started_utc"].as_str().unwrap_or_default().to_string(),
            build: super::identity::BUILD,
            host: serde_json::from_value(id["host"].clone()).map_err(|e| format!("identity.host: {e}"))?,
            candidate: serde_json::from_value(id["candidate"].clone()).map_err(|e| format!("identity.candidate: {e}"))?,
        })
    };
    let mut identity = identity_of(first)?;
    let mut merged_from = Vec::new();
    let (mut tally, mut configurations, mut families) = (tally::Tally::default(), tally::Tally::default(), read::families(&first["families"])?);
    families.iter_mut().for_each(|f| f.kept = 0);
    let (mut duration, mut starts, mut stopped) = (0.0f64, 0u64, None::<Stopped>);
    for b in &bundles {
        let (doc, summary) = (&b.doc, &b.doc["summary"]);
        let id = identity_of(doc)?;
        identity.started_utc = identity.started_utc.min(id.started_utc.clone());
        let seconds = summary["duration_s"].as_f64().unwrap_or(0.0);
        duration = duration.max(seconds);
        starts += doc["candidate"]["process_starts"].as_u64().unwrap_or(0);
        add_configurations(&mut configurations, doc);
        for (f, g) in families.iter_mut().zip(read::families(&doc["families"])?) {
            f.kept += g.kept;
        }
        if let Some(s) = summary["stopped"].as_object() {
            let consecutive = s.get("consecutive_failures").and_then(Value::as_u64).unwrap_or(0) as u32;
            let planned = s.get("planned").and_then(Value::as_u64).unwrap_or(0) as usize;
            let st = stopped.get_or_insert(Stopped { consecutive_failures: 0, judged: 0, planned });
            st.consecutive_failures = st.consecutive_failures.max(consecutive);
        }
        let dir = b.dir.display().to_string();
        let cases = summary["cases"].as_u64().unwrap_or(0) as usize;
        merged_from.push(ShardRun { shard: b.shard.to_string(), bundle: dir, started_utc: id.started_utc, host: id.host.name, duration_s: seconds, cases });
    }
    // Each shard's divergence groups: its minimized input, by the shard's group number.
    let local_minimized: Vec<Vec<Value>> = bundles
        .iter()
        .map(|b| b.doc["divergences"].as_array().into_iter().flatten().map(|g| g["minimized"].clone()).collect())
        .collect();
    let file = staging.create_file("cases.jsonl").map_err(|e| format!("--out {}: {e}", request.out.display()))?;
    let mut out = BufWriter::with_capacity(1 << 16, file);
    let write_error = |e: std::io::Error| format!("cannot write cases.jsonl: {e}");
    let mut streams = bundles.iter().enumerate().map(|(i, b)| Stream::open(i, &b.dir)).collect::<Result<Vec<_>, _>>()?;
    let (mut corpus, mut failures, mut groups, mut plot_dirs) = (Vec::new(), Vec::new(), Vec::new(), BTreeMap::new());
    let mut last: Option<Key> = None;
    while let Some(next) = streams.iter_mut().filter(|s| s.head.is_some()).min_by_key(|s| s.head.as_ref().map(|h| h.0)) {
        let (k, record, mut line) = next.head.take().ok_or("no case")?;
        let (shard, path) = (next.shard, next.path.clone());
        next.advance()?;
        if last == Some(k) {
            return Err(format!("{}: case {} is in two shards", path.display(), record.name));
        }
        let owner = bundles[shard].shard;
        if !owner.contains(k.1) {
            return Err(format!("{}: case {} is not shard {owner}'s", path.display(), record.name));
        }
        last = Some(k);
        tally.add(&record);
        let opened = groups.len();
        let group = minimize::add(&mut groups, &record, None);
        if let Some(g) = group {
            if g == opened && g < MAX_MINIMIZED {
                let local = line["group"].as_u64().ok_or_else(|| format!("{}: diverging case {} has no group", path.display(), record.name))?;
                let m = local_minimized[shard].get(local as usize).ok_or_else(|| format!("{}: no divergence group {local}", path.display()))?;
                groups[g].minimized = read::minimized(m).map_err(|e| format!("{}: group {local}: {e}", bundles[shard].dir.display()))?;
            }
            line["group"] = Value::from(g);
        }
        writeln!(out, "{line}").map_err(write_error)?;
        if matches!(record.result, CaseResult::Failure { .. }) && failures.len() < MAX_LISTED_FAILURES {
            failures.push(record.clone());
        }
        if matches!(record.origin, Origin::Corpus { .. }) {
            plot_dirs.insert(record.name.clone(), bundles[shard].dir.clone());
            corpus.push(record);
        }
    }
    out.flush().map_err(write_error)?;
    drop(out);
    for (s, b) in streams.iter().zip(&bundles) {
        let expected = b.doc["summary"]["cases"].as_u64().unwrap_or(0) as usize;
        if s.read != expected {
            return Err(format!("{}: {} cases where its evidence.json counts {expected} (truncated?)", s.path.display(), s.read));
        }
    }
    if let Some(st) = stopped.as_mut() {
        st.judged = tally.cases;
    }
    // The records' configurations are not all known (see `read::record`): the shards' counts are.
    (tally.dialect, tally.grid) = (configurations.dialect, configurations.grid);
    (tally.with_parameters, tally.with_start) = (configurations.with_parameters, configurations.with_start);
    tally.with_operator_script = configurations.with_operator_script;
    tally.readings = configurations.readings;
    let run = Run {
        candidate: first["candidate"]["name"].as_str().unwrap_or("impl").to_string(),
        candidate_argv: serde_json::from_value(first["candidate"]["command"].clone()).unwrap_or(None),
        candidate_starts: starts,
        identity,
        tally,
        corpus,
        failures,
        families,
        groups,
        stopped,
        proofs: proofs::Proofs::check(options.kani_log.clone()),
        duration: Duration::from_secs_f64(duration),
        merged_from,
        readings: super::readings_plan::Plan::from_json(&first["parameters"]["readings"])?,
        level: first["candidate"]["level"].as_str().map_or(Ok(cycle_kernel::conformance::Level::Full), cycle_kernel::conformance::Level::parse)?,
        options,
    };
    let mut plot_error = None;
    let files = super::bundle::files_with_plots(&run, &mut |r| {
        let path = plot_dirs.get(&r.name)?.join(format!("plots/{}.svg", r.name));
        match std::fs::read_to_string(&path) {
            Ok(svg) => Some(svg),
            // A program whose traces the run did not keep has no plot.
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => None,
            Err(e) => {
                plot_error = Some(format!("{}: {e}", path.display()));
                None
            }
        }
    });
    if let Some(e) = plot_error {
        return Err(e);
    }
    let written = files.iter().try_for_each(|(rel, contents)| staging.write(rel, contents)).and_then(|()| staging.commit());
    written.map_err(|e| format!("cannot write {}: {e}", request.out.display()))?;
    Ok(run)
}

#[cfg(test)]
mod tests;
