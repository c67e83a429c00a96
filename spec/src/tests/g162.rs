//! Hand-checked G162 (M004) and G32/G33/G34 (M003) programs: every number below is worked out
//! from docs/INTERPRETATION.md by hand, not taken from the spec's output.

use crate::tests::util::{alarm_with as alarm_of, Expect};
use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::readings::G162Lead;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Event, Grid, Increment, MoveKind, Params, Readings, Rule, Units};

fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

fn run(src: &str, config: &Config) -> Trace {
    expand(src.as_bytes(), config)
}

/// The radius depths of the pass headers.
fn depths(t: &Trace) -> Vec<i64> {
    t.events
        .iter()
        .filter_map(|e| match e {
            Event::Pass(p) => Some(p.diameter_depth / 2),
            _ => None,
        })
        .collect()
}

/// The register's worked example, pass 1 and pass 6 in full.
#[test]
fn worked_example() {
    let t = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 V2 F1.5\n", &nc201());
    assert_eq!(t.alarm, None);
    assert_eq!(depths(&t), vec![500, 1_000, 1_100, 1_150, 1_175, 1_200]);
    let g = t.to_gcode();
    let pass1 = "(PASS 1 ROUGH DEPTH 0.500)\nG01 X23.000 Z5.000 F500.0000\nG32 X23.000 Z-18.000 F1.5000\n\
                 G01 X27.000 Z-20.000 F500.0000\nG01 X30.000 Z-20.000 F500.0000\nG01 X30.000 Z5.000 F500.0000\n";
    let pass6 = "(PASS 6 ROUGH DEPTH 1.200)\nG01 X21.600 Z5.000 F500.0000\nG32 X21.600 Z-18.000 F1.5000\n\
                 G01 X25.600 Z-20.000 F500.0000\nG01 X30.000 Z-20.000 F500.0000\nG01 X30.000 Z5.000 F500.0000\n";
    assert!(g.contains(pass1), "{g}");
    assert!(g.ends_with(pass6), "{g}");
    // 1 rapid + 6 passes × 5 moves; H on ①③④⑤ (feed moves, never rapids), F on ②.
    assert_eq!(t.moves().count(), 31);
    assert!(t.moves().skip(1).all(|m| match m.kind {
        MoveKind::Feed => m.feed == 5_000_000,
        MoveKind::Thread => m.feed == 15_000 && m.rule == Rule::G162F,
        MoveKind::Rapid | MoveKind::ArcCw | MoveKind::ArcCcw => false,
    }));
    let pass_rules: Vec<Rule> = t
        .events
        .iter()
        .filter_map(|e| if let Event::Pass(p) = e { Some(p.rule) } else { None })
        .collect();
    assert_eq!(pass_rules, [[Rule::G162Pq; 2].as_slice(), &[Rule::G162Split; 4]].concat());
}

/// The example: P2.5 Q1 — 1, 2, 2.25, 2.375, 2.4375, 2.5 on the ISC grid; 2.438 on ISB.
#[test]
fn p2_5_q1() {
    let src = "G0 X40 Z5\nG162 X30 Z-30 H300 P2.5 Q1 F2\n";
    let isb = run(src, &nc201());
    assert_eq!(depths(&isb), vec![1_000, 2_000, 2_250, 2_375, 2_438, 2_500]);
    let isc = Config { grid: Grid { units: Units::Metric, increment: Increment::Isc }, ..nc201() };
    assert_eq!(depths(&run(src, &isc)), vec![10_000, 20_000, 22_500, 23_750, 24_375, 25_000]);
    assert!(isb.to_gcode().contains("(PASS 5 ROUGH DEPTH 2.438)\nG01 X25.124 Z5.000"));
}

