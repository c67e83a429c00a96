//! The shape checks of G71 and G72 (M003): cycle checks (4) TYPE2 then FIRST and (5) MONOTONE,
//! written over the infeed axis p and the cutting axis q ([`super::Axes`]).

use super::Axes;
use crate::arc;
use crate::contour::{Contour, Mode, Point};
use crate::words::alarm;
use cycle_vocab::{Alarm, AlarmCode};

/// G71.TYPE2, G71.FIRST (M003; G72 mirrored): "the ns block's end Z ≠ A.z is `UNSUPPORTED` on Z,
/// rule G71.TYPE2 (a Type II contour: not modelled); its end X = A.x is `GEOMETRY` on X, rule
/// G71.FIRST (no infeed direction)" — by motion, not by words; on the ns block's line.
pub fn first(ax: Axes, c: &Contour, a: Point) -> Result<(), Alarm> {
    let [type2, first, ..] = ax.rules();
    let ns = c.ns();
    if ax.q(ns.end) != ax.q(a) {
        return Err(alarm(AlarmCode::Unsupported, ax.q_letter(), type2, ns.line));
    }
    if ax.p(ns.end) == ax.p(a) {
        return Err(alarm(AlarmCode::Geometry, ax.p_letter(), first, ns.line));
    }
    Ok(())
}

/// G71.MONOTONE (M003, OPEN; G72 mirrored): "c = 0 is `GEOMETRY` on Z" (on the cycle block's
/// line); "then every element after ns, in order, must satisfy s·Δx ≤ 0 and c·Δz ≥ 0 between
/// its ends, and an arc must not turn inside its sweep"; "a violation is `GEOMETRY` on X (when
/// X fails) or Z … on that element's line (X is checked before Z …)". Written over p and q, the
/// infeed axis is checked first: X for G71, Z for G72. Returns c, the cutting direction.
pub fn monotone(ax: Axes, contour: &Contour, s: i128, line: u32) -> Result<i128, Alarm> {
    let rule = ax.rules()[2];
    let c = (ax.q(contour.last()) - ax.q(contour.ns().end)).signum();
    if c == 0 {
        return Err(alarm(AlarmCode::Geometry, ax.q_letter(), rule, line));
    }
    for e in contour.rest().iter().filter(|e| e.moves) {
        let (turns_p, turns_q) = turns(ax, e.mode, e.start, e.end, e.centre);
        if s * (ax.p(e.end) - ax.p(e.start)) > 0 || turns_p {
            return Err(alarm(AlarmCode::Geometry, ax.p_letter(), rule, e.line));
        }
        if c * (ax.q(e.end) - ax.q(e.start)) < 0 || turns_q {
            return Err(alarm(AlarmCode::Geometry, ax.q_letter(), rule, e.line));
        }
    }
    Ok(c)
}

/// Whether an arc has a quadrant point strictly inside its sweep where p, resp. q, is extreme
/// ([`arc::turns`] gives (extreme X, extreme Z)). Lines never turn.
fn turns(ax: Axes, mode: Mode, start: Point, end: Point, centre: Option<Point>) -> (bool, bool) {
    let (Mode::Arc { cw }, Some(c)) = (mode, centre) else {
        return (false, false);
    };
    let (x, z) = arc::turns(start, end, c, cw);
    match ax {
        Axes::G71 => (x, z),
        Axes::G72 => (z, x),
    }
}
