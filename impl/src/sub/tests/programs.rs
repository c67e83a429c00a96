//! Subprograms M98/M99 (docs/INTERPRETATION.md, "Subprograms: M98, M99") on the whole
//! expander: calls, repeats, returns, nesting, the run bound, the area and its search, the O
//! block's line, contours within their own program, and every alarm with its word and rule.
extern crate std;

use crate::tests::assert_fill_agrees;
use crate::tests::{expand, moves};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, Params, Rule};
use std::format;
use std::string::String;

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

fn rapid(x: i64, z: i64) -> Move {
    Move::rapid(x * 1_000, z * 1_000, Rule::PrjModal)
}

/// SUB.CALL, SUB.RETURN: `M98 P1000` runs O1000 — its O block included, as any block — and
/// the caller goes on after the M98 block; no event marks the call or the return.
#[test]
fn call_runs_the_subprogram_once_and_returns() {
    let src = "G0 X10 Z10\nM98 P1000\nG0 X30\nM30\nO1000 G0 Z5\nG0 X20\nM99\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t), [rapid(10, 10), rapid(10, 5), rapid(20, 5), rapid(30, 5)]);
    assert_eq!(t.events.len(), 4);
    // M98 P2 calls O2 once (`003_…` line 145); leading zeros of P are no repeats.
    let t = expand("M98 P2\nM98 P00002\nM02\nO2\nG0 U2\nM99\n", Config::default());
    assert_eq!((t.alarm, moves(&t)), (None, std::vec![rapid(2, 0), rapid(4, 0)]));
    // The O word's exact value: O0002 and O2.0 are O2.
    assert_eq!(moves(&expand("M98 P2\nM30\nO0002\nG0 X1\nM99\n", Config::default())), [rapid(1, 0)]);
    assert_eq!(moves(&expand("M98 P2\nM30\nO2.0\nG0 X1\nM99\n", Config::default())), [rapid(1, 0)]);
}

/// SUB.CALL (DEPARTS from line 144's gloss): `M98P42000` runs O2000 four times.
#[test]
fn repeats_are_the_leading_digits() {
    let src = "G0 X0 Z0\nM98P42000\nG0 Z-1\nM30\nO2000\nG0 U2\nM99\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t), [rapid(2, 0), rapid(4, 0), rapid(6, 0), rapid(8, 0), rapid(8, -1)]);
    // r = 0 is once.
    assert_eq!(moves(&expand("M98 P02000\nM30\nO2000\nG0 U2\nM99\n", Config::default())).len(), 1);
}

