//! The running cycle: a small state machine that yields one trace event per call (PRJ.TRACE):
//! pass headers, then per start the moves of G92.PATH / G76.PATH, skipping moves to the current
//! position (PRJ.NOOP). No buffering: each move is computed from the pass geometry and a step
//! counter.

use crate::batch::Unit;
use crate::fixed::start_angle;
use crate::passes::{Cut, Multi};
use crate::pullout::{z_long, Offsets};
use cycle_vocab::{Event, Move, Pass, Rule};

/// What stays fixed for a whole cycle.
#[derive(Clone, Copy, Debug)]
pub struct Path {
    /// The start point A (X diameter).
    pub a: (i64, i64),
    /// Lead, lead counts.
    pub lead: i64,
    /// Number of starts L (≥ 1).
    pub starts: u32,
    /// G76.LEADIN: offset of the lead-in point from Bn on X, diameter (s·2E); 0 = no lead-in.
    pub leadin: i64,
    /// The pull-out, as offsets from the pass end; `None`: no pull-out.
    pub pull: Option<Offsets>,
    /// Rule of rapids and the thread cut.
    pub rule_path: Rule,
    /// Rule of the pull-out move.
    pub rule_pull: Rule,
}

/// The passes of a cycle.
#[derive(Clone, Copy, Debug)]
pub enum Plan {
    /// G92: one pass, with its header.
    Single(Pass),
    /// G76/G78: rough passes from the schedule, then the finishing passes.
    Multi(Multi),
}

/// A cycle being expanded.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    path: Path,
    plan: Plan,
    cut: Cut,
    /// The current pass's header is still to be emitted.
    header: bool,
    start: u32,
    /// The spindle start angle of `start` (COM.MULTISTART), computed once per start.
    angle: u32,
    step: u8,
}

/// Steps of one start: approach, lead-in, cut, pull-out, retract X, retract Z.
const STEPS: u8 = 6;

/// `p + d`. Pass points and offsets come from range-checked words (every term below 2^40), so
/// the sum never wraps; wrapping arithmetic keeps an impossible overflow from panicking.
fn add(p: (i64, i64), d: (i64, i64)) -> (i64, i64) {
    (p.0.wrapping_add(d.0), p.1.wrapping_add(d.1))
}

impl Cycle {
    /// A cycle whose first pass has the geometry `cut`.
    pub fn new(path: Path, plan: Plan, cut: Cut) -> Cycle {
        Cycle { path, plan, cut, header: true, start: 0, angle: 0, step: 0 }
    }

    /// The header of the current pass, made from the plan's state when it is written (not kept
    /// in a field written just before: the event is then built from values in registers).
    #[inline]
    fn header(&self) -> Event {
        match &self.plan {
            Plan::Single(h) => Event::Pass(*h),
            Plan::Multi(m) => Event::Pass(m.header()),
        }
    }

    /// The pending header, if any.
    #[inline]
    fn take_header(&mut self) -> Option<Event> {
        if !self.header {
            return None;
        }
        self.header = false;
        Some(self.header())
    }

    /// Where the cut of the current pass ends, after the pull-out if any.
    fn cut_exit(&self) -> (i64, i64) {
        match self.path.pull {
            Some(o) => add(self.cut.end, o.end),
            None => self.cut.end,
        }
    }

    /// The move of `step` for the current start, or `None` when the step has no move.
    #[inline]
    fn move_at(&self, step: u8) -> Option<Move> {
        let p = &self.path;
        let thread = |(x, z): (i64, i64), rule: Rule| Some(Move::thread(x, z, p.lead, self.angle, rule));
        match step {
            // G76.PATH / G92.PATH ①: rapid to the infeed point (to the lead-in point first).
            0 => {
                let (x, z) = self.cut.p0;
                Some(Move::rapid(x.wrapping_add(p.leadin), z, p.rule_path))
            }
            // G76.LEADIN: synchronized X move from the lead-in point to Bn.
            1 if p.leadin != 0 => thread(self.cut.p0, Rule::G76LeadIn),
            // ②: the cut, to the pull-out start or to the end.
            2 => match p.pull {
                Some(o) => thread(add(self.cut.end, o.start), p.rule_path),
                None => thread(self.cut.end, p.rule_path),
            },
            // G92.PULLOUT / G76.PULLOUT: the pull-out segment.
            3 => p.pull.and_then(|o| thread(add(self.cut.end, o.end), p.rule_pull)),
            // ③: rapid X back to A.x.
            4 => Some(Move::rapid(p.a.0, self.cut_exit().1, p.rule_path)),
            // ④: rapid Z back to A.z.
            5 => Some(Move::rapid(p.a.0, p.a.1, p.rule_path)),
            _ => None,
        }
    }

    /// What the operator layer reads after an event (G92.HOLD, G76.HOLD): the step of the last
    /// move emitted (0 approach, 1 lead-in, 2 cut, 3 pull-out, 4 rapid X, 5 rapid Z; a header
    /// leaves the step of the start it begins, 0), the start, and the pass's fixed geometry.
    pub fn state(&self) -> CutState {
        let pull = self.path.pull.map(|o| (add(self.cut.end, o.start), add(self.cut.end, o.end)));
        CutState {
            step: self.step.wrapping_sub(1),
            start: self.start,
            a: self.path.a,
            // COM.LONGAXIS as the pull-out was made: W = the cut's Z travel, R = its X travel
            // on radius (C.x − D.x = 2R for G92, Bn.x − En.x = 2i for G76/G78: exact halves).
            z_long: z_long(
                self.cut.end.1.wrapping_sub(self.cut.p0.1),
                self.cut.p0.0.wrapping_sub(self.cut.end.0) / 2,
            ),
            pull,
            g92: self.path.rule_path == Rule::G92Path,
        }
    }

