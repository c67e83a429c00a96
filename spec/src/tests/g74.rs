//! G74, G75 (M003) on the seed's examples 4 and 5 and the feature programs' blocks; every number
//! is worked out by hand from docs/INTERPRETATION.md, "G74 … and G75", not taken from the
//! spec's output.

use crate::tests::util::*;
use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::readings::G75Relief;
use cycle_vocab::{AlarmCode, Config, Dialect, MoveKind, PassKind, Readings, Rule};



type M = (MoveKind, i64, i64);

fn moves(t: &Trace) -> Vec<M> {
    t.moves().map(|m| (m.kind, m.x, m.z)).collect()
}





use MoveKind::{Feed, Rapid};

/// G74.EXAMPLE (example 4): from X0 Z2, e = 1, Z−12, Δk = 5 — "feed to Z−3, rapid to Z−2, feed
/// to Z−8, rapid to Z−7, feed to Z−12 …, then the rapid back to Z2"; one column, depth 2·14.
#[test]
fn example4_pecks() {
    let t = run(include_str!("../../../corpus/g74_example.nc"));
    let expect = vec![
        (Rapid, 0, 2_000),
        (Feed, 0, -3_000),
        (Rapid, 0, -2_000),
        (Feed, 0, -8_000),
        (Rapid, 0, -7_000),
        (Feed, 0, -12_000),
        (Rapid, 0, 2_000),
        (Rapid, 60_000, 40_000),
    ];
    assert_eq!(moves(&t), expect);
    assert_eq!(passes(&t), vec![(1, PassKind::Rough, 28_000, Rule::G74Column)]);
    let rules: Vec<Rule> = t.moves().map(|m| m.rule).collect();
    assert_eq!(rules[1..7], [Rule::G74Peck, Rule::G74E, Rule::G74Peck, Rule::G74E, Rule::G74Peck, Rule::G74Column]);
    // F30 is 30 mm in lead counts of 0.0001 mm; it stays the modal feed (one-shot cycle).
    assert!(t.moves().filter(|m| m.kind == Feed).all(|m| m.feed == 300_000));
}

/// The blocks of example 5 (`corpus/g75_example.nc` without its header comments, whose nested
/// parentheses the lexer does not read: see the report).
const EXAMPLE5: &str = "G50 X60 Z70\nG00 X42 Z22 S400\nG75 R1\nG75 X30 Z10 P3 Q2.9 F30\nG00 X60 Z70\n";

/// G75.EXAMPLE (example 5): "six grooves at Z22, 19.1, 16.2, 13.3, 10.4, 10; in each, pecks to
/// X36 (then a rapid to X38) and X30; no relief".
#[test]
fn example5_grooves() {
    let t = run(EXAMPLE5);
    let mut expect = vec![(Rapid, 42_000, 22_000)];
    let zs = [22_000, 19_100, 16_200, 13_300, 10_400, 10_000];
    for (j, &z) in zs.iter().enumerate() {
        if j > 0 {
            expect.push((Rapid, 42_000, z));
        }
        expect.extend([(Feed, 36_000, z), (Rapid, 38_000, z), (Feed, 30_000, z), (Rapid, 42_000, z)]);
    }
    expect.extend([(Rapid, 42_000, 22_000), (Rapid, 60_000, 70_000)]);
    assert_eq!(moves(&t), expect);
    let p = passes(&t);
    assert_eq!(p.len(), 6);
    assert!(p.iter().enumerate().all(|(j, h)| *h == (j as u32 + 1, PassKind::Rough, 12_000, Rule::G75Column)));
}

