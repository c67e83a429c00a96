//! G73 (M003; docs/INTERPRETATION.md, "G73") on the whole expander: the seed's example 3, d = 1,
//! both formats and the kept values, the pass offsets' rounding, every alarm of the block and the
//! cycle checks with its word and rule, the pass bound before motion, and `fill` against the
//! iterator.
extern crate std;

use crate::tests::assert_fill_agrees;
use crate::tests::{expand, moves, passes};
use cycle_vocab::readings::G73C;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, MoveKind, Rule};
use std::vec::Vec;

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

/// The reading g73.c = skip (no rapid A → C): the pass offsets alone.
fn skip() -> Config {
    let mut c = Config::default();
    c.readings.g73_c = G73C::Skip;
    c
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

const EXAMPLE_3: &str = "N010 G50 X100 Z100\nN020 G00 X50 Z10\nN030 G73 U18 W5 R10\n\
    N040 G73 P50 Q100 U0.5 W0.5 F100\nN050 G01 X0 Z1\nN060 G03 X12 W-6 R6\nN070 G01 W-10\n\
    N080 X20 W-15\nN090 W-13\nN100 G02 X34 W-7 R7\nN110 G70 P50 Q100 F30\n";

/// The contour of example 3 (ends and centres), untranslated.
const CONTOUR_3: [(MoveKind, i64, i64, i64, i64); 6] = [
    (MoveKind::Feed, 0, 1_000, 0, 0),
    (MoveKind::ArcCcw, 12_000, -5_000, 0, -5_000),
    (MoveKind::Feed, 12_000, -15_000, 0, 0),
    (MoveKind::Feed, 20_000, -30_000, 0, 0),
    (MoveKind::Feed, 20_000, -43_000, 0, 0),
    (MoveKind::ArcCw, 34_000, -50_000, 34_000, -43_000),
];

/// G73.EXAMPLE: ten passes, pass n offset by (2·round(1.8·(10 − n)) + 0.5,
/// round(0.5·(10 − n)) + 0.5), each a rapid to A + T_n then the contour translated (arcs about
/// translated centres, at F100); the last one on the contour plus U0.5 W0.5; then the rapid to A and G70.
/// Under the letter (g73.c = visit) the tool first retreats to C = X86.5 Z15.5 (the register).
#[test]
fn example_3() {
    let t = expand(EXAMPLE_3, Config::default());
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(p.len(), 11);
    let m = moves(&t);
    let mut want = std::vec![Move::rapid(50_000, 10_000, Rule::PrjModal), Move::rapid(86_500, 15_500, Rule::G73Path)];
    for n in 1..=10i64 {
        let (ei, ek) = (1_800 * (10 - n), 500 * (10 - n));
        assert_eq!((p[n as usize - 1].index, p[n as usize - 1].diameter_depth), (n as u32, 2 * ei));
        assert_eq!(p[n as usize - 1].rule, Rule::G73Depth);
        let (tx, tz) = (2 * ei + 500, ek + 500);
        want.push(Move::rapid(50_000 + tx, 10_000 + tz, Rule::G73Path));
        for (kind, x, z, cx, cz) in CONTOUR_3 {
            want.push(match kind {
                MoveKind::Feed => Move::feed(x + tx, z + tz, 1_000_000, Rule::G73Path),
                k => Move::arc(k == MoveKind::ArcCw, x + tx, z + tz, cx + tx, cz + tz, 1_000_000, Rule::G73Path),
            });
        }
    }
    want.push(Move::rapid(50_000, 10_000, Rule::G73Path));
    assert_eq!(m[..want.len()], want[..]);
    // The last pass: the contour plus U0.5 W0.5.
    assert_eq!(m[want.len() - 2], Move::arc(true, 34_500, -49_500, 34_500, -42_500, 1_000_000, Rule::G73Path));
    // G70 finds the same contour before it; the program goes on after N100 (CNT.FLOW).
    assert_eq!(m[want.len()], Move::feed(0, 1_000, 300_000, Rule::G70Path));
    assert_eq!(m.len(), want.len() + 7);
}

/// G73.COUNT: d = 1 is one pass at the allowances (depth 0), ns G00 a rapid.
#[test]
fn one_pass() {
    let src = "G00 X40 Z5\nG73 U6 W2 R1\nG73 P10 Q40 U0.4 W0.1 F0.2\nN10 G00 X10 Z1\nN20 G01 Z-10\n\
               N30 G02 X20 Z-15 R5\nN40 G01 X30 Z-25\nG00 X60 Z50\n";
    let t = expand(src, skip());
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t).iter().map(|p| (p.index, p.diameter_depth)).collect::<Vec<_>>(), [(1, 0)]);
    let m = moves(&t);
    assert_eq!(m[1..3], [Move::rapid(40_400, 5_100, Rule::G73Path), Move::rapid(10_400, 1_100, Rule::G73Path)]);
    assert_eq!(m[4], Move::arc(true, 20_400, -14_900, 20_400, -9_900, 2_000, Rule::G73Path));
    assert_eq!(m[6..], [Move::rapid(40_000, 5_000, Rule::G73Path), Move::rapid(60_000, 50_000, Rule::PrjModal)]);
}

