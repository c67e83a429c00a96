//! `cyclecheck certify`: the certification run and its evidence bundle.
//!
//! The run takes the built-in corpus (the manuals' examples and the feature programs,
//! [`crate::corpus`]) and a fixed-seed generated campaign ([`crate::gen`]: G92, G76/G78/FANUC
//! G76, garbage), runs each case through the reference spec and a candidate — the production
//! expander, or a vendor's expander behind the candidate protocol ([`crate::candidate`]) — and
//! judges each pair of traces with the conformance relation ([`crate::conformance`]).
//!
//! Every case is recorded: its cycle, the rules its reference trace exercises (the rule tags of
//! its moves, passes and alarm), and its result — conform, the first divergence, or the
//! candidate's failure (timeout, crash, garbage, …). Divergences are grouped by signature (kind,
//! field, rule); the first case of each group is minimized: a generated case first by proptest's
//! shrinking of its knobs, then — like a corpus program — by deleting lines while the same
//! divergence stays.
//!
//! The bundle ([`bundle::write`]): `evidence.json` ([`evidence`]), `index.html` ([`html`]) with
//! the traceability matrix ([`matrix`]) and the interpretation register, and one SVG toolpath
//! per corpus program ([`plot`]).

pub mod bundle;
pub mod evidence;
pub mod html;
pub mod markdown;
pub mod matrix;
pub mod plot;

use crate::campaign::cycle_of;
use crate::candidate::{CandidateEngine, Limits};
use crate::conformance::{self, Divergence, DivergenceKind};
use crate::engine::{Engine, Failure, FailureKind, ImplEngine, SpecEngine};
use crate::{corpus, gen};
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Rule};
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config as ProptestConfig, RngAlgorithm, TestRng, TestRunner};
use std::collections::{BTreeMap, BTreeSet};
use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

/// The cycles a run covers, by their `--cycles` names.
pub const CYCLES: &[(&str, &str)] = &[
    ("g92", "G92"),
    ("g76", "G76"),
    ("g78", "G78"),
    ("f76", "G76 fanuc"),
    ("g162", "G162"),
    ("g32", "G32/G33/G34"),
];

/// The cycle a program exercises: [`cycle_of`]'s name (`G92`, `G76`, `G76 fanuc`, `G78`), else
/// `G162` or `G32/G33/G34` for the first of those codes, else `none`.
pub fn cycle(program: &[u8], config: &Config) -> &'static str {
    match cycle_of(program, config) {
        "none" => {}
        named => return named,
    }
    for block in cycle_vocab::Blocks::new(program) {
        let Ok(block) = block else { break };
        for g in block.g_codes().iter().filter(|g| !g.point && !g.negative) {
            match g.mantissa {
                162 => return "G162",
                32..=34 => return "G32/G33/G34",
                _ => {}
            }
        }
    }
    "none"
}

/// The default seed of the generated campaign (the differential tests' default).
pub const DEFAULT_SEED: u64 = 0x5eed_c7c1_e0ac_1e00;
/// Generated cases per family by default.
pub const DEFAULT_CASES: u32 = 2000;
/// At most this many divergence signatures are minimized.
pub const MAX_MINIMIZED: usize = 32;
/// At most this many steps (engine runs) per minimization, for each of its two stages.
pub const SHRINK_STEPS: usize = 1000;

/// What to run.
#[derive(Clone, Debug)]
pub struct Options {
    /// The candidate command (`--candidate`); `None`: the production expander.
    pub candidate: Option<String>,
    pub limits: Limits,
    /// The cycles covered (campaign names `G92`, `G76`, `G78`, `G76 fanuc`); all by default.
    pub cycles: BTreeSet<&'static str>,
    /// Generated cases per family (the garbage family gets a fifth).
    pub cases: u32,
    pub seed: u64,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            candidate: None,
            limits: Limits::default(),
            cycles: CYCLES.iter().map(|&(_, c)| c).collect(),
            cases: DEFAULT_CASES,
            seed: DEFAULT_SEED,
        }
    }
}

