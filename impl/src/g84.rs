//! G84, rigid tapping along Z at the current X, read as FANUC lathe controls do (M003;
//! docs/INTERPRETATION.md, "G83 and G84"): the lead (F under G99; F / S rounded once on the lead
//! grid under G98) and the path (G84.PATH): rapid to the R level, one synchronized thread move to
//! the bottom, the dwell P, the spindle reversed, the thread move back to the R level at the same
//! lead, the spindle forward, a rapid to the initial level. Eight events at most; O(1) state.

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
