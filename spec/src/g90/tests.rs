use super::*;

#[test]
fn cut_start() {
    assert_eq!(cut_start_x(40_000, -5_000), 30_000); // the seed: I-5 at X40 starts at X30
    assert_eq!(cut_start_x(35_000, -5_000), 25_000);
}

#[test]
fn taper_rule_as_g92() {
    // U = −10 (diameter): I up to +5 (radius) against it, any I with it.
    assert!(taper_ok(2 * 5_000, -10_000));
    assert!(!taper_ok(2 * 5_001, -10_000));
    assert!(taper_ok(2 * -9_000, -10_000));
    assert!(taper_ok(2 * 7, 0));
    for (r, u) in [(0, 100), (-50, 100), (-51, 100), (100, 100), (5, 0)] {
        assert_eq!(taper_ok(2 * r, u), crate::g92::taper_ok(r, u));
    }
}
