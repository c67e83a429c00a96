//! The case list of a certification run: the corpus programs of the covered cycles, then the
//! generated cases — one generator per covered registry family, and garbage when every family
//! is covered.

use super::judge::try_engine;
use super::{Options, Origin};
use crate::corpus;
use crate::engine::SpecEngine;
use crate::gen::{self, Case};
use crate::registry::{self, FAMILIES};
use cycle_vocab::Config;
use proptest::strategy::{BoxedStrategy, Strategy, ValueTree};
use proptest::test_runner::{Config as ProptestConfig, RngAlgorithm, TestRng, TestRunner};

/// One case of the list: its name, origin, program and configuration, and (generated cases)
/// the value tree it came from, for shrinking.
pub(super) struct Pending {
    pub name: String,
    pub origin: Origin,
    pub program: Vec<u8>,
    pub config: Config,
    pub tree: Option<Box<dyn ValueTree<Value = Case>>>,
}

/// A generator's seed and size in a run.
#[derive(Clone, Debug)]
pub struct FamilyRun {
    /// A registry family's name, or `garbage`.
    pub family: &'static str,
    pub seed: u64,
    /// Cases drawn from the generator, and those kept (their cycle is in the run).
    pub drawn: u32,
    pub kept: u32,
}

/// A generator's seed: the run's seed mixed with the generator's number (its place in the
/// registry from 1, garbage 0), so a family draws the same cases alone or with the others.
fn family_seed(seed: u64, number: u64) -> u64 {
    seed ^ number.wrapping_mul(0x9e37_79b9_7f4a_7c15)
}

/// The generators of a run: name, number, strategy, cases to draw.
fn generators(options: &Options) -> Vec<(&'static str, u64, BoxedStrategy<Case>, u32)> {
    let mut g: Vec<_> = FAMILIES
        .iter()
        .enumerate()
        .filter(|(_, f)| options.cycles.contains(f))
        .map(|(i, f)| (f.name, i as u64 + 1, f.strategy(), options.cases))
        .collect();
    if options.all_cycles() {
        g.push(("garbage", 0, gen::garbage::strategy(), options.cases.div_ceil(5)));
    }
    g
}

/// Whether the run covers a case: always with every family; else when the case runs a covered
/// family (the reference run once more for its alarm line).
fn covered(options: &Options, program: &[u8], config: &Config) -> bool {
    if options.all_cycles() {
        return true;
    }
    let reference = try_engine(&SpecEngine, program, config).ok();
    options.covers(registry::cycle_run(program, config, reference.as_ref()))
}

/// The case list and the generators' runs.
pub(super) fn case_list(options: &Options) -> (Vec<Pending>, Vec<FamilyRun>) {
    let mut list = Vec::new();
    for p in corpus::PROGRAMS {
        let config = p.config();
        if covered(options, p.text.as_bytes(), &config) {
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
    for (family, number, strategy, count) in generators(options) {
        let seed = family_seed(options.seed, number);
        let config = ProptestConfig { cases: count, failure_persistence: None, ..ProptestConfig::default() };
        let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &gen::seed_bytes(seed)));
        let mut kept = 0;
        for index in 0..count {
            let Ok(tree) = strategy.new_tree(&mut runner) else { continue };
            let case = tree.current();
            if !covered(options, &case.program, &case.config) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::CycleRun;

    fn runs(program: &[u8], config: &Config) -> CycleRun {
        registry::cycle_run(program, config, Some(&cycle_spec::expand(program, config)))
    }

    #[test]
    fn case_list_is_seeded_and_filtered() {
        let o = Options { cycles: Options::parse_cycles("g92").unwrap(), cases: 20, ..Options::default() };
        let (a, fa) = case_list(&o);
        let (b, _) = case_list(&o);
        assert_eq!(a.iter().map(|p| &p.program).collect::<Vec<_>>(), b.iter().map(|p| &p.program).collect::<Vec<_>>());
        let g92 = CycleRun::Family(registry::find("g92").unwrap());
        assert!(a.iter().all(|p| runs(&p.program, &p.config) == g92));
        assert_eq!(a.iter().filter(|p| matches!(p.origin, Origin::Corpus { .. })).count(), 6);
        assert_eq!((fa.len(), fa[0].family, fa[0].drawn), (1, "g92", 20));
        assert!(fa[0].kept >= 15, "{fa:?}");
        let other = Options { seed: 1, ..o.clone() };
        let (c, _) = case_list(&other);
        assert_ne!(a.last().unwrap().program, c.last().unwrap().program);
        // A family draws the same cases alone as with the others.
        let (all, _) = case_list(&Options { cases: 20, ..Options::default() });
        let generated = |l: &[Pending]| -> Vec<Vec<u8>> {
            l.iter().filter(|p| p.name.starts_with("g92#")).map(|p| p.program.clone()).collect()
        };
        let with_all = generated(&all);
        assert!(generated(&a).iter().all(|p| with_all.contains(p)));
    }

    #[test]
    fn every_family_and_garbage_generate_with_all_cycles() {
        let (_, runs) = case_list(&Options { cases: 5, ..Options::default() });
        let names: Vec<&str> = runs.iter().map(|r| r.family).collect();
        let mut expected: Vec<&str> = FAMILIES.iter().map(|f| f.name).collect();
        expected.push("garbage");
        assert_eq!(names, expected);
        assert!(runs.iter().all(|r| r.kept == r.drawn), "{runs:?}");
    }
}
