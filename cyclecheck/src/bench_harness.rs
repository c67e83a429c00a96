//! `cyclecheck bench-harness`: the harness's three rates measured in one run, as ratios to the
//! first — the in-process campaign (spec against impl), the production expander as a compiled
//! candidate over the protocol (`cyclecheck serve`), and the `diff_spec_impl` fuzz target's
//! executions under libFuzzer (`docs/PERFORMANCE.md`, "The harness's rates").
//!
//! Both campaigns draw the cases of `certify` (its corpus and generators, `--cases` per family)
//! and judge each against the spec, drawing included; each is run `rounds` times, interleaved,
//! and its best round counts (the machine is shared: the least disturbed round is the one that
//! measures the harness). The fuzz binary, when there is one, runs once for a fixed number of
//! executions from the committed seeds; its rate is executions over the process's wall time.

use crate::candidate::{CandidateEngine, Limits};
use crate::certify::{self, cases::{Ahead, Cases}};
use cycle_kernel::engine::{Engine, ImplEngine, SpecEngine};
use cycle_kernel::fuzzing::{decoded, seeds::encode, CycleInput, Target};
use cycle_kernel::judge::judge;
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

/// How many cases ahead the campaign tells the candidate ([`Engine::prefetch`]).
pub const LOOKAHEAD: usize = crate::candidate::WINDOW;

/// A campaign's cases judged, those that did not conform, and the time.
#[derive(Clone, Copy, Debug)]
pub struct Rate {
    pub cases: u64,
    pub bad: u64,
    pub time: Duration,
}

impl Rate {
    pub fn per_second(&self) -> f64 {
        self.cases as f64 / self.time.as_secs_f64().max(1e-9)
    }

    /// The faster of two measurements.
    fn best(self, other: Rate) -> Rate {
        if other.per_second() > self.per_second() {
            other
        } else {
            self
        }
    }
}

/// Runs `certify`'s cases (drawn as the run goes) through the spec and `engine`, telling the
/// engine `lookahead` cases ahead.
pub fn campaign(engine: &dyn Engine, options: &certify::Options, lookahead: usize) -> Rate {
    let started = Instant::now();
    let (mut n, mut bad) = (0, 0);
    // The readings drawn per case, as in process: `cyclecheck serve` takes them from each request.
    let plan = certify::readings_plan::Plan::drawn(options.readings.clone());
    for p in Ahead::new(Cases::new(options, &plan), engine, lookahead) {
        n += 1;
        bad += u64::from(!judge(&SpecEngine, engine, &p.program, &p.config).result.conforms());
    }
    Rate { cases: n, bad, time: started.elapsed() }
}

/// Drawing the cases alone (no engine runs).
pub fn drawing(options: &certify::Options) -> Rate {
    let started = Instant::now();
    let n = Cases::new(options, &certify::readings_plan::Plan::drawn(options.readings.clone())).count() as u64;
    Rate { cases: n, bad: 0, time: started.elapsed() }
}

/// A fuzz binary's run: executions, wall time, and its sanitizer as found in the binary.
#[derive(Clone, Debug)]
pub struct FuzzRate {
    pub binary: PathBuf,
    pub executions: u64,
    pub time: Duration,
    /// `address` when AddressSanitizer's runtime is linked in, else `none`.
    pub sanitizer: &'static str,
    /// The target's body in this process (uninstrumented) on the run's corpus — the seeds and
    /// the inputs libFuzzer kept — and of that, decoding the inputs into cases alone.
    pub body: Rate,
    pub decoding: Rate,
}

impl FuzzRate {
    pub fn per_second(&self) -> f64 {
        self.executions as f64 / self.time.as_secs_f64().max(1e-9)
    }
}

