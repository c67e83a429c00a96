use super::*;
use crate::trace::{Pass, PassKind};
use crate::{AlarmCode, Rule};

fn sample() -> Trace {
    Trace {
        grid: Grid::METRIC_ISB,
        events: vec![
            Event::Move(Move::rapid(65_000, 5_000, Rule::PrjModal)),
            Event::Pass(Pass { index: 1, kind: PassKind::Rough, diameter_depth: 6_300, rule: Rule::G92Path }),
            Event::Move(Move::thread(58_700, -27_000, 30_000, 0, Rule::G92Path)),
            Event::Move(Move::variable_thread(1, -2, 3, 180_000, -5, 360_000, 0, Rule::G34)),
            Event::Move(Move::variable_thread(1, -4, 30_000, 0, -2_500, 90_000, 2_500, Rule::G162F)),
            Event::Pass(Pass { index: 2, kind: PassKind::Finish, diameter_depth: 1, rule: Rule::G92Path }),
            Event::Move(Move::feed(-1_500, 0, 2_000, Rule::PrjModal)),
        ],
        alarm: Some(Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3)),
    }
}

#[test]
fn gcode_form() {
    let text = sample().to_gcode();
    let expect = "(CYCLECHECK TRACE MM GRID 0.001)\n\
            G00 X65.000 Z5.000\n\
            (PASS 1 ROUGH DEPTH 3.150)\n\
            G32 X58.700 Z-27.000 F3.0000\n\
            G32 X0.001 Z-0.002 F0.0003 Q180000 K-0.0005\n\
            G32 X0.001 Z-0.004 F3.0000 K-0.2500 J90000 R0.2500\n\
            (PASS 2 FINISH DEPTH 0.0005)\n\
            G01 X-1.500 Z0.000 F0.2000\n\
            (ALARM 2001 LINE 3 WORD P RULE G76.REQUIRED)\n";
    assert_eq!(text, expect);
}

#[test]
fn json_round_trip() {
    let t = sample();
    assert_eq!(Trace::from_json(&t.to_json()).unwrap(), t);
}

#[test]
fn fixed_formats() {
    assert_eq!(fixed(0, 3), "0.000");
    assert_eq!(fixed(-5, 3), "-0.005");
    assert_eq!(fixed(i64::MIN, 3), "-9223372036854775.808");
}
