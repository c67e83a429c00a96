use super::*;
use crate::engine::wrong::{Panics, SpecWith};
use crate::engine::{ImplEngine, SpecEngine};

const P: &[u8] = b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX58\n";

#[test]
fn lockstep_judges_like_the_whole_traces() {
    let c = Config::default();
    let t = cycle_spec::expand(P, &c);
    if !crate::spec_alone::skip("the lockstep judge of spec against impl") {
        let j = judge(&SpecEngine, &ImplEngine, P, &c);
        assert_eq!(j.result, CaseResult::Conform);
        let seen = j.reference.unwrap();
        assert_eq!((seen.events, seen.alarm), (t.events.len(), None));
        assert!(seen.rules.contains(&Rule::G92Pullout) && j.traces.is_none());
    }
    let wrong = SpecWith { name: "late-x", fault: |i, m| m.x += i64::from(i == 5) };
    let j = judge_keeping(&SpecEngine, &wrong, P, &c);
    let CaseResult::Diverge(d) = &j.result else { panic!("{:?}", j.result) };
    let (r, cand) = j.traces.unwrap();
    assert_eq!(**d, crate::conformance::check(&r, cand.as_ref().unwrap()).unwrap_err());
    assert_eq!(d.lengths, (t.events.len(), t.events.len()));
}

#[test]
fn panics_are_failures_with_the_reference_seen() {
    let j = judge(&SpecEngine, &Panics, b"G0 X1", &Config::default());
    assert_eq!(j.result, CaseResult::Failure { engine: "panics".into(), failure: Failure { kind: FailureKind::Panic, message: "boom".into() } });
    assert_eq!(j.result.short(), "FAIL (panics panic)");
    assert_eq!(j.reference.map(|s| s.events), Some(1));
    let j = judge(&Panics, &SpecEngine, b"G0 X1", &Config::default());
    assert!(j.reference.is_none() && matches!(j.result, CaseResult::Failure { ref engine, .. } if engine == "panics"));
}

/// The judge reads the program once, beside the two engines' own runs, and its result
/// carries the cycle and the alarm block's codes that the counts and hints use — whether
/// the case conforms, the candidate panics or the reference fails.
#[test]
fn a_judged_case_reads_its_program_once() {
    let c = Config::default();
    let alarmed = b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nG20 X58\n";
    for (reference, candidate) in [(&SpecEngine as &dyn Engine, &ImplEngine as &dyn Engine), (&SpecEngine, &Panics), (&Panics, &SpecEngine)] {
        let before = registry::sightings();
        let j = judge(reference, candidate, alarmed, &c);
        assert_eq!(registry::sightings() - before, 1, "{} against {}", reference.name(), candidate.name());
        assert_eq!(j.sighting.cycle, registry::CycleRun::Family(registry::find("g92").unwrap()));
        if j.reference.is_some() {
            assert_eq!((j.alarm().map(|a| a.line), j.sighting.alarm_codes.as_slice()), (Some(3), &[20][..]));
        }
    }
    let before = registry::sightings();
    let report = crate::campaign::run((&SpecEngine, &ImplEngine), crate::corpus::cases());
    assert_eq!(registry::sightings() - before, report.cases());
}
