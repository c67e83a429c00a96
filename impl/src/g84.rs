//! G84, rigid tapping along Z at the current X, read as FANUC lathe controls do (M003;
//! docs/INTERPRETATION.md, "G83 and G84"): the lead (F under G99; F / S rounded once on the lead
//! grid under G98) and the path (G84.PATH): rapid to the R level, one synchronized thread move to
//! the bottom, the dwell P, the spindle reversed, the thread move back to the R level at the same
//! lead, the spindle forward, a rapid to the initial level. Eight events at most; O(1) state.

use crate::batch::{self, Batch, Unit};
use crate::emit::emit;
use crate::fixed::div_round;
use crate::g83::{Levels, Words};
use cycle_vocab::{Alarm, AlarmCode, Dwell, Event, Move, Rule, Spindle, SpindleState};

/// A G84 cycle whose checks passed.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    lv: Levels,
    lead: i64,
    dwell: u32,
    step: u8,
}

/// G84.FORMAT: the lead from the feed `f` (lead counts) — under G98 (`per_minute`) F / S
/// exactly, rounded half up once on the lead grid, where a lead that rounds to 0 is
/// `OUT OF RANGE` on F — then the levels (`GEOMETRY` on Z when the bottom is the R level).
pub fn cycle(a: (i64, i64), w: &Words, speed: Option<i64>, line: u32) -> Result<Cycle, Alarm> {
    let Words { r, bottom, dwell, feed: f, .. } = *w;
    let lead = match speed {
        None => f,
        Some(s) => {
            let lead = i64::try_from(div_round(f.unsigned_abs().into(), s.unsigned_abs().into())).unwrap_or(i64::MAX);
            if lead == 0 {
                return Err(Alarm::new(AlarmCode::OutOfRange, Some(b'F'), Rule::G84Format, line));
            }
            lead
        }
    };
    let lv = Levels::new(a, r, bottom, Rule::G84Format, line)?;
    Ok(Cycle { lv, lead, dwell, step: 0 })
}

impl Cycle {
    /// The next event, updating the machine position; `None` when the cycle is done. PRJ.NOOP:
    /// a move to the current position is not emitted. Bounded work: eight steps at most.
    pub fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        let rule = Rule::G84Path;
        let spindle = |state| Some(Event::Spindle(Spindle { state, rule }));
        loop {
            let step = self.step;
            self.step = self.step.saturating_add(1);
            let m = match step {
                0 => return Some(self.lv.header(rule)),
                1 => Move::rapid(self.lv.x, self.lv.r_level, rule),
                2 => Move::thread(self.lv.x, self.lv.bottom, self.lead, 0, rule),
                3 if self.dwell > 0 => return Some(Event::Dwell(Dwell { ms: self.dwell, rule })),
                3 => continue,
                4 => return spindle(SpindleState::Reverse),
                5 => Move::thread(self.lv.x, self.lv.r_level, self.lead, 0, rule),
                6 => return spindle(SpindleState::Forward),
                7 => Move::rapid(self.lv.x, self.lv.initial, rule),
                _ => return None,
            };
            if let Some(e) = emit(m, pos) {
                return Some(e);
            }
        }
    }
}

/// The most events of a tap: its header and seven steps.
const TAP_EVENTS: usize = 8;

impl Batch<TAP_EVENTS> for Cycle {
    fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        Cycle::next_event(self, pos)
    }

    fn begun(&self) -> bool {
        self.step != 0 && usize::from(self.step) < TAP_EVENTS
    }

    fn ready(&mut self) -> bool {
        self.step == 0
    }

    /// The whole tap, as `next_event`'s steps 0…7, each event built in place.
    #[inline(always)]
    fn write_unit(&mut self, pos: &mut (i64, i64), slots: &mut [Event; TAP_EVENTS]) -> usize {
        let rule = Rule::G84Path;
        let lv = self.lv;
        let mut unit = Unit::new(slots);
        unit.put(lv.header(rule));
        unit.put_some(emit(Move::rapid(lv.x, lv.r_level, rule), pos));
        unit.put_some(emit(Move::thread(lv.x, lv.bottom, self.lead, 0, rule), pos));
        if self.dwell > 0 {
            unit.put(Event::Dwell(Dwell { ms: self.dwell, rule }));
        }
        unit.put(Event::Spindle(Spindle { state: SpindleState::Reverse, rule }));
        unit.put_some(emit(Move::thread(lv.x, lv.r_level, self.lead, 0, rule), pos));
        unit.put(Event::Spindle(Spindle { state: SpindleState::Forward, rule }));
        unit.put_some(emit(Move::rapid(lv.x, lv.initial, rule), pos));
        self.step = TAP_EVENTS as u8;
        unit.written()
    }
}

impl Cycle {
    /// Writes the tap's next events into `out`, the same events as [`Cycle::next_event`], the
    /// whole tap at once where it fits ([`batch::fill`]); how many, and whether it is done.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
        batch::fill(self, pos, out)
    }
}