impl Options {
    /// Whether every cycle is covered (then programs without a cycle, and garbage, are too).
    pub fn all_cycles(&self) -> bool {
        self.cycles.len() == CYCLES.len()
    }

    /// Parses `--cycles`: `all` or a comma list of `g92`, `g76`, `g78`, `f76`, `g162`, `g32`.
    pub fn parse_cycles(list: &str) -> Result<BTreeSet<&'static str>, String> {
        if list == "all" {
            return Ok(CYCLES.iter().map(|&(_, c)| c).collect());
        }
        let mut set = BTreeSet::new();
        for name in list.split(',').map(str::trim) {
            match CYCLES.iter().find(|&&(n, _)| n == name) {
                Some(&(_, cycle)) => set.insert(cycle),
                None => {
                    return Err(format!("--cycles takes all or a comma list of g92, g76, g78, f76, g162, g32, not {name:?}"))
                }
            };
        }
        Ok(set)
    }

    /// Whether a case of `cycle` (a [`cycle`] name, `none` for no cycle) is in the run: with
    /// every cycle selected, any case is.
    pub fn covers(&self, cycle: &str) -> bool {
        self.all_cycles() || self.cycles.contains(cycle)
    }
}

/// How a case ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CaseResult {
    Conform,
    Diverge(Box<Divergence>),
    /// An engine produced no trace (`engine` is `spec` or the candidate's name).
    Failure { engine: String, failure: Failure },
}

impl CaseResult {
    pub fn conforms(&self) -> bool {
        matches!(self, CaseResult::Conform)
    }

    /// One line: `conform`, `DIVERGE (field mismatch at event 5, field x, rule G92.PULLOUT)`,
    /// `FAIL (timeout: …)`.
    pub fn short(&self) -> String {
        match self {
            CaseResult::Conform => "conform".to_string(),
            CaseResult::Diverge(d) => {
                let field = d.field.map(|f| format!(", field {f}")).unwrap_or_default();
                let rule = d.rule.map(|r| format!(", rule {r}")).unwrap_or_default();
                format!("DIVERGE ({} at event {}{field}{rule})", d.kind, d.index)
            }
            CaseResult::Failure { engine, failure } => format!("FAIL ({engine} {})", failure.kind),
        }
    }
}

