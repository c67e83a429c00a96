//! A reader of canonical expanded G-code (the format `cycle_vocab::text` prints and docs/TRACE.md
//! documents): the header comment, then one motion per block, `G00 X Z`, `G01 X Z F`,
//! `G32 X Z F [Q] [K [J]] [R] [L1]` or `G02`/`G03 X Z I K F` (I, K the absolute centre), and the
//! non-motion events `G04 P` (a dwell) and `M03`/`M04` (the spindle); pass and alarm comments are
//! passed over.
//!
//! It reads the printed form back into motions on the integer grid, so a vendor's expander that
//! prints G-code can be compared motion by motion, and so the printer is checked by a round
//! trip (`crate::fuzzing`, target `gcode_roundtrip`). Blocks are split by the reference's lexer
//! (`cycle_spec::lex`, PRJ.LEX); everything else in a block is an error naming its line and
//! word: the format has one form of each motion.

use cycle_spec::lex::{Block, Blocks, Number};
use cycle_vocab::text::fixed;
use cycle_vocab::{Dwell, Event, Grid, Increment, Move, MoveKind, Spindle, SpindleState, Units};
use num_traits::ToPrimitive;

/// One motion as the canonical form prints it (the rule tag is not printed).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Motion {
    pub kind: MoveKind,
    /// End X (diameter) and Z, increments.
    pub x: i64,
    pub z: i64,
    /// Feed or lead, lead counts (0 for a rapid).
    pub feed: i64,
    /// An arc's absolute centre, X (diameter) and Z, increments (0, 0 for other motions).
    pub cx: i64,
    pub cz: i64,
    /// Start angle, 0.001° (thread moves).
    pub angle: u32,
    /// Lead change per `lead_change_angle`, lead counts (thread moves).
    pub lead_change: i64,
    /// The angle of that change, 0.001° (360 000 when `J` is not printed and `K` is; else 0).
    pub lead_change_angle: u32,
    /// The floor of a shrinking lead, lead counts (0: none).
    pub lead_floor: i64,
    /// The lead changes in steps (`L1` printed).
    pub lead_steps: bool,
}

/// Every field of the move but its rule tag (not printed); a field added to `Move` does not
/// compile here until the canonical form prints and reads it.
impl From<&Move> for Motion {
    fn from(m: &Move) -> Motion {
        let Move { kind, x, z, feed, cx, cz, angle, lead_change, lead_change_angle, lead_floor, lead_steps, rule: _ } = *m;
        Motion { kind, x, z, feed, cx, cz, angle, lead_change, lead_change_angle, lead_floor, lead_steps }
    }
}

/// One printed event as read back: a motion, a dwell (ms), or a spindle event.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Printed {
    Motion(Motion),
    Dwell(u32),
    Spindle(SpindleState),
}

