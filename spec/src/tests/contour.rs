//! Every alarm of docs/INTERPRETATION.md's contour sections (CNT.*, G70, G71, G72) with its
//! code, word, rule and line, the cycle check order, CNT.FLOW, and the layer ends on arcs.

use crate::tests::util::*;
use crate::contour::Contour;
use crate::expand;
use crate::stock_removal::layers::arc_crossing;
use crate::stock_removal::{Axes, Cycle};
use cycle_vocab::{AlarmCode, Config, Event, Params, Rule};
use AlarmCode::*;




/// A G71 program from A = X50 Z2 with `contour` as blocks N10, N20, … (one per line, from line 4).
fn g71(contour: &[&str]) -> String {
    let nf = 10 * contour.len();
    let mut s = format!("G00 X50 Z2\nG71 U2 R0.5\nG71 P10 Q{nf} U0.4 W0.1 F0.3\n");
    for (i, b) in contour.iter().enumerate() {
        s.push_str(&format!("N{} {b}\n", 10 * (i + 1)));
    }
    s
}

/// G71.FORMAT, G71.DEPTH, G71.RETRACT, G72.DEPTH, CNT.PQ: words and values of both blocks,
/// then the missing words in the register's order (F, P, Q), all on the cycle block's line.
#[test]
fn cycle_block_words_values_and_missing_words() {
    let cases: &[(&str, Expect)] = &[
        ("G71 U0 R1", (OutOfRange, Some('U'), Rule::G71Depth, 1)),
        ("G71 U-1", (OutOfRange, Some('U'), Rule::G71Depth, 1)),
        ("G71 U1000000", (OutOfRange, Some('U'), Rule::G71Depth, 1)),
        ("G71 R-0.001", (OutOfRange, Some('R'), Rule::G71Retract, 1)),
        ("G71 U1.0001", (Precision, Some('U'), Rule::ComUnits, 1)),
        ("G71 U1 F1", (WordNotAllowed, Some('F'), Rule::PrjWord, 1)),
        ("G71 U1 W1", (WordNotAllowed, Some('W'), Rule::PrjWord, 1)),
        ("G72 W0", (OutOfRange, Some('W'), Rule::G72Depth, 1)),
        ("G72 W1 R-1", (OutOfRange, Some('R'), Rule::G72Depth, 1)),
        ("G72 U1", (WordNotAllowed, Some('U'), Rule::PrjWord, 1)),
        ("G71 P10 Q20 X1 F1", (WordNotAllowed, Some('X'), Rule::PrjWord, 1)),
        ("G71 P10 Q20 R1 F1", (WordNotAllowed, Some('R'), Rule::PrjWord, 1)),
        ("G71 P1.0 Q2 F1", (NotInteger, Some('P'), Rule::ComRanges, 1)),
        ("G71 P0 Q2 F1", (OutOfRange, Some('P'), Rule::CntPq, 1)),
        ("G72 P1 Q100000 F1", (OutOfRange, Some('Q'), Rule::CntPq, 1)),
        ("G70 P1 Q2 U1000000 F1", (OutOfRange, Some('U'), Rule::ComRanges, 1)),
        ("G70 P1 Q2 R1 F1", (WordNotAllowed, Some('R'), Rule::PrjWord, 1)),
        ("G71 P10 Q20", (MissingWord, Some('F'), Rule::ComLead, 1)),
        ("G71 Q20 F1", (MissingWord, Some('P'), Rule::CntPq, 1)),
        ("G72 P10 F1", (MissingWord, Some('Q'), Rule::CntPq, 1)),
        ("G70 Q20", (MissingWord, Some('F'), Rule::ComLead, 1)),
        ("G70 Q20 F1", (MissingWord, Some('P'), Rule::CntPq, 1)),
        ("G70 P20 F1", (MissingWord, Some('Q'), Rule::CntPq, 1)),
        ("G0 G71 U1", (Conflict, Some('G'), Rule::PrjWord, 1)),
    ];
    for (src, expect) in cases {
        assert_eq!(alarm_of(src), *expect, "{src}");
    }
    // The modal feed serves: a G71 second block without F after G01 F0.2 is looking for N10.
    assert_eq!(alarm_of("G1 X50 F0.2\nG71 P10 Q20\nG0 X1"), (BlockNotFound, Some('P'), Rule::CntFind, 2));
}