/// G162.X single pass: X is where the one pass cuts; depth 0; no leg without V.
#[test]
fn single_pass() {
    let t = run("G0 X30 Z5\nG162 X23 Z-20 H500 F1.5\n", &nc201());
    assert_eq!(
        t.to_gcode(),
        "(CYCLECHECK TRACE MM GRID 0.001)\nG00 X30.000 Z5.000\n(PASS 1 ROUGH DEPTH 0.000)\n\
         G01 X23.000 Z5.000 F500.0000\nG32 X23.000 Z-20.000 F1.5000\nG01 X30.000 Z-20.000 F500.0000\n\
         G01 X30.000 Z5.000 F500.0000\n"
    );
    let rules: Vec<Rule> = t.events.iter().map(|e| e.rule()).collect();
    assert_eq!(rules[1], Rule::G162X);
    // A tapered single pass: X is the thread's END; ② starts at X23 − 2 = X21.
    let t = run("G0 X30 Z5\nG162 X23 Z-20 W2 H500 F1.5\n", &nc201());
    let m: Vec<(MoveKind, i64, i64)> = t.moves().skip(1).map(|m| (m.kind, m.x, m.z)).collect();
    assert_eq!(
        m,
        vec![(MoveKind::Feed, 21_000, 5_000), (MoveKind::Thread, 23_000, -20_000), (MoveKind::Feed, 30_000, -20_000), (MoveKind::Feed, 30_000, 5_000)]
    );
    // The side and the checks use that start X: from X22 the thread starts below S (s = +1)
    // and ends above it at X23 — the retract ④ would go into the work; from X21 there is no
    // approach (s = 0). (Read as a start X, X23 from X22 would be a legal internal thread.)
    assert_eq!(alarm_of("G0 X22 Z5\nG162 X23 Z-20 W2 H500 F1.5\n", &nc201()), (AlarmCode::Geometry, Some('X'), Rule::G162Retract, 2));
    assert_eq!(alarm_of("G0 X21 Z5\nG162 X23 Z-20 W2 H500 F1.5\n", &nc201()), (AlarmCode::Geometry, Some('X'), Rule::G162Retract, 2));
    // Multi-pass: X stays the start of the depth-0 line.
    let t = run("G0 X30 Z5\nG162 X23 Z-20 W2 H500 P0.5 Q0.5 F1.5\n", &nc201());
    assert_eq!(t.moves().nth(1).map(|m| m.x), Some(22_000));
}

/// NC201.ABSINC: G91 distances from the position before the block give the same cycle; G91 is
/// modal and applies to G00/G01 too; G90 restores positions.
#[test]
fn g91_incremental() {
    let abs = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 V2 F1.5\n", &nc201());
    let inc = run("G0 X30 Z5\nG91 G162 X-6 Z-25 H500 P1.2 Q0.5 V2 F1.5\n", &nc201());
    assert_eq!(inc, abs);
    let t = run("G0 X30 Z5\nG91\nG0 X-2 Z-1\nG1 Z-3 F0.2\nG90 G0 X50\n", &nc201());
    let ends: Vec<(i64, i64)> = t.moves().map(|m| (m.x, m.z)).collect();
    assert_eq!(ends, vec![(30_000, 5_000), (28_000, 4_000), (28_000, 1_000), (50_000, 1_000)]);
}

/// NC201.XMODE: with x_radius = 1, X and W are radii (X12 = diameter 24), also for G00; P, Q, V
/// stay radii either way.
#[test]
fn x_radius_mode() {
    let radius = Config { params: Params { x_radius: Some(1), ..Params::default() }, ..nc201() };
    let r = run("G0 X15 Z5\nG162 X12 Z-20 H500 P1.2 Q0.5 V2 W1 F1.5\n", &radius);
    let d = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 V2 W2 F1.5\n", &nc201());
    assert_eq!(r, d);
    assert_eq!(r.alarm, None);
    // Under gsk the parameter is not read.
    let gsk = Config { params: Params { x_radius: Some(1), ..Params::default() }, ..Config::default() };
    assert_eq!(run("G0 X15\n", &gsk).moves().next().unwrap().x, 15_000);
    // Out of range through the library API: line 0, NC201.XMODE.
    let bad = Config { params: Params { x_radius: Some(2), ..Params::default() }, ..nc201() };
    assert_eq!(run("G0 X1\n", &bad).alarm, Some(Alarm::new(AlarmCode::OutOfRange, None, Rule::Nc201XMode, 0)));
}