/// G74.COLUMN, G74.RELIEF (`g74_columns.nc`): columns X20, 26, 32, 38, 40; pecks −1, −3, −5 with
/// returns by 0.5; a relief of 2·0.2 in −X (against the +X step) in every column but the first.
#[test]
fn g74_columns_and_relief() {
    let t = run("G00 X20 Z1\nG74 R0.5\nG74 X40 Z-5 P3 Q2 R0.2 F0.05\n");
    let pecks = |x: i64| vec![(Feed, x, -1_000), (Rapid, x, -500), (Feed, x, -3_000), (Rapid, x, -2_500), (Feed, x, -5_000)];
    let mut expect = vec![(Rapid, 20_000, 1_000)];
    expect.extend(pecks(20_000));
    expect.push((Rapid, 20_000, 1_000));
    for x in [26_000, 32_000, 38_000, 40_000] {
        expect.push((Rapid, x, 1_000));
        expect.extend(pecks(x));
        expect.extend([(Rapid, x - 400, -5_000), (Rapid, x - 400, 1_000)]);
    }
    expect.push((Rapid, 20_000, 1_000));
    assert_eq!(moves(&t), expect);
    assert_eq!(passes(&t).len(), 5);
    assert_eq!(t.moves().filter(|m| m.rule == Rule::G74Relief).count(), 4);
}

/// G74.PECK edges (`g74_one_peck.nc`, `g74_last_increment.nc`).
#[test]
fn g74_peck_edges() {
    let t = run("G00 X0 Z2\nG74 R1\nG74 Z-3 Q10 F0.1\n");
    assert_eq!(moves(&t), vec![(Rapid, 0, 2_000), (Feed, 0, -3_000), (Rapid, 0, 2_000)]);
    let t = run("G00 X0 Z2\nG74 R0.5\nG74 Z-8.001 Q5 F0.1\n");
    let expect =
        vec![(Rapid, 0, 2_000), (Feed, 0, -3_000), (Rapid, 0, -2_500), (Feed, 0, -8_000), (Rapid, 0, -7_500), (Feed, 0, -8_001), (Rapid, 0, 2_000)];
    assert_eq!(moves(&t), expect);
}

/// G75.RELIEF (`g75_relief.nc`): grooves Z−10, −13, −16, −19, −20 (step −Z), a relief of 0.3 in
/// Z in every groove but the first — under the letter (`minus-z`, the default) toward −Z, here
/// with the step; under `against-step` toward +Z. Pecks of 2·2 with returns of 2·0.5.
#[test]
fn g75_relief_by_reading() {
    let src = "G00 X52 Z-10\nG75 R0.5\nG75 X40 Z-20 P2 Q3 R0.3 F0.05\n";
    let expect = |relief: i64| {
        let pecks = |z: i64| vec![(Feed, 48_000, z), (Rapid, 49_000, z), (Feed, 44_000, z), (Rapid, 45_000, z), (Feed, 40_000, z)];
        let mut expect = vec![(Rapid, 52_000, -10_000)];
        expect.extend(pecks(-10_000));
        expect.push((Rapid, 52_000, -10_000));
        for z in [-13_000, -16_000, -19_000, -20_000] {
            expect.push((Rapid, 52_000, z));
            expect.extend(pecks(z));
            expect.extend([(Rapid, 40_000, z + relief), (Rapid, 52_000, z + relief)]);
        }
        expect.push((Rapid, 52_000, -10_000));
        expect
    };
    let with = |r: G75Relief| Config { readings: Readings { g75_relief: r, ..Readings::default() }, ..Config::default() };
    assert_eq!(moves(&run(src)), expect(-300));
    assert_eq!(moves(&run_with(src, &with(G75Relief::MinusZ))), expect(-300));
    assert_eq!(moves(&run_with(src, &with(G75Relief::AgainstStep))), expect(300));
    // Grooves stepping toward +Z: the letter still relieves toward −Z, against the step too.
    let up = "G00 X52 Z-20\nG75 X40 Z-17 P6 Q3 R0.3 F0.05\n";
    let reliefs = |c: &Config| -> Vec<i64> { run_with(up, c).moves().filter(|m| m.rule == Rule::G75Relief).map(|m| m.z).collect() };
    assert_eq!(reliefs(&Config::default()), vec![-17_300]);
    assert_eq!(reliefs(&with(G75Relief::AgainstStep)), vec![-17_300]);
    // G74 is not affected by the reading: against its step in X.
    let g74 = "G00 X0 Z2\nG74 X10 Z-5 P3 Q5 R0.5 F0.1\n";
    assert_eq!(run_with(g74, &with(G75Relief::AgainstStep)), run(g74));
}

