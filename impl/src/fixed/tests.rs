extern crate std;
use super::*;

#[test]
fn sat_saturates_toward_the_sign() {
    assert_eq!(sat(i128::MAX), i64::MAX);
    assert_eq!(sat(i128::MIN), i64::MIN);
    assert_eq!(sat(i128::from(i64::MAX) + 1), i64::MAX);
    assert_eq!(sat(i128::from(i64::MIN) - 1), i64::MIN);
    assert_eq!((sat(-7), sat(0), sat(7)), (-7, 0, 7));
}

#[test]
fn mul_wide_matches_small_products() {
    assert_eq!(mul_wide(3, 5), U256 { hi: 0, lo: 15 });
    assert_eq!(mul_wide(u128::MAX, u128::MAX), U256 { hi: u128::MAX - 1, lo: 1 });
    assert_eq!(mul_wide(1u128 << 127, 2), U256 { hi: 1, lo: 0 });
    let x = (1u128 << 100) + 12345;
    let y = (1u128 << 90) + 777;
    // (2^100 + a)(2^90 + b) = 2^190 + b·2^100 + a·2^90 + ab
    let p = mul_wide(x, y);
    assert_eq!(p.hi, 1u128 << 62);
    assert_eq!(p.lo, (777u128 << 100) + (12345u128 << 90) + 12345 * 777);
    assert_eq!(U256 { hi: 1, lo: 0 }.checked_mul_u64(3), Some(U256 { hi: 3, lo: 0 }));
    assert_eq!(U256 { hi: u128::MAX, lo: 0 }.checked_mul_u64(2), None);
}

#[test]
fn square_roots() {
    for n in 0u128..10_000 {
        let r = isqrt(n);
        assert!(r * r <= n && (r + 1) * (r + 1) > n, "{n}");
        let rr = sqrt_round(n);
        // round half up: rr - 1/2 <= sqrt(n) < rr + 1/2  <=>  (2rr-1)^2 <= 4n < (2rr+1)^2
        assert!((2 * rr).saturating_sub(1).pow(2) <= 4 * n && 4 * n < (2 * rr + 1).pow(2), "{n}");
    }
    assert_eq!(isqrt(u128::MAX), u128::from(u64::MAX));
    assert_eq!(sqrt_round(u128::MAX), 1u128 << 64);
    // F76.EX1: 0.7 mm · √2 = 0.98995 mm → 990 µm.
    assert_eq!(sqrt_round(2 * 700 * 700), 990);
}

#[test]
fn rounding_quotients() {
    assert_eq!(div_round(5, 2), 3);
    assert_eq!(div_round(7, 3), 2);
    assert_eq!(div_round(8, 3), 3);
    assert_eq!(div_round(u128::MAX, u128::MAX), 1);
    assert_eq!(div_round(1, 0), 0);
    assert_eq!(div_round_signed(-5, 2), -3);
    assert_eq!(div_round_signed(5, -2), -3);
    assert_eq!(div_round_signed(-4, 3), -1);
    // Across the 64-bit fast path's edges: each side, and a numerator or a denominator
    // just beyond 64 bits.
    let big = u128::from(u64::MAX);
    assert_eq!(div_round(big, 2), big / 2 + 1);
    assert_eq!(div_round(big + 1, 2), 1 << 63);
    assert_eq!(div_round(big + 3, big + 1), 1);
    assert_eq!(div_round((big + 1) * 3 + big / 2 + 1, big + 1), 4);
    assert_eq!(div_round(3 * big + big / 2, big), 3);
    assert_eq!(div_round(3 * big + big / 2 + 1, big), 4);
}

#[test]
fn tangents() {
    assert_eq!(mul_tan(1_000_000, 0), 0);
    assert_eq!(mul_tan(123_457, 90), 123_457); // tan 45° = 1
    // tan 30° = 0.577350269…
    assert_eq!(mul_tan(1_000_000, 60), 577_350);
    assert_eq!(mul_tan(1_000, 60), 577);
    // tan 89° = 57.28996163…
    assert_eq!(mul_tan(1_000_000, 178), 57_289_962);
    // tan 22.5° = √2 − 1 = 0.41421356237…
    assert_eq!(mul_tan(100_000_000, 45), 41_421_356);
    assert_eq!(mul_tan(1, 179), 0);
    assert_eq!(mul_tan(u64::MAX, 178), u64::MAX);
    // Decided for a spread of δ up to 10^9 on every entry.
    let mut d = 1u64;
    while d <= 1_000_000_000 {
        for h in 0..=TAN_MAX_INDEX {
            for dd in [d, d + 1, d * 3 + 7] {
                let (_, ok) = mul_tan_checked(dd, h).unwrap();
                assert!(ok, "h {h} d {dd}");
            }
        }
        d = d * 7 + 3;
    }
}