/// G73.FORMAT: format (b) uses its own I, K, D and leaves format (a)'s kept values; a first
/// block without words falls back to 5135, 5136, 5137.
#[test]
fn both_formats_and_kept_values() {
    let contour = |n: u32| std::format!("N{n} G00 X16 Z2\nN{} G01 X40 Z-30\n", n + 1);
    let src = std::format!(
        "G00 X50 Z5\nG73 U8 W2 R4\nG73 P10 Q11 F0.25\n{}G73 P20 Q21 I4.5 K1.5 D3 F0.2\n{}G73 P30 Q31\n{}",
        contour(10),
        contour(20),
        contour(30)
    );
    let t = expand(&src, skip());
    assert_eq!(t.alarm, None);
    let d: Vec<(u32, i64)> = passes(&t).iter().map(|p| (p.index, p.diameter_depth)).collect();
    assert_eq!(d, [(1, 12_000), (2, 8_000), (3, 4_000), (4, 0), (1, 6_000), (2, 3_000), (3, 0), (1, 12_000), (2, 8_000), (3, 4_000), (4, 0)]);
    let mut c = skip();
    (c.params.p5135_escape_x, c.params.p5136_escape_z, c.params.p5137_count) = (Some(-3_000), Some(1_000), Some(3));
    let t = expand("G00 X50 Z5\nG73\nG73 P1 Q2 F1\nN1 G1 X10\nN2 Z-10\n", c);
    assert_eq!(t.alarm, None);
    let starts: Vec<(i64, i64)> = moves(&t).iter().filter(|m| m.kind == MoveKind::Rapid).map(|m| (m.x, m.z)).collect();
    assert_eq!(starts, [(50_000, 5_000), (46_000, 5_667), (48_000, 5_333), (50_000, 5_000), (50_000, 5_000)]);
}

/// G73.DEPTH: each offset the exact quotient rounded once, half away from zero (−1.5 → −2,
/// 0.5 → 1), the offsets never grow.
#[test]
fn offsets_round_half_away_from_zero() {
    let t = expand("G0 X10 Z0\nG73 U-0.003 W0.001 R2\nG73 P1 Q2 F1\nN1 G1 X5\nN2 Z-5\n", skip());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[1], Move::rapid(10_000 - 4, 1, Rule::G73Path));
    assert_eq!(passes(&t)[0].diameter_depth, 4);
}

