use super::*;

/// G34: F 2 mm, K −0.1 mm/rev over 20 mm of Z (ISB): L² = 2² − 2·0.1·20 = 0 → the lead would
/// reach 0 at the end: refused; over 19.999 mm it stays positive.
#[test]
fn shrinking_lead_must_stay_positive() {
    let g = Grid::METRIC_ISB;
    let s2 = long_travel_twice(-20_000, 0, g);
    assert_eq!(lead_stays_legal(20_000, -1_000, s2, g, 3), Err(alarm(AlarmCode::Geometry, b'K', Rule::G34, 3)));
    let s2 = long_travel_twice(-19_999, 0, g);
    assert!(lead_stays_legal(20_000, -1_000, s2, g, 3).is_ok());
    assert!(lead_stays_legal(20_000, 1_000, s2, g, 3).is_ok());
    assert!(lead_stays_legal(20_000, 0, s2, g, 3).is_ok());
}

#[test]
fn growing_lead_stays_in_range() {
    let g = Grid::METRIC_ISB;
    // F 9000 mm, K 10 mm/rev: L² = 9000² + 2·10·ΔZ ≤ 9999² needs ΔZ ≤ 949 000.05 mm.
    assert!(lead_stays_legal(90_000_000, 100_000, long_travel_twice(949_000_050, 0, g), g, 1).is_ok());
    assert!(lead_stays_legal(90_000_000, 100_000, long_travel_twice(949_000_051, 0, g), g, 1).is_err());
}

#[test]
fn laws() {
    assert_eq!(g34_law(0), LeadLaw::default());
    assert_eq!(g34_law(-5), LeadLaw { change: -5, change_angle: 360_000, floor: 0, stepped: false });
}

/// The alarm (code, word, rule, line) a program ends in, if any.
fn alarm_of(src: &str) -> Option<(AlarmCode, Option<u8>, Rule, u32)> {
    let t = crate::expand(src.as_bytes(), &cycle_vocab::Config::default());
    t.alarm.map(|a| (a.code, a.word, a.rule, a.line))
}

/// G34 (`003_…` line 155: `G34 X(U)_Z(W)_F_K_`), its lead bound measured from the current
/// position, not from 0 (docs/INTERPRETATION.md "G34 lead bound": s2 from ΔZ, ΔX). Metric ISB,
/// c = 10 lead counts an increment. Z long: from Z5 to Z-15, |ΔZ| = 20 mm, F2 K-0.1:
/// L² = 20 000² − 1 000·(2·20 000·10) = 0, refused; to Z-14.999 it stays above 0.
#[test]
fn g34_bound_over_the_z_travel_from_the_start() {
    assert_eq!(alarm_of("G0 X20 Z5\nG34 Z-15 F2 K-0.1\n"), Some((AlarmCode::Geometry, Some(b'K'), Rule::G34, 2)));
    assert_eq!(alarm_of("G0 X20 Z5\nG34 Z-14.999 F2 K-0.1\n"), None);
}

/// X long (|ΔX| 40 mm on the diameter = 20 mm radius > |ΔZ| = 1 mm): s2 = |ΔX|·c = 400 000.
/// From X10 to X50, F2 K-0.09: L² = 20 000² − 900·400 000 = 4·10⁷ > 0, legal; K-0.1: L² = 0,
/// refused.
#[test]
fn g34_bound_over_the_x_travel_from_the_start() {
    assert_eq!(alarm_of("G0 X10 Z0\nG34 X50 W-1 F2 K-0.09\n"), None);
    assert_eq!(alarm_of("G0 X10 Z0\nG34 X50 W-1 F2 K-0.1\n"), Some((AlarmCode::Geometry, Some(b'K'), Rule::G34, 2)));
}
