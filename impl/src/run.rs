//! The running part of a block (PRJ.TRACE): one enum over every family the expander carries
//! out, each a small state machine that yields one event per call (`next_event`) or writes its
//! next events straight into the caller's buffer (`fill`). [`crate::Expander`] dispatches on it.

use crate::contour::Contour;
use crate::emit::{self, emit};
use crate::finish;
use crate::g162;
use crate::g73;
use crate::g74;
use crate::g83;
use crate::g84;
use crate::g90;
use crate::rough::Roughing;
use cycle_vocab::{Event, Move};

/// What a block asks of the expander while it is carried out.
// No heap: the running state is moved once into the expander; boxing is not an option.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug)]
pub enum Run {
    /// Nothing running: the next block is read.
    Idle,
    /// One move not yet emitted: G00/G01 (PRJ.MODAL) or a thread move G32/G33/G34.
    Move(Move),
    /// A G92, G76 or G78 cycle (G92.PATH, G76.PATH): whole starts at a time.
    Multipass(emit::Cycle),
    /// A G162 cycle (G162.PATH).
    G162(g162::Cycle),
    /// A G90 or G94 cycle (G90.PATH, G94.PATH).
    Cut(g90::Cycle),
    /// A G71 or G72 cycle (G71.LAYER …): its geometry and cursor; the contour is the expander's.
    Rough(Roughing),
    /// A G70 cycle (G70.PATH).
    Finish(finish::Cycle),
    /// A G74 or G75 cycle (G74.PECK, G74.COLUMN, G75.*).
    Peck(g74::Cycle),
    /// A G73 cycle (G73.PATH): its pass and cursor; the contour is the expander's.
    Pattern(g73::Cycle),
    /// A G83 cycle (G83.PECK).
    Drill(g83::Cycle),
    /// A G84 cycle (G84.PATH).
    Tap(g84::Cycle),
}

impl Run {
    /// The next event, updating the machine position `pos`; `None` when the family is done
    /// (it must then not be asked again: the caller makes it [`Run::Idle`]). Bounded work: each
    /// family's own bound.
    pub fn next_event(&mut self, pos: &mut (i64, i64), contour: &Contour) -> Option<Event> {
        match self {
            Run::Idle => None,
            Run::Move(m) => {
                let m = *m;
                *self = Run::Idle;
                emit(m, pos)
            }
            Run::Multipass(c) => c.next_event(pos),
            Run::G162(c) => c.next_event(pos),
            Run::Cut(c) => c.next_event(pos),
            Run::Rough(c) => c.next_event(pos, contour),
            Run::Finish(c) => c.next_event(pos, contour),
            Run::Peck(c) => c.next_event(pos),
            Run::Pattern(c) => c.next_event(pos, contour),
            Run::Drill(c) => c.next_event(pos),
            Run::Tap(c) => c.next_event(pos),
        }
    }

    /// Writes the next events into `out`, the same events as [`Run::next_event`]; returns how
    /// many and whether the family is done (then the caller makes it [`Run::Idle`]). `out` is
    /// not empty. Kept out of line: [`crate::Expander::fill`] inlines the G92/G76/G78 arm, the
    /// hot path, itself.
    #[inline(never)]
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event], contour: &Contour) -> (usize, bool) {
        match self {
            Run::Idle => (0, true),
            Run::Multipass(c) => c.fill(pos, out),
            Run::G162(c) => c.fill(pos, out),
            Run::Cut(c) => c.fill(pos, out),
            Run::Rough(c) => c.fill(pos, out, contour),
            Run::Finish(c) => c.fill(pos, out, contour),
            Run::Peck(c) => c.fill(pos, out),
            Run::Pattern(c) => c.fill(pos, out, contour),
            Run::Drill(c) => c.fill(pos, out),
            Run::Tap(c) => c.fill(pos, out),
            Run::Move(m) => {
                let m = *m;
                let Some(slot) = out.first_mut() else {
                    return (0, false);
                };
                *self = Run::Idle;
                match emit(m, pos) {
                    Some(e) => {
                        *slot = e;
                        (1, true)
                    }
                    None => (0, true),
                }
            }
        }
    }
}
