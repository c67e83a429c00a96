//! Hand-checked G90 and G94 (M003) programs: every number below is worked out from
//! docs/INTERPRETATION.md, "G90 and G94", by hand, not taken from the spec's output.

use crate::tests::util::{alarm_with as alarm_of, passes, Expect};
use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::readings::G94K;
use cycle_vocab::{AlarmCode, Config, Dialect, Grid, Increment, MoveKind, PassKind, Readings, Rule, Units};

fn run(src: &str) -> Trace {
    expand(src.as_bytes(), &Config::default())
}

/// The trace as canonical G-code without its header line.
fn gcode(t: &Trace) -> String {
    assert_eq!(t.alarm, None, "{}", t.to_gcode());
    t.to_gcode().split_once('\n').map(|(_, rest)| rest.to_string()).unwrap_or_default()
}

/// The pass headers: (index, kind, diameter depth, rule).
/// G90.EXAMPLE: the register's reading of `G90X40.Z-40.I-5.F0.3;35.` from X50 Z2.
#[test]
fn g90_seed_taper() {
    let t = run("G0 X50 Z2\nG90 X40. Z-40. I-5. F0.3\nX35.\n");
    assert_eq!(
        gcode(&t),
        "G00 X50.000 Z2.000\n\
         (PASS 1 ROUGH DEPTH 10.000)\nG00 X30.000 Z2.000\nG01 X40.000 Z-40.000 F0.3000\n\
         G01 X50.000 Z-40.000 F0.3000\nG00 X50.000 Z2.000\n\
         (PASS 2 ROUGH DEPTH 12.500)\nG00 X25.000 Z2.000\nG01 X35.000 Z-40.000 F0.3000\n\
         G01 X50.000 Z-40.000 F0.3000\nG00 X50.000 Z2.000\n"
    );
    let rules: Vec<Rule> = t.moves().skip(1).take(4).map(|m| m.rule).collect();
    assert_eq!(rules, vec![Rule::G90Taper, Rule::G90Path, Rule::G90Path, Rule::G90Path]);
    assert_eq!(passes(&t)[0], (1, PassKind::Rough, 20_000, Rule::G90Path));
}

/// The corpus programs: the straight fragment (read with Z-40.), the taper and its repeat;
/// the G94 face steps to Z−3.5, −7, −10.
#[test]
fn corpus_examples() {
    let t = run(include_str!("../../../corpus/g90_example.nc"));
    let straight = "(PASS 1 ROUGH DEPTH 5.000)\nG00 X40.000 Z2.000\nG01 X40.000 Z-40.000 F0.3000\n\
                    G01 X50.000 Z-40.000 F0.3000\nG00 X50.000 Z2.000\n";
    let g = gcode(&t);
    assert!(g.starts_with(&format!("G00 X50.000 Z2.000\n{straight}(PASS 1 ROUGH DEPTH 10.000)\n")), "{g}");
    assert_eq!(g, gcode(&run("G0 X50 Z2\nG90 X40 Z-40 F0.3\nG0 X50\nG90 X40 Z-40 I-5\nX35\n")));
    assert_eq!(t.moves().next().map(|m| m.rule), Some(Rule::PrjModal));
    assert_eq!(t.moves().nth(1).map(|m| m.rule), Some(Rule::G90Path)); // ① of a straight cut

    let t = run(include_str!("../../../corpus/g94_example.nc"));
    let face = |n: u32, z: &str, depth: &str| {
        format!(
            "(PASS {n} ROUGH DEPTH {depth})\nG00 X50.000 Z{z}\nG01 X40.000 Z{z} F0.3000\n\
             G01 X40.000 Z2.000 F0.3000\nG00 X50.000 Z2.000\n"
        )
    };
    let expect = format!(
        "G00 X50.000 Z2.000\n{}{}{}",
        face(1, "-3.500", "5.500"),
        face(2, "-7.000", "9.000"),
        face(3, "-10.000", "12.000")
    );
    assert_eq!(gcode(&t), expect);
    // G94's depth is the Z infeed: twice it on the diameter field.
    assert_eq!(passes(&t).iter().map(|p| p.2).collect::<Vec<_>>(), vec![11_000, 18_000, 24_000]);
    assert!(t.moves().skip(1).all(|m| m.rule == Rule::G94Path));
}

