//! TNRC.* — tool-nose radius compensation (M003), modelled with a nose radius of 0 only.
//!
//! G41 (left), G42 (right) and G40 (cancel) are modal no-motion codes that change no path while
//! the parameter `nose_radius` is 0 (docs/INTERPRETATION.md, "Program words", OPEN TNRC.RADIUS).
//! What the register decides is which blocks are legal; [`check`] makes those checks, in check
//! step 2 right after the two-motion-codes conflict, in the register's order.

use crate::lex::Block;
use crate::program::code_value;
use crate::words::alarm;
use cycle_vocab::{Alarm, AlarmCode, Rule};

/// The compensation in force (TNRC.CODES): none (G40, the start), left (G41), right (G42).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Side {
    #[default]
    Off,
    Left,
    Right,
}

/// The compensation codes of a block (G40, G41, G42), in the order written.
fn codes(b: &Block) -> Vec<u64> {
    b.g_codes().filter_map(code_value).filter(|g| matches!(g, 40..=42)).collect()
}

/// Check step 2 for the compensation codes, in the register's order — [`no_arc`],
/// [`switch`], [`tool_call`], [`radius`] — returning the side in force after the block.
/// `writes_arc`: the block writes G02 or G03. TNRC.TIP: the seed gives no offset geometry and
/// no tip codes, so the side returned only feeds these checks: no path reads it.
pub fn check(b: &Block, writes_arc: bool, before: Side, nose_radius: i64) -> Result<Side, Alarm> {
    let codes = codes(b);
    no_arc(&codes, writes_arc, b.line)?;
    let after = switch(&codes, before, b.line)?;
    tool_call(b, after)?;
    radius(&codes, nose_radius, b.line)?;
    Ok(after)
}

/// TNRC.NOARC (M003): "G40, G41 or G42 in a block that writes G02 or G03 is `CONFLICT` on G".
pub fn no_arc(codes: &[u64], writes_arc: bool, line: u32) -> Result<(), Alarm> {
    if writes_arc && !codes.is_empty() {
        return Err(alarm(AlarmCode::Conflict, b'G', Rule::TnrcNoarc, line));
    }
    Ok(())
}

/// TNRC.SWITCH (M003): "G41 while G42 is in force, or G42 while G41 is (no G40 between), is
/// `WORD NOT ALLOWED` on G"; "G41 written while G41 is in force changes nothing". The codes
/// take effect in the order written, so `G40 G42` after G41 is legal.
pub fn switch(codes: &[u64], before: Side, line: u32) -> Result<Side, Alarm> {
    let mut side = before;
    for &g in codes {
        side = match (g, side) {
            (40, _) => Side::Off,
            (41, Side::Right) | (42, Side::Left) => {
                return Err(alarm(AlarmCode::WordNotAllowed, b'G', Rule::TnrcSwitch, line));
            }
            (41, _) => Side::Left,
            _ => Side::Right,
        };
    }
    Ok(side)
}

/// TNRC.SWITCH (M003): "a T word in a block after which G41 or G42 is still in force" is
/// `WORD NOT ALLOWED` on T (`G40 T0202` is legal): the tool is changed with compensation off.
pub fn tool_call(b: &Block, after: Side) -> Result<(), Alarm> {
    if b.has(b'T') && after != Side::Off {
        return Err(alarm(AlarmCode::WordNotAllowed, b'T', Rule::TnrcSwitch, b.line));
    }
    Ok(())
}

/// TNRC.RADIUS (PRJ): "G41 or G42 with `nose_radius` ≠ 0 is `UNSUPPORTED` on G" — a real
/// offset needs square roots at every corner and is not modelled.
pub fn radius(codes: &[u64], nose_radius: i64, line: u32) -> Result<(), Alarm> {
    if nose_radius != 0 && codes.iter().any(|&g| g == 41 || g == 42) {
        return Err(alarm(AlarmCode::Unsupported, b'G', Rule::TnrcRadius, line));
    }
    Ok(())
}

#[cfg(test)]
mod tests;