/// G75.FORMAT: one groove without Z, Q, R (`g75_single_groove.nc`).
#[test]
fn g75_single_groove() {
    let t = run("G00 X42 Z-10\nG75 R1\nG75 X30 P2.5 F0.05\n");
    let z = -10_000;
    let expect =
        vec![(Rapid, 42_000, z), (Feed, 37_000, z), (Rapid, 39_000, z), (Feed, 32_000, z), (Rapid, 34_000, z), (Feed, 30_000, z), (Rapid, 42_000, z)];
    assert_eq!(moves(&t), expect);
}

/// The kept e: per code, until another first block; without one, 5139 (default 0); a first block
/// without R falls back to 5139. One-shot: the motion mode before (G01) stays.
#[test]
fn kept_return_per_code_and_parameter() {
    let no_return = run("G0 X0 Z2\nG74 Z-8 Q5 F0.1\n");
    // e = 0: the return to the peck's own end is no move (PRJ.NOOP).
    assert_eq!(moves(&no_return), vec![(Rapid, 0, 2_000), (Feed, 0, -3_000), (Feed, 0, -8_000), (Rapid, 0, 2_000)]);
    let mut config = Config::default();
    config.params.p5139_peck_return = Some(250);
    let t = run_with("G0 X0 Z2\nG74 Z-8 Q5 F0.1\n", &config);
    assert_eq!(moves(&t)[2], (Rapid, 0, -2_750));
    // G75's R1 does not change G74's e; G74 alone (no R) falls back to 5139.
    let t = run("G0 X0 Z2\nG74 R1\nG75 R2\nG74 Z-8 Q5 F0.1\n");
    assert_eq!(moves(&t)[2], (Rapid, 0, -2_000));
    let t = run_with("G0 X0 Z2\nG74 R1\nG74\nG74 Z-8 Q5 F0.1\n", &config);
    assert_eq!(moves(&t)[2], (Rapid, 0, -2_750));
    let t = run("G1 X0 Z2 F1\nG74 Z-8 Q5 F0.1\nX5\n");
    assert_eq!(t.moves().last().map(|m| (m.kind, m.x, m.z, m.feed)), Some((Feed, 5_000, 2_000, 1_000)));
}

/// G74.FORMAT: "A block with any of X U Z W P Q is the second block (R = Δd there), otherwise
/// the first" — P alone, or Q alone, already makes it the second block: the cycle's checks run
/// (no travel along the peck axis: `GEOMETRY`), not the first block's word list (R only).
#[test]
fn p_or_q_alone_is_the_second_block() {
    for (block, letter, rule) in [
        ("G74 P1 F1", 'Z', Rule::G74Format),
        ("G74 Q1 F1", 'Z', Rule::G74Format),
        ("G75 P1 F1", 'X', Rule::G75Format),
        ("G75 Q1 F1", 'X', Rule::G75Format),
    ] {
        assert_eq!(alarm_of(&format!("G0 X20 Z2\n{block}\n")), (AlarmCode::Geometry, Some(letter), rule, 2), "{block}");
    }
}

/// PRJ.MAXPASS at its edge, counted by hand: from X20 Z1, `G74 X32 Z-5 P3 Q2` steps 2Δi = 6 on
/// the diameter — columns at X20, X26, X32 (the X travel 12 an exact multiple: "one at A and one
/// per step, the last exactly at E") — and pecks Q2 over the Z travel 6: 3 per column, 9 in all.
/// "The pecks of all columns together > `max_passes`" is the alarm: 9 runs, 8 does not.
#[test]
fn pass_bound_with_whole_steps() {
    let src = "G0 X20 Z1\nG74 X32 Z-5 P3 Q2 F1\n";
    let with = |n: i64| Config { params: cycle_vocab::Params { max_passes: Some(n), ..Default::default() }, ..Config::default() };
    let t = run_with(src, &with(9));
    assert_eq!(passes(&t).len(), 3);
    assert_eq!(t.moves().filter(|m| m.kind == MoveKind::Feed).count(), 9);
    assert_eq!(alarm_with(src, &with(8)), (AlarmCode::TooManyPasses, Some('Q'), Rule::PrjMaxPass, 2));
}

