use super::*;

/// The largest q ≥ 0 with (2q − 1)²·den ≤ 4·num, i.e. round(√(num/den)) half up
/// (√(num/den) is never exactly q − ½ when it is irrational).
fn round_sqrt_ratio(num: u128, den: u128) -> i64 {
    let target = 4 * num;
    let mut q = ((num / den) as f64).sqrt() as i64 + 2;
    while q > 0 && ((2 * q - 1) as u128).pow(2) * den > target {
        q -= 1;
    }
    q
}

#[test]
fn exact_cases() {
    assert_eq!(round_mul_tan_degrees(1234, 45), Some(1234));
    assert_eq!(round_mul_tan_half_angle(1234, 0), Some(0));
    assert_eq!(round_mul_tan_half_angle(-1234, 90), Some(-1234));
    assert_eq!(round_mul_tan_half_degrees(5, 180), None);
}

#[test]
fn against_square_root_references() {
    let mut deltas: Vec<i64> = (1..400).collect();
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    for _ in 0..200 {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        deltas.push((s % 999_999_999) as i64 + 1);
    }
    for &d in &deltas {
        let d2 = (d as u128) * (d as u128);
        // tan 30° = 1/√3, tan 60° = √3
        assert_eq!(round_mul_tan_degrees(d, 30), Some(round_sqrt_ratio(d2, 3)), "30° {d}");
        assert_eq!(round_mul_tan_degrees(d, 60), Some(round_sqrt_ratio(3 * d2, 1)), "60° {d}");
        assert_eq!(round_mul_tan_half_angle(d, 120), Some(round_sqrt_ratio(3 * d2, 1)));
        // tan 22.5° = √2 − 1: round(√2·δ) − δ (an integer shift keeps the rounding)
        assert_eq!(
            round_mul_tan_half_angle(d, 45),
            Some(round_sqrt_ratio(2 * d2, 1) - d),
            "22.5° {d}"
        );
        assert_eq!(round_mul_tan_half_angle(-d, 45), Some(-(round_sqrt_ratio(2 * d2, 1) - d)));
    }
}

/// G162.A: tenths of a degree. tan 15° = 2 − √3 and tan 75° = 2 + √3 against integer square
/// roots; other tenths against 50-digit values (27.3° → 516.138…, 0.1° → 1745.331…).
#[test]
fn tenths_of_a_degree() {
    for d in (1..300).chain([999_999_999]) {
        let r3 = round_sqrt_ratio(3 * (d as u128) * (d as u128), 1);
        assert_eq!(round_mul_tan_tenths(d, 150), Some(2 * d - r3), "15° {d}");
        assert_eq!(round_mul_tan_tenths(d, 750), Some(2 * d + r3), "75° {d}");
        assert_eq!(round_mul_tan_tenths(d, 300), round_mul_tan_degrees(d, 30));
        assert_eq!(round_mul_tan_tenths(d, 275), round_mul_tan_half_degrees(d, 55));
    }
    assert_eq!(round_mul_tan_tenths(1_000, 273), Some(516));
    assert_eq!(round_mul_tan_tenths(-1_000, 273), Some(-516));
    assert_eq!(round_mul_tan_tenths(2_000, 295), Some(1_132)); // 1131.546
    assert_eq!(round_mul_tan_tenths(1_000_000, 1), Some(1_745)); // 1745.331
    assert_eq!(round_mul_tan_tenths(1_000, 890), Some(57_290)); // 57289.962
    assert_eq!(round_mul_tan_tenths(1_000, 899), Some(572_957)); // 572957.213
    assert_eq!(round_mul_tan_tenths(1_000, 450), Some(1_000));
    assert_eq!(round_mul_tan_tenths(1_000, 0), Some(0));
    assert_eq!(round_mul_tan_tenths(1_000, 900), None);
}

#[test]
fn steep_angles_are_decided() {
    // tan 89.5° ≈ 114.589; tan 89° ≈ 57.29
    assert_eq!(round_mul_tan_half_degrees(1000, 179), Some(114_589));
    assert_eq!(round_mul_tan_degrees(1000, 89), Some(57_290));
    assert_eq!(round_mul_tan_degrees(1000, 1), Some(17));
}
