//! Subprograms M98, M99 (SUB.CALL, SUB.FIND, SUB.RETURN, SUB.NEST, PRJ.MAXPASS) against
//! docs/INTERPRETATION.md, "Subprograms: M98, M99", and `003_…` lines 144–145.

use crate::expand;
use crate::tests::util::{alarm_of, alarm_with, run, run_with, Expect};
use cycle_vocab::{AlarmCode::*, Config, Dialect, MoveKind, Params, Rule};

/// The end points (X, Z) of the moves of a clean run.
fn ends(src: &str) -> Vec<(i64, i64)> {
    run(src).moves().map(|m| (m.x, m.z)).collect()
}

fn max_passes(n: i64) -> Config {
    Config { params: Params { max_passes: Some(n), ..Params::default() }, ..Config::default() }
}

/// SUB.CALL, SUB.RETURN: `M98 P1000` runs O1000 (from its O block to its M99) and the caller goes
/// on after its M98 block; the subprogram area follows the main program's M30.
#[test]
fn call_runs_the_subprogram_and_returns() {
    let src = "G0 X10\nM98 P1000\nG0 X30\nM30\nO1000\nG0 Z-5\nM99\n";
    assert_eq!(ends(src), vec![(10_000, 0), (10_000, -5_000), (30_000, -5_000)]);
    // `003_…` line 145, "M98 P2 … 调用2号程序一次": O2, once. M02 ends the main program too.
    assert_eq!(ends("M98 P2\nM02\nO2\nG0 X4\nM99\n"), vec![(4_000, 0)]);
}

/// SUB.CALL (DEPARTS from line 144's gloss): `M98P42000` calls O2000 **four** times — the last
/// four digits are the number, the digits before them the repeat count.
#[test]
fn p42000_runs_o2000_four_times() {
    let src = "G1 F1\nM98P42000\nM30\nO2000\nU1\nM99\n";
    assert_eq!(ends(src), vec![(1_000, 0), (2_000, 0), (3_000, 0), (4_000, 0)]);
    // r = 0 is one run; the number's leading zeros are its value (O0002 is O2).
    assert_eq!(ends("G1 F1\nM98 P00002\nM30\nO0002\nU1\nM99\n"), vec![(1_000, 0)]);
    assert_eq!(ends("G1 F1\nM98 P20002\nM30\nO2.0\nU1\nM99\n"), vec![(1_000, 0), (2_000, 0)]);
}

/// SUB.CALL: P's value (check step 3) and its presence (step 4); a bare `M98` is never ignored.
#[test]
fn p_word() {
    let area = "\nM30\nO1\nM99\n";
    let cases: &[(&str, Expect)] = &[
        ("M98", (MissingWord, Some('P'), Rule::SubCall, 1)),
        ("N5 M98", (MissingWord, Some('P'), Rule::SubCall, 1)),
        ("M98 P0", (OutOfRange, Some('P'), Rule::SubCall, 1)),
        ("M98 P-1", (OutOfRange, Some('P'), Rule::SubCall, 1)),
        ("M98 P10000", (OutOfRange, Some('P'), Rule::SubCall, 1)),
        ("M98 P100000000", (OutOfRange, Some('P'), Rule::SubCall, 1)),
        ("M98 P1.", (NotInteger, Some('P'), Rule::ComRanges, 1)),
        ("M98 P1.5", (NotInteger, Some('P'), Rule::ComRanges, 1)),
    ];
    for (block, expect) in cases {
        assert_eq!(alarm_of(&format!("{block}{area}")), *expect, "{block}");
    }
    // The largest P: 9 999 runs of O9999, within max_passes.
    let t = expand(b"M98 P99999999\nM30\nO9999\nM99\n", &Config::default());
    assert_eq!(t.alarm, None);
}