/// CNT.FIND, CNT.MAX: where the contour must stand, on the cycle block's line.
#[test]
fn finding_the_contour() {
    let lines = |n: usize, nf: &str| -> String { (0..n).map(|i| format!("N{} G01 X{}\n", 10 + i, 20 + i % 5)).chain([nf.to_string()]).collect() };
    let cases: &[(String, Expect)] = &[
        ("G0 X50\nG71 P10 Q20 F1\nN11 G0 X20\nN20 Z-5".into(), (BlockNotFound, Some('P'), Rule::CntFind, 2)),
        ("G0 X50\nG71 P10 Q20 F1\n".into(), (BlockNotFound, Some('P'), Rule::CntFind, 2)),
        ("G0 X50\nG71 P10 Q20 F1\nN10 G0 X20\nN21 Z-5\n".into(), (BlockNotFound, Some('Q'), Rule::CntFind, 2)),
        // G70: N(ns) exactly once before it; N(nf) after it, before the G70 block.
        ("G0 X50\nG70 P10 Q20 F1\nN10 G0 X20\nN20 Z-5".into(), (BlockNotFound, Some('P'), Rule::CntFind, 2)),
        ("N10 G0 X20\nN10 G0 X30\nN20 Z-5\nG70 P10 Q20 F1".into(), (BlockNotFound, Some('P'), Rule::CntFind, 4)),
        ("N20 G0 X20\nN10 G0 X30\nG70 P10 Q20 F1\nN20 Z-5".into(), (BlockNotFound, Some('Q'), Rule::CntFind, 3)),
        // A 1 001st block without N(nf) is CONTOUR TOO LONG; 1 000 blocks then the end: not found.
        (format!("G0 X50 Z2\nG71 P10 Q5000 F1\n{}", lines(1_000, "X1\n")), (ContourTooLong, Some('Q'), Rule::CntMax, 2)),
        (format!("G0 X50 Z2\nG71 P10 Q5000 F1\n{}", lines(1_000, "N5000 X1\n")), (ContourTooLong, Some('Q'), Rule::CntMax, 2)),
        (format!("G0 X50 Z2\nG71 P10 Q5000 F1\n{}", lines(1_000, "")), (BlockNotFound, Some('Q'), Rule::CntFind, 2)),
        (format!("G1 F1\n{}G70 P10 Q5000\n", lines(1_001, "N5000 X1\n")), (ContourTooLong, Some('Q'), Rule::CntMax, 1_004)),
        // A lexing alarm met while the contour is read is that alarm, on its line.
        ("G0 X50\nG71 P10 Q20 F1\nN10 G0 X20\nN15 Z-5 #\nN20 Z-9".into(), (BadCharacter, Some('#'), Rule::PrjLex, 4)),
    ];
    for (src, expect) in cases {
        assert_eq!(alarm_of(src), *expect, "{src}");
    }
    // 1 000 blocks, N(nf) the last of them: found, and checked — its last point has A's Z, so
    // MONOTONE's c = 0 names Z on the cycle block's line.
    let src = format!("G0 X50 Z2\nG71 P10 Q1009 F1\n{}", lines(999, "N1009 X1\n"));
    assert_eq!(alarm_of(&src), (Geometry, Some('Z'), Rule::G71Monotone, 2));
    // N(nf) twice after N(ns): the first ends the contour; the second runs as an ordinary block.
    let t = expand(b"G0 X50\nG72 P10 Q20 F1\nN10 G0 Z-20\nN20 X20\nN20 Z2\n", &Config::default());
    assert_eq!((t.alarm, t.moves().last().map(|m| (m.x, m.z))), (None, Some((50_000, 2_000))));
}

