//! G83, G84, G80 (M003) on the seed's two lines and the feature programs' blocks; every number
//! is worked out by hand from docs/INTERPRETATION.md, "G83 and G84", not taken from the spec's
//! output.

use crate::tests::util::*;
use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{AlarmCode, Config, Dialect, Event, MoveKind, PassKind, Rule, SpindleState};


/// Every event, compactly: moves as (kind, z, feed), dwells as ms, spindle states, passes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum E {
    Pass(u32, PassKind, i64),
    Move(MoveKind, i64, i64),
    Dwell(u32),
    Spindle(SpindleState),
}

/// The events of the trace after its first `skip` events, all at X0 (asserted).
fn events(t: &Trace, skip: usize) -> Vec<E> {
    t.events
        .iter()
        .skip(skip)
        .map(|e| match e {
            Event::Pass(p) => E::Pass(p.index, p.kind, p.diameter_depth),
            Event::Move(m) => {
                assert_eq!(m.x, 0);
                E::Move(m.kind, m.z, m.feed)
            }
            Event::Dwell(d) => E::Dwell(d.ms),
            Event::Spindle(s) => E::Spindle(s.state),
            Event::Press(_) | Event::Stop(_) | Event::Resume(_) => panic!("no operator event without a script"),
        })
        .collect()
}




use MoveKind::{Feed, Rapid, Thread};

/// G83.FORMAT (`G83Z-30R0.5Q2000F0.2` from Z0): R level Z0.5, pecks of 2 mm to −1.5, −3.5, …,
/// −29.5 and the last to −30 (16 pecks); a rapid back to the R level after each but the last,
/// and a rapid down to the depth reached before the next; then the rapid to Z0. No dwell.
#[test]
fn seed_g83_line() {
    let t = run("G50 X60 Z40\nG00 X0 Z0 S800\nG83Z-30R0.5Q2000F0.2\n");
    let f = 2_000;
    let mut expect = vec![E::Pass(1, PassKind::Rough, 61_000), E::Move(Rapid, 500, 0)];
    let depths: Vec<i64> = (1..=15).map(|k| 500 - 2_000 * k).chain([-30_000]).collect();
    for (k, &z) in depths.iter().enumerate() {
        if k > 0 {
            expect.push(E::Move(Rapid, depths[k - 1], 0));
        }
        expect.push(E::Move(Feed, z, f));
        if z != -30_000 {
            expect.push(E::Move(Rapid, 500, 0));
        }
    }
    expect.push(E::Move(Rapid, 0, 0));
    assert_eq!(events(&t, 1), expect);
    assert!(t.moves().skip(1).all(|m| m.rule == Rule::G83Peck));
}

/// G83.PECK edges (`g83_edges.nc`): no Q: one feed and the dwell P500; Q larger than the depth:
/// one peck; R omitted: pecks from the initial level, the last of one increment.
#[test]
fn g83_edges() {
    let t = run("G00 X0 Z3\nG83 Z-10 R-1 P500 F0.1\nG83 Z-4 R-1 Q9000 F0.1\n");
    let f = 1_000;
    let expect = vec![
        E::Pass(1, PassKind::Rough, 24_000),
        E::Move(Rapid, 2_000, 0),
        E::Move(Feed, -10_000, f),
        E::Dwell(500),
        E::Move(Rapid, 3_000, 0),
        E::Pass(1, PassKind::Rough, 12_000),
        E::Move(Rapid, 2_000, 0),
        E::Move(Feed, -4_000, f),
        E::Move(Rapid, 3_000, 0),
    ];
    assert_eq!(events(&t, 1), expect);
    let t = run("G00 X0 Z3\nG83 Z-5.001 Q1000 F0.1\n");
    let ev = events(&t, 1);
    assert_eq!(ev[0], E::Pass(1, PassKind::Rough, 16_002));
    assert_eq!(ev[1], E::Move(Feed, 2_000, f)); // the R level is the initial level: no rapid
    assert_eq!(ev[ev.len() - 3..], [E::Move(Rapid, -5_000, 0), E::Move(Feed, -5_001, f), E::Move(Rapid, 3_000, 0)]);
    assert_eq!(ev.iter().filter(|e| matches!(e, E::Move(Feed, ..))).count(), 9);
}

