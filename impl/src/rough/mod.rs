//! G71 and G72, stock removal along Z and along X (M003; docs/INTERPRETATION.md, "G71", "G72"):
//! the cycle's checks once its contour is read (G71.FIRST, G71.TYPE2, G71.MONOTONE, the pass
//! bound) and its run — the layers (G71.LAYER, G71.RETRACT), the semi-finish pass along the
//! translated contour (G71.LASTPASS) and the return (G71.RETURN) — one event at a time.
//!
//! **One frame for both.** A point is read as (a, b): a the coordinate the layers step along
//! (G71: X, G72: Z), b the one they cut along (G71: Z, G72: X). Layer k stands at
//! a_k = A.a + s·k·Δd·p_a (p_a = 2 for X, whose counts are diameters; 1 for Z) and cuts from A.b
//! in direction c to b_k, where the translated contour Q leaves it.
//!
//! **The sweep.** With Q's points P_0 = Q₀, P_1, …, P_{n−1} (the contour's element ends, shifted
//! by the allowances) and D(P) = s·(P.a − A.a), layer k lies on or before P_j exactly when
//! D(P_j) ≥ k·step (step = Δd·p_a); D is non-increasing along Q (G71.MONOTONE), so the last such
//! j is non-increasing in k: a cursor that starts at Q's last point moves only toward Q₀ as the
//! layers go deeper — at most n − 1 moves over the whole cycle, O(1) amortised per layer, never a
//! search of the contour per layer. Layer k's cut ends on the element after P_j (or at P_{n−1}
//! when j = n − 1): on a line one rounded quotient, on an arc one integer square root
//! (`cut_on`), rounded once, half away from zero.
//!
//! **The layer count** is found before any motion, without stepping through the layers: layers
//! exist while D(Q₀) > k·step (closed form) and their cut is positive, c·(b_k − A.b) > 0. On one
//! element b_k is monotone in k, so one pass over the elements in layer order tests each
//! element's deepest layer and, on the first element where the cut fails, finds the first
//! failing layer by bisection: O(n + log K) cut evaluations, and it stops at `max_passes`.
//!
//! **Bounds.** Words and parameters are |v| ≤ N < 2^30 and every position a program reaches is
//! below 2^62 in magnitude; a_k = A.a ± k·step with k ≤ max_passes ≤ 10^6 and step ≤ 2N, so
//! |a_k| < 2^62 + 2^51. Differences of two coordinates are formed in `i128` (< 2^64), products of
//! two of them (< 2^128) in `i128` as signed values below 2^127: the line quotient's numerator
//! b₀·(a₁ − a₀) + (a_k − a₀)·(b₁ − b₀) is below 2^127. On an arc (radius < 2^33 in half units,
//! ARC.IK/ARC.R) the layer crosses between the element's ends, within the radius plus the
//! tolerance of the centre, so the radicand r² − d² is below 2^68.

use crate::arc::round_sqrt_sum;
use crate::contour::{Contour, Kind};
use crate::fixed::{div_round_signed, sat};
use cycle_vocab::{Alarm, AlarmCode, Rule};

mod axis;
mod run;
mod step;

use step::LineStep;

pub use axis::Axis;

/// The cycle's words and kept values.
#[derive(Clone, Copy, Debug)]
pub struct Words {
    /// Δd (G71.DEPTH, G72.DEPTH), radius increments (G71) or Z increments (G72), ≥ 1.
    pub depth: i64,
    /// e (G71.RETRACT), ≥ 0.
    pub retract: i64,
    /// (Δu, Δw) (G71.ALLOW): Δu a diameter count.
    pub allowance: (i64, i64),
    /// The roughing feed.
    pub feed: i64,
}

/// Where the run is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// Layer `k`, step 0 (header) … 4 (back along the cut axis).
    Layer,
    /// The semi-finish pass: step 0 header, 1 the move to Q₀, then the elements.
    Semi,
    /// The rapid back to A.
    Return,
    Done,
}

