//! G71.LAYER, G72.LAYER (M003, OPEN): where the layers stand and where each cut ends — exact,
//! over the infeed axis p and the cutting axis q of [`super::Axes`].
//!
//! Layer k stands at P_k = A.p + s·k·step (step = Δd counted on p: 2Δd on the diameter count for
//! G71, Δd for G72). It exists while P_k lies strictly between A.p and Q₀.p **and** its cut is
//! positive; the first k that fails either ends the layers. The cut ends at "the **last** point
//! of Q, in contour order, with s·(p − P_k) ≥ 0 — where Q leaves the layer". Q is monotone
//! (checked), so along Q the ends s·p never increase: the element where Q leaves the layer is
//! the first whose end lies strictly beyond it, found by bisection, and the crossing lies on it.

use super::{half_units, Cycle};
use crate::contour::{Element, Mode, Point};
use crate::exact::{round_div_big, round_root};
use num_bigint::BigInt;
use num_traits::{Signed, ToPrimitive};

/// The layer geometry of one checked cycle.
#[derive(Debug)]
pub struct Roughing<'a> {
    cy: &'a Cycle,
    /// Δd as counts of p.
    step: i128,
}

impl<'a> Roughing<'a> {
    pub fn new(cy: &'a Cycle) -> Roughing<'a> {
        let step = i128::from(cy.depth) * super::counts_per_length(cy.ax.p_letter());
        Roughing { cy, step }
    }

    /// G71.LAYER: X_k = A.x + s·2k·Δd (G72: Z_k = A.z + s·k·Δd), "from A".
    pub fn p_of(&self, k: i128) -> i128 {
        self.cy.ax.p(self.cy.a) + self.cy.s * k * self.step
    }

    /// G71.LAYER: how many k ≥ 1 have "s·(X_k − Q₀.x) < 0 (strictly between A.x and Q₀.x)":
    /// with D = s·(Q₀.p − A.p), those with k·step < D.
    pub fn between(&self) -> i128 {
        let (ax, cy) = (self.cy.ax, self.cy);
        let d = cy.s * (ax.p(cy.q.ns().end) - ax.p(cy.a));
        if d > 0 {
            (d - 1) / self.step
        } else {
            0
        }
    }

    /// G71.LAYER: layer k, its infeed p and its cut end q, if it exists — between A and Q₀, and
    /// "its cut is positive, c·(z_k − A.z) > 0".
    pub fn layer(&self, k: i128) -> Option<(i128, i128)> {
        if k < 1 || k > self.between() {
            return None;
        }
        let p = self.p_of(k);
        let q = self.cut_end(p);
        (self.cy.c * (q - self.cy.ax.q(self.cy.a)) > 0).then_some((p, q))
    }

    /// The number of layers, counted no further than `cap`: "the first k that fails either ends
    /// the layers".
    pub fn count(&self, cap: i128) -> i128 {
        let last = self.between().min(cap);
        (1..=last).find(|&k| self.layer(k).is_none()).map_or(last, |k| k - 1)
    }

    /// G71.LAYER: the q where Q leaves the layer at infeed `p`: on the first element of Q whose
    /// end lies strictly beyond the layer (s·(p_end − p) < 0); Q's last point if none does.
    pub fn cut_end(&self, p: i128) -> i128 {
        let (ax, s) = (self.cy.ax, self.cy.s);
        let rest = self.cy.q.rest();
        let j = rest.partition_point(|e| s * (ax.p(e.end) - p) >= 0);
        match rest.get(j) {
            None => ax.q(self.cy.q.last()),
            Some(e) => self.crossing(e, p),
        }
    }

    /// Where element `e` (its start on or before the layer, its end beyond it) meets infeed `p`,
    /// rounded once, half away from zero.
    fn crossing(&self, e: &Element, p: i128) -> i128 {
        let ax = self.cy.ax;
        match (e.mode, e.centre) {
            (Mode::Arc { .. }, Some(c)) => arc_crossing(self.cy, e.start, e.end, c, p),
            _ => line_crossing(ax.p(e.start), ax.q(e.start), ax.p(e.end), ax.q(e.end), p),
        }
    }
}

fn big(v: i128) -> BigInt {
    BigInt::from(v)
}

fn small(v: BigInt) -> i128 {
    v.to_i128().unwrap_or(if v.is_negative() { i128::MIN } else { i128::MAX })
}

/// G71.LAYER (M003): "On a line from (x₀, z₀) to (x₁, z₁): z = z₀ + (X_k − x₀)(z₁ − z₀)/(x₁ −
/// x₀)" (G72 with X and Z exchanged) — one quotient, rounded once (`p₁ ≠ p₀`: the line crosses
/// the layer).
pub fn line_crossing(p0: i128, q0: i128, p1: i128, q1: i128, p: i128) -> i128 {
    let num = big(q0) * big(p1 - p0) + big(p - p0) * big(q1 - q0);
    small(round_div_big(&num, &big(p1 - p0)))
}

/// G71.LAYER (M003): "on an arc: z = c_z ± √(r² − (X_k − c_x)²)/2 in half-increment units (r² =
/// (x₀ − c_x)² + 4(z₀ − c_z)², the circle through the element's start; the sign that keeps the
/// point on the arc) — one integer square root, rounded once"; G72: x = c_x ± √(r² − 4(Z_k −
/// c_z)²), on the diameter count. The arc, monotone, lies on one side of the line q = c_q: the
/// sign is that of its start's q − c_q (of its end's when the start is on that line). A layer
/// beyond the circle's extreme (possible only within `arc_tolerance` of the programmed end)
/// takes the root 0: the extreme point.
pub fn arc_crossing(cy: &Cycle, start: Point, end: Point, c: Point, p: i128) -> i128 {
    let ax = cy.ax;
    let (hp, hq) = (half_units(ax.p_letter()), half_units(ax.q_letter()));
    let r2 = big(start.0 - c.0).pow(2) + big(2 * (start.1 - c.1)).pow(2);
    let m = r2 - big((p - ax.p(c)) * hp).pow(2);
    let m = if m.is_negative() { BigInt::from(0) } else { m };
    let side = |pt: Point| (ax.q(pt) - ax.q(c)).signum();
    let sigma = if side(start) != 0 { side(start) } else { side(end) };
    let root = round_root(&big(ax.q(c) * hq), sigma as i8, m.magnitude(), &big(hq));
    small(root)
}

#[cfg(test)]
mod tests;
