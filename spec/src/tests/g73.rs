//! G73 (M003) on the seed's example 3 and the feature programs' blocks; every number is worked
//! out by hand from docs/INTERPRETATION.md, "G73 (pattern repeating)", not taken from the
//! spec's output.

use crate::tests::util::*;
use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::readings::G73C;
use cycle_vocab::{AlarmCode, Config, Dialect, MoveKind, PassKind, Readings, Rule};



/// A move with its arc centre (0, 0 for lines).
type M = (MoveKind, i64, i64, i64, i64);

fn moves(t: &Trace) -> Vec<M> {
    t.moves().map(|m| (m.kind, m.x, m.z, m.cx, m.cz)).collect()
}





use MoveKind::{ArcCcw, ArcCw, Feed, Rapid};

/// Example 3's blocks (`corpus/g73_example.nc` without its header comments, whose nested
/// parentheses the lexer does not read: see the report).
const EXAMPLE3: &str = "N010 G50 X100 Z100\nN020 G00 X50 Z10\nN030 G73 U18 W5 R10\nN040 G73 P50 Q100 U0.5 W0.5 F100\n\
N050 G01 X0 Z1\nN060 G03 X12 W-6 R6\nN070 G01 W-10\nN080 X20 W-15\nN090 W-13\nN100 G02 X34 W-7 R7\nN110 G70 P50 Q100 F30\n";

/// Example 3's contour translated by (tx, tz) as the cycle runs it, from the rapid to A + T:
/// the ball end R6 about X0 Z−5, the taper, the fillet R7 about X34 Z−43 (centres of the
/// programmed contour: R6 from X0 Z1 to X12 Z−5 is a quarter about X0 Z−5; R7 from X20 Z−43
/// to X34 Z−50 a quarter about X34 Z−43 — both exact).
fn pass3(tx: i64, tz: i64, f: MoveKind) -> Vec<M> {
    vec![
        (Rapid, 50_000 + tx, 10_000 + tz, 0, 0),
        (f, tx, 1_000 + tz, 0, 0),
        (ArcCcw, 12_000 + tx, -5_000 + tz, tx, -5_000 + tz),
        (Feed, 12_000 + tx, -15_000 + tz, 0, 0),
        (Feed, 20_000 + tx, -30_000 + tz, 0, 0),
        (Feed, 20_000 + tx, -43_000 + tz, 0, 0),
        (ArcCw, 34_000 + tx, -50_000 + tz, 34_000 + tx, -43_000 + tz),
    ]
}

/// `g73.c=skip`: no retreat to C.
fn skip_c() -> Config {
    Config { readings: Readings { g73_c: G73C::Skip, ..Readings::default() }, ..Config::default() }
}

/// The moves of `src` under the letter (`g73.c=visit`, the default) are those under `skip` with
/// the rapid to `c` inserted after the move at `at` (the last move before the cycle).
fn visits_c(src: &str, at: usize, c: (i64, i64)) -> Vec<M> {
    let mut skip = moves(&run_with(src, &skip_c()));
    skip.insert(at + 1, (Rapid, c.0, c.1, 0, 0));
    let visit = moves(&run(src));
    assert_eq!(visit, skip, "{src}");
    assert_eq!(moves(&run_with(src, &Config { readings: Readings { g73_c: G73C::Visit, ..Readings::default() }, ..Config::default() })), visit);
    visit
}

