//! How each proof property was checked, for the evidence bundle: the z3 lemmas of `smt/` (run
//! here when `z3` is on the PATH — the lemma files are compiled in), the Kani harnesses of
//! `cycle-proofs` (not run by certify: a vendor's `cargo kani` log can be imported with
//! `--kani-log FILE`, [`super::kani::parse_log`]), and the drivers that `cargo test` runs on
//! every harness body. Nothing is called a proof that no prover checked in this bundle: a Kani
//! harness without a SUCCESSFUL verdict in the imported log is listed as "not run here".

use super::kani::{self, CheckedBy, KaniLog, Verdict};
use serde_json::{json, Value};
use std::io::Write;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// The lemma files of `smt/lemmas/`, compiled in: (file stem, SMT-LIB2 text).
pub const LEMMAS: &[(&str, &str)] = &include!(concat!(env!("OUT_DIR"), "/lemmas.rs"));

/// How long z3 may take on one lemma.
pub const Z3_TIMEOUT: Duration = Duration::from_secs(60);

/// One lemma's run.
#[derive(Clone, Debug, PartialEq)]
pub struct LemmaRun {
    pub name: &'static str,
    /// The rule IDs its header names.
    pub rules: Vec<&'static str>,
    /// `unsat` (proved), `sat`, `unknown`, `timeout`, or why it did not run.
    pub result: String,
    pub seconds: Option<f64>,
}

impl LemmaRun {
    pub fn proved(&self) -> bool {
        self.result == "unsat"
    }
}

/// The rule IDs a lemma's comment header names (the lines before its first definition).
fn header_rules(text: &str) -> Vec<&'static str> {
    let header = text.lines().take_while(|l| l.starts_with(';'));
    let mut rules: Vec<&'static str> = header
        .flat_map(|l| l.split(|c: char| !(c.is_ascii_alphanumeric() || c == '.')))
        .filter_map(|w| cycle_vocab::Rule::from_id(w.trim_end_matches('.')).map(|r| r.id()))
        .collect();
    rules.sort_unstable();
    rules.dedup();
    rules
}

/// The z3 version, when z3 is on the PATH.
pub fn z3_version() -> Option<String> {
    let out = Command::new("z3").arg("--version").output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Runs every lemma through z3 (each expected `unsat`), or records that z3 is not there.
pub fn run_lemmas() -> Vec<LemmaRun> {
    let available = z3_version().is_some();
    LEMMAS
        .iter()
        .map(|&(name, text)| {
            let rules = header_rules(text);
            if !available {
                return LemmaRun { name, rules, result: "not run: z3 is not on the PATH".to_string(), seconds: None };
            }
            let started = Instant::now();
            let result = z3(text).unwrap_or_else(|e| format!("not run: {e}"));
            LemmaRun { name, rules, result, seconds: Some(started.elapsed().as_secs_f64()) }
        })
        .collect()
}

/// z3's answer to one query: its first line (`unsat`, `sat`, `unknown`, `timeout`).
fn z3(text: &str) -> Result<String, String> {
    let mut child = Command::new("z3")
        .args(["-smt2", "-in", &format!("-T:{}", Z3_TIMEOUT.as_secs())])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .map_err(|e| e.to_string())?;
    child.stdin.take().ok_or("no stdin")?.write_all(text.as_bytes()).map_err(|e| e.to_string())?;
    let out = child.wait_with_output().map_err(|e| e.to_string())?;
    Ok(String::from_utf8_lossy(&out.stdout).lines().next().unwrap_or("no answer").trim().to_string())
}

/// The proofs part of a run: the lemmas as run, and the imported Kani log (if any).
#[derive(Clone, Debug, Default)]
pub struct Proofs {
    pub z3_version: Option<String>,
    pub lemmas: Vec<LemmaRun>,
    pub kani: Option<KaniLog>,
    /// A shard's run: the lemmas are left to `cyclecheck merge`, which runs them once.
    pub left_to_merge: bool,
}

impl Proofs {
    /// Runs the lemmas now; `kani` is the parsed `--kani-log`, if given.
    pub fn check(kani: Option<KaniLog>) -> Proofs {
        Proofs { z3_version: z3_version(), lemmas: run_lemmas(), kani, left_to_merge: false }
    }

    /// A shard's proofs: the Kani log listed, the lemmas not run (each says so).
    pub fn left_to_merge(kani: Option<KaniLog>) -> Proofs {
        let lemmas = LEMMAS
            .iter()
            .map(|&(name, text)| LemmaRun { name, rules: header_rules(text), result: "not run in a shard: cyclecheck merge runs it".to_string(), seconds: None })
            .collect();
        Proofs { z3_version: None, lemmas, kani, left_to_merge: true }
    }

    /// What Kani says of `harness` in this bundle, in words.
    pub fn kani_status(&self, harness: &str, checked_by: CheckedBy) -> String {
        if checked_by == CheckedBy::Drivers {
            return "a TEST: no Kani proof (Kani reached no verdict on it; proofs/README.md)".to_string();
        }
        let Some(log) = &self.kani else {
            return "not run here (a Kani proof harness; import a cargo-kani log with --kani-log)".to_string();
        };
        match log.result_of(harness) {
            None => "not in the imported Kani log".to_string(),
            Some(r) => {
                let time = r.seconds.map(|s| format!(" in {s:.1} s")).unwrap_or_default();
                let version = log.kani_version.as_deref().unwrap_or("unknown");
                match &r.verdict {
                    Verdict::Successful => format!("SUCCESSFUL{time} (imported log, Kani {version})"),
                    v => format!("{}{time} (imported log, Kani {version}): not a proof", v.label()),
                }
            }
        }
    }

    /// The lemmas that bear on any of `rules`.
    pub fn lemmas_for(&self, rules: &[&str]) -> Vec<&LemmaRun> {
        self.lemmas.iter().filter(|l| l.rules.iter().any(|r| rules.contains(r))).collect()
    }

    /// The evidence.json section.
    pub fn json(&self) -> Value {
        let properties: Vec<Value> = kani::PROPERTIES
            .iter()
            .map(|p| {
                json!({
                    "harness": p.harness,
                    "rules": p.rules,
                    "statement": p.statement,
                    "kani": self.kani_status(p.harness, p.checked_by),
                    "z3": self.lemmas_for(p.rules).iter().map(|l| format!("{} {}", l.name, l.result)).collect::<Vec<_>>(),
                    "drivers": "the harness body's bounded-exhaustive and random drivers, run by `cargo test` (not by this certify run)",
                })
            })
            .collect();
        json!({
            "z3": { "version": self.z3_version, "lemmas": self.lemmas.iter().map(|l| json!({
                "name": l.name, "rules": l.rules, "result": l.result, "seconds": l.seconds })).collect::<Vec<_>>() },
            "kani": self.kani.as_ref().map(|k| json!({
                "kani_version": k.kani_version, "cbmc_version": k.cbmc_version,
                "harnesses": k.harnesses.iter().map(|h| json!({ "name": h.name, "verdict": h.verdict.label(), "seconds": h.seconds })).collect::<Vec<_>>() })),
            "properties": properties,
        })
    }
}

#[cfg(test)]
mod tests;
