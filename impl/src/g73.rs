//! G73, pattern repeating (M003; docs/INTERPRETATION.md, "G73"): d passes, each the contour
//! translated by T_n = (2·round(Δi·(d − n)/d) + Δu, round(Δk·(d − n)/d) + Δw) (G73.DEPTH,
//! G73.PATH), then one rapid back to A; under the letter of g73.c one rapid A → C first. The
//! contour is the expander's buffer (CNT.MAX), read once and walked d times by index; the cycle
//! keeps only its pass, element and offset — O(1) state.
//!
//! Bounds: Δi, Δk, Δu, Δw ≤ N < 2^30 and d ≤ 10^9, so Δi·(d − n) < 2^60 in `i128` exactly;
//! each offset is below 2^32 and each translated coordinate stays below 2^62 (lib.rs).

use crate::contour::{Contour, Kind};
use crate::emit::emit;
use crate::fixed::{div_round_signed, sat};
use cycle_vocab::{Alarm, AlarmCode, Event, Move, Pass, PassKind, Rule};

/// The cycle's values: Δi (radius) and Δk — the total escape — the count d, the allowances Δu
/// (diameter) and Δw, the roughing feed, the word that gave d (R in format (a), D in (b)), and
/// whether the tool first retreats to C (declared reading g73.c: `visit`, the letter).
#[derive(Clone, Copy, Debug)]
pub struct Words {
    pub di: i64,
    pub dk: i64,
    pub d: i64,
    pub allowance: (i64, i64),
    pub feed: i64,
    pub count_word: u8,
    pub visit_c: bool,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// G73 point C: the rapid A → C before pass 1 (g73.c = visit).
    ToC,
    Header,
    ToStart,
    Contour,
    Return,
    Done,
}

/// A G73 cycle whose checks passed.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    a: (i64, i64),
    w: Words,
    /// The pass (1 … d) and its offset T_n.
    n: i64,
    shift: (i64, i64),
    elem: usize,
    len: usize,
    phase: Phase,
}

/// Pass `n`'s radius and Z escapes: round(Δi·(d − n)/d), round(Δk·(d − n)/d), half away from
/// zero (G73.DEPTH). (Public, hidden: the proof harness `g73_passes` in cycle-proofs stubs it by
/// its specification, smt/ lemma 15.)
#[doc(hidden)]
pub fn escape(w: &Words, n: i64) -> (i64, i64) {
    let left = i128::from(w.d.saturating_sub(n));
    let d = i128::from(w.d);
    (sat(div_round_signed(i128::from(w.di) * left, d)), sat(div_round_signed(i128::from(w.dk) * left, d)))
}

impl Cycle {
    /// The cycle from A = `a` over `contour` (its checks — CNT.FIND, CNT.MAX, the blocks',
    /// CNT.FIRST — passed): step 5's last check, d > `max_passes` (`TOO MANY PASSES` on the word
    /// that gave d, PRJ.MAXPASS), before any motion.
    pub fn new(a: (i64, i64), w: &Words, contour: &Contour, max_passes: u32, line: u32) -> Result<Cycle, Alarm> {
        if w.d > i64::from(max_passes) {
            return Err(Alarm::new(AlarmCode::TooManyPasses, Some(w.count_word), Rule::PrjMaxPass, line));
        }
        let phase = if w.visit_c { Phase::ToC } else { Phase::Header };
        Ok(Cycle { a, w: *w, n: 1, shift: (0, 0), elem: 0, len: contour.len(), phase })
    }

    /// The header of pass `n`, its offset T_n set (G73.DEPTH); the rapid to the start follows.
    #[inline(always)]
    fn pass_header(&mut self) -> Event {
        let (ei, ek) = escape(&self.w, self.n);
        self.shift = (ei.saturating_mul(2).saturating_add(self.w.allowance.0), ek.saturating_add(self.w.allowance.1));
        self.elem = 0;
        self.phase = Phase::ToStart;
        let index = u32::try_from(self.n).unwrap_or(u32::MAX);
        let diameter_depth = ei.saturating_mul(2).saturating_abs();
        Event::Pass(Pass { index, kind: PassKind::Rough, diameter_depth, rule: Rule::G73Depth })
    }

    /// The rapid to the pass's translated start A + T_n; the contour follows.
    #[inline(always)]
    fn rapid_to_start(&mut self) -> Move {
        self.phase = Phase::Contour;
        Move::rapid(self.a.0.saturating_add(self.shift.0), self.a.1.saturating_add(self.shift.1), Rule::G73Path)
    }

    /// Pass `n` next: its header is the next event (what `end_pass` does after pass n − 1).
    /// (Public, hidden: the proof harness `g73_passes` in cycle-proofs starts a run at a
    /// symbolic pass n ≥ 2 with it.)
    #[doc(hidden)]
    #[inline(always)]
    pub fn enter_pass(&mut self, n: i64) {
        self.n = n;
        self.phase = Phase::Header;
    }

