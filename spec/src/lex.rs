//! The spec's own reader of program text (PRJ.LEX, PRJ.WORD), written from the register
//! (docs/INTERPRETATION.md, "Program text") for clarity, not speed.
//!
//! [`blocks`] streams a program as [`Block`]s: each block is read when asked for, so memory
//! stays flat however long the program. The first lexing alarm ends the stream; the blocks
//! before it have been handed out (and executed) first.
//!
//! ```
//! use cycle_spec::lex::blocks;
//! let b = blocks(b"g0 X5. (rapid) z-.25\n").next().unwrap().unwrap();
//! assert_eq!((b.line, b.words.len()), (1, 3));
//! assert_eq!(b.get(b'Z').unwrap().to_string(), "-0.25");
//! assert!(b.get(b'X').unwrap().point);
//! ```

use cycle_vocab::{Alarm, AlarmCode, Rule};
use num_bigint::BigInt;
use std::fmt;

/// At most 18 significant digits and 18 digits after the point (PRJ.LEX).
pub const MAX_DIGITS: usize = 18;

/// At most four G words in a block (PRJ.WORD).
pub const MAX_G_WORDS: usize = 4;

/// A number exactly as written (PRJ.LEX): value = ±`digits` / 10^`decimals`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Number {
    /// A negative value. `-0` and `-0.0` are zero without a sign.
    pub negative: bool,
    /// The digits written, the point left out and the leading zeros dropped (`""` for zero):
    /// the significant digits, at most 18. `X007.50` has `"750"`.
    pub digits: String,
    /// How many digits stand after the point, at most 18 (`X007.50` has 2).
    pub decimals: u32,
    /// Whether a decimal point was written (`X5.` has one).
    pub point: bool,
}

impl Number {
    /// The signed integer ±`digits`; the value is this divided by 10^`decimals`.
    pub fn mantissa(&self) -> BigInt {
        let magnitude: BigInt = if self.digits.is_empty() { BigInt::from(0) } else { self.digits.parse().unwrap_or_default() };
        if self.negative {
            -magnitude
        } else {
            magnitude
        }
    }

    /// Reads a whole text as one number by the lexer's rules (`"5."`, `"-.5"`, `"+007"`); `None`
    /// when the text is not exactly one legal number.
    pub fn parse(text: &str) -> Option<Number> {
        let mut reader = Blocks { text: text.as_bytes(), pos: 0, line: 1, stopped: false };
        match reader.number() {
            Some(Ok(n)) if reader.pos == text.len() => Some(n),
            _ => None,
        }
    }
}

/// The canonical form: sign, integer part (at least `0`), then the point and exactly the
/// decimals written when a point was written (`5.`, `0.050`, `-12`).
impl fmt::Display for Number {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let decimals = self.decimals as usize;
        let padded = format!("{:0>width$}", self.digits, width = decimals + 1);
        let (int, frac) = padded.split_at(padded.len() - decimals);
        let sign = if self.negative { "-" } else { "" };
        if self.point {
            write!(f, "{sign}{int}.{frac}")
        } else {
            write!(f, "{sign}{int}")
        }
    }
}

/// One word: its address letter (upper case), its number, and its source line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Word {
    pub letter: u8,
    pub number: Number,
    pub line: u32,
}

/// One block: its words in the order written and its line (a block never spans lines).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Block {
    pub line: u32,
    pub words: Vec<Word>,
}

impl Block {
    /// The number of the word with this (upper-case) letter; for G, the first G word.
    pub fn get(&self, letter: u8) -> Option<&Number> {
        self.words.iter().find(|w| w.letter == letter).map(|w| &w.number)
    }

    /// Whether the block has a word with this letter.
    pub fn has(&self, letter: u8) -> bool {
        self.get(letter).is_some()
    }

    /// The numbers of the G words, in the order written.
    pub fn g_codes(&self) -> impl Iterator<Item = &Number> {
        self.words.iter().filter(|w| w.letter == b'G').map(|w| &w.number)
    }

    /// The letters of the block's words other than G, each once, in alphabetical order.
    pub fn letters(&self) -> Vec<u8> {
        let mut letters: Vec<u8> = self.words.iter().map(|w| w.letter).filter(|&l| l != b'G').collect();
        letters.sort_unstable();
        letters.dedup();
        letters
    }
}

/// The blocks of `program`, read one at a time (PRJ.LEX); the first alarm ends the stream.
pub fn blocks(program: &[u8]) -> Blocks<'_> {
    Blocks::new(program)
}

/// The stream of blocks of one program (an iterator of `Result<Block, Alarm>`).
pub struct Blocks<'a> {
    text: &'a [u8],
    pos: usize,
    line: u32,
    stopped: bool,
}

/// The UTF-8 byte-order mark, skipped as the first three bytes of a program (PRJ.LEX).
const BOM: &[u8] = &[0xEF, 0xBB, 0xBF];

fn lex_alarm(code: AlarmCode, byte: u8, line: u32) -> Alarm {
    Alarm::new(code, Some(byte), Rule::PrjLex, line)
}