/// G162.W and G162.F: the manual's cone (50 long, 20 on diameter) threaded with F1.96; the lead
/// is printed as written, along Z (the long axis); the taper follows every pass.
#[test]
fn taper_with_the_manual_pitch() {
    let t = run("G0 X45 Z0\nG162 X20 Z-50 H300 P1.2 Q0.4 W20 F1.96\n", &nc201());
    assert_eq!(t.alarm, None);
    let threads: Vec<(i64, i64, i64)> =
        t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z, m.feed)).collect();
    assert_eq!(threads, vec![(39_200, -50_000, 19_600), (38_400, -50_000, 19_600), (37_600, -50_000, 19_600)]);
    let starts: Vec<i64> = t.moves().filter(|m| m.rule == Rule::G162Path && m.z == 0 && m.x != 45_000).map(|m| m.x).collect();
    assert_eq!(starts, vec![19_200, 18_400, 17_600]);
}

/// G162.A: the Z shift and its sign (external +Z for A > 0; internal −Z; A < 0 mirrors), the
/// whole pass translated.
#[test]
fn infeed_angle() {
    let ext = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1 Q0.5 V2 A30 F1.5\n", &nc201());
    let firsts: Vec<(i64, i64)> = ext.moves().skip(1).take(5).map(|m| (m.x, m.z)).collect();
    // t(0.5) = round(500·tan 30°) = round(288.675) = 289.
    assert_eq!(firsts, vec![(23_000, 5_289), (23_000, -17_711), (27_000, -19_711), (30_000, -19_711), (30_000, 5_000)]);
    let neg = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1 Q0.5 V2 A-30 F1.5\n", &nc201());
    assert_eq!(neg.moves().nth(1).map(|m| (m.x, m.z)), Some((23_000, 4_711)));
    // Internal: S below the thread, deeper is +X, A > 0 shifts −Z; t(1.0) = round(577.350) = 577.
    let int = run("G0 X10 Z5\nG162 X20 Z-20 H500 P1 Q1 V2 A30 F1.5\n", &nc201());
    let m: Vec<(i64, i64)> = int.moves().skip(1).map(|m| (m.x, m.z)).collect();
    assert_eq!(m, vec![(22_000, 4_423), (22_000, -18_577), (18_000, -20_577), (10_000, -20_577), (10_000, 5_000)]);
    // Half degrees: 27.5°; 1 mm·tan 27.5° = 0.52057 → 0.521.
    let half = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1 Q1 A27.5 F1.5\n", &nc201());
    assert_eq!(half.moves().nth(1).map(|m| m.z), Some(5_521));
    // Any tenth: 27.3°; 1 mm·tan 27.3° = 0.516138 → 0.516; 14.9°: 0.266 (0.26608).
    let tenth = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1 Q1 A27.3 F1.5\n", &nc201());
    assert_eq!(tenth.moves().nth(1).map(|m| m.z), Some(5_516));
    let tenth = run("G0 X30 Z5\nG162 X24 Z-20 H500 P1 Q1 A-14.9 F1.5\n", &nc201());
    assert_eq!(tenth.moves().nth(1).map(|m| m.z), Some(4_734));
}

