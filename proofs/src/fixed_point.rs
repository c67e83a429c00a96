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
//! drivers); the scope named `KANI` below is what a Kani run would take, kept for the drivers.
//!
//! **Former Kani bounds.** `isqrt` is core's loop-free staged root; our 256-bit helpers loop at most 4
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


#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::{exhaustive, random, random_cases};

    #[test]
    fn no_overflow_isqrt_tan_exhaustive() {
        // Every branch; numbers take their 5 smallest and 5 largest values (u128 as two halves),
        // angles all 183 indices.
        let r = exhaustive(5, 2_000_000, body).assert_ok();
        println!("{r}");
    }

    #[test]
    fn no_overflow_isqrt_tan_random() {
        let r = random(0x5eed_0003, random_cases(1), body).assert_ok();
        println!("{r}");
    }

    /// Small δ at every angle against `f64::tan` (a coarse cross-check, test only): the exact
    /// δ·tan lies within 10^-9 of the f64 value here, so a correct rounding is within ½ + 10^-9.
    #[test]
    fn tangent_matches_f64_for_small_delta() {
        for h in 0..=TAN_MAX_INDEX {
            let tan = (f64::from(h) * 0.5).to_radians().tan();
            for delta in (0..2000u64).chain([10_000, 123_457, 1_000_000]) {
                let t = mul_tan(delta, h) as f64;
                let exact = delta as f64 * tan;
                assert!((t - exact).abs() <= 0.5 + 1e-6, "h {h} δ {delta}: {t} vs {exact}");
            }
        }
    }

    /// An unsigned big integer, base 2^64, least significant limb first (test only).
    #[derive(Clone, Debug, PartialEq, Eq)]
    struct Big(Vec<u64>);

    impl Big {
        fn from_u128(v: u128) -> Big {
            Big(vec![v as u64, (v >> 64) as u64]).trim()
        }
        fn trim(mut self) -> Big {
            while self.0.len() > 1 && self.0.last() == Some(&0) {
                self.0.pop();
            }
            self
        }
        fn mul(&self, o: &Big) -> Big {
            let mut out = vec![0u64; self.0.len() + o.0.len()];
            for (i, &a) in self.0.iter().enumerate() {
                let mut carry = 0u128;
                for (j, &b) in o.0.iter().enumerate() {
                    let cur = u128::from(out[i + j]) + u128::from(a) * u128::from(b) + carry;
                    out[i + j] = cur as u64;
                    carry = cur >> 64;
                }
                out[i + o.0.len()] = carry as u64;
            }
            Big(out).trim()
        }
        fn add(&self, o: &Big) -> Big {
            let n = self.0.len().max(o.0.len()) + 1;
            let mut out = vec![0u64; n];
            let mut carry = 0u128;
            for (i, slot) in out.iter_mut().enumerate() {
                let cur = u128::from(*self.0.get(i).unwrap_or(&0)) + u128::from(*o.0.get(i).unwrap_or(&0)) + carry;
                *slot = cur as u64;
                carry = cur >> 64;
            }
            Big(out).trim()
        }
        /// self − o, requires self ≥ o.
        fn sub(&self, o: &Big) -> Big {
            assert!(self >= o);
            let mut out = self.0.clone();
            let mut borrow = 0i128;
            for (i, slot) in out.iter_mut().enumerate() {
                let cur = i128::from(*slot) - i128::from(*o.0.get(i).unwrap_or(&0)) - borrow;
                borrow = i128::from(cur < 0);
                *slot = cur.rem_euclid(1i128 << 64) as u64;
            }
            Big(out).trim()
        }
        fn pow2(bits: usize) -> Big {
            let mut v = vec![0u64; bits / 64 + 1];
            v[bits / 64] = 1 << (bits % 64);
            Big(v)
        }
    }

    impl PartialOrd for Big {
        fn partial_cmp(&self, o: &Big) -> Option<std::cmp::Ordering> {
            Some(self.cmp(o))
        }
    }

    impl Ord for Big {
        fn cmp(&self, o: &Big) -> std::cmp::Ordering {
            self.0.len().cmp(&o.0.len()).then_with(|| self.0.iter().rev().cmp(o.0.iter().rev()))
        }
    }

    /// The table entry as A = ⌊tan·2^128⌋; the true tangent lies in [A, A + 1)·2^-128 (exactly A
    /// at 0° and 45°).
    fn entry(h: u32) -> Big {
        let (int, frac) = tan_half_degrees(h).unwrap();
        Big::from_u128(u128::from(int)).mul(&Big::pow2(128)).add(&Big::from_u128(frac))
    }

    /// Each entry against its neighbour by tan(x + y)·(1 − tan x·tan y) = tan x + tan y with
    /// y = 0.5°, in exact interval arithmetic on the table's enclosures (scaled by 2^384):
    /// C·(2^256 − (A+1)(B+1)) ≤ (A + B + 2)·2^256 and (A + B)·2^256 ≤ (C + 1)·(2^256 − A·B).
    /// Chained from tan 0 = 0 through tan 45° = 1 (exact) to 89°: an entry off by more than a
    /// few units of 2^-128 (a few thousand near 89°, where the intervals widen with tan², still
    /// below 2^-116) breaks the chain; tan 0.5° itself is pinned by landing on 1 at 45°.
    #[test]
    fn tangent_table_satisfies_the_addition_formula() {
        assert_addition_chain(entry, TAN_MAX_INDEX, 90, 2.0);
    }

    /// The chain of the addition formula over a table whose entry `i` is tan(i / `per_degree`
    /// degrees) as ⌊tan·2^128⌋ (exact at 0 and at `exact45`, the index of 45°), each entry
    /// against the one before with y = one step (see the test above).
    fn assert_addition_chain(entry: impl Fn(u32) -> Big, max: u32, exact45: u32, per_degree: f64) {
        let one = Big::pow2(256);
        let b = entry(1);
        let b1 = b.add(&Big::from_u128(1));
        let exact = |i: u32| i == 0 || i == exact45;
        for i in 1..=max {
            let a = entry(i - 1);
            let c = entry(i);
            let a_hi = if exact(i - 1) { a.clone() } else { a.add(&Big::from_u128(1)) };
            let c_hi = if exact(i) { c.clone() } else { c.add(&Big::from_u128(1)) };
            let ab_lo = a.mul(&b);
            let ab_hi = a_hi.mul(&b1);
            assert!(ab_hi < one, "tan x·tan y < 1 below 90°");
            // LHS interval [c·(1 − ab_hi), c_hi·(1 − ab_lo)], RHS [(a + b), (a_hi + b1)], scaled.
            let lhs_lo = c.mul(&one.sub(&ab_hi));
            let lhs_hi = c_hi.mul(&one.sub(&ab_lo));
            let rhs_lo = a.add(&b).mul(&one);
            let rhs_hi = a_hi.add(&b1).mul(&one);
            let deg = |i: u32| f64::from(i) / per_degree;
            assert!(lhs_lo <= rhs_hi && rhs_lo <= lhs_hi, "tan({}°) inconsistent with tan({}°)", deg(i), deg(i - 1));
        }
    }

    /// The table on the 0.1° grid (G162.A), by the same addition formula with y = 0.1°: each
    /// tenth against the one before, chained from tan 0 = 0 through tan 45° = 1 (exact) to 89°
    /// (tan 0.1° is pinned by landing on 1 at 45°); and every tenth against `f64::tan` for
    /// small δ (a coarse, independent cross-check).
    #[test]
    fn tenths_table_satisfies_the_addition_formula() {
        let entry_t = |t: u32| {
            let (int, frac) = tan_tenths(t).unwrap();
            Big::from_u128(u128::from(int)).mul(&Big::pow2(128)).add(&Big::from_u128(frac))
        };
        assert_addition_chain(entry_t, TAN_MAX_TENTHS, 450, 10.0);
        for t in 0..=TAN_MAX_TENTHS {
            let tan = (f64::from(t) * 0.1).to_radians().tan();
            for delta in (0..200u64).chain([10_000, 123_457]) {
                let v = cycle_impl::fixed::mul_tan_tenths(delta, t) as f64;
                assert!((v - delta as f64 * tan).abs() <= 0.5 + 1e-6, "t {t} δ {delta}");
            }
        }
    }

    /// The check above rejects an entry moved by 8 units of 2^-128 (at 30.5°).
    #[test]
    fn addition_formula_check_is_sharp() {
        let one = Big::pow2(256);
        let b = entry(1);
        let b1 = b.add(&Big::from_u128(1));
        let h = 61u32;
        let a = entry(h - 1);
        let consistent = |c: &Big| {
            let (a_hi, c_hi) = (a.add(&Big::from_u128(1)), c.add(&Big::from_u128(1)));
            let lhs_lo = c.mul(&one.sub(&a_hi.mul(&b1)));
            let lhs_hi = c_hi.mul(&one.sub(&a.mul(&b)));
            let rhs_lo = a.add(&b).mul(&one);
            let rhs_hi = a_hi.add(&b1).mul(&one);
            lhs_lo <= rhs_hi && rhs_lo <= lhs_hi
        };
        assert!(consistent(&entry(h)));
        assert!(!consistent(&entry(h).add(&Big::from_u128(8))));
        assert!(!consistent(&entry(h).sub(&Big::from_u128(8))));
    }
}
