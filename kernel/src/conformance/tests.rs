//! The conformance relation's own tests: each divergence kind, every field, the report.

use super::*;
use cycle_vocab::text::Trace;
use cycle_vocab::{Increment, PassKind, Units};

fn rapid(x: i64, z: i64) -> Event {
    Event::Move(Move::rapid(x, z, Rule::G92Path))
}
fn thread(x: i64, z: i64) -> Event {
    Event::Move(Move::thread(x, z, 30_000, 0, Rule::G92Pullout))
}
fn pass(index: u32, depth: i64) -> Event {
    Event::Pass(Pass { index, kind: PassKind::Rough, diameter_depth: depth, rule: Rule::G76Depth1 })
}
fn alarm(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

/// The manual's first G92 cycle (G92.EXAMPLE), by hand.
fn g92() -> Trace {
    Trace {
        grid: Grid::METRIC_ISB,
        events: vec![
            rapid(65_000, 5_000),
            pass(1, 6_300),
            rapid(58_700, 5_000),
            thread(58_700, -27_000),
            thread(64_700, -28_000),
            rapid(65_000, -28_000),
            rapid(65_000, 5_000),
        ],
        alarm: None,
    }
}

fn with(events: Vec<Event>, alarm: Option<Alarm>) -> Trace {
    Trace { grid: Grid::METRIC_ISB, events, alarm }
}

#[test]
fn equal_traces_conform() {
    assert_eq!(check(&g92(), &g92()), Ok(()));
    let a = alarm(AlarmCode::MissingWord, b'P', Rule::G76Required, 3);
    assert_eq!(check(&with(vec![rapid(1, 2)], a), &with(vec![rapid(1, 2)], a)), Ok(()));
    assert_eq!(check(&with(vec![], None), &with(vec![], None)), Ok(()));
}

#[test]
fn rule_tags_are_not_compared() {
    let mut c = g92();
    for e in &mut c.events {
        match e {
            Event::Move(m) => m.rule = Rule::PrjTrace,
            Event::Pass(p) => p.rule = Rule::PrjTrace,
            Event::Dwell(d) => d.rule = Rule::PrjTrace,
            Event::Spindle(s) => s.rule = Rule::PrjTrace,
            Event::Press(p) => p.rule = Rule::PrjTrace,
            Event::Stop(s) => s.rule = Rule::PrjTrace,
            Event::Resume(r) => r.rule = Rule::PrjTrace,
        }
    }
    assert_eq!(check(&g92(), &c), Ok(()));
}

#[test]
fn grid_mismatch() {
    let mut c = g92();
    c.grid = Grid { units: Units::Metric, increment: Increment::Isc };
    let d = check(&g92(), &c).unwrap_err();
    assert_eq!((d.kind, d.index, d.field), (DivergenceKind::GridMismatch, 0, Some("grid")));
    assert_eq!((d.reference.as_str(), d.candidate.as_str()), ("MM GRID 0.001", "MM GRID 0.0001"));
    assert!(d.context.is_empty());
    let text = d.to_string();
    assert!(text.contains("grid mismatch") && text.contains("MM GRID 0.0001"), "{text}");
}

#[test]
fn field_mismatch_names_field_values_rule_and_context() {
    let mut c = g92();
    c.events[3] = thread(58_702, -27_000);
    let d = check(&g92(), &c).unwrap_err();
    assert_eq!((d.kind, d.index, d.field), (DivergenceKind::FieldMismatch, 3, Some("x")));
    assert_eq!(d.reference, "G32 X58.700 Z-27.000 F3.0000");
    assert_eq!(d.candidate, "G32 X58.702 Z-27.000 F3.0000");
    assert_eq!(d.values, Some(("58700".to_string(), "58702".to_string())));
    assert_eq!(d.rule, Some(Rule::G92Pullout));
    assert_eq!(d.context.len(), 3);
    assert_eq!(d.context[0], (0, "G00 X65.000 Z5.000".to_string()));
    assert_eq!(d.context[2], (2, "G00 X58.700 Z5.000".to_string()));
    let text = d.to_string();
    for part in [
        "field mismatch at event 3, field `x`",
        "reference: G32 X58.700 Z-27.000 F3.0000",
        "candidate: G32 X58.702 Z-27.000 F3.0000",
        "x differs: reference 58700, candidate 58702 (grid increments)",
        "rule: G92.PULLOUT (M002, impl): K before the end",
        "(PASS 1 ROUGH DEPTH 3.150)",
    ] {
        assert!(text.contains(part), "missing {part:?} in\n{text}");
    }
}

/// The event with one field changed: a number one more, a kind another variant.
fn with_field_changed(event: &Event, field: &str) -> Event {
    let mut json = serde_json::to_value(event).unwrap();
    let value = json[field].clone();
    if let Some(n) = value.as_i64() {
        json[field] = (n + 1).into();
        return serde_json::from_value(json).unwrap();
    }
    for variant in ["rapid", "feed", "thread", "ROUGH", "FINISH", "SPRING"] {
        json[field] = variant.into();
        match serde_json::from_value::<Event>(json.clone()) {
            Ok(changed) if changed != *event => return changed,
            _ => {}
        }
    }
    panic!("no other value for {field} = {value}")
}

/// Every field of a move and of a pass but the rule tag, changed alone, is a divergence
/// naming it. The fields are those the event serializes, so a field added to `Move` or
/// `Pass` is tried without a change here.
#[test]
fn a_change_in_any_single_field_diverges_naming_it() {
    let m = Event::Move(Move::variable_thread(1_000, -2_000, 30_000, 120_000, -5, 90_000, 5, Rule::G76Path));
    let p = Event::Pass(Pass { index: 2, kind: PassKind::Finish, diameter_depth: 4_800, rule: Rule::G76Finish });
    for (event, fields) in [(m, 8), (p, 3)] {
        let json = serde_json::to_value(event).unwrap();
        let names: Vec<&String> = json.as_object().unwrap().keys().filter(|k| *k != "event" && *k != "rule").collect();
        assert!(names.len() >= fields, "{names:?}");
        for field in names {
            let changed = with_field_changed(&event, field);
            let d = check(&with(vec![event], None), &with(vec![changed], None)).unwrap_err();
            assert_eq!((d.kind, d.index, d.field), (DivergenceKind::FieldMismatch, 0, Some(field.as_str())), "{changed:?}");
            assert_eq!(d.rule, Some(event.rule()));
        }
    }
}

/// A variable lead that differs only in how it changes is a divergence naming that field,
/// with its unit.
#[test]
fn lead_change_divergence_is_reported() {
    let r = Move::variable_thread(24_000, -18_000, 15_000, 0, 500, 180_000, 0, Rule::G162F);
    let c = Move { lead_change_angle: 360_000, ..r };
    let d = check(&with(vec![Event::Move(r)], None), &with(vec![Event::Move(c)], None)).unwrap_err();
    assert_eq!((d.kind, d.field, d.rule), (DivergenceKind::FieldMismatch, Some("lead_change_angle"), Some(Rule::G162F)));
    let text = d.to_string();
    assert!(text.contains("lead_change_angle differs: reference 180000, candidate 360000 (0.001°)"), "{text}");
    assert!(text.contains("K0.0500 J180000"), "{text}");
}

#[test]
fn event_kind_mismatch() {
    let mut c = g92();
    c.events.remove(1); // the pass header is missing: a move stands at index 1
    let d = check(&g92(), &c).unwrap_err();
    assert_eq!((d.kind, d.index, d.field), (DivergenceKind::EventKindMismatch, 1, Some("event")));
    assert_eq!(d.reference, "(PASS 1 ROUGH DEPTH 3.150)");
    assert_eq!(d.candidate, "G00 X58.700 Z5.000");
    assert_eq!(d.rule, Some(Rule::G76Depth1));
    assert!(d.to_string().contains("event kind mismatch at event 1"), "{d}");
}

#[test]
fn missing_events() {
    let mut c = g92();
    c.events.truncate(5);
    let d = check(&g92(), &c).unwrap_err();
    assert_eq!((d.kind, d.index, d.field), (DivergenceKind::MissingEvents, 5, None));
    assert_eq!(d.reference, "G00 X65.000 Z-28.000");
    assert_eq!(d.candidate, END);
    assert_eq!(d.lengths, (7, 5));
    assert_eq!(d.rule, Some(Rule::G92Path));
    // An empty candidate (the production expander before it exists) diverges at event 0.
    let d = check(&g92(), &with(vec![], None)).unwrap_err();
    assert_eq!((d.kind, d.index), (DivergenceKind::MissingEvents, 0));
    assert!(d.to_string().contains("context: none"), "{d}");
}

#[test]
fn extra_events() {
    let mut c = g92();
    c.events.push(rapid(0, 0));
    let d = check(&g92(), &c).unwrap_err();
    assert_eq!((d.kind, d.index), (DivergenceKind::ExtraEvents, 7));
    assert_eq!((d.reference.as_str(), d.candidate.as_str()), (END, "G00 X0.000 Z0.000"));
    assert_eq!(d.rule, None);
    assert_eq!(d.context.len(), CONTEXT);
}

#[test]
fn alarm_mismatch_in_every_field() {
    let r = Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3);
    let cases: [(&str, Alarm); 5] = [
        ("code", Alarm { code: AlarmCode::OutOfRange, ..r }),
        ("word", Alarm { word: Some(b'Q'), ..r }),
        ("word", Alarm { word: None, ..r }),
        ("line", Alarm { line: 4, ..r }),
        ("rule", Alarm { rule: Rule::ComLead, ..r }),
    ];
    for (field, c) in cases {
        let d = check(&with(vec![rapid(1, 1)], Some(r)), &with(vec![rapid(1, 1)], Some(c))).unwrap_err();
        assert_eq!((d.kind, d.index, d.field), (DivergenceKind::AlarmMismatch, 1, Some(field)));
        assert_eq!(d.rule, Some(Rule::G76Required));
        assert_eq!(d.reference, "(ALARM 2001 LINE 3 WORD P RULE G76.REQUIRED)");
    }
    let d = check(&with(vec![], Some(r)), &with(vec![], Some(Alarm { code: AlarmCode::OutOfRange, ..r }))).unwrap_err();
    assert_eq!(d.values, Some(("2001 MISSING WORD".to_string(), "2002 OUT OF RANGE".to_string())));
    assert!(d.to_string().contains("rule: G76.REQUIRED (M001, impl): P(k) or Q(Δd) missing"), "{d}");
}

