use super::escape;

/// The escape steps by Δi/d, rounded once, half away from zero, and is 0 at the last pass.
#[test]
fn escapes_round_once() {
    assert_eq!((1..=10).map(|n| escape(18_000, 10, n)).collect::<Vec<_>>()[..3], [16_200, 14_400, 12_600]);
    assert_eq!(escape(18_000, 10, 10), 0);
    assert_eq!(escape(1, 2, 1), 1); // 0.5 → 1
    assert_eq!(escape(-1, 2, 1), -1); // −0.5 → −1
    assert_eq!(escape(10, 3, 1), 7); // 6.67 → 7
    assert_eq!(escape(10, 3, 2), 3); // 3.33 → 3
    assert_eq!(escape(7, 1, 1), 0); // d = 1: one pass at the allowances
}