/// Runs the libFuzzer binary `binary` for `runs` executions (`-runs`, seed 1, the dictionary
/// and the campaign's `-max_len`) from the decoded seeds in `seeds` (`fuzz/seeds/diff_spec_impl`,
/// encoded here into a scratch folder), new inputs going to another scratch folder; both are
/// removed afterwards.
pub fn fuzz(binary: &Path, seeds: Option<&Path>, dict: Option<&Path>, runs: u64, extra: &[String]) -> Result<FuzzRate, String> {
    let bytes = std::fs::read(binary).map_err(|e| format!("{}: {e}", binary.display()))?;
    let sanitizer = if bytes.windows(11).any(|w| w == b"__asan_init") { "address" } else { "none" };
    drop(bytes);
    let scratch = std::env::temp_dir().join(format!("cyclecheck-bench-fuzz-{}", std::process::id()));
    let result = fuzz_in(binary, seeds, dict, runs, extra, &scratch);
    let _ = std::fs::remove_dir_all(&scratch);
    let (executions, time, body, decoding) = result?;
    Ok(FuzzRate { binary: binary.to_path_buf(), executions, time, sanitizer, body, decoding })
}

fn fuzz_in(binary: &Path, seeds: Option<&Path>, dict: Option<&Path>, runs: u64, extra: &[String], scratch: &Path) -> Result<(u64, Duration, Rate, Rate), String> {
    let (new, encoded) = (scratch.join("new"), scratch.join("seeds"));
    for d in [&new, &encoded] {
        std::fs::create_dir_all(d).map_err(|e| format!("{}: {e}", d.display()))?;
    }
    for (name, program, case) in seeds.map(decoded::load_programs).transpose()?.unwrap_or_default() {
        let bytes = encode(Target::DiffSpecImpl, &program, &case).map_err(|e| format!("seed {name}: {e}"))?;
        std::fs::write(encoded.join(&name), bytes).map_err(|e| format!("seed {name}: {e}"))?;
    }
    let mut c = std::process::Command::new(binary);
    c.args([&new, &encoded]).args([format!("-runs={runs}"), "-seed=1".into(), "-max_len=2048".into(), "-print_final_stats=1".into()]);
    c.args(dict.map(|d| format!("-dict={}", d.display()))).args(extra);
    let started = Instant::now();
    let out = c.output().map_err(|e| format!("{}: {e}", binary.display()))?;
    let time = started.elapsed();
    let log = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() {
        let tail: Vec<&str> = log.lines().rev().take(20).collect();
        return Err(format!("{} exited with {}:\n{}", binary.display(), out.status, tail.into_iter().rev().collect::<Vec<_>>().join("\n")));
    }
    let executions = log
        .lines()
        .find_map(|l| l.strip_prefix("stat::number_of_executed_units:"))
        .and_then(|n| n.trim().parse().ok())
        .ok_or_else(|| format!("{}: no stat::number_of_executed_units in its log", binary.display()))?;
    let mut inputs = decoded::read_dir(&new)?;
    inputs.extend(decoded::read_dir(&encoded)?);
    let body = best_of(3, || {
        let bad = inputs.iter().filter(|(_, data)| Target::DiffSpecImpl.run(data).is_err()).count();
        bad as u64
    }, inputs.len());
    let decoding = best_of(
        3,
        || {
            inputs.iter().for_each(|(_, data)| drop(std::hint::black_box(CycleInput::from_bytes(data).case())));
            0
        },
        inputs.len(),
    );
    Ok((executions, time, body, decoding))
}

/// The fastest of `rounds` runs of `f` over `n` inputs (`f` returns the failures).
fn best_of(rounds: u32, mut f: impl FnMut() -> u64, n: usize) -> Rate {
    let mut best: Option<Rate> = None;
    for _ in 0..rounds {
        let started = Instant::now();
        let bad = f();
        let r = Rate { cases: n as u64, bad, time: started.elapsed() };
        best = Some(best.map_or(r, |b| b.best(r)));
    }
    best.expect("a round")
}

/// What to measure.
#[derive(Clone, Debug)]
pub struct Options {
    pub campaign: certify::Options,
    pub rounds: u32,
    /// The `serve` command of this build.
    pub serve: String,
    pub fuzz_binary: Option<PathBuf>,
    pub fuzz_seeds: Option<PathBuf>,
    pub fuzz_dict: Option<PathBuf>,
    pub fuzz_runs: u64,
    /// More libFuzzer flags.
    pub fuzz_args: Vec<String>,
}

