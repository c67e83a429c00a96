//! The geometry of generated contours: monotone contours of lines and arcs for G71 and G72
//! (G71.MONOTONE, G72.MONOTONE), drawn in a frame where every contour goes the same way.
//!
//! **The frame.** A contour of G71 or G72 starts at the cycle's start point A, infeeds along
//! the axis p (G71 X, G72 Z) in direction s and cuts along the axis q (G71 Z, G72 X) in
//! direction c. In *half units* — u = X (a diameter count is a radius in half increments) and
//! v = 2·Z, where distances are Euclidean (docs/INTERPRETATION.md, "Contours, arcs …") — the
//! frame's coordinates are T = s·(p − A.p)·h_p, the depth from A, and W = c·(q − A.q)·h_q, the
//! length along the cut (h = 1 for X, 2 for Z). A monotone contour starts at A′ = (T₀, 0) and
//! never increases T nor decreases W. Every contour built here is monotone in the frame; the
//! invalid variants (a step back, an arc through a quadrant point) are made by the caller.
//!
//! **Arcs.** A monotone arc lies in one quadrant of its circle: quadrant I (T, W ≥ 0 from the
//! centre) swept counter-clockwise in the frame, or quadrant III swept clockwise. Three kinds:
//! *quadrant arcs* (90°, tangent to the pieces before and after), *lattice arcs* between two
//! points of a circle with integer points (Pythagorean triples scaled by an even factor: both
//! ends exactly on the circle, every offset even, so the I/K centre is a grid point and
//! R = ρ/2 gives the same centre exactly), and *rounded arcs* whose end is rounded to the grid
//! (within the ARC.TOL band; never with `exact`). Every centre offset is even in half units, so
//! an arc can be written by I/K (I = ΔX/2) as well as by R.

use super::super::Dice;

/// The cycle a contour is roughed by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axis {
    /// Layers in X, cuts along Z.
    G71,
    /// Layers in Z, cuts along X.
    G72,
}

/// A point in the frame's half units: (T, W).
pub type Half = (i64, i64);

/// Where a contour stands: A, s and c (see the module's notes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frame {
    pub axis: Axis,
    /// A: X (diameter count), Z.
    pub a: (i64, i64),
    /// The infeed direction, ±1: sign(A′.p − A.p).
    pub s: i64,
    /// The cutting direction, ±1: sign(B.q − A′.q).
    pub c: i64,
}

impl Frame {
    /// Half units per count of T (the p axis) and of W (the q axis).
    pub fn h(self) -> (i64, i64) {
        match self.axis {
            Axis::G71 => (1, 2),
            Axis::G72 => (2, 1),
        }
    }

    /// The absolute point (X, Z) of the frame point `t` (on the grid: T a multiple of h_p, W of
    /// h_q).
    pub fn xz(self, (t, w): Half) -> (i64, i64) {
        let (hp, hq) = self.h();
        let p = self.p(self.a) + self.s * t / hp;
        let q = self.q(self.a) + self.c * w / hq;
        match self.axis {
            Axis::G71 => (p, q),
            Axis::G72 => (q, p),
        }
    }

    /// The frame point of an absolute point.
    pub fn half(self, pt: (i64, i64)) -> Half {
        let (hp, hq) = self.h();
        (self.s * (self.p(pt) - self.p(self.a)) * hp, self.c * (self.q(pt) - self.q(self.a)) * hq)
    }

    /// The infeed coordinate p and the cutting coordinate q of an absolute point.
    pub fn p(self, (x, z): (i64, i64)) -> i64 {
        match self.axis {
            Axis::G71 => x,
            Axis::G72 => z,
        }
    }
    pub fn q(self, (x, z): (i64, i64)) -> i64 {
        match self.axis {
            Axis::G71 => z,
            Axis::G72 => x,
        }
    }

    /// Whether a sweep that turns from +T toward +W in the frame is clockwise (G02) in the
    /// view of ARC.DIR (+Z to the right, +X up). The frame's (T, W) are (u, v) mirrored by s
    /// and c, and exchanged for G72.
    pub fn cw(self, frame_ccw: bool) -> bool {
        let ccw_keeps = match self.axis {
            Axis::G71 => self.s * self.c < 0,
            Axis::G72 => self.s * self.c > 0,
        };
        frame_ccw != ccw_keeps
    }

