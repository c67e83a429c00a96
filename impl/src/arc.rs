//! Arcs G02/G03 (ARC.*; docs/INTERPRETATION.md, "Arcs (G02, G03)"): the centre from I/K
//! (ARC.IK) or from R (ARC.R, the exact centre rounded once), the end-point tolerance (ARC.TOL),
//! the sweep tests the stock-removal cycles need (G71.MONOTONE), and the exact roundings of
//! values of the form (w + σ·√Q) / q that the centre and the layer ends are made of.
//!
//! **Units.** Geometry is done in half increments, u = X (a diameter count is a radius in half
//! increments) and v = 2·Z, where distances are Euclidean and every programmed point is an
//! integer. Results are rounded once, half away from zero: X on the diameter count, Z on the Z
//! count.
//!
//! **Bounds.** Words are |v| ≤ N = 999 999 999 increments (COM.RANGES); R ≤ N, |I|, |K| ≤ N.
//! Positions are `i64` (see `lib.rs`: every coordinate a program reaches stays below 2^62 in
//! magnitude). Every difference of two positions is formed in `i128`, and each test below first
//! screens its inputs so that the products it forms are bounded as its comments say.

use crate::fixed::{isqrt, mul_wide, sat};
use cycle_vocab::{Alarm, AlarmCode, Move, Rule};

/// A point in half-increment units (u, v) = (X, 2·Z), as `i128` so that differences of any two
/// `i64` positions are exact.
fn half(p: (i64, i64)) -> (i128, i128) {
    (i128::from(p.0), 2 * i128::from(p.1))
}

/// round((w + φ) / q) half away from zero, for an integer `w`, an **even** q ≥ 2 (or any q ≥ 1
/// when φ = 0) and an unknown φ with 0 ≤ φ < 1, φ > 0 exactly when `inexact`. Decided in
/// integers: with w = q·a + b (0 ≤ b < q) the fraction is (b + φ)/q, compared with ½ — for an
/// even q, b + φ against the integer q/2 is decided by b and whether φ = 0.
pub fn round_frac(w: i128, q: i128, inexact: bool) -> i128 {
    let a = w.div_euclid(q);
    let b = w.rem_euclid(q);
    // 2(b + φ) against q: b and q are integers and 0 ≤ φ < 1.
    let twice = 2 * b;
    if twice > q || (twice == q && inexact) {
        a + 1
    } else if twice == q {
        // Exactly a + ½: away from zero.
        if a >= 0 {
            a + 1
        } else {
            a
        }
    } else {
        a
    }
}

/// round((w + σ·T) / q) half away from zero, where T ≥ 0 has ⌊T⌋ = `k` and is an integer exactly
/// when `exact` (σ = +1 when `plus`, else −1).
pub fn round_root_sum(w: i128, plus: bool, k: i128, exact: bool, q: i128) -> i128 {
    if plus || exact {
        let s = if plus { w + k } else { w - k };
        round_frac(s, q, !exact)
    } else {
        // w − (k + f) with 0 < f < 1 is (w − k − 1) + (1 − f), 0 < 1 − f < 1.
        round_frac(w - k - 1, q, true)
    }
}

/// round((w + σ·√m) / q) half away from zero, q = 1, 2 or 4: one integer square root. For
/// q = 1 there is no tie (√m is an integer or irrational): w + σ·round(√m).
pub fn round_sqrt_sum(w: i128, plus: bool, m: u128, q: i128) -> i128 {
    if q == 1 {
        let r = i128::try_from(crate::fixed::sqrt_round(m)).unwrap_or(i128::MAX);
        return if plus { w + r } else { w - r };
    }
    let k = isqrt(m);
    // k ≤ 2^64: k² ≤ m fits u128 and k fits i128.
    let exact = k * k == m;
    round_root_sum(w, plus, i128::try_from(k).unwrap_or(i128::MAX), exact, q)
}