/// G162.V: the leg is a feed at H, 45° outward: Z travel V toward the cut, X travel V radius.
/// Cutting toward +Z mirrors it.
#[test]
fn run_out_leg() {
    let t = run("G0 X30 Z-40\nG162 X24 Z-10 H200 V1.5 F1\n", &nc201());
    let m: Vec<(MoveKind, i64, i64, Rule)> = t.moves().skip(1).map(|m| (m.kind, m.x, m.z, m.rule)).collect();
    assert_eq!(
        m,
        vec![
            (MoveKind::Feed, 24_000, -40_000, Rule::G162Path),
            (MoveKind::Thread, 24_000, -11_500, Rule::G162F),
            (MoveKind::Feed, 27_000, -10_000, Rule::G162V),
            (MoveKind::Feed, 30_000, -10_000, Rule::G162Retract),
            (MoveKind::Feed, 30_000, -40_000, Rule::G162Path),
        ]
    );
}

/// G162.B, G162.I, G162.J: start angle, the variable-lead fields, the stop at |I|. The letter
/// (`g162.lead=steps`, the default) marks the move stepped (` L1`); `continuous` does not.
#[test]
fn start_angle_and_variable_pitch() {
    let t = run("G0 X30 Z5\nG162 X24 Z-20 H500 F1.5 B90 I-0.5 J180\n", &nc201());
    let th = t.moves().find(|m| m.kind == MoveKind::Thread).copied().unwrap();
    assert_eq!((th.feed, th.angle, th.lead_change, th.lead_change_angle, th.lead_floor), (15_000, 90_000, -5_000, 180_000, 5_000));
    assert!(th.lead_steps);
    assert!(t.to_gcode().contains("G32 X24.000 Z-20.000 F1.5000 Q90000 K-0.5000 J180000 R0.5000 L1\n"));
    let cont = with_lead(G162Lead::Continuous);
    let t = run("G0 X30 Z5\nG162 X24 Z-20 H500 F1.5 B90 I-0.5 J180\n", &cont);
    let tc = t.moves().find(|m| m.kind == MoveKind::Thread).copied().unwrap();
    assert_eq!(tc, cycle_vocab::Move { lead_steps: false, ..th });
    assert!(t.to_gcode().contains("G32 X24.000 Z-20.000 F1.5000 Q90000 K-0.5000 J180000 R0.5000\n"));
    assert_eq!(run("G0 X30 Z5\nG162 X24 Z-20 H500 F1.5 I0.1\n", &with_lead(G162Lead::Steps)), run("G0 X30 Z5\nG162 X24 Z-20 H500 F1.5 I0.1\n", &nc201()));
    // Growing, J omitted: per revolution, no floor; B360 is the zero mark.
    let t = run("G0 X30 Z5\nG162 X24 Z-20 H500 F1.5 B360 I0.01\n", &nc201());
    let th = t.moves().find(|m| m.kind == MoveKind::Thread).copied().unwrap();
    assert_eq!((th.angle, th.lead_change, th.lead_change_angle, th.lead_floor), (0, 100, 360_000, 0));
    // F ≤ |I| already: the change has stopped, the lead is constant (never stepped).
    let t = run("G0 X30 Z5\nG162 X24 Z-20 H500 F0.5 I-0.5\n", &nc201());
    let th = t.moves().find(|m| m.kind == MoveKind::Thread).copied().unwrap();
    assert_eq!((th.feed, th.lead_change, th.lead_change_angle, th.lead_floor, th.lead_steps), (5_000, 0, 0, 0, false));
}

fn with_lead(lead: G162Lead) -> Config {
    Config { readings: Readings { g162_lead: lead, ..Readings::default() }, ..nc201() }
}

