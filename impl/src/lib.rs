//! Production expander of the lathe thread cycles G92, G76, G78, FANUC-style G76 and G162
//! (`nc201`), of the thread moves G32, G33, G34, of the single cutting cycles G90, G94, of arcs
//! G02/G03, of the contour cycles G70, G71, G72 and of the canned cycles G73, G74, G75, G83, G84
//! (M003).
//!
//! `no_std`, no heap, no floating point, no `unsafe`, no panics: [`Expander`] is a streaming
//! iterator over the trace events of a program (PRJ.TRACE), computed on the integer grid with
//! exact fixed-point arithmetic ([`fixed`]); [`Expander::fill`] writes the same stream into a
//! caller's buffer, a whole start of a cycle at a time. The rules and every interpretation are those of
//! `docs/RULES.md` and `docs/INTERPRETATION.md`; each rule-implementing function cites its ID.
//!
//! Modules: [`lex`] (the program lexer) and [`number`] (numbers as written, scaled exactly),
//! [`schedule`] (rough-pass depths), [`fixed`] (exact integer helpers and the tangent table),
//! `words` (word values and ranges), `modal` (block interpreter and check order), `run` (the
//! enum of everything that runs, dispatched by [`Expander`]), `g92`, `multipass` (G76/G78),
//! `pullout`, `emit` (the per-pass move state machine of G92/G76/G78), [`g162`] (depth split,
//! checks and its own move state machine), `thread_move` (G32/G33/G34), `g90` (G90/G94),
//! [`arc`] (G02/G03: centres, tolerance, sweeps, exact roundings), [`contour`] (the contour
//! buffer, CNT.FIND for G70), `rough` (G71/G72: checks, layer count, layers, semi-finish pass),
//! `finish` (G70), `g73` (pattern repeating over the contour buffer), `g74` (G74/G75 pecks and
//! columns), `g83` (peck drilling), `g84` (rigid tapping), `sub` (subprograms M98/M99: the call
//! stack, the area and its search), `config`;
//! `operator` (operator events: feed hold, cycle start, single block, reset — OP.SCRIPT —
//! between the generators and the caller).
//!
//! **Memory.** An [`Expander`] holds the block being read (~0.5 KB), the machine state, what
//! runs, the subprogram call stack (`sub`: 4 frames, 248 bytes; SUB.NEST), and the contour
//! buffer of the contour cycles: [`contour::MAX_BLOCKS`] (CNT.MAX, 1 000) elements of 48 bytes,
//! 48 000 bytes, initialised on the first contour cycle (a program without one writes none of
//! it; G73 shares it). Nothing else grows with the program:
//! the canned cycles keep O(1) state (their pass, column, peck) and count their passes in closed
//! form before any motion. The operator layer (`operator`, OP.SCRIPT) holds its script
//! (16 actions), the events of one cut (`emit::START_EVENTS` = 7, for the repeat after a
//! G92.HOLD/G76.HOLD retract), one event of look-ahead and an output queue of 8 events:
//! 2 344 bytes, fixed.
//!
//! **Magnitudes.** Every word and parameter is at most N = 999 999 999 < 2^30 increments
//! (COM.RANGES) and the start point too, so a block moves the machine by at most N from where it
//! stands (an absolute word puts it within N of 0; a cycle returns to its start after excursions
//! below 2^52): after B blocks every position is below (B + 1)·N, under 2^61 for any program of
//! fewer than 2^31 blocks (over 20 GB of text; B counts the blocks run — a subprogram's once per
//! run, at most `max_passes` runs, PRJ.MAXPASS). The arithmetic is written, and its bounds proved
//! in each module, for positions below 2^62; beyond, it saturates (never wraps, never panics).
#![no_std]
#![forbid(unsafe_code)]
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::indexing_slicing,
        clippy::panic,
        clippy::unreachable,
        clippy::float_arithmetic
    )
)]

pub mod arc;
pub mod config;
pub mod contour;
mod emit;
pub mod family;
mod finish;
pub mod fixed;
mod g73;
/// G74/G75 peck cycles (public for the proof harness `peck_counts`).
pub mod g74;
mod g83;
mod g84;
pub mod g162;
/// Public (hidden) only so that the proof harnesses (`cycle-proofs`) can drive one G90/G94 cycle
/// below the lexer; not part of the API.
#[doc(hidden)]
#[allow(clippy::new_without_default)]
pub mod g90;
mod g92;
pub mod lex;
mod modal;
mod multipass;
pub mod number;
mod operator;
/// The feed-hold retract as a pure function (G92.HOLD, G76.HOLD), for the proofs.
pub use operator::geometry as hold_geometry;
/// Public (hidden) only so that the proof harnesses (`cycle-proofs`) can check the G92 pull-out
/// amounts and geometry below the lexer; not part of the API.
#[doc(hidden)]
pub mod pullout;
/// Public (hidden) only so that the proof harnesses (`cycle-proofs`) can drive one G71/G72 cycle's
/// layer schedule below the lexer (`g71_layers`); not part of the API.
#[doc(hidden)]
pub mod rough;
mod run;
pub mod schedule;
mod sub;
mod thread_move;
mod words;

