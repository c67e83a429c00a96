//! `cyclecheck certify`: the certification run and its evidence bundle.
//!
//! The run takes the built-in corpus (the manuals' examples and the feature programs,
//! [`crate::corpus`]) and a fixed-seed generated campaign ([`cases`]: one generator per cycle
//! family of [`crate::registry`], and garbage), runs each case through the reference spec and a
//! candidate — the production expander, or a vendor's expander behind the candidate protocol
//! ([`crate::candidate`]) — and judges each pair of traces with the conformance relation
//! ([`crate::conformance`]).
//!
//! Every case is recorded: the cycle it runs ([`crate::registry::cycle_run`]), the rules its
//! reference trace exercises (the rule tags of its moves, passes and alarm), and its result —
//! conform, the first divergence, or the candidate's failure (timeout, crash, garbage, …).
//! Divergences are grouped by signature and the first case of each group minimized
//! ([`minimize`]).
//!
//! The bundle ([`bundle::write`]): `evidence.json` ([`evidence`]), `index.html` ([`html`]) with
//! the traceability matrix ([`matrix`]) and the interpretation register, and one SVG toolpath
//! per corpus program ([`plot`]).

pub mod bundle;
pub mod cases;
pub mod evidence;
pub mod html;
pub mod judge;
pub mod markdown;
pub mod matrix;
pub mod minimize;
pub mod plot;

pub use cases::FamilyRun;
pub use judge::{candidate_engine, judge, CaseResult};
pub use minimize::{Group, Minimized, Signature};

use crate::candidate::{CandidateEngine, Limits};
use crate::conformance;
use crate::engine::{Engine, FailureKind, ImplEngine, SpecEngine};
use crate::registry::{self, CycleRun, Family, FAMILIES};
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Rule};
use std::collections::{BTreeMap, BTreeSet};
use std::time::{Duration, Instant};

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
    /// The families covered (`--cycles`), in registry order; all by default.
    pub cycles: Vec<&'static Family>,
    /// Generated cases per family (the garbage generator gets a fifth).
    pub cases: u32,
    pub seed: u64,
}

impl Default for Options {
    fn default() -> Options {
        Options {
            candidate: None,
            limits: Limits::default(),
            cycles: FAMILIES.iter().collect(),
            cases: DEFAULT_CASES,
            seed: DEFAULT_SEED,
        }
    }
}

impl Options {
    /// Whether every family is covered (then programs that run none, and garbage, are too).
    pub fn all_cycles(&self) -> bool {
        self.cycles.len() == FAMILIES.len()
    }

    /// Parses `--cycles`: `all` or a comma list of family names ([`registry::names`]).
    pub fn parse_cycles(list: &str) -> Result<Vec<&'static Family>, String> {
        let names: Vec<&str> = list.split(',').map(str::trim).collect();
        if let Some(bad) = names.iter().find(|&&n| n != "all" && registry::find(n).is_none()) {
            return Err(format!("--cycles takes all or a comma list of {}, not {bad:?}", registry::names()));
        }
        Ok(FAMILIES.iter().filter(|f| names.contains(&"all") || names.contains(&f.name)).collect())
    }

    /// Whether a case that runs `run` is in the run: with every family covered, any case is.
    pub fn covers(&self, run: CycleRun) -> bool {
        self.all_cycles() || matches!(run, CycleRun::Family(f) if self.cycles.contains(&f))
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
    /// The cycle the program runs ([`registry::cycle_run`]).
    pub cycle: CycleRun,
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

    /// Per cycle run: cases, conform, diverge, fail.
    pub fn by_cycle(&self) -> BTreeMap<CycleRun, [usize; 4]> {
        let mut m: BTreeMap<CycleRun, [usize; 4]> = BTreeMap::new();
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
            s.push_str(&format!("  {:<20} {n:>6} cases  {ok:>6} conform  {div:>5} diverge  {fail:>5} fail\n", cycle.label()));
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
    let (mut list, families) = cases::case_list(options);
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
        let cycle = registry::cycle_run(&p.program, &p.config, reference.as_ref());
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
            cycle,
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

    let mut groups = minimize::groups(&records);
    let to_minimize = groups.len().min(MAX_MINIMIZED);
    for (n, g) in groups.iter_mut().take(MAX_MINIMIZED).enumerate() {
        progress(Progress { phase: "minimizing", done: n, total: to_minimize, bad });
        let first = g.cases[0];
        g.minimized = minimize::minimize(engine, &records[first], &mut list[first], g.signature);
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


#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::wrong::Panics;
    use crate::engine::Failure;

    #[test]
    fn cycles_option() {
        let names = |list: &str| -> Vec<&str> { Options::parse_cycles(list).unwrap().iter().map(|f| f.name).collect() };
        assert_eq!(names("g92"), ["g92"]);
        assert_eq!(names("f76, g76"), ["g76", "f76"]);
        assert_eq!(names("g162,g32"), ["g162", "g32"]);
        assert_eq!(Options::parse_cycles("all").unwrap().len(), FAMILIES.len());
        let e = Options::parse_cycles("g92,g93").unwrap_err();
        assert_eq!(e, format!("--cycles takes all or a comma list of {}, not \"g93\"", registry::names()));
        let o = Options { cycles: Options::parse_cycles("g92").unwrap(), ..Options::default() };
        let g92 = CycleRun::Family(registry::find("g92").unwrap());
        let g78 = CycleRun::Family(registry::find("g78").unwrap());
        assert!(o.covers(g92) && !o.covers(g78) && !o.covers(CycleRun::NoCycle) && !o.covers(CycleRun::AlarmFirst));
        assert!(Options::default().covers(CycleRun::NoCycle) && Options::default().covers(CycleRun::AlarmFirst));
    }

    #[test]
    fn panics_are_failures() {
        let (_, _, r) = judge(&SpecEngine, &Panics, b"G0 X1", &Config::default());
        assert_eq!(r, CaseResult::Failure { engine: "panics".into(), failure: Failure { kind: FailureKind::Panic, message: "boom".into() } });
        assert_eq!(r.short(), "FAIL (panics panic)");
    }
}
