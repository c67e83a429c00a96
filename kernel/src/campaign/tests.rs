use super::*;
use crate::conformance::DivergenceKind;
use crate::engine::SpecEngine;

use crate::engine::wrong::{Panics, SpecWith};

/// The spec with every X one increment off after the first event: a wrong candidate.
const OFF_BY_ONE: SpecWith = SpecWith { name: "off-by-one", fault: |i, m| m.x += i64::from(i > 0) };

#[test]
fn spec_against_itself_conforms_on_the_corpus() {
    let r = run((&SpecEngine, &SpecEngine), crate::corpus::cases());
    assert_eq!(r.cases(), crate::corpus::PROGRAMS.len());
    assert!(r.all_conform(), "{}", r.summary());
    assert_eq!(r.conforming(), r.cases());
    assert_eq!(r.by_ending.get("alarm 2002 P G78.MODE"), Some(&1), "{}", r.summary());
    let family = |name| CycleRun::Family(registry::find(name).unwrap());
    assert_eq!(r.by_cycle.get(&family("g78")), Some(&9), "{}", r.summary());
    assert_eq!(r.by_cycle.get(&family("f76")), Some(&2), "{}", r.summary());
    assert!(r.outcomes.iter().all(|o| matches!(o.cycle, CycleRun::Family(_))), "{}", r.summary());
    let g92 = r.outcomes.iter().find(|o| o.name == "g92_example").unwrap();
    assert_eq!((g92.cycle, g92.passes), (family("g92"), 4));
    assert_eq!(g92.verdict.short(), "conform");
    let g78 = r.outcomes.iter().find(|o| o.name == "g78_example").unwrap();
    assert_eq!(g78.verdict.short(), "conform (alarm 2002 P G78.MODE)");
}

#[test]
fn a_wrong_candidate_is_found_on_every_moving_program() {
    let r = run((&SpecEngine, &OFF_BY_ONE), crate::corpus::cases());
    // Every program but the G78 example (one rapid, then its alarm) moves more than once.
    assert_eq!(r.findings.len(), r.cases() - 1, "{}", r.summary());
    for (f, d) in r.divergences() {
        assert_eq!((d.kind, d.field), (DivergenceKind::FieldMismatch, Some("x")), "{}", f.name);
        assert!(f.to_string().contains("program:\n"), "{f}");
    }
    assert!(r.outcomes[0].verdict.short().starts_with("DIVERGE (field mismatch at event "));
}

#[test]
fn a_panic_is_a_finding() {
    let cases = vec![("p".to_string(), b"G0 X1".to_vec(), Config::default())];
    let r = run((&SpecEngine, &Panics), cases.into_iter());
    assert_eq!(r.findings.len(), 1);
    assert!(matches!(&r.findings[0].verdict, Verdict::Panic { engine, message } if engine == "panics" && message == "boom"));
    assert_eq!(r.outcomes[0].verdict.short(), "PANIC (panics)");
}