use contour::Contour;
use cycle_vocab::{Alarm, Config, Event};
use lex::{Block, Blocks};

/// N: the largest length of any word or parameter, increments (COM.RANGES).
pub use words::MAX_LENGTH;
use modal::Machine;
use run::Run;

/// Streaming expansion of a program: one trace event per call of `next`, the alarm last.
///
/// With an operator script (`Config::operator`, OP.SCRIPT) the events are those of the
/// interrupted run ([`operator`]): the uninterrupted stream of [`Core`] passes through the
/// operator layer. With an empty script the layer is never entered: one branch per event.
pub struct Expander<'a> {
    core: Core<'a>,
    /// The script is not empty: events go through [`operator::Layer`].
    operated: bool,
    op: operator::Layer,
}

/// The uninterrupted expansion (the trace U of OP.SCRIPT): blocks in, events out.
pub(crate) struct Core<'a> {
    blocks: Blocks<'a>,
    /// The block being read, built in place by the lexer.
    block: Block,
    machine: Machine,
    /// What the last block asked for while it is carried out: a running cycle, a move not yet
    /// returned, or nothing ([`Run`]). The block interpreter writes it in place.
    run: Run,
    /// The configuration has been checked.
    checked: bool,
    /// M02/M30 was read: nothing after that block.
    ended: bool,
    /// The stream is over (end of program or after an alarm).
    done: bool,
    /// An alarm that [`Expander::fill`] met after writing events, returned by the next call.
    pending: Option<Alarm>,
    /// The contour of the G70/G71/G72 cycle being carried out (CNT.MAX: at most
    /// [`contour::MAX_BLOCKS`] elements, 48 000 bytes, initialised on first use). It lives here,
    /// outside [`Run`], so that it is written once, in place, by the contour reader and never
    /// copied: `Run` is moved by value; the running cycle keeps only its cursor.
    contour: Contour,
    /// The subprogram call stack (SUB.*: four frames, fixed); `blocks` reads the running
    /// program, main or subprogram.
    calls: sub::Calls,
}

/// What the block interpreter may read besides the block: the running program's reader (a
/// G71/G72 reads its contour ahead; a G70 reads the running program again from its first block,
/// `origin`), the contour buffer, and whether a subprogram runs (SUB.RETURN).
pub(crate) struct Program<'p, 'a> {
    pub blocks: &'p mut Blocks<'a>,
    pub contour: &'p mut Contour,
    /// Where the running program's first block stands: the text's start, or the running
    /// subprogram's O block (CNT.FIND).
    pub origin: lex::Mark,
    pub in_subprogram: bool,
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
    /// runs writes into `out` directly (`Run::fill`): a G92/G76/G78 cycle whole starts at a
    /// time, each event built in place. With an operator script, one event at a time.
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

impl<'a> Core<'a> {
    fn new(program: &'a [u8], config: Config) -> Core<'a> {
        Core {
            blocks: Blocks::new(program),
            block: Block::new(),
            machine: Machine::new(config),
            run: Run::Idle,
            checked: false,
            ended: false,
            done: false,
            pending: None,
            contour: Contour::new(),
            calls: sub::Calls::new(program),
        }
    }

    fn fail(&mut self, alarm: Alarm) -> Option<Result<Event, Alarm>> {
        self.done = true;
        self.run = Run::Idle;
        Some(Err(alarm))
    }

    /// [`Expander::fill`] without an operator script.
    fn fill(&mut self, out: &mut [Event]) -> Result<usize, Alarm> {
        let mut n = 0;
        while let Some(rest) = out.get_mut(n..).filter(|r| !r.is_empty()) {
            let pos = &mut self.machine.pos;
            let (written, done) = match &mut self.run {
                // The hot path, inlined here: a G92/G76/G78 cycle writes whole starts.
                Run::Multipass(c) => c.fill(pos, rest),
                Run::Idle => (0, false),
                other => other.fill(pos, rest, &self.contour),
            };
            if written != 0 || done {
                n += written;
                if done {
                    self.run = Run::Idle;
                }
                continue;
            }
            match self.fill_slow() {
                None => break,
                Some(Ok(None)) => {}
                Some(Ok(Some(e))) => {
                    if let Some(slot) = rest.first_mut() {
                        *slot = e;
                        n += 1;
                    }
                }
                Some(Err(a)) if n == 0 => return Err(a),
                Some(Err(a)) => {
                    self.pending = Some(a);
                    break;
                }
            }
        }
        Ok(n)
    }
}

impl Iterator for Expander<'_> {
    type Item = Result<Event, Alarm>;