    /// After the pass's last element: the next pass, or the return after the last.
    #[inline(always)]
    fn end_pass(&mut self) {
        if self.n < self.w.d {
            self.enter_pass(self.n + 1);
        } else {
            self.phase = Phase::Return;
        }
    }

    /// The next event, updating the machine position; `None` when the cycle is done. PRJ.NOOP:
    /// a move to the current position is not emitted. Bounded work: within a pass only the
    /// rapid to the start and the ns element can be moves to where the tool stands (later
    /// elements each move), so at most three moves (with the rapid to C) are skipped per call.
    pub fn next_event(&mut self, pos: &mut (i64, i64), contour: &Contour) -> Option<Event> {
        #[cfg(test)]
        crate::probe::count();
        loop {
            let m = match self.phase {
                // G73 point C = A + (2Δi + Δu, Δk + Δw) (diameter count; not emitted when C = A).
                Phase::ToC => {
                    self.phase = Phase::Header;
                    let (u, w) = self.w.allowance;
                    let cx = self.a.0.saturating_add(self.w.di.saturating_mul(2)).saturating_add(u);
                    Move::rapid(cx, self.a.1.saturating_add(self.w.dk).saturating_add(w), Rule::G73Path)
                }
                Phase::Header => return Some(self.pass_header()),
                Phase::ToStart => self.rapid_to_start(),
                Phase::Contour => {
                    if self.elem >= self.len {
                        self.end_pass();
                        continue;
                    }
                    let e = contour.get(self.elem);
                    self.elem += 1;
                    let (x, z) = (e.x.saturating_add(self.shift.0), e.z.saturating_add(self.shift.1));
                    match e.kind {
                        Kind::Rapid => Move::rapid(x, z, Rule::G73Path),
                        Kind::Feed => Move::feed(x, z, self.w.feed, Rule::G73Path),
                        Kind::Arc(cw) => {
                            let (cx, cz) = (e.cx.saturating_add(self.shift.0), e.cz.saturating_add(self.shift.1));
                            Move::arc(cw, x, z, cx, cz, self.w.feed, Rule::G73Path)
                        }
                    }
                }
                Phase::Return => {
                    self.phase = Phase::Done;
                    Move::rapid(self.a.0, self.a.1, Rule::G73Path)
                }
                Phase::Done => return None,
            };
            if let Some(ev) = emit(m, pos) {
                return Some(ev);
            }
        }
    }
}

impl Cycle {
    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`]:
    /// each pass's contour elements (the bulk of the cycle) built in place from the contour
    /// buffer, every other event through `next_event`. How many, and whether the cycle is done.
    /// Bounded work: `out.len()` events and at most three skipped moves per pass change.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event], contour: &Contour) -> (usize, bool) {
        let mut n = 0;
        while n < out.len() {
            // The passes' events are built here, in place; the rapid to C, the return and the
            // end through `next_event` (once a cycle: its event comes back through memory).
            match self.phase {
                Phase::Header => {
                    if let Some(slot) = out.get_mut(n) {
                        *slot = self.pass_header();
                        n += 1;
                    }
                }
                Phase::ToStart => {
                    let m = self.rapid_to_start();
                    if let (Some(e), Some(slot)) = (emit(m, pos), out.get_mut(n)) {
                        *slot = e;
                        n += 1;
                    }
                }
                Phase::Contour if self.elem >= self.len => self.end_pass(),
                Phase::Contour => n += self.write_contour(pos, out.get_mut(n..).unwrap_or_default(), contour),
                _ => match (self.next_event(pos, contour), out.get_mut(n)) {
                    (Some(e), Some(slot)) => {
                        *slot = e;
                        n += 1;
                    }
                    _ => return (n, true),
                },
            }
        }
        (n, false)
    }

    /// The current pass's contour elements from `elem` on, while `out` has room: as
    /// `next_event`'s `Contour` phase. Returns how many events were written.
    #[inline]
    fn write_contour(&mut self, pos: &mut (i64, i64), out: &mut [Event], contour: &Contour) -> usize {
        let (sx, sz) = self.shift;
        let feed = self.w.feed;
        let elements = contour.elements().get(self.elem..self.len).unwrap_or_default();
        let mut at = *pos;
        let mut n = 0;
        for e in elements {
            let Some(slot) = out.get_mut(n) else {
                break;
            };
            self.elem += 1;
            let (x, z) = (e.x.saturating_add(sx), e.z.saturating_add(sz));
            // PRJ.NOOP, as `emit`: a move to where the tool stands is not written.
            if (x, z) == at {
                continue;
            }
            at = (x, z);
            *slot = Event::Move(match e.kind {
                Kind::Rapid => Move::rapid(x, z, Rule::G73Path),
                Kind::Feed => Move::feed(x, z, feed, Rule::G73Path),
                Kind::Arc(cw) => Move::arc(cw, x, z, e.cx.saturating_add(sx), e.cz.saturating_add(sz), feed, Rule::G73Path),
            });
            n += 1;
        }
        *pos = at;
        n
    }
}

#[cfg(test)]
mod tests;
