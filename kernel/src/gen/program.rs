//! Program-structure wrappers, applied to a built case by [`super::build`] from knobs of their
//! own ([`STRUCTURE_KNOBS`]), so every family's programs also run:
//! - from subprograms (SUB.CALL, SUB.FIND, SUB.RETURN, SUB.NEST): a part of the main program —
//!   the whole body, the blocks before the first cycle block, or the blocks from one of them on
//!   — moved into a subprogram `O<nnnn>` … `M99` after the main program's `M30`, called by a
//!   block `[N…] M98 P[count]<nnnn>` of exactly those words; sometimes nested (up to four
//!   deep, rarely five: `NESTING`), repeated, or with a defect (no such program, a word beside
//!   P, no P);
//! - under a spindle-mode prelude (G50.SMAX, G96.SPEED, G96.SMAX, G96.RAPID): `G50 S` (the
//!   maximum), then `G97 S` (rpm), or G96 S (surface speed) cancelled by G97 S, or left in force
//!   so that the program's G00 blocks run under G96 (refused under `g96.rapid = refuse`), or
//!   G96 without a `G50 S` before it.
//!
//! Nesting: each level's subprogram holds only the call of the next, up to four levels, rarely
//! five (one too deep). A knob of 0 leaves the case as built: a case shrinks toward no wrapper.

use super::{Case, Dice};
use crate::registry::FAMILIES;
use cycle_vocab::Dialect;

/// How many knobs the wrappers draw from (after the spelling knobs, `gen::STRUCTURE_AT`).
pub const STRUCTURE_KNOBS: usize = 48;

/// Percent of cases run from a subprogram.
pub const SUBPROGRAM_PERCENT: u32 = 8;
/// Percent of cases with a spindle-mode prelude.
pub const SPINDLE_PERCENT: u32 = 10;

/// The case, wrapped as the dice say.
pub fn wrap(mut case: Case, d: &mut Dice) -> Case {
    let subprogram = d.chance(SUBPROGRAM_PERCENT);
    let spindle = d.chance(SPINDLE_PERCENT) && case.config.dialect != Dialect::Nc201;
    if !subprogram && !spindle {
        return case;
    }
    let Ok(text) = std::str::from_utf8(&case.program) else { return case };
    let (bom, body) = match text.strip_prefix('\u{feff}') {
        Some(rest) => ("\u{feff}", rest),
        None => ("", text),
    };
    let crlf = body.contains("\r\n");
    let mut lines: Vec<String> = body.split('\n').map(|l| l.trim_end_matches('\r').to_string()).collect();
    // The main program's end: the M30/M02 line the writer's tail wrote; what follows it is
    // dropped (the subprograms go there), and M30 ends every wrapped program.
    let end = lines.iter().position(|l| matches!(l.trim(), "M30" | "M02")).unwrap_or(lines.len());
    lines.truncate(end);
    while lines.last().is_some_and(|l| l.trim().is_empty()) {
        lines.pop();
    }
    let mut first_cycle = first_cycle_line(body.as_bytes(), case.config.dialect).unwrap_or(lines.len()).min(lines.len());
    let mut prelude = d.fork(6);
    if spindle {
        let p = spindle_prelude(&mut prelude);
        first_cycle += p.len();
        lines.splice(0..0, p);
    }
    let mut subs = Vec::new();
    if subprogram && !lines.is_empty() {
        subs = call(&mut lines, first_cycle, d);
    }
    let mut out = String::from(bom);
    for l in lines.iter().map(String::as_str).chain(["M30"]).chain(subs.iter().map(String::as_str)) {
        out.push_str(l);
        out.push_str(if crlf { "\r\n" } else { "\n" });
    }
    case.program = out.into_bytes();
    case
}

/// The 0-based line of the first block that selects a family (as `registry::sight` reads
/// it), if the program lexes that far.
// A generator writing a program, before any judge: where to put its words.
#[allow(clippy::disallowed_methods)]
fn first_cycle_line(program: &[u8], dialect: Dialect) -> Option<usize> {
    for block in cycle_spec::lex::blocks(program) {
        let block = block.ok()?;
        if block.g_codes().any(|g| FAMILIES.iter().any(|f| f.selected_by(g, dialect))) {
            return Some(block.line as usize - 1);
        }
    }
    None
}

/// Moves a part of `lines` into a subprogram called from where it was; the subprograms' lines
/// (the called one first, then those it calls in turn).
fn call(lines: &mut Vec<String>, first_cycle: usize, d: &mut Dice) -> Vec<String> {
    let n = lines.len();
    // The part moved: the whole body, the blocks before the first cycle block, or the blocks
    // from one of those on (a contour stays with its cycle).
    let cut = d.range(0, first_cycle as i64) as usize;
    let (from, to) = match d.weighted(&[45, 20, 35]) {
        0 => (0, n),
        1 if cut > 0 => (0, cut),
        _ => (cut, n),
    };
    let number = d.range(1, 9999);
    let count = match d.weighted(&[70, 12, 8, 10]) {
        0 => None,
        1 => Some(1),
        2 => Some(0),
        _ => Some(2),
    };
    // P: the program number, after the repeat count's digits when there is one.
    let p = match count {
        None => number.to_string(),
        Some(c) => format!("{c}{number:04}"),
    };
    let n_word = if d.chance(30) { format!("N{} ", d.range(1, 9999)) } else { String::new() };
    let mut block = format!("{n_word}M98 P{p}");
    let mut called = number;
    match d.weighted(&[94, 2, 2, 2]) {
        0 => {}
        // A defect: no program with that number, a word beside P, no P.
        1 => called = number % 9999 + 1,
        2 => block.push_str(" X1"),
        _ => block = format!("{n_word}M98"),
    }
    // Nesting: each level's subprogram holds only the call of the next; level 5 is one too deep.
    let levels = [1, 2, 3, 4, 5][d.weighted(&[75, 10, 6, 5, 4])];
    let body: Vec<String> = lines.splice(from..to, [block]).collect();
    let mut out = Vec::new();
    let mut number = called;
    for level in 1..levels {
        let next = (called + level - 1) % 9999 + 1;
        out.extend([format!("O{number:04}"), format!("M98 P{next}"), "M99".to_string()]);
        number = next;
    }
    out.push(format!("O{number:04}"));
    out.extend(body);
    out.push("M99".to_string());
    out
}

/// `G50 S` and the spindle mode before the program's first block.
fn spindle_prelude(d: &mut Dice) -> Vec<String> {
    let max = d.range(500, 6_000);
    let rpm = d.range(50, max);
    let speed = d.range(20, 400);
    match d.weighted(&[45, 30, 15, 10]) {
        0 => vec![format!("G50 S{max}"), format!("G97 S{rpm}")],
        1 => vec![format!("G50 S{max}"), format!("G96 S{speed}"), format!("G97 S{rpm}")],
        // G96 in force: the program's G00 blocks run under it (G96.RAPID).
        2 => vec![format!("G50 S{max}"), format!("G96 S{speed}")],
        // G96 without the maximum (G96.SMAX).
        _ => vec![format!("G96 S{speed}"), format!("G97 S{rpm}")],
    }
}
