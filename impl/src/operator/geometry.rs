//! The retract of a feed hold in a thread cut (G92.HOLD, G76.HOLD, No.0018 bit 6 = 0), as a pure
//! function of the hold point, so that its envelope can be proved on its own (proofs:
//! `hold_retract`).

/// A point: X (diameter) and Z, increments.
pub type Point = (i64, i64);

/// The targets of the retract, in order; a move to where the tool already is gets left out by
/// the caller (PRJ.NOOP).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Retract {
    /// The end of the move in the pull-out manner; `None` without a pull-out.
    pub manner: Option<Point>,
    /// The end of the rapid on the short axis.
    pub short: Point,
    /// A, the cycle's start point.
    pub end: Point,
}

/// The retract from the hold point `p`: in the pull-out manner — to P + (E − S) when the held
/// move is before the pull-out S → E, to E when it is the pull-out, no move without a pull-out —
/// then a rapid on the short axis (COM.LONGAXIS: Z long → X to A.x; X long → Z to A.z), then A.
pub fn retract_targets(p: Point, on_pullout: bool, pull: Option<(Point, Point)>, a: Point, z_long: bool) -> Retract {
    let manner = pull.map(|(s, e)| if on_pullout { e } else { add(p, sub(e, s)) });
    let q = manner.unwrap_or(p);
    let short = if z_long { (a.0, q.1) } else { (q.0, a.1) };
    Retract { manner, short, end: a }
}

/// `p + d`, saturating (positions are below 2^62: never reached).
pub(crate) fn add(p: Point, d: Point) -> Point {
    (p.0.saturating_add(d.0), p.1.saturating_add(d.1))
}

pub(crate) fn sub(a: Point, b: Point) -> Point {
    (a.0.saturating_sub(b.0), a.1.saturating_sub(b.1))
}
