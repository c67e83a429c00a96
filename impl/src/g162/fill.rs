//! G162's batch path ([`crate::Expander::fill`]): whole passes, header and five moves, written
//! straight into the caller's buffer ([`batch::fill`]).

use super::{Cycle, STEPS};
use crate::batch::{self, Batch, Unit};
use crate::emit::emit;
use cycle_vocab::Event;

/// The most events of one pass: its header and five moves.
const PASS_EVENTS: usize = 1 + STEPS as usize;

impl Batch<PASS_EVENTS> for Cycle {
    fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        Cycle::next_event(self, pos)
    }

    fn begun(&self) -> bool {
        !self.header && self.step < STEPS
    }

    fn ready(&mut self) -> bool {
        if self.step < STEPS {
            return true;
        }
        match self.next_pass() {
            Some(pass) => {
                self.begin(pass);
                true
            }
            None => false,
        }
    }

    /// The pass's header and moves, unrolled, each event built in place.
    #[inline(always)]
    fn write_unit(&mut self, pos: &mut (i64, i64), slots: &mut [Event; PASS_EVENTS]) -> usize {
        let mut unit = Unit::new(slots);
        if self.header {
            self.header = false;
            unit.put(Event::Pass(self.pass_header()));
        }
        for step in 0..STEPS {
            unit.put_some(self.move_at(step).and_then(|m| emit(m, pos)));
        }
        self.step = STEPS;
        unit.written()
    }
}

impl Cycle {
    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`],
    /// whole passes at a time ([`batch::fill`]); how many, and whether the cycle is done.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
        batch::fill(self, pos, out)
    }
}

