//! `certify`: checks its options and `--out` before anything runs, stages the bundle (each case
//! written to `cases.jsonl` as it is judged), runs with a progress bar on stderr, writes the rest
//! of the bundle and renames it into place; prints the summary. Exit 0 when every case conforms,
//! 1 otherwise, 2 on bad options, an unusable `--out` or a failed write.

use crate::cli::args::{CertifyArgs, MergeArgs, ThirdPartyArgs};
use crate::cli::{bad, Bad};
use cyclecheck::candidate::split_command;
use cyclecheck::certify::{self, bundle::Staging};
use std::io::BufWriter;

/// The `--kani-log` file, parsed; a file that is no cargo-kani log is refused.
fn kani_log(file: Option<&std::path::Path>) -> Result<Option<certify::kani::KaniLog>, Bad> {
    let Some(f) = file else { return Ok(None) };
    let text = std::fs::read_to_string(f).map_err(|e| Bad(format!("--kani-log {}: {e}", f.display())))?;
    let log = certify::kani::parse_log(&text);
    if log.harnesses.is_empty() {
        return bad(format!("--kani-log {}: no \"Checking harness\" line: not a cargo-kani log", f.display()));
    }
    Ok(Some(log))
}

pub fn run(a: &CertifyArgs) -> Result<u8, Bad> {
    let kani_log = kani_log(a.kani_log.as_deref())?;
    let options = certify::Options {
        candidate: a.candidate.candidate.clone(),
        limits: a.candidate.limits(),
        cycles: a.cycles.0.clone(),
        operator: a.cycles.1,
        cases: a.cases,
        seed: a.seed,
        max_failures: a.max_failures,
        kani_log,
        shard: a.shard,
        readings: cycle_kernel::readings::Pins::parse(&a.readings).map_err(Bad)?,
        deviations: match &a.deviations {
            None => Vec::new(),
            Some(f) => certify::deviations::read(f).map_err(|e| Bad(format!("--deviations {e}")))?,
        },
        level: a.level,
        ..certify::Options::default()
    };
    if let Some(cmd) = &options.candidate {
        split_command(cmd).map_err(|e| Bad(format!("--candidate {cmd:?}: {e}")))?;
    }
    if let Some(required) = a.level {
        if let Some(refused) = level_refused(options.candidate.as_deref(), options.limits, required) {
            crate::cli::expand::emit(&format!("FAIL: {refused}\n"));
            return Ok(1);
        }
    }
    let out = &a.out;
    let staging = Staging::create(out).map_err(|e| Bad(format!("--out {}: {e}", out.display())))?;
    let file = staging.create_file("cases.jsonl").map_err(|e| Bad(format!("--out {}: {e}", out.display())))?;
    let mut cases = BufWriter::with_capacity(1 << 16, file);
    let mut bar = ProgressBar::new();
    let run = certify::run(&options, &mut cases, &mut |p| bar.show(p)).map_err(|e| Bad(e.0))?;
    bar.finish();
    drop(cases);
    let files = certify::bundle::files(&run);
    let written = files.iter().try_for_each(|(rel, contents)| staging.write(rel, contents)).and_then(|()| staging.commit());
    if let Err(e) = written {
        return bad(format!("cannot write {}: {e}", out.display()));
    }
    Ok(report(&run, files.iter().filter(|(f, _)| f.starts_with("plots/")).count(), out))
}

/// Why `--level required` refuses the candidate before the run: it declares a weaker level in
/// its greeting (or cannot be greeted). The production expander compares at `full`.
fn level_refused(candidate: Option<&str>, limits: cyclecheck::candidate::Limits, required: cycle_kernel::conformance::Level) -> Option<String> {
    let declared = match candidate {
        None => cycle_kernel::conformance::Level::Full,
        Some(cmd) => match certify::declared_level(cmd, limits) {
            Ok(l) => l,
            Err(e) => return Some(format!("--level {required}: the candidate could not be greeted: {e}")),
        },
    };
    (declared < required).then(|| certify::level_refusal(declared, required))
}