    /// The hot path — the next move of a running G92/G76/G78 cycle — is small enough to inline
    /// into the caller's loop, so the event is written straight to where the caller keeps it;
    /// everything else is `Core::next_slow`, which dispatches on `Run`.
    /// With an operator script: one branch, then the operator layer ([`operator::Layer`]).
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

impl Core<'_> {
    /// Every event but the hot path's: the configuration check, blocks, the other families,
    /// the end.
    #[inline(never)]
    fn next_slow(&mut self) -> Option<Result<Event, Alarm>> {
        if let Some(a) = self.pending.take() {
            return Some(Err(a));
        }
        if self.done {
            return None;
        }
        if !self.checked {
            self.checked = true;
            if let Err(a) = self.check() {
                return self.fail(a);
            }
        }
        loop {
            if let Some(e) = self.run.next_event(&mut self.machine.pos, &self.contour) {
                return Some(Ok(e));
            }
            self.run = Run::Idle;
            match self.read_block() {
                Ok(true) => {}
                Ok(false) => return None,
                Err(a) => return self.fail(a),
            }
        }
    }

    /// [`Expander::fill`] with nothing running: the next block is read without taking an event
    /// from it (`Ok(None)`), so that what it runs writes its own events; before the first block,
    /// after the end or an alarm, as [`Core::next_slow`].
    #[inline(never)]
    fn fill_slow(&mut self) -> Option<Result<Option<Event>, Alarm>> {
        let steady = self.checked && !self.done && self.pending.is_none();
        if steady && matches!(self.run, Run::Idle) {
            return match self.read_block() {
                Ok(true) => Some(Ok(None)),
                Ok(false) => None,
                Err(a) => self.fail(a).map(|r| r.map(Some)),
            };
        }
        self.next_slow().map(|r| r.map(Some))
    }

    /// The configuration check before the first block, then the script's (OP.SCRIPT, after the
    /// other configuration checks).
    fn check(&self) -> Result<(), Alarm> {
        config::check(&self.machine.config)?;
        operator::check_script(&self.machine.config.operator)
    }

    /// With nothing running: reads the next block into what it runs (possibly
    /// nothing); `false` when the program is over (its end, or the block after M02/M30). An
    /// alarm is for the caller to [`fail`](Core::fail) with. An M98 or M99 block moves the
    /// reader to the subprogram or back ([`sub::Calls`]) and runs nothing: no event.
    fn read_block(&mut self) -> Result<bool, Alarm> {
        if self.ended {
            self.done = true;
            return Ok(false);
        }
        if !self.blocks.read(&mut self.block)? {
            // SUB.RETURN: the text ends inside a subprogram.
            self.calls.end_of_text()?;
            self.done = true;
            return Ok(false);
        }
        let mut program = Program {
            blocks: &mut self.blocks,
            contour: &mut self.contour,
            origin: self.calls.origin(),
            in_subprogram: self.calls.in_subprogram(),
        };
        match self.machine.block(&self.block, &mut self.run, &mut program)? {
            sub::Flow::Next => {}
            sub::Flow::End => self.ended = true,
            sub::Flow::Call(c) => self.calls.call(c, &mut self.blocks, self.machine.params.max_passes)?,
            sub::Flow::Return => self.calls.ret(&mut self.blocks),
        }
        Ok(true)
    }
}

#[cfg(test)]
mod tests;

#[cfg(test)]
mod g162_tests;

#[cfg(test)]
mod front_tests;

#[cfg(test)]
mod g90_tests;

#[cfg(test)]
mod program_tests;

#[cfg(test)]
mod arc_tests;

#[cfg(test)]
mod contour_tests;

#[cfg(test)]
mod g74_tests;

#[cfg(test)]
mod g73_tests;

#[cfg(test)]
mod g83_tests;

#[cfg(test)]
mod operator_tests;

#[cfg(test)]
mod operator_cycle_tests;

#[cfg(test)]
mod thread_points_tests;

#[cfg(test)]
mod readings_tests;

#[cfg(test)]
mod readings_g162_tests;

#[cfg(test)]
mod sub_tests;

#[cfg(test)]
mod speed_tests;