/// G90.TAPER and G94.TAPER: the four sign cases and the equality edge, in the feature programs.
#[test]
fn taper_signs() {
    let t = run(include_str!("../../../tests/programs/g90_taper_signs.nc"));
    let starts: Vec<i64> = passes(&t).iter().map(|p| p.2).collect();
    // |A.x − C.x| on diameter: 50−34, 44−50, 50−50; 36−20, 26−20, 20−20.
    assert_eq!(starts, vec![16_000, 6_000, 0, 16_000, 6_000, 0]);
    assert_eq!(t.moves().filter(|m| m.kind == MoveKind::Feed).count(), 12);
    // Past the edge, each way: GEOMETRY on I.
    let over = (AlarmCode::Geometry, Some('I'), Rule::G90Taper, 2);
    assert_eq!(alarm_of("G0 X50 Z2\nG90 X40 Z-20 I5.001 F0.2\n", &Config::default()), over);
    assert_eq!(alarm_of("G0 X20 Z2\nG90 X30 Z-20 I-5.001 F0.2\n", &Config::default()), over);
    // Same sign: any size.
    assert_eq!(run("G0 X50 Z2\nG90 X40 Z-20 I-100 F0.2\n").alarm, None);
    assert_eq!(run("G0 X20 Z2\nG90 X30 Z-20 I100 F0.2\n").alarm, None);

    // g94_taper.nc is written for `g94.k=start-minus-end` (FANUC: K = start Z − end Z).
    let fanuc_k = g94k(G94K::StartMinusEnd);
    let t = expand(include_bytes!("../../../tests/programs/g94_taper.nc"), &fanuc_k);
    let z_depths: Vec<i64> = passes(&t).iter().map(|p| p.2 / 2).collect();
    assert_eq!(z_depths, vec![5_000, 7_000, 6_000, 0, 8_000]);
    let over = (AlarmCode::Geometry, Some('K'), Rule::G94Taper, 2);
    assert_eq!(alarm_of("G0 X50 Z2\nG94 X20 Z-6 K8.001 F0.2\n", &fanuc_k), over);
    assert_eq!(alarm_of("G0 X50 Z-6\nG94 X20 Z2 K-8.001 F0.2\n", &fanuc_k), over);
    assert_eq!(expand(b"G0 X50 Z-6\nG94 X20 Z2 K-8 F0.2\n", &fanuc_k).alarm, None);
    // ① is tagged with the taper rule when K ≠ 0.
    assert_eq!(t.moves().nth(1).map(|m| (m.kind, m.z, m.rule)), Some((MoveKind::Rapid, -3_000, Rule::G94Taper)));
}

fn g94k(k: G94K) -> Config {
    Config { readings: Readings { g94_k: k, ..Readings::default() }, ..Config::default() }
}

