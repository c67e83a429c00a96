//! Subprograms M98/M99 (docs/INTERPRETATION.md, "Subprograms: M98, M99": SUB.CALL, SUB.FIND,
//! SUB.RETURN, SUB.NEST, PRJ.MAXPASS) without heap: the program text is the one byte slice the
//! expander reads; a call moves the expander's reader to the subprogram's O block and a return
//! moves it back, so no block is copied and no event marks either.
//!
//! **Memory.** A fixed call stack of [`MAX_DEPTH`] = 4 [`Frame`]s (where the caller's reader
//! stands after its M98 block and how many blocks it had read, the subprogram's start and its O
//! block's line, the runs left), where the subprogram area starts (found once), where the main
//! program starts, and the count of subprogram runs: 248 bytes, fixed.
//!
//! **Work.** The first call reads the main program's rest once, to its first M02/M30 block (the
//! area's start, remembered). Every call then reads the area once, to the end of the text, with
//! the production lexer (SUB.FIND: exactly one O block, any lexing alarm there): one pass over
//! the text per call. A return, or a repeat, is O(1). Runs are bounded by `max_passes`
//! (PRJ.MAXPASS), so a whole expansion reads at most (`max_passes` + 1) × the text's length of
//! subprogram text besides the blocks it runs.

use crate::lex::{Block, Blocks, Mark};
use cycle_vocab::{Alarm, AlarmCode, Rule};

/// SUB.NEST: the deepest subprogram level (main → 1 → 2 → 3 → 4).
pub const MAX_DEPTH: usize = 4;

/// What a block asks of the program's flow once its checks passed (steps 2–4 of an M98 block
/// are the block interpreter's; its step 5 is [`Calls::call`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flow {
    /// Go on with the next block.
    Next,
    /// M02/M30: the program is over.
    End,
    /// M98: call a subprogram.
    Call(Call),
    /// M99: end one run of the subprogram.
    Return,
}

/// SUB.CALL: an M98 block's call — program number n (1 … 9999), repeats r (1 … 9999), and the
/// M98 block's line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Call {
    pub program: u64,
    pub repeats: u32,
    pub line: u32,
}

/// One level of the call stack.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Frame {
    /// Where the caller's reader stands after its M98 block, and how many blocks it had read
    /// (CNT.FIND of a later G70 in the caller counts its own blocks only).
    ret: Mark,
    ret_count: u64,
    /// Before the subprogram's O block (each run reads from here).
    start: Mark,
    /// The O block's line (SUB.RETURN: the end of the text before M99 is reported there).
    o_line: u32,
    /// Runs left after the current one.
    left: u32,
}

const NO_FRAME: Frame = Frame { ret: Mark::ZERO, ret_count: 0, start: Mark::ZERO, o_line: 0, left: 0 };

/// Where the subprogram area starts (SUB.FIND).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Area {
    /// Not looked for yet (no call so far).
    Unknown,
    /// The main program has no M02/M30 block: the area is empty.
    Empty,
    /// After the main program's first M02/M30 block.
    At(Mark),
}

/// The call stack and what the calls have counted.
#[derive(Clone, Copy, Debug)]
pub struct Calls {
    frames: [Frame; MAX_DEPTH],
    depth: usize,
    area: Area,
    /// Subprogram runs so far, every repeat counted (PRJ.MAXPASS).
    runs: u64,
    /// Where the main program's reader started (after a byte-order mark).
    main: Mark,
}

impl Calls {
    pub fn new(src: &[u8]) -> Calls {
        Calls { frames: [NO_FRAME; MAX_DEPTH], depth: 0, area: Area::Unknown, runs: 0, main: Blocks::new(src).mark() }
    }

    /// Whether a subprogram is running (M99 is legal).
    pub fn in_subprogram(&self) -> bool {
        self.depth > 0
    }

    fn top(&self) -> Option<&Frame> {
        self.depth.checked_sub(1).and_then(|i| self.frames.get(i))
    }

    /// Where the running program's first block stands: the main program's start, or the running
    /// subprogram's O block (the blocks a G70 searches, CNT.FIND).
    pub fn origin(&self) -> Mark {
        self.top().map_or(self.main, |f| f.start)
    }

    /// SUB.RETURN: the text ended while a subprogram runs (before its M99): `BLOCK NOT FOUND` on
    /// M at its O block's line. Nothing in the main program.
    pub fn end_of_text(&self) -> Result<(), Alarm> {
        match self.top() {
            Some(f) => Err(Alarm::new(AlarmCode::BlockNotFound, Some(b'M'), Rule::SubReturn, f.o_line)),
            None => Ok(()),
        }
    }

