//! The cases of a certification run, drawn one at a time: the corpus programs of the covered
//! cycles, then the generated cases — one generator per covered registry family, and garbage
//! when every family is covered. Nothing is drawn ahead, so the run's memory does not grow with
//! the number of cases. A sharded run ([`super::shard`]) draws every case and keeps its own.

use super::readings_plan::Plan;
use super::shard::Shard;
use super::{Options, Origin};
use cycle_kernel::corpus;
use cycle_kernel::engine::{Engine, SpecEngine};
use cycle_kernel::gen::{self, Case};
use cycle_kernel::judge::observe;
use cycle_kernel::registry::{self, FAMILIES};
use cycle_vocab::Config;
use std::collections::VecDeque;
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config as ProptestConfig, RngAlgorithm, TestRng, TestRunner};

/// One case: its name, origin, program and configuration, and (generated cases) the value tree
/// it came from, for shrinking.
pub struct Pending {
    pub name: String,
    pub origin: Origin,
    pub program: Vec<u8>,
    pub config: Config,
    pub tree: Option<Box<dyn ValueTree<Value = Case>>>,
    /// The run's dialect and parameters, set over every configuration the tree yields
    /// ([`Options::configure`]).
    pub params: cycle_vocab::Params,
    pub dialect: Option<cycle_vocab::Dialect>,
}


/// A generator's seed and size in a run.
#[derive(Clone, Debug)]
pub struct FamilyRun {
    /// A registry family's name, or `garbage`.
    pub family: &'static str,
    pub seed: u64,
    /// Cases drawn from the generator, and those kept (their cycle is in the run, and with
    /// `--shard`, their number in the shard).
    pub drawn: u32,
    pub kept: u32,
}

/// A generator's seed: the run's seed mixed with the generator's number (its place in the
/// registry from 1, garbage 0), so a family draws the same cases alone or with the others.
fn family_seed(seed: u64, number: u64) -> u64 {
    seed ^ number.wrapping_mul(0x9e37_79b9_7f4a_7c15)
}

/// A generator of a run: name, number, strategy, cases to draw.
struct Generator {
    family: &'static str,
    number: u64,
    strategy: BoxedStrategy<Case>,
    count: u32,
}

/// `strategy` with each case's readings set by `plan`.
fn planned(strategy: BoxedStrategy<Case>, plan: &Plan) -> BoxedStrategy<Case> {
    let plan = plan.clone();
    strategy
        .prop_map(move |mut case| {
            plan.apply(&mut case.config);
            case
        })
        .boxed()
}

fn generators(options: &Options, plan: &Plan) -> Vec<Generator> {
    let mut g: Vec<Generator> = FAMILIES
        .iter()
        .enumerate()
        .filter(|(_, f)| options.cycles.contains(f))
        .map(|(i, f)| Generator { family: f.name, number: i as u64 + 1, strategy: planned(f.strategy(), plan), count: options.cases })
        .collect();
    let threads: Vec<&'static registry::Family> = options.cycles.iter().copied().filter(|f| gen::operator::FAMILIES.contains(&f.name)).collect();
    if options.operator && !threads.is_empty() {
        let (number, count) = (FAMILIES.len() as u64 + 1, options.cases.div_ceil(4));
        g.push(Generator { family: "operator", number, strategy: planned(gen::operator::strategy(threads), plan), count });
    }
    if options.all_cycles() {
        g.push(Generator { family: "garbage", number: 0, strategy: planned(gen::garbage::strategy(), plan), count: options.cases.div_ceil(5) });
    }
    g
}

/// Whether the run covers a case: always with every family; else when the case runs a covered
/// family (the reference run once more, for its alarm line).
fn covered(options: &Options, program: &[u8], config: &Config) -> bool {
    if options.all_cycles() {
        return true;
    }
    let alarm = observe(&SpecEngine, program, config, false).ok().and_then(|(seen, _)| seen.alarm);
    options.covers(registry::sight(program, config, alarm.as_ref()).cycle)
}