/// CNT.WORDS, CNT.NOSUB, arcs in the contour, CNT.FIRST: each on the contour block's line.
#[test]
fn contour_block_checks() {
    let cases: &[(&[&str], Expect)] = &[
        (&["G01 X20", "G04 Z-5"], (WordNotAllowed, Some('G'), Rule::CntWords, 5)),
        (&["G01 X20", "G41 Z-5"], (WordNotAllowed, Some('G'), Rule::CntWords, 5)),
        (&["G01 X20", "G71 Z-5"], (WordNotAllowed, Some('G'), Rule::CntWords, 5)),
        (&["G01 X20", "G1.5 Z-5"], (WordNotAllowed, Some('G'), Rule::CntWords, 5)),
        (&["G01 X20", "Z-5 M98"], (WordNotAllowed, Some('M'), Rule::CntNosub, 5)),
        (&["G01 X20 M99"], (WordNotAllowed, Some('M'), Rule::CntNosub, 4)),
        (&["G01 X20", "Z-5 M3"], (WordNotAllowed, Some('M'), Rule::CntWords, 5)),
        // M98, M99 "by exact value": M98.0 and M99.00 are M98 and M99.
        (&["G01 X20", "Z-5 M98.0"], (WordNotAllowed, Some('M'), Rule::CntNosub, 5)),
        (&["G01 X20", "Z-5 M99.00"], (WordNotAllowed, Some('M'), Rule::CntNosub, 5)),
        (&["G01 X20", "Z-5 M9.8"], (WordNotAllowed, Some('M'), Rule::CntWords, 5)),
        (&["G01 X20", "Z-5 P1"], (WordNotAllowed, Some('P'), Rule::CntWords, 5)),
        (&["G01 X20", "Z-5 O1"], (WordNotAllowed, Some('O'), Rule::CntWords, 5)),
        (&["G01 X20", "Z-5 J1"], (WordNotAllowed, Some('J'), Rule::CntWords, 5)),
        (&["G01 X20", "Z-5 R1"], (WordNotAllowed, Some('R'), Rule::PrjWord, 5)),
        (&["G01 X20", "G01 G02 Z-5"], (Conflict, Some('G'), Rule::PrjWord, 5)),
        (&["G01 X20", "X30 U1"], (Conflict, Some('U'), Rule::ComAbsInc, 5)),
        (&["G01 X20", "G02 X30 Z-5 R5 K1"], (Conflict, Some('R'), Rule::ArcFormat, 5)),
        (&["G01 X20", "G02 X30 Z-5"], (MissingWord, Some('R'), Rule::ArcFormat, 5)),
        (&["G01 X20", "G02 X30 Z-5 R0"], (OutOfRange, Some('R'), Rule::ArcR, 5)),
        (&["G01 X20", "G02 X40 Z-5 R1"], (Geometry, Some('R'), Rule::ArcR, 5)),
        (&["G01 X20", "G02 X30 Z-5 I0 K0"], (Geometry, Some('I'), Rule::ArcIk, 5)),
        (&["G01 X20", "G03 X30 Z-5 I1"], (Geometry, Some('X'), Rule::ArcTol, 5)),
        (&["G01 X20", "Z-5 F0"], (OutOfRange, Some('F'), Rule::ComRanges, 5)),
        // CNT.FIRST, after every block's own checks.
        (&["X20", "Z-5"], (MissingWord, Some('G'), Rule::CntFirst, 4)),
        (&["X20", "Z-5 Q1"], (WordNotAllowed, Some('Q'), Rule::CntWords, 5)),
        (&["G02 X20 Z2 R20", "G01 Z-5"], (WordNotAllowed, Some('G'), Rule::CntFirst, 4)),
    ];
    for (contour, expect) in cases {
        assert_eq!(alarm_of(&g71(contour)), *expect, "{contour:?}");
    }
    // The same checks for G70's contour, which stands before it. Its blocks run first as
    // ordinary blocks (CNT.FLOW), so its M98 is a legal call there (SUB.CALL: N, M, P only);
    // as a contour block it is still CNT.NOSUB (SUB.* "Contours").
    let g70 = "N10 G0 X20 F1\nN20 M98 P1000\nN30 Z-5\nG70 P10 Q30\nM30\nO1000\nM99\n";
    assert_eq!(alarm_of(g70), (WordNotAllowed, Some('M'), Rule::CntNosub, 2));
    assert_eq!(alarm_of("N10 G0 X20 F1\nN20 Z-5 M98\nG70 P10 Q20"), (WordNotAllowed, Some('Z'), Rule::SubCall, 2));
    // No feed is needed in a contour, and arcs need none either.
    assert_eq!(expand(g71(&["G01 X20", "Z-5", "G02 X30 Z-10 R5", "G01 X50"]).as_bytes(), &Config::default()).alarm, None);
    // A T word while compensation is in force, as in any block (TNRC.SWITCH).
    assert_eq!(alarm_of(&format!("G41\n{}", g71(&["G01 X20", "Z-5 T0101", "X50"]))), (WordNotAllowed, Some('T'), Rule::TnrcSwitch, 6));
}