/// The measurements of one run.
#[derive(Clone, Debug)]
pub struct Report {
    pub drawing: Rate,
    pub in_process: Rate,
    pub serve: Rate,
    pub serve_pipelined: bool,
    /// `serve` told no case ahead: one round trip per case.
    pub serve_lockstep: Rate,
    pub fuzz: Option<Result<FuzzRate, String>>,
    /// `/proc/loadavg` before and after.
    pub load: (String, String),
}

fn loadavg() -> String {
    std::fs::read_to_string("/proc/loadavg").map_or_else(|_| "?".to_string(), |l| l.split_whitespace().take(3).collect::<Vec<_>>().join(" "))
}

/// Measures the three rates (and the drawing alone).
pub fn run(o: &Options) -> Result<Report, String> {
    let load_before = loadavg();
    let limits = Limits::default();
    let serve = CandidateEngine::new(&o.serve, limits).map_err(|e| format!("serve command: {e}"))?;
    let mut best: [Option<Rate>; 4] = [None; 4];
    for _ in 0..o.rounds.max(1) {
        let rates = [
            drawing(&o.campaign),
            campaign(&ImplEngine, &o.campaign, 0),
            campaign(&serve, &o.campaign, LOOKAHEAD),
            campaign(&serve, &o.campaign, 0),
        ];
        for (b, r) in best.iter_mut().zip(rates) {
            *b = Some(b.map_or(r, |b| b.best(r)));
        }
    }
    let fuzz = o.fuzz_binary.as_ref().map(|b| fuzz(b, o.fuzz_seeds.as_deref(), o.fuzz_dict.as_deref(), o.fuzz_runs, &o.fuzz_args));
    let [drawing, in_process, serve_rate, serve_lockstep] = best.map(|b| b.expect("one round"));
    let serve_pipelined = serve.speaks().pipeline;
    Ok(Report { drawing, in_process, serve: serve_rate, serve_pipelined, serve_lockstep, fuzz, load: (load_before, loadavg()) })
}

impl Report {
    /// The table of rates and ratios, in Markdown.
    pub fn table(&self) -> String {
        let base = self.in_process.per_second();
        let row = |name: &str, rate: f64, note: String| format!("| {name} | {rate:.0} | {:.2} | {note} |\n", rate / base);
        let cases = |r: &Rate| format!("{} cases, {} not conforming, {:.2} s", r.cases, r.bad, r.time.as_secs_f64());
        let mut s = String::from("| rate | per second | ratio to in-process | |\n|---|---:|---:|---|\n");
        s.push_str(&row("in-process campaign, spec vs impl", base, cases(&self.in_process)));
        let pipelined = if self.serve_pipelined { "pipelined" } else { "one request at a time" };
        s.push_str(&row("`cyclecheck serve` as the candidate", self.serve.per_second(), format!("{pipelined}; {}", cases(&self.serve))));
        match &self.fuzz {
            Some(Ok(f)) => s.push_str(&row(
                "`diff_spec_impl` under libFuzzer",
                f.per_second(),
                format!("sanitizer: {}; {} executions, {:.2} s", f.sanitizer, f.executions, f.time.as_secs_f64()),
            )),
            Some(Err(e)) => s.push_str(&format!("| `diff_spec_impl` under libFuzzer | - | - | failed: {} |\n", e.lines().next().unwrap_or(""))),
            None => s.push_str("| `diff_spec_impl` under libFuzzer | - | - | no fuzz binary (--fuzz-binary) |\n"),
        }
        if let Some(Ok(f)) = &self.fuzz {
            s.push_str(&row("(`diff_spec_impl`'s body in-process, uninstrumented, on that run's corpus)", f.body.per_second(), cases(&f.body)));
            s.push_str(&row("(of which decoding the inputs into cases)", f.decoding.per_second(), cases(&f.decoding)));
        }
        s.push_str(&row("(`cyclecheck serve`, no case told ahead: a round trip per case)", self.serve_lockstep.per_second(), cases(&self.serve_lockstep)));
        s.push_str(&row("(drawing the cases alone)", self.drawing.per_second(), cases(&self.drawing)));
        s.push_str(&format!("\nload average before {}, after {}\n", self.load.0, self.load.1));
        s
    }
}

#[cfg(test)]
mod tests;
