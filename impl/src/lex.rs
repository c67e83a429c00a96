//! The production lexer (PRJ.LEX, PRJ.WORD): bytes in, blocks of words out, no allocation
//! (docs/INTERPRETATION.md, "Program text").
//!
//! A program is words — an address letter (either case) and a number — grouped into blocks.
//! Spaces, tabs, CR and `%` may stand anywhere between tokens, `(comments)` close on their line,
//! `;` or a newline ends a block, `O` and `N` numbers are ordinary words the expander ignores, a
//! UTF-8 byte-order mark at the very start is skipped. Anything else is an alarm naming the byte
//! and its line. The lexer stops at the first alarm.

use crate::number::Number;
use cycle_vocab::{Alarm, AlarmCode, Rule};

/// At most this many G words in one block.
pub const MAX_G_WORDS: usize = 4;
/// At most this many digits in one number (so every number fits an `u64` exactly).
pub const MAX_DIGITS: u32 = 18;

/// One block: at most one word per address letter, except G (up to [`MAX_G_WORDS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Block {
    /// 1-based line of the block's first word.
    pub line: u32,
    /// The letters (not G) with a word: bit `l − 'A'` for letter `l` ([`letter_bit`]).
    present: u32,
    /// The word at each letter; [`ZERO`] where absent.
    words: [Number; 26],
    g: [Number; MAX_G_WORDS],
    g_count: u8,
}

const ZERO: Number = Number { negative: false, mantissa: 0, decimals: 0, point: false };

/// The bit of an address letter (upper case) in a letter mask ([`Block::mask`]); 0 for a byte
/// that is no upper-case letter.
pub const fn letter_bit(letter: u8) -> u32 {
    if letter.is_ascii_uppercase() {
        1 << (letter - b'A')
    } else {
        0
    }
}

/// The mask of a set of address letters (upper case).
pub const fn letter_mask(letters: &[u8]) -> u32 {
    let mut mask = 0;
    let mut rest = letters;
    while let [first, tail @ ..] = rest {
        mask |= letter_bit(*first);
        rest = tail;
    }
    mask
}

impl Block {
    /// An empty block; [`Blocks::read`] fills it.
    pub const fn new() -> Block {
        Block { line: 0, present: 0, words: [ZERO; 26], g: [ZERO; MAX_G_WORDS], g_count: 0 }
    }

    /// Empties the block for reuse: only the words present are reset, so that it equals a new
    /// block.
    fn clear(&mut self) {
        let mut present = self.present;
        while present != 0 {
            if let Some(w) = self.words.get_mut(present.trailing_zeros() as usize) {
                *w = ZERO;
            }
            present &= present - 1;
        }
        self.present = 0;
        for g in self.g.iter_mut().take(self.g_count as usize) {
            *g = ZERO;
        }
        self.g_count = 0;
        self.line = 0;
    }

    /// The word at `letter` (upper case, not G).
    pub fn get(&self, letter: u8) -> Option<Number> {
        debug_assert!(letter.is_ascii_uppercase() && letter != b'G');
        if !self.has(letter) {
            return None;
        }
        self.words.get(letter.wrapping_sub(b'A') as usize).copied()
    }

    /// Whether the block has a word at `letter` (upper case, not G).
    pub fn has(&self, letter: u8) -> bool {
        self.present & letter_bit(letter) != 0
    }

    /// The letters (not G) present, as a [`letter_mask`].
    pub fn mask(&self) -> u32 {
        self.present
    }

    /// Whether the block has a G word ([`Block::g_codes`] not empty).
    pub fn has_g(&self) -> bool {
        self.g_count != 0
    }

    /// The G words, in the order written.
    pub fn g_codes(&self) -> &[Number] {
        self.g.get(..self.g_count as usize).unwrap_or(&[])
    }

