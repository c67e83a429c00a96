//! The plain blocks of one kind read in a loop of their own ([`Core::fill_blocks`]): G90/G94
//! passes, G92 passes, G00/G01/G32–G34 moves. A plain block keeps the mode, so the plain
//! blocks after it are of its kind until another block comes; each loop is out of line, so
//! that it keeps its own values in registers and its code together.
//!
//! Each loop reads the block in `Core::block` (a plain block of its kind), writes what it runs
//! into `out` from `n` on, then reads the next block while `out` has room. It returns how far
//! `out` is written, and `None` when the block read is not a plain block of its kind (for
//! [`Core::fill_blocks`] to read), else what the call returns.

use super::Core;
use crate::emit::{emit, START_EVENTS};
use crate::g90::{CutCode, CUT_EVENTS};
use crate::modal::{Machine, Plain};
use crate::run::Run;
use cycle_vocab::{Alarm, Event};

/// How far `out` is written, and what the call returns (`None`: a block of another kind).
pub(super) type RunEnd = (usize, Option<Result<bool, Alarm>>);

/// The end of each loop's round: the next block read if `out` has room left, the loop going on
/// while it is a plain block of the loop's kind (a plain block leaves the mode and the dialect as
/// it found them, `Machine::plain_again`); else the loop returns. A macro, not a method: a method
/// returning how the loop ends costs the loops 7 instructions a block more (callgrind).
macro_rules! next_plain {
    ($core:ident, $out:ident, $n:ident) => {
        if let Err(r) = $core.advance($out.len() > $n) {
            return ($n, Some(r));
        }
        if !Machine::plain_again(&$core.block) {
            return ($n, None);
        }
    };
}

impl Core<'_> {
    /// G90/G94 passes of the mode `code`: each cycle written whole where it fits; one that does
    /// not fit is left in `run` and ends the call ([`Core::fill`] runs it next).
    #[inline(never)]
    pub(super) fn cut_run(&mut self, code: CutCode, out: &mut [Event], mut n: usize) -> RunEnd {
        #[cfg(test)]
        crate::probe::count_run();
        let places = self.machine.config.grid.decimals();
        loop {
            match self.machine.plain_cut(code, &self.block, places) {
                Ok(Some(cycle)) => match out.get_mut(n..).and_then(|r| r.first_chunk_mut::<CUT_EVENTS>()) {
                    Some(slots) => n += cycle.write_new(&mut self.machine.pos, slots),
                    None => {
                        self.run = Run::Cut(cycle);
                        return (n, Some(Ok(true)));
                    }
                },
                Ok(None) => {}
                Err(a) => return (n, Some(self.fail_with(a))),
            }
            next_plain!(self, out, n);
        }
    }

    /// G92 passes: a pass of one start written whole where it fits; several starts, or less
    /// room, left in `run`, ending the call.
    #[inline(never)]
    pub(super) fn g92_run(&mut self, out: &mut [Event], mut n: usize) -> RunEnd {
        #[cfg(test)]
        crate::probe::count_run();
        let places = self.machine.config.grid.decimals();
        loop {
            match self.machine.plain_g92(&self.block, places) {
                Ok(Some(cycle)) => match out.get_mut(n..).and_then(|r| r.first_chunk_mut::<START_EVENTS>()) {
                    Some(slots) if cycle.is_single() => n += cycle.write_new(&mut self.machine.pos, slots),
                    _ => {
                        self.run = Run::Multipass(cycle);
                        return (n, Some(Ok(true)));
                    }
                },
                Ok(None) => {}
                Err(a) => return (n, Some(self.fail_with(a))),
            }
            next_plain!(self, out, n);
        }
    }

    /// G00/G01/G32–G34 moves of the kind `plain`: each move written straight into the next
    /// slot (none for a move to where the machine stands, PRJ.NOOP).
    #[inline(never)]
    pub(super) fn move_run(&mut self, plain: Plain, out: &mut [Event], mut n: usize) -> RunEnd {
        #[cfg(test)]
        crate::probe::count_run();
        let places = self.machine.config.grid.decimals();
        loop {
            match self.machine.plain_move(plain, &self.block, places) {
                Ok(Some(m)) => {
                    if let (Some(e), Some(slot)) = (emit(m, &mut self.machine.pos), out.get_mut(n)) {
                        *slot = e;
                        n += 1;
                    }
                }
                Ok(None) => {}
                Err(a) => return (n, Some(self.fail_with(a))),
            }
            next_plain!(self, out, n);
        }
    }
}

#[cfg(test)]
mod tests;