/// SUB.CALL, SUB.RETURN: an M98 block takes N, M, P; an M99 block N, M; any other word (G, O, S,
/// T, axes included) is `WORD NOT ALLOWED`, in alphabetical order, after the codes and conflicts.
#[test]
fn words_of_m98_and_m99_blocks() {
    let sub = "\nM30\nO1\nM99\n";
    let cases: &[(&str, Expect)] = &[
        ("M98 P1 X5", (WordNotAllowed, Some('X'), Rule::SubCall, 1)),
        ("G0 M98 P1", (WordNotAllowed, Some('G'), Rule::SubCall, 1)),
        ("O7 M98 P1", (WordNotAllowed, Some('O'), Rule::SubCall, 1)),
        ("M98 P1 S500", (WordNotAllowed, Some('S'), Rule::SubCall, 1)),
        ("M98 P1 T0101", (WordNotAllowed, Some('T'), Rule::SubCall, 1)),
        ("M98 F1", (WordNotAllowed, Some('F'), Rule::SubCall, 1)),
        ("M98 P1 L2", (WordNotAllowed, Some('L'), Rule::SubCall, 1)),
        // Codes and conflicts (step 2) come before the words allowed.
        ("G4 M98 P1", (UnsupportedCode, Some('G'), Rule::PrjSupported, 1)),
        ("M98 P1 X1 U1", (Conflict, Some('U'), Rule::ComAbsInc, 1)),
    ];
    for (block, expect) in cases {
        assert_eq!(alarm_of(&format!("{block}{sub}")), *expect, "{block}");
    }
    assert_eq!(alarm_of("M98 P1\nM30\nO1\nM99 P5\n"), (WordNotAllowed, Some('P'), Rule::SubReturn, 4));
    assert_eq!(alarm_of("M98 P1\nM30\nO1\nG0 M99\n"), (WordNotAllowed, Some('G'), Rule::SubReturn, 4));
    // The O block runs as any block (its O has no effect); N is allowed with M99.
    assert_eq!(ends("M98 P1\nM30\nO1 G0 X2\nN10 M99\n"), vec![(2_000, 0)]);
    // An O block that is also the M99 block: O is no word of an M99 block.
    assert_eq!(alarm_of("M98 P1\nM30\nO1 M99\n"), (WordNotAllowed, Some('O'), Rule::SubReturn, 3));
}

/// SUB.FIND: exactly one block of the area has O n (its exact value), else `BLOCK NOT FOUND` on
/// P at the M98 block; the area is what follows the main program's first M02/M30.
#[test]
fn finding_the_subprogram() {
    let not_found = (BlockNotFound, Some('P'), Rule::SubFind, 2);
    assert_eq!(alarm_of("G0 X1\nM98 P1000\nM30\nO2000\nM99\n"), not_found);
    assert_eq!(alarm_of("G0 X1\nM98 P1000\nM30\nO1000\nM99\nO1000.0\nM99\n"), not_found);
    // An O block in the main program is not in the area; no M02/M30: the area is empty.
    assert_eq!(alarm_of("G0 X1\nM98 P1000\nO1000\nM99\nM30\n"), not_found);
    assert_eq!(alarm_of("G0 X1\nM98 P1000\nO1000\nM99\n"), not_found);
    // O-1000 is not O1000; O01000 is.
    assert_eq!(alarm_of("G0 X1\nM98 P1000\nM30\nO-1000\nM99\n"), not_found);
    assert_eq!(ends("M98 P1000\nM30\nO01000\nG0 X3\nM99\n"), vec![(3_000, 0)]);
    // Nothing moved before the alarm but the block before the call.
    assert_eq!(expand(b"G0 X1\nM98 P1000\nM30\n", &Config::default()).moves().count(), 1);
}