/// G94.TAPER under the letter (`g94.k=end-minus-start`, the default): C.z = D.z − K, the taper
/// checked on k = C.z − D.z (`g94_k_letter.nc`: the register's `G94 X20 Z-5 K-2` starts at Z−3;
/// FANUC's reading starts the same block at Z−7).
#[test]
fn g94_k_letter() {
    let src = include_str!("../../../tests/programs/g94_k_letter.nc");
    let t = run(src);
    assert_eq!(t, expand(src.as_bytes(), &g94k(G94K::EndMinusStart)));
    let starts: Vec<i64> = t.moves().filter(|m| m.rule == Rule::G94Taper).map(|m| m.z).collect();
    assert_eq!(starts, vec![-3_000, -6_000, -7_000]); // the K-8 cut starts at A.z: no approach
    let z_depths: Vec<i64> = passes(&t).iter().map(|p| p.2 / 2).collect();
    assert_eq!(z_depths, vec![5_000, 8_000, 0, 9_000]);
    let fanuc = expand(b"G0 X50 Z2\nG94 X20 Z-5 K-2 F0.2\n", &g94k(G94K::StartMinusEnd));
    assert_eq!(fanuc.moves().nth(1).map(|m| m.z), Some(-7_000));
    // The taper edge under the letter: k = −K against W.
    let over = (AlarmCode::Geometry, Some('K'), Rule::G94Taper, 2);
    assert_eq!(alarm_of("G0 X50 Z2\nG94 X20 Z-6 K-8.001 F0.2\n", &Config::default()), over);
    assert_eq!(alarm_of("G0 X50 Z-6\nG94 X20 Z2 K8.001 F0.2\n", &Config::default()), over);
    assert_eq!(run("G0 X50 Z2\nG94 X20 Z-6 K8.001 F0.2\n").alarm, None); // same sign: any size
    assert_eq!(run("G0 X50 Z-6\nG94 X20 Z2 K8 F0.2\n").alarm, None);
}

/// G90.MODAL: X, Z and I kept within a run; a block without axis words updates I and F; G76
/// between blocks does not end the run; G94, G01 and G00 start a new one.
#[test]
fn modal_runs() {
    let t = run(include_str!("../../../tests/programs/g90_modal_runs.nc"));
    let cycles: Vec<(u32, i64, Rule)> =
        passes(&t).iter().filter(|p| matches!(p.3, Rule::G90Path | Rule::G94Path)).map(|p| (p.0, p.2, p.3)).collect();
    assert_eq!(
        cycles,
        vec![(1, 6_000, Rule::G90Path), (2, 8_000, Rule::G90Path), (3, 10_000, Rule::G90Path), (1, 6_000, Rule::G94Path), (1, 10_000, Rule::G90Path), (1, 14_000, Rule::G90Path)]
    );
    // Only I (and F) in the mode: nothing is cut; the next axis block takes them.
    let a = run("G0 X50 Z2\nG90 X40 Z-40 F0.3\nI-5 F0.2\nX35\n");
    let b = run("G0 X50 Z2\nG90 X40 Z-40 F0.3\nX35 I-5 F0.2\n");
    assert_eq!(a, b);
    assert_eq!(passes(&a).len(), 2);
    // A new run forgets the end Z (then W = 0) and I.
    let g = (AlarmCode::Geometry, Some('Z'), Rule::G90Format, 4);
    assert_eq!(alarm_of("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG0 X50\nG90 X35\n", &Config::default()), g);
    let fresh = run("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG94 X40 Z-1\nG90 X35 Z-40\n");
    let xs: Vec<i64> = fresh.moves().map(|m| m.x).collect();
    assert_eq!(xs[xs.len() - 4..], [35_000, 35_000, 50_000, 50_000]); // I = 0: the cut starts at X35
    // G90 written again within the run continues it (index 2).
    assert_eq!(passes(&run("G0 X50 Z2\nG90 X40 Z-40 F0.3\nG90 X35\n"))[1].0, 2);
    // G92, a motion mode, ends the run like G00.
    let t = run("G0 X50 Z2\nG90 X40 Z-40 F0.3\nG92 X40 Z-20 F1\nG90 X35\n");
    assert_eq!(t.alarm.map(|a| (a.code, a.rule)), Some((AlarmCode::Geometry, Rule::G90Format)));
}