    /// The nearest grid point of a frame point given in reals.
    pub fn snap(self, (t, w): (f64, f64)) -> Half {
        let (hp, hq) = self.h();
        ((t / hp as f64).round() as i64 * hp, (w / hq as f64).round() as i64 * hq)
    }
}

/// A contour block's motion.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    Rapid,
    Feed,
    /// G02 (`cw`) or G03.
    Arc { cw: bool },
}

/// One contour element, absolute.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Element {
    pub kind: Kind,
    /// The end point: X (diameter count), Z.
    pub end: (i64, i64),
    /// An arc's centre, on the grid, an even number of X counts from its start.
    pub centre: Option<(i64, i64)>,
    /// Whether the end lies exactly on the circle through the start about the centre (then R
    /// = the radius gives the same centre exactly).
    pub exact: bool,
}

impl Element {
    /// An arc's radius in increments, |start − centre| rounded (exact when [`Element::exact`]).
    pub fn radius(&self, start: (i64, i64)) -> Option<i64> {
        let c = self.centre?;
        let (du, dv) = ((start.0 - c.0) as f64, 2.0 * (start.1 - c.1) as f64);
        Some(((du * du + dv * dv).sqrt() / 2.0).round() as i64)
    }
}

/// What the contour is drawn to meet.
#[derive(Clone, Copy, Debug)]
pub struct Plan {
    /// One unit of geometry (1 mm or 0.1 in), in counts.
    pub unit: i64,
    /// T₀: A′'s depth, half units (a multiple of h_p), > 0.
    pub depth: i64,
    /// The layers Q meets, as frame depths of the *programmed* contour: layer k at
    /// `layer_t + k·layer_step` (half units), the allowance taken out.
    pub layer_t: i64,
    pub layer_step: i64,
    /// Pieces after the ns block drawn from the dice (more come from a seeded stream).
    pub pieces: usize,
    /// Only arcs exactly on their circles.
    pub exact: bool,
}

/// One piece of a contour, in the frame: its motion, its end, its centre.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Piece {
    pub(super) kind: Kind,
    pub(super) end: Half,
    pub(super) centre: Option<Half>,
    pub(super) exact: bool,
}

/// Circles with integer points: the primitive radii (Pythagorean hypotenuses, 65 with four).
const RADII: [i64; 7] = [5, 13, 17, 25, 29, 65, 85];

/// The integer points of quadrant I of the circle of radius `r`, by rising W (angle).
fn lattice(r: i64) -> Vec<Half> {
    let mut v: Vec<Half> = (0..=r)
        .filter_map(|w| {
            let t2 = r * r - w * w;
            let t = (t2 as f64).sqrt().round() as i64;
            (t * t == t2).then_some((t, w))
        })
        .collect();
    v.sort_by_key(|p| p.1);
    v
}

/// A monotone contour: the ns block (G00 or G01 along p to A′, `ns_feed`) and its pieces, in
/// the frame of `f`. Vertices and horizontal pieces land on the plan's layers now and then.
pub fn monotone(d: &mut Dice, f: Frame, plan: &Plan, ns_feed: bool) -> Vec<Element> {
    let mut pieces = Vec::new();
    let mut at: Half = (plan.depth, 0);
    let ns_kind = if ns_feed { Kind::Feed } else { Kind::Rapid };
    pieces.push(Piece { kind: ns_kind, end: at, centre: None, exact: true });
    // Where the contour ends in depth: at A.p mostly (as the seed's N120 X41), inside the
    // stock, or beyond A.
    let (hp, _) = f.h();
    let end_t = match d.weighted(&[60, 25, 15]) {
        0 => 0,
        1 => d.range(0, plan.depth / hp - 1) * hp,
        _ => -d.range(1, 5 * plan.unit) * hp,
    };
    let seed = d.range(0, u32::MAX as i64) as u64;
    let extra = stream(seed, plan.pieces.saturating_sub(PIECES_FROM_DICE) * PIECE_KNOBS);
    for i in 0..plan.pieces {
        let from = i.saturating_sub(PIECES_FROM_DICE) * PIECE_KNOBS;
        let pd = &mut if i < PIECES_FROM_DICE { d.fork(PIECE_KNOBS) } else { Dice::new(&extra[from..from + PIECE_KNOBS]) };
        let left = plan.pieces - i;
        let share = (at.0 - end_t).max(0) / left as i64;
        for p in piece(pd, f, plan, at, share) {
            at = p.end;
            pieces.push(p);
        }
    }
    // Close: no Z (G72: X) travel is c = 0 (G71.MONOTONE's first alarm), so the contour always
    // travels along q; then down to its end depth.
    if at.1 == 0 {
        at.1 += f.h().1 * plan.unit.max(1);
        pieces.push(Piece { kind: Kind::Feed, end: at, centre: None, exact: true });
    }
    if at.0 > end_t {
        at.0 = end_t;
        pieces.push(Piece { kind: Kind::Feed, end: at, centre: None, exact: true });
    }
    pieces.iter().map(|p| element(f, p)).collect()
}

