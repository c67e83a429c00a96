use super::*;

fn along(num: u32, den: u32) -> Along {
    Along { event: 0, num, den }
}

#[test]
fn the_point_truncates_toward_the_start() {
    // The register's example: Z 5 → −27 at 1/2: 5 + trunc(−32/2) = −11.
    assert_eq!(point((58_700, 5_000), (58_700, -27_000), &along(1, 2)), (58_700, -11_000));
    // −7/2 = −3.5 → −3 (toward S), +7/2 → 3.
    assert_eq!(point((0, 0), (-7, 7), &along(1, 2)), (-3, 3));
    assert_eq!(point((10, 10), (20, 0), &along(0, 5)), (10, 10));
    assert_eq!(point((10, 10), (20, 0), &along(5, 5)), (20, 0));
}

#[test]
fn coverage_is_exact() {
    let half = Fraction::of(&along(1, 2));
    assert!(covers(Fraction::START, &along(0, 1)));
    assert!(covers(half, &along(2, 4)));
    assert!(covers(half, &along(500_001, 1_000_000)));
    assert!(!covers(half, &along(499_999, 1_000_000)));
    assert!(half != Fraction::START && !half.is_end() && Fraction::of(&along(3, 3)).is_end());
}
