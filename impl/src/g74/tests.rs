//! G74 and G75 (M003; docs/INTERPRETATION.md, "G74 … and G75") on the whole expander: the seed's
//! examples 4 and 5, columns and reliefs, edges of the last peck, the kept e, every alarm of the
//! cycle's checks with its word and rule, the pass bound before motion, and `fill` against the
//! iterator.
extern crate std;

use crate::tests::assert_fill_agrees;
use crate::tests::{expand, moves, passes};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, Pass, PassKind, Rule};
use std::vec::Vec;

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

fn max_passes(n: i64) -> Config {
    let mut c = Config::default();
    c.params.max_passes = Some(n);
    c
}

const EXAMPLE_4: &str = "G0 X0 Z2\nG74 R1\nG74 Z-12 Q5 F30\n";
const EXAMPLE_5: &str = "G0 X42 Z22\nG75 R1\nG75 X30 Z10 P3 Q2.9 F30\n";

/// G74.EXAMPLE: pecks to Z−3, −8, −12, a 1 mm rapid back after each but the last, then the
/// rapid back to Z2; one column, depth 14 (printed as the Z depth).
#[test]
fn example_4() {
    let t = expand(EXAMPLE_4, Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t), [Pass { index: 1, kind: PassKind::Rough, diameter_depth: 28_000, rule: Rule::G74Column }]);
    let f = 300_000;
    assert_eq!(
        moves(&t)[1..],
        [
            Move::feed(0, -3_000, f, Rule::G74Peck),
            Move::rapid(0, -2_000, Rule::G74E),
            Move::feed(0, -8_000, f, Rule::G74Peck),
            Move::rapid(0, -7_000, Rule::G74E),
            Move::feed(0, -12_000, f, Rule::G74Peck),
            Move::rapid(0, 2_000, Rule::G74Column),
        ]
    );
}

/// G75.EXAMPLE: six grooves at Z22, 19.1, 16.2, 13.3, 10.4, 10; in each pecks to X36 (a rapid
/// to X38) and X30, back to X42; no relief; then Z back to 22.
#[test]
fn example_5() {
    let t = expand(EXAMPLE_5, Config::default());
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(p.len(), 6);
    assert!(p.iter().enumerate().all(|(i, p)| p.index == i as u32 + 1 && p.diameter_depth == 12_000 && p.rule == Rule::G75Column));
    let m = moves(&t);
    let mut want = std::vec![Move::rapid(42_000, 22_000, Rule::PrjModal)];
    for (j, z) in [22_000, 19_100, 16_200, 13_300, 10_400, 10_000].into_iter().enumerate() {
        if j > 0 {
            want.push(Move::rapid(42_000, z, Rule::G75Column));
        }
        want.push(Move::feed(36_000, z, 300_000, Rule::G75Peck));
        want.push(Move::rapid(38_000, z, Rule::G75Peck));
        want.push(Move::feed(30_000, z, 300_000, Rule::G75Peck));
        want.push(Move::rapid(42_000, z, Rule::G75Column));
    }
    want.push(Move::rapid(42_000, 22_000, Rule::G75Column));
    assert_eq!(m, want);
}

/// G74.COLUMN, G74.RELIEF: columns X20, 26, 32, 38, 40 (a shorter last step); a relief of
/// −2Δd in X at the bottom of every column but the first; back to A.
#[test]
fn g74_columns_and_relief() {
    let t = expand("G00 X20 Z1\nG74 R0.5\nG74 X40 Z-5 P3 Q2 R0.2 F0.05\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t).len(), 5);
    let m = moves(&t);
    let col: Vec<i64> = m.iter().filter(|m| m.rule == Rule::G74Column && m.z == 1_000 && m.x != 20_000).map(|m| m.x).collect();
    assert_eq!(col, [26_000, 25_600, 32_000, 31_600, 38_000, 37_600, 40_000, 39_600]);
    let reliefs: Vec<(i64, i64)> = m.iter().filter(|m| m.rule == Rule::G74Relief).map(|m| (m.x, m.z)).collect();
    assert_eq!(reliefs, [(25_600, -5_000), (31_600, -5_000), (37_600, -5_000), (39_600, -5_000)]);
    assert_eq!(m.last(), Some(&Move::rapid(20_000, 1_000, Rule::G74Column)));
    assert_eq!(m.iter().filter(|m| m.rule == Rule::G74Peck).count(), 15);
}

/// G75.RELIEF under g75.relief = against-step: +Z against a −Z step; G75 returns 2e on the
/// diameter. (The letter, −Z: `crate::tests::readings`.)
#[test]
fn g75_relief_against_the_step() {
    let mut c = Config::default();
    c.readings.g75_relief = cycle_vocab::readings::G75Relief::AgainstStep;
    let t = expand("G00 X52 Z-10\nG75 R0.5\nG75 X40 Z-20 P2 Q3 R0.3 F0.05\n", c);
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[1..3], [Move::feed(48_000, -10_000, 500, Rule::G75Peck), Move::rapid(49_000, -10_000, Rule::G75Peck)]);
    let reliefs: Vec<i64> = m.iter().filter(|m| m.rule == Rule::G75Relief).map(|m| m.z).collect();
    assert_eq!(reliefs, [-12_700, -15_700, -18_700, -19_700]);
    assert_eq!(m.last(), Some(&Move::rapid(52_000, -10_000, Rule::G75Column)));
}

