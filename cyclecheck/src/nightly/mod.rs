//! `cyclecheck fuzz`: the unattended nightly fuzz campaign, leaving a reproducible record.
//!
//! For each target ([`cycle_kernel::fuzzing::Target`]), from the repository root:
//!
//! 1. the committed decoded seeds (`fuzz/seeds/TARGET/`) are encoded into libFuzzer's corpus
//!    folder `fuzz/corpus/TARGET/` ([`committed::encode_corpus`]; not committed);
//! 2. `cargo +nightly fuzz run TARGET OUT/corpus/TARGET fuzz/corpus/TARGET -- -max_total_time=B
//!    -dict=fuzz/gcode.dict -artifact_prefix=OUT/artifacts/TARGET/ -print_final_stats=1
//!    -rss_limit_mb=MB [-fork=N]`: libFuzzer writes new inputs to the scratch corpus (kept across
//!    nights when OUT is) and only reads the seeds; a crash or divergence stops the target's run
//!    (with `-fork`, an out-of-memory or timed-out job does not: libFuzzer counts it and goes on);
//! 3. `cargo +nightly fuzz cmin TARGET OUT/corpus/TARGET`: minimizes the scratch corpus;
//! 4. each finding (`crash-*`, `timeout-*`, `oom-*`, `leak-*` artifact) is minimized with
//!    `cargo +nightly fuzz tmin` and written decoded to `tests/fuzz_regressions/TARGET/`
//!    ([`committed::write_regression`]: replayed by `cargo test`, `tests/tests/fuzz_replay.rs`:
//!    commit it), with the target's report on it in this build;
//! 5. `OUT/summary.json` and `OUT/summary.txt`: per target the executions, execs/s, libFuzzer's
//!    coverage (`cov`: edges, `ft`: features), peak RSS (libFuzzer's, else sampled: [`rss`]),
//!    corpus size before and after `cmin`, findings ([`parse_stats`] reads libFuzzer's output in
//!    both modes).
//!
//! The exit code is 1 when anything was found or a step failed, else 0.

use cycle_kernel::fuzzing::committed;
pub mod libfuzzer_log;
pub mod rss;

pub use libfuzzer_log::{parse_stats, Stats};
use cycle_kernel::fuzzing::Target;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::Instant;

/// What to run.
#[derive(Clone, Debug)]
pub struct Plan {
    /// Seconds of fuzzing per target.
    pub budget: u64,
    pub targets: Vec<Target>,
    /// Scratch corpus, artifacts and the summary.
    pub out: PathBuf,
    /// Cargo features of the fuzz crate (`planted-depth-bug` to show the campaign finds it).
    pub features: Option<String>,
    /// The repository root (holds `fuzz/`).
    pub root: PathBuf,
    /// libFuzzer's `-fork=N` (jobs in parallel); 1: one process, no `-fork`.
    pub fork: u32,
    /// libFuzzer's `-rss_limit_mb` (0: none).
    pub rss_limit_mb: u64,
}

/// One finding, minimized and written decoded into the regression folder.
#[derive(Clone, Debug, Serialize)]
pub struct Finding {
    pub artifact: String,
    pub minimized: Option<String>,
    /// The regression case's name in `tests/fuzz_regressions/<target>/` (`NAME.json`, and
    /// `NAME.nc` for the program targets).
    pub regression: String,
    /// The body's report in this build, or why it does not reproduce here.
    pub report: String,
}

/// The record of one target.
#[derive(Clone, Debug, Serialize)]
pub struct TargetSummary {
    pub target: &'static str,
    pub seconds: f64,
    pub fuzz_exit: Option<i32>,
    pub stats: Stats,
    /// The peak RSS of the target's processes as `cyclecheck fuzz` sampled it ([`rss`]): the
    /// summary's figure when libFuzzer printed none (fork mode).
    pub sampled_peak_rss_mb: Option<u64>,
    /// Files in the scratch corpus before and after `cmin`.
    pub corpus_files: (usize, usize),
    pub corpus_bytes: (u64, u64),
    pub findings: Vec<Finding>,
    /// Steps that failed to run (not findings): cargo errors and the like.
    pub errors: Vec<String>,
}

fn dir_size(dir: &Path) -> (usize, u64) {
    let Ok(entries) = std::fs::read_dir(dir) else { return (0, 0) };
    entries
        .filter_map(|e| e.ok()?.metadata().ok())
        .filter(|m| m.is_file())
        .fold((0, 0), |(n, b), m| (n + 1, b + m.len()))
}

