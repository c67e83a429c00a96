//! Pull-out amounts and geometry (G92.JK.*, G92.PULLOUT, G76.PULLOUT, G78.PULLOUT,
//! COM.LONGAXIS). Amounts are radius increments; offsets returned are relative to the thread
//! end point, X on diameter.

use crate::fixed::{div_round, div_round_signed, mul_tan, sat};
use cycle_vocab::Grid;

/// A resolved pull-out: J on the short axis, K along the long axis (both > 0).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Amounts {
    pub j: i64,
    pub k: i64,
}

/// A length of `tenths` × lead / 10, rounded once half up to the length grid (G92.JK.1 No.19,
/// G76.PULLOUT chamfer width r / 5130).
pub fn tenths_of_lead(tenths: u32, lead: i64, grid: Grid) -> i64 {
    let num = u128::from(tenths) * u128::from(lead.unsigned_abs());
    let den = 10 * u128::from(grid.lead_counts_per_increment().unsigned_abs());
    i64::try_from(div_round(num, den)).unwrap_or(i64::MAX)
}

/// round(k·tan(angle_deg)) (the chamfer angle 5131, 1…89°: exact, [`mul_tan`]).
fn short_leg(k: i64, angle_deg: u32) -> i64 {
    let v = mul_tan(k.max(0).unsigned_abs(), angle_deg.saturating_mul(2));
    i64::try_from(v).unwrap_or(i64::MAX)
}

/// G92.JK.1–G92.JK.6 as one function of J and K (absolute values, G92.JK.7), the No.19
/// amount `c` and the chamfer angle 5131 in degrees; `None` when no pull-out is made (a
/// resolved amount of 0). JK.1 (both omitted): K = c, J = round(c·tan 5131°) (No.5131 for
/// G92, `000_…` line 79); JK.2 (J omitted, K given): J = c (M002 note 3).
pub fn g92_amounts(j: Option<i64>, k: Option<i64>, c: i64, angle_deg: u32) -> Option<Amounts> {
    let (j, k) = match (j, k) {
        (None, None) => (short_leg(c, angle_deg), c), // G92.JK.1
        (None, Some(0)) => (c, c),           // G92.JK.2 with K = 0 read as JK.5
        (None, Some(k)) => (c, k),           // G92.JK.2
        (Some(0), _) => (0, 0),              // G92.JK.4, G92.JK.6
        (Some(j), None | Some(0)) => (j, j), // G92.JK.3, G92.JK.5
        (Some(j), Some(k)) => (j, k),
    };
    (j > 0 && k > 0).then_some(Amounts { j, k })
}

/// G76.PULLOUT / G78.PULLOUT: J and K of the second block, the chamfer width (r or 5130 tenths
/// of the lead, already on the grid) and the chamfer angle 5131 in degrees. `None`: no pull-out.
pub fn multi_amounts(j: Option<i64>, k: Option<i64>, chamfer: i64, angle_deg: u32) -> Option<Amounts> {
    let j_of = |k: i64| short_leg(k, angle_deg);
    let (j, k) = match (j, k) {
        (None, None) => (j_of(chamfer), chamfer),
        (None, Some(k)) => (j_of(k), k),
        (Some(j), None | Some(0)) => (j, j),
        (Some(j), Some(k)) => (j, k),
    };
    (j > 0 && k > 0).then_some(Amounts { j, k })
}

/// The pull-out of a thread from `start` to `end` (X diameter), as offsets of its start and end
/// points from `end` (X on diameter), and the long-axis travel it must stay within.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Offsets {
    pub start: (i64, i64),
    pub end: (i64, i64),
}

/// Sign of a value: −1, 0, 1.
pub const fn sign(v: i64) -> i64 {
    if v > 0 {
        1
    } else if v < 0 {
        -1
    } else {
        0
    }
}

/// COM.LONGAXIS: whether Z is the long axis of a thread with Z travel `w` and radius taper
/// `r` (start X − end X, radius): |W| > |R|.
pub fn z_long(w: i64, r: i64) -> bool {
    w.unsigned_abs() > r.unsigned_abs()
}

/// The long-axis travel of the thread (what K must stay below).
pub fn travel(w: i64, r: i64) -> u64 {
    if z_long(w, r) {
        w.unsigned_abs()
    } else {
        r.unsigned_abs()
    }
}

/// G92.PULLOUT geometry (also G76.PATH with R = i): `w` is the thread's Z travel (≠ 0), `r` the
/// radius taper (start X − end X), `s` the side (toward A on X).
///
/// Z long: the pull-out starts where K of Z travel remains, X there = end + round(R·K/|W|)
/// (radius); it ends at the end Z, X = end + s·J. X long: it starts at X = end + sign(R)·K,
/// Z = end − sign(W)·round(|W|·K/|R|); it ends at the end X, Z = end − sign(W)·J.
pub fn offsets(a: Amounts, w: i64, r: i64, s: i64) -> Offsets {
    let sz = i128::from(sign(w));
    let (j, k) = (i128::from(a.j), i128::from(a.k));
    let (w, r) = (i128::from(w), i128::from(r));
    if z_long(sat(w), sat(r)) {
        let dx = div_round_signed(r * k, w.abs()); // radius
        Offsets { start: (sat(2 * dx), sat(-sz * k)), end: (sat(i128::from(s) * (2 * j)), 0) }
    } else {
        let dz = div_round_signed(w.abs() * k, r.abs());
        Offsets { start: (sat(i128::from(sign(sat(r))) * (2 * k)), sat(-sz * dz)), end: (0, sat(-sz * j)) }
    }
}

#[cfg(test)]
mod tests;