/// Modal state is one for the whole program: the subprogram's mode and feed stay for the caller.
#[test]
fn modal_state_is_shared() {
    let t = expand("M98 P7\nZ-5\nM30\nO7\nG1 X4 F0.5\nM99\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t), [Move::feed(4_000, 0, 5_000, Rule::PrjModal), Move::feed(4_000, -5_000, 5_000, Rule::PrjModal)]);
}

/// SUB.NEST: four levels run, each returning to its caller; a call from level 4 is NESTING on P
/// at that M98 block (recursion too).
#[test]
fn nesting() {
    let level = |n: u32, last: u32| {
        if n < last {
            format!("O{n}\nG0 U1\nM98 P{}\nG0 W-1\nM99\n", n + 1)
        } else {
            format!("O{n}\nG0 U1\nM99\n")
        }
    };
    let program = |last: u32| {
        let mut s = String::from("G0 X0 Z0\nM98 P1\nG0 X100\nM30\n");
        for n in 1..=last {
            s += &level(n, last);
        }
        s
    };
    let t = expand(&program(4), Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[..4], [rapid(1, 0), rapid(2, 0), rapid(3, 0), rapid(4, 0)]);
    assert_eq!(m[4..], [rapid(4, -1), rapid(4, -2), rapid(4, -3), rapid(100, -3)]);
    // Five levels: O4's M98 (line 5 + 3·5 + 2 = 22) is the fifth.
    let t = expand(&program(5), Config::default());
    assert_eq!(t.alarm, al(AlarmCode::Nesting, b'P', Rule::SubNest, 22));
    assert_eq!(moves(&t).len(), 4);
    assert_eq!(alarm_of("M98 P1\nM30\nO1\nM98 P1\nM99\n"), al(AlarmCode::Nesting, b'P', Rule::SubNest, 4));
    // Step 5 of an M98 block in the register's order: SUB.FIND, SUB.NEST, then the run bound.
    let deep = "M98 P1\nM30\nO1\nM98 P2\nM99\nO2\nM98 P3\nM99\nO3\nM98 P4\nM99\nO4\n";
    assert_eq!(alarm_of(&format!("{deep}M98 P9\nM99\n")), al(AlarmCode::BlockNotFound, b'P', Rule::SubFind, 13));
    let cfg = Config { params: Params { max_passes: Some(5), ..Params::default() }, ..Config::default() };
    let t = expand(&format!("{deep}M98 P90001\nM99\n"), cfg);
    assert_eq!(t.alarm, al(AlarmCode::Nesting, b'P', Rule::SubNest, 13));
}

/// PRJ.MAXPASS: the runs, every repeat counted, against `max_passes`; the call that would
/// exceed it is refused before its first run.
#[test]
fn runs_are_bounded_by_max_passes() {
    let cfg = Config { params: Params { max_passes: Some(3), ..Params::default() }, ..Config::default() };
    let sub = "M30\nO1\nG0 U1\nM99\n";
    let t = expand(&format!("M98 P40001\n{sub}"), cfg);
    assert_eq!((t.alarm, t.events.len()), (al(AlarmCode::TooManyPasses, b'P', Rule::PrjMaxPass, 1), 0));
    assert_eq!(expand(&format!("M98 P30001\n{sub}"), cfg).alarm, None);
    let t = expand(&format!("M98 P20001\nM98 P20001\n{sub}"), cfg);
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'P', Rule::PrjMaxPass, 2));
    assert_eq!(moves(&t).len(), 2);
    // Nested runs count too.
    let t = expand("M98 P20001\nM30\nO1\nM98 P2\nM99\nO2\nG0 U1\nM99\n", cfg);
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'P', Rule::PrjMaxPass, 4));
    assert_eq!(moves(&t).len(), 1);
}

/// SUB.FIND: the area after the main program's first M02/M30; exactly one O block there.
#[test]
fn find_alarms() {
    let nf = |line| al(AlarmCode::BlockNotFound, b'P', Rule::SubFind, line);
    assert_eq!(alarm_of("G0 X1\nM98 P1000\nM30\nO1001\nM99\n"), nf(2));
    assert_eq!(alarm_of("M98 P1000\nM30\nO1000\nM99\nO1000\nM99\n"), nf(1));
    // Without M02/M30 the area is empty; an O block in the main program is not a subprogram.
    assert_eq!(alarm_of("M98 P1000\nO1000\nM99\n"), nf(1));
    assert_eq!(alarm_of("M98 P1000\nO1000\nM99\nM30\n"), nf(1));
    // The area starts after the first M02/M30: a later M30 is part of it.
    let t = expand("M98 P5\nM02\nM30\nO5\nG0 X3\nM99\n", Config::default());
    assert_eq!((t.alarm, moves(&t)), (None, std::vec![rapid(3, 0)]));
    // The events before the call stand before the alarm.
    let t = expand("G0 X1\nM98 P9\nM30\n", Config::default());
    assert_eq!((t.alarm, moves(&t)), (nf(2), std::vec![rapid(1, 0)]));
    // A lexing alarm anywhere in the area is raised at the call, on its own line — after the O
    // block too — and so is one in the main program's rest, read to find the area.
    let bad = |line| al(AlarmCode::BadCharacter, b'-', Rule::PrjLex, line);
    assert_eq!(alarm_of("M98 P1\nM30\nO1\nM99\nX1-2\n"), bad(5));
    let t = expand("G0 X1\nM98 P1\nG0 X2-\nM30\nO1\nG0 X9\nM99\n", Config::default());
    assert_eq!((t.alarm, moves(&t)), (bad(3), std::vec![rapid(1, 0)]));
    // Without a call the area is never read (nothing after M30 is).
    assert_eq!(alarm_of("G0 X1\nM30\nX1-2\n"), None);
}

