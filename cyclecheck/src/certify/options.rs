//! What a certification run runs ([`Options`]: the candidate, the families, the cases, the
//! readings, the declared deviations, the required level) and the defaults of its flags.

use super::{deviations, kani, shard};
use crate::candidate::Limits;
use cycle_kernel::conformance::Level;
use cycle_kernel::registry::{self, CycleRun, Family, FAMILIES};
use cycle_vocab::{Config, Dialect, Params};

/// Where the bundle goes by default.
pub const DEFAULT_OUT: &str = "evidence";
/// The default seed of the generated campaign (the differential tests' default).
pub const DEFAULT_SEED: u64 = 0x5eed_c7c1_e0ac_1e00;
/// Generated cases per family by default.
pub const DEFAULT_CASES: u32 = 2000;
/// A candidate run stops after this many consecutive candidate failures by default.
pub const DEFAULT_MAX_FAILURES: u32 = 10;
/// At most this many divergence signatures are minimized.
pub const MAX_MINIMIZED: usize = 32;
/// At most this many steps (engine runs) per minimization, for each of its two stages.
pub const SHRINK_STEPS: usize = 1000;
/// The page and `evidence.json` list at most this many failed cases (`cases.jsonl` has all).
pub const MAX_LISTED_FAILURES: usize = 100;

/// The `--cycles` name of the operator generator.
pub const OPERATOR: &str = "operator";

/// What to run.
#[derive(Clone, Debug)]
pub struct Options {
    /// The candidate command (`--candidate`); `None`: the production expander.
    pub candidate: Option<String>,
    pub limits: Limits,
    /// The families covered (`--cycles`), in registry order; all by default.
    pub cycles: Vec<&'static Family>,
    /// Whether the operator generator runs (`--cycles` all, or naming `operator`): thread cases
    /// with operator scripts (OP.SCRIPT), over the covered thread families.
    pub operator: bool,
    /// Generated cases per family (the garbage generator gets a fifth).
    pub cases: u32,
    pub seed: u64,
    /// Stop after this many consecutive candidate failures (refusals aside); 0: never.
    pub max_failures: u32,
    /// A vendor's `cargo kani` log (`--kani-log`), parsed: the proofs section lists its verdicts.
    pub kani_log: Option<kani::KaniLog>,
    /// The slice of the run to judge (`--shard K/N`); `None`: every case.
    pub shard: Option<shard::Shard>,
    /// `--reading` pins: fixed in every case of an in-process run (the others drawn per case);
    /// merged with a candidate's declared readings.
    pub readings: cycle_kernel::readings::Pins,
    /// The declared deviations (`--deviations`): a case whose first divergence matches one
    /// deviates as declared ([`super::CaseResult::Deviate`]).
    pub deviations: Vec<deviations::Deviation>,
    /// The comparison level the run requires (`--level`): a candidate that declares a weaker
    /// one does not pass. `None`: whatever it declares.
    pub level: Option<Level>,
    /// Every case's dialect, over the generator's (a third-party campaign's `dialect`: both
    /// engines expand each program under it); `None`: as drawn.
    pub dialect: Option<Dialect>,
    /// Parameters set in every case's configuration, over the generator's (a campaign's
    /// `params`); those left `None` stay as drawn.
    pub params: Params,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            candidate: None,
            limits: Limits::default(),
            cycles: FAMILIES.iter().collect(),
            operator: true,
            cases: DEFAULT_CASES,
            seed: DEFAULT_SEED,
            max_failures: DEFAULT_MAX_FAILURES,
            kani_log: None,
            shard: None,
            readings: cycle_kernel::readings::Pins::default(),
            deviations: Vec::new(),
            level: None,
            dialect: None,
            params: Params::default(),
        }
    }
}

impl Options {
    /// Whether every family is covered (then programs that run none, and garbage, are too).
    pub fn all_cycles(&self) -> bool {
        self.cycles.len() == FAMILIES.len()
    }

    /// Parses `--cycles`: `all` or a comma list of family names ([`registry::names`]) and
    /// `operator` (the operator generator, [`Options::operator`]; `all` includes it).
    pub fn parse_cycles(list: &str) -> Result<Vec<&'static Family>, String> {
        let names: Vec<&str> = list.split(',').map(str::trim).collect();
        if let Some(bad) = names.iter().find(|&&n| n != "all" && n != OPERATOR && registry::find(n).is_none()) {
            return Err(format!("--cycles takes all or a comma list of {}, {OPERATOR}, not {bad:?}", registry::names()));
        }
        Ok(FAMILIES.iter().filter(|f| names.contains(&"all") || names.contains(&f.name)).collect())
    }

    /// Whether `--cycles` asks for the operator generator: `all`, or `operator` named.
    pub fn parse_operator(list: &str) -> bool {
        list.split(',').map(str::trim).any(|n| n == "all" || n == OPERATOR)
    }

    /// The names `--cycles` would take for this run: the families, then `operator`.
    pub fn cycle_names(&self) -> Vec<&'static str> {
        self.cycles.iter().map(|f| f.name).chain(self.operator.then_some(OPERATOR)).collect()
    }

    /// `config` with the run's dialect and parameters set over its own ([`Options::dialect`],
    /// [`Options::params`]).
    pub fn configure(&self, config: &mut Config) {
        if let Some(d) = self.dialect {
            config.dialect = d;
        }
        set_params(&self.params, config);
    }

    /// Whether a case that runs `run` is in the run: with every family covered, any case is.
    pub fn covers(&self, run: CycleRun) -> bool {
        self.all_cycles() || matches!(run, CycleRun::Family(f) if self.cycles.contains(&f))
    }
}

/// `config` with every parameter `over` sets set over its own.
pub fn set_params(over: &Params, config: &mut Config) {
    for name in Params::NAMES {
        if let Some(v) = over.get(name) {
            let _ = config.params.set(name, v);
        }
    }
}
