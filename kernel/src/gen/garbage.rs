//! Garbage: random bytes, random word soup, and the corpus with a few bytes changed — programs
//! of no family in particular, mostly alarms.

use super::{config, knobs, Case, Dice};
use crate::corpus;
use proptest::prelude::*;

/// Random bytes, word soup, corpus mutants.
pub fn strategy() -> BoxedStrategy<Case> {
    let bytes = (proptest::collection::vec(any::<u8>(), 0..200), knobs()).prop_map(|(program, k)| {
        let config = config(&mut Dice::new(&k).fork(48), false);
        Case { family: "bytes", program, config }
    });
    let soup = knobs().prop_map(|k| soup(&mut Dice::new(&k)));
    let mutant = knobs().prop_map(|k| mutant(&mut Dice::new(&k)));
    super::drawn(prop_oneof![bytes, soup, mutant])
}

/// Random word soup: letters (either case, any address), numbers of every shape, separators,
/// comments (closed or not), `%`, and the cycle codes, in random order.
pub fn soup(d: &mut Dice) -> Case {
    let fanuc = d.chance(20);
    let config = config(&mut d.fork(48), fanuc);
    let mut out = String::new();
    let tokens = d.range(1, 40);
    for _ in 0..tokens {
        match d.weighted(&[30, 20, 10, 8, 8, 4, 4, 4, 4, 4, 4]) {
            0 => {
                let letter = (b'A' + d.below(26) as u8) as char;
                out.push(if d.chance(20) { letter.to_ascii_lowercase() } else { letter });
                out.push_str(&soup_number(d));
            }
            1 => out.push_str(d.one_of(&["G92", "G76", "G78", "G0", "G00", "G1", "G20", "G21", "G18", "G97", "G96", "G50", "G92.1", "G-1"])),
            2 => out.push_str(d.one_of(&[" ", "\t", "  "])),
            3 => out.push_str(d.one_of(&["\n", ";", ";\n", "\r\n"])),
            4 => out.push_str(d.one_of(&["X", "Z", "U", "W", "P", "Q", "R", "F", "I", "J", "K", "L", "D", "E"])),
            5 => out.push_str(d.one_of(&["(comment)", "(open", "()", "(a(b)"])),
            6 => out.push_str(d.one_of(&["%", "%\n", "O1", "N10"])),
            7 => out.push_str(d.one_of(&["M30", "M02", "M3", "M100", "M1.5", "M-1", "M98", "M99"])),
            8 => out.push_str(&soup_number(d)),
            9 => out.push(d.one_of(&['#', '/', '=', '[', '*', '$', '.', '-', '+'])),
            _ => out.push_str(d.one_of(&["G76 P020545 Q0.15 R0.5\n", "G76 X60 Z-60 P3 Q1.8 F3\n", "G0 X65 Z5\n", "G92 X58.7 Z-28 F3\n"])),
        }
    }
    Case { family: "soup", program: out.into_bytes(), config }
}

/// A number in any shape the lexer may meet: signs, leading dots, long digit strings, a point
/// alone, nothing.
fn soup_number(d: &mut Dice) -> String {
    match d.weighted(&[40, 15, 10, 10, 8, 7, 5, 5]) {
        0 => d.range(0, 100).to_string(),
        1 => format!("{}.{}", d.range(0, 100), d.range(0, 9999)),
        2 => format!("-{}", d.range(0, 1_000_000)),
        3 => format!(".{}", d.range(0, 999)),
        4 => "9".repeat(d.range(9, 22) as usize),
        5 => d.one_of(&["", ".", "-", "+", "-.", "1.2.3", "0.0000000001"]).to_string(),
        6 => format!("+{}", d.range(0, 99)),
        _ => format!("{}.", d.range(0, 999_999_999)),
    }
}

/// A corpus program with a few bytes replaced, inserted or deleted, under its configuration or
/// a random one.
pub fn mutant(d: &mut Dice) -> Case {
    let p = corpus::PROGRAMS[d.below(corpus::PROGRAMS.len() as u64) as usize];
    let mut bytes = p.text.as_bytes().to_vec();
    let edits = d.range(1, 4);
    for _ in 0..edits {
        if bytes.is_empty() {
            break;
        }
        let at = d.below(bytes.len() as u64) as usize;
        let byte = match d.weighted(&[40, 30, 30]) {
            0 => b"0123456789.-+ ;\nXZUWPQRFIJKLDEGM"[d.below(32) as usize],
            1 => d.below(256) as u8,
            _ => b'0' + d.below(10) as u8,
        };
        match d.below(3) {
            0 => bytes[at] = byte,
            1 => bytes.insert(at, byte),
            _ => {
                bytes.remove(at);
            }
        }
    }
    let config = if !d.chance(30) {
        p.config()
    } else {
        let fanuc = d.chance(20);
        config(&mut d.fork(48), fanuc)
    };
    Case { family: "mutant", program: bytes, config }
}