/// The pieces drawn from the dice; those after are drawn from [`stream`].
const PIECES_FROM_DICE: usize = 7;
/// Knobs per piece.
const PIECE_KNOBS: usize = 10;
/// The knobs [`monotone`] draws from: the contour's end, the stream's seed, the pieces.
pub const KNOBS: usize = 5 + PIECES_FROM_DICE * PIECE_KNOBS;

/// `n` knobs from a xorshift seeded by `seed` (0: all 0, the plain pieces).
pub fn stream(seed: u64, n: usize) -> Vec<u32> {
    let mut s = seed;
    (0..n)
        .map(|_| {
            if s == 0 {
                return 0;
            }
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            s as u32
        })
        .collect()
}

fn element(f: Frame, p: &Piece) -> Element {
    Element { kind: p.kind, end: f.xz(p.end), centre: p.centre.map(|c| f.xz(c)), exact: p.exact }
}

/// The next piece(s) from `at`, using about `share` of the depth left (half units).
fn piece(d: &mut Dice, f: Frame, plan: &Plan, at: Half, share: i64) -> Vec<Piece> {
    let (hp, hq) = f.h();
    let u = plan.unit.max(1);
    let line = |kind, end| Piece { kind, end, centre: None, exact: true };
    let kind = if d.chance(15) { Kind::Rapid } else { Kind::Feed };
    let dw = hq * match d.weighted(&[80, 12, 8]) {
        0 => d.range(u / 2, 10 * u).max(1),
        1 => d.range(1, 3), // very short
        _ => d.range(10 * u, 40 * u),
    };
    let dt = (share / hp).max(0) * hp;
    let dt = if d.chance(20) { (d.range(0, 3) * hp).min(dt) } else { dt };
    match d.weighted(&[22, 22, 16, 12, 12, 8, 8]) {
        // Along the cut ("horizontal").
        0 => vec![line(kind, (at.0, at.1 + dw))],
        // Back along the infeed ("vertical"), then along the cut.
        1 => vec![line(kind, (at.0 - dt, at.1)), line(Kind::Feed, (at.0 - dt, at.1 + dw))],
        // A taper.
        2 => vec![line(kind, (at.0 - dt, at.1 + dw))],
        // A vertex exactly on a layer, then a piece along the cut exactly on it.
        3 => {
            let k_lo = (at.0 - dt - plan.layer_t).div_euclid(plan.layer_step.max(1)) + 1;
            let t = plan.layer_t + k_lo * plan.layer_step;
            if plan.layer_step <= 0 || t > at.0 || t % hp != 0 {
                return vec![line(kind, (at.0 - dt, at.1 + dw))];
            }
            let mid = if d.chance(50) { (t, at.1 + dw) } else { (t, at.1) };
            let mut v = vec![line(kind, mid)];
            if mid.1 == at.1 || d.chance(50) {
                v.push(line(Kind::Feed, (t, mid.1 + dw)));
            }
            v
        }
        // A quadrant arc, convex or concave, tangent to its neighbours.
        4 => {
            let rho = 2 * (dt.min(2 * d.range(u / 4, 10 * u)) / 2).max(1);
            quadrant(f, at, rho, d.chance(50))
        }
        // An arc between integer points of a circle.
        5 => lattice_arc(d, f, at, dt.max(2 * hp)),
        // A rounded arc (lattice when only exact arcs are wanted).
        _ if plan.exact => lattice_arc(d, f, at, dt.max(2 * hp)),
        _ => rounded_arc(d, f, at, dt.max(2 * hp), u),
    }
}