/// G73 point C: the seed's C, X86.5 Z15.5 (A X50 Z10 + (2·18 + 0.5, 5 + 0.5)), one rapid before
/// pass 1's header under the letter, tagged G73.PATH; none under `skip`; none when C = A.
#[test]
fn example3_point_c() {
    let t = run(EXAMPLE3);
    let m: Vec<_> = t.moves().take(3).map(|m| (m.kind, m.x, m.z, m.rule)).collect();
    assert_eq!(m[1], (Rapid, 86_500, 15_500, Rule::G73Path));
    assert_eq!(m[2], (Rapid, 82_900, 15_000, Rule::G73Path)); // pass 1: A + (2·16.2 + 0.5, 4.5 + 0.5)
    // Header after the rapid to C: event 0 the G00 to A, 1 the rapid to C, 2 pass 1's header.
    assert!(matches!(t.events[2], cycle_vocab::Event::Pass(_)));
    visits_c(EXAMPLE3, 0, (86_500, 15_500));
    // C = A (no escapes, no allowances): no move.
    let src = "G0 X10 Z0\nG73 U0 W0 R2\nG73 P1 Q2 F1\nN1 G1 X5\nN2 Z-5\n";
    assert_eq!(run(src), run_with(src, &skip_c()));
    // Signs as written: Δi −2, Δu −0.4, Δk 1, Δw −0.3 → C = (10 − 4 − 0.4, 0 + 1 − 0.3).
    visits_c("G0 X10 Z0\nG73 U-2 W1 R2\nG73 P1 Q2 U-0.4 W-0.3 F1\nN1 G1 X5\nN2 Z-5\n", 0, (5_600, 700));
}

/// Under the letter the rapid to C X86.5 Z15.5 comes first; then G73.EXAMPLE: "ten passes, pass
/// n offset by (2·round(1.8·(10 − n)) + 0.5, round(0.5·(10 − n)) + 0.5) — the last one on the
/// contour plus U0.5 W0.5"; then one rapid to A; then G70.
#[test]
fn example3_ten_passes() {
    let t = run(EXAMPLE3);
    let mut expect = vec![(Rapid, 50_000, 10_000, 0, 0), (Rapid, 86_500, 15_500, 0, 0)];
    for n in 1..=10i64 {
        let (tx, tz) = (2 * 1_800 * (10 - n) + 500, 500 * (10 - n) + 500);
        expect.extend(pass3(tx, tz, Feed));
    }
    expect.push((Rapid, 50_000, 10_000, 0, 0));
    // The last pass (n = 10) is the contour plus (0.5, 0.5): its first point X0.5 Z1.5.
    assert_eq!(expect[expect.len() - 7].1..=expect[expect.len() - 7].2, 500..=1_500);
    // G70: from A straight to the contour (no rapid: its first move is the ns block's G01).
    let mut g70 = pass3(0, 0, Feed);
    g70.remove(0);
    expect.extend(g70);
    expect.push((Rapid, 50_000, 10_000, 0, 0));
    assert_eq!(moves(&t), expect);
    let p = passes(&t);
    let rough: Vec<_> = (1..=10u32).map(|n| (n, PassKind::Rough, 3_600 * (10 - i64::from(n)), Rule::G73Depth)).collect();
    assert_eq!(p[..10], rough[..]);
    assert_eq!(p[10], (1, PassKind::Finish, 50_000, Rule::G70Path));
    // The roughing runs at the cycle's F100; G70 at its own F30.
    assert!(t.moves().take(72).filter(|m| m.kind != Rapid).all(|m| m.feed == 1_000_000));
}

/// G73.COUNT edge (`g73_d1.nc`): d = 1 is one pass exactly at the allowances U0.4 W0.1.
#[test]
fn d1_is_one_pass_at_the_allowances() {
    let t = run("G00 X40 Z5\nG73 U6 W2 R1\nG73 P10 Q40 U0.4 W0.1 F0.2\nN10 G00 X10 Z1\nN20 G01 Z-10\nN30 G02 X20 Z-15 R5\nN40 G01 X30 Z-25\nG00 X60 Z50\n");
    let expect = vec![
        (Rapid, 40_000, 5_000, 0, 0),
        (Rapid, 52_400, 7_100, 0, 0), // C: A + (2·6 + 0.4, 2 + 0.1)
        (Rapid, 40_400, 5_100, 0, 0),
        (Rapid, 10_400, 1_100, 0, 0),
        (Feed, 10_400, -9_900, 0, 0),
        (ArcCw, 20_400, -14_900, 20_400, -9_900),
        (Feed, 30_400, -24_900, 0, 0),
        (Rapid, 40_000, 5_000, 0, 0),
        (Rapid, 60_000, 50_000, 0, 0),
    ];
    assert_eq!(moves(&t), expect);
    assert_eq!(passes(&t), vec![(1, PassKind::Rough, 0, Rule::G73Depth)]);
}