/// G71/G72 cycle checks (4)–(6) and their order: CNT.FIRST before TYPE2 before FIRST before
/// MONOTONE before the pass bound; all before any motion of the cycle.
#[test]
fn shape_checks_and_their_order() {
    let cases: &[(&[&str], Expect)] = &[
        (&["G01 X20 Z1", "Z-5", "X50"], (Unsupported, Some('Z'), Rule::G71Type2, 4)),
        (&["G01 Z-1", "X50"], (Unsupported, Some('Z'), Rule::G71Type2, 4)),
        (&["G01 X50 Z2", "Z-5"], (Geometry, Some('X'), Rule::G71First, 4)),
        (&["G01 W0", "Z-5"], (Geometry, Some('X'), Rule::G71First, 4)),
        (&["G01 X20", "X30", "X50"], (Geometry, Some('Z'), Rule::G71Monotone, 3)),
        (&["G01 X20", "Z-5", "X18", "X50 Z-9"], (Geometry, Some('X'), Rule::G71Monotone, 6)),
        (&["G01 X20", "Z-5", "X30 Z-4", "Z-9"], (Geometry, Some('Z'), Rule::G71Monotone, 6)),
        // X is checked before Z on the same element.
        (&["G01 X20", "Z-5", "X18 Z-4", "Z-9"], (Geometry, Some('X'), Rule::G71Monotone, 6)),
        // Arcs: a half circle through an extreme X fails on X; a quarter through extreme Z on Z.
        (&["G01 X20", "Z-5", "G03 X20 Z-15 R5", "G01 X50"], (Geometry, Some('X'), Rule::G71Monotone, 6)),
        // A short arc about X30 Z−9 through its top (+Z): ends at equal Z, X rising; turns in Z.
        (&["G01 X24", "Z-5", "G03 X36 Z-5 I3 K-4", "G01 X50 Z-9"], (Geometry, Some('Z'), Rule::G71Monotone, 6)),
        // A short arc about X22 Z−8 through its extreme X: ends at equal X, Z falling; turns in X.
        (&["G01 X30", "Z-5", "G03 X30 Z-11 I-4 K-3", "G01 X50"], (Geometry, Some('X'), Rule::G71Monotone, 6)),
    ];
    for (contour, expect) in cases {
        assert_eq!(alarm_of(&g71(contour)), *expect, "{contour:?}");
    }
    // Monotone arcs pass: a ball end (G03 +Z → +X) and a fillet (G02 −X → −Z).
    assert_eq!(expand(g71(&["G01 X20", "G03 X30 Z-3 I0 K-5", "G01 Z-9", "G02 X40 Z-14 I5 K0", "G01 X50"]).as_bytes(), &Config::default()).alarm, None);
    // G72, mirrored: TYPE2 on X, FIRST on Z, c = 0 on X, Z checked before X on an element.
    let g72 = |c: &str| format!("G00 X50 Z2\nG72 W2 R0.5\nG72 P10 Q30 F0.3\n{c}");
    assert_eq!(alarm_of(&g72("N10 G00 X40 Z-20\nN20 X20\nN30 Z2")), (Unsupported, Some('X'), Rule::G72Type2, 4));
    assert_eq!(alarm_of(&g72("N10 G00 W0\nN20 X20\nN30 Z2")), (Geometry, Some('Z'), Rule::G72First, 4));
    assert_eq!(alarm_of(&g72("N10 G00 Z-20\nN20 Z-10\nN30 X50")), (Geometry, Some('X'), Rule::G72Monotone, 3));
    assert_eq!(alarm_of(&g72("N10 G00 Z-20\nN20 X55 Z-25\nN30 X20 Z2")), (Geometry, Some('Z'), Rule::G72Monotone, 5));
    assert_eq!(alarm_of(&g72("N10 G00 Z-20\nN20 X55 Z-10\nN30 X20 Z2")), (Geometry, Some('X'), Rule::G72Monotone, 5));
}