impl<'a> Blocks<'a> {
    /// PRJ.LEX (PRJ): a byte-order mark as the very first three bytes is skipped.
    pub fn new(program: &'a [u8]) -> Blocks<'a> {
        let pos = if program.starts_with(BOM) { BOM.len() } else { 0 };
        Blocks { text: program, pos, line: 1, stopped: false }
    }

    fn peek(&self) -> Option<u8> {
        self.text.get(self.pos).copied()
    }

    /// PRJ.LEX: space, tab, CR and `%` are blanks, skipped between tokens.
    fn is_blank(byte: u8) -> bool {
        matches!(byte, b' ' | b'\t' | b'\r' | b'%')
    }

    fn skip_blanks(&mut self) {
        while self.peek().is_some_and(Self::is_blank) {
            self.pos += 1;
        }
    }

    /// PRJ.LEX: the next block with words, `None` at the end of the program. `;` or LF ends a
    /// block; a block without words is skipped.
    fn block(&mut self) -> Result<Option<Block>, Alarm> {
        let mut words: Vec<Word> = Vec::new();
        loop {
            let Some(byte) = self.peek() else {
                return Ok(if words.is_empty() { None } else { Some(Block { line: self.line, words }) });
            };
            match byte {
                b if Self::is_blank(b) => self.pos += 1,
                b';' | b'\n' => {
                    let line = self.line;
                    self.pos += 1;
                    if byte == b'\n' {
                        self.line = self.line.saturating_add(1);
                    }
                    if !words.is_empty() {
                        return Ok(Some(Block { line, words }));
                    }
                }
                b'(' => self.comment()?,
                b if b.is_ascii_alphabetic() => {
                    let word = self.word()?;
                    add_word(&mut words, word)?;
                }
                other => return Err(lex_alarm(AlarmCode::BadCharacter, other, self.line)),
            }
        }
    }

    /// PRJ.LEX: `(` opens a comment closed by the next `)` on the same line; LF or the end of
    /// the program first is `UNCLOSED COMMENT` on `(` at its line.
    fn comment(&mut self) -> Result<(), Alarm> {
        self.pos += 1;
        loop {
            match self.peek() {
                Some(b')') => {
                    self.pos += 1;
                    return Ok(());
                }
                None | Some(b'\n') => return Err(lex_alarm(AlarmCode::UnclosedComment, b'(', self.line)),
                Some(_) => self.pos += 1,
            }
        }
    }

    /// PRJ.LEX: a letter (either case), blanks, then its number; no such number is `BAD NUMBER`
    /// on the (upper-case) letter.
    fn word(&mut self) -> Result<Word, Alarm> {
        let letter = self.peek().unwrap_or(b'?').to_ascii_uppercase();
        self.pos += 1;
        self.skip_blanks();
        match self.number() {
            Some(Ok(number)) => Ok(Word { letter, number, line: self.line }),
            Some(Err(TooManyDigits)) | None => Err(lex_alarm(AlarmCode::BadNumber, letter, self.line)),
        }
    }

    /// PRJ.LEX: `[+-]digits[.digits]` or `[+-].digits`, at least one digit, nothing between the
    /// sign and the digits; at most 18 significant digits and 18 decimals. `None` when no
    /// number stands here.
    fn number(&mut self) -> Option<Result<Number, TooManyDigits>> {
        let mut negative = false;
        if let Some(sign @ (b'+' | b'-')) = self.peek() {
            negative = sign == b'-';
            self.pos += 1;
        }
        let mut digits = String::new();
        let (mut written, mut decimals, mut point, mut too_many) = (0usize, 0usize, false, false);
        while let Some(byte) = self.peek() {
            match byte {
                b'0'..=b'9' => {
                    written += 1;
                    if point {
                        decimals += 1;
                    }
                    // Leading zeros are not significant; past 18 digits only the excess is noted.
                    if !(digits.is_empty() && byte == b'0') {
                        if digits.len() == MAX_DIGITS {
                            too_many = true;
                        } else {
                            digits.push(byte as char);
                        }
                    }
                }
                b'.' if !point => point = true,
                _ => break,
            }
            self.pos += 1;
        }
        if written == 0 {
            return None;
        }
        if too_many || decimals > MAX_DIGITS {
            return Some(Err(TooManyDigits));
        }
        let negative = negative && !digits.is_empty();
        Some(Ok(Number { negative, digits, decimals: decimals as u32, point }))
    }
}

/// More digits than PRJ.LEX allows (a `BAD NUMBER`).
struct TooManyDigits;

/// PRJ.WORD (PRJ): at most one word per letter, except up to four G words; else `DUPLICATE
/// WORD` on the letter at the block's line.
fn add_word(words: &mut Vec<Word>, word: Word) -> Result<(), Alarm> {
    let same = words.iter().filter(|w| w.letter == word.letter).count();
    let limit = if word.letter == b'G' { MAX_G_WORDS } else { 1 };
    if same >= limit {
        return Err(Alarm::new(AlarmCode::DuplicateWord, Some(word.letter), Rule::PrjWord, word.line));
    }
    words.push(word);
    Ok(())
}

impl Iterator for Blocks<'_> {
    type Item = Result<Block, Alarm>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.stopped {
            return None;
        }
        match self.block() {
            Ok(Some(b)) => Some(Ok(b)),
            Ok(None) => {
                self.stopped = true;
                None
            }
            Err(a) => {
                self.stopped = true;
                Some(Err(a))
            }
        }
    }
}