/// G73.FORMAT (`g73_both_formats.nc`): format a (U8 W2 R4: escapes 8·(4−n)/4 = 6, 4, 2, 0 and
/// 2·(4−n)/4 = 1.5, 1, 0.5, 0) then format b (I4.5 K1.5 D3: round(4.5·(3−n)/3) = 3, 1.5, 0 and
/// round(1.5·(3−n)/3) = 1, 0.5, 0 — exact), whose I K D leave the kept values alone.
#[test]
fn both_formats() {
    let contour = "N10 G00 X16 Z2\nN20 G01 Z-12\nN30 G03 X28 Z-18 I0 K-6\nN40 G01 X40 Z-30\n";
    let contour_b = contour.replace("N10", "N50").replace("N20", "N60").replace("N30", "N70").replace("N40", "N80");
    let src = format!("G00 X50 Z5\nG73 U8 W2 R4\nG73 P10 Q40 U0.5 W0.2 F0.25\n{contour}G73 P50 Q80 I4.5 K1.5 U0.3 W0.1 D3 F0.2\n{contour_b}G73 P10 Q40 F0.25\n{contour}");
    let t = run(&src);
    let pass = |tx: i64, tz: i64| {
        vec![
            (Rapid, 50_000 + tx, 5_000 + tz, 0, 0),
            (Rapid, 16_000 + tx, 2_000 + tz, 0, 0),
            (Feed, 16_000 + tx, -12_000 + tz, 0, 0),
            (ArcCcw, 28_000 + tx, -18_000 + tz, 16_000 + tx, -18_000 + tz),
            (Feed, 40_000 + tx, -30_000 + tz, 0, 0),
        ]
    };
    // Each cycle first retreats to its C: A + (2Δi + Δu, Δk + Δw).
    let mut expect = vec![(Rapid, 50_000, 5_000, 0, 0), (Rapid, 66_500, 7_200, 0, 0)];
    for (x, z) in [(12_000, 1_500), (8_000, 1_000), (4_000, 500), (0, 0)] {
        expect.extend(pass(x + 500, z + 200));
    }
    expect.push((Rapid, 50_000, 5_000, 0, 0));
    expect.push((Rapid, 59_300, 6_600, 0, 0));
    for (x, z) in [(6_000, 1_000), (3_000, 500), (0, 0)] {
        expect.extend(pass(x + 300, z + 100));
    }
    expect.push((Rapid, 50_000, 5_000, 0, 0));
    expect.push((Rapid, 66_000, 7_000, 0, 0));
    // Format a again, no U W: the kept U8 W2 R4, allowances 0.
    for (x, z) in [(12_000, 1_500), (8_000, 1_000), (4_000, 500), (0, 0)] {
        expect.extend(pass(x, z));
    }
    expect.push((Rapid, 50_000, 5_000, 0, 0));
    assert_eq!(moves(&t), expect);
    assert_eq!(passes(&t).len(), 11);
}