/// A G71/G72 cycle whose checks passed: its geometry and where its run stands.
#[derive(Clone, Copy, Debug)]
pub struct Roughing {
    axis: Axis,
    /// A, the cycle's start and end.
    start: (i64, i64),
    /// (Δu, Δw).
    shift: (i64, i64),
    s: i64,
    c: i64,
    /// Δd, and the layer spacing along a (Δd·p_a).
    depth: i64,
    step: i64,
    /// The 45° retract as an offset along (a, b): (−s·e·p_a, −c·e·p_b).
    retract: (i64, i64),
    feed: i64,
    /// The ns block is G00: infeeds and the move to Q₀ are rapids.
    rapid_infeed: bool,
    /// Elements of the contour (the ns block's included).
    n: usize,
    /// K, the number of layers.
    layers: u32,
    phase: Phase,
    /// The current layer (1-based) or element.
    k: u32,
    elem: usize,
    step_no: u8,
    /// The sweep's cursor: the last point of Q on or before the current layer.
    cursor: usize,
    /// The current layer's cut end b_k.
    cut: i64,
    /// The cut on the element after P_`line_j`, kept for layer `line_k` to step to the next
    /// layer without a division (`step`); `line_j` = usize::MAX when none is kept.
    line: LineStep,
    line_j: usize,
    line_k: u32,
}

fn sign(v: i64) -> i64 {
    v.signum()
}

impl Roughing {
    /// The cycle's checks after the contour's (docs/INTERPRETATION.md, G71 "Cycle checks", (4)–(6)):
    /// G71.TYPE2 (the ns block moves along the cut axis: `UNSUPPORTED`) and G71.FIRST (it does not
    /// move along the layer axis: `GEOMETRY`), both on the ns block's line ("Alarm lines");
    /// G71.MONOTONE (c = 0, on the cycle block's `line`; then each element after ns: the layer
    /// axis — its ends, then a turn inside an arc — before the cut axis, on the element's line),
    /// then the pass bound: K + 1 > `max_passes` is `TOO MANY PASSES` on U (G72: W), PRJ.MAXPASS,
    /// on the cycle block's `line`.
    pub fn new(axis: Axis, start: (i64, i64), w: &Words, contour: &Contour, max_passes: u32, line: u32) -> Result<Roughing, Alarm> {
        let rules = axis.rules();
        let (la, lb) = axis.letters();
        let alarm = |code: AlarmCode, word: u8, rule: Rule, line: u32| Alarm::new(code, Some(word), rule, line);
        let n = contour.len().max(1);
        let a_prime = contour.get(0).end();
        let ns_line = contour.get(0).line;
        if axis.b(a_prime) != axis.b(start) {
            return Err(alarm(AlarmCode::Unsupported, lb, rules.type2, ns_line));
        }
        if axis.a(a_prime) == axis.a(start) {
            return Err(alarm(AlarmCode::Geometry, la, rules.first, ns_line));
        }
        let s = sign(axis.a(a_prime).saturating_sub(axis.a(start)));
        let c = sign(axis.b(contour.last().end()).saturating_sub(axis.b(a_prime)));
        if c == 0 {
            return Err(alarm(AlarmCode::Geometry, lb, rules.monotone, line));
        }
        let mut prev = a_prime;
        for i in 1..n {
            let e = contour.get(i);
            let end = e.end();
            let (turn_a, turn_b) = match e.kind {
                Kind::Arc(cw) => {
                    let (x, z) = crate::arc::turns(prev, end, e.centre(), cw);
                    match axis {
                        Axis::G71 => (x, z),
                        Axis::G72 => (z, x),
                    }
                }
                _ => (false, false),
            };
            if s * sign(axis.a(end).saturating_sub(axis.a(prev))) > 0 || turn_a {
                return Err(alarm(AlarmCode::Geometry, la, rules.monotone, e.line));
            }
            if c * sign(axis.b(end).saturating_sub(axis.b(prev))) < 0 || turn_b {
                return Err(alarm(AlarmCode::Geometry, lb, rules.monotone, e.line));
            }
            prev = end;
        }
        let (pa, pb) = axis.per_radius();
        let mut cycle = Roughing {
            axis,
            start,
            shift: w.allowance,
            s,
            c,
            depth: w.depth,
            step: w.depth.saturating_mul(pa),
            retract: (-s * w.retract * pa, -c * w.retract * pb),
            feed: w.feed,
            rapid_infeed: contour.get(0).kind == Kind::Rapid,
            n,
            layers: 0,
            phase: Phase::Layer,
            k: 1,
            elem: 1,
            step_no: 0,
            cursor: n - 1,
            cut: 0,
            line: LineStep::default(),
            line_j: usize::MAX,
            line_k: 0,
        };
        let layers = cycle.count(contour, max_passes);
        if layers >= max_passes {
            return Err(alarm(AlarmCode::TooManyPasses, axis.depth_word(), Rule::PrjMaxPass, line));
        }
        cycle.layers = layers;
        if layers == 0 {
            cycle.phase = Phase::Semi;
        }
        Ok(cycle)
    }