/// Where a case comes from.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Origin {
    /// A built-in program, by path.
    Corpus { path: &'static str },
    /// A generated case: its family and index in the family's seeded sequence.
    Generated { family: &'static str, index: u32 },
}

/// One case of the run.
#[derive(Clone, Debug)]
pub struct CaseRecord {
    pub name: String,
    pub origin: Origin,
    /// [`cycle`] of the program: `G92`, `G76`, `G76 fanuc`, `G78`, `G162`, `G32/G33/G34` or `none`.
    pub cycle: &'static str,
    pub program: Vec<u8>,
    pub config: Config,
    /// Events of the reference trace (0 when the reference failed).
    pub events: usize,
    /// The rules the reference trace exercises: the rule tags of its events and alarm.
    pub rules: BTreeSet<Rule>,
    /// `clean`, or the reference's alarm in short form.
    pub ending: String,
    pub result: CaseResult,
    /// Both traces, kept for corpus programs (the plots).
    pub traces: Option<(Trace, Option<Trace>)>,
}

/// The identity of a divergence for grouping: kind, field, the reference's rule.
pub type Signature = (DivergenceKind, Option<&'static str>, Option<Rule>);

fn signature(d: &Divergence) -> Signature {
    (d.kind, d.field, d.rule)
}

/// A minimized divergent input.
#[derive(Clone, Debug)]
pub struct Minimized {
    pub program: Vec<u8>,
    pub config: Config,
    pub divergence: Divergence,
    /// `proptest shrinking, line deletion` or `line deletion`.
    pub method: &'static str,
    /// Engine runs spent.
    pub steps: usize,
}

/// The cases with one divergence signature.
#[derive(Clone, Debug)]
pub struct Group {
    pub signature: Signature,
    /// Indices into [`Run::records`], in run order.
    pub cases: Vec<usize>,
    /// The first case minimized (the first [`MAX_MINIMIZED`] groups only).
    pub minimized: Option<Minimized>,
}

/// A generated family's seed and size.
#[derive(Clone, Debug)]
pub struct FamilyRun {
    pub family: &'static str,
    pub seed: u64,
    /// Cases drawn from the generator, and those kept (their cycle is in the run).
    pub drawn: u32,
    pub kept: u32,
}

/// The result of a certification run.
pub struct Run {
    pub options: Options,
    /// The candidate's name for reports: `impl` or `candidate`.
    pub candidate: String,
    /// The candidate's command as split, when external.
    pub candidate_argv: Option<Vec<String>>,
    /// How many times the candidate process was started (external candidates).
    pub candidate_starts: u64,
    pub records: Vec<CaseRecord>,
    pub families: Vec<FamilyRun>,
    pub groups: Vec<Group>,
    pub duration: Duration,
}

impl Run {
    pub fn cases(&self) -> usize {
        self.records.len()
    }

    pub fn conforming(&self) -> usize {
        self.records.iter().filter(|r| r.result.conforms()).count()
    }

    pub fn diverging(&self) -> usize {
        self.records.iter().filter(|r| matches!(r.result, CaseResult::Diverge(_))).count()
    }

    pub fn failures(&self) -> usize {
        self.records.iter().filter(|r| matches!(r.result, CaseResult::Failure { .. })).count()
    }

    /// Whether every case conformed.
    pub fn passed(&self) -> bool {
        self.conforming() == self.cases()
    }

    /// Failures by kind.
    pub fn failures_by_kind(&self) -> BTreeMap<FailureKind, usize> {
        let mut m = BTreeMap::new();
        for r in &self.records {
            if let CaseResult::Failure { failure, .. } = &r.result {
                *m.entry(failure.kind).or_default() += 1;
            }
        }
        m
    }

    /// Per cycle: cases, conform, diverge, fail.
    pub fn by_cycle(&self) -> BTreeMap<&'static str, [usize; 4]> {
        let mut m: BTreeMap<&'static str, [usize; 4]> = BTreeMap::new();
        for r in &self.records {
            let c = m.entry(r.cycle).or_default();
            c[0] += 1;
            match r.result {
                CaseResult::Conform => c[1] += 1,
                CaseResult::Diverge(_) => c[2] += 1,
                CaseResult::Failure { .. } => c[3] += 1,
            }
        }
        m
    }

    /// Per rule: cases whose reference trace exercises it, and divergences that name it.
    pub fn by_rule(&self) -> BTreeMap<Rule, (usize, usize)> {
        let mut m: BTreeMap<Rule, (usize, usize)> = BTreeMap::new();
        for r in &self.records {
            for &rule in &r.rules {
                m.entry(rule).or_default().0 += 1;
            }
            if let CaseResult::Diverge(d) = &r.result {
                if let Some(rule) = d.rule {
                    m.entry(rule).or_default().1 += 1;
                }
            }
        }
        m
    }

    /// A few lines for the terminal: counts, then each divergence group (first case in full)
    /// and each failure kind with its first case.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "spec vs {}: {} cases, {} conform, {} diverge, {} fail ({:.1} s)\n",
            self.candidate,
            self.cases(),
            self.conforming(),
            self.diverging(),
            self.failures(),
            self.duration.as_secs_f64()
        );
        for (cycle, [n, ok, div, fail]) in self.by_cycle() {
            s.push_str(&format!("  {cycle:<10} {n:>6} cases  {ok:>6} conform  {div:>5} diverge  {fail:>5} fail\n"));
        }
        for g in &self.groups {
            let first = &self.records[g.cases[0]];
            s.push_str(&format!("\n{} case(s) diverge like {}:\n", g.cases.len(), first.name));
            if let CaseResult::Diverge(d) = &first.result {
                s.push_str(&format!("{d}\n"));
            }
            if let Some(m) = &g.minimized {
                s.push_str(&format!(
                    "minimized ({}, {} steps), divergence at event {}:\n{}",
                    m.method,
                    m.steps,
                    m.divergence.index,
                    String::from_utf8_lossy(&m.program)
                ));
                if !m.program.ends_with(b"\n") {
                    s.push('\n');
                }
            }
        }
        for (kind, n) in self.failures_by_kind() {
            let first = self.records.iter().find(|r| matches!(&r.result, CaseResult::Failure { failure, .. } if failure.kind == kind));
            if let Some(CaseRecord { name, result: CaseResult::Failure { engine, failure }, .. }) = first {
                s.push_str(&format!("\n{n} case(s) fail with {kind}; first {name} ({engine}): {}\n", failure.message));
            }
        }
        s
    }
}