/// SUB.RETURN: the end of the text before M99 (BLOCK NOT FOUND on M at the O block's line,
/// checked at the call: nothing of the subprogram runs — the register's clarification); M99 in
/// the main program; M02/M30 in a subprogram ends all.
#[test]
fn return_alarms() {
    let t = expand("M98 P3\nG0 X9\nM30\n\nO3 (no return)\nG0 X1\n", Config::default());
    assert_eq!(t.alarm, al(AlarmCode::BlockNotFound, b'M', Rule::SubReturn, 5));
    assert!(moves(&t).is_empty());
    // An M30 in it does not make it a subprogram: it has no M99 either.
    let t = expand("G0 X2\nM98 P3\nM30\nO3\nG0 X1\nM30\n", Config::default());
    assert_eq!((t.alarm, moves(&t)), (al(AlarmCode::BlockNotFound, b'M', Rule::SubReturn, 4), std::vec![rapid(2, 0)]));
    assert_eq!(alarm_of("G0 X1\nM99\n"), al(AlarmCode::Unsupported, b'M', Rule::SubReturn, 2));
    // Before the words of the block (check step 2: the codes first).
    assert_eq!(alarm_of("M99 X1\n"), al(AlarmCode::Unsupported, b'M', Rule::SubReturn, 1));
    let t = expand("M98 P3\nG0 X9\nM30\nO3\nG0 X1\nM30\nG0 X2\nM99\n", Config::default());
    assert_eq!((t.alarm, moves(&t)), (None, std::vec![rapid(1, 0)]));
    // Under every dialect.
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(expand("M98 P3\nG0 X9\nM30\nO3\nG0 X1\nM99\n", nc201).alarm, None);
    assert_eq!(expand("M99\n", nc201).alarm, al(AlarmCode::Unsupported, b'M', Rule::SubReturn, 1));
}

/// SUB.CALL, SUB.RETURN: the words of M98 (N, M, P) and M99 (N, M) blocks, P's value, P missing.
#[test]
fn call_words_and_values() {
    let sub = "M30\nO1\nM99\n";
    let a = |call: &str| alarm_of(&format!("{call}\n{sub}"));
    let call = |code: AlarmCode, word: u8, rule: Rule| al(code, word, rule, 1);
    assert_eq!(a("M98"), call(AlarmCode::MissingWord, b'P', Rule::SubCall));
    assert_eq!(a("N5 M98 P1"), None);
    assert_eq!(a("M98 P1 X1"), call(AlarmCode::WordNotAllowed, b'X', Rule::SubCall));
    assert_eq!(a("G0 M98 P1"), call(AlarmCode::WordNotAllowed, b'G', Rule::SubCall));
    assert_eq!(a("O5 M98 P1"), call(AlarmCode::WordNotAllowed, b'O', Rule::SubCall));
    assert_eq!(a("M98 P1 S100 T1"), call(AlarmCode::WordNotAllowed, b'S', Rule::SubCall));
    // Words before values: a word not allowed wins over a bad P.
    assert_eq!(a("M98 P1.5 Q1"), call(AlarmCode::WordNotAllowed, b'Q', Rule::SubCall));
    assert_eq!(a("M98 P1."), call(AlarmCode::NotInteger, b'P', Rule::ComRanges));
    assert_eq!(a("M98 P0"), call(AlarmCode::OutOfRange, b'P', Rule::SubCall));
    assert_eq!(a("M98 P-1"), call(AlarmCode::OutOfRange, b'P', Rule::SubCall));
    assert_eq!(a("M98 P30000"), call(AlarmCode::OutOfRange, b'P', Rule::SubCall));
    assert_eq!(a("M98 P100000000"), call(AlarmCode::OutOfRange, b'P', Rule::SubCall));
    assert_eq!(a("M98 P99999999999999999"), call(AlarmCode::OutOfRange, b'P', Rule::SubCall));
    assert_eq!(a("M98 P99990001"), None);
    // Conflicts come before the words allowed (check step 2).
    assert_eq!(a("M98 P1 X1 U1"), call(AlarmCode::Conflict, b'U', Rule::ComAbsInc));
    // M99's words.
    let r = |ret: &str| alarm_of(&format!("M98 P1\nM30\nO1\n{ret}\n"));
    assert_eq!(r("N9 M99"), None);
    assert_eq!(r("M99 P5"), al(AlarmCode::WordNotAllowed, b'P', Rule::SubReturn, 4));
    assert_eq!(r("G1 M99"), al(AlarmCode::WordNotAllowed, b'G', Rule::SubReturn, 4));
    // An M98 in a contour stays CNT.NOSUB.
    let t = alarm_of("G0 X50 Z5\nG71 U1 R1\nG71 P10 Q20 F1\nN10 G1 X20\nN20 M98 P1 Z-10\nM30\nO1\nM99\n");
    assert_eq!(t, al(AlarmCode::WordNotAllowed, b'M', Rule::CntNosub, 5));
}

