//! `cyclecheck gate`: the pre-merge gate — fast, strict, non-zero on any failure.
//!
//! Steps, in order, each timed (the gate goes on after a failure, so one run lists them all):
//!
//! 1. `corpus`: every built-in program (the manuals' examples, one program per feature)
//!    through spec and impl; all must conform;
//! 2. `campaign`: a fixed-seed differential campaign over every registry family's
//!    generator and garbage (`cycle_kernel::gen::any_case`), `cases` cases, spec vs impl by the conformance relation;
//! 3. `fuzz replay`: the committed decoded seeds and regression cases (`fuzz/seeds/`,
//!    `tests/fuzz_regressions/`) of the program fuzz targets through their bodies, each case's
//!    expected verdict checked (`cycle_kernel::fuzzing::replay`), and those of `impl_invariants`
//!    through the proof harnesses' bodies (`cycle_kernel::fuzzing::invariants`);
//! 4. `cargo test`: the workspace's tests with `CI=true INSTA_UPDATE=no` (snapshots checked,
//!    never written), a fixed `CYCLECHECK_SEED`, `CYCLECHECK_CASES` and
//!    `CYCLECHECK_PROOF_CASES` — snapshots, properties, differential campaigns, the bounded
//!    proofs' exhaustive and random drivers, the fuzz replay. Skipped with `--no-cargo-test`.
//!
//! With `--shard K/N` steps 1–3 take case i of their corpus, campaign and committed cases when
//! i mod N = K - 1 ([`crate::certify::shard`]); step 4 runs on shard 1 only. The N shards
//! together gate what one unsharded gate gates.
//!
//! Steps 1–3 run in this process, so a `cyclecheck` built with a feature of the impl (the
//! planted bug, `planted-depth-bug`) gates that impl; step 4 passes the same feature on.

use cycle_kernel::campaign::{self, Verdict};
use crate::certify::shard::Shard;
use cycle_kernel::engine::{ImplEngine, SpecEngine};
use cycle_kernel::fuzzing::{committed, decoded, invariants, replay, Target};
use cycle_kernel::{corpus, gen};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config as PtConfig, RngAlgorithm, TestRng, TestRunner};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// What the gate runs.
#[derive(Clone, Debug)]
pub struct Options {
    /// Cases of the in-process differential campaign.
    pub cases: u32,
    /// The campaign's seed, also passed to `cargo test` as `CYCLECHECK_SEED`.
    pub seed: u64,
    /// Whether to run step 4.
    pub cargo_test: bool,
    /// `CYCLECHECK_CASES` for `cargo test` (properties and differential campaigns).
    pub test_cases: u32,
    /// `CYCLECHECK_PROOF_CASES` for `cargo test` (the proofs' random drivers).
    pub proof_cases: u64,
    /// The repository root.
    pub root: PathBuf,
    /// The slice of steps 1–3 to run (`--shard K/N`); step 4 runs on shard 1 only.
    pub shard: Option<Shard>,
}

/// Cases of the in-process campaign by default.
pub const DEFAULT_CASES: u32 = 3_000;
/// The gate's seed by default.
pub const DEFAULT_SEED: u64 = 0x5eed_6a7e;
/// `CYCLECHECK_CASES` of the `cargo test` step by default.
pub const DEFAULT_TEST_CASES: u32 = 2_000;
/// `CYCLECHECK_PROOF_CASES` of the `cargo test` step by default.
pub const DEFAULT_PROOF_CASES: u64 = 200_000;

impl Default for Options {
    fn default() -> Options {
        Options {
            cases: DEFAULT_CASES,
            seed: DEFAULT_SEED,
            cargo_test: true,
            test_cases: DEFAULT_TEST_CASES,
            proof_cases: DEFAULT_PROOF_CASES,
            root: PathBuf::from("."),
            shard: None,
        }
    }
}

/// One step's result.
#[derive(Clone, Debug)]
pub struct Step {
    pub name: &'static str,
    pub passed: bool,
    /// One line: what ran, counts.
    pub summary: String,
    /// The failure reports (empty when passed).
    pub details: String,
    pub time: Duration,
}

fn step(name: &'static str, f: impl FnOnce() -> (bool, String, String)) -> Step {
    let t = Instant::now();
    let (passed, summary, details) = f();
    Step { name, passed, summary, details, time: t.elapsed() }
}

/// The first few findings of a report, whole.
fn findings_text(report: &campaign::Report) -> String {
    let shown: Vec<String> = report.findings.iter().take(3).map(|f| f.to_string()).collect();
    let more = report.findings.len().saturating_sub(3);
    let mut s = shown.join("\n\n");
    if more > 0 {
        s += &format!("\n\n… and {more} more");
    }
    s
}