impl Printed {
    /// What the canonical form prints of `event` (every field but the rule tag); `None` for a
    /// pass header and an operator event (comments, compared in the JSON form only).
    pub fn of(event: &Event) -> Option<Printed> {
        match event {
            Event::Pass(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => None,
            Event::Move(m) => Some(Printed::Motion(Motion::from(m))),
            Event::Dwell(Dwell { ms, rule: _ }) => Some(Printed::Dwell(*ms)),
            Event::Spindle(Spindle { state, rule: _ }) => Some(Printed::Spindle(*state)),
        }
    }
}

/// The header line of canonical G-code on `grid`.
pub fn header(grid: Grid) -> String {
    format!("(CYCLECHECK TRACE {} GRID {})", grid.unit_name(), fixed(1, grid.decimals()))
}

const GRIDS: [Grid; 4] = [
    Grid { units: Units::Metric, increment: Increment::Isb },
    Grid { units: Units::Metric, increment: Increment::Isc },
    Grid { units: Units::Inch, increment: Increment::Isb },
    Grid { units: Units::Inch, increment: Increment::Isc },
];

/// Reads canonical G-code: its grid (from the header) and its events but pass headers, in order.
pub fn read(text: &[u8]) -> Result<(Grid, Vec<Printed>), String> {
    let first = text.split(|&b| b == b'\n').next().unwrap_or_default();
    let grid = GRIDS
        .into_iter()
        .find(|g| header(*g).as_bytes() == first)
        .ok_or_else(|| format!("line 1: not a canonical trace header: {:?}", String::from_utf8_lossy(first)))?;
    let mut motions = Vec::new();
    for block in Blocks::new(text) {
        let block = block.map_err(|a| format!("line {}: {} (word {:?})", a.line, a.code.text(), a.word.map(char::from)))?;
        motions.push(event(&block, grid)?);
    }
    Ok((grid, motions))
}

/// A block: `G04 P`, `M03`, `M04`, or a motion.
fn event(block: &Block, grid: Grid) -> Result<Printed, String> {
    let line = block.line;
    let codes: Vec<String> = block.g_codes().map(|g| g.to_string()).collect();
    let only = |letters: &[u8]| block.letters().iter().all(|l| letters.contains(l));
    if codes == ["4"] && only(b"P") {
        let p = block.get(b'P').filter(|n| !n.point && !n.negative).and_then(|n| n.mantissa().to_u32());
        return p.map(Printed::Dwell).ok_or_else(|| format!("line {line}: word P: not a dwell in ms"));
    }
    if codes.is_empty() && block.letters() == [b'M'] {
        return match block.get(b'M').map(|m| m.to_string()).as_deref() {
            Some("3") => Ok(Printed::Spindle(SpindleState::Forward)),
            Some("4") => Ok(Printed::Spindle(SpindleState::Reverse)),
            _ => Err(format!("line {line}: word M: not M03 or M04")),
        };
    }
    motion(block, grid).map(Printed::Motion)
}

fn motion(block: &Block, grid: Grid) -> Result<Motion, String> {
    let line = block.line;
    let msg = |word: char, what: &str| format!("line {line}: word {word}: {what}");
    let err = |word: char, what: &str| Err(msg(word, what));
    // A G code as its value: `G00` and `G0` alike, no point, no sign.
    let codes: Vec<String> = block.g_codes().map(|g| g.to_string()).collect();
    let kind = match codes.iter().map(String::as_str).collect::<Vec<_>>()[..] {
        ["0"] => MoveKind::Rapid,
        ["1"] => MoveKind::Feed,
        ["32"] => MoveKind::Thread,
        ["2"] => MoveKind::ArcCw,
        ["3"] => MoveKind::ArcCcw,
        [] => return err('G', "missing"),
        _ => return err('G', "not one of G00, G01, G02, G03, G32"),
    };
    let allowed: &[u8] = match kind {
        MoveKind::Rapid => b"XZ",
        MoveKind::Feed => b"XZF",
        MoveKind::Thread => b"XZFQKJRL",
        MoveKind::ArcCw | MoveKind::ArcCcw => b"XZIKF",
    };
    if let Some(l) = block.letters().into_iter().find(|l| !allowed.contains(l)) {
        return err(l as char, "not part of this motion's canonical form");
    }
    let value = |letter: u8, places: u32| -> Result<Option<i64>, String> {
        match block.get(letter) {
            None => Ok(None),
            Some(n) => exact(n, places).map(Some).map_err(|e| format!("line {line}: word {}: {e}", letter as char)),
        }
    };
    let required = |letter: u8, places: u32| -> Result<i64, String> {
        value(letter, places)?.ok_or_else(|| format!("line {line}: word {}: missing", letter as char))
    };
    let (dec, lead_dec) = (grid.decimals(), grid.lead_decimals());
    let x = required(b'X', dec)?;
    let z = required(b'Z', dec)?;
    let feed = if kind == MoveKind::Rapid { 0 } else { required(b'F', lead_dec)? };
    if matches!(kind, MoveKind::ArcCw | MoveKind::ArcCcw) {
        let (cx, cz) = (required(b'I', dec)?, required(b'K', dec)?);
        return Ok(Motion { kind, x, z, feed, cx, cz, angle: 0, lead_change: 0, lead_change_angle: 0, lead_floor: 0, lead_steps: false });
    }
    let count = |letter: u8| -> Result<Option<u32>, String> {
        match block.get(letter) {
            None => Ok(None),
            Some(n) if n.point || n.negative => Err(msg(letter as char, "not a non-negative integer")),
            Some(n) => n.mantissa().to_u32().map(Some).ok_or_else(|| msg(letter as char, "too large")),
        }
    };
    let angle = count(b'Q')?.unwrap_or(0);
    let lead_change = value(b'K', lead_dec)?.unwrap_or(0);
    let lead_change_angle = match (lead_change, count(b'J')?) {
        (0, Some(_)) => return err('J', "printed without K"),
        (0, None) => 0,
        (_, Some(360_000)) => return err('J', "360000 is not printed"),
        (_, j) => j.unwrap_or(360_000),
    };
    let lead_floor = value(b'R', lead_dec)?.unwrap_or(0);
    let lead_steps = match count(b'L')? {
        None => false,
        Some(1) if lead_change != 0 => true,
        Some(_) => return err('L', "printed only as L1, with K"),
    };
    Ok(Motion { kind, x, z, feed, cx: 0, cz: 0, angle, lead_change, lead_change_angle, lead_floor, lead_steps })
}

/// A printed value with exactly `places` decimals (the canonical form prints every digit).
fn exact(n: &Number, places: u32) -> Result<i64, String> {
    if !n.point || n.decimals != places {
        return Err(format!("not printed with exactly {places} decimals"));
    }
    n.mantissa().to_i64().ok_or_else(|| "too large".to_string())
}

#[cfg(test)]
mod tests;
