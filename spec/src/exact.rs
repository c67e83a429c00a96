//! Exact integer arithmetic: the project's one rounding rule, integer square roots, and
//! products with tangents decided by an enclosure (docs/INTERPRETATION.md, "Rounding").
//!
//! Every rounding is **half up on the magnitude** of an exactly known real value, done once:
//!
//! * quotients `a / b`: integer division with remainder ([`round_div`]);
//! * square roots `√N`: `round(√N) = r + 1` when `N − r² > r`, else `r`, with `r = ⌊√N⌋`
//!   ([`round_sqrt`]); `√N` is never exactly `r + ½` for an integer `N`;
//! * `δ·tan θ`: see [`crate::tangent`];
//! * quotients and square roots of big integers, where products of legal words exceed i128
//!   (the contour cycles, M003): [`round_div_big`] and [`round_root`], one exact method for
//!   every root of the arcs and layers.

use num_bigint::{BigInt, BigUint, Sign};
use num_integer::{Integer, Roots};
use num_traits::{Signed, Zero};

/// `round(num / den)`, half up on the magnitude, for `den > 0`. Exact: integer division with
/// remainder on `2·|num| + den` over `2·den`.
pub fn round_div(num: i128, den: i128) -> i128 {
    debug_assert!(den > 0);
    let mag = num.unsigned_abs();
    let den = den.unsigned_abs();
    // ⌊(2|num| + den) / (2 den)⌋ = ⌊|num|/den + ½⌋. The sums cannot overflow u128 for the
    // magnitudes used here (|num| < 2^100); saturate rather than wrap if they ever did.
    let q = mag.saturating_mul(2).saturating_add(den) / den.saturating_mul(2);
    let q = i128::try_from(q).unwrap_or(i128::MAX);
    if num < 0 {
        -q
    } else {
        q
    }
}

/// `⌊√n⌋`, exact.
pub fn isqrt(n: u128) -> u128 {
    n.sqrt()
}

/// `round(√n)`, half up: `r + 1` when `n − r² > r`, else `r`, with `r = ⌊√n⌋`.
pub fn round_sqrt(n: u128) -> u128 {
    let r = isqrt(n);
    if n - r * r > r {
        r + 1
    } else {
        r
    }
}

/// `⌊√n⌋` of a big integer (used only by tests and references).
pub fn isqrt_big(n: &BigUint) -> BigUint {
    n.sqrt()
}

/// `round(num / den)`, half away from zero, for `den ≠ 0`: integer division with remainder
/// on the magnitudes, `⌊(2|num| + |den|) / (2|den|)⌋`, the sign of the quotient put back.
pub fn round_div_big(num: &BigInt, den: &BigInt) -> BigInt {
    let (n, d) = (num.abs(), den.abs());
    if d.is_zero() {
        return BigInt::zero();
    }
    let two = BigInt::from(2);
    let q: BigInt = (n * &two + &d) / (d * &two);
    if (num.sign() == Sign::Minus) != (den.sign() == Sign::Minus) {
        -q
    } else {
        q
    }
}

/// `round((n + σ·√m) / d)`, half away from zero, exactly, for `d > 0` and `σ` ∈ {−1, 0, +1}.
///
/// When `m` is a square, `r²`, the value is the rational `(n + σr)/d`, rounded by
/// [`round_div_big`] (a tie is decided half away from zero on the signed total). Otherwise the
/// value `y` is irrational, never a tie, and `round(y) = ⌊y + ½⌋ = ⌊(⌊2dy⌋ + d) / 2d⌋` with
/// `⌊2dy⌋ = 2n + ⌊2σ√m⌋`, where `⌊2√m⌋ = ⌊√4m⌋` and `⌊−2√m⌋ = −⌊√4m⌋ − 1` (4m is no square
/// either).
pub fn round_root(n: &BigInt, sigma: i8, m: &BigUint, d: &BigInt) -> BigInt {
    let r = m.sqrt();
    if sigma == 0 || &r * &r == *m {
        let root = BigInt::from(r);
        let total = match sigma {
            0 => n.clone(),
            s if s > 0 => n + root,
            _ => n - root,
        };
        return round_div_big(&total, d);
    }
    let two = BigInt::from(2);
    let two_root = BigInt::from((m * 4u32).sqrt());
    let floor_twice: BigInt = if sigma > 0 { n * &two + two_root } else { n * &two - two_root - 1 };
    (floor_twice + d).div_floor(&(d * &two))
}

#[cfg(test)]
mod tests {
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
}