/// G162.I, the growing-pitch bound under each reading. F9999 I0.0001 over 10 mm: continuously
/// the lead passes Fmax; in steps the first step comes after one revolution (9999 mm of travel),
/// never reached. F1 I9998.999: the first step, to 9999.999 mm > Fmax, after 1 mm: reached.
#[test]
fn growing_pitch_bound_by_reading() {
    let over = (AlarmCode::Geometry, Some('I'), Rule::G162I, 2);
    let slow = "G0 X30 Z5\nG162 X24 Z-5 H1 F9999 I0.0001\n";
    assert_eq!(alarm_of(slow, &with_lead(G162Lead::Continuous)), over);
    assert_eq!(run(slow, &nc201()).alarm, None);
    let jump = "G0 X30 Z5\nG162 X24 Z-5 H1 F1 I9998.999\n";
    assert_eq!(alarm_of(jump, &nc201()), over);
    // Exactly 1 mm of thread: the step would come at its end, not during it.
    assert_eq!(run("G0 X30 Z5\nG162 X24 Z4 H1 F1 I9998.999\n", &nc201()).alarm, None);
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z3.999 H1 F1 I9998.999\n", &nc201()), over);
}

/// G162.F: F omitted takes the modal feed (a G01 mm/min value read as mm/rev); F in G162 sets
/// it; H does not.
#[test]
fn modal_lead() {
    let t = run("G0 X30 Z5\nG1 X30 F100\nG162 X24 Z-20 H500\n", &nc201());
    assert_eq!(t.moves().find(|m| m.kind == MoveKind::Thread).map(|m| m.feed), Some(1_000_000));
    let t = run("G0 X30 Z5\nG162 X24 Z-20 H500 F1.5\nG1 X31\n", &nc201());
    assert_eq!(t.moves().last().map(|m| (m.kind, m.feed)), Some((MoveKind::Feed, 15_000)));
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z-20 H500\n", &nc201()), (AlarmCode::MissingWord, Some('F'), Rule::G162F, 2));
}

