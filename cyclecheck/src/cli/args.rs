//! The command line (clap, derive). Every default shown by `--help` is the constant the code
//! uses (`cyclecheck/tests/cli.rs` compares them).

use clap::{Args, Parser, Subcommand};
use cyclecheck::certify::{self, identity::LONG_VERSION, shard::Shard};
use cycle_kernel::conformance::Level;
use cycle_kernel::registry;
use cyclecheck::{gate, nightly};
use std::path::PathBuf;

mod shared;
use shared::{certify_readings_help, reading, readings_help};
pub use shared::{CandidateArgs, ConfigArgs, CorpusFormat, EngineArg, FormatArg, IncrementArg, UnitsArg};

#[derive(Parser, Debug)]
#[command(
    name = "cyclecheck",
    version = LONG_VERSION,
    about = "The lathe canned-cycle reference: expand programs, compare the production expander or your own with the reference spec, and write certification evidence.",
    after_help = "Exit status: 0 success / the engines conform (an alarm both engines raise conforms); 1 the engines diverge or the candidate fails (diff, corpus, certify, bench-harness), a gate step or a fuzz campaign fails; 2 bad input (the command line, an unreadable file, an unusable --out) — and for expand, a program that ends in an alarm; 130 interrupted (SIGINT/SIGTERM).\nREADME.md is the guide; docs/CANDIDATE.md the candidate protocol."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Expand a program into its trace (canonical G-code or JSON), written as it is produced.
    Expand(ExpandArgs),
    /// Compare the reference spec with the production expander (or a candidate) on programs.
    Diff(DiffArgs),
    /// Run every built-in program (the manuals' examples, the feature programs) through spec and impl.
    Corpus(CorpusArgs),
    /// Write the certification evidence bundle: the corpus and a generated campaign, spec vs the candidate.
    Certify(CertifyArgs),
    /// Join the bundles of certify --shard 1/N … N/N into the bundle of the whole run.
    Merge(MergeArgs),
    /// Certify the third-party expanders of candidates/*/candidate.toml and write their report (docs/THIRD-PARTY.md), or --check it.
    ThirdParty(ThirdPartyArgs),
    /// The pre-merge gate: corpus, campaign, fuzz replay, cargo test (run from the repository root).
    Gate(GateArgs),
    /// The nightly fuzz campaign with cargo-fuzz; or write the seeds; or decode a fuzz input (run from the repository root).
    Fuzz(FuzzArgs),
    /// Answer the candidate protocol on stdin/stdout with the production expander (a reference peer: --candidate 'cyclecheck serve').
    Serve,
    /// Measure the harness's rates in one run, as ratios: in-process campaign, cyclecheck serve as candidate, diff_spec_impl under libFuzzer.
    BenchHarness(BenchArgs),
}

#[derive(Args, Debug)]
pub struct ExpandArgs {
    /// The program file; - reads standard input.
    #[arg(value_name = "FILE")]
    pub file: String,
    /// The engine: the reference spec or the production expander.
    #[arg(long, value_enum, default_value_t = EngineArg::Spec)]
    pub engine: EngineArg,
    /// Canonical expanded G-code, or the trace as JSON (as the candidate protocol answers it).
    #[arg(long, value_enum, default_value_t = FormatArg::Gcode)]
    pub format: FormatArg,
    #[command(flatten)]
    pub config: ConfigArgs,
}

#[derive(Args, Debug)]
pub struct DiffArgs {
    /// Program files; - reads standard input (once).
    #[arg(value_name = "FILE", required = true)]
    pub files: Vec<String>,
    /// The report per file: text (gcode), or one JSON object per line.
    #[arg(long, value_enum, default_value_t = FormatArg::Gcode)]
    pub format: FormatArg,
    #[command(flatten)]
    pub config: ConfigArgs,
    #[command(flatten)]
    pub candidate: CandidateArgs,
}

#[derive(Args, Debug)]
pub struct CorpusArgs {
    /// One line per program and a summary, or one JSON document.
    #[arg(long, value_enum, default_value_t = CorpusFormat::Text)]
    pub format: CorpusFormat,
    #[arg(long = "reading", value_name = "NAME=VALUE", value_parser = reading, help = readings_help())]
    pub readings: Vec<String>,
}

fn cycles_help() -> String {
    format!("all, or a comma list of: {}, operator (the corpus and the generated campaign restricted to cases that run them; operator: thread cases with operator scripts, on the thread families listed)", registry::names())
}

