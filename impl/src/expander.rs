//! The expander: the uninterrupted stream of [`Core`], through the operator layer when the
//! configuration has a script (OP.SCRIPT).

use crate::operator;
use crate::run::Run;
use crate::stream::Core;
use cycle_vocab::{Alarm, Config, Event};

/// Streaming expansion of a program: one trace event per call of `next`, the alarm last.
///
/// With an operator script (`Config::operator`, OP.SCRIPT) the events are those of the
/// interrupted run (`operator`): the uninterrupted stream of `Core` passes through the
/// operator layer. With an empty script the layer is never entered: one branch per event.
pub struct Expander<'a> {
    core: Core<'a>,
    /// The script is not empty: events go through [`operator::Layer`].
    operated: bool,
    op: operator::Layer,
}

impl<'a> Expander<'a> {
    pub fn new(program: &'a [u8], config: Config) -> Expander<'a> {
        Expander {
            core: Core::new(program, config),
            operated: !config.operator.is_empty(),
            op: operator::Layer::new(&config),
        }
    }

    /// Writes the next events of the stream into `out` and returns how many: the same events,
    /// in the same order, as the iterator, for a caller that keeps them in a buffer. Whatever
    /// runs writes into `out` directly (`Run::fill`), each event built in place: a G92/G76/G78
    /// cycle whole starts at a time, G162 whole passes, G84 a whole tap, G90/G94 the whole
    /// cycle, G74/G75/G83 their pecks, G70/G71/G72/G73 their contour walks. With an operator
    /// script, one event at a time.
    ///
    /// Fewer than `out.len()` events (0 included) means the stream ended, or an alarm follows:
    /// the alarm is returned by the next call as `Err`, after which the stream is over.
    pub fn fill(&mut self, out: &mut [Event]) -> Result<usize, Alarm> {
        if !self.operated {
            return self.core.fill(out);
        }
        self.op.fill(&mut self.core, out)
    }
}

impl Iterator for Expander<'_> {
    type Item = Result<Event, Alarm>;

    /// The hot path — the next move of a running G92/G76/G78 cycle — is small enough to inline
    /// into the caller's loop, so the event is written straight to where the caller keeps it;
    /// everything else is `Core::next_slow`, which dispatches on `Run`.
    /// With an operator script: one branch, then the operator layer (`operator::Layer`).
    #[inline]
    fn next(&mut self) -> Option<Self::Item> {
        if self.operated {
            return self.op.next(&mut self.core);
        }
        let core = &mut self.core;
        if let Run::Multipass(c) = &mut core.run {
            if let Some(e) = c.next_event(&mut core.machine.pos) {
                return Some(Ok(e));
            }
            // The cycle is done (a cycle is not fused: it must not be asked again).
            core.run = Run::Idle;
        }
        core.next_slow()
    }
}