/// Progress of a run, for a progress bar.
#[derive(Clone, Copy, Debug)]
pub struct Progress<'a> {
    /// `corpus`, `generated`, `minimizing`.
    pub phase: &'a str,
    pub done: usize,
    pub total: usize,
    /// Cases not conforming so far.
    pub bad: usize,
}

/// Why a run could not start.
#[derive(Debug)]
pub struct Error(pub String);

impl std::fmt::Display for Error {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

/// One case of the list: its name, origin, program and configuration, and (generated cases)
/// the value tree it came from, for shrinking.
struct Pending {
    name: String,
    origin: Origin,
    program: Vec<u8>,
    config: Config,
    tree: Option<Box<dyn ValueTree<Value = gen::Case>>>,
}

/// The 32-byte ChaCha seed of a family: the run's seed mixed with the family's number.
fn family_seed(seed: u64, family: u64) -> u64 {
    seed ^ family.wrapping_mul(0x9e37_79b9_7f4a_7c15)
}

/// The generated families of a run: name, strategy, cases to draw.
fn families(options: &Options) -> Vec<(&'static str, BoxedStrategy<gen::Case>, u32)> {
    let mut f = Vec::new();
    if options.cycles.contains("G92") {
        f.push(("g92", gen::g92().boxed(), options.cases));
    }
    if ["G76", "G78", "G76 fanuc"].iter().any(|c| options.cycles.contains(c)) {
        f.push(("multipass", gen::multipass().boxed(), options.cases));
    }
    if options.cycles.contains("G162") {
        f.push(("g162", gen::g162().boxed(), options.cases));
    }
    if options.cycles.contains("G32/G33/G34") {
        f.push(("thread_moves", gen::thread_moves().boxed(), options.cases));
    }
    if options.all_cycles() {
        f.push(("garbage", gen::garbage().boxed(), options.cases.div_ceil(5)));
    }
    f
}

/// The case list: the corpus programs of the covered cycles, then the generated families.
fn case_list(options: &Options) -> (Vec<Pending>, Vec<FamilyRun>) {
    let mut list = Vec::new();
    for p in corpus::PROGRAMS {
        let config = p.config();
        if options.covers(cycle(p.text.as_bytes(), &config)) {
            list.push(Pending {
                name: p.name.to_string(),
                origin: Origin::Corpus { path: p.path },
                program: p.text.as_bytes().to_vec(),
                config,
                tree: None,
            });
        }
    }
    let mut runs = Vec::new();
    for (number, (family, strategy, count)) in families(options).into_iter().enumerate() {
        let seed = family_seed(options.seed, number as u64 + 1);
        let config = ProptestConfig { cases: count, failure_persistence: None, ..ProptestConfig::default() };
        let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &gen::seed_bytes(seed)));
        let mut kept = 0;
        for index in 0..count {
            let Ok(tree) = strategy.new_tree(&mut runner) else { continue };
            let case = tree.current();
            if !options.covers(cycle(&case.program, &case.config)) {
                continue;
            }
            kept += 1;
            list.push(Pending {
                name: format!("{family}#{index}"),
                origin: Origin::Generated { family, index },
                program: case.program,
                config: case.config,
                tree: Some(tree),
            });
        }
        runs.push(FamilyRun { family, seed, drawn: count, kept });
    }
    (list, runs)
}