#[test]
fn unexpected_alarm() {
    let a = alarm(AlarmCode::Geometry, b'K', Rule::G92Pullout, 2);
    // Where the reference ends cleanly…
    let d = check(&g92(), &with(g92().events, a)).unwrap_err();
    assert_eq!((d.kind, d.index), (DivergenceKind::UnexpectedAlarm, 7));
    assert_eq!((d.reference.as_str(), d.candidate.as_str()), (END, "(ALARM 3001 LINE 2 WORD K RULE G92.PULLOUT)"));
    // …and where it goes on.
    let d = check(&g92(), &with(g92().events[..2].to_vec(), a)).unwrap_err();
    assert_eq!((d.kind, d.index), (DivergenceKind::UnexpectedAlarm, 2));
    assert_eq!(d.reference, "G00 X58.700 Z5.000");
    assert_eq!(d.rule, Some(Rule::G92Path));
}

#[test]
fn missing_alarm() {
    let a = alarm(AlarmCode::OutOfRange, b'P', Rule::G78Mode, 3);
    let r = with(vec![rapid(80_000, 10_000)], a);
    // The candidate ends cleanly where the reference alarms…
    let d = check(&r, &with(vec![rapid(80_000, 10_000)], None)).unwrap_err();
    assert_eq!((d.kind, d.index), (DivergenceKind::MissingAlarm, 1));
    assert_eq!((d.reference.as_str(), d.candidate.as_str()), ("(ALARM 2002 LINE 3 WORD P RULE G78.MODE)", END));
    assert_eq!(d.rule, Some(Rule::G78Mode));
    // …or goes on moving.
    let d = check(&r, &with(vec![rapid(80_000, 10_000), pass(1, 10)], None)).unwrap_err();
    assert_eq!((d.kind, d.index), (DivergenceKind::MissingAlarm, 1));
    assert_eq!(d.candidate, "(PASS 1 ROUGH DEPTH 0.005)");
    assert!(d.to_string().contains("rule: G78.MODE (M000, impl)"), "{d}");
}

