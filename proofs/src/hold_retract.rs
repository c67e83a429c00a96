//! Harness `hold_retract` — G92.HOLD, G76.HOLD (docs/INTERPRETATION.md, "Operator events",
//! "Feed hold", No.0018 bit 6 = 0): the envelope of the retract after a feed hold in a thread cut.
//!
//! **Property.** For every start point A, cut C → S and pull-out S → E of a G92/G76/G78 cut (each
//! coordinate in ±2^40 and the pull-out's J, K within 2^40, far beyond every reachable position: words are ≤ N < 2^30), the long
//! axis either way (COM.LONGAXIS), the cut advancing on the long axis and the pull-out not going
//! back on it, and every hold point P on the held move (the cut, or the pull-out), the
//! production expander's retract (`cycle_impl::hold_geometry::retract_targets`):
//!
//! - moves in the pull-out manner exactly when the cut has a pull-out, by exactly the programmed
//!   pull-out's displacement E − S from a point of the cut ("the programmed pull-out translated
//!   to P"), or to E from a point of the pull-out — so on the short axis it moves the way the
//!   programmed pull-out does (outward, never deeper), and on the long axis it never passes the
//!   thread's end E;
//! - then rapids on the short axis only, to A's coordinate, then to A: the retract ends at A.
//!
//! How P is found on the grid (`trunc((E − S)·num/den)`, a quotient of products) is not part of
//! this harness: P is any point of the held move's box. The point's own rule is tested by the
//! engines' tests, the properties (`tests/tests/properties_operator.rs`) and the differential
//! campaigns. **Kani bounds.** Everything symbolic over the ranges above; no loop.

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::hold_geometry::retract_targets;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |coordinate|.
    pub max_pos: i64,
}

/// Kani's scope (and the drivers' edges): ±2^40.
pub const KANI: Scope = Scope { max_pos: 1 << 40 };

fn point<S: Source>(src: &mut S, m: i64) -> (i64, i64) {
    (src.bounded_i64(-m, m), src.bounded_i64(-m, m))
}

/// A value between `a` and `b` inclusive, either order.
fn between<S: Source>(src: &mut S, a: i64, b: i64) -> i64 {
    src.bounded_i64(a.min(b), a.max(b))
}

fn axis(p: (i64, i64), long: bool) -> i64 {
    if long {
        p.1
    } else {
        p.0
    }
}

pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let (z_long, has_pull, on_pullout) = (src.bool(), src.bool(), src.bool());
    src.assume(has_pull || !on_pullout)?;
    let m = scope.max_pos;
    let (a, c, s) = (point(src, m), point(src, m), point(src, m));
    // The long axis: index 1 (Z) when Z is long. The cut advances on it; the pull-out goes on
    // by K ≥ 0 in the same direction and J either way on the short axis, or is absent (E = S).
    let (long, short) = (|p| axis(p, z_long), |p| axis(p, !z_long));
    let dir = (long(s) - long(c)).signum();
    src.assume(dir != 0)?;
    let (k, j) = (src.bounded_i64(0, m), src.bounded_i64(-m, m));
    let e = match (has_pull, z_long) {
        (false, _) => s,
        (true, true) => (s.0 + j, s.1 + dir * k),
        (true, false) => (s.0 + dir * k, s.1 + j),
    };
    let (from, to) = if on_pullout { (s, e) } else { (c, s) };
    let p = (between(src, from.0, to.0), between(src, from.1, to.1));

    let r = retract_targets(p, on_pullout, has_pull.then_some((s, e)), a, z_long);
    let (manner, rapid, end) = (r.manner, r.short, r.end);

    check!(src, manner.is_some() == has_pull, "G92.HOLD: a move in the pull-out manner exactly when the cut has a pull-out");
    let q = manner.unwrap_or(p);
    if let Some(q) = manner {
        if on_pullout {
            check!(src, q == e, "G92.HOLD: from the pull-out, on to its end E");
        } else {
            let moved = (i128::from(q.0) - i128::from(p.0), i128::from(q.1) - i128::from(p.1));
            let programmed = (i128::from(e.0) - i128::from(s.0), i128::from(e.1) - i128::from(s.1));
            check!(src, moved == programmed, "G92.HOLD: the programmed pull-out translated to P");
        }
        // Short axis: the way the programmed pull-out goes (never against it: never deeper).
        let (went, pulls) = ((short(q) - short(p)).signum(), (short(e) - short(s)).signum());
        check!(src, went == 0 || went == pulls, "G92.HOLD: the retract leaves the way the pull-out does");
        // Long axis: never past the thread's end E, never backwards.
        check!(src, (long(e) - long(q)).signum() != -dir, "G92.HOLD: never past the thread's end on the long axis");
        check!(src, (long(q) - long(p)).signum() != -dir, "G92.HOLD: the long axis does not go back");
        cover!(src, !on_pullout && went != 0, "a retract from the cut");
        cover!(src, on_pullout && q != p, "the rest of the pull-out");
    }
    check!(src, long(rapid) == long(q) && short(rapid) == short(a), "G92.HOLD: a rapid on the short axis only, to A's coordinate");
    check!(src, end == a, "G92.HOLD: the retract ends at the start point A");
    cover!(src, !has_pull, "no pull-out: the rapids only");
    cover!(src, z_long, "Z long");
    cover!(src, !z_long, "X long");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = hold_retract in crate::PROPERTIES {
        rules: ["G92.HOLD", "G76.HOLD"],
        states: "The feed-hold retract of a thread cut (No.0018 bit 6 = 0) over ±2^40, from any point of the held move: a move in the pull-out manner exactly when the cut has a pull-out, by the programmed pull-out's displacement (or on to its end from the pull-out), the way the pull-out goes on the short axis, never past the thread's end on the long axis; then a rapid on the short axis only to A's coordinate, then A.",
        body: |src, scope| body(src, &scope),
        /// Kani: the retract over the ranges of [`KANI`]; no loop.
        kani: proof(KANI) { measured: "SUCCESSFUL (129 checks; 5/5 covers), 25.9 s, 0.14 GB" },
        tests {
            /// Coordinates in ±1: every combination of points, pull-outs, axes and held moves.
            fn hold_retract_exhaustive_small = exhaustive(3, 3_000_000) on Scope { max_pos: 1 };
            fn hold_retract_random = random(0x5eed_4010, 2) on KANI;
        }
    }
}
