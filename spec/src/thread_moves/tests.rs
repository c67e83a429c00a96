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