/// The register's alarms, each naming its word and rule, in the check order.
#[test]
fn alarms() {
    let c = nc201();
    let cases: &[(&str, Expect)] = &[
        // Missing words: F, H, P/Q, X, Z.
        ("G162 X1 Z1 F1", (AlarmCode::MissingWord, Some('H'), Rule::G162H, 1)),
        ("G162 X1 Z1 H1 F1 Q1", (AlarmCode::MissingWord, Some('P'), Rule::G162Pq, 1)),
        ("G162 X1 Z1 H1 F1 P1", (AlarmCode::MissingWord, Some('Q'), Rule::G162Pq, 1)),
        ("G162 Z1 H1 F1", (AlarmCode::MissingWord, Some('X'), Rule::G162Format, 1)),
        ("G162 X1 H1 F1", (AlarmCode::MissingWord, Some('Z'), Rule::G162Format, 1)),
        // Values, alphabetical: A before B before H …
        ("G162 X1 Z1 H0 F1 A27.35 B400", (AlarmCode::Precision, Some('A'), Rule::G162A, 1)),
        ("G162 X1 Z1 H0 F1 A27.3 B400", (AlarmCode::OutOfRange, Some('B'), Rule::G162B, 1)),
        ("G162 X1 Z1 H0 F1 A90 B400", (AlarmCode::OutOfRange, Some('A'), Rule::G162A, 1)),
        ("G162 X1 Z1 H0 F1 B400", (AlarmCode::OutOfRange, Some('B'), Rule::G162B, 1)),
        ("G162 X1 Z1 H0 F1", (AlarmCode::OutOfRange, Some('H'), Rule::G162H, 1)),
        ("G162 X1 Z1 H1 F1 I10000", (AlarmCode::OutOfRange, Some('I'), Rule::G162I, 1)),
        ("G162 X1 Z1 H1 F1 J0", (AlarmCode::OutOfRange, Some('J'), Rule::G162J, 1)),
        ("G162 X1 Z1 H1 F1 P0 Q1", (AlarmCode::OutOfRange, Some('P'), Rule::ComRanges, 1)),
        ("G162 X1 Z1 H1 F1 V-1", (AlarmCode::OutOfRange, Some('V'), Rule::ComRanges, 1)),
        ("G162 X1 Z1 H1 F1 U1", (AlarmCode::WordNotAllowed, Some('U'), Rule::PrjWord, 1)),
        // Cycle checks (step 5), in order.
        ("G0 X30 Z5\nG162 X24 Z5 H1 F1 V9", (AlarmCode::Geometry, Some('Z'), Rule::G162Format, 2)),
        ("G0 X30 Z5\nG162 X24 Z-5 H1 F1 V10", (AlarmCode::Geometry, Some('V'), Rule::G162V, 2)),
        ("G0 X30 Z5\nG162 X30 Z-5 H1 F1", (AlarmCode::Geometry, Some('X'), Rule::G162Retract, 2)),
        ("G0 X30 Z5\nG162 X24 Z-5 H1 F1 V4", (AlarmCode::Geometry, Some('X'), Rule::G162Retract, 2)),
        ("G0 X30 Z5\nG162 X24 Z-5 H1 F1 P1 Q1 W7", (AlarmCode::Geometry, Some('X'), Rule::G162Retract, 2)),
        ("G0 X30 Z5\nG162 X31 Z-5 H1 F1 W7", (AlarmCode::Geometry, Some('X'), Rule::G162Retract, 2)),
        ("G0 X30 Z5\nG162 X24 Z-5 H1 F1 P11 Q0.001", (AlarmCode::TooManyPasses, Some('Q'), Rule::PrjMaxPass, 2)),
        ("G0 X30 Z5\nG162 X24 Z-5 H1 F1 I9998.999", (AlarmCode::Geometry, Some('I'), Rule::G162I, 2)),
        // Dialect and nc201 modal codes.
        ("G92 X1 Z1 F1", (AlarmCode::UnsupportedCode, Some('G'), Rule::PrjDialect, 1)),
        ("G32 X1 Z1 F1", (AlarmCode::UnsupportedCode, Some('G'), Rule::PrjDialect, 1)),
        ("G90 G91 X1", (AlarmCode::Conflict, Some('G'), Rule::Nc201AbsInc, 1)),
        ("G90 G91 M1.5", (AlarmCode::NotInteger, Some('M'), Rule::ComRanges, 1)),
        ("G0 G162 X1 Z1 H1 F1", (AlarmCode::Conflict, Some('G'), Rule::PrjWord, 1)),
        ("G1 X1 U1 F1", (AlarmCode::WordNotAllowed, Some('U'), Rule::PrjWord, 1)),
        ("G1 X1 F1 I1", (AlarmCode::WordNotAllowed, Some('I'), Rule::PrjWord, 1)),
    ];
    for (src, expect) in cases {
        assert_eq!(alarm_of(src, &c), *expect, "{src}");
    }
    // No pair conflict under nc201: Z with W, F with I are G162 words.
    assert_eq!(run("G0 X30 Z5\nG162 X24 Z-20 W2 H1 F1.5 I0.1\n", &c).alarm, None);
    // G162 under gsk / fanuc, G90 under gsk.
    assert_eq!(alarm_of("G162 X1 Z1 H1", &Config::default()), (AlarmCode::UnsupportedCode, Some('G'), Rule::PrjDialect, 1));
    assert_eq!(alarm_of("G91 X1", &Config::default()), (AlarmCode::UnsupportedCode, Some('G'), Rule::PrjSupported, 1));
}

/// The pass bound counts the split passes too: P1.05 Q0.1 is 10 full passes and, for D = 0.05,
/// the targets 1.025, 1.0375 → 1.038, 1.04375 → 1.044 and 1.05: 14 passes.
#[test]
fn pass_bound_counts_split_passes() {
    let src = "G0 X30 Z5\nG162 X24 Z-20 H500 P1.05 Q0.1 F1.5\n";
    let t = run(src, &nc201());
    assert_eq!(depths(&t), [(1..=10).map(|n| n * 100).collect::<Vec<_>>(), vec![1_025, 1_038, 1_044, 1_050]].concat());
    let at = |max| Config { params: Params { max_passes: Some((max) as i64), ..Params::default() }, ..nc201() };
    assert_eq!(run(src, &at(14)).alarm, None);
    assert_eq!(alarm_of(src, &at(13)), (AlarmCode::TooManyPasses, Some('Q'), Rule::PrjMaxPass, 2));
}

