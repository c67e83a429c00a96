//! `cyclecheck certify`: the certification run and its evidence bundle.
//!
//! The run takes the built-in corpus (the manuals' examples and the feature programs,
//! [`cycle_kernel::corpus`]) and a fixed-seed generated campaign ([`cases`]: one generator per cycle
//! family of [`cycle_kernel::registry`], and garbage), runs each case through the reference spec and a
//! candidate — the production expander, or a vendor's expander behind the candidate protocol
//! ([`crate::candidate`]) — and judges the pair in lockstep with the conformance relation
//! ([`cycle_kernel::judge`]).
//!
//! Every case is recorded as it is judged, one JSON line in `cases.jsonl` ([`tally`]): the
//! cycle it runs ([`cycle_kernel::registry::cycle_run`]), the rules its reference trace exercises (the
//! rule tags of its moves, passes and alarm), and its result — conform, the first divergence, or
//! the candidate's failure (timeout, crash, garbage, …). In memory the run keeps counts
//! ([`tally::Tally`]), the corpus programs' traces (the plots), the first failures, and the
//! divergence groups by signature, the first case of each minimized ([`minimize`]): memory does
//! not grow with the number of cases.
//!
//! The bundle ([`bundle`]): `evidence.json` ([`evidence`]) with the run's identity
//! ([`identity`]), `cases.jsonl`, `index.html` ([`html`]) with the traceability matrix
//! ([`matrix`]) and the interpretation register, and one SVG toolpath per corpus program
//! ([`plot`]).
//!
//! A run can be one shard of N ([`shard`]: `--shard K/N`); `cyclecheck merge` ([`merge`])
//! joins the shards' bundles into the bundle of the whole run.

pub mod bundle;
pub mod cases;
pub mod deviations;
pub mod evidence;
pub mod html;
pub mod identity;
pub mod kani;
pub mod markdown;
pub mod matrix;
pub mod merge;
pub mod minimize;
pub mod plot;
pub mod proofs;
pub mod readings_plan;
pub mod shard;
pub mod tally;
mod options;
mod verdict;

pub use cycle_kernel::judge::CaseResult;
pub use cases::FamilyRun;
pub use minimize::{Group, Minimized, Signature};
pub use options::{
    set_params, Options, DEFAULT_CASES, DEFAULT_MAX_FAILURES, DEFAULT_OUT, DEFAULT_SEED, MAX_LISTED_FAILURES, MAX_MINIMIZED, OPERATOR, SHRINK_STEPS,
};
pub use verdict::{declared_level, level_refusal};

use crate::candidate::CandidateEngine;
use cycle_kernel::conformance::{self, Level};
use cycle_kernel::corpus;
use cycle_kernel::engine::{Engine, FailureKind, ImplEngine, SpecEngine};
use cycle_kernel::judge::{judge, judge_keeping, Judged};
use cycle_kernel::registry::CycleRun;
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Rule};
use std::collections::{BTreeMap, BTreeSet};
use std::io::Write;
use std::time::{Duration, Instant};

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
    /// The cycle the program runs (the judge's read of it, [`cycle_kernel::registry::sight`]).
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

impl CaseRecord {
    fn new(p: &cases::Pending, j: Judged) -> CaseRecord {
        let alarm = j.alarm().copied();
        let cycle = j.sighting.cycle;
        let (events, rules, ending) = match j.reference {
            Some(r) => (r.events, r.rules, alarm.as_ref().map_or_else(|| "clean".to_string(), conformance::alarm_short)),
            None => (0, BTreeSet::new(), "reference failed".to_string()),
        };
        let (name, origin, program, config) = (p.name.clone(), p.origin.clone(), p.program.clone(), p.config);
        CaseRecord { name, origin, cycle, program, config, events, rules, ending, result: j.result, traces: j.traces }
    }

    /// Whether the candidate failed on it (a refusal aside: a quick, well-formed answer).
    fn candidate_failed(&self) -> bool {
        matches!(&self.result, CaseResult::Failure { engine, failure } if engine != "spec" && failure.kind != FailureKind::Refused)
    }
}