/// Every alarm of the register's checks for G74 and G75, in order, with its word, rule, line.
#[test]
fn g74_g75_alarms() {
    use AlarmCode::*;
    let a = "G0 X20 Z2\n";
    let cases: &[(&str, Expect)] = &[
        ("G74 Z-5 Q1", (MissingWord, Some('F'), Rule::ComLead, 2)),
        ("G74 X30 Q1 F1", (Geometry, Some('Z'), Rule::G74Format, 2)),
        ("G74 Z-5 F1", (MissingWord, Some('Q'), Rule::G74Peck, 2)),
        ("G74 Z-5 Q0 F1", (MissingWord, Some('Q'), Rule::G74Peck, 2)),
        ("G74 X30 Z-5 Q1 F1", (MissingWord, Some('P'), Rule::G74Column, 2)),
        ("G75 Z-5 P1 F1", (Geometry, Some('X'), Rule::G75Format, 2)),
        ("G75 X10 F1", (MissingWord, Some('P'), Rule::G75Peck, 2)),
        ("G75 X10 Z-5 P1 F1", (MissingWord, Some('Q'), Rule::G75Column, 2)),
        ("G74 Z-5 Q-1 F1", (OutOfRange, Some('Q'), Rule::ComRanges, 2)),
        ("G74 X30 Z-5 P-1 Q1 F1", (OutOfRange, Some('P'), Rule::ComRanges, 2)),
        ("G74 Z-5 Q1 R-1 F1", (OutOfRange, Some('R'), Rule::ComRanges, 2)),
        ("G74 R-1", (OutOfRange, Some('R'), Rule::ComRanges, 2)),
        ("G75 R1 F1", (WordNotAllowed, Some('F'), Rule::PrjWord, 2)),
        ("G74 Z-5 Q1 I1 F1", (WordNotAllowed, Some('I'), Rule::PrjWord, 2)),
        ("G74 G0 Z-5 Q1 F1", (Conflict, Some('G'), Rule::PrjWord, 2)),
    ];
    for (block, expect) in cases {
        assert_eq!(alarm_of(&format!("{a}{block}\n")), *expect, "{block}");
    }
    // PRJ.MAXPASS: 5 columns × 3 pecks = 15 > 14 on Q (G74) / P (G75), before any motion.
    let mut config = Config::default();
    config.params.max_passes = Some(14);
    let t = expand(b"G0 X20 Z1\nG74 X40 Z-5 P3 Q2 F1\n", &config);
    assert_eq!(t.alarm.map(|a| (a.code, a.word, a.rule, a.line)), Some((TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, 2)));
    assert_eq!(t.events.len(), 1);
    config.params.max_passes = Some(15);
    run_with("G0 X20 Z1\nG74 X40 Z-5 P3 Q2 F1\n", &config);
    config.params.max_passes = Some(5);
    let t = alarm_with("G0 X52 Z-10\nG75 X40 Z-20 P2 Q3 F1\n", &config);
    assert_eq!(t, (TooManyPasses, Some('P'), Rule::PrjMaxPass, 2));
    // A count far beyond max_passes is refused by arithmetic, not by running it.
    let t = alarm_of("G0 X0 Z0\nG74 X1999 Z-999999 P0.001 Q0.001 F1\n");
    assert_eq!(t, (TooManyPasses, Some('Q'), Rule::PrjMaxPass, 2));
    // Under nc201 the codes are unsupported.
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(alarm_with("G74 R1\n", &nc201), (UnsupportedCode, Some('G'), Rule::PrjDialect, 1));
    assert_eq!(alarm_with("G75 R1\n", &nc201), (UnsupportedCode, Some('G'), Rule::PrjDialect, 1));
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    run_with("G0 X0 Z2\nG74 Z-3 Q5 F1\n", &fanuc);
}