/// `, shard K/N` for a step's summary.
fn shard_note(shard: Option<Shard>) -> String {
    shard.map(|s| format!(", shard {s}")).unwrap_or_default()
}

/// Step 1.
pub fn corpus_step(shard: Option<Shard>) -> Step {
    step("corpus", || {
        let cases = corpus::cases().enumerate().filter(|(i, _)| Shard::includes(shard, *i)).map(|(_, c)| c);
        let r = campaign::run((&SpecEngine, &ImplEngine), cases);
        let summary = format!(
            "{} programs{}, {} conform; by cycle: {}",
            r.cases(),
            shard_note(shard),
            r.conforming(),
            cycle_kernel::registry::counts_line(&r.by_cycle)
        );
        (r.all_conform(), summary, findings_text(&r))
    })
}

/// Step 2: `cases` cases of `gen::any_case()` from a fixed seed.
pub fn campaign_step(cases: u32, seed: u64, shard: Option<Shard>) -> Step {
    step("campaign", || {
        let bytes = gen::seed_bytes(seed);
        let mut runner = TestRunner::new_with_rng(PtConfig::default(), TestRng::from_seed(RngAlgorithm::ChaCha, &bytes));
        let strategy = gen::any_case();
        // Every case is drawn, so each shard's cases are the unsharded campaign's.
        let cases = (0..cases).filter_map(|i| {
            let tree = strategy.new_tree(&mut runner).ok()?;
            let case = Shard::includes(shard, i as usize).then(|| tree.current())?;
            Some((format!("{}#{i}", case.family), case.program, case.config))
        });
        let r = campaign::run((&SpecEngine, &ImplEngine), cases);
        let panics = r.findings.iter().filter(|f| matches!(f.verdict, Verdict::Panic { .. })).count();
        let summary = format!(
            "seed {seed:#x}: {} cases{}, {} conform, {} panics; by cycle: {}",
            r.cases(),
            shard_note(shard),
            r.conforming(),
            panics,
            cycle_kernel::registry::counts_line(&r.by_cycle)
        );
        (r.all_conform() && r.cases() > 0, summary, findings_text(&r))
    })
}

/// Step 3.
pub fn replay_step(root: &Path, shard: Option<Shard>) -> Step {
    step("fuzz replay", || {
        let (mut n, mut harness_cases, mut failures) = (0, 0, Vec::new());
        for t in Target::ALL {
            for dir in [committed::seeds_dir(root, t), committed::regressions_dir(root, t)] {
                if t == Target::ImplInvariants {
                    let cases = decoded::load_harnesses(&dir).unwrap_or_else(|e| {
                        failures.push(e);
                        Vec::new()
                    });
                    for (_, (name, case)) in cases.iter().enumerate().filter(|(i, _)| Shard::includes(shard, *i)) {
                        harness_cases += 1;
                        let here = format!("{} {}/{name}", t.name(), dir.display());
                        match std::panic::catch_unwind(|| invariants::replay(case)) {
                            Ok(Ok(())) => {}
                            Ok(Err(report)) => failures.push(format!("{here}:\n{report}")),
                            Err(_) => failures.push(format!("{here}: the harness panicked")),
                        }
                    }
                    continue;
                }
                let cases = match decoded::load_programs(&dir) {
                    Ok(cases) => cases,
                    Err(e) => {
                        failures.push(e);
                        continue;
                    }
                };
                for (i, (name, program, case)) in cases.into_iter().enumerate() {
                    if !Shard::includes(shard, i) {
                        continue;
                    }
                    n += 1;
                    let here = format!("{} {}/{name}", t.name(), dir.display());
                    match std::panic::catch_unwind(|| replay::replay(t, &program, &case)) {
                        Ok(Ok(())) => {}
                        Ok(Err(report)) => failures.push(format!("{here}:\n{report}")),
                        Err(_) => failures.push(format!("{here}: the body panicked")),
                    }
                }
            }
        }
        let summary = format!(
            "{n} committed program cases and {harness_cases} impl_invariants cases{}, {} fail",
            shard_note(shard),
            failures.len()
        );
        (n > 0 && failures.is_empty(), summary, failures.into_iter().take(3).collect::<Vec<_>>().join("\n\n"))
    })
}