/// Why a run stopped before its last case.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Stopped {
    /// Consecutive candidate failures that stopped it (`--max-failures`).
    pub consecutive_failures: u32,
    /// Cases judged, and the most the run would have had.
    pub judged: usize,
    pub planned: usize,
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
    /// When, with what build, on which host, against which executable.
    pub identity: identity::Identity,
    pub tally: tally::Tally,
    /// The corpus programs' cases, with their traces.
    pub corpus: Vec<CaseRecord>,
    /// The first [`MAX_LISTED_FAILURES`] failed cases.
    pub failures: Vec<CaseRecord>,
    pub families: Vec<FamilyRun>,
    pub groups: Vec<Group>,
    /// Set when `--max-failures` stopped the run.
    pub stopped: Option<Stopped>,
    /// How each proof property was checked: the z3 lemmas run now, the imported Kani log.
    pub proofs: proofs::Proofs,
    pub duration: Duration,
    /// The shards a merged bundle was joined from (empty for a run).
    pub merged_from: Vec<shard::ShardRun>,
    /// The declared readings the cases ran under (their counts: `tally.readings`).
    pub readings: readings_plan::Plan,
    /// The comparison level the candidate declared (the weakest of its children's).
    pub level: Level,
}

impl Run {
    pub fn cases(&self) -> usize {
        self.tally.cases
    }

    pub fn conforming(&self) -> usize {
        self.tally.conform
    }

    pub fn diverging(&self) -> usize {
        self.tally.diverge
    }

    pub fn failures(&self) -> usize {
        self.tally.fail
    }

    /// Whether every case conformed or deviated as declared, the run was not stopped, and the
    /// candidate's level is the one asked for (if any). [`Run::verdict`] says at which level.
    pub fn passed(&self) -> bool {
        self.conforming() + self.tally.deviate == self.cases() && self.stopped.is_none() && self.level_ok()
    }

    /// Failures by kind.
    pub fn failures_by_kind(&self) -> BTreeMap<FailureKind, usize> {
        self.tally.failures_by_kind.clone()
    }

    /// Per cycle run: cases, conform, deviate as declared, diverge, fail.
    pub fn by_cycle(&self) -> BTreeMap<CycleRun, [usize; 5]> {
        self.tally.by_cycle.clone()
    }

    /// Per rule: cases whose reference trace exercises it, and divergences that name it.
    pub fn by_rule(&self) -> BTreeMap<Rule, (usize, usize)> {
        self.tally.by_rule.clone()
    }

    /// Per rule: the built-in programs that illustrate it (`corpus::Program::rules`) and ran and
    /// conformed in this run.
    pub fn illustrated(&self) -> BTreeMap<Rule, usize> {
        let mut m = BTreeMap::new();
        for r in self.corpus.iter().filter(|r| r.result.conforms()) {
            for &rule in corpus::find(&r.name).map_or(&[][..], |p| p.rules) {
                *m.entry(rule).or_default() += 1;
            }
        }
        m
    }

