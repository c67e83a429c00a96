//! The run of a G71/G72 cycle, one event at a time: the layers (G71.LAYER, G71.RETRACT), the
//! semi-finish pass along the translated contour (G71.LASTPASS) and the return (G71.RETURN).

use super::{Axis, Phase, Roughing};
use crate::contour::{Contour, Element, Kind};
use crate::emit::emit;
use crate::fixed::sat;
use cycle_vocab::{Event, Move, Pass, PassKind, Rule};

/// The most events of one layer: its header and four moves.
const LAYER_EVENTS: usize = 5;

impl Roughing {
    /// The next event, updating the machine position; `None` when the cycle is done. Bounded
    /// work: a header is emitted at least every five steps, and the sweep's cursor moves at most
    /// n − 1 times over the whole cycle.
    pub fn next_event(&mut self, pos: &mut (i64, i64), contour: &Contour) -> Option<Event> {
        #[cfg(test)]
        crate::probe::count();
        loop {
            let ev = match self.phase {
                Phase::Layer => self.layer_step(contour),
                Phase::Semi => self.semi_step(contour),
                Phase::Return => {
                    self.phase = Phase::Done;
                    Some(Event::Move(Move::rapid(self.start.0, self.start.1, self.axis.rules().ret)))
                }
                Phase::Done => return None,
            };
            match ev {
                Some(Event::Move(m)) => {
                    if let Some(e) = emit(m, pos) {
                        return Some(e);
                    }
                }
                Some(e) => return Some(e),
                None => {}
            }
        }
    }

