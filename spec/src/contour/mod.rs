//! The finishing contour of G70, G71, G72 (M003): CNT.* (docs/INTERPRETATION.md, "The contour").
//!
//! A contour is the blocks N(ns) … N(nf) (CNT.RANGE). Where it stands is CNT.FIND: G71 and G72
//! read it **ahead**, from the blocks right after their P/Q block (and the program goes on after
//! N(nf), CNT.FLOW); G70 reads it **behind**, by lexing the program text again from its start up
//! to the G70 block — the spec never collects the blocks of a program, only the ≤ 1 000 blocks
//! of one contour (CNT.MAX). [`block`] checks each contour block and turns it into an
//! [`Element`]; [`path`] runs a (translated) contour as moves.

pub mod block;
pub mod path;

use crate::family::Source;
use crate::lex::Block;
use crate::words::alarm;
use cycle_vocab::{Alarm, AlarmCode, Rule};
use num_bigint::BigInt;

/// A point in increments: X as a diameter count, Z.
pub type Point = (i128, i128);

/// CNT.MAX (PRJ): "A contour has at most 1 000 blocks".
pub const MAX_BLOCKS: usize = 1_000;

/// A contour block's motion (CNT.WORDS): G00, G01, G02 (`cw`), G03.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Rapid,
    Feed,
    Arc { cw: bool },
}

/// One contour block as the cycles use it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Element {
    /// The block's motion: written, or the contour's own mode continued.
    pub mode: Mode,
    /// The motion code the block writes (0…3), if any (CNT.FIRST).
    pub written: Option<u32>,
    /// Whether the block has axis words ("A block without axis words moves nothing").
    pub moves: bool,
    /// The previous contour point (the cycle's start point for the ns block) and the end.
    pub start: Point,
    pub end: Point,
    /// An arc's centre on the grid (ARC.IK, or the R centre rounded once).
    pub centre: Option<Point>,
    /// The F written in the block (CNT.FST: used by G70 only), lead counts.
    pub feed: Option<i64>,
    pub line: u32,
}

/// A contour: its elements in program order, the ns block first.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Contour {
    pub elements: Vec<Element>,
}

impl Contour {
    /// The ns block (a contour has at least one block, CNT.RANGE).
    pub fn ns(&self) -> &Element {
        &self.elements[0]
    }

    /// The elements after the ns block.
    pub fn rest(&self) -> &[Element] {
        &self.elements[1..]
    }

    /// The contour's last point (B, the end of the nf block).
    pub fn last(&self) -> Point {
        self.elements[self.elements.len() - 1].end
    }

    /// G71.ALLOW, G70.UW (M003): the contour translated by (`du` on the diameter count, `dw` on
    /// Z) — every point and every arc centre alike, the radii kept, no normal offset.
    pub fn translated(&self, du: i64, dw: i64) -> Contour {
        let shift = |p: Point| (p.0 + i128::from(du), p.1 + i128::from(dw));
        let elements = self
            .elements
            .iter()
            .map(|e| Element { start: shift(e.start), end: shift(e.end), centre: e.centre.map(shift), ..*e })
            .collect();
        Contour { elements }
    }
}

/// The program words (M003): "a block *is N(p)* when its N word's exact value equals p (`N50`,
/// `N050`, `N50.0` are N50)".
pub fn is_sequence(b: &Block, p: i64) -> bool {
    b.get(b'N').is_some_and(|n| {
        let scaled = BigInt::from(p) * num_traits::pow(BigInt::from(10), n.decimals as usize);
        !n.negative && n.mantissa() == scaled
    })
}

fn not_found(word: u8, line: u32) -> Alarm {
    alarm(AlarmCode::BlockNotFound, word, Rule::CntFind, line)
}

/// CNT.FIND (M003, OPEN) for G71 and G72: "the block right after the cycle's P/Q block must be
/// N(ns), else `BLOCK NOT FOUND` on P; N(nf) must follow before the program ends, else
/// `BLOCK NOT FOUND` on Q". The blocks are taken from the stream, so the program goes on after
/// N(nf) (CNT.FLOW). A lexing alarm met while the contour is read is that alarm.
pub fn ahead(src: &mut Source, ns: i64, nf: i64, line: u32) -> Result<Vec<Block>, Alarm> {
    let first = match src.next_block() {
        None => return Err(not_found(b'P', line)),
        Some(Err(lexing)) => return Err(lexing),
        Some(Ok(b)) => b,
    };
    if !is_sequence(&first, ns) {
        return Err(not_found(b'P', line));
    }
    up_to_nf(first, nf, line, || src.next_block())
}

/// CNT.FIND (M003, OPEN) for G70: "the whole contour stands before the G70 block: N(ns) must be
/// the N of exactly one block before it (none, or more than one: `BLOCK NOT FOUND` on P), and
/// N(nf) must follow it before the G70 block (else `BLOCK NOT FOUND` on Q)". The blocks before
/// the G70 are read again from the program text, twice: once to count N(ns), once for the
/// contour.
pub fn behind(src: &Source, ns: i64, nf: i64, line: u32) -> Result<Vec<Block>, Alarm> {
    if src.before().filter(|b| is_sequence(b, ns)).count() != 1 {
        return Err(not_found(b'P', line));
    }
    let mut from_ns = src.before().skip_while(|b| !is_sequence(b, ns));
    let Some(first) = from_ns.next() else {
        return Err(not_found(b'P', line));
    };
    up_to_nf(first, nf, line, || from_ns.next().map(Ok))
}

/// CNT.RANGE, CNT.MAX (M003, PRJ): the blocks from N(ns) "up to and including the first block
/// N(nf) at or after it"; "a 1 001st block without reaching N(nf) is `CONTOUR TOO LONG` on Q".
/// The end of the blocks first is `BLOCK NOT FOUND` on Q.
fn up_to_nf(
    first: Block,
    nf: i64,
    line: u32,
    mut next: impl FnMut() -> Option<Result<Block, Alarm>>,
) -> Result<Vec<Block>, Alarm> {
    let mut blocks = vec![first];
    while !blocks.last().is_some_and(|b| is_sequence(b, nf)) {
        match next() {
            None => return Err(not_found(b'Q', line)),
            Some(Err(lexing)) => return Err(lexing),
            Some(Ok(_)) if blocks.len() == MAX_BLOCKS => {
                return Err(alarm(AlarmCode::ContourTooLong, b'Q', Rule::CntMax, line));
            }
            Some(Ok(b)) => blocks.push(b),
        }
    }
    Ok(blocks)
}

/// CNT.FIRST (M003): "The ns block must write G00 or G01: none is `MISSING WORD G`, rule
/// CNT.FIRST; G02 or G03 is `WORD NOT ALLOWED` on G, rule CNT.FIRST" — on the ns block's line.
pub fn first(c: &Contour) -> Result<(), Alarm> {
    let ns = c.ns();
    match ns.written {
        None => Err(alarm(AlarmCode::MissingWord, b'G', Rule::CntFirst, ns.line)),
        Some(2 | 3) => Err(alarm(AlarmCode::WordNotAllowed, b'G', Rule::CntFirst, ns.line)),
        Some(_) => Ok(()),
    }
}

#[cfg(test)]
mod tests;
