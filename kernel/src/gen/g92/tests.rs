use crate::engine::{Engine, SpecEngine};
use cycle_vocab::Rule;

/// Over 3 000 random knob vectors most G92 programs are legal (at least 40 %, as every
/// structured family); step ③ (G92.PATH: a pull-out ending beyond the start X) is reached on
/// purpose — a first cycle cut shallower than its pull-out, a J past the infeed — but in few
/// cases (at most 6 %), beside the pull-out, taper and lead alarms.
#[test]
fn g92_reaches_step_3_and_mostly_runs() {
    let mut seen = std::collections::BTreeMap::new();
    let mut s = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..3_000 {
        let case = super::super::build(super::build, &super::super::tests::random_knobs(&mut s));
        let t = SpecEngine.expand(&case.program, &case.config);
        *seen.entry(t.alarm.map(|a| a.rule)).or_insert(0u32) += 1;
    }
    assert!(seen.get(&None).is_some_and(|&n| n >= 1_200), "{seen:?}");
    assert!(seen.get(&Some(Rule::G92Path)).is_some_and(|&n| (1..=180).contains(&n)), "{seen:?}");
    for rule in [Rule::G92Pullout, Rule::G92Taper, Rule::ComLead, Rule::ComRanges, Rule::ComSide] {
        assert!(seen.contains_key(&Some(rule)), "never reaches {rule}: {seen:?}");
    }
}