/// G74.PECK edges: one peck when Q exceeds the depth; a last peck of one increment; e = 0 (no
/// return move); e kept per code and from parameter 5139; the modal feed after the cycle.
#[test]
fn peck_edges_and_kept_values() {
    let t = expand("G0 X0 Z2\nG74 R1\nG74 Z-3 Q10 F0.1\n", Config::default());
    assert_eq!(moves(&t)[1..], [Move::feed(0, -3_000, 1_000, Rule::G74Peck), Move::rapid(0, 2_000, Rule::G74Column)]);
    let t = expand("G0 X0 Z2\nG74 R0.5\nG74 Z-8.001 Q5 F0.1\n", Config::default());
    let z: Vec<i64> = moves(&t)[1..].iter().map(|m| m.z).collect();
    assert_eq!(z, [-3_000, -2_500, -8_000, -7_500, -8_001, 2_000]);
    // No first block: e = 5139's default 0, so no returns; G75's e is not G74's.
    let t = expand("G0 X0 Z2\nG75 R2\nG74 Z-8 Q4 F0.1\n", Config::default());
    let z: Vec<i64> = moves(&t)[1..].iter().map(|m| m.z).collect();
    assert_eq!(z, [-2_000, -6_000, -8_000, 2_000]);
    let mut c = Config::default();
    c.params.p5139_peck_return = Some(300);
    let t = expand("G0 X0 Z2\nG74 Z-8 Q5 F0.1\nG01 Z3\n", c);
    let m = moves(&t);
    assert_eq!(m[2], Move::rapid(0, -2_700, Rule::G74E));
    // The modal feed is the cycle's F; the motion mode (G00) is as before.
    assert_eq!(m.last(), Some(&Move::feed(0, 3_000, 1_000, Rule::PrjModal)));
    let t = expand("G0 X0 Z2\nG74 Z-8 Q5 F0.1\nZ3\n", Config::default());
    assert_eq!(moves(&t).last(), Some(&Move::rapid(0, 3_000, Rule::PrjModal)));
    // Incremental words; X travel toward −X.
    let t = expand("G0 X40 Z0\nG74 U-10 W-2 P2.5 Q5 F0.1\n", Config::default());
    let x: Vec<i64> = moves(&t).iter().filter(|m| m.rule == Rule::G74Peck).map(|m| m.x).collect();
    assert_eq!(x, [40_000, 35_000, 30_000]);
}