/// SUB.RETURN: the end of the text before M99 is `BLOCK NOT FOUND` on M at the O block's line,
/// checked at the call (nothing of the subprogram runs); M99 in the main program is
/// `UNSUPPORTED` on M (check step 2, before its words); M02/M30 in a subprogram end the program.
#[test]
fn returning() {
    let t = expand(b"G0 X1\nM98 P7\nM30\nG0 X5\nO7\nG0 X9\n", &Config::default());
    let a = t.alarm.expect("an alarm");
    assert_eq!((a.code, a.word, a.rule, a.line), (BlockNotFound, Some(b'M'), Rule::SubReturn, 5));
    assert_eq!(t.moves().count(), 1);
    assert_eq!(alarm_of("G0 X1\nM99\n"), (Unsupported, Some('M'), Rule::SubReturn, 2));
    assert_eq!(alarm_of("M99 X1\n"), (Unsupported, Some('M'), Rule::SubReturn, 1));
    // M30 inside the subprogram ends the whole program: the caller's next block never runs.
    assert_eq!(ends("M98 P7\nG0 X50\nM30\nO7\nG0 X1\nM30\nM99\n"), vec![(1_000, 0)]);
}

/// SUB.NEST: four levels are legal; a call from level 4 is `NESTING` (3006) on P at that M98
/// block — recursion ends there too. The call's checks come in the register's order: SUB.FIND,
/// SUB.RETURN, then SUB.NEST, then the run bound.
#[test]
fn nesting() {
    let four = "M98 P1\nM30\nO1\nM98 P2\nM99\nO2\nM98 P3\nM99\nO3\nM98 P4\nM99\nO4\nG0 X4\nM99\n";
    assert_eq!(ends(four), vec![(4_000, 0)]);
    let five = "M98 P1\nM30\nO1\nM98 P2\nM99\nO2\nM98 P3\nM99\nO3\nM98 P4\nM99\nO4\nM98 P5\nM99\nO5\nG0 X5\nM99\n";
    assert_eq!(alarm_of(five), (Nesting, Some('P'), Rule::SubNest, 13));
    assert_eq!(alarm_of("M98 P1\nM30\nO1\nG1 U1 F1\nM98 P1\nM99\n"), (Nesting, Some('P'), Rule::SubNest, 5));
    let t = expand(b"M98 P1\nM30\nO1\nG1 U1 F1\nM98 P1\nM99\n", &Config::default());
    assert_eq!(t.moves().count(), 4);
    // From level 4, a missing program is SUB.FIND, not NESTING.
    let missing = "M98 P1\nM30\nO1\nM98 P2\nM99\nO2\nM98 P3\nM99\nO3\nM98 P4\nM99\nO4\nM98 P9\nM99\n";
    assert_eq!(alarm_of(missing), (BlockNotFound, Some('P'), Rule::SubFind, 13));
}

/// PRJ.MAXPASS: the runs of subprograms, every repeat counted, at most `max_passes`; the call that
/// would exceed it is `TOO MANY PASSES` on P before its first run.
#[test]
fn runs_are_bounded() {
    let c = max_passes(5);
    assert_eq!(run_with("G1 F1\nM98 P50001\nM30\nO1\nU1\nM99\n", &c).moves().count(), 5);
    let t = expand(b"G1 F1\nM98 P60001\nM30\nO1\nU1\nM99\n", &c);
    let a = t.alarm.expect("an alarm");
    assert_eq!((a.code, a.word, a.rule, a.line), (TooManyPasses, Some(b'P'), Rule::PrjMaxPass, 2));
    assert_eq!(t.moves().count(), 0);
    // Two calls: 3 + 3 > 5, the second one alarms after the first ran.
    assert_eq!(alarm_with("G1 F1\nM98 P30001\nM98 P30001\nM30\nO1\nU1\nM99\n", &c), (TooManyPasses, Some('P'), Rule::PrjMaxPass, 3));
    // Nested repeats count: 2 runs of O1, each calling O2 twice: 2 + 2 + 2 = 6 > 5 at the
    // second run's call.
    let nested = "G1 F1\nM98 P20001\nM30\nO1\nM98 P20002\nM99\nO2\nU1\nM99\n";
    assert_eq!(alarm_with(nested, &c), (TooManyPasses, Some('P'), Rule::PrjMaxPass, 5));
    assert_eq!(run_with(nested, &max_passes(6)).moves().count(), 4);
}