/// PRJ.MAXPASS: layers + 1 > `max_passes` is `TOO MANY PASSES` on U (G72: W), before any
/// motion of the cycle. g71: layers X46 … X22 from X50 toward Q₀.x 20.4 (7 + SEMI = 8 passes).
#[test]
fn pass_bound_before_any_motion() {
    let with = |n: i64| Config { params: Params { max_passes: Some(n), ..Params::default() }, ..Config::default() };
    let src = g71(&["G00 X20", "G01 Z-20", "X50"]);
    let t = expand(src.as_bytes(), &with(7));
    assert_eq!(t.alarm.map(|a| (a.code, a.word, a.rule, a.line)), Some((TooManyPasses, Some(b'U'), Rule::PrjMaxPass, 3)));
    assert_eq!(t.events.len(), 1); // only the G00 to A
    let t = expand(src.as_bytes(), &with(8));
    assert_eq!((t.alarm, t.events.iter().filter(|e| matches!(e, Event::Pass(_))).count()), (None, 8));
    let g72 = "G00 X50 Z2\nG72 W1 R0.5\nG72 P10 Q30 F0.3\nN10 G00 Z-20\nN20 G01 X20\nN30 Z2\n";
    assert_eq!(alarm_with(g72, &with(5)), (TooManyPasses, Some('W'), Rule::PrjMaxPass, 3));
    // Δd of one increment over a 2 000 mm diameter: 10⁶ layers, refused at once.
    let huge = "G00 X2000.002 Z2\nG71 U0.001 R0\nG71 P1 Q2 F1\nN1 G00 X0\nN2 G01 Z-1\n";
    assert_eq!(alarm_with(huge, &with(1_000_000)).0, TooManyPasses);
}

/// CNT.FLOW, CYC.ONESHOT: after G71 the program resumes after N(nf); a G90 run goes on; the
/// kept first blocks of G71 and G72 are apart and fall back to 5132/5133.
#[test]
fn flow_and_kept_values() {
    let t = expand(b"G00 X50 Z2\nG71 U2 R0.5\nG71 P10 Q20 F0.3\nN10 G00 X40\nN20 G01 Z-5\nG01 X60 F1\n", &Config::default());
    assert_eq!(t.moves().last().map(|m| (m.x, m.z, m.feed)), Some((60_000, 2_000, 10_000)));
    let a = expand(b"G0 X50 Z2\nG90 X40 Z-40 F0.3\nG71 P10 Q20 F0.3\nN10 G00 X45\nN20 G01 Z-5\nX35\n", &Config::default());
    assert_eq!(a.alarm, None);
    let tail: Vec<_> = a.moves().skip(a.moves().count() - 4).map(|m| (m.x, m.z)).collect();
    assert_eq!(tail, vec![(35_000, 2_000), (35_000, -40_000), (50_000, -40_000), (50_000, 2_000)]);
    let last_pass = a.events.iter().rev().find_map(|e| if let Event::Pass(p) = e { Some((p.index, p.rule)) } else { None });
    assert_eq!(last_pass, Some((2, Rule::G90Path)));
    // G72's first block does not change G71's Δd: G71 cuts at 5132 = 1 mm (X48, X46, …).
    let t = expand(b"G00 X50 Z2\nG72 W3 R1\nG71 P10 Q20 F0.3\nN10 G00 X40\nN20 G01 Z-5\n", &Config::default());
    let first_cut = t.moves().nth(1).map(|m| (m.x, m.z));
    assert_eq!(first_cut, Some((48_000, 2_000)));
    // A later first block omitting R falls back to 5133 = 0.5 mm (retract X + 1).
    let t = expand(b"G00 X50 Z2\nG71 U2 R1\nG71 U2\nG71 P10 Q20 F0.3\nN10 G00 X40\nN20 G01 Z-5\n", &Config::default());
    assert_eq!(t.moves().nth(3).map(|m| (m.x, m.z)), Some((47_000, -4_500)));
}

