use super::*;

/// Lines: a rounded quotient, ties half away from zero.
#[test]
fn line_crossings() {
    // Example 1's Q from X11.5 Z−15.3 to X17.5 Z−25.3 at X17: −15 300 − 5 500·10 000/6 000.
    assert_eq!(line_crossing(11_500, -15_300, 17_500, -25_300, 17_000), -24_467);
    assert_eq!(line_crossing(11_500, -15_300, 17_500, -25_300, 13_000), -17_800);
    // Ties: from (0, 0) to (2, −1) at p = 1: −½ → −1; to (2, 1): ½ → 1; to (−2, 3) at −1: 1.5 → 2.
    assert_eq!(line_crossing(0, 0, 2, -1, 1), -1);
    assert_eq!(line_crossing(0, 0, 2, 1, 1), 1);
    assert_eq!(line_crossing(0, 0, -2, 3, -1), 2);
}