    /// Step 5 of an M98 block and the call: SUB.FIND (the area read whole: a lexing alarm there is
    /// that alarm; no O block with the number, or more than one: `BLOCK NOT FOUND` on P),
    /// SUB.RETURN (no M99 block from the O block on: `BLOCK NOT FOUND` on M at the O block's line,
    /// before the subprogram runs — the register's clarification "Subprograms"), SUB.NEST
    /// (a call from level 4: `NESTING` on P), PRJ.MAXPASS (the runs, every repeat counted, beyond
    /// `max_passes`: `TOO MANY PASSES` on P); then `reader` — the caller's, just after its M98
    /// block — reads the subprogram from its O block. Work: one pass over the text.
    pub fn call(&mut self, c: Call, reader: &mut Blocks<'_>, max_passes: u32) -> Result<(), Alarm> {
        let src = reader.source();
        let area = match self.area {
            Area::Unknown => {
                // Only the main program calls before the area is known: its reader stands in it.
                let found = area_after(reader.clone())?;
                self.area = found;
                found
            }
            known => known,
        };
        let p_alarm = |code: AlarmCode, rule: Rule| Alarm::new(code, Some(b'P'), rule, c.line);
        let (start, o_line, returns) = match area {
            Area::At(from) => find(src, from, c.program)?,
            _ => None,
        }
        .ok_or(p_alarm(AlarmCode::BlockNotFound, Rule::SubFind))?;
        if !returns {
            return Err(Alarm::new(AlarmCode::BlockNotFound, Some(b'M'), Rule::SubReturn, o_line));
        }
        let Some(slot) = self.frames.get_mut(self.depth) else {
            return Err(p_alarm(AlarmCode::Nesting, Rule::SubNest));
        };
        let runs = self.runs.saturating_add(u64::from(c.repeats));
        if runs > u64::from(max_passes) {
            return Err(p_alarm(AlarmCode::TooManyPasses, Rule::PrjMaxPass));
        }
        self.runs = runs;
        *slot = Frame { ret: reader.mark(), ret_count: reader.blocks_read(), start, o_line, left: c.repeats.saturating_sub(1) };
        self.depth += 1;
        *reader = Blocks::resume(src, start);
        Ok(())
    }

    /// SUB.RETURN: M99 ends one run — with runs left the subprogram runs again from its O block,
    /// else `reader` goes on in the caller after its M98 block. O(1). (M99 in the main program is
    /// refused before: the block interpreter's check step 2.)
    pub fn ret(&mut self, reader: &mut Blocks<'_>) {
        let src = reader.source();
        let Some(f) = self.depth.checked_sub(1).and_then(|i| self.frames.get_mut(i)) else {
            return;
        };
        if f.left > 0 {
            f.left -= 1;
            *reader = Blocks::resume(src, f.start);
        } else {
            *reader = Blocks::resume_counted(src, f.ret, f.ret_count);
            self.depth -= 1;
        }
    }
}

/// Whether `b` ends the main program: M02 or M30 exactly as the block interpreter reads them (an
/// M written with a point or a sign is an alarm there, never an end).
fn ends(b: &Block) -> bool {
    b.get(b'M').is_some_and(|m| !m.point && !m.negative && matches!(m.mantissa, 2 | 30))
}

/// SUB.FIND: the area's start — after the first M02/M30 block `reader` reads (the main
/// program's rest). A lexing alarm met there is returned (it stands before any end the reader
/// could find). Work: one pass over the main program's rest.
fn area_after(mut reader: Blocks<'_>) -> Result<Area, Alarm> {
    let mut b = Block::new();
    while reader.read(&mut b)? {
        if ends(&b) {
            return Ok(Area::At(reader.mark()));
        }
    }
    Ok(Area::Empty)
}

/// SUB.FIND: reads the area from `from` to the end of the text; the one block whose O word's
/// exact value is `n` — where it stands, its line, and whether an M99 block stands at or after
/// it (SUB.RETURN) — or `None` when there is none or more than one. A lexing alarm anywhere in
/// the area is returned. Work: one pass over the area.
fn find(src: &[u8], from: Mark, n: u64) -> Result<Option<(Mark, u32, bool)>, Alarm> {
    let mut reader = Blocks::resume(src, from);
    let mut b = Block::new();
    let mut found = None;
    let mut count = 0u32;
    loop {
        let at = reader.mark();
        if !reader.read(&mut b)? {
            break;
        }
        if b.get(b'O').is_some_and(|o| o.is(n)) {
            count = count.saturating_add(1);
            found.get_or_insert((at, b.line, false));
        }
        if let Some((_, _, returns)) = &mut found {
            *returns |= b.get(b'M').is_some_and(|m| !m.point && !m.negative && m.mantissa == 99);
        }
    }
    Ok(if count == 1 { found } else { None })
}

#[cfg(test)]
mod tests;