/// The cases of a run, in order, drawn as they are asked for.
pub struct Cases<'o> {
    options: &'o Options,
    plan: Plan,
    corpus: std::iter::Enumerate<std::slice::Iter<'static, corpus::Program>>,
    generators: std::vec::IntoIter<Generator>,
    /// The generator being drawn from, its runner and the next index.
    current: Option<(Generator, TestRunner, u32)>,
    /// The generators' runs so far (the current one last).
    pub runs: Vec<FamilyRun>,
    /// Candidates for cases drawn so far (kept or not), and the most there can be.
    pub drawn: usize,
    pub total: usize,
}

impl<'o> Cases<'o> {
    /// The cases of `options`, their readings set by `plan` (the corpus programs' from the
    /// letter).
    pub fn new(options: &'o Options, plan: &Plan) -> Cases<'o> {
        let generators = generators(options, plan);
        let total = corpus::PROGRAMS.len() + generators.iter().map(|g| g.count as usize).sum::<usize>();
        Cases { options, plan: plan.clone(), corpus: corpus::PROGRAMS.iter().enumerate(), generators: generators.into_iter(), current: None, runs: Vec::new(), drawn: 0, total }
    }

    fn next_corpus(&mut self) -> Option<Pending> {
        for (i, p) in self.corpus.by_ref() {
            self.drawn += 1;
            let mut config = p.config();
            self.plan.apply(&mut config);
            self.options.configure(&mut config);
            if Shard::includes(self.options.shard, i) && covered(self.options, p.text.as_bytes(), &config) {
                let (name, origin) = (p.name.to_string(), Origin::Corpus { path: p.path });
                return Some(Pending { name, origin, program: p.text.as_bytes().to_vec(), config, tree: None, params: self.options.params, dialect: self.options.dialect });
            }
        }
        None
    }

    fn next_generated(&mut self) -> Option<Pending> {
        loop {
            if self.current.is_none() {
                let g = self.generators.next()?;
                let seed = family_seed(self.options.seed, g.number);
                let config = ProptestConfig { cases: g.count, failure_persistence: None, ..ProptestConfig::default() };
                let runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &gen::seed_bytes(seed)));
                self.runs.push(FamilyRun { family: g.family, seed, drawn: g.count, kept: 0 });
                self.current = Some((g, runner, 0));
            }
            let (g, runner, index) = self.current.as_mut()?;
            if *index == g.count {
                self.current = None;
                continue;
            }
            let i = *index;
            *index += 1;
            self.drawn += 1;
            let Ok(tree) = g.strategy.new_tree(runner) else { continue };
            if !Shard::includes(self.options.shard, i as usize) {
                continue;
            }
            let mut case = tree.current();
            self.options.configure(&mut case.config);
            if !covered(self.options, &case.program, &case.config) {
                continue;
            }
            if let Some(run) = self.runs.last_mut() {
                run.kept += 1;
            }
            let family = g.family;
            let origin = Origin::Generated { family, index: i };
            let (params, dialect) = (self.options.params, self.options.dialect);
            return Some(Pending { name: format!("{family}#{i}"), origin, program: case.program, config: case.config, tree: Some(tree), params, dialect });
        }
    }
}

impl Iterator for Cases<'_> {
    type Item = Pending;

    fn next(&mut self) -> Option<Pending> {
        self.next_corpus().or_else(|| self.next_generated())
    }
}

/// The cases drawn `lookahead` ahead of the one judged, each told to `engine` as it is drawn
/// ([`Engine::prefetch`]), so that a candidate's child computes while the caller judges.
pub struct Ahead<'o, 'e> {
    pub cases: Cases<'o>,
    engine: &'e dyn Engine,
    queue: VecDeque<Pending>,
    lookahead: usize,
}

impl<'o, 'e> Ahead<'o, 'e> {
    pub fn new(cases: Cases<'o>, engine: &'e dyn Engine, lookahead: usize) -> Ahead<'o, 'e> {
        Ahead { cases, engine, queue: VecDeque::new(), lookahead }
    }

    /// Cases drawn but not yet handed out.
    pub fn waiting(&self) -> usize {
        self.queue.len()
    }
}

impl Iterator for Ahead<'_, '_> {
    type Item = Pending;

    fn next(&mut self) -> Option<Pending> {
        while self.queue.len() <= self.lookahead {
            let Some(p) = self.cases.next() else { break };
            self.engine.prefetch(&p.program, &p.config);
            self.queue.push_back(p);
        }
        self.queue.pop_front()
    }
}

#[cfg(test)]
mod tests;
