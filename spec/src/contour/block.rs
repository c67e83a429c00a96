//! The checks of one contour block (CNT.WORDS, CNT.NOSUB, ARC.*) and the element it gives.
//!
//! "Contour blocks are checked like any block (steps 2–5 in their order, arcs included), each
//! alarm on the contour block's own line — except that they need no feed (the cycle gives it)"
//! (docs/INTERPRETATION.md, "The contour"). Contour blocks never change the machine's state:
//! the points are the contour's own, starting at the cycle's start point, X/Z positions and U/W
//! distances from the previous contour point.

use super::{Contour, Element, Mode, Point};
use crate::arc;
use crate::family::{Values, Words};
use crate::lex::Block;
use crate::program::code_value;
use crate::tnrc::{self, Side};
use crate::words::{alarm, F, U, W, X, Z};
use cycle_vocab::{Alarm, AlarmCode, Config, Rule};
use num_bigint::BigInt;

/// What a contour block is checked against: the configuration (values, `arc_tolerance`) and
/// the nose-radius compensation in force at the cycle (TNRC.SWITCH for a T word).
#[derive(Clone, Copy, Debug)]
pub struct Reader<'c> {
    pub config: &'c Config,
    pub side: Side,
}

/// CNT.WORDS (M003, OPEN): "the words X U Z W R I K F S T N" — besides the motion codes, which
/// [`codes`] checks. S, T, N have no effect in a contour (CNT.FST for S and T).
const CONTOUR_LETTERS: &[u8] = b"FIKNRSTUWXZ";

/// The words each contour mode accepts, as the same block outside a contour would: G00/G01
/// X U Z W F, arcs also R I K (ARC.FORMAT).
const LINEAR: Words = Words::of(&[F, U, W, X, Z]);

fn words_of(mode: Mode) -> Words {
    match mode {
        Mode::Arc { .. } => arc::WORDS,
        Mode::Rapid | Mode::Feed => LINEAR,
    }
}

/// Reads the contour's blocks from `start` (the cycle's start point), each block's checks in
/// program order (cycle check (2) of G70, G71, G72).
pub fn read(blocks: &[Block], start: Point, r: &Reader) -> Result<Contour, Alarm> {
    let mut elements = Vec::with_capacity(blocks.len());
    let (mut at, mut mode) = (start, None);
    for b in blocks {
        let e = element(b, at, &mut mode, r)?;
        at = e.end;
        elements.push(e);
    }
    Ok(Contour { elements })
}

/// One contour block, in the check order of any block: (2) codes, conflicts, words allowed;
/// (3) values; (4) missing words; (5) the arc's checks. `mode` is the contour's own modal
/// motion ("Later contour blocks without a motion code continue the contour's own mode"); a
/// block before any motion code is checked as a G00/G01 block (CNT.FIRST refuses it later).
pub fn element(b: &Block, at: Point, mode: &mut Option<Mode>, r: &Reader) -> Result<Element, Alarm> {
    let line = b.line;
    let written = codes(b)?;
    conflicts(b, &written, r.side)?;
    if let Some(&g) = written.first() {
        *mode = Some(match g {
            0 => Mode::Rapid,
            1 => Mode::Feed,
            g => Mode::Arc { cw: g == 2 },
        });
    }
    let m = mode.unwrap_or(Mode::Feed);
    if let Mode::Arc { .. } = m {
        if b.has(b'R') && (b.has(b'I') || b.has(b'K')) {
            return Err(alarm(AlarmCode::Conflict, b'R', Rule::ArcFormat, line));
        }
    }
    let words = words_of(m);
    allowed(b, &words)?;
    let v = values(b, &words, r.config)?;
    let moves = [b'X', b'U', b'Z', b'W'].iter().any(|&l| b.has(l));
    let end = (
        v.get(b'X').map(i128::from).or(v.get(b'U').map(|u| at.0 + i128::from(u))).unwrap_or(at.0),
        v.get(b'Z').map(i128::from).or(v.get(b'W').map(|w| at.1 + i128::from(w))).unwrap_or(at.1),
    );
    let mut centre = None;
    if let (Mode::Arc { cw }, true) = (m, moves) {
        // Step 4: no feed is needed in a contour; neither R nor I nor K is MISSING WORD R.
        let Some(by) = arc::by(&v) else {
            return Err(alarm(AlarmCode::MissingWord, b'R', Rule::ArcFormat, line));
        };
        let tolerance = crate::config::params(r.config).arc_tolerance;
        centre = Some(arc::decide(at, end, cw, by, tolerance, line)?.centre);
    }
    let written = written.first().map(|&g| g as u32);
    Ok(Element { mode: m, written, moves, start: at, end, centre, feed: v.get(b'F'), line })
}

