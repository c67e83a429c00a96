//! The contour of the stock-removal cycles (CNT.*; docs/INTERPRETATION.md, "The contour"): the
//! fixed-capacity buffer that holds it, the search for a G70's contour before the G70 block
//! (CNT.FIND), and the checks every cycle makes on it once read (CNT.FIRST).
//!
//! **The buffer.** A contour has at most [`MAX_BLOCKS`] blocks (CNT.MAX); each block makes at
//! most one [`Element`] (48 bytes), so the buffer is `MAX_BLOCKS` elements, 48 000 bytes, in the
//! [`crate::Expander`] itself — no heap, and no second copy: the contour reader writes it in
//! place and the running cycle reads it by index. It is initialised on first use, so a program
//! without a contour cycle pays nothing for it but the expander's size.

use crate::lex::{Block, Blocks, Mark};
use cycle_vocab::{Alarm, AlarmCode, Rule};

/// CNT.MAX: the most blocks a contour may have. The one place this bound is written; the buffer
/// holds this many elements.
pub const MAX_BLOCKS: usize = 1_000;

/// How a contour element is travelled.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// G00.
    Rapid,
    /// G01.
    Feed,
    /// G02 (`true`, clockwise) or G03, about the element's centre.
    Arc(bool),
}

/// One contour block that moves, as written (untranslated): its end point, its centre (arcs;
/// given by I/K or the R-centre rounded once, ARC.*), the F written in it or in the blocks
/// without motion since the previous element (0: none; CNT.FST, G70.FEED), its line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Element {
    pub x: i64,
    pub z: i64,
    pub cx: i64,
    pub cz: i64,
    pub feed: u32,
    pub line: u32,
    pub kind: Kind,
}

impl Element {
    pub const ZERO: Element = Element { x: 0, z: 0, cx: 0, cz: 0, feed: 0, line: 0, kind: Kind::Rapid };

    /// The end point.
    pub const fn end(&self) -> (i64, i64) {
        (self.x, self.z)
    }

    /// The centre (arcs).
    pub const fn centre(&self) -> (i64, i64) {
        (self.cx, self.cz)
    }
}

/// The contour of the cycle being carried out: element 0 is the ns block, then every later
/// contour block that moves, in program order.
#[derive(Clone, Debug)]
pub struct Contour {
    /// `None` until the first contour cycle (no cost before it).
    elements: Option<[Element; MAX_BLOCKS]>,
    len: usize,
}

impl Contour {
    pub const fn new() -> Contour {
        Contour { elements: None, len: 0 }
    }

    pub fn clear(&mut self) {
        self.len = 0;
    }

    /// Appends `e`; `false` when the buffer is full (never for a contour within CNT.MAX, which
    /// the reader checks before it pushes).
    pub fn push(&mut self, e: Element) -> bool {
        // Initialised once, on the first push of the expander's first contour (not `get_or_insert`,
        // which would build the array on every call).
        if self.elements.is_none() {
            self.elements = Some([Element::ZERO; MAX_BLOCKS]);
        }
        let Some(elements) = &mut self.elements else {
            return false;
        };
        match elements.get_mut(self.len) {
            Some(slot) => {
                *slot = e;
                self.len += 1;
                true
            }
            None => false,
        }
    }

    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Element `i` (`Element::ZERO` beyond the end: callers index within `len`).
    #[inline]
    pub fn get(&self, i: usize) -> Element {
        match &self.elements {
            Some(e) if i < self.len => e.get(i).copied().unwrap_or(Element::ZERO),
            _ => Element::ZERO,
        }
    }

    /// The elements read, in order (empty before the first contour cycle).
    #[inline]
    pub fn elements(&self) -> &[Element] {
        match &self.elements {
            Some(e) => e.get(..self.len).unwrap_or_default(),
            None => &[],
        }
    }

    /// The last element (B's block).
    pub fn last(&self) -> Element {
        self.get(self.len.saturating_sub(1))
    }
}

impl Default for Contour {
    fn default() -> Contour {
        Contour::new()
    }
}

/// `BLOCK NOT FOUND` (CNT.FIND) or `CONTOUR TOO LONG` (CNT.MAX) on P or Q of the cycle block.
pub fn not_found(word: u8, line: u32) -> Alarm {
    Alarm::new(AlarmCode::BlockNotFound, Some(word), Rule::CntFind, line)
}

pub fn too_long(line: u32) -> Alarm {
    Alarm::new(AlarmCode::ContourTooLong, Some(b'Q'), Rule::CntMax, line)
}

/// CNT.FIND for G70: the contour stands before the G70 block, the `before`-th block read by a
/// reader of `src` from `origin` (the running program's first block: the text's start, or a
/// subprogram's O block). The program is read again from there, in bounded memory: N(ns)
/// must be the N of exactly one of those blocks (else `BLOCK NOT FOUND` on P), and the first
/// N(nf) at or after it must come within [`MAX_BLOCKS`] blocks (a 1 001st block without it:
/// `CONTOUR TOO LONG` on Q) and before the G70 block (else `BLOCK NOT FOUND` on Q). Returns
/// where the ns block stands. Each block from N(ns) on, while N(nf) is not yet met and the
/// count is within CNT.MAX + 1, is handed to `on_block` as it is read: G70 reads its contour in
/// this same pass. Work: one pass over the blocks before the G70 block.
pub fn find_before(src: &[u8], origin: Mark, before: u64, ns: u64, nf: u64, line: u32, mut on_block: impl FnMut(&Block)) -> Result<Mark, Alarm> {
    let mut reader = Blocks::resume(src, origin);
    let mut block = Block::new();
    let mut first: Option<Mark> = None;
    let mut ns_count = 0u32;
    // Blocks from the first N(ns) on, and whether N(nf) was met among them.
    let mut since = 0usize;
    let mut closed = false;
    for _ in 0..before {
        let mark = reader.mark();
        // Every block before the G70 block was read before it, without an alarm.
        if !matches!(reader.read(&mut block), Ok(true)) {
            break;
        }
        if block.is_sequence(ns) {
            ns_count = ns_count.saturating_add(1);
            first.get_or_insert(mark);
        }
        if first.is_some() && !closed && since <= MAX_BLOCKS {
            on_block(&block);
            since += 1;
            closed = since <= MAX_BLOCKS && block.is_sequence(nf);
        }
    }
    let at = match first {
        Some(at) if ns_count == 1 => at,
        _ => return Err(not_found(b'P', line)),
    };
    if closed {
        Ok(at)
    } else if since > MAX_BLOCKS {
        Err(too_long(line))
    } else {
        Err(not_found(b'Q', line))
    }
}

/// CNT.FIRST: the ns block must write G00 or G01 — none is `MISSING WORD G`, G02/G03 `WORD NOT
/// ALLOWED` on G — on the ns block's `line` (docs/INTERPRETATION.md, G71 "Alarm lines":
/// "CNT.FIRST, G71.TYPE2 and G71.FIRST on the ns block's").
pub fn check_first(first_motion: Option<u64>, line: u32) -> Result<(), Alarm> {
    match first_motion {
        None => Err(Alarm::new(AlarmCode::MissingWord, Some(b'G'), Rule::CntFirst, line)),
        Some(2 | 3) => Err(Alarm::new(AlarmCode::WordNotAllowed, Some(b'G'), Rule::CntFirst, line)),
        Some(_) => Ok(()),
    }
}

#[cfg(test)]
mod tests;
