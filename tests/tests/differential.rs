//! Differential campaigns: the production expander (`cycle-impl`) against the executable
//! reference (`cycle-spec`) on generated programs, judged by the exact conformance relation
//! (`cycle_oracle::conformance::check`: equal traces field by field, rule tags aside).
//!
//! One campaign per generator family of `cycle_oracle::gen`:
//! - G92 programs (valid and invalid, modal repeats, J/K combinations, multi-start, grids);
//! - G76 / G78 / FANUC G76 two-block programs (modes, depth schedules and their ties, tapers,
//!   internal threads, lead-in, pull-outs, the pass bound);
//! - G162 programs under `nc201` (M004: depth split, infeed angle, leg, taper, variable pitch,
//!   G90/G91, X radius or diameter, every cycle check);
//! - G32 / G33 / G34 thread-move programs (M003: start angles, lead changes, modal repeats);
//! - garbage (random bytes, word soup, corpus mutants): the same alarm, never a panic.
//!
//! Cases per campaign: `CYCLECHECK_CASES` (default 10 000 for G92, G76/G78, G162 and the thread
//! moves, a fifth of it for garbage); RNG seed: `CYCLECHECK_SEED` (a u64; a fixed default, so runs repeat). A failure
//! is shrunk to a minimal program, then reported as the divergence (kind, event, field, both
//! values as canonical G-code, the rule and its catalogue text, context) and the program text.

use cycle_oracle::campaign;
use cycle_oracle::conformance;
use cycle_oracle::corpus;
use cycle_oracle::engine::{Engine, ImplEngine, SpecEngine};
use cycle_oracle::gen::{self, Case};
use proptest::strategy::Strategy;
use proptest::test_runner::{Config as ProptestConfig, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};

/// `CYCLECHECK_CASES`, or the family's default.
fn cases(default: u32) -> u32 {
    std::env::var("CYCLECHECK_CASES").ok().and_then(|v| v.trim().parse().ok()).unwrap_or(default)
}

/// The RNG seed: `CYCLECHECK_SEED` (u64), else a fixed one.
fn seed() -> [u8; 32] {
    let s: u64 = std::env::var("CYCLECHECK_SEED").ok().and_then(|v| v.trim().parse().ok()).unwrap_or(0x5eed_c7c1_e0ac_1e00);
    gen::seed_bytes(s)
}

/// One case: both engines, then the relation. The failure message is the divergence and the
/// program.
fn conforms(case: &Case) -> Result<(), TestCaseError> {
    let reference = SpecEngine.expand(&case.program, &case.config);
    let candidate = ImplEngine::default().expand(&case.program, &case.config);
    conformance::check(&reference, &candidate).map_err(|d| {
        TestCaseError::fail(format!(
            "{d}\n\nprogram ({} family; {:?}, {:?}, start X{} Z{}, {:?}):\n{}",
            case.family,
            case.config.dialect,
            case.config.grid,
            case.config.start_x,
            case.config.start_z,
            case.config.params,
            case.text()
        ))
    })
}

/// Runs a campaign of `default` cases (unless `CYCLECHECK_CASES` says otherwise) and panics with
/// the minimal divergent case.
fn campaign(name: &str, strategy: impl Strategy<Value = Case>, default: u32) {
    let config = ProptestConfig { cases: cases(default), failure_persistence: None, ..ProptestConfig::default() };
    let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &seed()));
    match runner.run(&strategy, |case| conforms(&case)) {
        Ok(()) => {}
        Err(TestError::Fail(reason, _)) => {
            panic!("{name} campaign: the production expander diverges from the spec (case shrunk)\n{reason}")
        }
        Err(TestError::Abort(reason)) => panic!("{name} campaign aborted: {reason}"),
    }
}

#[test]
fn g92_programs_conform() {
    campaign("G92", gen::g92(), 10_000);
}

#[test]
fn g76_g78_programs_conform() {
    campaign("G76/G78", gen::multipass(), 10_000);
}

#[test]
fn g162_programs_conform() {
    campaign("G162", gen::g162(), 10_000);
}

#[test]
fn g32_g33_g34_programs_conform() {
    campaign("G32/G33/G34", gen::thread_moves(), 10_000);
}

#[test]
fn garbage_gets_the_same_alarm() {
    campaign("garbage", gen::garbage(), cases(10_000).div_ceil(5));
}

/// The built-in corpus (what `cyclecheck corpus` runs), through the campaign runner.
#[test]
fn corpus_conforms() {
    let report = campaign::run((&SpecEngine, &ImplEngine::default()), corpus::cases());
    let findings: Vec<String> = report.findings.iter().map(ToString::to_string).collect();
    assert!(report.all_conform(), "{}\n\n{}", report.summary(), findings.join("\n\n"));
}