#[test]
fn tan_table_monotone() {
    for h in 1..=TAN_MAX_INDEX {
        assert!(tan_half_degrees(h - 1) < tan_half_degrees(h));
    }
    for t in 1..=TAN_MAX_TENTHS {
        assert!(tan_tenths(t - 1) < tan_tenths(t));
    }
    assert_eq!(tan_half_degrees(90), Some((1, 0)));
    assert_eq!(tan_tenths(450), Some((1, 0)));
    assert_eq!((tan_tenths(891), tan_half_degrees(179)), (None, None));
    // A half degree is five tenths.
    for h in 0..=TAN_MAX_INDEX {
        assert_eq!(tan_half_degrees(h), tan_tenths(5 * h));
        assert_eq!(Tan::half_degrees(h), Tan::tenths(5 * h));
    }
}

/// G162.A on the 0.1° grid: tenths against known values, and the table deciding the
/// rounding for a spread of δ up to 2^32 on every entry (the margin of `tan_tenths`).
#[test]
fn tangents_in_tenths() {
    // tan 27.3° = 0.516138…, tan 14.5° = 0.258618…, tan 0.1° = 0.001745331…, tan 88.9° = 52.0807…
    assert_eq!(mul_tan_tenths(1_000_000, 273), 516_138);
    assert_eq!(mul_tan_tenths(1_000_000, 145), 258_618);
    assert_eq!(mul_tan_tenths(1_000_000_000, 1), 1_745_331);
    assert_eq!(mul_tan_tenths(1_000, 889), 52_081);
    assert_eq!(mul_tan_tenths(123_457, 450), 123_457);
    assert_eq!(mul_tan_tenths(5, 891), 0);
    let mut d = 1u64;
    while d <= 1 << 32 {
        for t in 0..=TAN_MAX_TENTHS {
            for dd in [d, d + 1, d * 3 + 7] {
                let (_, ok) = Tan::tenths(t).unwrap().mul_checked(dd).unwrap();
                assert!(ok, "t {t} d {dd}");
            }
        }
        d = d * 7 + 3;
    }
}

#[test]
fn angles() {
    assert_eq!(start_angle(0, 3), 0);
    assert_eq!(start_angle(1, 3), 120_000);
    assert_eq!(start_angle(1, 7), 51_429); // 51428.57…
    assert_eq!(start_angle(1, 16), 22_500);
    assert_eq!(start_angle(998, 999), 359_640); // 359639.63…
    assert_eq!(start_angle(1, 0), 0);
}

/// The tangent table is the generator's output, entry for entry (impl/tools/tan_tenths.py):
/// an FNV-1a hash of its 891 integer parts and 891 fractions (16 bytes each, little-endian),
/// taken of the table as generated; any changed entry changes it. Spot entries: 0° and 45° are
/// exact, tan 89° = 57.28996…
#[test]
fn tan_table_is_the_generated_one() {
    let mut h: u64 = 0xcbf2_9ce4_8422_2325;
    let mut feed = |b: u8| {
        h ^= u64::from(b);
        h = h.wrapping_mul(0x0100_0000_01b3);
    };
    TAN_INT.iter().for_each(|&b| feed(b));
    TAN_FRAC.iter().for_each(|f| f.to_le_bytes().into_iter().for_each(&mut feed));
    assert_eq!(h, 0x257e_4504_d870_ce05);
    assert_eq!((TAN_INT.len(), TAN_FRAC.len()), (891, 891));
    assert_eq!(tan_tenths(0), Some((0, 0)));
    assert_eq!(tan_tenths(450), Some((1, 0)));
    assert_eq!(tan_tenths(890).map(|(i, _)| i), Some(57));
    assert_eq!(TAN_INT.iter().map(|&i| u32::from(i)).sum::<u32>(), 1954);
}