fn panic_message(p: Box<dyn std::any::Any + Send>) -> String {
    match p.downcast::<String>() {
        Ok(s) => *s,
        Err(p) => p.downcast_ref::<&str>().map_or_else(|| "panic".to_string(), |s| s.to_string()),
    }
}

/// One engine on one case; a panic becomes a [`FailureKind::Panic`] failure.
fn try_engine(engine: &dyn Engine, program: &[u8], config: &Config) -> Result<Trace, Failure> {
    catch_unwind(AssertUnwindSafe(|| engine.try_expand(program, config)))
        .unwrap_or_else(|p| Err(Failure { kind: FailureKind::Panic, message: panic_message(p) }))
}

/// Runs one case through the reference and the candidate: both traces (when produced) and the
/// result.
pub fn judge(reference: &dyn Engine, candidate: &dyn Engine, program: &[u8], config: &Config) -> (Option<Trace>, Option<Trace>, CaseResult) {
    let r = match try_engine(reference, program, config) {
        Ok(t) => t,
        Err(failure) => return (None, None, CaseResult::Failure { engine: reference.name().to_string(), failure }),
    };
    match try_engine(candidate, program, config) {
        Err(failure) => (Some(r), None, CaseResult::Failure { engine: candidate.name().to_string(), failure }),
        Ok(c) => {
            let result = match conformance::check(&r, &c) {
                Ok(()) => CaseResult::Conform,
                Err(d) => CaseResult::Diverge(Box::new(d)),
            };
            (Some(r), Some(c), result)
        }
    }
}

/// The candidate engine of a run.
pub fn candidate_engine(options: &Options) -> Result<Box<dyn Engine>, Error> {
    match &options.candidate {
        None => Ok(Box::new(ImplEngine::default())),
        Some(cmd) => Ok(Box::new(CandidateEngine::new(cmd, options.limits).map_err(|e| Error(format!("--candidate: {e}")))?)),
    }
}