    /// K, the number of layers `new` counted (the run's layers are 1…K). (Public, hidden, only
    /// for the proof harness `g71_layer_step` in cycle-proofs.)
    #[doc(hidden)]
    pub fn layer_count(&self) -> u32 {
        self.layers
    }

    /// Q's point i: the end of element i shifted by the allowances.
    #[inline]
    fn point(&self, contour: &Contour, i: usize) -> (i64, i64) {
        let e = contour.get(i);
        (e.x.saturating_add(self.shift.0), e.z.saturating_add(self.shift.1))
    }

    /// D(P) = s·(P.a − A.a).
    #[inline]
    fn reach(&self, p: (i64, i64)) -> i128 {
        let d = i128::from(self.axis.a(p)) - i128::from(self.axis.a(self.start));
        // s = ±1 (`new` refused A′.a = A.a): s·d as a negation, not a product (the same value;
        // no multiplier circuit in the Kani query of `g71_layer_step`).
        if self.s < 0 {
            -d
        } else {
            d
        }
    }

    /// a_k, the layer coordinate of layer k. (Public, hidden, only for the proof harnesses
    /// `g71_layers` and `g71_layer_step` in cycle-proofs.)
    #[doc(hidden)]
    #[inline]
    pub fn layer_at(&self, k: u32) -> i64 {
        let d = layer_offset(k, self.step);
        // s·d (s = ±1, d ≥ 0) as a negation, as in `reach`.
        self.axis.a(self.start).saturating_add(if self.s < 0 { d.saturating_neg() } else { d })
    }

    /// Layer k's cut end b_k when P_j is the last point of Q on or before it (G71.LAYER): Q's
    /// last point when j = n − 1, else where the element after P_j crosses a_k.
    fn cut_at(&self, contour: &Contour, j: usize, k: u32) -> i64 {
        let from = self.point(contour, j);
        if j + 1 >= self.n {
            return self.axis.b(from);
        }
        let e = contour.get(j + 1);
        let to = self.point(contour, j + 1);
        let centre = (e.cx.saturating_add(self.shift.0), e.cz.saturating_add(self.shift.1));
        cut_on(self.axis, e.kind, from, to, centre, self.layer_at(k))
    }

    /// The current layer's cut end, `cut_at(cursor, k)`: on a line element stepped from the
    /// previous layer's when the sweep stayed on that element (`step`, exact), else computed.
    #[inline(always)]
    fn layer_cut(&mut self, contour: &Contour) -> i64 {
        if self.line_j == self.cursor && self.line_k.wrapping_add(1) == self.k {
            self.line.advance();
            self.line_k = self.k;
            return sat(self.line.value());
        }
        self.new_layer_cut(contour)
    }

    /// `layer_cut` when the sweep reached a new element (or an arc): the cut computed, and on a
    /// line the stepping state set up for the next layers.
    #[inline(never)]
    fn new_layer_cut(&mut self, contour: &Contour) -> i64 {
        #[cfg(test)]
        crate::probe::count_cut();
        let (j, k) = (self.cursor, self.k);
        self.line_j = usize::MAX;
        if j + 1 < self.n && !matches!(contour.get(j + 1).kind, Kind::Arc(_)) {
            let (from, to) = (self.point(contour, j), self.point(contour, j + 1));
            let (a0, b0) = (i128::from(self.axis.a(from)), i128::from(self.axis.b(from)));
            let (a1, b1) = (i128::from(self.axis.a(to)), i128::from(self.axis.b(to)));
            let (den, db) = (a1 - a0, b1 - b0);
            let num = b0 * den + (i128::from(self.layer_at(k)) - a0) * db;
            if let Some(line) = LineStep::new(num, den, i128::from(self.s) * i128::from(self.step) * db) {
                self.line = line;
                self.line_j = j;
                self.line_k = k;
                return sat(line.value());
            }
        }
        self.cut_at(contour, j, k)
    }

    /// Whether layer k's cut is positive, c·(b_k − A.b) > 0: the sign of b_k − A.b is c (c = ±1,
    /// `new` refused c = 0), written without a product.
    fn cuts(&self, b: i64) -> bool {
        sign(b.saturating_sub(self.axis.b(self.start))) == self.c
    }

