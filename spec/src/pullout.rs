//! Pull-out geometry shared by G92, G76 and G78 (G92.PULLOUT, G76.PULLOUT, G78.PULLOUT,
//! COM.LONGAXIS; docs/INTERPRETATION.md "G92.PULLOUT geometry").
//!
//! The pull-out is one synchronized straight segment: K before the end on the long axis the
//! short axis retracts J (toward the start point A) while the long axis keeps threading to the
//! end. The exponential profile of the real machine changes timing, not end points.

/// A point (X diameter, Z), increments.
pub type Point = (i128, i128);

/// One thread line from its start to its end `(end_x, end_z)` (X on diameter).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ThreadLine {
    /// End X (diameter) and Z of the thread, increments.
    pub end_x: i128,
    pub end_z: i128,
    /// Radius X travel, start X − end X over 2 (G92 R, G76/G78 R(i)).
    pub r: i128,
    /// Z travel, end Z − start Z (W), never 0.
    pub w: i128,
    /// COM.SIDE: +1 when A lies on +X of the thread (external), −1 otherwise.
    pub s: i128,
}

/// The resolved pull-out amounts, radius / length increments, both > 0.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Amounts {
    /// Short-axis amount.
    pub j: i128,
    /// Long-axis amount.
    pub k: i128,
}

/// The long axis of a thread.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LongAxis {
    Z,
    X,
}

/// COM.LONGAXIS (M001, M002): Z is the long axis when |W| > |R| (R as a radius), else X
/// (including |W| = |R|).
pub fn long_axis(w: i128, r: i128) -> LongAxis {
    if w.abs() > r.abs() {
        LongAxis::Z
    } else {
        LongAxis::X
    }
}

/// The travel along the long axis (radius on X), the bound for K.
pub fn long_travel(w: i128, r: i128) -> i128 {
    match long_axis(w, r) {
        LongAxis::Z => w.abs(),
        LongAxis::X => r.abs(),
    }
}

/// Why a pull-out cannot be placed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct KTooLong;

/// G92.PULLOUT (M002), also G76.PULLOUT / G78.PULLOUT with R = i: the start and end points of
/// the pull-out segment.
///
/// * Z long: start on the thread line where K of Z travel remains, Z = end.z − sz·K,
///   X = end.x + round(R·K/|W|) (radius); end at Z = end.z, X = end.x + s·J.
/// * X long: start where K of X travel remains, X = end.x + sign(R)·K (radius),
///   Z = end.z − sz·round(|W|·K/|R|); end at X = end.x, Z = end.z − sz·J (toward A on Z).
///
/// K must be less than the long-axis travel, else [`KTooLong`] (`GEOMETRY` on K).
pub fn segment(line: &ThreadLine, a: Amounts) -> Result<(Point, Point), KTooLong> {
    if a.k >= long_travel(line.w, line.r) {
        return Err(KTooLong);
    }
    let sz = line.w.signum();
    Ok(match long_axis(line.w, line.r) {
        LongAxis::Z => {
            let dx = crate::exact::round_div(line.r * a.k, line.w.abs());
            let start = (line.end_x + 2 * dx, line.end_z - sz * a.k);
            let end = (line.end_x + 2 * line.s * a.j, line.end_z);
            (start, end)
        }
        LongAxis::X => {
            let dz = crate::exact::round_div(line.w.abs() * a.k, line.r.abs());
            let start = (line.end_x + 2 * line.r.signum() * a.k, line.end_z - sz * dz);
            let end = (line.end_x, line.end_z - sz * a.j);
            (start, end)
        }
    })
}

#[cfg(test)]
mod tests;
