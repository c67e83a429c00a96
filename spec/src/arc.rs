//! ARC.* — circular arcs G02, G03 (M003), under `gsk` and `fanuc`.
//!
//! G02 and G03 are motion modes like G00/G01 (docs/INTERPRETATION.md, "Arcs"). An arc runs from
//! its start S about its centre C, on the circle through S, clockwise (G02) or counter-clockwise
//! (G03) viewed with +Z to the right and +X (radius) up (ARC.DIR), to the point of that circle on
//! the ray from C through the programmed end E; the trace carries E itself.
//!
//! All geometry is decided exactly in **half-increment units**: u = X (a diameter count is a
//! radius in half increments) and v = 2·Z. Distances are Euclidean there and every programmed
//! point is an integer point. Products of legal words exceed i128, so they are big integers.

use crate::exact::round_root;
use crate::family::{State, Values};
use crate::lex::Number;
use crate::words::{alarm, count, in_range, Read, F, N, U, W, X, Z};
use cycle_vocab::{Alarm, AlarmCode, Config, Rule};
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive, Zero};

/// A point in increments: X as a diameter count, Z.
pub type Point = (i128, i128);

/// ARC.R (M003): R, a radius length 1 … N. "R ≤ 0 is `OUT OF RANGE` on R, rule ARC.R"; a value
/// beyond N is out of the generic length range (COM.RANGES), like every length word.
fn read_r(n: &Number, letter: u8, config: &Config, line: u32) -> Result<i64, Alarm> {
    let v = count(n, config.grid.decimals(), letter, line)?;
    if !v.is_positive() {
        return Err(alarm(AlarmCode::OutOfRange, letter, Rule::ArcR, line));
    }
    in_range(&v, 1, N, letter, Rule::ComRanges, line)
}

/// ARC.FORMAT (M003): `G02/G03 X(U) Z(W) R F` or `… I K F`. I (a radius) and K are signed
/// lengths, |v| ≤ N; F is the modal feed (no lead: F with I is legal here).
pub const R: (u8, Read) = (b'R', Read::Own(read_r));
pub const I: (u8, Read) = (b'I', Read::Length { lo: -N, hi: N });
pub const K: (u8, Read) = (b'K', Read::Length { lo: -N, hi: N });
pub const WORDS: crate::family::Words = crate::family::Words::of(&[F, I, K, R, U, W, X, Z]);

/// How an arc block gives its centre.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum By {
    /// ARC.R: the radius, increments.
    R(i64),
    /// ARC.IK: I (radius) and K from the start, increments; an omitted one is 0.
    Ik(i64, i64),
}

/// ARC.FORMAT (M003): R, else I and/or K ("I alone or K alone is legal (the other is 0)");
/// `None` when the block writes none of them (`MISSING WORD R`).
pub fn by(v: &Values) -> Option<By> {
    match (v.get(b'R'), v.get(b'I'), v.get(b'K')) {
        (Some(r), _, _) => Some(By::R(r)),
        (None, None, None) => None,
        (None, i, k) => Some(By::Ik(i.unwrap_or(0), k.unwrap_or(0))),
    }
}

/// An arc whose checks passed: its direction, its centre (on the grid), and the rule that gave
/// the centre (the trace's rule tag of an arc block).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Arc {
    pub cw: bool,
    pub centre: Point,
    pub rule: Rule,
}

/// ARC.* check step 5 of an arc from `s` to `e`, in the register's order: "E = S; the centre
/// (ARC.IK, ARC.R); the tolerance".
pub fn decide(s: Point, e: Point, cw: bool, by: By, tolerance: i64, line: u32) -> Result<Arc, Alarm> {
    full_circle(s, e, line)?;
    let (centre, rule) = match by {
        By::Ik(i, k) => (centre_ik(s, i, k, line)?, Rule::ArcIk),
        By::R(r) => (centre_r(s, e, r, cw, line)?, Rule::ArcR),
    };
    on_circle(s, e, centre, tolerance, line)?;
    Ok(Arc { cw, centre, rule })
}

/// ARC.TOL (PRJ): "E = S (a full circle) is `GEOMETRY` on X".
pub fn full_circle(s: Point, e: Point, line: u32) -> Result<(), Alarm> {
    if s == e {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::ArcTol, line));
    }
    Ok(())
}