/// The families of `--cycles`, and whether it asks for the operator generator.
#[derive(Clone, Debug)]
pub struct Cycles(pub Vec<&'static registry::Family>, pub bool);

fn cycles(list: &str) -> Result<Cycles, String> {
    certify::Options::parse_cycles(list).map(|f| Cycles(f, certify::Options::parse_operator(list)))
}

#[derive(Args, Debug)]
pub struct CertifyArgs {
    /// Where the bundle goes: a new directory, an empty one, or a previous bundle (replaced).
    #[arg(long, value_name = "DIR", default_value = certify::DEFAULT_OUT)]
    pub out: PathBuf,
    #[command(flatten)]
    pub candidate: CandidateArgs,
    /// Stop a candidate run after N consecutive candidate failures (refusals aside); 0: never.
    #[arg(long, value_name = "N", default_value_t = certify::DEFAULT_MAX_FAILURES)]
    pub max_failures: u32,
    #[arg(long, value_name = "LIST", default_value = "all", value_parser = cycles, help = cycles_help())]
    pub cycles: Cycles,
    /// Generated cases per family (the garbage generator a fifth; it runs only with all cycles).
    #[arg(long, value_name = "N", default_value_t = certify::DEFAULT_CASES)]
    pub cases: u32,
    /// Seed of the generated campaign.
    #[arg(long, value_name = "S", default_value_t = certify::DEFAULT_SEED)]
    pub seed: u64,
    /// A `cargo kani -p cycle-proofs` log to list with the proof properties (verdict, time,
    /// Kani and CBMC versions per harness); without it Kani is "not run here".
    #[arg(long, value_name = "FILE")]
    pub kani_log: Option<PathBuf>,
    /// Judge only shard K of N: case i of the corpus and of each family goes to shard i mod N + 1 (merge the shards' bundles with cyclecheck merge).
    #[arg(long, value_name = "K/N", value_parser = shard)]
    pub shard: Option<Shard>,
    #[arg(long = "reading", value_name = "NAME=VALUE", value_parser = reading, help = certify_readings_help())]
    pub readings: Vec<String>,
    /// Declared deviations (TOML, [[deviation]] rule, family, dialect, field, reason): a case whose first divergence matches one deviates as declared, never conforms (docs/CANDIDATE.md).
    #[arg(long, value_name = "FILE")]
    pub deviations: Option<PathBuf>,
    /// Require this comparison level (full, motion, motion-alarm-presence): a candidate whose greeting declares a weaker one fails before the run (exit 1).
    #[arg(long, value_name = "LEVEL", value_parser = Level::parse)]
    pub level: Option<Level>,
}

fn shard(text: &str) -> Result<Shard, String> {
    Shard::parse(text)
}

#[derive(Args, Debug)]
pub struct MergeArgs {
    /// Where the merged bundle goes: a new directory, an empty one, or a previous bundle (replaced).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// A `cargo kani -p cycle-proofs` log to list with the proof properties, as certify --kani-log.
    #[arg(long, value_name = "FILE")]
    pub kani_log: Option<PathBuf>,
    /// The shards' bundles: every shard 1/N … N/N of one certify run, each once.
    #[arg(value_name = "BUNDLE", required = true)]
    pub bundles: Vec<PathBuf>,
}

#[derive(Args, Debug)]
pub struct ThirdPartyArgs {
    /// Where the manifests are: DIR/*/candidate.toml.
    #[arg(long, value_name = "DIR", default_value = cyclecheck::thirdparty::DEFAULT_CANDIDATES)]
    pub candidates: PathBuf,
    /// Only this candidate (repeatable); the others keep their sections of --out.
    #[arg(long, value_name = "NAME")]
    pub only: Vec<String>,
    /// Only the candidates whose manifest says ci = true.
    #[arg(long)]
    pub ci: bool,
    /// The report.
    #[arg(long, value_name = "FILE", default_value = cyclecheck::thirdparty::DEFAULT_OUT)]
    pub out: PathBuf,
    /// Regenerate the report in memory and compare its counts, verdicts and divergence groups with --out (exit 1 when they differ or a group has no note).
    #[arg(long)]
    pub check: bool,
    /// List a candidate whose command cannot be started (or exits before the greeting) as not installed here, not as a failure.
    #[arg(long)]
    pub skip_missing: bool,
}

#[derive(Args, Debug)]
pub struct GateArgs {
    /// Cases of the in-process differential campaign.
    #[arg(long, value_name = "N", default_value_t = gate::DEFAULT_CASES)]
    pub cases: u32,
    /// Seed of the campaign, also CYCLECHECK_SEED of cargo test.
    #[arg(long, value_name = "S", default_value_t = gate::DEFAULT_SEED)]
    pub seed: u64,
    /// Skip the cargo test step.
    #[arg(long)]
    pub no_cargo_test: bool,
    /// CYCLECHECK_CASES of the cargo test step.
    #[arg(long, value_name = "N", default_value_t = gate::DEFAULT_TEST_CASES)]
    pub test_cases: u32,
    /// CYCLECHECK_PROOF_CASES of the cargo test step.
    #[arg(long, value_name = "N", default_value_t = gate::DEFAULT_PROOF_CASES)]
    pub proof_cases: u64,
    /// Run only shard K of N of the corpus, campaign and fuzz replay steps (case i to shard i mod N + 1); the cargo test step runs on shard 1 only.
    #[arg(long, value_name = "K/N", value_parser = shard)]
    pub shard: Option<Shard>,
}

/// The targets of `--targets`.
#[derive(Clone, Debug)]
pub struct Targets(pub Vec<cycle_kernel::fuzzing::Target>);

fn targets(list: &str) -> Result<Targets, String> {
    nightly::parse_targets(list).map(Targets)
}

fn targets_help() -> String {
    format!("Fuzz targets, a comma list of: {} (default: all)", nightly::target_names())
}

#[derive(Args, Debug)]
pub struct FuzzArgs {
    /// Seconds of fuzzing per target.
    #[arg(long, value_name = "SECS", default_value_t = nightly::DEFAULT_BUDGET, value_parser = clap::value_parser!(u64).range(1..))]
    pub budget: u64,
    #[arg(long, value_name = "T,..", value_parser = targets, help = targets_help())]
    pub targets: Option<Targets>,
    /// Scratch corpora, artifacts, logs and the summary.
    #[arg(long, value_name = "DIR", default_value = nightly::DEFAULT_OUT)]
    pub out: PathBuf,
    /// Cargo features of the fuzz crate (planted-depth-bug).
    #[arg(long, value_name = "F")]
    pub features: Option<String>,
    /// Fuzz each target with N jobs in parallel (libFuzzer's -fork=N); 1: one process, no -fork.
    #[arg(long, value_name = "N", default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    pub fork: u32,
    /// libFuzzer's -rss_limit_mb: an input using more memory is an oom finding (0: no limit).
    #[arg(long, value_name = "MB", default_value_t = nightly::DEFAULT_RSS_LIMIT_MB)]
    pub rss_limit_mb: u64,
    /// Rewrite fuzz/seeds/ from the built-in set and encode them into fuzz/corpus/, then exit.
    #[arg(long, conflicts_with = "decode")]
    pub write_seeds: bool,
    /// Write a fuzz input as a decoded regression case (tests/fuzz_regressions/TARGET/NAME), then exit.
    #[arg(long, num_args = 2..=3, value_names = ["TARGET", "FILE", "NAME"])]
    pub decode: Option<Vec<String>>,
}

#[derive(Args, Debug)]
pub struct BenchArgs {
    /// Generated cases per family in each campaign (certify's cases: the corpus, then each generator).
    #[arg(long, value_name = "N", default_value_t = 100)]
    pub cases: u32,
    /// Rounds of each campaign, interleaved; the best counts.
    #[arg(long, value_name = "N", default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..))]
    pub rounds: u32,
    /// The diff_spec_impl libFuzzer binary (built by cargo fuzz build); default: fuzz/target/x86_64-unknown-linux-gnu/release/diff_spec_impl when it exists.
    #[arg(long, value_name = "FILE")]
    pub fuzz_binary: Option<PathBuf>,
    /// Executions of the fuzz binary (libFuzzer's -runs), starting from the seeds of fuzz/seeds/diff_spec_impl.
    #[arg(long, value_name = "N", default_value_t = 30_000)]
    pub fuzz_runs: u64,
    /// A further libFuzzer flag for the fuzz binary (repeatable), e.g. --fuzz-arg=-entropic=0.
    #[arg(long, value_name = "FLAG", allow_hyphen_values = true)]
    pub fuzz_arg: Vec<String>,
}