/// G84.PATH under G98 (the seed's line, `g84_example.nc`): lead F / S = 60 / 60 = 1 mm (10 000
/// lead counts); R level Z2, tapping to Z−21 and back, the spindle reversed between, then Z0.
/// F60 stays the modal feed; the rigid-tapping mode ends after the cycle.
#[test]
fn seed_g84_line_g98() {
    let t = run("G50 X60 Z40\nG00 X0 Z0\nG98M29S60\nG84Z-21R2F60\nG80\nG1 Z1\n");
    let expect = vec![
        E::Pass(1, PassKind::Rough, 46_000),
        E::Move(Rapid, 2_000, 0),
        E::Move(Thread, -21_000, 10_000),
        E::Spindle(SpindleState::Reverse),
        E::Move(Thread, 2_000, 10_000),
        E::Spindle(SpindleState::Forward),
        E::Move(Rapid, 0, 0),
        E::Move(Feed, 1_000, 600_000),
    ];
    assert_eq!(events(&t, 1), expect);
    assert!(t.events.iter().skip(1).take(7).all(|e| e.rule() == Rule::G84Path));
    // The seed's line as one block: the G80 written with M29 ends only an earlier M29 (`Rule::G80`).
    let one = run("G50 X60 Z40\nG00 X0 Z0\nG98M29S60G84Z-21R2F60G80\n");
    assert_eq!(one.events, t.events[..8]);
    // Rounded once, half away from zero: F0.0003 / S2 = 1.5 lead counts → 2.
    let t = run("G98 M29 S2\nG84 Z-1 F0.0003\n");
    assert_eq!(t.moves().next().map(|m| (m.kind, m.feed)), Some((Thread, 2)));
}

/// G84 under G99 (`g84_g99.nc`): the lead is F; the dwell P200 at the bottom; M29 in the same
/// block; an R level below the initial level.
#[test]
fn g84_g99_lead_is_f() {
    let t = run("G00 X0 Z5\nG99 M29 S500 G84 Z-15 R-3 P200 F1.25\nG80\n");
    let expect = vec![
        E::Pass(1, PassKind::Rough, 34_000),
        E::Move(Rapid, 2_000, 0),
        E::Move(Thread, -15_000, 12_500),
        E::Dwell(200),
        E::Spindle(SpindleState::Reverse),
        E::Move(Thread, 2_000, 12_500),
        E::Spindle(SpindleState::Forward),
        E::Move(Rapid, 5_000, 0),
    ];
    assert_eq!(events(&t, 1), expect);
}

/// Every alarm of the register's G83 / G84 checks, with its word, rule and line.
#[test]
fn g83_g84_alarms() {
    use AlarmCode::*;
    let a = "G0 X0 Z0\n";
    let cases: &[(&str, Expect)] = &[
        ("G83 Z-5 Q1000", (MissingWord, Some('F'), Rule::ComLead, 2)),
        ("G83 Z-5 R-5 F1", (Geometry, Some('Z'), Rule::G83Format, 2)),
        ("G83 F1", (Geometry, Some('Z'), Rule::G83Format, 2)),
        ("G83 X1 Z-5 F1", (WordNotAllowed, Some('X'), Rule::PrjWord, 2)),
        ("G83 Z-5 K1 F1", (WordNotAllowed, Some('K'), Rule::PrjWord, 2)),
        ("G83 Z-5 Q1. F1", (NotInteger, Some('Q'), Rule::ComRanges, 2)),
        ("G83 Z-5 Q-1 F1", (OutOfRange, Some('Q'), Rule::ComRanges, 2)),
        ("G83 Z-5 P1.5 F1", (NotInteger, Some('P'), Rule::ComRanges, 2)),
        ("G83 Z-5 P100000000 F1", (OutOfRange, Some('P'), Rule::ComRanges, 2)),
        ("G83 Z-5 R1000000 F1", (OutOfRange, Some('R'), Rule::ComRanges, 2)),
        ("G83 Z-50 Q4 F1", (TooManyPasses, Some('Q'), Rule::PrjMaxPass, 2)),
        ("M29 G84 Z-5", (MissingWord, Some('F'), Rule::ComLead, 2)),
        ("G84 Z-5 F1", (Unsupported, Some('G'), Rule::G84Format, 2)),
        ("M29\nG80\nG84 Z-5 F1", (Unsupported, Some('G'), Rule::G84Format, 4)),
        ("M29 G84 Z-5 F1\nG84 Z-5 F1", (Unsupported, Some('G'), Rule::G84Format, 3)),
        ("M29 G84 Z-5 Q1 F1", (WordNotAllowed, Some('Q'), Rule::PrjWord, 2)),
        ("M29 G84 U1 Z-5 F1", (WordNotAllowed, Some('U'), Rule::PrjWord, 2)),
        ("G98 M29 G84 Z-5 F1", (MissingWord, Some('S'), Rule::G84Format, 2)),
        ("G98 M29 S60. G84 Z-5 F1", (NotInteger, Some('S'), Rule::ComRanges, 2)),
        ("G98 M29 S0 G84 Z-5 F1", (OutOfRange, Some('S'), Rule::G84Format, 2)),
        ("S100000\nG98 M29 G84 Z-5 F1", (OutOfRange, Some('S'), Rule::G84Format, 3)),
        ("G98 M29 S3 G84 Z-5 F0.0001", (OutOfRange, Some('F'), Rule::G84Format, 2)),
        ("M29 G84 R2 Z2 F1", (Geometry, Some('Z'), Rule::G84Format, 2)),
    ];
    for (block, expect) in cases {
        assert_eq!(alarm_of(&format!("{a}{block}\n")), *expect, "{block}");
    }
    // The pass bound stops the cycle before any motion (12 501 pecks of 4 µm > 10 000).
    assert_eq!(expand(b"G0 X1 Z0\nG83 Z-50 Q4 F1\n", &Config::default()).events.len(), 1);
    // G99 after G98 makes the lead F again (no S needed).
    run("G98\nG99 M29 G84 Z-5 F1\n");
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    for code in ["G83 Z-1 F1", "G84 Z-1 F1", "G80"] {
        assert_eq!(alarm_with(&format!("{code}\n"), &nc201), (UnsupportedCode, Some('G'), Rule::PrjDialect, 1), "{code}");
    }
    // G80 is a no-motion code accepted in any block (here with a move), not a motion code.
    let t = run("G80 G0 X5\nG80\n");
    assert_eq!(t.moves().count(), 1);
}