/// SUB.FIND: the call reads the whole area: a lexing alarm there is raised at the call, on its
/// own line, before the subprogram runs; without a call nothing after M30 is read.
#[test]
fn the_area_is_read_at_the_call() {
    let t = expand(b"G0 X1\nM98 P1\nM30\nO1\nG0 X2\nM99\nG0 #\n", &Config::default());
    let a = t.alarm.expect("an alarm");
    assert_eq!((a.code, a.word, a.line), (BadCharacter, Some(b'#'), 7));
    assert_eq!(t.moves().count(), 1);
    assert_eq!(expand(b"G0 X1\nM30\nO1\nG0 #\n", &Config::default()).alarm, None);
    // A lexing alarm of the main program after the call is met while the area is found.
    assert_eq!(alarm_of("M98 P1\nG0 #\nM30\nO1\nM99\n").3, 2);
}

/// SUB.RETURN: the modal state is one for the whole program — a subprogram changes it for its
/// caller (the G01 mode and the feed here), and a repeated run starts from the state the
/// previous run left.
#[test]
fn modal_state_is_shared() {
    let t = run("G0 X10\nM98 P1\nZ-4\nM30\nO1\nG1 X12 F0.5\nM99\n");
    let kinds: Vec<(MoveKind, i64, i64)> = t.moves().map(|m| (m.kind, m.x, m.z)).collect();
    assert_eq!(kinds, vec![(MoveKind::Rapid, 10_000, 0), (MoveKind::Feed, 12_000, 0), (MoveKind::Feed, 12_000, -4_000)]);
}

/// SUB.* "Contours": a cycle's contour is found in the program it stands in. G71 in a subprogram
/// reads its contour ahead there and the run goes on after N(nf) to M99; G70 in a subprogram
/// searches only that subprogram's blocks before it (from its O block).
#[test]
fn contours_in_subprograms() {
    let contour = "N10 G0 X0\nN20 G1 Z-10 F0.3\nN30 X40\n";
    let cycle = format!("G0 X41 Z1\nG71 U2 R1\nG71 P10 Q30 F0.2\n{contour}G0 X50 Z5\n");
    let path = |t: &cycle_vocab::text::Trace| t.moves().map(|m| (m.kind, m.x, m.z, m.rule)).collect::<Vec<_>>();
    let main = run(&cycle);
    let called = run(&format!("M98 P100\nM30\nO100\n{cycle}M99\n"));
    assert!(main.moves().any(|m| m.rule == Rule::G71Layer));
    assert_eq!(path(&main), path(&called));
    // G70 in O100 does not see the main program's N10 … N30 (they ran as ordinary blocks).
    let src = format!("G0 X41 Z1\n{contour}M98 P100\nM30\nO100\nG0 X41 Z1\nG70 P10 Q30 F0.1\nM99\n");
    assert_eq!(alarm_of(&src), (BlockNotFound, Some('P'), Rule::CntFind, 9));
    // With its contour in O100 (before it, from the O block on) it finishes along it.
    let inside = run(&format!("M98 P100\nM30\nO100\nG0 X41 Z1\n{contour}G0 X41 Z1\nG70 P10 Q30 F0.1\nM99\n"));
    assert!(inside.moves().any(|m| m.rule == Rule::G70Path));
    // M98 in a contour stays CNT.NOSUB, in a subprogram too.
    let nosub = "M98 P100\nM30\nO100\nG0 X41 Z1\nG71 P10 Q30 F0.2\nN10 G0 X0\nN20 G1 Z-10 M98\nN30 X40\nM99\n";
    assert_eq!(alarm_of(nosub), (WordNotAllowed, Some('M'), Rule::CntNosub, 7));
}

/// "Under every dialect": subprograms run under `nc201` and `fanuc` alike.
#[test]
fn every_dialect() {
    for dialect in [Dialect::Nc201, Dialect::Fanuc] {
        let c = Config { dialect, ..Config::default() };
        let t = run_with("M98 P20001\nM30\nO1\nG1 X2 F1\nG0 X0\nM99\n", &c);
        assert_eq!(t.moves().count(), 4, "{dialect:?}");
        assert_eq!(alarm_with("M98\n", &c), (MissingWord, Some('P'), Rule::SubCall, 1));
    }
}