    /// A few lines for the terminal: counts, then each divergence group (first case in full)
    /// and each failure kind with its first case.
    pub fn summary(&self) -> String {
        let mut s = format!(
            "spec vs {} at comparison level {}: {} cases, {} conform, {} deviate as declared, {} diverge, {} fail ({:.1} s)\n{}\n",
            self.candidate,
            self.level,
            self.cases(),
            self.conforming(),
            self.tally.deviate,
            self.diverging(),
            self.failures(),
            self.duration.as_secs_f64(),
            self.readings.line()
        );
        s.push_str(&self.level_and_deviation_lines());
        if let Some(st) = self.stopped {
            s.push_str(&format!(
                "STOPPED after {} consecutive candidate failures (--max-failures): {} of at most {} cases judged\n",
                st.consecutive_failures, st.judged, st.planned
            ));
        }
        for (cycle, [n, ok, dev, div, fail]) in self.by_cycle() {
            s.push_str(&format!("  {:<20} {n:>6} cases  {ok:>6} conform  {dev:>5} deviate  {div:>5} diverge  {fail:>5} fail\n", cycle.label()));
        }
        for g in &self.groups {
            s.push_str(&format!("\n{} case(s) diverge like {}:\n", g.count, g.first.name));
            if let CaseResult::Diverge(d) = &g.first.result {
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
            let first = self.failures.iter().find(|r| matches!(&r.result, CaseResult::Failure { failure, .. } if failure.kind == kind));
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

/// Runs the certification: every case, each written to `cases_out` as a line of
/// `cases.jsonl` when judged, then the minimization of each divergence group. A candidate is
/// greeted first: its declared readings, merged with `options.readings`, are every case's (a
/// pin that contradicts them is an error, before any case runs).
pub fn run(options: &Options, cases_out: &mut dyn Write, progress: &mut dyn FnMut(Progress)) -> Result<Run, Error> {
    let candidate = match &options.candidate {
        None => None,
        Some(cmd) => Some(CandidateEngine::new(cmd, options.limits).map_err(|e| Error(format!("--candidate: {e}")))?),
    };
    let argv = candidate.as_ref().map(|c| c.argv().to_vec());
    let engine: &dyn Engine = match &candidate {
        Some(c) => c,
        None => &ImplEngine,
    };
    let plan = match &candidate {
        None => readings_plan::Plan::drawn(options.readings.clone()),
        Some(c) => readings_plan::Plan::declared(c.declared().ok(), options.readings.clone()).map_err(Error)?,
    };
    let mut run = run_engine(options, &plan, engine, argv, cases_out, progress)?;
    run.candidate_starts = candidate.as_ref().map_or(0, CandidateEngine::starts);
    run.level = candidate.as_ref().map_or(Level::Full, CandidateEngine::weakest_level);
    Ok(run)
}

/// [`run`] against `engine`, whose command line is `argv` when it is an external candidate, its
/// cases under the readings of `plan`.
pub fn run_engine(
    options: &Options,
    plan: &readings_plan::Plan,
    engine: &dyn Engine,
    argv: Option<Vec<String>>,
    cases_out: &mut dyn Write,
    progress: &mut dyn FnMut(Progress),
) -> Result<Run, Error> {
    let started = Instant::now();
    let identity = identity::Identity::capture(argv.as_deref());
    let (mut tally, mut corpus, mut failures, mut groups) = (tally::Tally::default(), Vec::new(), Vec::new(), Vec::new());
    let (mut consecutive, mut stopped) = (0u32, None);
    let write_error = |e: std::io::Error| Error(format!("cannot write cases.jsonl: {e}"));
    // An external candidate is told the next cases ahead, so its child computes while this
    // judges (a run stopped early has drawn those cases too).
    let lookahead = if argv.is_some() { crate::candidate::WINDOW } else { 0 };
    let mut cases = cases::Ahead::new(cases::Cases::new(options, plan), engine, lookahead);
    while let Some(p) = cases.next() {
        let in_corpus = matches!(p.origin, Origin::Corpus { .. });
        if tally.cases % 8 == 0 {
            let phase = if in_corpus { "corpus" } else { "generated" };
            progress(Progress { phase, done: cases.cases.drawn - cases.waiting() - 1, total: cases.cases.total, bad: tally.cases - tally.conform });
        }
        let judged = if in_corpus { judge_keeping(&SpecEngine, engine, &p.program, &p.config) } else { judge(&SpecEngine, engine, &p.program, &p.config) };
        let record = verdict::deviate(&options.deviations, CaseRecord::new(&p, judged));
        tally.add(&record);
        let group = minimize::add(&mut groups, &record, Some(p));
        writeln!(cases_out, "{}", tally::case_line(&record, group)).map_err(write_error)?;
        consecutive = if record.candidate_failed() { consecutive + 1 } else { 0 };
        if matches!(record.result, CaseResult::Failure { .. }) && failures.len() < MAX_LISTED_FAILURES {
            failures.push(CaseRecord { traces: None, ..record.clone() });
        }
        if in_corpus {
            corpus.push(record);
        }
        if options.max_failures > 0 && consecutive >= options.max_failures {
            stopped = Some(Stopped { consecutive_failures: consecutive, judged: tally.cases, planned: cases.cases.total });
            break;
        }
    }
    cases_out.flush().map_err(write_error)?;
    let bad = tally.cases - tally.conform;
    progress(Progress { phase: "generated", done: cases.cases.total, total: cases.cases.total, bad });
    minimize::minimize_groups(engine, &mut groups, &mut |done, total| progress(Progress { phase: "minimizing", done, total, bad }));
    Ok(Run {
        options: options.clone(),
        candidate: engine.name().to_string(),
        candidate_argv: argv,
        candidate_starts: 0,
        identity,
        tally,
        corpus,
        failures,
        families: cases.cases.runs,
        groups,
        stopped,
        proofs: match options.shard {
            Some(_) => proofs::Proofs::left_to_merge(options.kani_log.clone()),
            None => proofs::Proofs::check(options.kani_log.clone()),
        },
        duration: started.elapsed(),
        merged_from: Vec::new(),
        readings: plan.clone(),
        level: engine.level(),
    })
}

#[cfg(test)]
mod tests;
