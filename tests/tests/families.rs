//! The completeness of the cycle families (`cycle_kernel::registry`): every registry family is
//! in every consumer, so a family added to the table without its generator, programs,
//! snapshots, fuzz seeds, bench case or catalogue rules fails here, naming what is missing
//! (its differential campaign is checked by `differential.rs` itself). And the G codes of each
//! family agree in the three places they are stated: the registry, the spec's family table and
//! the production expander's.

use cycle_kernel::engine::{Engine, SpecEngine};
use cycle_kernel::corpus;
use cycle_kernel::gen;
use cycle_kernel::registry::{self, CycleRun, Family, FAMILIES};
use cycle_vocab::{Dialect, Event, MoveKind, Rule};
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

#[test]
fn every_family_is_in_every_consumer() {
    let mut report = Vec::new();
    for family in FAMILIES {
        for what in missing(family) {
            report.push(format!("{}: no {what}", family.name));
        }
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

/// A family as one table states it: its name, its dialects and its G codes, each sorted.
#[derive(Clone, Debug, PartialEq, Eq)]
struct Codes {
    name: &'static str,
    dialects: Vec<String>,
    codes: Vec<u64>,
}

impl Codes {
    fn new(name: &'static str, dialects: &[Dialect], codes: impl IntoIterator<Item = u64>) -> Codes {
        let mut dialects: Vec<String> = dialects.iter().map(|d| format!("{d:?}")).collect();
        let mut codes: Vec<u64> = codes.into_iter().collect();
        dialects.sort();
        codes.sort_unstable();
        Codes { name, dialects, codes }
    }
}

/// The registry's rows (`cycle_kernel::registry::FAMILIES`).
fn registry_table() -> Vec<Codes> {
    FAMILIES.iter().map(|f| Codes::new(f.name, f.dialects, f.codes.iter().copied())).collect()
}

/// The spec's family table (`cycle_spec::family::FAMILIES`).
fn spec_table() -> Vec<Codes> {
    cycle_spec::family::FAMILIES.iter().map(|f| Codes::new(f.name, f.dialects, f.codes.iter().map(|&g| u64::from(g)))).collect()
}

/// The production expander's family table (`cycle_impl::family::FAMILIES`).
fn impl_table() -> Vec<Codes> {
    cycle_impl::family::FAMILIES.iter().map(|f| Codes::new(f.name, f.dialects, f.codes.iter().map(|&g| u64::from(g)))).collect()
}

/// Where table `b` disagrees with table `a`, one line each: a family stated twice in one, in one
/// table only, or with other dialects or codes.
fn disagreements((a_name, a): (&str, &[Codes]), (b_name, b): (&str, &[Codes])) -> Vec<String> {
    let mut lines = Vec::new();
    for (table, rows) in [(a_name, a), (b_name, b)] {
        for (i, row) in rows.iter().enumerate() {
            if rows[..i].iter().any(|r| r.name == row.name) {
                lines.push(format!("{}: twice in the {table} table", row.name));
            }
        }
    }
    for row in a {
        match b.iter().find(|r| r.name == row.name) {
            None => lines.push(format!("{}: in the {a_name} table, not in the {b_name} table", row.name)),
            Some(other) if other != row => lines.push(format!(
                "{}: the {a_name} table says {:?} {:?}, the {b_name} table {:?} {:?}",
                row.name, row.dialects, row.codes, other.dialects, other.codes
            )),
            Some(_) => {}
        }
    }
    for row in b.iter().filter(|r| !a.iter().any(|x| x.name == r.name)) {
        lines.push(format!("{}: in the {b_name} table, not in the {a_name} table", row.name));
    }
    lines
}

/// The G codes of each family are the same in the registry, the spec and the production
/// expander: same families, same dialects, same codes.
#[test]
fn the_three_code_tables_agree() {
    let registry = registry_table();
    let mut report = disagreements(("registry", &registry), ("spec", &spec_table()));
    report.extend(disagreements(("registry", &registry), ("impl", &impl_table())));
    assert!(report.is_empty(), "the family code tables disagree:\n{}", report.join("\n"));
}

/// The comparison finds each kind of disagreement: another dialect, a code more, a family
/// missing, a family more, a family twice.
#[test]
fn a_wrong_table_is_named() {
    let registry = registry_table();
    let mut wrong = registry.clone();
    let at = |t: &[Codes], name: &str| t.iter().position(|r| r.name == name).unwrap();
    let g78 = at(&wrong, "g78");
    wrong[g78] = Codes::new("g78", &[Dialect::Gsk, Dialect::Fanuc], [78]);
    let g32 = at(&wrong, "g32");
    wrong[g32] = Codes::new("g32", &[Dialect::Gsk, Dialect::Fanuc], [32, 33, 34, 35]);
    wrong.remove(at(&wrong, "g84"));
    wrong.push(Codes::new("g99", &[Dialect::Gsk], [99]));
    wrong.push(Codes::new("g70", &[Dialect::Gsk, Dialect::Fanuc], [70]));
    let lines = disagreements(("registry", &registry), ("wrong", &wrong));
    assert_eq!(
        lines,
        [
            "g70: twice in the wrong table",
            r#"g78: the registry table says ["Gsk"] [78], the wrong table ["Fanuc", "Gsk"] [78]"#,
            r#"g32: the registry table says ["Fanuc", "Gsk"] [32, 33, 34], the wrong table ["Fanuc", "Gsk"] [32, 33, 34, 35]"#,
            "g84: in the registry table, not in the wrong table",
            "g99: in the wrong table, not in the registry table",
        ]
    );
    assert_eq!(disagreements(("registry", &registry), ("same", &registry)), Vec::<String>::new());
}