/// Kept values fall back to 5135, 5136, 5137; rounding half away from zero, once (Δi = 1
/// increment over d = 2: round(0.5) = 1 on the radius, 2 on the diameter). The program resumes
/// after N(nf) (CNT.FLOW) and the motion mode before the cycle stays (CYC.ONESHOT).
#[test]
fn parameters_rounding_and_flow() {
    let mut config = Config::default();
    config.params.p5135_escape_x = Some(1);
    config.params.p5136_escape_z = Some(-3);
    config.params.p5137_count = Some(2);
    let t = run_with("G1 X10 Z0 F1\nG73 P1 Q2 F0.5\nN1 G0 X5\nN2 G1 Z-5\nZ-1\n", &config);
    let expect = vec![
        (Feed, 10_000, 0, 0, 0),
        (Rapid, 10_002, -3, 0, 0), // C: A + (2·1, −3)
        (Rapid, 10_002, -2, 0, 0), // round(1/2) = 1 → 2 on X; round(−3/2) = −2
        (Rapid, 5_002, -2, 0, 0),
        (Feed, 5_002, -5_002, 0, 0),
        (Rapid, 10_000, 0, 0, 0),
        (Rapid, 5_000, 0, 0, 0),
        (Feed, 5_000, -5_000, 0, 0),
        (Rapid, 10_000, 0, 0, 0),
        (Feed, 10_000, -1_000, 0, 0), // G01 is still the mode, at the cycle's F0.5
    ];
    assert_eq!(moves(&t), expect);
    assert_eq!(t.moves().last().map(|m| m.feed), Some(5_000));
}

/// Every alarm of the register's G73 checks, with its word, rule and line.
#[test]
fn g73_alarms() {
    use AlarmCode::*;
    let c = "N1 G1 X5\nN2 Z-5\n";
    let a = "G0 X10 Z0\n";
    let cases: Vec<(String, Expect)> = vec![
        (format!("{a}G73 P1 Q2\n{c}"), (MissingWord, Some('F'), Rule::ComLead, 2)),
        (format!("{a}G73 Q2 F1\n{c}"), (MissingWord, Some('P'), Rule::CntPq, 2)),
        (format!("{a}G73 P1 F1\n{c}"), (MissingWord, Some('Q'), Rule::CntPq, 2)),
        (format!("{a}G73 P1 Q2 K1 D2 F1\n{c}"), (MissingWord, Some('I'), Rule::G73Format, 2)),
        (format!("{a}G73 P1 Q2 I1 D2 F1\n{c}"), (MissingWord, Some('K'), Rule::G73Format, 2)),
        (format!("{a}G73 P1 Q2 I1 K1 F1\n{c}"), (MissingWord, Some('D'), Rule::G73Format, 2)),
        (format!("{a}G73 P1 Q2 R3 F1\n{c}"), (WordNotAllowed, Some('R'), Rule::PrjWord, 2)),
        (format!("{a}G73 P1 Q2 I1 K1 D2 R3 F1\n{c}"), (WordNotAllowed, Some('R'), Rule::PrjWord, 2)),
        (format!("{a}G73 U1 W1 R2 F1\n"), (WordNotAllowed, Some('F'), Rule::PrjWord, 2)),
        (format!("{a}G73 R2.\n"), (NotInteger, Some('R'), Rule::ComRanges, 2)),
        (format!("{a}G73 R0\n"), (OutOfRange, Some('R'), Rule::G73Count, 2)),
        (format!("{a}G73 P1 Q2 I1 K1 D0 F1\n{c}"), (OutOfRange, Some('D'), Rule::G73Count, 2)),
        (format!("{a}G73 P1 Q2 I1 K1 D-1 F1\n{c}"), (OutOfRange, Some('D'), Rule::G73Count, 2)),
        (format!("{a}G73 U1000000\n"), (OutOfRange, Some('U'), Rule::ComRanges, 2)),
        (format!("{a}G73 P1 Q2 F1\nG0 X1\n{c}"), (BlockNotFound, Some('P'), Rule::CntFind, 2)),
        (format!("{a}G73 P1 Q3 F1\n{c}"), (BlockNotFound, Some('Q'), Rule::CntFind, 2)),
        (format!("{a}G73 P1 Q2 F1\nN1 X5\nN2 Z-5\n"), (MissingWord, Some('G'), Rule::CntFirst, 3)),
        (format!("{a}G73 P1 Q2 F1\nN1 G1 X5\nN2 Z-5 M8\n"), (WordNotAllowed, Some('M'), Rule::CntWords, 4)),
        (format!("{a}G73 R10001\nG73 P1 Q2 F1\n{c}"), (TooManyPasses, Some('R'), Rule::PrjMaxPass, 3)),
        (format!("{a}G73 P1 Q2 I1 K1 D10001 F1\n{c}"), (TooManyPasses, Some('D'), Rule::PrjMaxPass, 2)),
    ];
    for (src, expect) in &cases {
        assert_eq!(alarm_of(src), *expect, "{src}");
    }
    // The pass bound stops the cycle before any motion: only the first rapid stands.
    let t = expand(format!("{a}G73 R10001\nG73 P1 Q2 F1\n{c}").as_bytes(), &Config::default());
    assert_eq!(t.events.len(), 1);
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(alarm_with("G73 U1\n", &nc201), (UnsupportedCode, Some('G'), Rule::PrjDialect, 1));
}

