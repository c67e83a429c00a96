use super::*;
use std::collections::BTreeSet;

/// Every `.nc` file of `corpus/` and `tests/programs/` is built in, and nothing else.
#[test]
fn corpus_lists_every_program_file() {
    let root = concat!(env!("CARGO_MANIFEST_DIR"), "/..");
    let mut on_disk = BTreeSet::new();
    for dir in ["corpus", "tests/programs"] {
        for entry in std::fs::read_dir(format!("{root}/{dir}")).unwrap() {
            let name = entry.unwrap().file_name().into_string().unwrap();
            if let Some(stem) = name.strip_suffix(".nc") {
                on_disk.insert(format!("{dir}/{stem}.nc"));
            }
        }
    }
    let built_in: BTreeSet<String> = PROGRAMS.iter().map(|p| p.path.to_string()).collect();
    assert_eq!(built_in, on_disk);
    assert_eq!(built_in.len(), PROGRAMS.len(), "a program is listed twice");
}

/// Each program's header comment matches the configuration given here: `--dialect fanuc`
/// and `--units inch` are named there when needed.
#[test]
fn configurations_follow_the_headers() {
    for p in PROGRAMS {
        let header = p.text.lines().next().unwrap_or("");
        assert_eq!(header.contains("--dialect fanuc"), p.dialect == Dialect::Fanuc, "{}", p.name);
        assert_eq!(header.contains("--dialect nc201"), p.dialect == Dialect::Nc201, "{}", p.name);
        assert_eq!(header.contains("--units inch"), p.units == Units::Inch, "{}", p.name);
        assert_eq!(header.contains("--increment isc"), p.increment == Increment::Isc, "{}", p.name);
        assert!(!p.rules.is_empty(), "{} illustrates no rule", p.name);
        assert_eq!(header.matches("--reading ").count(), p.readings.len(), "{}", p.name);
        for (name, value) in p.readings {
            assert!(header.contains(&format!("--reading {name}={value}")), "{}: --reading {name}={value}", p.name);
            assert!(Readings::default().set(name, value).is_ok(), "{}: {name}={value} is no reading", p.name);
        }
        assert_eq!(header.matches("--param ").count(), p.params.len(), "{}", p.name);
        for (name, value) in p.params {
            assert!(header.contains(&format!("--param {name}={value}")), "{}: --param {name}={value}", p.name);
            assert!(Params::default().set(name, *value).is_ok(), "{}: {name} is no parameter", p.name);
        }
    }
}

/// The reference expands each program as expected: the G78 example ends in its alarm, every
/// other program without one, with a cycle's pass header (every cycle family writes one) or,
/// for the thread moves, a thread move.
#[test]
fn reference_results_are_as_expected() {
    for p in PROGRAMS {
        let t = cycle_spec::expand(p.text.as_bytes(), &p.config());
        match (p.expect_alarm, t.alarm) {
            (None, None) => {
                let pass = t.events.iter().any(|e| matches!(e, cycle_vocab::Event::Pass(_)));
                let thread = t.moves().any(|m| m.kind == cycle_vocab::MoveKind::Thread);
                assert!(pass || thread, "{}: no cycle ran", p.name)
            }
            (Some(e), Some(a)) => assert_eq!((e.code, e.word, e.rule), (a.code, a.word, a.rule), "{}", p.name),
            (e, a) => panic!("{}: expected alarm {e:?}, got {a:?}", p.name),
        }
    }
}

#[test]
fn find_by_name() {
    assert_eq!(find("g78_example").unwrap().expect_alarm.unwrap().rule, Rule::G78Mode);
    assert_eq!(find("f76_ex1_microns").unwrap().config().dialect, Dialect::Fanuc);
    assert!(find("nope").is_none());
    assert_eq!(cases().count(), PROGRAMS.len());
}