/// Every alarm of the register's checks, with its word and rule.
#[test]
fn alarms() {
    use AlarmCode::*;
    // (4) no feed at all.
    assert_eq!(alarm_of("G0 X0 Z2\nG74 Z-12 Q5\n"), al(MissingWord, b'F', Rule::ComLead, 2));
    // (5) G74: no Z travel; Δk = 0; X travel without Δi.
    assert_eq!(alarm_of("G0 X0 Z2\nG74 X10 P1 Q5 F1\n"), al(Geometry, b'Z', Rule::G74Format, 2));
    assert_eq!(alarm_of("G0 X0 Z2\nG74 Z-1 F1\n"), al(MissingWord, b'Q', Rule::G74Peck, 2));
    assert_eq!(alarm_of("G0 X0 Z2\nG74 Z-1 Q0 F1\n"), al(MissingWord, b'Q', Rule::G74Peck, 2));
    assert_eq!(alarm_of("G0 X0 Z2\nG74 X10 Z-1 Q1 F1\n"), al(MissingWord, b'P', Rule::G74Column, 2));
    assert_eq!(alarm_of("G0 X0 Z2\nG74 X10 Q1 F1\n"), al(Geometry, b'Z', Rule::G74Format, 2));
    // G75: no X travel; Δi = 0; Z travel without Δk.
    assert_eq!(alarm_of("G0 X40 Z2\nG75 Z-10 P1 Q1 F1\n"), al(Geometry, b'X', Rule::G75Format, 2));
    assert_eq!(alarm_of("G0 X40 Z2\nG75 X30 Q1 F1\n"), al(MissingWord, b'P', Rule::G75Peck, 2));
    assert_eq!(alarm_of("G0 X40 Z2\nG75 X30 Z-5 P1 F1\n"), al(MissingWord, b'Q', Rule::G75Column, 2));
    // Words and values.
    assert_eq!(alarm_of("G74 R1 F1\n"), al(WordNotAllowed, b'F', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G74 R1 Q1\n"), al(MissingWord, b'F', Rule::ComLead, 1));
    assert_eq!(alarm_of("G74 R1 K1\n"), al(WordNotAllowed, b'K', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G75 X1 Z1 I1 F1\n"), al(WordNotAllowed, b'I', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G74 R-1\n"), al(OutOfRange, b'R', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G74 Z-1 Q-1 F1\n"), al(OutOfRange, b'Q', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G75 X1 P-1 F1\n"), al(OutOfRange, b'P', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G75 X1 P1000000 F1\n"), al(OutOfRange, b'P', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G74 Z-1 Q0.0001 F1\n"), al(Precision, b'Q', Rule::ComUnits, 1));
    assert_eq!(alarm_of("G74 X1 U1 Z1\n"), al(Conflict, b'U', Rule::ComAbsInc, 1));
    assert_eq!(alarm_of("G74 G75 Z1\n"), al(Conflict, b'G', Rule::PrjWord, 1));
    // nc201: the codes do not exist.
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(expand("G74 R1\n", nc201).alarm, al(UnsupportedCode, b'G', Rule::PrjDialect, 1));
    assert_eq!(expand("G75 R1\n", nc201).alarm, al(UnsupportedCode, b'G', Rule::PrjDialect, 1));
    // fanuc reads Q5 as 5 mm too (G74.UNITS).
    let f = crate::tests::fanuc();
    assert_eq!(moves(&expand(EXAMPLE_4, f)), moves(&expand(EXAMPLE_4, Config::default())));
}

/// PRJ.MAXPASS: the pecks of all columns, in closed form, before any motion — a huge legal count
/// is refused at once; exactly the bound is cut.
#[test]
fn pass_bound_before_motion() {
    // 999 999 999 increments in pecks of 1: ~10^9 pecks, refused without a single move.
    let t = expand("G74 Z-999999.999 Q0.001 F1\n", Config::default());
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass, 1));
    assert!(t.events.is_empty());
    // 10^9 columns × 1 peck on G75: P names it.
    let t = expand("G75 X-999999.999 Z999999.999 P999999 Q0.001 F1\n", Config::default());
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'P', Rule::PrjMaxPass, 1));
    // 4 pecks × 3 columns = 12.
    let src = "G0 X0 Z0\nG74 X4 Z-4 P1 Q1 F1\n";
    assert_eq!(expand(src, max_passes(11)).alarm, al(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass, 2));
    let t = expand(src, max_passes(12));
    assert_eq!((t.alarm, passes(&t).len()), (None, 3));
    // 10 000 pecks (the default bound) are cut.
    let t = expand("G0 X0 Z0\nG74 Z-10 Q0.001 F1\n", Config::default());
    assert_eq!((t.alarm, moves(&t).iter().filter(|m| m.rule == Rule::G74Peck).count()), (None, 10_000));
}

#[test]
fn fill_equals_the_iterator() {
    let sizes: Vec<usize> = (1..=40).chain([64, 1_000]).collect();
    for src in [
        EXAMPLE_4,
        EXAMPLE_5,
        "G00 X20 Z1\nG74 R0.5\nG74 X40 Z-5 P3 Q2 R0.2 F0.05\nG1 X30\n",
        "G00 X52 Z-10\nG75 R0.5\nG75 X40 Z-20 P2 Q3 R0.3 F0.05\n",
        "G0 X0 Z2\nG74 Z-8 Q4 F0.1\nG75 X1 Z1\n",
    ] {
        assert_fill_agrees(src, Config::default(), &sizes);
    }
}

