//! `round(δ·tan θ)` exactly, for θ a whole number of tenths of a degree, 0 ≤ θ < 90°
//! (G76.INFEED.Z: θ = a/2 with a = 0…99, half degrees; G76.PULLOUT: θ = parameter 5131, 1…89°;
//! G162.A: θ = |A| on the 0.1° grid, 0…89°).
//!
//! # Argument
//!
//! Write θ = h·π/1800 with h = 0…899 (tenths of a degree). tan 0 = 0 and tan 45° = 1 are exact
//! (h = 0, h = 450). For every other h, tan θ is irrational: tan of a rational multiple of π other
//! than 0 and π/4 (modulo π, on [0, π/2)) is irrational — were tan θ = r rational, e^{2iθ} =
//! (1 + ir)/(1 − ir) would be a root of unity in ℚ(i), i.e. ±1 or ±i, so θ ∈ {0, π/4, π/2, 3π/4}
//! modulo π. Hence δ·tan θ is never exactly k + ½ for δ ≠ 0 and the rounding is decided by any
//! enclosure narrow enough. The enclosure is computed
//! in fixed point with scale 2^p:
//!
//! 1. **π** by Machin's formula π = 16·atan(1/5) − 4·atan(1/239). Each series term
//!    ⌊2^p / ((2j+1)·x^(2j+1))⌋ is exact up to < 1 unit (nested floors of integer divisions equal
//!    one floor), the series alternate with decreasing terms, so stopping at the first term that
//!    floors to 0 leaves a tail < 1 unit: each atan is within (terms + 1) units, π·2^p within
//!    16·e₁ + 4·e₂ units.
//! 2. **θ** enclosed by θ_lo = ⌊h·π_lo/1800⌋, θ_hi = ⌈h·π_hi/1800⌉ (both exact fixed-point values
//!    below π/2 for p ≥ 64).
//! 3. **sin, cos** at the exact endpoints by Taylor series. Term n+2 is term n times x²/((n+1)(n+2))
//!    computed with a floor; as x < 1.6 the factor is < 1, so the error of the j-th term grows by
//!    at most one unit per step (≤ j units), and once a term floors to 0 the alternating,
//!    decreasing tail is below N + 1 units. Total error ≤ (N + 2)² units for N terms.
//!    sin is increasing and cos decreasing on [0, π/2], so sin θ ∈ [sin θ_lo − e, sin θ_hi + e],
//!    cos θ ∈ [cos θ_hi − e, cos θ_lo + e].
//! 4. **tan** ∈ [⌊sin_lo·2^p / cos_hi⌋, ⌈sin_hi·2^p / cos_lo⌉]·2^-p, hence δ·tan θ in
//!    [δ·t_lo, δ·t_hi]·2^-p. If ⌊δ·t_lo·2^-p + ½⌋ = ⌊δ·t_hi·2^-p + ½⌋ that is the rounding;
//!    otherwise p is doubled and the enclosure recomputed.
//!
//! Enclosures are cached per (h, p). Termination: the enclosure width tends to 0 as p grows and
//! the value is not a rounding boundary, so some p decides. The first try uses 192 bits, which
//! leaves about 150 bits of margin beyond the size of any product the cycles form (|δ| < 2^31,
//! tan < 2^7); a value that close to k + ½ has not been observed. A cap of 2^14 bits bounds the
//! loop all the same (robustness: never panic, bounded time); at the cap the rounding of the
//! lower bound is returned.

use num_bigint::{BigInt, Sign};
use num_integer::Integer;
use num_traits::{One, Signed, Zero};
use std::collections::HashMap;
use std::sync::{Mutex, OnceLock};

/// The starting precision in bits.
const BASE_BITS: u64 = 192;
/// The largest precision tried.
const MAX_BITS: u64 = 1 << 14;

/// `round(δ·tan(h/10 degrees))`, half up on the magnitude, for `h` = 0…899 (θ < 90°), the
/// tenths of a degree G162.A reads. `h ≥ 900` is outside the domain and yields `None`.
pub fn round_mul_tan_tenths(delta: i64, h: u32) -> Option<i64> {
    if h >= 900 {
        return None;
    }
    if h == 0 || delta == 0 {
        return Some(0);
    }
    if h == 450 {
        return Some(delta);
    }
    let mag = BigInt::from(delta.unsigned_abs());
    let mut p = BASE_BITS;
    loop {
        let (t_lo, t_hi) = tan_enclosure(h, p);
        let lo = round_scaled(&(&mag * &t_lo), p);
        let hi = round_scaled(&(&mag * &t_hi), p);
        if lo == hi || p >= MAX_BITS {
            let v = i64::try_from(lo).ok()?;
            return Some(if delta < 0 { -v } else { v });
        }
        p *= 2;
    }
}

/// `round(δ·tan(h/2 degrees))`, half up on the magnitude, for `h` = 0…179 (θ < 90°).
/// `h ≥ 180` is outside the domain and yields `None`.
pub fn round_mul_tan_half_degrees(delta: i64, h: u32) -> Option<i64> {
    if h >= 180 {
        return None;
    }
    round_mul_tan_tenths(delta, 5 * h)
}