/// ARC.R: the centre of the arc from `s` to `e` with radius `r` (increments, 1 … N) on the side
/// the direction names — right of the travel for G02 (`cw`), left for G03, viewed with +Z to the
/// right and +X up — rounded once (X on the diameter count, Z on the Z count); `None` when the
/// chord is longer than the diameter (GEOMETRY on R).
///
/// In half units, with d = E − S = (du, dv), chord c = |d|, R_h = 2r: the exact centre is the
/// chord's midpoint moved by t·(a_v, a_u), t = √((4R_h² − c²) / (4c²)), (a_v, a_u) = (du, −dv)
/// for G02 and (−du, dv) for G03. So X = (su + eu + σ_u·T_u) / 2 and Z = (sv + ev + σ_v·T_v) / 4
/// with T² = a²·(4R_h² − c²) / c² for a = |a_u|, |a_v|: each rounding is decided from ⌊T⌋ and
/// whether T is an integer, both from one integer square root of ⌊a²·(4R_h² − c²) / c²⌋.
///
/// Bounds: after the screen |du|, |dv| ≤ 2R_h ≤ 4·10^9 < 2^32, so c² < 2^65; and
/// a²·(4R_h² − c²) ≤ c²·(4R_h² − c²) ≤ 4R_h⁴ = 64 r⁴ ≤ 6.4·10^37 < 2^126: every product fits
/// `u128`, exactly, for every legal R.
pub fn centre_r(s: (i64, i64), e: (i64, i64), r: i64, cw: bool) -> Option<(i64, i64)> {
    let (su, sv) = half(s);
    let (eu, ev) = half(e);
    let (du, dv) = (eu - su, ev - sv);
    let rh = 2 * i128::from(r.max(0));
    // Screen: a component longer than the diameter 2R_h makes the chord longer too.
    if du.abs() > 2 * rh || dv.abs() > 2 * rh {
        return None;
    }
    let (du2, dv2) = (du.unsigned_abs().pow(2), dv.unsigned_abs().pow(2));
    let c2 = du2 + dv2;
    let four_rh2 = 4 * rh.unsigned_abs().pow(2);
    if c2 > four_rh2 || c2 == 0 {
        return None;
    }
    let h = four_rh2 - c2;
    let (a_v, a_u) = if cw { (du, -dv) } else { (-du, dv) };
    // ⌊T⌋ and whether T is an integer, T² = a²·h / c².
    let root = |a: i128| -> (i128, bool) {
        let n = a.unsigned_abs().pow(2).saturating_mul(h);
        let k = isqrt(n / c2);
        (i128::try_from(k).unwrap_or(i128::MAX), k * k * c2 == n)
    };
    let (ku, exact_u) = root(a_u);
    let (kv, exact_v) = root(a_v);
    let x = round_root_sum(su + eu, a_u >= 0, ku, exact_u, 2);
    let z = round_root_sum(sv + ev, a_v >= 0, kv, exact_v, 4);
    Some((sat(x), sat(z)))
}

/// ARC.IK: the centre (S.x + 2I, S.z + K), exact; I is a radius.
pub fn centre_ik(s: (i64, i64), i: i64, k: i64) -> (i64, i64) {
    (s.0.saturating_add(i.saturating_mul(2)), s.1.saturating_add(k))
}

/// ARC.TOL: whether `e` lies within `tol` (radius increments) of the circle through `s` about
/// `c`: | |E − C| − |S − C| | ≤ tol, decided exactly on squares in half units (τ = 2·tol).
///
/// Bounds: |S − C|² = A < 2^64 for every centre the engines make (I/K: 4I² + 4K² ≤ 8·10^18;
/// R: about (2r)²). E is screened: a component beyond √A + 1 + τ fails at once, so after it
/// B = |E − C|² < 2^68, the differences B − A − τ² below are < 2^68 and their squares < 2^136
/// are compared as 256-bit products.
pub fn within_tolerance(s: (i64, i64), e: (i64, i64), c: (i64, i64), tol: i64) -> bool {
    let (su, sv) = half(s);
    let (eu, ev) = half(e);
    let (cu, cv) = half(c);
    let a = (su - cu).unsigned_abs().saturating_pow(2).saturating_add((sv - cv).unsigned_abs().saturating_pow(2));
    let tau = 2 * u128::from(tol.unsigned_abs());
    let lim = isqrt(a) + 1 + tau;
    let (du, dv) = ((eu - cu).unsigned_abs(), (ev - cv).unsigned_abs());
    if du > lim || dv > lim {
        return false;
    }
    let b = du * du + dv * dv;
    // √y ≤ √x + τ  ⇔  y − x − τ² ≤ 2τ√x  ⇔  y − x − τ² ≤ 0, or (y − x − τ²)² ≤ 4τ²·x.
    let not_beyond = |x: u128, y: u128| -> bool {
        let Some(d) = y.checked_sub(x).and_then(|d| d.checked_sub(tau * tau)).filter(|&d| d > 0) else {
            return true;
        };
        mul_wide(d, d) <= mul_wide(4 * tau * tau, x)
    };
    not_beyond(a, b) && not_beyond(b, a)
}

/// The words of an arc block: R, or I and K (each 0 when omitted).
#[derive(Clone, Copy, Debug)]
pub enum Centre {
    R(i64),
    Ik(i64, i64),
}

/// ARC.TOL: whether `e` lies on the ray from `c` through `s` (E = S included) — the arc would
/// close the full circle. Only after [`within_tolerance`] passed: its screen bounds E − C, so
/// every component below is < 2^35 in half units and the products < 2^71.
fn on_start_ray(s: (i64, i64), e: (i64, i64), c: (i64, i64)) -> bool {
    let (su, sv) = half(s);
    let (eu, ev) = half(e);
    let (cu, cv) = half(c);
    same((sv - cv, su - cu), (ev - cv, eu - cu))
}