    /// Writes the next events into `out`, the same events as [`Roughing::next_event`]: a whole
    /// layer (its header and up to four moves) at a time while one fits, each event built where
    /// it is kept, else one event at a time. Returns how many were written and whether the
    /// cycle is done.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event], contour: &Contour) -> (usize, bool) {
        let mut n = 0;
        loop {
            // The whole layers that fit, one loop per axis (the axis then a constant in each).
            let rest = out.get_mut(n..).unwrap_or_default();
            n += match self.axis {
                Axis::G71 => self.write_layers(Axis::G71, pos, rest, contour),
                Axis::G72 => self.write_layers(Axis::G72, pos, rest, contour),
            };
            let Some(slot) = out.get_mut(n) else {
                return (n, false);
            };
            match self.next_event(pos, contour) {
                Some(e) => {
                    *slot = e;
                    n += 1;
                }
                None => return (n, true),
            }
        }
    }

    /// Whole layers into `out` while one fits, `self.axis` being `axis`; returns how many
    /// events were written.
    #[inline(always)]
    fn write_layers(&mut self, axis: Axis, pos: &mut (i64, i64), out: &mut [Event], contour: &Contour) -> usize {
        let mut n = 0;
        while self.phase == Phase::Layer && self.step_no == 0 && self.axis == axis {
            let Some(slots) = out.get_mut(n..).and_then(|r| r.first_chunk_mut::<LAYER_EVENTS>()) else {
                break;
            };
            n += self.write_layer(pos, slots, contour);
        }
        n
    }

    /// The events of one whole layer into `slots` (the header, then the moves that move);
    /// returns how many. The same events as five `layer_step`s, built in place: the header,
    /// then the four moves, each kept only when it moves (PRJ.NOOP).
    #[inline(always)]
    fn write_layer(&mut self, pos: &mut (i64, i64), slots: &mut [Event; LAYER_EVENTS], contour: &Contour) -> usize {
        let [first, rest @ ..] = slots;
        *first = Event::Pass(self.layer_header(contour));
        let ak = self.layer_at(self.k);
        let mut n = 0;
        for i in 1..=4u8 {
            let m = self.layer_move(i, ak);
            if (m.x, m.z) != *pos {
                *pos = (m.x, m.z);
                if let Some(slot) = rest.get_mut(n) {
                    *slot = Event::Move(m);
                }
                n += 1;
            }
        }
        self.next_layer();
        n + 1
    }

    /// One step of the current layer: the pass header (`layer_header`), then its four moves
    /// (`layer_move`).
    #[inline(always)]
    fn layer_step(&mut self, contour: &Contour) -> Option<Event> {
        let step = self.step_no;
        self.step_no += 1;
        if step == 0 {
            return Some(Event::Pass(self.layer_header(contour)));
        }
        let m = self.layer_move(step, self.layer_at(self.k));
        if step >= 4 {
            self.next_layer();
        }
        Some(Event::Move(m))
    }

    /// The current layer's header, after the sweep: the cursor moves toward Q₀ while its point
    /// lies beyond the layer, and the layer's cut end b_k is found (G71.LAYER).
    #[inline(always)]
    fn layer_header(&mut self, contour: &Contour) -> Pass {
        let need = i128::from(self.k) * i128::from(self.step);
        while self.cursor > 0 && self.reach(self.point(contour, self.cursor)) < need {
            self.cursor -= 1;
        }
        self.cut = self.layer_cut(contour);
        let diameter_depth = i64::from(self.k).saturating_mul(self.depth).saturating_mul(2);
        Pass { index: self.k, kind: PassKind::Rough, diameter_depth, rule: self.axis.rules().layer }
    }

    /// Move `step` (1–4) of the current layer: ① infeed along a to a_k in the ns block's mode,
    /// ② the cut at feed to b_k (G71.LAYER), ③ the 45° retract at feed, ④ the rapid back to A.b
    /// (G71.RETRACT); `ak` = a_k, `layer_at(k)`.
    #[inline(always)]
    fn layer_move(&self, step: u8, ak: i64) -> Move {
        let rules = self.axis.rules();
        let b0 = self.axis.b(self.start);
        match step {
            1 => self.linear(self.rapid_infeed, self.axis.point(ak, b0), rules.layer),
            2 => self.linear(false, self.axis.point(ak, self.cut), rules.layer),
            3 => {
                let p = self.axis.point(ak.saturating_add(self.retract.0), self.cut.saturating_add(self.retract.1));
                self.linear(false, p, rules.retract)
            }
            _ => {
                let p = self.axis.point(ak.saturating_add(self.retract.0), b0);
                Move::rapid(p.0, p.1, rules.retract)
            }
        }
    }

    /// After a layer's last move: the next layer, or the semi-finish pass after layer K.
    #[inline(always)]
    fn next_layer(&mut self) {
        self.step_no = 0;
        if self.k >= self.layers {
            self.phase = Phase::Semi;
        } else {
            self.k += 1;
        }
    }

    /// G71.LASTPASS: the header (index K + 1, kind SEMI), the move to Q₀ in the ns block's mode,
    /// then Q element by element in each element's mode, all at the roughing feed.
    fn semi_step(&mut self, contour: &Contour) -> Option<Event> {
        let rule = self.axis.rules().lastpass;
        let step = self.step_no;
        self.step_no = self.step_no.saturating_add(1);
        match step {
            0 => {
                let q0 = self.point(contour, 0);
                let d = i128::from(self.axis.a(self.start)) - i128::from(self.axis.a(q0));
                let diameter_depth = sat(d.abs() * self.axis.half().0);
                Some(Event::Pass(Pass { index: self.layers + 1, kind: PassKind::Semi, diameter_depth, rule }))
            }
            1 => Some(Event::Move(self.linear(self.rapid_infeed, self.point(contour, 0), rule))),
            _ => {
                if self.elem >= self.n {
                    self.phase = Phase::Return;
                    return None;
                }
                let i = self.elem;
                self.elem += 1;
                let e = contour.get(i);
                Some(Event::Move(self.shifted_move(&e, self.point(contour, i), rule)))
            }
        }
    }

    /// A G00 (`rapid`) or G01 move at the roughing feed.
    fn linear(&self, rapid: bool, (x, z): (i64, i64), rule: Rule) -> Move {
        if rapid {
            Move::rapid(x, z, rule)
        } else {
            Move::feed(x, z, self.feed, rule)
        }
    }

    /// Element `e` of Q, ending at `to`: in its own mode, arcs about their shifted centres.
    fn shifted_move(&self, e: &Element, (x, z): (i64, i64), rule: Rule) -> Move {
        match e.kind {
            Kind::Rapid => Move::rapid(x, z, rule),
            Kind::Feed => Move::feed(x, z, self.feed, rule),
            Kind::Arc(cw) => {
                let (cx, cz) = (e.cx.saturating_add(self.shift.0), e.cz.saturating_add(self.shift.1));
                Move::arc(cw, x, z, cx, cz, self.feed, rule)
            }
        }
    }
}