/// A quarter circle of radius `rho` (even, half units) from `at` to `at + (−ρ, ρ)`: convex
/// (quadrant I, the centre behind in T) or concave (quadrant III, the centre ahead in W).
pub(super) fn quadrant(f: Frame, at: Half, rho: i64, convex: bool) -> Vec<Piece> {
    let end = (at.0 - rho, at.1 + rho);
    let centre = if convex { (at.0 - rho, at.1) } else { (at.0, at.1 + rho) };
    vec![Piece { kind: Kind::Arc { cw: f.cw(convex) }, end, centre: Some(centre), exact: true }]
}

/// An arc between two integer points of a circle of radius r·k (k even), in quadrant I or III,
/// about as deep as `depth`.
fn lattice_arc(d: &mut Dice, f: Frame, at: Half, depth: i64) -> Vec<Piece> {
    let r = d.one_of(&RADII);
    let k = 2 * (depth / (2 * r)).clamp(1, 2_000);
    let pts: Vec<Half> = lattice(r).iter().map(|&(t, w)| (t * k, w * k)).collect();
    let i = d.below(pts.len() as u64 - 1) as usize;
    let j = i + 1 + d.below((pts.len() - i - 1) as u64) as usize;
    let convex = d.chance(50);
    // Quadrant I: from pts[i] to pts[j] counter-clockwise; III: from −pts[j] to −pts[i].
    let (from, to) = if convex { (pts[i], pts[j]) } else { ((-pts[j].0, -pts[j].1), (-pts[i].0, -pts[i].1)) };
    let centre = (at.0 - from.0, at.1 - from.1);
    let end = (centre.0 + to.0, centre.1 + to.1);
    vec![Piece { kind: Kind::Arc { cw: f.cw(convex) }, end, centre: Some(centre), exact: true }]
}

/// An arc whose end is the grid point nearest its circle: from the angle φ₀ to φ₁ (degrees,
/// 8° … 82° from +T in quadrant I; mirrored in III), radius about `depth`. Sometimes instead a
/// quarter of quadrant III whose end lies a little beyond the circle's extreme in T, on the ray
/// through it (within the tolerance): layers there pass beyond the circle (G71.LAYER's root 0).
fn rounded_arc(d: &mut Dice, f: Frame, at: Half, depth: i64, u: i64) -> Vec<Piece> {
    if d.chance(20) {
        let mut arc = quadrant(f, at, 2 * (depth / 2).max(1), false);
        arc[0].end.0 -= f.h().0 * d.range(1, 8);
        arc[0].exact = false;
        return arc;
    }
    let rho = (depth.max(4 * u) as f64) * (0.5 + d.below(100) as f64 / 100.0);
    let a0 = 8.0 + d.below(50) as f64;
    let a1 = a0 + 5.0 + d.below((82.0 - a0 - 5.0) as u64 + 1) as f64;
    // Sometimes a flat arc: a radius up to 10⁵ times the piece (at most N/4 increments), its
    // sweep about the piece's length — a centre far off, products near the engines' bounds.
    let (rho, a1) = if d.chance(15) {
        let big = (rho * (100 + d.below(100_000)) as f64).min(super::super::N as f64 / 2.0);
        (big, a0 + (depth.max(4 * u) as f64 / big).to_degrees().clamp(1e-6, 20.0))
    } else {
        (rho, a1)
    };
    let convex = d.chance(50);
    let polar = |deg: f64| {
        let r = (deg).to_radians();
        (rho * r.cos(), rho * r.sin())
    };
    let (from, to) = if convex { (polar(a0), polar(a1)) } else { (neg(polar(a1)), neg(polar(a0))) };
    // The centre an even number of half units from the start in each axis (I/K on the grid).
    let even = |v: f64| (v / 2.0).round() as i64 * 2;
    let centre = (at.0 - even(from.0), at.1 - even(from.1));
    let end = f.snap((centre.0 as f64 + to.0, centre.1 as f64 + to.1));
    if end.0 > at.0 || end.1 < at.1 || end == at {
        return vec![Piece { kind: Kind::Feed, end: (at.0, at.1 + f.h().1), centre: None, exact: true }];
    }
    vec![Piece { kind: Kind::Arc { cw: f.cw(convex) }, end, centre: Some(centre), exact: false }]
}

fn neg((a, b): (f64, f64)) -> (f64, f64) {
    (-a, -b)
}

#[cfg(test)]
mod tests;