    /// The letters (not G) present, in alphabetical order — the order in which engines check
    /// words (docs/INTERPRETATION.md, check order).
    pub fn letters(&self) -> impl Iterator<Item = u8> + '_ {
        let mut rest = self.present;
        core::iter::from_fn(move || {
            let bit = rest.trailing_zeros();
            rest &= rest.wrapping_sub(1);
            (bit < 26).then_some(b'A' + bit as u8)
        })
    }

    /// Whether this block *is N(p)* (CNT.RANGE, "Sequence numbers"): its N word's exact value
    /// equals `p` — `N50`, `N050`, `N+50`, `N50.0` are N50; `N-50`, `N50.5` and a block without
    /// N are not.
    pub fn is_sequence(&self, p: u64) -> bool {
        self.get(b'N').is_some_and(|n| n.is(p))
    }

    fn is_empty(&self) -> bool {
        self.g_count == 0 && self.present == 0
    }

    fn push(&mut self, letter: u8, value: Number, line: u32) -> Result<(), Alarm> {
        if self.is_empty() {
            self.line = line;
        }
        if letter == b'G' {
            let Some(slot) = self.g.get_mut(self.g_count as usize) else {
                return Err(Alarm::new(AlarmCode::DuplicateWord, Some(b'G'), Rule::PrjWord, line));
            };
            *slot = value;
            self.g_count += 1;
            return Ok(());
        }
        if self.has(letter) {
            return Err(Alarm::new(AlarmCode::DuplicateWord, Some(letter), Rule::PrjWord, line));
        }
        if let Some(slot) = self.words.get_mut((letter - b'A') as usize) {
            *slot = value;
            self.present |= letter_bit(letter);
        }
        Ok(())
    }
}

impl Default for Block {
    fn default() -> Block {
        Block::new()
    }
}

/// Iterator over the blocks of a program; yields one `Err` at the first alarm, then ends.
#[derive(Clone, Debug)]
pub struct Blocks<'a> {
    src: &'a [u8],
    pos: usize,
    line: u32,
    done: bool,
    /// Blocks read so far.
    count: u64,
}

/// Where a reader stands between blocks ([`Blocks::mark`]): a byte offset and its line.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Mark {
    pos: usize,
    line: u32,
}

impl Mark {
    /// The start of a text (a placeholder before any reader stood anywhere).
    pub const ZERO: Mark = Mark { pos: 0, line: 1 };
}

/// The UTF-8 byte-order mark, skipped as the program's first three bytes (PRJ.LEX).
const BOM: [u8; 3] = [0xEF, 0xBB, 0xBF];