/// Prints the summary and what was written; the exit code.
fn report(run: &certify::Run, plots: usize, out: &std::path::Path) -> u8 {
    let verdict = run.verdict();
    let shard = match (run.options.shard, run.merged_from.len()) {
        (Some(s), _) => format!(" (shard {s}: merge the shards with cyclecheck merge)"),
        (None, 0) => String::new(),
        (None, n) => format!(" (merged from {n} shards)"),
    };
    crate::cli::expand::emit(&format!(
        "{}\nwrote {}: index.html, evidence.json, cases.jsonl, {plots} plots — {verdict}{shard}\n",
        run.summary(),
        out.display()
    ));
    if run.passed() { 0 } else { 1 }
}

/// `merge`: joins shard bundles (`certify::merge`); exit 0 when every case conforms, 1
/// otherwise, 2 when the bundles cannot be merged.
pub fn merge(a: &MergeArgs) -> Result<u8, Bad> {
    let request = certify::merge::Request { bundles: a.bundles.clone(), out: a.out.clone(), kani_log: kani_log(a.kani_log.as_deref())? };
    let run = certify::merge::merge(&request).map_err(Bad)?;
    let plots = std::fs::read_dir(a.out.join("plots")).map_or(0, |d| d.count());
    Ok(report(&run, plots, &a.out))
}

/// `third-party`: runs the manifests' campaigns and writes the report, or compares it
/// (`--check`); exit 0 written or up to date, 1 when the check finds a difference, 2 on a bad
/// manifest or deviations file.
pub fn third_party(a: &ThirdPartyArgs) -> Result<u8, Bad> {
    let root = std::env::current_dir().map_err(|e| Bad(format!("cannot read the working directory: {e}")))?;
    let request = cyclecheck::thirdparty::Request {
        candidates: a.candidates.clone(),
        only: a.only.clone(),
        ci: a.ci,
        out: a.out.clone(),
        check: a.check,
        skip_missing: a.skip_missing,
        root,
    };
    let (ok, message) = cyclecheck::thirdparty::command(&request, &mut |line| eprintln!("{line}")).map_err(Bad)?;
    crate::cli::expand::emit(&message);
    Ok(u8::from(!ok))
}

/// A progress bar on stderr: redrawn in place on a terminal, a line per phase otherwise.
struct ProgressBar {
    tty: bool,
    phase: String,
    last: Option<std::time::Instant>,
}

impl ProgressBar {
    fn new() -> ProgressBar {
        use std::io::IsTerminal as _;
        ProgressBar { tty: std::io::stderr().is_terminal(), phase: String::new(), last: None }
    }

    fn show(&mut self, p: certify::Progress) {
        let new_phase = self.phase != p.phase;
        if !self.tty {
            if new_phase {
                eprintln!("certify: {} ({} of {} cases done, {} not conforming)", p.phase, p.done, p.total, p.bad);
                self.phase = p.phase.to_string();
            }
            return;
        }
        let now = std::time::Instant::now();
        let due = self.last.is_none_or(|t| now.duration_since(t).as_millis() >= 100);
        if !(due || new_phase || p.done == p.total) {
            return;
        }
        if new_phase && !self.phase.is_empty() {
            eprintln!();
        }
        self.phase = p.phase.to_string();
        self.last = Some(now);
        const WIDTH: usize = 30;
        let filled = (p.done * WIDTH).checked_div(p.total).unwrap_or(WIDTH).min(WIDTH);
        eprint!(
            "\r{:<10} [{}{}] {:>7}/{:<7} {} not conforming ",
            p.phase,
            "#".repeat(filled),
            "-".repeat(WIDTH - filled),
            p.done,
            p.total,
            p.bad
        );
    }

    fn finish(&mut self) {
        if self.tty && !self.phase.is_empty() {
            eprintln!();
        }
    }
}