fn cargo_fuzz(plan: &Plan, args: &[String]) -> Command {
    let mut c = Command::new("cargo");
    c.current_dir(&plan.root).arg("+nightly").arg("fuzz").args(args);
    c
}

/// Runs a command, its stdout and stderr together, and returns (exit code, output).
fn run_logged(cmd: Command, log: &Path) -> Result<(Option<i32>, String), String> {
    run_sampled(cmd, log, None).map(|(code, text, _)| (code, text))
}

/// [`run_logged`], and with `Some(name)` the peak RSS in MB of its processes named `name`
/// ([`rss`]).
fn run_sampled(mut cmd: Command, log: &Path, name: Option<&str>) -> Result<(Option<i32>, String, Option<u64>), String> {
    use std::process::Stdio;
    let child = cmd.stdout(Stdio::piped()).stderr(Stdio::piped()).spawn().map_err(|e| format!("cannot run {cmd:?}: {e}"))?;
    let sampler = name.map(|n| rss::start(child.id(), n));
    let out = child.wait_with_output().map_err(|e| format!("cannot run {cmd:?}: {e}"));
    let peak = sampler.and_then(rss::Sampler::finish);
    let out = out?;
    let mut text = String::from_utf8_lossy(&out.stdout).into_owned();
    text.push_str(&String::from_utf8_lossy(&out.stderr));
    let _ = std::fs::write(log, &text);
    Ok((out.status.code(), text, peak))
}

fn features_args(plan: &Plan) -> Vec<String> {
    plan.features.iter().flat_map(|f| ["--features".to_string(), f.clone()]).collect()
}

/// Fuzzes one target (see the module documentation).
pub fn run_target(plan: &Plan, target: Target) -> TargetSummary {
    let name = target.name();
    let started = Instant::now();
    let corpus = plan.out.join("corpus").join(name);
    let artifacts = plan.out.join("artifacts").join(name);
    let logs = plan.out.join("logs");
    let mut summary = TargetSummary {
        target: name,
        seconds: 0.0,
        fuzz_exit: None,
        stats: Stats::default(),
        sampled_peak_rss_mb: None,
        corpus_files: (0, 0),
        corpus_bytes: (0, 0),
        findings: Vec::new(),
        errors: Vec::new(),
    };
    for d in [&corpus, &artifacts, &logs] {
        if let Err(e) = std::fs::create_dir_all(d) {
            summary.errors.push(format!("cannot create {}: {e}", d.display()));
            return summary;
        }
    }
    if let Err(e) = committed::encode_corpus(&plan.root, &[target]) {
        summary.errors.push(format!("cannot encode the seeds: {e}"));
        return summary;
    }
    let seeds = committed::corpus_dir(&plan.root, target);
    let mut args = vec!["run".to_string(), name.to_string()];
    args.extend(features_args(plan));
    args.extend([corpus.display().to_string(), seeds.display().to_string(), "--".to_string()]);
    args.extend([
        format!("-max_total_time={}", plan.budget),
        format!("-dict={}", plan.root.join("fuzz/gcode.dict").display()),
        format!("-artifact_prefix={}/", artifacts.display()),
        "-print_final_stats=1".to_string(),
        "-timeout=20".to_string(),
        "-max_len=2048".to_string(),
        format!("-rss_limit_mb={}", plan.rss_limit_mb),
    ]);
    if plan.fork > 1 {
        args.push(format!("-fork={}", plan.fork));
    }
    match run_sampled(cargo_fuzz(plan, &args), &logs.join(format!("{name}.run.log")), Some(name)) {
        Ok((code, log, peak)) => {
            summary.fuzz_exit = code;
            summary.stats = parse_stats(&log);
            summary.sampled_peak_rss_mb = peak;
            if summary.stats.executions == 0 {
                summary.errors.push(format!("no executions (exit {code:?}); see logs/{name}.run.log"));
            }
        }
        Err(e) => summary.errors.push(e),
    }
    let before = dir_size(&corpus);
    let mut cmin = vec!["cmin".to_string(), name.to_string()];
    cmin.extend(features_args(plan));
    cmin.push(corpus.display().to_string());
    match run_logged(cargo_fuzz(plan, &cmin), &logs.join(format!("{name}.cmin.log"))) {
        Ok((Some(0), _)) => {}
        Ok((code, _)) => summary.errors.push(format!("cmin exited {code:?}; see logs/{name}.cmin.log")),
        Err(e) => summary.errors.push(e),
    }
    let after = dir_size(&corpus);
    summary.corpus_files = (before.0, after.0);
    summary.corpus_bytes = (before.1, after.1);
    summary.findings = findings(plan, target, &artifacts, &logs, &mut summary.errors);
    summary.seconds = started.elapsed().as_secs_f64();
    summary
}

