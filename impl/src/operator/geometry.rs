//! The retract of a feed hold in a thread cut (G92.HOLD, G76.HOLD, No.0018 bit 6 = 0), as a pure
//! function of the hold point, so that its envelope can be proved on its own (proofs:
//! `hold_retract`).

/// The retract from the hold point `p` (X diameter, Z): the end of the move in the pull-out
/// manner — P + (E − S) when the held move is before the pull-out S → E, E when it is the
/// pull-out, none without a pull-out — then the end of the rapid on the short axis (COM.LONGAXIS:
/// Z long → X to A.x; X long → Z to A.z), then A. Each a target; a move to where the tool already
/// is gets left out by the caller (PRJ.NOOP).
pub fn retract_targets(
    p: (i64, i64),
    on_pullout: bool,
    pull: Option<((i64, i64), (i64, i64))>,
    a: (i64, i64),
    z_long: bool,
) -> (Option<(i64, i64)>, (i64, i64), (i64, i64)) {
    let manner = pull.map(|(s, e)| if on_pullout { e } else { add(p, sub(e, s)) });
    let q = manner.unwrap_or(p);
    let short = if z_long { (a.0, q.1) } else { (q.0, a.1) };
    (manner, short, a)
}

/// `p + d`, saturating (positions are below 2^62: never reached).
pub(crate) fn add(p: (i64, i64), d: (i64, i64)) -> (i64, i64) {
    (p.0.saturating_add(d.0), p.1.saturating_add(d.1))
}

pub(crate) fn sub(a: (i64, i64), b: (i64, i64)) -> (i64, i64) {
    (a.0.saturating_sub(b.0), a.1.saturating_sub(b.1))
}
