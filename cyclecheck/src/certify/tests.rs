//! Tests of the run and its options.
use super::*;
use cycle_kernel::registry::{self, FAMILIES};

#[test]
fn cycles_option() {
    let names = |list: &str| -> Vec<&str> { Options::parse_cycles(list).unwrap().iter().map(|f| f.name).collect() };
    assert_eq!(names("g92"), ["g92"]);
    assert_eq!(names("f76, g76"), ["g76", "f76"]);
    assert_eq!(names("g162,g32"), ["g162", "g32"]);
    assert_eq!(Options::parse_cycles("all").unwrap().len(), FAMILIES.len());
    let e = Options::parse_cycles("g92,g93").unwrap_err();
    assert_eq!(e, format!("--cycles takes all or a comma list of {}, operator, not \"g93\"", registry::names()));
    // `operator`: the operator generator, named or with all; no family of its own.
    assert_eq!(names("g92,operator"), ["g92"]);
    assert!(Options::parse_operator("g92, operator") && Options::parse_operator("all") && !Options::parse_operator("g92"));
    let o = Options { cycles: Options::parse_cycles("g92").unwrap(), ..Options::default() };
    let g92 = CycleRun::Family(registry::find("g92").unwrap());
    let g78 = CycleRun::Family(registry::find("g78").unwrap());
    assert!(o.covers(g92) && !o.covers(g78) && !o.covers(CycleRun::NoCycle) && !o.covers(CycleRun::AlarmFirst));
    assert!(Options::default().covers(CycleRun::NoCycle) && Options::default().covers(CycleRun::AlarmFirst));
}

#[test]
fn a_run_keeps_counts_not_cases() {
    let o = Options { cycles: Options::parse_cycles("g92").unwrap(), cases: 30, ..Options::default() };
    let mut lines = Vec::new();
    let run = run(&o, &mut lines, &mut |_| {}).unwrap();
    assert!(run.passed(), "{}", run.summary());
    let text = String::from_utf8(lines).unwrap();
    assert_eq!(text.lines().count(), run.cases());
    let first: serde_json::Value = serde_json::from_str(text.lines().next().unwrap()).unwrap();
    assert_eq!((first["name"].as_str(), first["result"].as_str()), (Some("g92_example"), Some("conform")));
    assert_eq!(run.corpus.len(), 9); // the g92 corpus programs, sub_call among them (certify::cases)
    assert!(run.corpus.iter().all(|r| r.traces.is_some()));
    assert!(run.illustrated().get(&Rule::G92Example).is_some_and(|&n| n == 1));
}

/// A certification run reads each judged case's program once (the judge's sighting, which the
/// record's cycle and the per-cycle counts take).
#[test]
fn a_run_reads_each_program_once() {
    let o = Options { cases: 12, ..Options::default() };
    let before = registry::sightings();
    let run = run(&o, &mut Vec::new(), &mut |_| {}).unwrap();
    assert_eq!(registry::sightings() - before, run.cases(), "{}", run.summary());
}
