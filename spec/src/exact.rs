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
mod tests;
