//! Check step 2 of a block (docs/INTERPRETATION.md, "Program and modal state", "Which alarm,
//! exactly"): the conflicts, then the words allowed, for the interpreter ([`crate::program`]).

use crate::family::Words;
use crate::lex::Block;
use crate::program::code_value;
use crate::words::alarm;
use cycle_vocab::{Alarm, AlarmCode, Dialect, Rule};

/// Words every block accepts (PRJ.MODAL): N, O, M, S, T (G and M are checked as codes; S is the
/// spindle's, [`crate::spindle`]; N, O, T have no effect). M98 / M99 blocks take fewer
/// ([`crate::sub::block`]).
pub const ALWAYS: &[u8] = b"MNOST";

/// PRJ.WORD (PRJ), F76.FORMAT (M003): the words the block's kind accepts, checked in
/// alphabetical order.
pub fn words_allowed(b: &Block, words: &Words) -> Result<(), Alarm> {
    for letter in b.letters() {
        if !ALWAYS.contains(&letter) && words.read(letter).is_none() {
            return Err(alarm(AlarmCode::WordNotAllowed, letter, words.refusal(letter), b.line));
        }
    }
    Ok(())
}

/// PRJ.WORD (PRJ): two motion/cycle codes in one block are a `CONFLICT` on G; under `nc201`
/// (NC201.ABSINC, M004) so are two of G90/G91, checked right after.
pub fn two_motion_codes(b: &Block, dialect: Dialect, motion_codes: usize) -> Result<(), Alarm> {
    let line = b.line;
    if motion_codes > 1 {
        return Err(alarm(AlarmCode::Conflict, b'G', Rule::PrjWord, line));
    }
    if dialect == Dialect::Nc201 {
        let absinc = b.g_codes().filter(|g| matches!(code_value(g), Some(90 | 91))).count();
        if absinc > 1 {
            return Err(alarm(AlarmCode::Conflict, b'G', Rule::Nc201AbsInc, line));
        }
    }
    Ok(())
}

/// COM.ABSINC, COM.LEAD (M001, M002), ARC.FORMAT (M003): X with U; Z with W; in an arc block
/// (G02/G03, written or modal) R with I or K (`CONFLICT` on R); F with I in a thread block
/// (G92, G76, G78, G32, G33, G34, written or modal), where I is threads per inch. Under `nc201`
/// U, W and I are no incremental or lead addresses, so the pair conflicts do not exist there.
pub fn conflicts(b: &Block, dialect: Dialect, thread: bool, arc: bool) -> Result<(), Alarm> {
    let line = b.line;
    if dialect == Dialect::Nc201 {
        return Ok(());
    }
    if b.has(b'X') && b.has(b'U') {
        return Err(alarm(AlarmCode::Conflict, b'U', Rule::ComAbsInc, line));
    }
    if b.has(b'Z') && b.has(b'W') {
        return Err(alarm(AlarmCode::Conflict, b'W', Rule::ComAbsInc, line));
    }
    if arc && b.has(b'R') && (b.has(b'I') || b.has(b'K')) {
        return Err(alarm(AlarmCode::Conflict, b'R', Rule::ArcFormat, line));
    }
    if thread && b.has(b'F') && b.has(b'I') {
        return Err(alarm(AlarmCode::Conflict, b'I', Rule::ComLead, line));
    }
    Ok(())
}
