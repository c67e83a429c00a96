//! G70, finishing (M003; docs/INTERPRETATION.md, "G70"): the contour's blocks, translated by
//! (U, W), as ordinary moves from the G70 start point (G70.PATH, G70.UW), each at the F in
//! effect — G70's own F or the modal feed, replaced by a contour block's F from that block on
//! (G70.FEED) — then one rapid back to the start point (G70.RETURN). One event at a time.

use crate::contour::{Contour, Kind};
use crate::emit::emit;
use cycle_vocab::{Event, Move, Pass, PassKind, Rule};

/// A G70 cycle whose checks passed.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    /// S, the start point and the end.
    start: (i64, i64),
    /// (U, W): U a diameter count.
    shift: (i64, i64),
    /// The F in effect.
    feed: i64,
    /// The pass header, until it is emitted.
    header: Option<Pass>,
    /// The next element, and how many there are.
    elem: usize,
    n: usize,
    returned: bool,
}

impl Cycle {
    /// The run of the contour in `contour` from `start`: header index 1, kind FINISH, depth on
    /// diameter |S.x − P₀.x| (P₀ the ns block's end translated), rule G70.PATH.
    pub fn new(start: (i64, i64), shift: (i64, i64), feed: i64, contour: &Contour) -> Cycle {
        let p0 = contour.get(0).x.saturating_add(shift.0);
        let diameter_depth = start.0.saturating_sub(p0).saturating_abs();
        Cycle {
            start,
            shift,
            feed,
            header: Some(Pass { index: 1, kind: PassKind::Finish, diameter_depth, rule: Rule::G70Path }),
            elem: 0,
            n: contour.len(),
            returned: false,
        }
    }

    /// The next event, updating the machine position; `None` when the cycle is done. Bounded
    /// work: only the ns block's move can be a move to the current position (later elements
    /// each move, by construction of the contour), so at most one move is skipped per call.
    pub fn next_event(&mut self, pos: &mut (i64, i64), contour: &Contour) -> Option<Event> {
        #[cfg(test)]
        crate::probe::count();
        if let Some(h) = self.header.take() {
            return Some(Event::Pass(h));
        }
        while self.elem < self.n {
            let e = contour.get(self.elem);
            self.elem += 1;
            if e.feed != 0 {
                self.feed = i64::from(e.feed);
            }
            let (x, z) = (e.x.saturating_add(self.shift.0), e.z.saturating_add(self.shift.1));
            let m = match e.kind {
                Kind::Rapid => Move::rapid(x, z, Rule::G70Path),
                Kind::Feed => Move::feed(x, z, self.feed, Rule::G70Path),
                Kind::Arc(cw) => {
                    let (cx, cz) = (e.cx.saturating_add(self.shift.0), e.cz.saturating_add(self.shift.1));
                    Move::arc(cw, x, z, cx, cz, self.feed, Rule::G70Path)
                }
            };
            if let Some(ev) = emit(m, pos) {
                return Some(ev);
            }
        }
        if self.returned {
            return None;
        }
        self.returned = true;
        emit(Move::rapid(self.start.0, self.start.1, Rule::G70Return), pos)
    }
}

impl Cycle {
    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`]:
    /// the contour's elements built in place from the contour slice, the header and the return
    /// through `next_event`. How many, and whether the cycle is done. Bounded work:
    /// `out.len()` events and at most one skipped element.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event], contour: &Contour) -> (usize, bool) {
        let mut n = 0;
        loop {
            if self.header.is_none() && self.elem < self.n {
                n += self.write_contour(pos, out.get_mut(n..).unwrap_or_default(), contour);
            }
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

    /// The contour's elements from `elem` on, while `out` has room: as `next_event`'s loop.
    /// Returns how many events were written.
    #[inline]
    fn write_contour(&mut self, pos: &mut (i64, i64), out: &mut [Event], contour: &Contour) -> usize {
        let (sx, sz) = self.shift;
        let elements = contour.elements().get(self.elem..self.n).unwrap_or_default();
        let mut at = *pos;
        let mut n = 0;
        for e in elements {
            let Some(slot) = out.get_mut(n) else {
                break;
            };
            self.elem += 1;
            if e.feed != 0 {
                self.feed = i64::from(e.feed);
            }
            let (x, z) = (e.x.saturating_add(sx), e.z.saturating_add(sz));
            // PRJ.NOOP, as `emit`: a move to where the tool stands is not written.
            if (x, z) == at {
                continue;
            }
            at = (x, z);
            let feed = self.feed;
            *slot = Event::Move(match e.kind {
                Kind::Rapid => Move::rapid(x, z, Rule::G70Path),
                Kind::Feed => Move::feed(x, z, feed, Rule::G70Path),
                Kind::Arc(cw) => Move::arc(cw, x, z, e.cx.saturating_add(sx), e.cz.saturating_add(sz), feed, Rule::G70Path),
            });
            n += 1;
        }
        *pos = at;
        n
    }
}

#[cfg(test)]
mod tests;