impl<'a> Blocks<'a> {
    /// The blocks of `src`; a byte-order mark as its first three bytes is skipped (PRJ.LEX:
    /// editors on Windows write it). Anywhere else its first byte is a bad character.
    pub fn new(src: &'a [u8]) -> Blocks<'a> {
        let pos = if src.starts_with(&BOM) { BOM.len() } else { 0 };
        Blocks { src, pos, line: 1, done: false, count: 0 }
    }

    /// A reader of `src` from `mark`, a place another reader of the same text stood at between
    /// blocks (CNT.FIND: the contour of a G70 is read again from its first block).
    pub fn resume(src: &'a [u8], mark: Mark) -> Blocks<'a> {
        Blocks { src, pos: mark.pos, line: mark.line, done: false, count: 0 }
    }

    /// A reader of `src` from `mark` that counts `count` blocks read already (SUB.RETURN: the
    /// caller's reader again, after its M98 block).
    pub fn resume_counted(src: &'a [u8], mark: Mark, count: u64) -> Blocks<'a> {
        Blocks { count, ..Blocks::resume(src, mark) }
    }

    /// Where the reader stands: the next [`Blocks::read`] reads the block after this place.
    pub fn mark(&self) -> Mark {
        Mark { pos: self.pos, line: self.line }
    }

    /// The program text.
    pub fn source(&self) -> &'a [u8] {
        self.src
    }

    /// How many blocks this reader has read.
    pub fn blocks_read(&self) -> u64 {
        self.count
    }

    fn peek(&self) -> Option<u8> {
        self.src.get(self.pos).copied()
    }

    fn alarm(&self, code: AlarmCode, word: Option<u8>) -> Alarm {
        Alarm::new(code, word, Rule::PrjLex, self.line)
    }

    fn skip_blanks(&mut self) {
        while let Some(b' ' | b'\t' | b'\r' | b'%') = self.peek() {
            self.pos += 1;
        }
    }

    /// Reads the number after an address letter: `[+-]digits[.digits]` or `[+-].digits`, with
    /// at most [`MAX_DIGITS`] significant digits (from the first nonzero one) and decimals.
    fn number(&mut self, letter: u8) -> Result<Number, Alarm> {
        self.skip_blanks();
        let mut n = Number { negative: false, mantissa: 0, decimals: 0, point: false };
        if let Some(sign @ (b'+' | b'-')) = self.peek() {
            n.negative = sign == b'-';
            self.pos += 1;
        }
        let mut significant = 0u32;
        let mut digits = self.digit_run(&mut n.mantissa, &mut significant);
        let mut decimals = 0;
        if self.peek() == Some(b'.') {
            n.point = true;
            self.pos += 1;
            decimals = self.digit_run(&mut n.mantissa, &mut significant);
            digits = digits.saturating_add(decimals);
            if cfg!(feature = "planted-lexer-bug") {
                n.point = planted_point(decimals);
            }
        }
        if digits == 0 || significant > MAX_DIGITS || decimals > MAX_DIGITS {
            return Err(self.alarm(AlarmCode::BadNumber, Some(letter)));
        }
        // decimals ≤ MAX_DIGITS (18), and at most 18 significant digits: the mantissa is exact.
        n.decimals = decimals as u8;
        if n.mantissa == 0 {
            n.negative = false;
        }
        Ok(n)
    }

    /// Reads a run of digits onto `mantissa` (× 10 + digit); returns how many were read, and
    /// adds those from the number's first nonzero digit on to `significant`. Beyond
    /// [`MAX_DIGITS`] significant digits the mantissa wraps, and the number is refused.
    fn digit_run(&mut self, mantissa: &mut u64, significant: &mut u32) -> u32 {
        let start = self.pos;
        if *significant == 0 {
            // Zeros before the number's first nonzero digit: not significant, nothing to add.
            while self.peek() == Some(b'0') {
                self.pos += 1;
            }
        }
        let from = self.pos;
        while let Some(d) = self.peek().map(|b| b.wrapping_sub(b'0')).filter(|&d| d <= 9) {
            *mantissa = mantissa.wrapping_mul(10).wrapping_add(u64::from(d));
            self.pos += 1;
        }
        let count = |since: usize| u32::try_from(self.pos - since).unwrap_or(u32::MAX);
        *significant = significant.saturating_add(count(from));
        count(start)
    }

    fn comment(&mut self) -> Result<(), Alarm> {
        let open_line = self.line;
        while let Some(b) = self.peek() {
            self.pos += 1;
            match b {
                b')' => return Ok(()),
                b'\n' => break,
                _ => {}
            }
        }
        Err(Alarm::new(AlarmCode::UnclosedComment, Some(b'('), Rule::PrjLex, open_line))
    }

    /// Reads the next block into `block` (its old words are cleared); `false` at the end of
    /// the program. The block is the caller's, so a reader that keeps one (the production
    /// expander) builds each block in place.
    pub fn read(&mut self, block: &mut Block) -> Result<bool, Alarm> {
        if self.done {
            return Ok(false);
        }
        block.clear();
        let read = self.block(block);
        self.done = !matches!(read, Ok(true));
        if !self.done {
            self.count += 1;
        }
        read
    }

    /// Reads words into `block` up to the end of a non-empty block; `false` when the program
    /// ends before a word.
    fn block(&mut self, block: &mut Block) -> Result<bool, Alarm> {
        loop {
            self.skip_blanks();
            let Some(b) = self.peek() else {
                return Ok(!block.is_empty());
            };
            match b {
                b'\n' | b';' => {
                    self.pos += 1;
                    if b == b'\n' {
                        self.line += 1;
                    }
                    if !block.is_empty() {
                        return Ok(true);
                    }
                }
                b'(' => {
                    self.pos += 1;
                    self.comment()?;
                }
                b if b.is_ascii_alphabetic() => {
                    let letter = b.to_ascii_uppercase();
                    let line = self.line;
                    self.pos += 1;
                    let value = self.number(letter)?;
                    block.push(letter, value, line)?;
                }
                other => return Err(self.alarm(AlarmCode::BadCharacter, Some(other))),
            }
        }
    }
}

/// TEST AID, never for production, used only with the feature `planted-lexer-bug` (off by
/// default): a number's point is recorded only when a digit follows it, so `X5.` reads as `X5`
/// (PRJ.LEX keeps "whether a point was written"). Lengths keep their value; what the point
/// decides goes wrong: `NOT INTEGER` (`P20545.`, `L2.`, `M3.`), F76.MICRONS (`P2.` is 2 mm, not
/// 2 increments), a G with a decimal part (`G0.`). Ordinary programs write `X40.`; the manuals'
/// thread examples in the corpus never put a point where it matters — the differential
/// campaigns are what must find it.
fn planted_point(decimals: u32) -> bool {
    decimals > 0
}

impl Iterator for Blocks<'_> {
    type Item = Result<Block, Alarm>;

    fn next(&mut self) -> Option<Self::Item> {
        let mut block = Block::new();
        match self.read(&mut block) {
            Ok(true) => Some(Ok(block)),
            Ok(false) => None,
            Err(a) => Some(Err(a)),
        }
    }
}

#[cfg(test)]
mod tests;