/// ARC.* step 5 of an arc block from `s` to `e`, in the register's order — E = S (GEOMETRY on X,
/// ARC.TOL), the centre (ARC.IK: centre = start, GEOMETRY on I; ARC.R: chord > 2R, GEOMETRY on
/// R), the tolerance (GEOMETRY on X, ARC.TOL: off the circle by more than `tol`, or on the ray
/// from the centre through S even within it — "would close the full circle") — then the centre
/// and the rule it was found by.
pub fn centre(s: (i64, i64), e: (i64, i64), cw: bool, words: Centre, tol: i64, line: u32) -> Result<((i64, i64), Rule), Alarm> {
    let geometry = |word: u8, rule: Rule| Alarm::new(AlarmCode::Geometry, Some(word), rule, line);
    if e == s {
        return Err(geometry(b'X', Rule::ArcTol));
    }
    let (c, rule) = match words {
        Centre::Ik(i, k) => {
            if i == 0 && k == 0 {
                return Err(geometry(b'I', Rule::ArcIk));
            }
            (centre_ik(s, i, k), Rule::ArcIk)
        }
        Centre::R(r) => (centre_r(s, e, r, cw).ok_or(geometry(b'R', Rule::ArcR))?, Rule::ArcR),
    };
    if !within_tolerance(s, e, c, tol) || on_start_ray(s, e, c) {
        return Err(geometry(b'X', Rule::ArcTol));
    }
    Ok((c, rule))
}

/// The arc move of a G02/G03 block (ARC.*): checked as [`centre`], then one arc event to `e`
/// about the centre at `feed`, tagged ARC.R or ARC.IK.
pub fn arc_move(s: (i64, i64), e: (i64, i64), cw: bool, words: Centre, feed: i64, tol: i64, line: u32) -> Result<Move, Alarm> {
    let ((cx, cz), rule) = centre(s, e, cw, words, tol, line)?;
    Ok(Move::arc(cw, e.0, e.1, cx, cz, feed, rule))
}

/// 2-D vector in the plane with v (Z) to the right and u (X) up, half units.
type V2 = (i128, i128);

fn cross(p: V2, q: V2) -> i128 {
    p.0 * q.1 - p.1 * q.0
}

fn dot(p: V2, q: V2) -> i128 {
    p.0 * q.0 + p.1 * q.1
}

/// Whether `d` points the same way as `p` (parallel, not opposite).
fn same(p: V2, d: V2) -> bool {
    cross(p, d) == 0 && dot(p, d) > 0
}

/// Whether the direction `d` lies strictly inside the counter-clockwise sweep from `a` to `b`.
/// `b` of no direction (E at the centre) or along `a` (E on the start's ray) is the full circle:
/// the arc runs from S back to S (docs/INTERPRETATION.md reads E = S as a full circle).
fn inside_ccw(a: V2, b: V2, d: V2) -> bool {
    let ab = cross(a, b);
    if b == (0, 0) || (ab == 0 && dot(a, b) > 0) {
        return !same(a, d);
    }
    if ab > 0 {
        cross(a, d) > 0 && cross(d, b) > 0
    } else if ab == 0 {
        // A half turn.
        cross(a, d) > 0
    } else {
        // More than a half turn: inside unless d is in the closed short sweep from b to a.
        let in_rest = (cross(b, d) > 0 && cross(d, a) > 0) || same(b, d) || same(a, d);
        !in_rest
    }
}

/// G71.MONOTONE, G72.MONOTONE: whether the arc from `s` to (the ray through) `e` about `c`, in
/// its direction, has a point of extreme X (its circle's top or bottom) and one of extreme Z
/// (its left or right end) strictly inside its sweep: (X turns, Z turns).
///
/// Bounds: for an arc that passed ARC.TOL every component of S − C and E − C is below 2^34 in
/// half units, so the cross products are below 2^69.
pub fn turns(s: (i64, i64), e: (i64, i64), c: (i64, i64), cw: bool) -> (bool, bool) {
    let (su, sv) = half(s);
    let (eu, ev) = half(e);
    let (cu, cv) = half(c);
    let (a, b) = ((sv - cv, su - cu), (ev - cv, eu - cu));
    // Clockwise from a to b is the same open sweep as counter-clockwise from b to a.
    let (from, to) = if cw { (b, a) } else { (a, b) };
    let any = |ds: [V2; 2]| ds.iter().any(|&d| inside_ccw(from, to, d));
    (any([(0, 1), (0, -1)]), any([(1, 0), (-1, 0)]))
}

#[cfg(test)]
mod tests;