/// Runs the certification: every case, then the minimization of each divergence group.
pub fn run(options: &Options, progress: &mut dyn FnMut(Progress)) -> Result<Run, Error> {
    let started = Instant::now();
    let candidate = match &options.candidate {
        None => None,
        Some(cmd) => Some(CandidateEngine::new(cmd, options.limits).map_err(|e| Error(format!("--candidate: {e}")))?),
    };
    let imp = ImplEngine::default();
    let engine: &dyn Engine = match &candidate {
        Some(c) => c,
        None => &imp,
    };
    let (mut list, families) = case_list(options);
    let total = list.len();
    let mut records = Vec::with_capacity(total);
    let mut bad = 0;
    for (i, p) in list.iter().enumerate() {
        let phase = if matches!(p.origin, Origin::Corpus { .. }) { "corpus" } else { "generated" };
        if i % 8 == 0 {
            progress(Progress { phase, done: i, total, bad });
        }
        let (reference, cand, result) = judge(&SpecEngine, engine, &p.program, &p.config);
        if !result.conforms() {
            bad += 1;
        }
        let mut rules = BTreeSet::new();
        let (events, ending) = match &reference {
            Some(t) => {
                rules.extend(t.events.iter().map(|e| e.rule()));
                rules.extend(t.alarm.map(|a| a.rule));
                let ending = t.alarm.as_ref().map_or_else(|| "clean".to_string(), conformance::alarm_short);
                (t.events.len(), ending)
            }
            None => (0, "reference failed".to_string()),
        };
        let traces = match (&p.origin, reference) {
            (Origin::Corpus { .. }, Some(r)) => Some((r, cand)),
            _ => None,
        };
        records.push(CaseRecord {
            name: p.name.clone(),
            origin: p.origin.clone(),
            cycle: cycle(&p.program, &p.config),
            program: p.program.clone(),
            config: p.config,
            events,
            rules,
            ending,
            result,
            traces,
        });
    }
    progress(Progress { phase: "generated", done: total, total, bad });

    let mut groups: Vec<Group> = Vec::new();
    for (i, r) in records.iter().enumerate() {
        if let CaseResult::Diverge(d) = &r.result {
            let sig = signature(d);
            match groups.iter_mut().find(|g| g.signature == sig) {
                Some(g) => g.cases.push(i),
                None => groups.push(Group { signature: sig, cases: vec![i], minimized: None }),
            }
        }
    }
    let to_minimize = groups.len().min(MAX_MINIMIZED);
    for (n, g) in groups.iter_mut().take(MAX_MINIMIZED).enumerate() {
        progress(Progress { phase: "minimizing", done: n, total: to_minimize, bad });
        let first = g.cases[0];
        g.minimized = minimize(engine, &records[first], &mut list[first], g.signature);
    }
    if to_minimize > 0 {
        progress(Progress { phase: "minimizing", done: to_minimize, total: to_minimize, bad });
    }
    Ok(Run {
        options: options.clone(),
        candidate: engine.name().to_string(),
        candidate_argv: candidate.as_ref().map(|c| c.argv().to_vec()),
        candidate_starts: candidate.as_ref().map_or(0, CandidateEngine::starts),
        records,
        families,
        groups,
        duration: started.elapsed(),
    })
}

/// The divergence of `program` if it has signature `sig`.
fn diverges_as(engine: &dyn Engine, program: &[u8], config: &Config, sig: Signature) -> Option<Divergence> {
    match judge(&SpecEngine, engine, program, config).2 {
        CaseResult::Diverge(d) if signature(&d) == sig => Some(*d),
        _ => None,
    }
}