/// `round(δ·tan(a/2))` for the tool angle `a` in whole degrees (G76.INFEED.Z).
pub fn round_mul_tan_half_angle(delta: i64, a_degrees: u32) -> Option<i64> {
    round_mul_tan_half_degrees(delta, a_degrees)
}

/// `round(δ·tan θ)` for θ in whole degrees (G76.PULLOUT, parameter 5131).
pub fn round_mul_tan_degrees(delta: i64, degrees: u32) -> Option<i64> {
    round_mul_tan_half_degrees(delta, degrees.checked_mul(2)?)
}

/// ⌊v·2^-p + ½⌋ for v ≥ 0.
fn round_scaled(v: &BigInt, p: u64) -> BigInt {
    let half = BigInt::one() << (p - 1);
    (v + half) >> p
}

/// [t_lo, t_hi] with t_lo·2^-p ≤ tan(h·π/1800) ≤ t_hi·2^-p, cached.
fn tan_enclosure(h: u32, p: u64) -> (BigInt, BigInt) {
    type Cache = Mutex<HashMap<(u32, u64), (BigInt, BigInt)>>;
    static CACHE: OnceLock<Cache> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(HashMap::new()));
    if let Some(v) = cache.lock().unwrap_or_else(|e| e.into_inner()).get(&(h, p)) {
        return v.clone();
    }
    let v = compute_tan_enclosure(h, p);
    cache.lock().unwrap_or_else(|e| e.into_inner()).insert((h, p), v.clone());
    v
}

fn compute_tan_enclosure(h: u32, p: u64) -> (BigInt, BigInt) {
    let one = BigInt::one() << p;
    let (pi, pi_err) = pi_fixed(&one);
    let pi_lo = &pi - BigInt::from(pi_err);
    let pi_hi = &pi + BigInt::from(pi_err);
    let h = BigInt::from(h);
    let d1800 = BigInt::from(1800);
    let theta_lo = (&h * &pi_lo).div_floor(&d1800);
    let theta_hi = (&h * &pi_hi).div_ceil(&d1800);
    let (s_lo_c, e1) = sin_fixed(&theta_lo, p);
    let (s_hi_c, e2) = sin_fixed(&theta_hi, p);
    let (c_lo_c, e3) = cos_fixed(&theta_hi, p);
    let (c_hi_c, e4) = cos_fixed(&theta_lo, p);
    let mut sin_lo = s_lo_c - BigInt::from(e1);
    if sin_lo.is_negative() {
        sin_lo = BigInt::zero();
    }
    let sin_hi = s_hi_c + BigInt::from(e2);
    let cos_lo = c_lo_c - BigInt::from(e3);
    let cos_hi = c_hi_c + BigInt::from(e4);
    if cos_lo.sign() != Sign::Plus {
        // Precision too low to separate cos from 0: an enclosure that decides nothing.
        return (BigInt::zero(), BigInt::one() << (2 * p));
    }
    let t_lo = (&sin_lo << p).div_floor(&cos_hi);
    let t_hi = (&sin_hi << p).div_ceil(&cos_lo);
    (t_lo, t_hi)
}

/// atan(1/x)·2^p (as a sum of floored terms) and its error bound in units.
fn atan_inv(x: u64, one: &BigInt) -> (BigInt, u64) {
    let x2 = BigInt::from(x * x);
    let mut power = one / BigInt::from(x); // ⌊2^p / x^(2j+1)⌋
    let mut sum = BigInt::zero();
    let mut j: u64 = 0;
    let mut positive = true;
    loop {
        let term = &power / BigInt::from(2 * j + 1);
        if term.is_zero() {
            break;
        }
        if positive {
            sum += term;
        } else {
            sum -= term;
        }
        positive = !positive;
        power /= &x2;
        j += 1;
    }
    (sum, j + 1)
}

/// π·2^p and its error bound in units (Machin).
fn pi_fixed(one: &BigInt) -> (BigInt, u64) {
    let (a5, e5) = atan_inv(5, one);
    let (a239, e239) = atan_inv(239, one);
    (a5 * 16 - a239 * 4, 16 * e5 + 4 * e239)
}

/// Σ (−1)^j x^(2j+start)/(2j+start)! in fixed point, x = x_fixed·2^-p, 0 ≤ x < 1.6; returns the
/// sum and its error bound (N + 2)² in units.
fn taylor(x_fixed: &BigInt, p: u64, start: u32) -> (BigInt, u64) {
    let one = BigInt::one() << p;
    let x2 = x_fixed * x_fixed; // scale 2^(2p)
    let mut term = if start == 0 { one } else { x_fixed.clone() };
    let mut n = start as u64;
    let mut sum = BigInt::zero();
    let mut count: u64 = 0;
    let mut positive = true;
    while !term.is_zero() {
        if positive {
            sum += &term;
        } else {
            sum -= &term;
        }
        count += 1;
        positive = !positive;
        let div = (BigInt::from((n + 1) * (n + 2))) << (2 * p);
        term = (&term * &x2) / div;
        n += 2;
    }
    (sum, (count + 2) * (count + 2))
}

fn sin_fixed(x: &BigInt, p: u64) -> (BigInt, u64) {
    taylor(x, p, 1)
}

fn cos_fixed(x: &BigInt, p: u64) -> (BigInt, u64) {
    taylor(x, p, 0)
}

#[cfg(test)]
mod tests;
