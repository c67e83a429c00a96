//! The uninterrupted expansion (the trace U of OP.SCRIPT): the program's blocks read one at a
//! time into what they run ([`Run`]), whose events are the stream; the configuration is checked
//! before the first block.

use crate::config;
use crate::contour::Contour;
use crate::lex::{Block, Blocks};
use crate::modal::{Machine, Program};
use crate::run::Run;
use crate::sub;
use cycle_vocab::{Alarm, Config, Event};

mod runs;

/// The uninterrupted expansion (the trace U of OP.SCRIPT): blocks in, events out.
pub(crate) struct Core<'a> {
    pub(crate) blocks: Blocks<'a>,
    /// The block being read, built in place by the lexer.
    pub(crate) block: Block,
    pub(crate) machine: Machine,
    /// What the last block asked for while it is carried out: a running cycle, a move not yet
    /// returned, or nothing ([`Run`]). The block interpreter writes it in place.
    pub(crate) run: Run,
    /// The configuration has been checked.
    pub(crate) checked: bool,
    /// M02/M30 was read: nothing after that block.
    pub(crate) ended: bool,
    /// The stream is over (end of program or after an alarm).
    pub(crate) done: bool,
    /// An alarm that [`crate::Expander::fill`] met after writing events, returned by the next call.
    pub(crate) pending: Option<Alarm>,
    /// The contour of the G70/G71/G72 cycle being carried out (CNT.MAX: at most
    /// [`crate::contour::MAX_BLOCKS`] elements, 48 000 bytes, initialised on first use). It lives here,
    /// outside [`Run`], so that it is written once, in place, by the contour reader and never
    /// copied: `Run` is moved by value; the running cycle keeps only its cursor.
    pub(crate) contour: Contour,
    /// The subprogram call stack (SUB.*: four frames, fixed); `blocks` reads the running
    /// program, main or subprogram.
    pub(crate) calls: sub::Calls,
}

impl<'a> Core<'a> {
    pub(crate) fn new(program: &'a [u8], config: Config) -> Core<'a> {
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

    /// [`crate::Expander::fill`] without an operator script.
    pub(crate) fn fill(&mut self, out: &mut [Event]) -> Result<usize, Alarm> {
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
            let (written, next) = self.fill_slow(rest);
            n += written;
            match next {
                Ok(true) => {}
                Ok(false) => break,
                Err(a) if n == 0 => return Err(a),
                Err(a) => {
                    self.pending = Some(a);
                    break;
                }
            }
        }
        Ok(n)
    }
}

impl Core<'_> {
    /// Every event but the hot path's: the configuration check, blocks, the other families,
    /// the end.
    #[inline(never)]
    pub(crate) fn next_slow(&mut self) -> Option<Result<Event, Alarm>> {
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

    /// [`crate::Expander::fill`] with nothing running, `out` not empty: blocks are read
    /// ([`Core::fill_blocks`]) so that what they run writes its own events; before the first
    /// block, after the end or an alarm, as [`Core::next_slow`]. Returns how many events were
    /// written into `out` and whether the stream goes on (`Ok(false)`: it is over; `Err`: its
    /// alarm, the stream failed).
    #[inline(never)]
    fn fill_slow(&mut self, out: &mut [Event]) -> (usize, Result<bool, Alarm>) {
        let steady = self.checked && !self.done && self.pending.is_none();
        if steady && matches!(self.run, Run::Idle) {
            return self.fill_blocks(out);
        }
        match self.next_slow() {
            None => (0, Ok(false)),
            Some(Ok(e)) => match out.first_mut() {
                Some(slot) => {
                    *slot = e;
                    (1, Ok(true))
                }
                None => (0, Ok(true)),
            },
            Some(Err(a)) => (0, Err(a)),
        }
    }

    /// Reads blocks with nothing running, while `out` has room. A plain block (`modal::Plain`)
    /// and the plain blocks of its kind after it are read by that kind's own loop
    /// (`stream::runs`), which writes what they run straight into `out`; any other block is
    /// read by the interpreter and ends the call (what it runs, if anything, is left in `run`).
    /// Returns as [`Core::fill_slow`]. Bounded work: a block per iteration, at most `out.len()`
    /// events.
    fn fill_blocks(&mut self, out: &mut [Event]) -> (usize, Result<bool, Alarm>) {
        let mut n = 0;
        if let Err(r) = self.advance(!out.is_empty()) {
            return (n, r);
        }
        loop {
            let Some(plain) = self.machine.plain(&self.block) else {
                return match self.interpret() {
                    Ok(()) => (n, Ok(true)),
                    Err(a) => (n, self.fail_with(a)),
                };
            };
            let (written, end) = if let Some(code) = plain.cut() {
                self.cut_run(code, out, n)
            } else if plain.is_g92() {
                self.g92_run(out, n)
            } else {
                self.move_run(plain, out, n)
            };
            n = written;
            if let Some(r) = end {
                return (n, r);
            }
        }
    }

    /// After a block: the next block read, if `room` is left. `Err`: what the call returns (the
    /// buffer full, the program over, or the lexer's alarm).
    #[inline(always)]
    fn advance(&mut self, room: bool) -> Result<(), Result<bool, Alarm>> {
        if !room {
            return Err(Ok(true));
        }
        match self.lex() {
            Ok(true) => Ok(()),
            Ok(false) => Err(Ok(false)),
            Err(a) => Err(self.fail_with(a)),
        }
    }

    /// Ends the stream with `alarm` ([`Core::fail`]) and returns it.
    fn fail_with(&mut self, alarm: Alarm) -> Result<bool, Alarm> {
        self.done = true;
        self.run = Run::Idle;
        Err(alarm)
    }

    /// The configuration check before the first block, then the script's (OP.SCRIPT, after the
    /// other configuration checks).
    pub(crate) fn check(&self) -> Result<(), Alarm> {
        config::check(&self.machine.config)?;
        config::check_script(&self.machine.config.operator)
    }

    /// With nothing running: reads the next block into what it runs (possibly
    /// nothing); `false` when the program is over (its end, or the block after M02/M30). An
    /// alarm is for the caller to [`fail`](Core::fail) with. An M98 or M99 block moves the
    /// reader to the subprogram or back ([`sub::Calls`]) and runs nothing: no event.
    pub(crate) fn read_block(&mut self) -> Result<bool, Alarm> {
        if !self.lex()? {
            return Ok(false);
        }
        self.interpret()?;
        Ok(true)
    }

    /// The lexer's part of [`Core::read_block`]: the next block into `block`; `false` when the
    /// program is over.
    #[inline(always)]
    fn lex(&mut self) -> Result<bool, Alarm> {
        if self.ended {
            self.done = true;
            return Ok(false);
        }
        #[cfg(test)]
        crate::probe::count_read();
        if !self.blocks.read(&mut self.block)? {
            // SUB.RETURN: the text ends inside a subprogram.
            self.calls.end_of_text()?;
            self.done = true;
            return Ok(false);
        }
        Ok(true)
    }

    /// The interpreter's part of [`Core::read_block`]: the block read into what it runs.
    fn interpret(&mut self) -> Result<(), Alarm> {
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
        Ok(())
    }
}