/// G90.PATH with U = 0 and I = 0: a legal cut along Z at the start X (① and ③ not emitted);
/// G94 with W = 0: a face cut at the start Z.
#[test]
fn degenerate_but_legal() {
    let t = run("G0 X50 Z2\nG90 Z-10 F0.3\n");
    assert_eq!(gcode(&t), "G00 X50.000 Z2.000\n(PASS 1 ROUGH DEPTH 0.000)\nG01 X50.000 Z-10.000 F0.3000\nG00 X50.000 Z2.000\n");
    let t = run("G0 X50 Z2\nG94 X40 W0 F0.3\n");
    assert_eq!(gcode(&t), "G00 X50.000 Z2.000\n(PASS 1 ROUGH DEPTH 0.000)\nG01 X40.000 Z2.000 F0.3000\nG00 X50.000 Z2.000\n");
}

/// Every G90/G94 alarm with its word and rule, in the check order.
#[test]
fn alarms() {
    let c = Config::default();
    let cases: &[(&str, Expect)] = &[
        // Step 2: words allowed (R refused), conflicts.
        ("G90 X40 Z-40 R-5 F0.3", (AlarmCode::WordNotAllowed, Some('R'), Rule::PrjWord, 1)),
        ("G90 X40 Z-40 K1 F0.3", (AlarmCode::WordNotAllowed, Some('K'), Rule::PrjWord, 1)),
        ("G94 X40 Z-4 I1 F0.3", (AlarmCode::WordNotAllowed, Some('I'), Rule::PrjWord, 1)),
        ("G94 X40 Z-4 R1 F0.3", (AlarmCode::WordNotAllowed, Some('R'), Rule::PrjWord, 1)),
        ("G90 X40.0001 Z-40 P1 F0.3", (AlarmCode::WordNotAllowed, Some('P'), Rule::PrjWord, 1)),
        ("G90 X40 U1 Z-40 F0.3", (AlarmCode::Conflict, Some('U'), Rule::ComAbsInc, 1)),
        ("G94 X40 Z-4 W1 F0.3", (AlarmCode::Conflict, Some('W'), Rule::ComAbsInc, 1)),
        ("G90 G01 X40 Z-40 F0.3", (AlarmCode::Conflict, Some('G'), Rule::PrjWord, 1)),
        ("G90 G94 X40 Z-40 F0.3", (AlarmCode::Conflict, Some('G'), Rule::PrjWord, 1)),
        ("G90 G90 X40 Z-40 F0.3", (AlarmCode::Conflict, Some('G'), Rule::PrjWord, 1)),
        ("G90 G76 X40 Z-40 F0.3", (AlarmCode::Conflict, Some('G'), Rule::PrjWord, 1)),
        // Step 3: values in alphabetical order.
        ("G90 X40.0001 Z-40 I1000000 F0", (AlarmCode::OutOfRange, Some('F'), Rule::ComRanges, 1)),
        ("G90 X40.0001 Z-40 I1000000 F0.3", (AlarmCode::OutOfRange, Some('I'), Rule::ComRanges, 1)),
        ("G90 X40.0001 Z-40 I0.0001 F0.3", (AlarmCode::Precision, Some('I'), Rule::ComUnits, 1)),
        ("G90 X40.0001 Z-40 F0.3", (AlarmCode::Precision, Some('X'), Rule::ComUnits, 1)),
        ("G94 X40 Z-4 K-999999999999999999 F0.3", (AlarmCode::OutOfRange, Some('K'), Rule::ComRanges, 1)),
        ("G90 X40 Z-40 F0.00001", (AlarmCode::Precision, Some('F'), Rule::ComUnits, 1)),
        // Step 4: missing feed, before the cycle's checks.
        ("G0 X50 Z2\nG90 X40", (AlarmCode::MissingWord, Some('F'), Rule::ComLead, 2)),
        ("G0 X50 Z2\nG94 Z-2", (AlarmCode::MissingWord, Some('F'), Rule::ComLead, 2)),
        // Step 5: W = 0 before the taper; U = 0 before the taper.
        ("G0 X50 Z2\nG90 X40 Z2 I9 F0.3", (AlarmCode::Geometry, Some('Z'), Rule::G90Format, 2)),
        ("G0 X50 Z2\nG90 X40 Z-40 I5.001 F0.3", (AlarmCode::Geometry, Some('I'), Rule::G90Taper, 2)),
        ("G0 X50 Z2\nG94 X50 Z-2 K9 F0.3", (AlarmCode::Geometry, Some('X'), Rule::G94Format, 2)),
        ("G0 X50 Z2\nG94 X40 Z-2 K-4.001 F0.3", (AlarmCode::Geometry, Some('K'), Rule::G94Taper, 2)),
    ];
    for (src, expect) in cases {
        assert_eq!(alarm_of(src, &c), *expect, "{src}");
    }
    // Without axis words nothing is cut, so no feed is needed.
    assert_eq!(run("G90 I-5\nG94 K1\n").events, vec![]);
    // F with I in G90 is legal (I is no lead here); under fanuc too.
    assert_eq!(run("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\n").alarm, None);
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(expand(b"G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG94 X40 Z-3\n", &fanuc).alarm, None);
}