/// Every alarm of the G73 blocks and of the cycle's checks, in the register's order.
#[test]
fn alarms() {
    use AlarmCode::*;
    let body = "N1 G1 X10\nN2 Z-10\n";
    let a = |head: &str| alarm_of(&std::format!("G0 X50 Z5\n{head}\n{body}"));
    // Words of each block.
    assert_eq!(a("G73 U1 W1 R1 F1"), al(WordNotAllowed, b'F', Rule::PrjWord, 2));
    assert_eq!(a("G73 P1 Q2 R1 F1"), al(WordNotAllowed, b'R', Rule::PrjWord, 2));
    assert_eq!(a("G73 P1 Q2 I1 K1 D1 R1 F1"), al(WordNotAllowed, b'R', Rule::PrjWord, 2));
    assert_eq!(a("G73 P1 Q2 I1 K1 D1 X1 F1"), al(WordNotAllowed, b'X', Rule::PrjWord, 2));
    // Values: d an integer ≥ 1; P, Q sequence numbers; I, K lengths.
    assert_eq!(a("G73 R1.0"), al(NotInteger, b'R', Rule::ComRanges, 2));
    assert_eq!(a("G73 R0"), al(OutOfRange, b'R', Rule::G73Count, 2));
    assert_eq!(a("G73 R-2"), al(OutOfRange, b'R', Rule::G73Count, 2));
    assert_eq!(a("G73 P1 Q2 I1 K1 D0 F1"), al(OutOfRange, b'D', Rule::G73Count, 2));
    assert_eq!(a("G73 P1 Q2 I1 K1 D9999999999999999 F1"), al(OutOfRange, b'D', Rule::G73Count, 2));
    assert_eq!(a("G73 P0 Q2 F1"), al(OutOfRange, b'P', Rule::CntPq, 2));
    assert_eq!(a("G73 P1 Q2 I1000000 K1 D1 F1"), al(OutOfRange, b'I', Rule::ComRanges, 2));
    assert_eq!(a("G73 U1000000 R1"), al(OutOfRange, b'U', Rule::ComRanges, 2));
    // Missing words: F, then P, Q, then (format (b)) I, K, D.
    assert_eq!(a("G73 P1 Q2"), al(MissingWord, b'F', Rule::ComLead, 2));
    assert_eq!(a("G73 Q2 F1"), al(MissingWord, b'P', Rule::CntPq, 2));
    assert_eq!(a("G73 P1 F1"), al(MissingWord, b'Q', Rule::CntPq, 2));
    assert_eq!(a("G73 P1 Q2 K1 D1 F1"), al(MissingWord, b'I', Rule::G73Format, 2));
    assert_eq!(a("G73 P1 Q2 I1 D1 F1"), al(MissingWord, b'K', Rule::G73Format, 2));
    assert_eq!(a("G73 P1 Q2 I1 K1 F1"), al(MissingWord, b'D', Rule::G73Format, 2));
    // CNT.FIND (the block after the cycle must be N(ns)), CNT.MAX, the blocks, CNT.FIRST.
    assert_eq!(alarm_of("G73 P1 Q2 F1\nG0 X1\nN1 G1 X10\nN2 Z-10\n"), al(BlockNotFound, b'P', Rule::CntFind, 1));
    assert_eq!(alarm_of("G73 P1 Q3 F1\nN1 G1 X10\nN2 Z-10\n"), al(BlockNotFound, b'Q', Rule::CntFind, 1));
    let long = std::format!("G73 P1 Q2 F1\nN1 G1 X10\n{}N2 Z-10\n", "Z-1\n".repeat(999));
    assert_eq!(alarm_of(&long), al(ContourTooLong, b'Q', Rule::CntMax, 1));
    assert_eq!(alarm_of("G73 P1 Q2 F1\nN1 G1 X10 M8\nN2 Z-10\n"), al(WordNotAllowed, b'M', Rule::CntWords, 2));
    assert_eq!(alarm_of("G73 P1 Q2 F1\nN1 X10\nN2 Z-10\n"), al(MissingWord, b'G', Rule::CntFirst, 2));
    assert_eq!(alarm_of("G73 P1 Q2 F1\nN1 G2 X10 R5\nN2 G1 Z-10\n"), al(WordNotAllowed, b'G', Rule::CntFirst, 2));
    // nc201: the code does not exist.
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(expand("G73 U1 W1 R1\n", nc201).alarm, al(UnsupportedCode, b'G', Rule::PrjDialect, 1));
}

/// PRJ.MAXPASS: d > max_passes is refused on the word that gave d, before any motion — a huge
/// legal d at once; exactly the bound is cut.
#[test]
fn pass_bound_before_motion() {
    let body = "N1 G1 X10\nN2 Z-10\n";
    let t = expand(&std::format!("G73 U1 W1 R999999999\nG73 P1 Q2 F1\n{body}"), Config::default());
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'R', Rule::PrjMaxPass, 2));
    assert!(t.events.is_empty());
    let t = expand(&std::format!("G73 P1 Q2 I1 K1 D10001 F1\n{body}"), Config::default());
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'D', Rule::PrjMaxPass, 1));
    assert!(t.events.is_empty());
    // The contour is found and checked first (step 5's order).
    let t = expand("G73 P1 Q2 I1 K1 D10001 F1\nN1 X10\nN2 Z-10\n", Config::default());
    assert_eq!(t.alarm, al(AlarmCode::MissingWord, b'G', Rule::CntFirst, 2));
    let t = expand(&std::format!("G0 X50 Z5\nG73 P1 Q2 I1 K1 D10000 F1\n{body}"), Config::default());
    assert_eq!((t.alarm, passes(&t).len()), (None, 10_000));
}

