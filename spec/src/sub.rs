//! Subprograms: M98, M99 (M003: SUB.CALL, SUB.FIND, SUB.RETURN, SUB.NEST; PRJ.MAXPASS), under
//! every dialect (docs/INTERPRETATION.md, "Subprograms: M98, M99").
//!
//! `003_…` line 144: "M98P**** ****; 例如:M98P42000"; line 145: "调用2号程序一次". The main program is
//! the text up to and including its first M02/M30 block; the blocks after it are the subprogram
//! area, read whole at the first call and kept (the reference holds them in memory, for
//! clarity). Subprogram n is the area's one block with O n, up to its first M99 block. [`run`]
//! drives the interpreter over the main program and a call stack of at most four runs.

use crate::family::Source;
use crate::lex::{Block, Blocks};
use crate::program::{code_value, Flow, Machine};
use crate::words::{alarm, integer};
use cycle_vocab::{Alarm, AlarmCode, Rule};
use num_bigint::BigInt;
use std::rc::Rc;

/// SUB.NEST: "at most 4 levels (main → 1 → 2 → 3 → 4)".
pub const MAX_LEVELS: usize = 4;

/// SUB.CALL: P is 1 … 99 999 999.
pub const P_MAX: i64 = 99_999_999;

/// SUB.CALL: the last four digits of P are the program number.
const NUMBER_DIGITS: i64 = 10_000;

/// An M98 or an M99 block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubCode {
    /// M98: a call (SUB.CALL).
    Call,
    /// M99: the end of one run (SUB.RETURN).
    Return,
}

/// A call as its M98 block writes it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Call {
    /// The program number n, 1 … 9 999.
    pub number: i64,
    /// The repeat count r, 1 … 9 999 (0 or none written: 1).
    pub runs: i64,
    /// The M98 block's line.
    pub line: u32,
}

/// Check steps 2 (words allowed), 3 (P's value) and 4 (missing P) of an M98 / M99 block, whose
/// codes and conflicts are checked. SUB.CALL: "An M98 block takes N, M, P only (any other word
/// is `WORD NOT ALLOWED`, SUB.CALL); `M98` without P is `MISSING WORD P`, SUB.CALL". SUB.RETURN:
/// "an M99 block (words N, M only; others `WORD NOT ALLOWED`, SUB.RETURN)". G counts as a word
/// here, in its alphabetical place.
pub fn block(b: &Block, code: SubCode) -> Result<Flow, Alarm> {
    let (allowed, rule): (&[u8], Rule) = match code {
        SubCode::Call => (b"MNP", Rule::SubCall),
        SubCode::Return => (b"MN", Rule::SubReturn),
    };
    let mut letters: Vec<u8> = b.words.iter().map(|w| w.letter).collect();
    letters.sort_unstable();
    if let Some(&stray) = letters.iter().find(|l| !allowed.contains(l)) {
        return Err(alarm(AlarmCode::WordNotAllowed, stray, rule, b.line));
    }
    match code {
        SubCode::Return => Ok(Flow::Return),
        SubCode::Call => match b.get(b'P') {
            Some(p) => Ok(Flow::Call(call(p, b.line)?)),
            None => Err(alarm(AlarmCode::MissingWord, b'P', Rule::SubCall, b.line)),
        },
    }
}

/// SUB.CALL (M003, DEPARTS from line 144's gloss): "P is an integer (`NOT INTEGER`, COM.RANGES)
/// 1 … 99 999 999 (else `OUT OF RANGE` on P, SUB.CALL): its last four digits are the program
/// number n (1 … 9999; n = 0 is `OUT OF RANGE` on P, SUB.CALL), the digits before them the repeat
/// count r (0 or none: 1)". `M98P42000` calls O2000 four times; `M98 P2` calls O2 once (line 145).
fn call(p: &crate::lex::Number, line: u32) -> Result<Call, Alarm> {
    let p = integer(p, b'P', 1, P_MAX, Rule::SubCall, line)?;
    let (runs, number) = (p / NUMBER_DIGITS, p % NUMBER_DIGITS);
    if number == 0 {
        return Err(alarm(AlarmCode::OutOfRange, b'P', Rule::SubCall, line));
    }
    Ok(Call { number, runs: runs.max(1), line })
}

/// One run of a subprogram in progress.
struct Frame<'p> {
    area: Rc<[Block]>,
    /// The index of its O block in the area.
    start: usize,
    /// Its blocks still to run.
    src: Source<'p>,
    /// Runs left, this one included.
    left: i64,
}

/// The calls in progress over one program text.
struct Calls<'p> {
    text: &'p [u8],
    /// The subprogram area, once a call has read it.
    area: Option<Rc<[Block]>>,
    /// The runs innermost last; the main program is level 0.
    stack: Vec<Frame<'p>>,
    /// Every run of a subprogram the program has made, each repeat counted (PRJ.MAXPASS).
    runs: i64,
}

/// Runs every block of `text` on `machine` — the main program and the subprograms it calls — up
/// to the program's end (M02/M30 in any program, or the main text's end), its first alarm, or
/// the block in which the sink stopped.
pub fn run(text: &[u8], machine: &mut Machine) -> Option<Alarm> {
    let mut main = Source::new(text);
    let mut calls = Calls { text, area: None, stack: Vec::new(), runs: 0 };
    let max_passes = machine.st.params().max_passes;
    loop {
        machine.in_subprogram = !calls.stack.is_empty();
        let src = match calls.stack.last_mut() {
            Some(frame) => &mut frame.src,
            None => &mut main,
        };
        let flow = match src.next_block() {
            Some(Ok(b)) => machine.block(&b, src),
            Some(Err(lexing)) => Err(lexing),
            None => return calls.unterminated(),
        };
        let step = match flow {
            Ok(_) if machine.stopped() => return None,
            Ok(Flow::Next) => Ok(()),
            Ok(Flow::End) => return None,
            Ok(Flow::Call(c)) => calls.call(c, max_passes),
            Ok(Flow::Return) => {
                calls.ret();
                Ok(())
            }
            Err(a) => Err(a),
        };
        if let Err(a) = step {
            return Some(a);
        }
    }
}

