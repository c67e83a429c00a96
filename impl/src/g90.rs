//! G90 and G94 single cutting cycles (M003; docs/INTERPRETATION.md, "G90 and G94"): the modal
//! run (G90.MODAL, G94.MODAL), the cycle's checks (step 5) and its four moves (G90.PATH,
//! G94.PATH), all in integers.
//!
//! Bounds: X, U, Z, W, I, K are words with |v| ≤ N = 999 999 999 and every position the
//! expander reaches stays far inside ±2^61 (a block moves at most 2N), so every sum and
//! difference below is exact in `i64`; saturating operations only keep an impossible overflow
//! from panicking.

use crate::batch::{self, Batch, Unit};
use crate::emit::emit;
use crate::fixed::abs_diff;
use cycle_vocab::{Alarm, AlarmCode, Event, Move, Pass, PassKind, Rule};

/// Which cutting cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CutCode {
    /// Along Z (outer/inner diameter), taper I on X.
    G90,
    /// Along X (face), taper K on Z.
    G94,
}

impl CutCode {
    /// The cycle's format, path and taper rules.
    const fn rules(self) -> (Rule, Rule, Rule) {
        match self {
            CutCode::G90 => (Rule::G90Format, Rule::G90Path, Rule::G90Taper),
            CutCode::G94 => (Rule::G94Format, Rule::G94Path, Rule::G94Taper),
        }
    }
}

/// G90.MODAL / G94.MODAL: what a run keeps when a block omits it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CutState {
    /// The end point D of the run (X diameter, Z), absolute.
    pub end: (i64, i64),
    /// G90: I (radius); G94: k = C.z − D.z, the K word as the declared reading g94.k reads it
    /// (−K under the letter `end-minus-start`, K under `start-minus-end`). Increments.
    pub taper: i64,
    /// Cycles cut in this run.
    pub index: u32,
}

impl CutState {
    pub const fn new() -> CutState {
        CutState { end: (0, 0), taper: 0, index: 0 }
    }

    /// A new run (the code written after another motion mode): taper 0, omitted end
    /// coordinates at the current position.
    pub fn new_run(&mut self, pos: (i64, i64)) {
        *self = CutState { end: pos, taper: 0, index: 0 };
    }
}

/// A cycle being expanded: its pass header, then ① rapid to the cut start, ② feed to D,
/// ③ feed back to the start's X (G90) or Z (G94), ④ rapid back to A. The machine ends at A.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    /// The pass header is still to be emitted. The header is built from `index`, `depth` and
    /// `rule_path` when it is written (not kept as a `Pass` written just before: the event is
    /// then built from values in registers, not re-read across narrower stores).
    header: bool,
    /// The pass index within the run and its depth (diameter, increments).
    index: u32,
    depth: i64,
    /// Ends of ① (the cut start), ② (D), ③, ④ (A).
    cut_start: (i64, i64),
    end: (i64, i64),
    back: (i64, i64),
    a: (i64, i64),
    feed: i64,
    /// Rule of ① (the taper rule when there is a taper) and of ②–④.
    rule_start: Rule,
    rule_path: Rule,
    step: u8,
}

/// Moves of one cycle.
const STEPS: u8 = 4;

/// `a − b`, `a + b`, saturating (exact within the module's bounds).
fn sub(a: i64, b: i64) -> i64 {
    a.saturating_sub(b)
}

fn add(a: i64, b: i64) -> i64 {
    a.saturating_add(b)
}

/// G90.TAPER / G94.TAPER: a taper `t` and travel `travel` of different signs need
/// |t| ≤ |travel| (both on the same scale).
fn taper_fits(t: i64, travel: i64) -> bool {
    t == 0 || travel == 0 || (t < 0) == (travel < 0) || t.unsigned_abs() <= travel.unsigned_abs()
}

/// One cycle from `a` (the position when the block is read) with the run's end point and
/// taper and the modal `feed`: step 5 in the register's order — G90: W = 0 (G90.FORMAT), then
/// the taper (G90.TAPER); G94: U = 0 (G94.FORMAT), then the taper (G94.TAPER) — then the pass
/// (index within the run, kind ROUGH, depth = the infeed of ①).
#[inline(always)]
pub fn cycle(code: CutCode, st: &CutState, a: (i64, i64), feed: i64, line: u32) -> Result<Cycle, Alarm> {
    let (rule_format, rule_path, rule_taper) = code.rules();
    let geometry = |word: u8, rule: Rule| Alarm::new(AlarmCode::Geometry, Some(word), rule, line);
    let d = st.end;
    let t = st.taper;
    let (cut_start, back, diameter_depth) = match code {
        CutCode::G90 => {
            // W = D.z − A.z = 0.
            if d.1 == a.1 {
                return Err(geometry(b'Z', rule_format));
            }
            // I is a radius: 2|I| ≤ |U| on diameter (U = D.x − A.x, diameter).
            if t != 0 && !taper_fits(t.saturating_mul(2), sub(d.0, a.0)) {
                return Err(geometry(b'I', rule_taper));
            }
            // C.x = D.x + 2I: ① rapid X to C.x; ③ feed X back to A.x at D.z.
            let cx = add(d.0, t.saturating_mul(2));
            ((cx, a.1), (a.0, d.1), abs_diff(a.0, cx))
        }
        CutCode::G94 => {
            // U = D.x − A.x = 0.
            if d.0 == a.0 {
                return Err(geometry(b'X', rule_format));
            }
            // W = D.z − A.z.
            if t != 0 && !taper_fits(t, sub(d.1, a.1)) {
                return Err(geometry(b'K', rule_taper));
            }
            // C.z = D.z + k (k = C.z − D.z, G94.TAPER): ① rapid Z to C.z; ③ feed Z back to A.z
            // at D.x. The Z depth is printed as a radius: diameter_depth = 2·|A.z − C.z|.
            let cz = add(d.1, t);
            ((a.0, cz), (d.0, a.1), abs_diff(a.1, cz).saturating_mul(2))
        }
    };
    Ok(Cycle {
        header: true,
        index: st.index,
        depth: diameter_depth,
        cut_start,
        end: d,
        back,
        a,
        feed,
        rule_start: if t != 0 { rule_taper } else { rule_path },
        rule_path,
        step: 0,
    })
}