/// Step 4.
pub fn cargo_test_step(o: &Options) -> Step {
    step("cargo test", || {
        let mut cmd = std::process::Command::new("cargo");
        cmd.current_dir(&o.root).args(["test", "--workspace"]);
        if cfg!(feature = "planted-depth-bug") {
            cmd.args(["--features", "cycle-impl/planted-depth-bug"]);
        }
        cmd.env("CI", "true")
            .env("INSTA_UPDATE", "no")
            .env("CYCLECHECK_SEED", o.seed.to_string())
            .env("CYCLECHECK_CASES", o.test_cases.to_string())
            .env("CYCLECHECK_PROOF_CASES", o.proof_cases.to_string());
        let line = format!(
            "CI=true INSTA_UPDATE=no CYCLECHECK_SEED={} CYCLECHECK_CASES={} CYCLECHECK_PROOF_CASES={} {}",
            o.seed,
            o.test_cases,
            o.proof_cases,
            if cfg!(feature = "planted-depth-bug") {
                "cargo test --workspace --features cycle-impl/planted-depth-bug"
            } else {
                "cargo test --workspace"
            }
        );
        match cmd.output() {
            Err(e) => (false, line, format!("cannot run cargo: {e}")),
            Ok(out) => {
                let text = format!("{}{}", String::from_utf8_lossy(&out.stdout), String::from_utf8_lossy(&out.stderr));
                let (passed, failed) = test_counts(&text);
                let summary = format!("{line}: {passed} passed, {failed} failed");
                let details = if out.status.success() { String::new() } else { failure_lines(&text) };
                (out.status.success(), summary, details)
            }
        }
    })
}

/// Sums the `test result:` lines of cargo test's output: (passed, failed).
pub fn test_counts(output: &str) -> (u64, u64) {
    let count = |line: &str, word: &str| -> u64 {
        let mut prev = None;
        for w in line.split([' ', ';']) {
            if w == word {
                return prev.and_then(|p: &str| p.parse().ok()).unwrap_or(0);
            }
            if !w.is_empty() {
                prev = Some(w);
            }
        }
        0
    };
    output
        .lines()
        .filter(|l| l.starts_with("test result:"))
        .fold((0, 0), |(p, f), l| (p + count(l, "passed"), f + count(l, "failed")))
}

/// The lines of cargo test's output that say what failed (at most 60).
fn failure_lines(output: &str) -> String {
    let keep = |l: &str| {
        l.contains("FAILED") || l.contains("panicked") || l.starts_with("error") || l.contains("failures:") || l.starts_with("    ")
    };
    output.lines().filter(|l| keep(l)).take(60).collect::<Vec<_>>().join("\n")
}

/// Runs the gate; the steps and the total wall time.
pub fn run(o: &Options) -> (Vec<Step>, Duration) {
    let t = Instant::now();
    let mut steps = vec![corpus_step(o.shard), campaign_step(o.cases, o.seed, o.shard), replay_step(&o.root, o.shard)];
    if o.cargo_test && o.shard.is_none_or(|s| s.index == 1) {
        steps.push(cargo_test_step(o));
    }
    (steps, t.elapsed())
}

/// The report: one line per step, failure details, the verdict and the wall time.
pub fn report(steps: &[Step], total: Duration) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    for st in steps {
        let _ = writeln!(s, "{:4} {:12} {:>7.1} s  {}", if st.passed { "ok" } else { "FAIL" }, st.name, st.time.as_secs_f64(), st.summary);
    }
    for st in steps.iter().filter(|st| !st.passed && !st.details.is_empty()) {
        let _ = writeln!(s, "\n--- {} ---\n{}", st.name, st.details);
    }
    let ok = steps.iter().all(|st| st.passed);
    let _ = writeln!(
        s,
        "\ngate {}: {} of {} steps passed, wall time {:.1} s on {} cores",
        if ok { "PASSED" } else { "FAILED" },
        steps.iter().filter(|st| st.passed).count(),
        steps.len(),
        total.as_secs_f64(),
        std::thread::available_parallelism().map_or(0, |n| n.get())
    );
    s
}


/// `cyclecheck gate`, run from the repository root: prints the report, returns the exit code
/// (0 every step passed, 1 otherwise).
pub fn command(o: &Options) -> Result<u8, String> {
    if !o.root.join("fuzz/seeds").is_dir() {
        return Err("gate: run it from the repository root (no fuzz/seeds here)".to_string());
    }
    let (steps, total) = run(o);
    print!("{}", report(&steps, total));
    Ok(if steps.iter().all(|s| s.passed) { 0 } else { 1 })
}

#[cfg(test)]
mod tests;
