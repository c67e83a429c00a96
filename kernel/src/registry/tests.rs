use super::*;
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, AlarmCode, Config};

/// The cycle run's name, with a reference trace that alarms on `alarm_line`.
fn run(program: &[u8], dialect: Dialect, alarm_line: Option<u32>) -> &'static str {
    let alarm = alarm_line.map(|line| cycle_vocab::Alarm::new(cycle_vocab::AlarmCode::Geometry, None, Rule::PrjWord, line));
    let reference = Trace { grid: cycle_vocab::Grid::METRIC_ISB, events: Vec::new(), alarm };
    cycle_run(program, &Config { dialect, ..Config::default() }, Some(&reference)).name()
}

#[test]
fn the_first_selecting_block_names_the_family() {
    assert_eq!(run(b"G0 X1\nG92 X1 Z-1 F1", Gsk, None), "g92");
    assert_eq!(run(b"G76 P1", Fanuc, None), "f76");
    assert_eq!(run(b"G76 P1", Gsk, None), "g76");
    assert_eq!(run(b"G0 X1\ng033 Z-1 F1\nG92 X1", Gsk, None), "g32");
    assert_eq!(run(b"G162 G91 X1", Nc201, None), "g162");
    // A contour written before G70 (arcs, G50: no family) runs G70; G71 before G70 runs G71.
    assert_eq!(run(b"G50 X10 Z0\nN1 G0 X5 F1\nN2 G2 X9 Z-2 R2\nG70 P1 Q2", Gsk, None), "g70");
    assert_eq!(run(b"G71 P1 Q2 F1\nN1 G0 X5\nN2 G1 Z-2\nG70 P1 Q2", Fanuc, None), "g71");
    assert_eq!(run(b"G72 W1", Nc201, Some(1)), "alarm_before_cycle");
    // G92.1 and G-92 select nothing; G78 selects nothing under fanuc.
    assert_eq!(run(b"G92.1\nG-92\nG0 X1", Gsk, None), "no_cycle");
    assert_eq!(run(b"G78 P1", Fanuc, Some(1)), "alarm_before_cycle");
}

#[test]
fn the_alarm_and_the_end_bound_the_search() {
    assert_eq!(run(b"G0 X1 Q5\nG92 X1 Z-1 F1", Gsk, Some(1)), "alarm_before_cycle");
    assert_eq!(run(b"G0 X1\nG92 X1 Z-1\n", Gsk, Some(2)), "g92");
    assert_eq!(run(b"G0 X1 #G92", Gsk, Some(1)), "alarm_before_cycle");
    assert_eq!(run(b"G0 X1\nM30\nG92 X1 Z-1 F1", Gsk, None), "no_cycle");
    assert_eq!(run(b"", Gsk, None), "no_cycle");
}

#[test]
fn rules_group_by_family() {
    assert_eq!(rule_group(Rule::G92Jk3), RuleGroup::Family(find("g92").unwrap()));
    assert_eq!(rule_group(Rule::G76DepthMin), RuleGroup::Family(find("g76").unwrap()));
    assert_eq!(rule_group(Rule::F76Microns), RuleGroup::Family(find("f76").unwrap()));
    assert_eq!(rule_group(Rule::Nc201XMode), RuleGroup::Family(find("g162").unwrap()));
    assert_eq!(rule_group(Rule::G33), RuleGroup::Family(find("g32").unwrap()));
    assert_eq!(rule_group(Rule::ComLead), RuleGroup::Common);
    assert_eq!(rule_group(Rule::G163), RuleGroup::Other);
    // The contour's rules stand with g71; arcs, G50 and the nose-radius codes are common.
    assert_eq!(rule_group(Rule::CntFind), RuleGroup::Family(find("g71").unwrap()));
    assert_eq!(rule_group(Rule::G72Layer), RuleGroup::Family(find("g72").unwrap()));
    assert_eq!(rule_group(Rule::G70Uw), RuleGroup::Family(find("g70").unwrap()));
    for rule in [Rule::ArcTol, Rule::G50Coord, Rule::TnrcSwitch] {
        assert_eq!(rule_group(rule), RuleGroup::Common, "{rule}");
    }
}

#[test]
fn rows_are_distinct_and_ordered() {
    for (i, f) in FAMILIES.iter().enumerate() {
        assert_eq!(f.index(), i);
        assert_eq!(find(f.name), Some(f));
        assert!(FAMILIES[..i].iter().all(|g| g.name != f.name && g.display != f.display), "{} twice", f.name);
    }
    assert!(CycleRun::Family(&FAMILIES[0]) < CycleRun::Family(&FAMILIES[1]));
    assert!(CycleRun::Family(&FAMILIES[5]) < CycleRun::NoCycle && CycleRun::NoCycle < CycleRun::AlarmFirst);
}

/// One read gives the cycle and the G codes of the alarm's block, wherever that block is: on
/// the cycle's line, after it, or in a subprogram past M30.
#[test]
fn the_alarm_block_is_sighted_with_the_cycle() {
    let c = Config::default();
    let at = |line| Alarm::new(AlarmCode::Geometry, Some(b'G'), Rule::PrjDialect, line);
    let s = sight(b"G0 X1\nG92 X1 Z-1 F1\nG162 G91 X1\n", &c, Some(&at(3)));
    assert_eq!((s.cycle.name(), s.alarm_codes), ("g92", vec![162, 91]));
    let s = sight(b"G0 X1\nG92 X1 Z-1 F1\nM30\nO1\nG20 G0 X2\n", &c, Some(&at(5)));
    assert_eq!((s.cycle.name(), s.alarm_codes), ("g92", vec![20, 0]));
    // G92.1 and G-92 are no whole-number codes; a line past the program's blocks has none.
    let s = sight(b"G92.1 G-92 G21\n", &c, Some(&at(1)));
    assert_eq!((s.cycle.name(), s.alarm_codes), ("alarm_before_cycle", vec![21]));
    assert_eq!(sight(b"G0 X1\n", &c, Some(&at(7))).alarm_codes, Vec::<u64>::new());
    assert_eq!(sight(b"G0 X1\n", &c, None), Sighting { cycle: CycleRun::NoCycle, alarm_codes: Vec::new() });
}