#[test]
fn every_kind_is_reachable() {
    // The kinds above, once more through one table, so that a kind no test reaches shows.
    let mut seen = std::collections::BTreeSet::new();
    let a = alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, 1);
    let b = alarm(AlarmCode::MissingWord, b'P', Rule::G76Required, 1);
    let isc = Trace { grid: Grid { units: Units::Inch, increment: Increment::Isc }, ..with(vec![], None) };
    let pairs = [
        (with(vec![], None), isc),
        (with(vec![rapid(1, 1)], None), with(vec![rapid(1, 2)], None)),
        (with(vec![rapid(1, 1)], None), with(vec![pass(1, 1)], None)),
        (with(vec![rapid(1, 1)], None), with(vec![], None)),
        (with(vec![], None), with(vec![rapid(1, 1)], None)),
        (with(vec![], a), with(vec![], b)),
        (with(vec![], None), with(vec![], a)),
        (with(vec![], a), with(vec![], None)),
    ];
    for (r, c) in &pairs {
        seen.insert(check(r, c).unwrap_err().kind);
    }
    assert_eq!(seen.into_iter().collect::<Vec<_>>(), DivergenceKind::ALL.to_vec());
}

#[test]
fn alarm_texts() {
    let a = Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3);
    assert_eq!(alarm_summary(&a), "ALARM 2001 MISSING WORD: word P, rule G76.REQUIRED, line 3");
    assert_eq!(alarm_short(&a), "alarm 2001 P G76.REQUIRED");
    let b = Alarm::new(AlarmCode::TooManyPasses, None, Rule::PrjMaxPass, 2);
    assert_eq!(alarm_summary(&b), "ALARM 3002 TOO MANY PASSES: rule PRJ.MAXPASS, line 2");
    let c = Alarm::new(AlarmCode::BadCharacter, Some(0x80), Rule::PrjLex, 1);
    assert_eq!(alarm_summary(&c), "ALARM 1001 BAD CHARACTER: word 0x80, rule PRJ.LEX, line 1");
    assert_eq!(code_name(AlarmCode::WordNotAllowed), "WORD NOT ALLOWED");
}

