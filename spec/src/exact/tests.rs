use super::*;

fn big(v: i64) -> BigInt {
    BigInt::from(v)
}

#[test]
fn round_div_big_is_half_away_from_zero() {
    for (n, d, q) in [(5, 2, 3), (-5, 2, -3), (5, -2, -3), (-5, -2, 3), (4, 3, 1), (-1, 2, -1), (1, 3, 0), (0, -7, 0)] {
        assert_eq!(round_div_big(&big(n), &big(d)), big(q), "{n}/{d}");
    }
}

/// The root against a decimal reference with 40 extra digits, on many cases, squares and
/// ties included.
#[test]
fn round_root_against_decimals() {
    let scale = num_traits::pow(BigInt::from(10), 40);
    let reference = |n: i64, sigma: i8, m: u64, d: i64| -> BigInt {
        // y·10^40 = (n·10^40 + σ·√(m·10^80)) / d, the root floored: off by < 1e-40.
        let root = BigInt::from((BigUint::from(m) * (&scale * &scale).to_biguint().unwrap()).sqrt());
        let y = big(n) * &scale + root * i64::from(sigma);
        // Not a tie unless m is a square (then exact): round the 40-digit value.
        round_div_big(&y, &(big(d) * &scale))
    };
    let mut seed = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..20_000 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let n = (seed % 2001) as i64 - 1000;
        let m = (seed >> 12) % 5000;
        let d = 1 + ((seed >> 40) % 4) as i64;
        for sigma in [-1i8, 1] {
            let r = m.isqrt();
            let exact = round_root(&big(n), sigma, &BigUint::from(m), &big(d));
            if r * r == m {
                assert_eq!(exact, round_div_big(&(big(n) + big(r as i64) * i64::from(sigma)), &big(d)));
            } else {
                assert_eq!(exact, reference(n, sigma, m, d), "n {n} σ {sigma} m {m} d {d}");
            }
        }
    }
    // Ties: (1 + √9)/8 = 0.5 → 1; (−7 + √9)/8 = −0.5 → −1; (−1 − √1)/4 = −0.5 → −1.
    assert_eq!(round_root(&big(1), 1, &BigUint::from(9u32), &big(8)), big(1));
    assert_eq!(round_root(&big(-7), 1, &BigUint::from(9u32), &big(8)), big(-1));
    assert_eq!(round_root(&big(-1), -1, &BigUint::from(1u32), &big(4)), big(-1));
    // √2/2 = 0.707 → 1; −√2/2 → −1; (1 − √2)/2 = −0.207 → 0.
    assert_eq!(round_root(&big(0), 1, &BigUint::from(2u32), &big(2)), big(1));
    assert_eq!(round_root(&big(0), -1, &BigUint::from(2u32), &big(2)), big(-1));
    assert_eq!(round_root(&big(1), -1, &BigUint::from(2u32), &big(2)), big(0));
}

#[test]
fn round_div_is_half_up_on_magnitude() {
    assert_eq!(round_div(5, 2), 3);
    assert_eq!(round_div(-5, 2), -3);
    assert_eq!(round_div(4, 3), 1);
    assert_eq!(round_div(-4, 3), -1);
    assert_eq!(round_div(0, 7), 0);
    assert_eq!(round_div(7, 7), 1);
    assert_eq!(round_div(-1, 2), -1);
    assert_eq!(round_div(1, 3), 0);
}

#[test]
fn round_sqrt_exact() {
    assert_eq!(round_sqrt(0), 0);
    assert_eq!(round_sqrt(2), 1);
    assert_eq!(round_sqrt(3), 2); // √3 = 1.732
    assert_eq!(round_sqrt(6), 2); // √6 = 2.449
    assert_eq!(round_sqrt(7), 3); // √7 = 2.646
    // √2·1800 = 2545.58…
    assert_eq!(round_sqrt(2 * 1800 * 1800), 2546);
    for n in 0u128..20_000 {
        let f = (n as f64).sqrt().round() as u128;
        assert_eq!(round_sqrt(n), f, "{n}");
    }
}

/// `isqrt_big` is ⌊√n⌋ exactly ("Rounding": square roots by integer square root), also beyond
/// u128: at a square, one below it, and between.
#[test]
fn isqrt_big_is_the_floor_of_the_root() {
    let ten = |k: usize| num_traits::pow(BigUint::from(10u32), k);
    let small = |v: u32| BigUint::from(v);
    let cases = [(small(0), small(0)), (ten(1), small(3)), (ten(40), ten(20)), (ten(40) - 1u32, ten(20) - 1u32), (ten(41), "316227766016837933199".parse().unwrap())];
    for (n, r) in cases {
        assert_eq!(isqrt_big(&n), r, "{n}");
    }
}

/// `round_root` with σ = 0 is round(n / d), whatever m: (7 + 0·√5)/2 = 3.5 → 4, (−7 + 0·√9)/2 →
/// −4, 6/4 = 1.5 → 2.
#[test]
fn round_root_without_the_root() {
    assert_eq!(round_root(&big(7), 0, &BigUint::from(5u32), &big(2)), big(4));
    assert_eq!(round_root(&big(-7), 0, &BigUint::from(9u32), &big(2)), big(-4));
    assert_eq!(round_root(&big(6), 0, &BigUint::from(0u32), &big(4)), big(2));
}