/// Minimizes each artifact and writes it decoded into the regression folder.
fn findings(plan: &Plan, target: Target, artifacts: &Path, logs: &Path, errors: &mut Vec<String>) -> Vec<Finding> {
    let name = target.name();
    let mut out = Vec::new();
    let Ok(entries) = std::fs::read_dir(artifacts) else { return out };
    let mut files: Vec<PathBuf> = entries.filter_map(|e| Some(e.ok()?.path())).collect();
    files.sort();
    for artifact in files {
        let file = artifact.file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default();
        if !["crash-", "timeout-", "oom-", "leak-"].iter().any(|p| file.starts_with(p)) {
            continue;
        }
        let mut tmin = vec!["tmin".to_string(), name.to_string()];
        tmin.extend(features_args(plan));
        tmin.extend(["--runs".to_string(), "2000".to_string(), artifact.display().to_string()]);
        let hash = file.split_once('-').map_or(file.as_str(), |(_, h)| h).to_string();
        // tmin writes its steps to fuzz/artifacts/TARGET/minimized-from-*, and names the last
        // one in its closing "Reproduce with:" line (from the root, or from fuzz/ in older
        // cargo-fuzz versions).
        let minimized = match run_logged(cargo_fuzz(plan, &tmin), &logs.join(format!("{name}.tmin.{hash}.log"))) {
            Ok((_, log)) => log
                .split_whitespace()
                .rfind(|w| w.contains("minimized-from-"))
                .and_then(|w| [plan.root.join(w), plan.root.join("fuzz").join(w)].into_iter().find(|p| p.is_file())),
            Err(e) => {
                errors.push(e);
                None
            }
        };
        let best = minimized.clone().unwrap_or_else(|| artifact.clone());
        let found_by = format!(
            "cyclecheck fuzz{} (libFuzzer artifact {file}{})",
            plan.features.as_deref().map(|f| format!(" --features {f}")).unwrap_or_default(),
            if minimized.is_some() { ", minimized by cargo fuzz tmin" } else { ", not minimized" }
        );
        let report = committed::write_regression(&plan.root, target, &best, &file, &found_by).unwrap_or_else(|e| {
            errors.push(format!("cannot write the regression {file}: {e}"));
            e
        });
        out.push(Finding {
            artifact: artifact.display().to_string(),
            minimized: minimized.map(|m| m.display().to_string()),
            regression: committed::regressions_dir(&plan.root, target).join(&file).display().to_string(),
            report,
        });
    }
    out
}

/// The whole campaign: every target, then `summary.json` and `summary.txt` in `plan.out`.
/// Returns the summaries and the text summary.
pub fn run(plan: &Plan) -> (Vec<TargetSummary>, String) {
    let summaries: Vec<TargetSummary> = plan.targets.iter().map(|&t| run_target(plan, t)).collect();
    let text = summary_text(plan, &summaries);
    let json = serde_json::json!({
        "budget_seconds_per_target": plan.budget,
        "features": plan.features,
        "fork": plan.fork,
        "rss_limit_mb": plan.rss_limit_mb,
        "targets": summaries,
    });
    let _ = std::fs::write(plan.out.join("summary.json"), serde_json::to_string_pretty(&json).unwrap_or_default());
    let _ = std::fs::write(plan.out.join("summary.txt"), &text);
    (summaries, text)
}

