//! TEST `no_overflow_isqrt_tan` (driver-only: not a Kani proof) — COM.RANGES (and the rounding of COM.UNITS, G76.INFEED.Z,
//! G76.PULLOUT, COM.MULTISTART): the fixed-point helpers of `cycle_impl::fixed` never panic
//! and meet their specifications.
//!
//! **Properties** (one branch of the body each; Kani explores all of them):
//!
//! 0. `isqrt(n)`, any `u128`: r² ≤ n < (r + 1)². `sqrt_round(n)`: r − ½ ≤ √n < r + ½, decided
//!    in integers as r(r − 1) < n ≤ r(r + 1) ([`crate::model::is_sqrt_round`]).
//! 1. `div_round(num, den)`, any `u128`s: 0 for den = 0, else q − ½ ≤ num/den < q + ½, decided
//!    in our own 256-bit arithmetic ([`crate::model::is_div_round`]).
//! 2. `div_round_signed(num, den)`, any `i128`s (including `i128::MIN`): magnitude as in 1,
//!    sign of num/den (half away from zero), no panic.
//! 3. `mul_wide(a, b)`, any `u128`s: equals our own schoolbook product ([`crate::model::W256`]).
//! 4. `mul_tan(δ, h)` for every legal length δ ≤ N and every table index h ≤ 178 (0°…89° in
//!    half degrees): the table decides the rounding (`mul_tan_checked`'s flag); the result is
//!    δ·tan rounded half up for every tangent in the table's enclosure [L, L + 2^-128)
//!    (checked in our own 256-bit arithmetic); it is monotone in δ and in the angle; exact at
//!    0° (0) and 45° (δ); and at 15°, 22.5°, 30°, 60°, 67.5°, 75° it equals the rounding
//!    of the closed forms 2 − √3, √2 − 1, 1/√3, √3, √2 + 1, 2 + √3, decided by integer square
//!    root brackets — an enclosure of tan independent of the table. Beyond 89° it is 0, and
//!    for any `u64` δ it does not panic.
//! 5. `start_angle(j, l)` for 1 ≤ l ≤ 999, 0 ≤ j < l: round(360 000·j / l) half up.
//!
//! The table itself is cross-checked by tests below (not under Kani: no symbolic input): each
//! entry against the tangent addition formula from its neighbour, in exact interval arithmetic,
//! chained from 0° to 45° = 1 and on to 89°; and against `f64::tan`.
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 reached no verdict in 600 s (3 M variables, 20.7 M clauses; issue #25): every branch checks a nonlinear specification (r² ≤ n, q·den, δ·tan) of up to 128-bit values. (`depth_step_clamp` keeps a Kani stub of `isqrt` by its specification for a next attempt.) The body runs under `cargo test` (bounded-exhaustive and random
//! drivers); its Kani harness (the scope named `KANI` below) is a proof harness only with the
//! feature `kani-attempts`.
//!
//! **Kani bounds of the attempt.** `isqrt` is core's loop-free staged root; our 256-bit helpers loop at most 4
//! times. `#[kani::unwind(65)]`.

use crate::model::{is_div_round, is_sqrt_round, W256};
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::fixed::{
    div_round, div_round_signed, isqrt, mul_tan, mul_tan_checked, mul_wide, sqrt_round, start_angle,
    tan_half_degrees, TAN_MAX_INDEX,
};
#[cfg(test)]
use cycle_impl::fixed::{tan_tenths, TAN_MAX_TENTHS};
use cycle_impl::MAX_LENGTH;

/// Whether `t` is δ·tan rounded half up for every tangent in the table's enclosure
/// [int + frac/2^128, int + (frac + 1)/2^128): in units of 2^-128, with X = δ·(int·2^128 + frac),
/// t·2^128 − 2^127 ≤ X and X + δ ≤ t·2^128 + 2^127.
fn rounds_enclosure(t: u64, delta: u64, int: u8, frac: u128) -> bool {
    let x_frac = W256::mul(u128::from(delta), frac);
    let x_int = W256::from_u128(u128::from(delta) * u128::from(int)).shift_limbs(2);
    let Some(x) = x_frac.checked_add(x_int) else { return false };
    let half = W256::from_u128(1u128 << 127);
    let t_scaled = W256::from_u128(u128::from(t)).shift_limbs(2);
    let Some(x_plus_half) = x.checked_add(half) else { return false };
    let Some(upper) = x.checked_add(W256::from_u128(u128::from(delta))) else { return false };
    let Some(t_plus_half) = t_scaled.checked_add(half) else { return false };
    // t·2^128 − 2^127 ≤ X  ⇔  t·2^128 ≤ X + 2^127.
    t_scaled <= x_plus_half && upper <= t_plus_half
}

/// The closed-form check of a tangent at the angles where tan is a quadratic surd.
fn closed_form(h: u32, delta: u64, t: u64) -> Option<bool> {
    let d = u128::from(delta);
    let t = u128::from(t);
    let (d2, d3) = (d * d * 2, d * d * 3);
    Some(match h {
        0 => t == 0,
        90 => t == d,
        // tan 30° = 1/√3: t − ½ ≤ δ/√3 < t + ½ ⇔ 3(2t − 1)² ≤ 4δ² < 3(2t + 1)² (t ≥ 1), 4δ² < 3 for t = 0.
        60 => {
            let four = 4 * d * d;
            if t == 0 { four < 3 } else { 3 * (2 * t - 1) * (2 * t - 1) <= four && four < 3 * (2 * t + 1) * (2 * t + 1) }
        }
        // tan 60° = √3.
        120 => is_sqrt_round(t, d3),
        // tan 22.5° = √2 − 1: t + δ = round(δ√2).
        45 => is_sqrt_round(t + d, d2),
        // tan 67.5° = √2 + 1: t − δ = round(δ√2).
        135 => t >= d && is_sqrt_round(t - d, d2),
        // tan 15° = 2 − √3: 2δ − t = round(δ√3) (δ√3 is never a half-integer).
        30 => 2 * d >= t && is_sqrt_round(2 * d - t, d3),
        // tan 75° = 2 + √3: t − 2δ = round(δ√3).
        150 => t >= 2 * d && is_sqrt_round(t - 2 * d, d3),
        _ => return None,
    })
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S) -> Outcome {
    match src.choose(6) {
        0 => {
            let n = src.any_u128();
            let r = isqrt(n);
            let square_ok = r.checked_mul(r).is_some_and(|sq| sq <= n);
            let next_ok = (r + 1).checked_mul(r + 1).is_none_or(|sq| sq > n);
            check!(src, square_ok && next_ok, "isqrt: r² ≤ n < (r + 1)²");
            let rr = sqrt_round(n);
            check!(src, is_sqrt_round(rr, n), "sqrt_round: r − ½ ≤ √n < r + ½");
            cover!(src, n > u128::from(u64::MAX), "isqrt above 2^64");
            cover!(src, rr == r + 1, "sqrt_round rounds up");
        }
        1 => {
            let num = src.any_u128();
            let den = src.any_u128();
            let q = div_round(num, den);
            if den == 0 {
                check!(src, q == 0, "div_round: 0 for a zero divisor");
            } else {
                check!(src, is_div_round(q, num, den), "div_round: q − ½ ≤ num/den < q + ½");
            }
            cover!(src, den != 0 && !num.is_multiple_of(den) && q > num / den, "div_round rounds up");
        }
        2 => {
            let num = src.bounded_i128(i128::MIN, i128::MAX);
            let den = src.bounded_i128(i128::MIN, i128::MAX);
            let q = div_round_signed(num, den);
            if den == 0 {
                check!(src, q == 0, "div_round_signed: 0 for a zero divisor");
            } else {
                let mag = q.unsigned_abs();
                // |num/den| ≤ 2^127; its rounding fits i128 except 2^127 itself (saturated).
                let exact = is_div_round(mag, num.unsigned_abs(), den.unsigned_abs());
                let saturated = q == i128::MAX && is_div_round(1u128 << 127, num.unsigned_abs(), den.unsigned_abs());
                check!(src, exact || saturated, "div_round_signed: magnitude rounded half up");
                let negative = (num < 0) != (den < 0);
                check!(src, q == 0 || (q < 0) == negative, "div_round_signed: sign of num/den");
            }
            cover!(src, q < 0, "a negative quotient");
        }
        3 => {
            let a = src.any_u128();
            let b = src.any_u128();
            let p = mul_wide(a, b);
            check!(src, W256::mul(a, b).halves() == (p.hi, p.lo), "mul_wide: the exact 256-bit product");
        }
        4 => {
            let h = src.every_u32(0, TAN_MAX_INDEX + 4);
            if h > TAN_MAX_INDEX {
                let delta = src.bounded_u64(0, u64::MAX);
                check!(src, mul_tan_checked(delta, h).is_none() && mul_tan(delta, h) == 0, "mul_tan: 0 beyond 89°");
                return Ok(());
            }
            if src.choose(4) == 0 {
                // Any u64: no panic; saturates where the product does not fit.
                let delta = src.bounded_u64(0, u64::MAX);
                let t = mul_tan(delta, h);
                check!(src, t >= delta || h < 90, "mul_tan: at least δ from 45° on");
                return Ok(());
            }
            let delta = src.bounded_u64(0, MAX_LENGTH as u64);
            let Some((int, frac)) = tan_half_degrees(h) else {
                check!(src, false, "tan table: an entry for every index ≤ 178");
                return Ok(());
            };
            let checked = mul_tan_checked(delta, h);
            check!(src, checked.is_some_and(|(_, decided)| decided), "mul_tan: the table decides the rounding for δ ≤ N");
            let t = mul_tan(delta, h);
            check!(src, checked.is_some_and(|(v, _)| v == t), "mul_tan agrees with mul_tan_checked");
            check!(src, rounds_enclosure(t, delta, int, frac), "mul_tan: δ·tan rounded half up over the table's enclosure");
            if let Some(ok) = closed_form(h, delta, t) {
                check!(src, ok, "mul_tan: exact at 0°, 45° and the closed forms 15°, 22.5°, 30°, 60°, 67.5°, 75°");
            }
            if delta < MAX_LENGTH as u64 {
                let t1 = mul_tan(delta + 1, h);
                check!(src, t1 >= t, "mul_tan: monotone in δ");
                check!(src, t1.saturating_sub(t) <= u64::from(int) + 2, "mul_tan: one more δ adds at most ⌈tan⌉ + 1");
            }
            if h < TAN_MAX_INDEX {
                check!(src, mul_tan(delta, h + 1) >= t, "mul_tan: monotone in the angle");
            }
            cover!(src, closed_form(h, delta, t).is_some() && delta > 1, "a closed-form angle");
            cover!(src, h > 90 && delta > 0, "an angle above 45°");
        }
        _ => {
            let l = src.bounded_u32(1, 999);
            let j = src.bounded_u32(0, l - 1);
            let v = start_angle(j, l);
            check!(src, is_div_round(u128::from(v), 360_000 * u128::from(j), u128::from(l)), "start_angle: round(360000·j / l) half up");
            check!(src, v < 360_000, "start_angle below 360°");
        }
    }
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = no_overflow_isqrt_tan in crate::PROPERTIES {
        rules: ["COM.RANGES", "COM.UNITS", "G76.INFEED.Z", "G76.PULLOUT", "COM.MULTISTART"],
        states: "The fixed-point helpers meet their specifications with no panic: isqrt and sqrt_round brackets, half-up quotients, the exact 256-bit product, δ·tan rounded over the table's enclosure, the start angle.",
        body: |src, _scope| body(src),
        /// The Kani attempt (a TEST: no verdict in 600 s; a harness only with `kani-attempts`).
        kani: test(()) { unwind: 65, why: "no verdict in 600 s (3 M variables, 20.7 M clauses)" },
        tests {
            fn no_overflow_isqrt_tan_exhaustive = exhaustive(5, 2_000_000) on ();
            fn no_overflow_isqrt_tan_random = random(0x5eed_0003, 1) on ();
        }
    }
}

#[cfg(test)]
mod tests;