/// The pass bound at its edge (docs/INTERPRETATION.md, "G83 and G84": "Pecks > `max_passes`:
/// `TOO MANY PASSES` on Q", PRJ.MAXPASS), the pecks counted by hand: from the R level Z0, Q1000
/// (µm, as the seed's `Q2000`, 003_b2c47ef6d53aacbe.txt:5) to Z-5 is 5 pecks exactly, to Z-5.001
/// six (the last 1 µm). A count equal to `max_passes` is legal, one more is the alarm.
#[test]
fn g83_pass_bound_at_its_edge() {
    let with = |n: i64| Config { params: cycle_vocab::Params { max_passes: Some(n), ..Default::default() }, ..Config::default() };
    for (z, pecks) in [("-5", 5), ("-5.001", 6)] {
        let src = format!("G0 X0 Z0\nG83 Z{z} Q1000 F1\n");
        let t = run_with(&src, &with(pecks));
        let feeds = t.moves().filter(|m| m.kind == MoveKind::Feed).count();
        assert_eq!(feeds, pecks as usize, "{src}");
        assert_eq!(alarm_with(&src, &with(pecks - 1)), (AlarmCode::TooManyPasses, Some('Q'), Rule::PrjMaxPass, 2), "{src}");
    }
}

/// The feature files whose header comments lex (no nested parentheses) expand exactly as the
/// blocks the tests above check by hand.
#[test]
fn lexable_feature_files_are_the_blocks_checked_above() {
    let cases: &[(&str, &str)] = &[
        (include_str!("../../../corpus/g84_example.nc"), "G50 X60 Z40\nG00 X0 Z0\nG98M29S60\nG84Z-21R2F60\nG80\nG00 X60 Z40\n"),
        (
            include_str!("../../../tests/programs/g83_edges.nc"),
            "G00 X0 Z3\nG83 Z-10 R-1 P500 F0.1\nG83 Z-4 R-1 Q9000 F0.1\nG83 Z-5.001 Q1000 F0.1\nG00 X50 Z50\n",
        ),
        (include_str!("../../../tests/programs/g74_one_peck.nc"), "G00 X0 Z2\nG74 R1\nG74 Z-3 Q10 F0.1\nG00 X50 Z50\n"),
        (
            include_str!("../../../tests/programs/g73_d1.nc"),
            "G00 X40 Z5\nG73 U6 W2 R1\nG73 P10 Q40 U0.4 W0.1 F0.2\nN10 G00 X10 Z1\nN20 G01 Z-10\nN30 G02 X20 Z-15 R5\nN40 G01 X30 Z-25\nG00 X60 Z50\n",
        ),
    ];
    for (file, blocks) in cases {
        let (a, b) = (run(file), run(blocks));
        assert_eq!(a.events, b.events, "{blocks}");
    }
}