/// The text form of the summary.
pub fn summary_text(plan: &Plan, summaries: &[TargetSummary]) -> String {
    use std::fmt::Write as _;
    let mut t = format!(
        "cyclecheck fuzz: {} s per target{}{}, RSS limit {}\n",
        plan.budget,
        plan.features.as_deref().map(|f| format!(", features {f}")).unwrap_or_default(),
        if plan.fork > 1 { format!(", -fork={}", plan.fork) } else { String::new() },
        if plan.rss_limit_mb > 0 { format!("{} MB", plan.rss_limit_mb) } else { "none".to_string() }
    );
    let _ = writeln!(
        t,
        "{:16} {:>10} {:>8} {:>6} {:>7} {:>15} {:>8} {:>7}",
        "target", "execs", "exec/s", "cov", "ft", "corpus (cmin)", "findings", "rss MB"
    );
    for s in summaries {
        let _ = writeln!(
            t,
            "{:16} {:>10} {:>8} {:>6} {:>7} {:>6} → {:>6} {:>8} {:>7}",
            s.target,
            s.stats.executions,
            s.stats.execs_per_sec,
            s.stats.coverage_edges,
            s.stats.features,
            s.corpus_files.0,
            s.corpus_files.1,
            s.findings.len(),
            s.stats.peak_rss_mb.or(s.sampled_peak_rss_mb).map_or("-".to_string(), |r| r.to_string())
        );
    }
    for s in summaries.iter().filter(|s| s.stats.fork > 0) {
        let st = &s.stats;
        let _ = writeln!(t, "{}: {} jobs; oom/timeout/crash {}/{}/{}", s.target, st.jobs, st.ooms, st.timeouts, st.crashes);
    }
    for s in summaries {
        for f in &s.findings {
            let _ = writeln!(t, "\n{} FINDING {}\n  regression case: {}\n{}", s.target, f.artifact, f.regression, f.report);
        }
        for e in &s.errors {
            let _ = writeln!(t, "\n{} ERROR {e}", s.target);
        }
    }
    t
}

/// Seconds of fuzzing per target by default.
pub const DEFAULT_BUDGET: u64 = 300;
/// Where the scratch corpora, artifacts, logs and summary go by default.
pub const DEFAULT_OUT: &str = "cyclecheck-out/fuzz";
/// libFuzzer's own default `-rss_limit_mb`.
pub const DEFAULT_RSS_LIMIT_MB: u64 = 2048;

/// What `cyclecheck fuzz` was asked to do.
#[derive(Clone, Debug)]
pub enum Request {
    /// A campaign over `plan` (its root is filled in by [`command`]).
    Campaign { budget: u64, targets: Vec<Target>, out: PathBuf, features: Option<String>, fork: u32, rss_limit_mb: u64 },
    /// `--write-seeds`.
    WriteSeeds,
    /// `--decode TARGET FILE [NAME]`.
    Decode { target: Target, file: PathBuf, name: Option<String> },
}

/// Parses `--targets`: a comma list of target names.
pub fn parse_targets(list: &str) -> Result<Vec<Target>, String> {
    list.split(',').map(|n| Target::by_name(n.trim()).ok_or_else(|| format!("--targets: no target {:?} (one of {})", n.trim(), target_names()))).collect()
}

/// The targets' names, comma-separated.
pub fn target_names() -> String {
    Target::ALL.iter().map(|t| t.name()).collect::<Vec<_>>().join(", ")
}

/// `cyclecheck fuzz`, run from the repository root: a campaign prints the text summary and
/// returns the exit code (0 nothing found, 1 findings or a failed step).
pub fn command(c: Request) -> Result<u8, String> {
    let root = PathBuf::from(".");
    if !root.join("fuzz/Cargo.toml").is_file() {
        return Err("fuzz: run it from the repository root (no fuzz/Cargo.toml here)".to_string());
    }
    let plan = match c {
        Request::WriteSeeds => {
            let n = committed::write_seeds(&root)?;
            println!("wrote {n} decoded seeds under fuzz/seeds/ and encoded them into fuzz/corpus/");
            return Ok(0);
        }
        Request::Decode { target, file, name } => {
            let stem = file.file_name().map(|f| f.to_string_lossy().into_owned()).unwrap_or_default();
            let name = name.unwrap_or(stem);
            let report = committed::write_regression(&root, target, &file, &name, "cyclecheck fuzz --decode")?;
            println!("wrote {}/{name}: {report}", committed::regressions_dir(&root, target).display());
            return Ok(0);
        }
        Request::Campaign { budget, targets, out, features, fork, rss_limit_mb } => {
            Plan { budget, targets, out, features, root, fork, rss_limit_mb }
        }
    };
    std::fs::create_dir_all(&plan.out).map_err(|e| format!("{}: {e}", plan.out.display()))?;
    let (summaries, text) = run(&plan);
    print!("{text}");
    println!("summary: {}/summary.json, {}/summary.txt", plan.out.display(), plan.out.display());
    let clean = summaries.iter().all(|s| s.findings.is_empty() && s.errors.is_empty());
    Ok(if clean { 0 } else { 1 })
}

#[cfg(test)]
mod tests;