/// `Cycle::fill` on its own writes `next_event`'s events, and writes while it has room: G74
/// with columns and reliefs, and G75 (the stream would hide a `fill` that writes nothing).
#[test]
fn cycle_fill_on_its_own() {
    use crate::g74::{cycle, Cycle, PeckCode, Words};
    let sizes: Vec<usize> = (1..=12).chain([64]).collect();
    let w = Words { end: (40_000, -5_000), di: 3_000, dk: 2_000, relief: 200, e: 500, feed: 500, relief_minus_z: false };
    let g74 = cycle(PeckCode::G74, (20_000, 1_000), &w, 10_000, 2).unwrap();
    let g75 = cycle(PeckCode::G75, (52_000, -10_000), &Words { end: (40_000, -20_000), ..w }, 10_000, 2).unwrap();
    for (c, at) in [(g74, (20_000, 1_000)), (g75, (52_000, -10_000))] {
        crate::tests::assert_cycle_fill(&c, at, Cycle::next_event, Cycle::fill, &sizes);
    }
}

/// The bulk path (`batch::Bulk`, what `fill` writes in place): in a column, before its last peck,
/// `in_bulk` holds and `write_bulk` writes each peck with its return while two events fit; at the
/// last peck it no longer holds. The seed's example 4: pecks to Z−3, −8, −12.
#[test]
fn bulk_writes_the_pecks_before_the_last() {
    use crate::batch::Bulk;
    use crate::g74::{cycle, PeckCode, Words};
    use cycle_vocab::Event;
    let w = Words { end: (0, -12_000), di: 0, dk: 5_000, relief: 0, e: 1_000, feed: 300_000, relief_minus_z: false };
    let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
    let (f, e, p) = (300_000, Rule::G74E, Rule::G74Peck);
    // Room for three events: one peck and its return.
    let mut c = cycle(PeckCode::G74, (0, 2_000), &w, 10_000, 2).unwrap();
    let mut pos = (0, 2_000);
    assert!(!c.in_bulk());
    assert!(matches!(c.next_event(&mut pos), Some(Event::Pass(_))));
    assert!(c.in_bulk());
    let mut out = [filler; 3];
    assert_eq!(c.write_bulk(&mut pos, &mut out), 2);
    assert_eq!(out[..2], [Event::Move(Move::feed(0, -3_000, f, p)), Event::Move(Move::rapid(0, -2_000, e))]);
    // Room for all: the second peck and return; the last peck is not bulk.
    let mut out = [filler; 8];
    assert!(c.in_bulk());
    assert_eq!(c.write_bulk(&mut pos, &mut out), 2);
    assert_eq!(out[..2], [Event::Move(Move::feed(0, -8_000, f, p)), Event::Move(Move::rapid(0, -7_000, e))]);
    assert!(!c.in_bulk());
    assert_eq!(c.next_event(&mut pos), Some(Event::Move(Move::feed(0, -12_000, f, p))));
}

/// `Cycle::after_column(j)` (the proof harnesses' state constructor) is the state the running
/// cycle is in right after column j's way back to A.p: G74 with columns and reliefs, G75, and a
/// single column.
#[test]
fn after_column_is_the_state_after_a_column() {
    use super::Phase;
    use crate::g74::{cycle, PeckCode, Words};
    let w = Words { end: (40_000, -5_000), di: 3_000, dk: 2_000, relief: 200, e: 500, feed: 500, relief_minus_z: false };
    let cases = [
        (cycle(PeckCode::G74, (20_000, 1_000), &w, 10_000, 2).unwrap(), (20_000, 1_000)),
        (cycle(PeckCode::G75, (52_000, -10_000), &Words { end: (40_000, -20_000), ..w }, 10_000, 2).unwrap(), (52_000, -10_000)),
        (cycle(PeckCode::G74, (40_000, 1_000), &w, 10_000, 2).unwrap(), (40_000, 1_000)),
    ];
    for (c0, start) in cases {
        let (mut c, mut pos, mut seen) = (c0, start, 0);
        while c.next_event(&mut pos).is_some() {
            if matches!(c.phase, Phase::Header | Phase::Home) && c.col >= 1 && c.peck_i == 1 {
                assert_eq!(c, c0.after_column(c.col - 1));
                seen += 1;
            }
        }
        assert_eq!(seen, c0.columns, "every column's end seen");
    }
}
