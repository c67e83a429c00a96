//! Exact integer arithmetic: the project's one rounding rule, integer square roots, and
//! products with tangents decided by an enclosure (docs/INTERPRETATION.md, "Rounding").
//!
//! Every rounding is **half up on the magnitude** of an exactly known real value, done once:
//!
//! * quotients `a / b`: integer division with remainder ([`round_div`]);
//! * square roots `√N`: `round(√N) = r + 1` when `N − r² > r`, else `r`, with `r = ⌊√N⌋`
//!   ([`round_sqrt`]); `√N` is never exactly `r + ½` for an integer `N`;
//! * `δ·tan θ`: see [`crate::tangent`].

use num_bigint::BigUint;
use num_integer::Roots;

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

#[cfg(test)]
mod tests {
    use super::*;

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