/// CNT.WORDS, CNT.NOSUB (M003, OPEN), check step 2: the G codes in the order written — a
/// contour takes G00, G01, G02, G03 ("Any other G code written there (supported elsewhere or
/// not) is `WORD NOT ALLOWED` on G, rule CNT.WORDS") — then M: "an M word is `WORD NOT
/// ALLOWED` on M, rule CNT.NOSUB for M98 and M99, CNT.WORDS otherwise" (M98, M99 by exact
/// value). Returns the motion codes written.
fn codes(b: &Block) -> Result<Vec<u64>, Alarm> {
    let mut written = Vec::new();
    for g in b.g_codes() {
        match code_value(g) {
            Some(g @ 0..=3) => written.push(g),
            _ => return Err(alarm(AlarmCode::WordNotAllowed, b'G', Rule::CntWords, b.line)),
        }
    }
    if let Some(m) = b.get(b'M') {
        let call = [98, 99].iter().any(|&v| m.mantissa() == BigInt::from(v) * num_traits::pow(BigInt::from(10), m.decimals as usize));
        let rule = if call && !m.negative { Rule::CntNosub } else { Rule::CntWords };
        return Err(alarm(AlarmCode::WordNotAllowed, b'M', rule, b.line));
    }
    Ok(written)
}

/// Check step 2, conflicts, as in any block: two motion codes (`CONFLICT` on G, PRJ.WORD),
/// the tool call while compensation is in force (TNRC.SWITCH), X with U, Z with W
/// (COM.ABSINC). R with I or K is checked once the block's mode is known (arcs only).
fn conflicts(b: &Block, written: &[u64], side: Side) -> Result<(), Alarm> {
    if written.len() > 1 {
        return Err(alarm(AlarmCode::Conflict, b'G', Rule::PrjWord, b.line));
    }
    tnrc::tool_call(b, side)?;
    if b.has(b'X') && b.has(b'U') {
        return Err(alarm(AlarmCode::Conflict, b'U', Rule::ComAbsInc, b.line));
    }
    if b.has(b'Z') && b.has(b'W') {
        return Err(alarm(AlarmCode::Conflict, b'W', Rule::ComAbsInc, b.line));
    }
    Ok(())
}

/// CNT.WORDS (M003), PRJ.WORD: the words allowed, in alphabetical order. A letter outside the
/// contour's words ("O, P, Q, J, L, …") is `WORD NOT ALLOWED` under CNT.WORDS; a contour word
/// the block's own mode does not take (R, I, K in a G00/G01 block) under PRJ.WORD, as in any
/// block.
fn allowed(b: &Block, words: &Words) -> Result<(), Alarm> {
    for letter in b.letters() {
        if matches!(letter, b'N' | b'S' | b'T') {
            continue;
        }
        if !CONTOUR_LETTERS.contains(&letter) {
            return Err(alarm(AlarmCode::WordNotAllowed, letter, Rule::CntWords, b.line));
        }
        if words.read(letter).is_none() {
            return Err(alarm(AlarmCode::WordNotAllowed, letter, Rule::PrjWord, b.line));
        }
    }
    Ok(())
}

/// Check step 3: each word's value in alphabetical order, read as the mode's table says.
fn values(b: &Block, words: &Words, config: &Config) -> Result<Values, Alarm> {
    let mut v = Values::default();
    for letter in b.letters() {
        if let (Some(n), Some(read)) = (b.get(letter), words.read(letter)) {
            v.set(letter, read.value(n, letter, config, b.line)?);
        }
    }
    Ok(v)
}