/// G32, G33, G34 (M003): one thread move each; modal; P and K per block.
#[test]
fn thread_moves() {
    let t = run("G0 X30 Z5\nG32 Z-20 F1.5\nX32 W-5\nG33 X30 Z5 P180000\nG34 Z-20 K-0.01\nG0 X40\n", &Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(
        t.to_gcode(),
        "(CYCLECHECK TRACE MM GRID 0.001)\nG00 X30.000 Z5.000\nG32 X30.000 Z-20.000 F1.5000\n\
         G32 X32.000 Z-25.000 F1.5000\nG32 X30.000 Z5.000 F1.5000 Q180000\nG32 X30.000 Z-20.000 F1.5000 K-0.0100\n\
         G00 X40.000 Z-20.000\n"
    );
    let rules: Vec<Rule> = t.moves().map(|m| m.rule).collect();
    assert_eq!(rules, vec![Rule::PrjModal, Rule::G32, Rule::G32, Rule::G33, Rule::G34, Rule::PrjModal]);
    // G33 repeated without P: angle 0 (not kept); G34 repeated without K: alarm (not kept).
    let t = run("G33 Z-5 F1 P90000\nZ-10\n", &Config::default());
    assert_eq!(t.moves().map(|m| m.angle).collect::<Vec<_>>(), vec![90_000, 0]);
    let c = Config::default();
    assert_eq!(alarm_of("G34 Z-5 F1 K0.1\nZ-10\n", &c), (AlarmCode::MissingWord, Some('K'), Rule::G34, 2));
    assert_eq!(alarm_of("G32 Z-5\n", &c), (AlarmCode::MissingWord, Some('F'), Rule::ComLead, 1));
    assert_eq!(alarm_of("G33 Z-5 F1 P360000\n", &c), (AlarmCode::OutOfRange, Some('P'), Rule::G33, 1));
    assert_eq!(alarm_of("G33 Z-5 F1 P1.5\n", &c), (AlarmCode::NotInteger, Some('P'), Rule::ComRanges, 1));
    assert_eq!(alarm_of("G32 Z-5 F1 K1\n", &c), (AlarmCode::WordNotAllowed, Some('K'), Rule::PrjWord, 1));
    assert_eq!(alarm_of("G32 Z-5 F1 I2\n", &c), (AlarmCode::Conflict, Some('I'), Rule::ComLead, 1));
    // G34: F 2, K −0.1 over 20 mm: L² = 4 − 2·0.1·20 = 0 → refused; over 19.999 mm legal.
    assert_eq!(alarm_of("G34 Z-20 F2 K-0.1\n", &c), (AlarmCode::Geometry, Some('K'), Rule::G34, 1));
    assert_eq!(run("G34 Z-19.999 F2 K-0.1\n", &c).alarm, None);
    // A block without axis words moves nothing and needs no K; a zero-length move is not emitted.
    assert_eq!(run("G34 F2\nG34 Z0 F2 K0.1\n", &c).events, vec![]);
    // FANUC dialect has them too; G34 K0 is a constant lead.
    let f = Config { dialect: Dialect::Fanuc, ..Config::default() };
    let t = run("G34 Z-5 F1 K0\n", &f);
    assert_eq!(t.moves().next().map(|m| (m.lead_change, m.lead_change_angle)), Some((0, 0)));
    // G34 growing per revolution: K prints without J.
    assert!(run("G34 X10 Z-5 F1 K0.2\n", &c).to_gcode().contains("G32 X10.000 Z-5.000 F1.0000 K0.2000\n"));
}