/// G73.FORMAT: "a G73 block with P or Q and any of I, K, D is format (b)" — one of them alone
/// already is, and the missing ones are then named in the order I, K, D (docs/INTERPRETATION.md,
/// "G73 (pattern repeating)"), not refused as words format (a)'s second block does not allow.
#[test]
fn any_one_of_i_k_d_makes_format_b() {
    let c = "N1 G1 X5\nN2 Z-5\n";
    for (words, missing) in [("I1", 'K'), ("K1", 'I'), ("D2", 'I')] {
        let src = format!("G0 X10 Z0\nG73 P1 Q2 {words} F1\n{c}");
        assert_eq!(alarm_of(&src), (AlarmCode::MissingWord, Some(missing), Rule::G73Format, 2), "{words}");
    }
}

/// PRJ.MAXPASS at its edge: "d greater than `max_passes` is `TOO MANY PASSES` on that word" —
/// d equal to `max_passes` runs (d passes), one more is the alarm, R in format (a), D in (b).
#[test]
fn pass_bound_at_its_edge() {
    let c = "N1 G1 X5\nN2 Z-5\n";
    let with = |n: i64| Config { params: cycle_vocab::Params { max_passes: Some(n), ..Default::default() }, ..Config::default() };
    for (blocks, word, line) in [("G73 R3\nG73 P1 Q2 F1\n", 'R', 3), ("G73 P1 Q2 I1 K1 D3 F1\n", 'D', 2)] {
        let src = format!("G0 X10 Z0\n{blocks}{c}");
        assert_eq!(passes(&run_with(&src, &with(3))).len(), 3, "{blocks}");
        assert_eq!(alarm_with(&src, &with(2)), (AlarmCode::TooManyPasses, Some(word), Rule::PrjMaxPass, line), "{blocks}");
    }
}

/// G73.USE: a contour that is not monotone (out to X20, back in to X14, out to X30) is taken by
/// G73 and run on every pass; G71 refuses the same contour (G71.MONOTONE).
#[test]
fn any_contour_is_taken() {
    let contour = "N10 G00 X10\nN20 G01 X20 Z-5\nN30 X14 Z-10\nN40 X30 Z-20\n";
    let g73 = expand(format!("G00 X40 Z5\nG73 U2 W0 R2\nG73 P10 Q40 F0.2\n{contour}").as_bytes(), &Config::default());
    assert_eq!(g73.alarm, None);
    assert!(g73.moves().any(|m| (m.x, m.z) == (14_000, -10_000)), "the last pass runs the contour as written");
    let g71 = expand(format!("G00 X40 Z5\nG71 U1 R0.5\nG71 P10 Q40 F0.2\n{contour}").as_bytes(), &Config::default());
    assert_eq!(g71.alarm.map(|a| a.rule), Some(Rule::G71Monotone));
}
