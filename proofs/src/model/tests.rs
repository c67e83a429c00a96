//! Unit tests of `model`.

use super::*;

#[test]
fn sqrt_bracket_matches_float_for_small_values() {
    for n in 0u128..20_000 {
        let r = ((n as f64).sqrt() + 0.5).floor() as u128;
        assert!(is_sqrt_round(r, n), "{n}");
        assert!(!is_sqrt_round(r + 1, n) && (r == 0 || !is_sqrt_round(r - 1, n)), "{n}");
        for t in 1..200u128 {
            assert_eq!(sqrt_round_at_least(n, t), r >= t, "{n} {t}");
        }
    }
    assert!(is_sqrt_round(1u128 << 64, u128::MAX));
}

#[test]
fn switch_pass_matches_the_definition() {
    for dd in 1..=40i64 {
        for dmin in 0..=40i64 {
            let direct = (1u32..200).find(|&n| {
                let n = f64::from(n);
                dmin > 0 && ((n.sqrt() - (n - 1.0).sqrt()) * dd as f64) < dmin as f64 - 1e-12
            });
            let got = switch_pass(dd, dmin).filter(|&s| s < 200);
            assert_eq!(got, direct, "dd {dd} dmin {dmin}");
        }
    }
    // (√13 − √12)·700 = 99.0 < 100 ≤ (√12 − √11)·700 = 103.2.
    assert_eq!(switch_pass(700, 100), Some(13));
    assert_eq!(switch_pass(999_999_999, 1), None);
}

#[test]
fn wide_arithmetic() {
    assert_eq!(W256::mul(u128::MAX, u128::MAX).halves(), (u128::MAX - 1, 1));
    assert_eq!(W256::mul(1u128 << 127, 2).halves(), (1, 0));
    assert_eq!(W256::mul(123_456_789, 987_654_321).halves(), (0, 123_456_789 * 987_654_321));
    assert!(W256::from_u128(5) < W256::from_u128(1).shift_limbs(2));
    assert_eq!(W256::from_u128(u128::MAX).checked_add(W256::from_u128(1)).unwrap().halves(), (1, 0));
    assert_eq!(W256([0, 0, 0, u64::MAX]).checked_add(W256([0, 0, 0, 1])), None);
    for (q, num, den, ok) in [(3, 5, 2, true), (2, 5, 2, false), (2, 7, 3, true), (3, 8, 3, true), (0, 1, 3, true), (1, 1, 2, true)] {
        assert_eq!(is_div_round(q, num, den), ok, "{q} {num}/{den}");
    }
    assert!(is_div_round(1, u128::MAX, u128::MAX));
    for num in 0u64..400 {
        for den in 1u64..30 {
            for q in 0u64..40 {
                let wide = is_div_round(u128::from(q), u128::from(num), u128::from(den));
                assert_eq!(is_div_round_u64(q, num, den), wide, "{q} {num}/{den}");
            }
        }
    }
    for (q, num, den) in [(u64::MAX, u64::MAX, 1), (u64::MAX, u64::MAX, u64::MAX), (1, u64::MAX, u64::MAX), (0, 0, u64::MAX), (u64::MAX / 2 + 1, u64::MAX, 2)] {
        let wide = is_div_round(u128::from(q), u128::from(num), u128::from(den));
        assert_eq!(is_div_round_u64(q, num, den), wide, "{q} {num}/{den}");
    }
    assert!(!is_div_round(u128::MAX, u128::MAX, 3));
}

#[test]
fn half_up_quotients() {
    for num in 0u128..300 {
        for den in 1u128..40 {
            let q = div_round_half_up(num, den);
            assert!((2 * q).saturating_sub(1) * den <= 2 * num || q == 0, "{num}/{den}");
            assert!(2 * num < (2 * q + 1) * den, "{num}/{den}");
        }
    }
}