/// Under `nc201` G90 stays the absolute mode (NC201.ABSINC) and G94 is refused (PRJ.DIALECT).
#[test]
fn nc201() {
    let c = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(alarm_of("G94 X40 Z-4 F0.3", &c), (AlarmCode::UnsupportedCode, Some('G'), Rule::PrjDialect, 1));
    let t = expand(b"G91 G0 X10\nG90 X40 Z-40\n", &c);
    assert_eq!(t.alarm, None);
    assert_eq!(t.moves().map(|m| (m.kind, m.x, m.z)).collect::<Vec<_>>(), vec![(MoveKind::Rapid, 10_000, 0), (MoveKind::Rapid, 40_000, -40_000)]);
    assert_eq!(alarm_of("G90 X40 Z-40 I1", &c), (AlarmCode::WordNotAllowed, Some('I'), Rule::PrjWord, 1));
}

/// COM.UNITS on the other grids: inch ISB (the feature program), inch ISC, metric ISC.
#[test]
fn other_grids() {
    let inch = Config { grid: Grid { units: Units::Inch, increment: Increment::Isb }, ..Config::default() };
    let t = expand(include_bytes!("../../../tests/programs/g90_inch.nc"), &inch);
    assert_eq!(t.alarm, None);
    // 0.0001 in increments; F0.01 in = 1 000 lead counts of 0.00001 in. Pass 3: C.x = 1.6 − 2·0.05.
    assert_eq!(passes(&t).iter().map(|p| p.2).collect::<Vec<_>>(), vec![2_000, 3_000, 5_000]);
    assert!(t.moves().filter(|m| m.kind == MoveKind::Feed).all(|m| m.feed == 1_000));
    assert_eq!(t.moves().nth(9).map(|m| (m.x, m.z)), Some((15_000, 1_000)));
    let inch_isc = Config { grid: Grid { units: Units::Inch, increment: Increment::Isc }, ..Config::default() };
    let t = expand(b"G20\nG0 X2 Z0.1\nG94 X1.5 Z-0.00001 K-0.00002 F0.005\n", &inch_isc);
    assert_eq!(t.alarm, None);
    assert_eq!(t.moves().nth(1).map(|m| (m.x, m.z)), Some((200_000, 1))); // C.z = −1 − (−2)
    assert_eq!(alarm_of("G20\nG94 X1.5 Z-0.000001 F0.005\n", &inch_isc), (AlarmCode::Precision, Some('Z'), Rule::ComUnits, 2));
    let metric_isc = Config { grid: Grid { units: Units::Metric, increment: Increment::Isc }, ..Config::default() };
    let t = expand(b"G0 X50 Z2\nG90 X40.0001 Z-40 I-0.0001 F0.3\n", &metric_isc);
    assert_eq!(t.moves().nth(1).map(|m| m.x), Some(399_999));
    assert_eq!(passes(&t)[0].2, 500_000 - 399_999);
}