#[test]
fn json_form() {
    let mut c = g92();
    c.events[3] = thread(58_702, -27_000);
    let j = to_json(&check(&g92(), &c).unwrap_err());
    assert_eq!(j["kind"], "field mismatch");
    assert_eq!(j["index"], 3);
    assert_eq!(j["field"], "x");
    assert_eq!(j["rule"], "G92.PULLOUT");
    assert_eq!(j["values"]["candidate"], "58702");
}

/// A dwell or spindle event that differs in its field, or stands where the other trace has
/// another kind of event, diverges and names the field.
#[test]
fn dwell_and_spindle_events_are_compared() {
    use cycle_vocab::{Dwell, Spindle, SpindleState};
    let dwell = |ms| Event::Dwell(Dwell { ms, rule: Rule::G83Peck });
    let spindle = |state| Event::Spindle(Spindle { state, rule: Rule::G84Path });
    let r = with(vec![rapid(1, 2), dwell(500), spindle(SpindleState::Reverse)], None);
    assert_eq!(check(&r, &r.clone()), Ok(()));
    let d = check(&r, &with(vec![rapid(1, 2), dwell(501), spindle(SpindleState::Reverse)], None)).unwrap_err();
    assert_eq!((d.kind, d.index, d.field), (DivergenceKind::FieldMismatch, 1, Some("ms")));
    assert_eq!((d.reference.as_str(), d.candidate.as_str()), ("G04 P500", "G04 P501"));
    let d = check(&r, &with(vec![rapid(1, 2), dwell(500), spindle(SpindleState::Forward)], None)).unwrap_err();
    assert_eq!((d.kind, d.index, d.field), (DivergenceKind::FieldMismatch, 2, Some("state")));
    let d = check(&r, &with(vec![rapid(1, 2), spindle(SpindleState::Reverse), dwell(500)], None)).unwrap_err();
    assert_eq!((d.kind, d.index), (DivergenceKind::EventKindMismatch, 1));
}