impl Cycle {
    /// The pass header (index within the run, kind ROUGH, depth = the infeed of ①), if it is
    /// still to be emitted; it is then emitted.
    #[inline(always)]
    fn take_header(&mut self) -> Option<Pass> {
        if !self.header {
            return None;
        }
        self.header = false;
        Some(Pass { index: self.index, kind: PassKind::Rough, diameter_depth: self.depth, rule: self.rule_path })
    }

    /// The move of `step` (G90.PATH / G94.PATH ①–④).
    fn move_at(&self, step: u8) -> Option<Move> {
        let p = self.rule_path;
        match step {
            0 => Some(Move::rapid(self.cut_start.0, self.cut_start.1, self.rule_start)),
            1 => Some(Move::feed(self.end.0, self.end.1, self.feed, p)),
            2 => Some(Move::feed(self.back.0, self.back.1, self.feed, p)),
            3 => Some(Move::rapid(self.a.0, self.a.1, p)),
            _ => None,
        }
    }

    /// The next event, updating the machine position; `None` when the cycle is done. A move
    /// to the current position is not emitted (PRJ.NOOP). Bounded work: at most four skipped
    /// moves per call.
    pub fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        if let Some(h) = self.take_header() {
            return Some(Event::Pass(h));
        }
        while self.step < STEPS {
            let mv = self.move_at(self.step);
            self.step += 1;
            if let Some(e) = mv.and_then(|m| emit(m, pos)) {
                return Some(e);
            }
        }
        None
    }
}

/// The most events of a cycle: its header and four moves.
pub(crate) const CUT_EVENTS: usize = 1 + STEPS as usize;

impl Batch<CUT_EVENTS> for Cycle {
    fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        Cycle::next_event(self, pos)
    }

    fn begun(&self) -> bool {
        !self.header && self.step < STEPS
    }

    fn ready(&mut self) -> bool {
        self.step < STEPS
    }

    /// The header and the four moves, unrolled, each event built in place.
    #[inline(always)]
    fn write_unit(&mut self, pos: &mut (i64, i64), slots: &mut [Event; CUT_EVENTS]) -> usize {
        let mut unit = Unit::new(slots);
        if let Some(h) = self.take_header() {
            unit.put(Event::Pass(h));
        }
        for step in 0..STEPS {
            unit.put_some(self.move_at(step).and_then(|m| emit(m, pos)));
        }
        self.step = STEPS;
        unit.written()
    }
}

impl Cycle {
    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`], the
    /// whole cycle at once where it fits ([`batch::fill`]); how many, and whether it is done.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
        batch::fill(self, pos, out)
    }

    /// Writes a new cycle's events, all of them, into `slots` (as [`Cycle::fill`] would: the
    /// header, then each move that moves, PRJ.NOOP); how many. The cycle is taken by value and
    /// each event built in its slot from the cycle's values, so that nothing of it is kept in
    /// memory on the way (a cycle that does not fit is run from [`crate::run::Run`] instead).
    #[inline(always)]
    pub(crate) fn write_new(self, pos: &mut (i64, i64), slots: &mut [Event; CUT_EVENTS]) -> usize {
        let [head, slots @ ..] = slots;
        *head = Event::Pass(Pass { index: self.index, kind: PassKind::Rough, diameter_depth: self.depth, rule: self.rule_path });
        let mut at = *pos;
        let mut n = 0;
        let mut put = |m: Move| {
            // PRJ.NOOP, as `emit`: a move to where the machine stands is not written.
            if (m.x, m.z) != at {
                at = (m.x, m.z);
                if let Some(slot) = slots.get_mut(n) {
                    *slot = Event::Move(m);
                }
                n += 1;
            }
        };
        let p = self.rule_path;
        put(Move::rapid(self.cut_start.0, self.cut_start.1, self.rule_start));
        put(Move::feed(self.end.0, self.end.1, self.feed, p));
        put(Move::feed(self.back.0, self.back.1, self.feed, p));
        put(Move::rapid(self.a.0, self.a.1, p));
        *pos = at;
        1 + n
    }
}

#[cfg(test)]
mod tests;
