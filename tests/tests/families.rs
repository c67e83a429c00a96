//! The completeness of the cycle families (`cycle_kernel::registry`): every registry family is
//! in every consumer, so a family added to the table without its generator, programs,
//! snapshots, fuzz seeds, bench case, catalogue rules or differential campaign fails here,
//! naming what is missing.

use cycle_kernel::engine::{Engine, SpecEngine};
use cycle_kernel::corpus;
use cycle_kernel::gen;
use cycle_kernel::registry::{self, CycleRun, Family, FAMILIES};
use cycle_vocab::{Event, MoveKind, Rule};
use proptest::strategy::{Strategy, ValueTree};
use proptest::test_runner::{Config as ProptestConfig, RngAlgorithm, TestRng, TestRunner};
use std::path::{Path, PathBuf};

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// What `family` lacks, one line each.
fn missing(family: &'static Family) -> Vec<String> {
    let run = CycleRun::Family(family);
    let runs = |program: &[u8], config: &cycle_vocab::Config| {
        registry::cycle_run(program, config, Some(&SpecEngine.expand(program, config))) == run
    };
    let mut missing = Vec::new();

    // Its generator: most of its cases run it (the rest alarm before the cycle).
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &gen::seed_bytes(1));
    let mut runner = TestRunner::new_with_rng(ProptestConfig::default(), rng);
    let strategy = family.strategy();
    let cases: Vec<gen::Case> = (0..200).map(|_| strategy.new_tree(&mut runner).unwrap().current()).collect();
    let running = cases.iter().filter(|c| runs(&c.program, &c.config)).count();
    if running * 2 < cases.len() || cases.iter().any(|c| c.family != family.name) {
        missing.push(format!("a generator: {running} of {} cases run it, families {:?}", cases.len(), cases[0].family));
    }

    // A corpus or feature program that runs it.
    if !corpus::PROGRAMS.iter().any(|p| runs(p.text.as_bytes(), &p.config())) {
        missing.push("a program in corpus/ or tests/programs/ that runs it".to_string());
    }

    // Its snapshot folder, with snapshots.
    let folder = root().join("tests/tests/snapshots").join(family.name);
    let snapshots = std::fs::read_dir(&folder)
        .map(|d| d.filter_map(Result::ok).filter(|e| e.path().extension().is_some_and(|x| x == "snap")).count())
        .unwrap_or(0);
    if snapshots == 0 {
        missing.push(format!("snapshots in {}", folder.display()));
    }

    // A fuzz seed that names it: `<prefix>_plain`, the prefix's parts (split at `_`) naming it.
    let seeds = std::fs::read_dir(root().join("fuzz/seeds/diff_spec_impl")).expect("the fuzz seeds are committed");
    let named = seeds.filter_map(Result::ok).any(|e| {
        let name = e.file_name().to_string_lossy().into_owned();
        name.strip_suffix("_plain.nc").is_some_and(|prefix| prefix.split('_').any(|part| part == family.name))
    });
    if !named {
        missing.push(format!("a fuzz seed fuzz/seeds/diff_spec_impl/…{}…_plain.nc", family.name));
    }

    // Its bench case: it runs the family, without an alarm, with pass headers or thread moves.
    for n in registry::BENCH_SIZES {
        let bench = (family.bench)(n);
        let trace = SpecEngine.expand(&bench.program, &bench.config);
        let cuts = trace.events.iter().any(|e| matches!(e, Event::Pass(_))) || trace.moves().any(|m| m.kind == MoveKind::Thread);
        if !runs(&bench.program, &bench.config) || trace.alarm.is_some() || !cuts {
            missing.push(format!("a bench case of size {n} that cuts without an alarm ({:?})", trace.alarm));
        }
    }

    // Its rules in the catalogue.
    if !Rule::ALL.iter().any(|&r| family.owns(r) && cycle_kernel::catalogue::entry(r).is_some()) {
        missing.push(format!("catalogue rules (docs/RULES.md) with prefix {:?}", family.rule_prefixes));
    }
    missing
}

/// The families of `family_campaigns!(…)` in `differential.rs`.
fn differential_campaigns() -> Vec<String> {
    let text = include_str!("differential.rs");
    let start = text.find("\nfamily_campaigns!(").expect("differential.rs lists its family campaigns") + "\nfamily_campaigns!(".len();
    let list = &text[start..start + text[start..].find(')').expect("the list closes")];
    list.split(',').map(|s| s.trim().to_string()).filter(|s| !s.is_empty()).collect()
}

#[test]
fn every_family_is_in_every_consumer() {
    let mut report = Vec::new();
    for family in FAMILIES {
        for what in missing(family) {
            report.push(format!("{}: no {what}", family.name));
        }
    }
    let registered: Vec<String> = FAMILIES.iter().map(|f| f.name.to_string()).collect();
    if differential_campaigns() != registered {
        report.push(format!("differential.rs campaigns {:?} are not the registry {registered:?}", differential_campaigns()));
    }
    assert!(report.is_empty(), "families missing from consumers:\n{}", report.join("\n"));
}

/// Every snapshot folder is a family's (or a named cycle run's), so none is left behind when a
/// family is renamed.
#[test]
fn every_snapshot_folder_is_a_cycle_run() {
    // `operator`: the operator events on the manuals' programs (tests/tests/operator.rs).
    let names: Vec<&str> = FAMILIES.iter().map(|f| f.name).chain([CycleRun::NoCycle.name(), CycleRun::AlarmFirst.name(), "operator"]).collect();
    for entry in std::fs::read_dir(root().join("tests/tests/snapshots")).unwrap() {
        let entry = entry.unwrap();
        let name = entry.file_name().to_string_lossy().into_owned();
        assert!(entry.path().is_dir() && names.contains(&name.as_str()), "tests/tests/snapshots/{name} is no cycle run's folder");
    }
}