/// The smallest input found that diverges with the same signature.
fn minimize(engine: &dyn Engine, record: &CaseRecord, pending: &mut Pending, sig: Signature) -> Option<Minimized> {
    let CaseResult::Diverge(first) = &record.result else { return None };
    let mut best = Minimized {
        program: record.program.clone(),
        config: record.config,
        divergence: (**first).clone(),
        method: "line deletion",
        steps: 0,
    };
    if let Some(tree) = pending.tree.as_mut() {
        // proptest's shrinking: simplify while the case fails, complicate when it passes.
        best.method = "proptest shrinking, line deletion";
        let mut failing = true;
        while best.steps < SHRINK_STEPS {
            let moved = if failing { tree.simplify() } else { tree.complicate() };
            if !moved {
                break;
            }
            best.steps += 1;
            let case = tree.current();
            match diverges_as(engine, &case.program, &case.config, sig) {
                Some(d) => {
                    failing = true;
                    best.program = case.program;
                    best.config = case.config;
                    best.divergence = d;
                }
                None => failing = false,
            }
        }
    }
    // Delete one line at a time, last first, while the same divergence stays.
    let mut lines: Vec<Vec<u8>> = best.program.split_inclusive(|&b| b == b'\n').map(<[u8]>::to_vec).collect();
    let budget = best.steps + SHRINK_STEPS;
    let mut changed = true;
    while changed && best.steps < budget {
        changed = false;
        for i in (0..lines.len()).rev() {
            if best.steps >= budget || lines.len() <= 1 {
                break;
            }
            let mut shorter = lines.clone();
            shorter.remove(i);
            let program = shorter.concat();
            best.steps += 1;
            if let Some(d) = diverges_as(engine, &program, &best.config, sig) {
                lines = shorter;
                best.program = program;
                best.divergence = d;
                changed = true;
            }
        }
    }
    Some(best)
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::engine::wrong::{Panics, SpecWith};

    /// The spec with the X of every thread move one increment off: a wrong candidate.
    const THREAD_X_OFF: SpecWith = SpecWith {
        name: "thread-x-off",
        fault: |_, m| m.x += i64::from(m.kind == cycle_vocab::MoveKind::Thread),
    };

    #[test]
    fn cycles_option() {
        assert_eq!(Options::parse_cycles("g92").unwrap(), BTreeSet::from(["G92"]));
        assert_eq!(Options::parse_cycles("g76,f76").unwrap(), BTreeSet::from(["G76", "G76 fanuc"]));
        assert_eq!(Options::parse_cycles("all").unwrap().len(), CYCLES.len());
        assert_eq!(Options::parse_cycles("g162,g32").unwrap(), BTreeSet::from(["G162", "G32/G33/G34"]));
        assert!(Options::parse_cycles("g93").is_err());
        let o = Options { cycles: Options::parse_cycles("g92").unwrap(), ..Options::default() };
        assert!(o.covers("G92") && !o.covers("G78") && !o.covers("none"));
        assert!(Options::default().covers("none"));
    }

    #[test]
    fn case_list_is_seeded_and_filtered() {
        let o = Options { cycles: Options::parse_cycles("g92").unwrap(), cases: 20, ..Options::default() };
        let (a, fa) = case_list(&o);
        let (b, _) = case_list(&o);
        assert_eq!(a.iter().map(|p| &p.program).collect::<Vec<_>>(), b.iter().map(|p| &p.program).collect::<Vec<_>>());
        assert!(a.iter().all(|p| cycle(&p.program, &p.config) == "G92"));
        assert_eq!(a.iter().filter(|p| matches!(p.origin, Origin::Corpus { .. })).count(), 6);
        assert_eq!((fa.len(), fa[0].family, fa[0].drawn, fa[0].kept), (1, "g92", 20, 20));
        let other = Options { seed: 1, ..o };
        let (c, _) = case_list(&other);
        assert_ne!(a.last().unwrap().program, c.last().unwrap().program);
    }

    #[test]
    fn a_wrong_candidate_is_found_grouped_and_minimized() {
        let o = Options { cycles: Options::parse_cycles("g92").unwrap(), cases: 10, ..Options::default() };
        let (mut list, _) = case_list(&o);
        let p = &list[0];
        let (r, c, result) = judge(&SpecEngine, &THREAD_X_OFF, &p.program, &p.config);
        assert!(r.is_some() && c.is_some());
        let CaseResult::Diverge(d) = &result else { panic!("{result:?}") };
        assert_eq!(d.field, Some("x"));
        let record = CaseRecord {
            name: p.name.clone(),
            origin: p.origin.clone(),
            cycle: "G92",
            program: p.program.clone(),
            config: p.config,
            events: 0,
            rules: BTreeSet::new(),
            ending: String::new(),
            result: result.clone(),
            traces: None,
        };
        let m = minimize(&THREAD_X_OFF, &record, &mut list[0], signature(d)).unwrap();
        assert_eq!(m.method, "line deletion");
        assert!(m.program.len() < record.program.len(), "{}", String::from_utf8_lossy(&m.program));
        assert_eq!(signature(&m.divergence), signature(d));
    }

    #[test]
    fn panics_are_failures() {
        let (_, _, r) = judge(&SpecEngine, &Panics, b"G0 X1", &Config::default());
        assert_eq!(r, CaseResult::Failure { engine: "panics".into(), failure: Failure { kind: FailureKind::Panic, message: "boom".into() } });
        assert_eq!(r.short(), "FAIL (panics panic)");
    }
}