/// ARC.IK (M003): "the centre is (S.x + 2I, S.z + K), exactly"; "a centre equal to the start is
/// `GEOMETRY` on I".
pub fn centre_ik(s: Point, i: i64, k: i64, line: u32) -> Result<Point, Alarm> {
    if i == 0 && k == 0 {
        return Err(alarm(AlarmCode::Geometry, b'I', Rule::ArcIk, line));
    }
    Ok((s.0 + 2 * i128::from(i), s.1 + i128::from(k)))
}

/// A vector in half-increment units, (du, dv), from `a` to `b`.
pub fn half_vector(a: Point, b: Point) -> (BigInt, BigInt) {
    (BigInt::from(b.0 - a.0), BigInt::from(b.1 - a.1) * BigInt::from(2))
}

/// The squared length of a half-unit vector.
pub fn norm2(d: &(BigInt, BigInt)) -> BigInt {
    &d.0 * &d.0 + &d.1 * &d.1
}

/// ARC.R (M003, OPEN): "R gives the arc of at most 180° whose centre lies on the side of the
/// chord S→E that the direction names: to the right of the travel for G02, to the left for
/// G03"; "the exact centre is the chord's midpoint moved by √(R² − c²/4) along the chord's
/// normal on that side; c > 2R is `GEOMETRY` on R; c = 2R is the half circle about the
/// midpoint", "rounded once to the grid (X on the diameter count, Z on the Z count)".
///
/// In half units, with the chord (du, dv), c² = du² + dv², R_h = 2R and A = 4R_h² − c²: the
/// normal of length c is n = (−dv, du) to the right (G02) and (dv, −du) to the left (G03), in
/// (u, v); the offset along it is √A / (2c), so
/// `C_u = ((u_s + u_e)·c² + n_u·√(A·c²)) / (2c²)` and `C_z = ((v_s + v_e)·c² + n_v·√(A·c²)) / (4c²)`,
/// each one root of an integer, rounded once by [`round_root`].
pub fn centre_r(s: Point, e: Point, r: i64, cw: bool, line: u32) -> Result<Point, Alarm> {
    let chord = half_vector(s, e);
    let c2 = norm2(&chord);
    let r_half = BigInt::from(r) * BigInt::from(2);
    let a: BigInt = &r_half * &r_half * BigInt::from(4) - &c2;
    if a.is_negative() {
        return Err(alarm(AlarmCode::Geometry, b'R', Rule::ArcR, line));
    }
    let (du, dv) = chord;
    let (nu, nv) = if cw { (-dv, du) } else { (dv, -du) };
    let ac2 = (&a * &c2).magnitude().clone();
    let coordinate = |sum: BigInt, n: &BigInt, den: BigInt| {
        let m = &ac2 * (n * n).magnitude();
        let sigma = if n.is_zero() { 0 } else if n.is_positive() { 1 } else { -1 };
        round_root(&(sum * &c2), sigma, &m, &den)
    };
    let cx = coordinate(BigInt::from(s.0 + e.0), &nu, &c2 * BigInt::from(2));
    let cz = coordinate(BigInt::from(s.1 + e.1) * BigInt::from(2), &nv, &c2 * BigInt::from(4));
    match (cx.to_i128(), cz.to_i128()) {
        (Some(x), Some(z)) => Ok((x, z)),
        _ => Err(alarm(AlarmCode::OutOfRange, b'R', Rule::ComRanges, line)),
    }
}

/// ARC.TOL (PRJ, OPEN): "E must lie within `arc_tolerance` … of that circle:
/// | |E − C| − |S − C| | ≤ tolerance, decided exactly (compare squares; X as a radius), else
/// `GEOMETRY` on X". An end on the ray from C through S other than S itself would close the
/// circle as E = S does: the same alarm.
pub fn on_circle(s: Point, e: Point, c: Point, tolerance: i64, line: u32) -> Result<(), Alarm> {
    let (a, b) = (half_vector(c, s), half_vector(c, e));
    let closes = cross(&a, &b).is_zero() && dot(&a, &b).is_positive();
    // In half units the tolerance (radius increments) counts twice.
    if closes || !within(&norm2(&a), &norm2(&b), &(BigInt::from(tolerance) * BigInt::from(2))) {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::ArcTol, line));
    }
    Ok(())
}