/// Contours: a G70 in a subprogram searches its own program, from its O block; a G70 in the
/// main program does not see a subprogram's blocks; a G71 in a subprogram reads ahead there.
#[test]
fn contours_within_their_program() {
    let main = "G0 X50 Z5\nM98 P8\nM30\n";
    let contour = "N10 G1 X20 F1\nN20 Z-10\n";
    let t = expand(&format!("{main}O8\n{contour}G0 X50 Z5\nG70 P10 Q20\nM99\n"), Config::default());
    assert_eq!(t.alarm, None);
    // The contour runs as ordinary blocks, then G70 finishes it: 2 + 1 + the finishing pass.
    assert!(moves(&t).len() > 3, "{}", t.to_gcode());
    // The contour stands in the main program, the G70 in the subprogram: not found.
    let t = expand(&format!("G0 X50 Z5\n{contour}G0 X50 Z5\nM98 P8\nM30\nO8\nG70 P10 Q20\nM99\n"), Config::default());
    assert_eq!(t.alarm, al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, 8));
    // The contour in the subprogram, the G70 in the main program after the call: not found.
    let t = expand(&format!("{main}O8\n{contour}M99\n").replace("M30\n", "G70 P10 Q20\nM30\n"), Config::default());
    assert_eq!(t.alarm, al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, 3));
    // The contour in the main program before the call, the G70 after it: the main program's
    // blocks are counted across the call (the caller's reader goes on where it stood).
    let t = expand(&format!("G0 X50 Z5\n{contour}G0 X50 Z5\nM98 P8\nG70 P10 Q20\nM30\nO8\nG0 X60\nG0 X50\nM99\n"), Config::default());
    assert_eq!(t.alarm, None);
    // The contour run as ordinary blocks (4 moves), the subprogram (2), the finishing pass (3).
    assert_eq!(moves(&t).len(), 4 + 2 + 3, "{}", t.to_gcode());
    assert_eq!(moves(&t).iter().filter(|m| m.rule == Rule::G70Path).count(), 2);
    // Run twice: each run searches from its O block again (the same contour, found once).
    let t = expand(&format!("G0 X50 Z5\nM98 P20008\nM30\nO8\n{contour}G0 X50 Z5\nG70 P10 Q20\nM99\n"), Config::default());
    assert_eq!(t.alarm, None);
    // G71 in a subprogram: its contour follows the P/Q block there; M99 after it returns.
    let t = expand(&format!("{main}O8\nG71 U1 R0.5\nG71 P10 Q20 F0.3\n{contour}M99\n"), Config::default());
    assert_eq!(t.alarm, None, "{}", t.to_gcode());
    assert_eq!(moves(&t).last().map(|m| (m.x, m.z)), Some((50_000, 5_000)));
}

/// Streaming: `fill` gives the iterator's events on subprogram programs, alarms included.
#[test]
fn fill_equals_the_iterator() {
    let sizes = [1, 2, 3, 5, 64];
    for src in [
        "G0 X0 Z0\nM98P42000\nG0 Z-1\nM30\nO2000\nG0 U2\nG90 X1 Z-3 F1\nM99\n",
        "M98 P1\nM30\nO1\nM98 P2\nG0 W-1\nM99\nO2\nG1 U1 F1\nM99\n",
        "M98 P3\nG0 X9\nM30\nO3\nG0 X1\n",
        "M98 P1\nM30\nO1\nM98 P1\nM99\n",
    ] {
        assert_fill_agrees(src, Config::default(), &sizes);
    }
}