/// CYC.ONESHOT: the motion mode and a G90 run go on after the cycle; the modal feed is G73's F.
#[test]
fn one_shot() {
    let t = expand("G0 X50 Z5\nG1 F0.3\nG73 P1 Q2 I1 K1 D1 F0.1\nN1 G0 X10\nN2 G1 Z-10\nX60 Z6\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t).last(), Some(&Move::feed(60_000, 6_000, 1_000, Rule::PrjModal)));
}

#[test]
fn fill_equals_the_iterator() {
    let sizes: Vec<usize> = (1..=40).chain([64, 1_000]).collect();
    for src in [
        EXAMPLE_3,
        "G00 X40 Z5\nG73 U6 W2 R1\nG73 P10 Q40 U0.4 W0.1 F0.2\nN10 G00 X10 Z1\nN20 G01 Z-10\nN30 G02 X20 Z-15 R5\nN40 G01 X30 Z-25\nG00 X60 Z50\n",
        "G0 X50 Z5\nG73 P1 Q2 I1 K1 D3 F1\nN1 G0 X50\nN2 G1 Z-10\nG73 P1 Q2 F1\nN1 X1\n",
    ] {
        assert_fill_agrees(src, Config::default(), &sizes);
    }
}

/// G73.USE: a contour that is not monotone (out to X20, back in to X14, out to X30) is taken by
/// G73 and run on every pass; G71 refuses the same contour (G71.MONOTONE).
#[test]
fn any_contour_is_taken() {
    let contour = "N10 G00 X10\nN20 G01 X20 Z-5\nN30 X14 Z-10\nN40 X30 Z-20\n";
    let g73 = expand(&std::format!("G00 X40 Z5\nG73 U2 W0 R2\nG73 P10 Q40 F0.2\n{contour}"), Config::default());
    assert_eq!(g73.alarm, None);
    assert!(moves(&g73).iter().any(|m| (m.x, m.z) == (14_000, -10_000)), "the last pass runs the contour as written");
    let g71 = expand(&std::format!("G00 X40 Z5\nG71 U1 R0.5\nG71 P10 Q40 F0.2\n{contour}"), Config::default());
    assert_eq!(g71.alarm.map(|a| a.rule), Some(Rule::G71Monotone));
}

/// `fill` builds each pass — its header, the rapid to its start, its contour elements — in place,
/// and takes only the rapid to C, the return to A and the end from `next_event` (issue #33: the
/// two paths give the same events, as `fill_equals_the_iterator` checks, so only the count of
/// `next_event` calls tells which ran): d = 4 passes over four elements, filled through buffers of
/// 1 to 64 events, call `next_event` three times under g73.c = visit and twice under skip; the
/// iterator alone is called once per event and once more for the end.
#[test]
fn fill_builds_the_passes_in_place() {
    use crate::g73::{Cycle, Words};
    use crate::probe;
    use cycle_vocab::Event;
    let (contour, a, w) = crate::tests::g73_case();
    for (w, calls) in [(w, 3), (Words { visit_c: false, ..w }, 2)] {
        let cycle = Cycle::new(a, &w, &contour, 10_000, 3).unwrap();
        let (mut c, mut pos, before) = (cycle, a, probe::calls());
        let mut events = 0;
        while c.next_event(&mut pos, &contour).is_some() {
            events += 1;
        }
        // 1 + 4 passes × (header, rapid, four elements) + the return (+ the rapid to C).
        assert_eq!(events, calls - 1 + 4 * 6);
        assert_eq!(probe::calls() - before, events + 1, "the iterator counts each call");
        for size in (1..=12).chain([64]) {
            let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
            let mut buffer = std::vec![filler; size];
            let (mut c, mut pos, mut got, before) = (cycle, a, 0, probe::calls());
            loop {
                let (n, done) = c.fill(&mut pos, &mut buffer, &contour);
                got += n;
                if done {
                    break;
                }
            }
            assert_eq!(got, events, "buffer of {size}");
            assert_eq!(probe::calls() - before, calls, "buffer of {size}: next_event ran for a pass's event");
        }
    }
}