impl Calls<'_> {
    /// The checks of a call, in the order the register lists them, then its first run:
    /// SUB.FIND (the area read whole: a lexing alarm met there is that alarm; exactly one O n,
    /// else `BLOCK NOT FOUND` on P), SUB.RETURN (an M99 after it, else `BLOCK NOT FOUND` on M at
    /// the O block's line), SUB.NEST (a call from level 4 is `NESTING` on P), PRJ.MAXPASS ("the
    /// call that would exceed it is `TOO MANY PASSES` on P … before its first run").
    fn call(&mut self, c: Call, max_passes: i64) -> Result<(), Alarm> {
        let area = self.area()?;
        let start = find(&area, c)?;
        returns(&area, start)?;
        if self.stack.len() >= MAX_LEVELS {
            return Err(alarm(AlarmCode::Nesting, b'P', Rule::SubNest, c.line));
        }
        if self.runs.saturating_add(c.runs) > max_passes {
            return Err(alarm(AlarmCode::TooManyPasses, b'P', Rule::PrjMaxPass, c.line));
        }
        self.runs += c.runs;
        let src = Source::subprogram(Rc::clone(&area), start);
        self.stack.push(Frame { area, start, src, left: c.runs });
        Ok(())
    }

    /// SUB.RETURN: "an M99 block … ends one run: with repeats left the subprogram runs again,
    /// else the caller goes on after its M98 block". (M99 in the main program never comes here:
    /// it is `UNSUPPORTED` on M at check step 2.)
    fn ret(&mut self) {
        let Some(frame) = self.stack.last_mut() else { return };
        frame.left -= 1;
        if frame.left > 0 {
            frame.src = Source::subprogram(Rc::clone(&frame.area), frame.start);
        } else {
            self.stack.pop();
        }
    }

    /// The end of the blocks: the program's end in the main program. In a subprogram run it is
    /// "the end of the text before M99", `BLOCK NOT FOUND` on M, rule SUB.RETURN, at the O
    /// block's line (the call found an M99, so only a contour read past it gets here, and that
    /// contour alarms first).
    fn unterminated(&self) -> Option<Alarm> {
        let frame = self.stack.last()?;
        Some(alarm(AlarmCode::BlockNotFound, b'M', Rule::SubReturn, frame.area[frame.start].line))
    }

    /// SUB.FIND: the subprogram area, read at the first call and kept.
    fn area(&mut self) -> Result<Rc<[Block]>, Alarm> {
        if let Some(area) = &self.area {
            return Ok(Rc::clone(area));
        }
        let area = read_area(self.text)?;
        self.area = Some(Rc::clone(&area));
        Ok(area)
    }
}

/// SUB.FIND (OPEN): "The main program is the text up to and including its first M02/M30 block;
/// the blocks after it are the subprogram area … The call reads the whole area (a lexing alarm
/// anywhere there is raised at the call, as that alarm on its own line) … Without an M02/M30 the
/// area is empty." The text is read from its start: a lexing alarm in the main program after
/// the call (before its M02/M30) is met on the way, and raised likewise.
fn read_area(text: &[u8]) -> Result<Rc<[Block]>, Alarm> {
    let mut blocks = Blocks::new(text);
    for b in blocks.by_ref() {
        if ends_program(&b?) {
            break;
        }
    }
    blocks.collect::<Result<Vec<Block>, Alarm>>().map(Rc::from)
}

/// PRJ.MODAL: M02 and M30 end the program.
fn ends_program(b: &Block) -> bool {
    matches!(b.get(b'M').and_then(code_value), Some(2 | 30))
}

/// SUB.RETURN: an M99 block (M by its code value, as the interpreter reads it).
fn is_return(b: &Block) -> bool {
    b.get(b'M').and_then(code_value) == Some(99)
}

/// SUB.FIND: "Subprogram n starts at the block of the area whose O word equals n (its exact
/// value) … no block with O n, or more than one, is `BLOCK NOT FOUND` on P, rule SUB.FIND, at
/// the M98 block". Returns the O block's index.
fn find(area: &[Block], c: Call) -> Result<usize, Alarm> {
    let mut found = area.iter().enumerate().filter(|(_, b)| is_program(b, c.number)).map(|(i, _)| i);
    match (found.next(), found.next()) {
        (Some(start), None) => Ok(start),
        _ => Err(alarm(AlarmCode::BlockNotFound, b'P', Rule::SubFind, c.line)),
    }
}

/// Whether the block's O word's exact value is `n` (`O2000`, `O02000`, `O2000.0` are O2000).
pub fn is_program(b: &Block, n: i64) -> bool {
    b.get(b'O').is_some_and(|o| {
        let scaled = BigInt::from(n) * num_traits::pow(BigInt::from(10), o.decimals as usize);
        !o.negative && o.mantissa() == scaled
    })
}

/// SUB.FIND, SUB.RETURN: the subprogram "runs to its first M99 block. … The end of the text
/// before M99 is `BLOCK NOT FOUND` on M, rule SUB.RETURN, at the subprogram's O block's line."
/// Checked at the call, before the first run.
fn returns(area: &[Block], start: usize) -> Result<(), Alarm> {
    if area[start..].iter().any(is_return) {
        Ok(())
    } else {
        Err(alarm(AlarmCode::BlockNotFound, b'M', Rule::SubReturn, area[start].line))
    }
}