/// |√p − √q| ≤ t for integers p, q, t ≥ 0, exactly: with p ≥ q, √p ≤ √q + t ⇔
/// p − q − t² ≤ 2t√q ⇔ (the left side ≤ 0, or its square ≤ 4t²q).
pub fn within(p: &BigInt, q: &BigInt, t: &BigInt) -> bool {
    let (p, q) = if p >= q { (p, q) } else { (q, p) };
    let lhs = p - q - t * t;
    !lhs.is_positive() || &lhs * &lhs <= t * t * q * BigInt::from(4)
}

/// The cross product of half-unit vectors in the view of ARC.DIR (v to the right, u up):
/// positive when `b` lies counter-clockwise of `a`, within half a turn.
pub fn cross(a: &(BigInt, BigInt), b: &(BigInt, BigInt)) -> BigInt {
    &a.1 * &b.0 - &a.0 * &b.1
}

fn dot(a: &(BigInt, BigInt), b: &(BigInt, BigInt)) -> BigInt {
    &a.0 * &b.0 + &a.1 * &b.1
}

/// Whether the direction `q` (from the centre) lies strictly inside the sweep of an arc that
/// starts in direction `a` and ends in direction `b`, turning counter-clockwise (`cw` false) or
/// clockwise. Exact sign tests; a sweep whose end lies on its start's ray is the full circle.
pub fn sweep_contains(a: &(BigInt, BigInt), b: &(BigInt, BigInt), cw: bool, q: &(BigInt, BigInt)) -> bool {
    // A clockwise sweep from a to b covers the points of the counter-clockwise one from b to a.
    let (a, b) = if cw { (b, a) } else { (a, b) };
    let ab = cross(a, b);
    if ab.is_zero() && dot(a, b).is_positive() {
        return !(cross(a, q).is_zero() && dot(a, q).is_positive());
    }
    if ab.is_positive() {
        return cross(a, q).is_positive() && cross(q, b).is_positive();
    }
    if ab.is_zero() {
        // Half a turn: the points strictly on the counter-clockwise side of a.
        return cross(a, q).is_positive();
    }
    // More than half a turn: inside unless in the closed remainder from b to a (< half a turn).
    !(!cross(b, q).is_negative() && !cross(q, a).is_negative())
}

/// The quadrant points of an arc's circle (ARC, G71.MONOTONE): whether a point of extreme X
/// (the directions ±u from the centre) and whether a point of extreme Z (±v) lies strictly
/// inside the sweep from `s` to the ray through `e`, about `c`.
pub fn turns(s: Point, e: Point, c: Point, cw: bool) -> (bool, bool) {
    let (a, b) = (half_vector(c, s), half_vector(c, e));
    let dir = |u: i32, v: i32| (BigInt::from(u), BigInt::from(v));
    let inside = |q: (BigInt, BigInt)| sweep_contains(&a, &b, cw, &q);
    let x = inside(dir(1, 0)) || inside(dir(-1, 0));
    let z = inside(dir(0, 1)) || inside(dir(0, -1));
    (x, z)
}

/// ARC.FORMAT, ARC.DIR, ARC.* (M003): one G02 (`cw`) or G03 block of the shared interpreter.
/// F sets the modal feed. A block without axis words moves nothing; with them: no feed is
/// `MISSING WORD F` (COM.LEAD), then neither R nor I nor K is `MISSING WORD R` (ARC.FORMAT);
/// then check step 5 ([`decide`]) and one arc event to E, tagged ARC.R or ARC.IK.
pub fn block(st: &mut State, v: &Values, cw: bool, moving: bool, line: u32) -> Result<(), Alarm> {
    st.take_feed(v);
    if !moving {
        return Ok(());
    }
    let Some(feed) = st.feed else {
        return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
    };
    let Some(by) = by(v) else {
        return Err(alarm(AlarmCode::MissingWord, b'R', Rule::ArcFormat, line));
    };
    st.missing_words_checked()?;
    let s = st.position();
    let (x, z) = st.end_point(v);
    let e = (x.unwrap_or(s.0), z.unwrap_or(s.1));
    let arc = decide(s, e, cw, by, st.params().arc_tolerance, line)?;
    st.out.arc(arc.cw, e, arc.centre, feed, arc.rule, line)
}
