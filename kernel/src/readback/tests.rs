use super::*;
use crate::engine::{Engine, SpecEngine};
use cycle_vocab::Config;

#[test]
fn reads_the_manual_example_back() {
    let t = SpecEngine.expand(b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n", &Config::default());
    let (grid, motions) = read(t.to_gcode().as_bytes()).unwrap();
    assert_eq!(grid, t.grid);
    assert_eq!(motions, t.events.iter().filter_map(Printed::of).collect::<Vec<_>>());
    assert!(motions.iter().any(|p| matches!(p, Printed::Motion(m) if m.kind == MoveKind::Thread && m.feed == 30_000)));
}

#[test]
fn reads_angle_and_lead_change() {
    let inch = Grid { units: Units::Inch, increment: Increment::Isc };
    let text = format!("{}\n(PASS 1 ROUGH DEPTH 0.00100)\nG32 X1.00000 Z-0.50000 F0.10000 Q180000 K-0.00005\nG32 X1.00000 Z-0.90000 F0.10000 K-0.00005 J90000 R0.00005\n(ALARM 2001 LINE 3 WORD P RULE G76.REQUIRED)\n", header(inch));
    let (grid, m) = read(text.as_bytes()).unwrap();
    assert_eq!(grid, inch);
    let first = Motion {
        kind: MoveKind::Thread,
        x: 100_000,
        z: -50_000,
        feed: 10_000,
        cx: 0,
        cz: 0,
        angle: 180_000,
        lead_change: -5,
        lead_change_angle: 360_000,
        lead_floor: 0,
        lead_steps: false,
    };
    let second = Motion { z: -90_000, angle: 0, lead_change_angle: 90_000, lead_floor: 5, ..first };
    assert_eq!(m, vec![Printed::Motion(first), Printed::Motion(second)]);
    // Arcs: the absolute centre as I (X, diameter) and K.
    let arc = cycle_vocab::Move::arc(true, 29_000, -47_848, 32_000, -40_500, 1_000_000, cycle_vocab::Rule::ArcR);
    let line = cycle_vocab::text::Trace::event_line(Grid::METRIC_ISB, &cycle_vocab::Event::Move(arc));
    assert_eq!(line, "G02 X29.000 Z-47.848 I32.000 K-40.500 F100.0000");
    let (_, m) = read(format!("{}\n{line}\n", header(Grid::METRIC_ISB)).as_bytes()).unwrap();
    assert_eq!(m, vec![Printed::Motion(Motion::from(&arc))]);
    let printed = cycle_vocab::text::Trace {
        grid: inch,
        events: vec![cycle_vocab::Event::Move(cycle_vocab::Move::variable_thread(
            100_000,
            -90_000,
            10_000,
            0,
            -5,
            90_000,
            5,
            cycle_vocab::Rule::G162I,
        ))],
        alarm: None,
    };
    assert_eq!(read(printed.to_gcode().as_bytes()).unwrap().1, vec![Printed::Motion(second)]);
}

#[test]
fn reads_dwell_and_spindle_back() {
    use cycle_vocab::{Dwell, Event, Rule, Spindle};
    let events = vec![
        Event::Dwell(Dwell { ms: 1500, rule: Rule::G84Path }),
        Event::Spindle(Spindle { state: SpindleState::Reverse, rule: Rule::G84Path }),
        Event::Spindle(Spindle { state: SpindleState::Forward, rule: Rule::G84Path }),
    ];
    let printed = cycle_vocab::text::Trace { grid: Grid::METRIC_ISB, events: events.clone(), alarm: None };
    let (_, read_back) = read(printed.to_gcode().as_bytes()).unwrap();
    assert_eq!(read_back, events.iter().filter_map(Printed::of).collect::<Vec<_>>());
    assert_eq!(read_back, vec![Printed::Dwell(1500), Printed::Spindle(SpindleState::Reverse), Printed::Spindle(SpindleState::Forward)]);
    let h = header(Grid::METRIC_ISB);
    for (body, needle) in [("G04 P1.5", "word P"), ("G04 P-1", "word P"), ("M05", "word M")] {
        let e = read(format!("{h}\n{body}\n").as_bytes()).unwrap_err();
        assert!(e.contains(needle), "{body}: {e}");
    }
}

#[test]
fn rejects_what_is_not_canonical() {
    let h = header(Grid::METRIC_ISB);
    for (body, needle) in [
        ("G00 X1.000 Z1.000 F1.0000", "word F"),
        ("G01 X1.000 Z1.000", "word F: missing"),
        ("G00 X1 Z1.000", "word X: not printed with exactly 3 decimals"),
        ("G04 X1.000 Z1.000", "word G"),
        ("G02 X1.000 Z1.000 I1.000 K1.000", "word F: missing"),
        ("G03 X1.000 Z1.000 I1.000 F1.0000", "word K: missing"),
        ("X1.000 Z1.000", "word G: missing"),
        ("G32 X1.000 Z1.000 F1.0000 Q1.5", "word Q"),
        ("G32 X1.000 Z1.000 F1.0000 J90000", "word J: printed without K"),
        ("G32 X1.000 Z1.000 F1.0000 K0.0001 J360000", "word J: 360000"),
        ("G00 X1.000 Z1.000 #", "line 2"),
    ] {
        let e = read(format!("{h}\n{body}\n").as_bytes()).unwrap_err();
        assert!(e.contains(needle), "{body}: {e}");
    }
    assert!(read(b"G00 X1.000 Z1.000\n").unwrap_err().contains("header"));
}