/// G71.LAYER on arcs: one integer root, the sign that keeps the point on the arc, rounded once
/// half away from zero; a tie needs an odd square under the root, so an odd X offset of the
/// start from the centre (possible with a rounded R centre, never with I/K).
#[test]
fn layer_ends_on_arcs() {
    let cycle = |ax| Cycle { ax, a: (0, 0), q: Contour { elements: Vec::new() }, s: -1, c: -1, depth: 1, retract: 0, feed: 1, line: 1 };
    let g71 = cycle(Axes::G71);
    // r² = 3 003² + 4 004² = 5 005² (half units); at X = c_x + 4 004 the root is 3 003: z = c_z ± 1 501.5.
    for (cz, up, expect) in [(-10_000, false, -11_502), (5_000, false, 3_499), (-5_000, true, -3_499), (10_000, true, 11_502)] {
        let c = (34_004, cz);
        let start = (c.0 - 3_003, if up { cz + 2_002 } else { cz - 2_002 });
        assert_eq!(arc_crossing(&g71, start, (c.0 + 5_005, cz), c, c.0 + 4_004), expect, "{cz} {up}");
        assert_eq!(arc_crossing(&g71, start, (c.0 + 5_005, cz), c, c.0 - 4_004), expect);
    }
    // Both signs without a tie: example 1's ball (+) and fillet (−) are checked end to end; here
    // a start on the centre line takes the sign from the end.
    let c = (20_000, -10_000);
    assert_eq!(arc_crossing(&g71, (10_000, -10_000), (20_000, -15_000), c, 12_000), -13_000); // √(10⁸ − 8 000²)/2 = 3 000
    assert_eq!(arc_crossing(&g71, (10_000, -10_000), (20_000, -5_000), c, 12_000), -7_000);
    // Beyond the circle's extreme (within the tolerance of the end): the root is 0.
    assert_eq!(arc_crossing(&g71, (10_000, -10_000), (20_000, -5_000), c, 9_999), -10_000);
    // G72: x = c_x ± √(r² − 4(Z − c_z)²) on the diameter count: never a tie.
    let g72 = cycle(Axes::G72);
    assert_eq!(arc_crossing(&g72, (30_000, -10_000), (20_000, -15_000), c, -13_000), 28_000); // √(10⁸ − 6 000²) = 8 000
    assert_eq!(arc_crossing(&g72, (30_000, -10_000), (20_000, -15_000), c, -14_999), 20_200); // √(10⁸ − 9 998²) = 199.99 → 200
}

/// g70_arcs_ik: each arc's centre is its start + (2I, K) and its kind is its G code; the eight
/// arcs cover the four quadrants in both directions, in the ordinary run and in G70's.
#[test]
fn g70_arcs_by_ik() {
    let t = expand(include_str!("../../../tests/programs/g70_arcs_ik.nc").as_bytes(), &Config::default());
    assert_eq!(t.alarm, None);
    let arcs: Vec<_> = t.moves().filter(|m| m.cx != 0).map(|m| (m.kind, m.x, m.z, m.cx, m.cz, m.rule)).collect();
    assert_eq!(arcs.len(), 16);
    use cycle_vocab::MoveKind::{ArcCcw, ArcCw};
    let expect = [
        (ArcCcw, 34_000, -2_000, 30_000, -2_000),
        (ArcCcw, 30_000, -5_000, 30_000, -3_000),
        (ArcCw, 26_000, -8_000, 30_000, -8_000),
        (ArcCw, 30_000, -11_000, 30_000, -9_000),
        (ArcCcw, 26_000, -14_000, 30_000, -14_000),
        (ArcCcw, 30_000, -17_000, 30_000, -19_000),
        (ArcCw, 26_000, -20_000, 26_000, -22_000),
        (ArcCw, 30_000, -23_000, 26_000, -23_000),
    ];
    for (i, a) in arcs.iter().enumerate() {
        assert_eq!((a.0, a.1, a.2, a.3, a.4), expect[i % 8]);
        assert_eq!(a.5, if i < 8 { Rule::ArcIk } else { Rule::G70Path });
    }
}

/// G70.PATH: "the first move goes to P₀ even when the ns block writes no axis word (with U/W:
/// from S to S + (U, W))"; G70.FEED: the ns block's F replaces G70's from that block on. S = X40
/// Z2; the ns block `N10 G1 F0.3` ends at S, translated by U1 W0.5 to P₀ = X41 Z2.5; N20 to X30
/// Z-10 translated to X31 Z-9.5; then the rapid back to S (G70.RETURN).
#[test]
fn g70_first_move_to_p0_without_axis_words() {
    let src = "G0 X40 Z2\nN10 G1 F0.3\nN20 X30 Z-10\nG0 X40 Z2\nG70 P10 Q20 U1 W0.5 F0.1\n";
    let t = run(src);
    let text = t.to_gcode();
    let g70: Vec<&str> = text.lines().skip(1).skip_while(|l| !l.starts_with("(PASS")).collect();
    assert_eq!(
        g70[1..],
        ["G01 X41.000 Z2.500 F0.3000", "G01 X31.000 Z-9.500 F0.3000", "G00 X40.000 Z2.000"]
    );
    assert_eq!(passes(&t), [(1, cycle_vocab::PassKind::Finish, 1_000, Rule::G70Path)]);
}
