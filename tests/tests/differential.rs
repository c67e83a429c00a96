//! Differential campaigns: the production expander (`cycle-impl`) against the executable
//! reference (`cycle-spec`) on generated programs, judged by the exact conformance relation
//! (`cycle_kernel::conformance::check`: equal traces field by field, rule tags aside).
//!
//! One campaign per cycle family of `cycle_kernel::registry` (a test module each, `g92::conforms`,
//! …: the family's generator in `cycle_kernel::gen`, every program spelled in the forms the lexer
//! promises), and one of garbage (random bytes, word soup, corpus mutants): the same alarm,
//! never a panic. The list of family campaigns must equal the registry's families
//! (`campaigns_are_the_registry`).
//!
//! Each generated case runs under declared readings drawn for it (`cycle_kernel::gen::drawn`:
//! each reading the letter half the time), so both engines are compared under every value.
//!
//! Cases per campaign: `CYCLECHECK_CASES` (default 10 000 per family, a fifth of it for
//! garbage); RNG seed: `CYCLECHECK_SEED` (a u64; a fixed default, so runs repeat). A failure
//! is shrunk to a minimal program, then reported as the divergence (kind, event, field, both
//! values as canonical G-code, the rule and its catalogue text, context) and the program text.

use cycle_kernel::campaign;
use cycle_kernel::conformance;
use cycle_kernel::corpus;
use cycle_kernel::engine::{Engine, ImplEngine, SpecEngine};
use cycle_kernel::gen::{self, Case};
use cycle_kernel::registry;
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
    let candidate = ImplEngine.expand(&case.program, &case.config);
    conformance::check(&reference, &candidate).map_err(|d| {
        TestCaseError::fail(format!(
            "{d}\n\nprogram ({} family; {:?}, {:?}, start X{} Z{}, {:?}; readings: {}):\n{}",
            case.family,
            case.config.dialect,
            case.config.grid,
            case.config.start_x,
            case.config.start_z,
            case.config.params,
            cycle_kernel::readings::line(&case.config.readings),
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

/// A test module per family, `<family>::conforms`, each the family's campaign, and the list of
/// them, `CAMPAIGNS`.
macro_rules! family_campaigns {
    ($($family:ident),* $(,)?) => {
        $(
            mod $family {
                #[test]
                fn conforms() {
                    super::family_campaign(stringify!($family));
                }
            }
        )*
        const CAMPAIGNS: &[&str] = &[$(stringify!($family)),*];
    };
}

family_campaigns!(g92, g76, g78, f76, g162, g32, g90, g94, g71, g72, g70, g73, g74, g75, g83, g84);

/// Every registry family has its campaign here, and each campaign is a registry family's, in
/// the registry's order.
#[test]
fn campaigns_are_the_registry() {
    let registered: Vec<&str> = registry::FAMILIES.iter().map(|f| f.name).collect();
    assert_eq!(CAMPAIGNS, registered, "the family campaigns of differential.rs are not the registry's families");
}

/// The campaign of the registry family `name`.
fn family_campaign(name: &str) {
    let family = registry::find(name).unwrap_or_else(|| panic!("{name} is no registry family"));
    campaign(family.display, family.strategy(), 10_000);
}

#[test]
fn garbage_gets_the_same_alarm() {
    campaign("garbage", gen::garbage::strategy(), cases(10_000).div_ceil(5));
}

/// The built-in corpus (what `cyclecheck corpus` runs), through the campaign runner.
#[test]
fn corpus_conforms() {
    let report = campaign::run((&SpecEngine, &ImplEngine), corpus::cases());
    let findings: Vec<String> = report.findings.iter().map(ToString::to_string).collect();
    assert!(report.all_conform(), "{}\n\n{}", report.summary(), findings.join("\n\n"));
}