    /// The next event of the cycle, updating the machine position; `None` when it is done.
    /// Bounded work: at most `STEPS` (6) skipped moves and one pass change per call.
    #[inline]
    pub fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        loop {
            if let Some(h) = self.take_header() {
                return Some(h);
            }
            if self.step >= STEPS {
                if !self.next_start() {
                    return None;
                }
                continue;
            }
            let mv = self.move_at(self.step);
            self.step += 1;
            if let Some(m) = mv {
                if let Some(e) = emit(m, pos) {
                    return Some(e);
                }
            }
        }
    }

    /// Moves on to the next start, or to the next pass after the last start; `false` when the
    /// cycle is done.
    fn next_start(&mut self) -> bool {
        self.step = 0;
        self.start = self.start.saturating_add(1);
        if self.start < self.path.starts {
            self.angle = start_angle(self.start, self.path.starts);
            return true;
        }
        self.start = 0;
        self.angle = 0;
        let Plan::Multi(multi) = &mut self.plan else {
            return false;
        };
        match multi.advance() {
            Some(cut) => {
                self.header = true;
                self.cut = cut;
                true
            }
            None => false,
        }
    }

    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`]:
    /// whole starts (pass header and moves) at a time while one fits, one event at a time
    /// otherwise. Returns how many were written and whether the cycle is done.
    /// Bounded work: [`START_EVENTS`] events and one pass change per start.
    #[inline]
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
        let mut n = 0;
        // A start begun by `next_event` is finished one event at a time.
        while self.step != 0 && self.step < STEPS {
            let Some(slot) = out.get_mut(n) else {
                return (n, false);
            };
            match self.next_event(pos) {
                Some(e) => {
                    *slot = e;
                    n += 1;
                }
                None => return (n, true),
            }
        }
        // Whole starts, the position kept in a local.
        let mut at = *pos;
        let mut done = false;
        while let Some(slots) = out.get_mut(n..).and_then(|r| r.first_chunk_mut::<START_EVENTS>()) {
            if self.step >= STEPS && !self.next_start() {
                done = true;
                break;
            }
            n += self.write_start(&mut at, slots);
        }
        *pos = at;
        if done {
            return (n, true);
        }
        // Less room than a start: one event at a time.
        while let Some(slot) = out.get_mut(n) {
            match self.next_event(pos) {
                Some(e) => {
                    *slot = e;
                    n += 1;
                }
                None => return (n, true),
            }
        }
        (n, false)
    }

    /// A cycle of one pass and one start (a G92 of L1): [`Cycle::write_new`] writes it whole.
    #[inline(always)]
    pub(crate) fn is_single(&self) -> bool {
        matches!(self.plan, Plan::Single(_)) && self.path.starts == 1
    }

    /// Writes a new cycle of one pass and one start ([`Cycle::is_single`]), all its events, into
    /// `slots` (as [`Cycle::fill`] would); how many. Taken by value, so that a cycle built just
    /// before is written from the values it was built from, never kept in memory.
    #[inline(always)]
    pub(crate) fn write_new(mut self, pos: &mut (i64, i64), slots: &mut [Event; START_EVENTS]) -> usize {
        let mut at = *pos;
        let n = self.write_start(&mut at, slots);
        *pos = at;
        n
    }

    /// Writes the pending pass header and the moves of the current start into `slots`; returns
    /// how many were written. The steps are unrolled, so each event is built in place.
    #[inline(always)]
    fn write_start(&mut self, pos: &mut (i64, i64), slots: &mut [Event; START_EVENTS]) -> usize {
        let mut unit = Unit::new(slots);
        if let Some(h) = self.take_header() {
            unit.put(h);
        }
        for step in 0..STEPS {
            unit.put_some(self.move_at(step).and_then(|m| emit(m, pos)));
        }
        self.step = STEPS;
        unit.written()
    }
}

/// A cycle's state as the operator layer reads it ([`Cycle::state`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CutState {
    /// The step of the last move emitted (see [`Cycle::state`]).
    pub step: u8,
    /// The start (0…L−1) of the pass being cut.
    pub start: u32,
    /// The start point A.
    pub a: (i64, i64),
    /// COM.LONGAXIS: Z is the long axis.
    pub z_long: bool,
    /// The pull-out of the current pass, start S and end E; `None`: no pull-out.
    pub pull: Option<((i64, i64), (i64, i64))>,
    /// A G92 cycle (else G76, G78 or FANUC G76).
    pub g92: bool,
}

/// The most events of one start: a pass header and one move per step.
pub const START_EVENTS: usize = 1 + STEPS as usize;

/// `m` as an event, updating the machine position; `None` for a move to the current position,
/// which is not emitted (PRJ.NOOP).
#[inline(always)]
pub fn emit(m: Move, pos: &mut (i64, i64)) -> Option<Event> {
    if (m.x, m.z) == *pos {
        return None;
    }
    *pos = (m.x, m.z);
    Some(Event::Move(m))
}