    /// G71.LAYER: the number of layers K — the k before the first that fails — counted up to
    /// `limit` (the caller refuses K ≥ `limit`). Layer k exists while k·step < D(Q₀) and its cut
    /// is positive. One pass over the elements in layer order (see the module's notes).
    /// (Public, hidden, only for the proof harness `g71_layers` in cycle-proofs.)
    #[doc(hidden)]
    pub fn count(&self, contour: &Contour, limit: u32) -> u32 {
        let step = i128::from(self.step.max(1));
        let d0 = self.reach(self.point(contour, 0));
        let k1 = if d0 > 0 { layers_within(d0 - 1, step) } else { 0 };
        let last = u32::try_from(k1.min(i128::from(limit))).unwrap_or(limit);
        let mut lo = 1u32;
        for j in (0..self.n).rev() {
            if lo > last {
                break;
            }
            // Layers whose last point of Q on or before them is P_j: lo … hi.
            let reach = self.reach(self.point(contour, j));
            if reach < step {
                continue;
            }
            let hi = u32::try_from(layers_within(reach, step).min(i128::from(last))).unwrap_or(last);
            if hi < lo {
                continue;
            }
            if !self.cuts(self.cut_at(contour, j, hi)) {
                // On one element b_k is monotone in k: bisect for the first failing layer.
                let (mut good, mut bad) = (lo - 1, hi);
                while bad - good > 1 {
                    let mid = good + (bad - good) / 2;
                    if self.cuts(self.cut_at(contour, j, mid)) {
                        good = mid;
                    } else {
                        bad = mid;
                    }
                }
                return bad - 1;
            }
            lo = hi + 1;
        }
        last
    }
}

/// k·step, layer k's distance from A along a (G71.LAYER): exact, as k ≤ `max_passes` ≤ 10^6
/// and step ≤ 2N keep it below 2^51 (it saturates, never wraps). (Public, hidden: the proof
/// harness `g71_layer_step` in cycle-proofs stubs it by its specification, (k + 1)·step =
/// k·step + step.)
#[doc(hidden)]
#[inline]
pub fn layer_offset(k: u32, step: i64) -> i64 {
    i64::from(k).saturating_mul(step)
}

/// ⌊`reach`/`step`⌋ for `reach` ≥ 0 and `step` ≥ 1: the number of layers k ≥ 1 with
/// k·step ≤ `reach` (G71.LAYER; `count` asks it for D(Q₀) − 1, the layers strictly before Q₀,
/// and for D(P_j)). (Public, hidden: the proof harness `g71_layer_step` in cycle-proofs stubs
/// it by that bracket.)
#[doc(hidden)]
#[inline]
pub fn layers_within(reach: i128, step: i128) -> i128 {
    reach / step
}

/// Where the element from `from` to `to` (a line, or an arc about `centre`) crosses the layer
/// a = `ak`, which lies between its ends: the cut coordinate, its exact value rounded once,
/// half away from zero (G71.LAYER, G72.LAYER).
///
/// Line: b = b₀ + (a_k − a₀)(b₁ − b₀)/(a₁ − a₀), one rounded quotient of the whole value.
/// Arc, in half units (u = X, v = 2Z): on the circle through `from`, r² = |from − centre|²; with
/// d the layer's offset from the centre along a, the cut coordinate is c_b ± √(r² − d²) (in half
/// units), the sign that of the arc's side of the centre (an arc that passed G71.MONOTONE lies in
/// one quadrant). G71: Z = (2·c_z ± √M)/2, which ties when M is an odd square; G72:
/// X = c_x ± √M, which never ties. Where the layer passes beyond the circle (possible only within
/// the ARC.TOL band of the element's end) M < 0 is taken as 0: the circle's extreme point.
pub fn cut_on(axis: Axis, kind: Kind, from: (i64, i64), to: (i64, i64), centre: (i64, i64), ak: i64) -> i64 {
    let (a0, b0) = (i128::from(axis.a(from)), i128::from(axis.b(from)));
    let (a1, b1) = (i128::from(axis.a(to)), i128::from(axis.b(to)));
    let ak = i128::from(ak);
    match kind {
        Kind::Arc(_) => {
            let (ha, hb) = axis.half();
            let (ca, cb) = (i128::from(axis.a(centre)), i128::from(axis.b(centre)));
            let r2 = ((a0 - ca) * ha).unsigned_abs().saturating_pow(2).saturating_add(((b0 - cb) * hb).unsigned_abs().saturating_pow(2));
            let d2 = ((ak - ca) * ha).unsigned_abs().saturating_pow(2);
            let m = r2.saturating_sub(d2);
            let side = if b0 != cb { b0 - cb } else { b1 - cb };
            // value = (hb·c_b ± √M) / hb
            sat(round_sqrt_sum(hb * cb, side >= 0, m, hb))
        }
        _ => {
            let den = a1 - a0;
            if den == 0 {
                return sat(b0);
            }
            sat(div_round_signed(b0 * den + (ak - a0) * (b1 - b0), den))
        }
    }
}

#[cfg(test)]
mod tests;