/// Below `full` only moves are compared, indexed among the moves; the alarm by its code
/// (`motion`) or by its presence (`motion-alarm-presence`).
#[test]
#[allow(clippy::result_large_err)]
fn levels_compare_moves_and_less_of_the_alarm() {
    let at = |level: Level, r: &Trace, c: &Trace| {
        let stream = c.events.iter().copied().map(Ok).chain(c.alarm.map(Err));
        let mut l = Lockstep::new(r.grid, c.grid, stream).at_level(level);
        r.events.iter().for_each(|&e| l.reference(e));
        l.finish(r.alarm)
    };
    let reference = with(g92().events, alarm(AlarmCode::MissingWord, b'P', Rule::G76Required, 3));
    let mut moves_only = reference.clone();
    moves_only.events.retain(|e| matches!(e, Event::Move(_)));
    assert!(at(Level::Full, &reference, &moves_only).is_err(), "full compares pass headers");
    assert_eq!(at(Level::Motion, &reference, &moves_only), Ok(()));
    // The alarm's word, line and rule are not compared at motion; its code is.
    let mut other_line = moves_only.clone();
    other_line.alarm = alarm(AlarmCode::MissingWord, b'Q', Rule::PrjTrace, 9);
    assert_eq!(at(Level::Motion, &reference, &other_line), Ok(()));
    assert_eq!(at(Level::Full, &reference, &reference.clone()), Ok(()));
    let mut other_code = moves_only.clone();
    other_code.alarm = alarm(AlarmCode::OutOfRange, b'P', Rule::G76Required, 3);
    let d = at(Level::Motion, &reference, &other_code).unwrap_err();
    assert_eq!((d.kind, d.field, d.level), (DivergenceKind::AlarmMismatch, Some("code"), Level::Motion));
    assert_eq!(at(Level::MotionAlarmPresence, &reference, &other_code), Ok(()));
    let mut no_alarm = moves_only.clone();
    no_alarm.alarm = None;
    assert_eq!(at(Level::MotionAlarmPresence, &reference, &no_alarm).unwrap_err().kind, DivergenceKind::MissingAlarm);
    // A move one increment off: found, indexed among the moves, and the report says so.
    let mut off = moves_only.clone();
    if let Event::Move(m) = &mut off.events[3] {
        m.z += 1;
    }
    let d = at(Level::Motion, &reference, &off).unwrap_err();
    assert_eq!((d.index, d.field, d.rule, d.lengths), (3, Some("z"), Some(Rule::G92Pullout), (6, 6)));
    let text = d.to_string();
    assert!(text.contains("at event 3 of the moves-only traces (comparison level motion") && text.contains("6 moves"), "{text}");
}
