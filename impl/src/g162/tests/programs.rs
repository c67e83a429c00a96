//! Hand-checked G162 (M004, `nc201`) and G32/G33/G34 (M003) examples on the whole expander:
//! the register's worked example and alarms in the check order (random cycles: `random`).
extern crate std;

use crate::tests::{expand, moves, passes};
use cycle_vocab::readings::G162Lead;
use cycle_vocab::text::Trace;
use cycle_vocab::{
    Alarm, AlarmCode, Config, Dialect, Grid, Increment, Move, MoveKind, Params, Pass, PassKind, Rule, Units,
};
use std::vec::Vec;

pub(super) fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

/// nc201 under the reading g162.lead = continuous (the reading before the letter's).
pub(crate) fn continuous() -> Config {
    let mut c = nc201();
    c.readings.g162_lead = G162Lead::Continuous;
    c
}

pub(super) fn with_params(params: Params) -> Config {
    Config { params, ..nc201() }
}

pub(super) fn depths(t: &Trace) -> Vec<i64> {
    passes(t).iter().map(|p| p.diameter_depth / 2).collect()
}

pub(super) fn threads(t: &Trace) -> Vec<Move> {
    t.moves().filter(|m| m.kind == MoveKind::Thread).copied().collect()
}

pub(super) fn alarm_of(src: &str, config: Config) -> Option<Alarm> {
    expand(src, config).alarm
}

pub(super) fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

/// The register's worked example (docs/INTERPRETATION.md, "Worked example"): six passes
/// 0.5, 1.0, 1.1, 1.15, 1.175, 1.2 with segments ① to ⑤ at H and ② at F (G162.PATH, G162.V,
/// G162.RETRACT, G162.SPLIT).
#[test]
fn worked_example() {
    let t = expand("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 V2 F1.5\n", nc201());
    assert_eq!(t.alarm, None);
    assert_eq!(depths(&t), [500, 1_000, 1_100, 1_150, 1_175, 1_200]);
    let h = 5_000_000; // 500 mm/min in 0.0001 mm
    let m = moves(&t);
    assert_eq!(
        m[..6],
        [
            Move::rapid(30_000, 5_000, Rule::PrjModal),
            Move::feed(23_000, 5_000, h, Rule::G162Path),
            Move::thread(23_000, -18_000, 15_000, 0, Rule::G162F),
            Move::feed(27_000, -20_000, h, Rule::G162V),
            Move::feed(30_000, -20_000, h, Rule::G162Retract),
            Move::feed(30_000, 5_000, h, Rule::G162Path),
        ]
    );
    let last = &m[m.len() - 5..];
    assert_eq!(last[0], Move::feed(21_600, 5_000, h, Rule::G162Path));
    assert_eq!(last[1], Move::thread(21_600, -18_000, 15_000, 0, Rule::G162F));
    assert_eq!(last[2], Move::feed(25_600, -20_000, h, Rule::G162V));
    let hs = passes(&t);
    assert!(hs.iter().all(|p| p.kind == PassKind::Rough));
    assert_eq!(hs.iter().map(|p| p.rule).collect::<Vec<_>>()[1..3], [Rule::G162Pq, Rule::G162Split]);
    assert_eq!(hs.iter().map(|p| p.index).collect::<Vec<_>>(), [1, 2, 3, 4, 5, 6]);
    // No rapid inside the cycle (G162.H).
    assert!(m[1..].iter().all(|m| m.kind != MoveKind::Rapid));
}

/// G162.SPLIT: P2.5 Q1 — 1, 2, 2.25, 2.375, 2.4375, 2.5 on ISC; 2.438 in place of 2.4375 on
/// ISB (the register: 2.4375 is off the 0.001 grid and rounds half up).
#[test]
fn manual_split_on_both_grids() {
    let src = "G0 X30 Z5\nG162 X24 Z-20 H500 P2.5 Q1 F1.5\n";
    assert_eq!(depths(&expand(src, nc201())), [1_000, 2_000, 2_250, 2_375, 2_438, 2_500]);
    let isc = Config { grid: Grid { units: Units::Metric, increment: Increment::Isc }, ..nc201() };
    assert_eq!(depths(&expand(src, isc)), [10_000, 20_000, 22_500, 23_750, 24_375, 25_000]);
    // The last pass cuts at X0 − 2P on diameter: 24 − 5 = 19.
    assert_eq!(threads(&expand(src, nc201())).last().map(|m| m.x), Some(19_000));
}

/// G162.F: the manual's cone (F1.96 written, as the manual does) threads at lead 1.96 along Z
/// (the long axis: 50 > 10), with the taper W20 on diameter over segment ②.
#[test]
fn manual_cone() {
    let t = expand(include_str!("../../../../corpus/g162_cone.nc"), nc201());
    assert_eq!(t.alarm, None);
    let th = threads(&t);
    assert!(th.iter().all(|m| m.feed == 19_600 && m.lead_change == 0));
    // Pass 1 at depth 0.4: X 20 − 0.8 = 19.2 → 39.2 at Z−50 (V = 0: no leg).
    assert_eq!((th[0].x, th[0].z), (39_200, -50_000));
    assert_eq!(crate::g162::pitch_along_long_axis(20_000, 50, 10), Some(19_612));
}

/// G162.X single pass: X is the X cut at the start; one pass of depth 0 (rule G162.X) and no leg
/// without V.
#[test]
fn single_pass() {
    let t = expand("G0 X30 Z5\nG162 X23 Z-20 H500 F1.5\n", nc201());
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t), [Pass { index: 1, kind: PassKind::Rough, diameter_depth: 0, rule: Rule::G162X }]);
    let h = 5_000_000;
    assert_eq!(
        moves(&t)[1..],
        [
            Move::feed(23_000, 5_000, h, Rule::G162Path),
            Move::thread(23_000, -20_000, 15_000, 0, Rule::G162F),
            Move::feed(30_000, -20_000, h, Rule::G162Retract),
            Move::feed(30_000, 5_000, h, Rule::G162Path),
        ]
    );
}

/// NC201.ABSINC and NC201.XMODE: G91 X and Z are distances from S; `x_radius` doubles X and W.
/// The same thread four ways gives the same trace.
#[test]
fn g91_and_x_radius() {
    let absolute = expand("G0 X30 Z5\nG162 X24 Z-20 H500 P1 Q0.4 W2 F1.5\n", nc201());
    assert_eq!(absolute.alarm, None);
    let incremental = expand("G0 X30 Z5\nG91 G162 X-6 Z-25 H500 P1 Q0.4 W2 F1.5\n", nc201());
    assert_eq!(incremental, absolute);
    let radius = with_params(Params { x_radius: Some(1), ..Params::default() });
    assert_eq!(expand("G0 X15 Z5\nG162 X12 Z-20 H500 P1 Q0.4 W1 F1.5\n", radius), absolute);
    assert_eq!(expand("G0 X15 Z5\nG91\nG162 X-3 Z-25 H500 P1 Q0.4 W1 F1.5\n", radius), absolute);
    // G91 stays modal for G00/G01; G90 restores absolute.
    let t = expand("G91 G0 X10 Z5\nG1 Z-2 F1\nX-4\nG90 X3\n", nc201());
    let ends: Vec<(i64, i64)> = t.moves().map(|m| (m.x, m.z)).collect();
    assert_eq!(ends, [(10_000, 5_000), (10_000, 3_000), (6_000, 3_000), (3_000, 3_000)]);
    // Only nc201 reads x_radius: under gsk and fanuc X stays a diameter.
    for dialect in [Dialect::Gsk, Dialect::Fanuc] {
        let cfg = Config { dialect, params: Params { x_radius: Some(1), ..Params::default() }, ..Config::default() };
        let t = expand("G0 X15 Z5\nG1 X14 F1\n", cfg);
        assert_eq!((t.alarm, moves(&t).iter().map(|m| m.x).collect::<Vec<_>>()), (None, std::vec![15_000, 14_000]), "{dialect:?}");
    }
}

/// G162.A sign rule and Z shift: σ = s·sign(A); the whole pass moves by t(d) =
/// round(d·tan|A|). External A30 shifts +Z, internal A30 −Z, A−30 mirrors both.
#[test]
fn infeed_angle_sign() {
    let first_z = |src: &str| {
        let t = expand(src, nc201());
        assert_eq!(t.alarm, None, "{src}");
        let m = moves(&t);
        (m[1].z, m[2].z, m[3].z)
    };
    // t(0.5) = round(500·tan 30°) = round(288.675) = 289.
    assert_eq!(first_z("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 V2 A30 F1.5\n"), (5_289, -17_711, -19_711));
    assert_eq!(first_z("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 V2 A-30 F1.5\n"), (4_711, -18_289, -20_289));
    assert_eq!(first_z("G0 X10 Z5\nG162 X16 Z-20 H500 P1.2 Q0.5 V2 A30 F1.5\n"), (4_711, -18_289, -20_289));
    assert_eq!(first_z("G0 X10 Z5\nG162 X16 Z-20 H500 P1.2 Q0.5 V2 A-30 F1.5\n"), (5_289, -17_711, -19_711));
    // Pass 2: t(1.0) = round(577.350) = 577; internal passes go deeper toward +X.
    let t = expand("G0 X10 Z5\nG162 X16 Z-20 H500 P1.2 Q0.5 A30 F1.5\n", nc201());
    let th = threads(&t);
    assert_eq!((th[1].x, th[1].z), (18_000, -20_577));
    // Half degrees: A29.5 → t(0.5) = round(500·tan 29.5°) = round(282.87) = 283.
    assert_eq!(first_z("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 A29.5 F1.5\n").0, 5_283);
}

/// G162.V, G162.RETRACT: the leg goes 45° outward (V on Z, 2V on diameter), the retract returns
/// to S.x; a leg as long as the thread, no side, or a path beyond S are alarms.
#[test]
fn run_out_leg_and_retract() {
    let t = expand("G0 X10 Z-2\nG162 X14 Z20 H100 P0.5 Q0.5 V1 F2\n", nc201());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    // Internal (s = −1), cutting toward +Z: ② ends at Z19, the leg toward −X by 2 on diameter.
    assert_eq!((m[1].x, m[1].z), (15_000, -2_000));
    assert_eq!((m[2].x, m[2].z), (15_000, 19_000));
    assert_eq!((m[3].x, m[3].z), (13_000, 20_000));
    assert_eq!((m[4].x, m[4].z), (10_000, 20_000));
    // A leg of V3 would end at X8, beyond S.x = 10 on the retract side.
    assert_eq!(
        alarm_of("G0 X10 Z-2\nG162 X14 Z20 H100 V3 F2\n", nc201()),
        al(AlarmCode::Geometry, b'X', Rule::G162Retract, 2)
    );
    let geo = |word, rule| al(AlarmCode::Geometry, word, rule, 2);
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z5 H500 F1\n", nc201()), geo(b'Z', Rule::G162Format));
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z-20 V25 H500 F1\n", nc201()), geo(b'V', Rule::G162V));
    assert_eq!(alarm_of("G0 X100 Z5\nG162 X24 Z-20 V24.999 H500 F1\n", nc201()), None);
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X30 Z-20 H500 F1\n", nc201()), geo(b'X', Rule::G162Retract));
    // Multi-pass leg end 24 + 6 + 2·1 = 32 beyond S.x = 30; 24 + 4 + 2 = 30 is S.x itself
    // (allowed). A single pass ends ② at X (G162.X): its leg ends at 29 + 2 = 31, or at 30.
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z-20 W6 V1 H500 P1 Q1 F1\n", nc201()), geo(b'X', Rule::G162Retract));
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z-20 W4 V1 H500 P1 Q1 F1\n", nc201()), None);
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X29 Z-20 W6 V1 H500 F1\n", nc201()), geo(b'X', Rule::G162Retract));
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X28 Z-20 W6 V1 H500 F1\n", nc201()), None);
}

/// G162.I, G162.J, G162.B under g162.lead = continuous: a shrinking pitch carries its floor
/// |I|; F ≤ |I| is constant; a growing pitch past the F maximum is GEOMETRY on I; B is the start
/// angle, B360 the zero mark. (The letter, `steps`: `super::readings`.)
#[test]
fn variable_pitch_and_start_angle() {
    let th = threads(&expand("G0 X50 Z5\nG162 X44 Z-30 H600 F3 I-0.5 J180 B90\n", continuous()));
    assert_eq!(th, [Move::variable_thread(44_000, -30_000, 30_000, 90_000, -5_000, 180_000, 5_000, Rule::G162F)]);
    let th = threads(&expand("G0 X50 Z5\nG162 X44 Z-30 H600 F0.5 I-0.5 B360\n", continuous()));
    assert_eq!(th, [Move::thread(44_000, -30_000, 5_000, 0, Rule::G162F)]);
    let th = threads(&expand("G0 X50 Z5\nG162 X44 Z-30 H600 F2 I0.01\n", continuous()));
    assert_eq!(th, [Move::variable_thread(44_000, -30_000, 20_000, 0, 100, 360_000, 0, Rule::G162F)]);
    // J without I: constant.
    let th = threads(&expand("G0 X50 Z5\nG162 X44 Z-30 H600 F2 J90\n", continuous()));
    assert_eq!(th[0].lead_change, 0);
    // Growing bound: J·F² + 360 000·I·s2 ≤ J·Fmax², s2 = 2·|ΔZ|·10 = 700 000 (ΔZ = 35 mm):
    // F = 9999 mm is already the maximum, so any growth is refused; F1 I1 grows by 1 mm/rev
    // over 35 mm to √(1 + 2·35) ≈ 8.4 mm: fine.
    let c = continuous();
    assert_eq!(
        alarm_of("G0 X50 Z5\nG162 X44 Z-30 H600 F9999 I0.0001\n", c),
        al(AlarmCode::Geometry, b'I', Rule::G162I, 2)
    );
    assert_eq!(alarm_of("G0 X50 Z5\nG162 X44 Z-30 H600 F1 I1\n", c), None);
    // The bound's edge: F = Fmax − 10 counts, I·s2·360 000 = J·(Fmax² − F²) exactly with
    // ΔZ = 1 increment (s2 = 20 counts): the end lead is exactly Fmax — accepted; ΔZ = 2 is not.
    assert_eq!(alarm_of("G0 X50 Z5\nG162 X44 Z4.999 H600 F9998.999 I9998.9995\n", c), None);
    assert_eq!(
        alarm_of("G0 X50 Z5\nG162 X44 Z4.998 H600 F9998.999 I9998.9995\n", c),
        al(AlarmCode::Geometry, b'I', Rule::G162I, 2)
    );
    // The edge with X the long axis (|Wd| = 4 mm > 2|ΔZ|: s2 = 4 000·10 = 40 000 counts), J360:
    // F = Fmax − 200 counts, I = (Fmax² − F²)/s2 = 999 899 counts exactly — accepted; I + 1 not.
    assert_eq!(alarm_of("G0 X50 Z5\nG162 X44 Z4.999 W4 H600 F9998.98 I99.9899 J360\n", c), None);
    assert_eq!(
        alarm_of("G0 X50 Z5\nG162 X44 Z4.999 W4 H600 F9998.98 I99.99 J360\n", c),
        al(AlarmCode::Geometry, b'I', Rule::G162I, 2)
    );
    // The lead at the end: L² = F² + 720 000·I·s/J never below the floor.
    let th = threads(&expand("G0 X50 Z5\nG162 X44 Z-30 H600 F1 I1\n", c));
    assert_eq!((th[0].feed, th[0].lead_change, th[0].lead_change_angle), (10_000, 10_000, 360_000));
}

/// G162.F: F omitted → the modal feed, even one set for mm/min (G01 F100 → 100 mm/rev); H does
/// not set the modal feed; F in G162 does.
#[test]
fn modal_feed_as_lead() {
    let t = expand("G0 X30 Z5\nG1 X30 Z4 F100\nG162 X24 Z-20 H500\n", nc201());
    assert_eq!(threads(&t)[0].feed, 1_000_000);
    let t = expand("G0 X30 Z5\nG162 X24 Z-20 H500 F2\nG1 X29\n", nc201());
    assert_eq!(t.moves().last().map(|m| m.feed), Some(20_000));
    assert_eq!(
        alarm_of("G0 X30 Z5\nG162 X24 Z-20 H500 F2\nG162 X24 Z-20 F2\nG162 X24 Z-20 H1\nG1 Z3\n", nc201()),
        al(AlarmCode::MissingWord, b'H', Rule::G162H, 3)
    );
    // The modal feed carries to the next G162 (no F, no alarm).
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z-20 H500 F2\nG162 X24 Z-20 H500\n", nc201()), None);
}

/// The check order of a G162 block: codes and conflicts, allowed words, values alphabetically,
/// missing words (F, H, P/Q, X, Z), then the cycle's checks; every alarm names its word and rule.
#[test]
fn g162_check_order() {
    let c = nc201();
    let cases: &[(&str, Option<Alarm>)] = &[
        ("G162 X1 Z1 H1 F1 G0", al(AlarmCode::Conflict, b'G', Rule::PrjWord, 1)),
        ("G90 G91 G0 X1", al(AlarmCode::Conflict, b'G', Rule::Nc201AbsInc, 1)),
        ("G91 G91 X1", al(AlarmCode::Conflict, b'G', Rule::Nc201AbsInc, 1)),
        ("G90 G91 M1.5", al(AlarmCode::NotInteger, b'M', Rule::ComRanges, 1)),
        ("G162 X1 Z1 H1 F1 U1", al(AlarmCode::WordNotAllowed, b'U', Rule::PrjWord, 1)),
        ("G1 X1 U1 F1", al(AlarmCode::WordNotAllowed, b'U', Rule::PrjWord, 1)),
        ("G1 X1 F1 I1", al(AlarmCode::WordNotAllowed, b'I', Rule::PrjWord, 1)),
        ("G92 X1 Z1 F1", al(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, 1)),
        ("G34 X1 Z1 F1 K1", al(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, 1)),
        ("G76 X1 Z1 P1 Q1 F1", al(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, 1)),
        // G162.A: any tenth is legal (A27.3: `super::readings`); a second decimal is
        // PRECISION under G162.A.
        ("G162 X1 Z-1 H1 F1 A27.35", al(AlarmCode::Precision, b'A', Rule::G162A, 1)),
        ("G162 X1 Z-1 H1 F1 A27.25", al(AlarmCode::Precision, b'A', Rule::G162A, 1)),
        ("G162 X1 Z-1 H1 F1 A-89.5", al(AlarmCode::OutOfRange, b'A', Rule::G162A, 1)),
        ("G162 X1 Z-1 H1 F1 B360.001", al(AlarmCode::OutOfRange, b'B', Rule::G162B, 1)),
        ("G162 X1 Z-1 H1 F1 B-1", al(AlarmCode::OutOfRange, b'B', Rule::G162B, 1)),
        ("G162 X1 Z-1 H0 F1", al(AlarmCode::OutOfRange, b'H', Rule::G162H, 1)),
        ("G162 X1 Z-1 H100000 F1", al(AlarmCode::OutOfRange, b'H', Rule::G162H, 1)),
        ("G162 X1 Z-1 H1 F1 I-9999.0001", al(AlarmCode::OutOfRange, b'I', Rule::G162I, 1)),
        ("G162 X1 Z-1 H1 F1 J0", al(AlarmCode::OutOfRange, b'J', Rule::G162J, 1)),
        ("G162 X1 Z-1 H1 F1 P0 Q1", al(AlarmCode::OutOfRange, b'P', Rule::ComRanges, 1)),
        ("G162 X1 Z-1 H1 F1 V-1", al(AlarmCode::OutOfRange, b'V', Rule::ComRanges, 1)),
        // Values alphabetically: A before B.
        ("G162 X1 Z-1 H1 F1 A90 B400", al(AlarmCode::OutOfRange, b'A', Rule::G162A, 1)),
        // Missing words: F, H, P/Q, X, Z.
        ("G162 P1", al(AlarmCode::MissingWord, b'F', Rule::G162F, 1)),
        ("G162 F1 P1", al(AlarmCode::MissingWord, b'H', Rule::G162H, 1)),
        ("G162 F1 H1 Q1", al(AlarmCode::MissingWord, b'P', Rule::G162Pq, 1)),
        ("G162 F1 H1 P1", al(AlarmCode::MissingWord, b'Q', Rule::G162Pq, 1)),
        ("G162 F1 H1 Z1", al(AlarmCode::MissingWord, b'X', Rule::G162Format, 1)),
        ("G162 F1 H1 X1", al(AlarmCode::MissingWord, b'Z', Rule::G162Format, 1)),
        // Z with W and F with I are legal together under nc201.
        ("G0 X5\nG162 X1 Z-1 W0.5 H1 F1 I0.1", None),
    ];
    for (src, expect) in cases {
        assert_eq!(alarm_of(src, c), *expect, "{src}");
    }
    // G162 under gsk and fanuc; G90/G91 there stay unsupported.
    for dialect in [Dialect::Gsk, Dialect::Fanuc] {
        let c = Config { dialect, ..Config::default() };
        assert_eq!(alarm_of("G162 X1 Z1 H1 F1", c), al(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, 1));
        assert_eq!(alarm_of("G91 X1", c), al(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, 1));
    }
    // PRJ.MAXPASS before any motion of the cycle: P2.5 Q1 is six passes.
    let two = with_params(Params { max_passes: Some(5), ..Params::default() });
    let t = expand("G0 X30 Z5\nG162 X24 Z-20 H500 P2.5 Q1 F1.5\n", two);
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass, 2));
    assert_eq!(t.events.len(), 1);
    let six = with_params(Params { max_passes: Some(6), ..Params::default() });
    assert_eq!(alarm_of("G0 X30 Z5\nG162 X24 Z-20 H500 P2.5 Q1 F1.5\n", six), None);
    // NC201.XMODE: x_radius is range-checked under every dialect.
    for dialect in [Dialect::Gsk, Dialect::Nc201] {
        let bad = Config { dialect, params: Params { x_radius: Some(2), ..Params::default() }, ..Config::default() };
        assert_eq!(alarm_of("G0 X1\n", bad), Some(Alarm::new(AlarmCode::OutOfRange, None, Rule::Nc201XMode, 0)));
    }
}

/// G32, G33, G34 (M003): modal thread moves, P not kept, K required, the G34 lead bound.
#[test]
fn thread_moves() {
    let c = Config::default();
    let t = expand(include_str!("../../../../tests/programs/g32_g33_g34.nc"), c);
    assert_eq!(t.alarm, None);
    let th = threads(&t);
    assert_eq!(th[0], Move::thread(30_000, -20_000, 20_000, 0, Rule::G32));
    assert_eq!(th[1], Move::thread(30_000, -20_000, 40_000, 0, Rule::G33));
    assert_eq!(th[2], Move::thread(30_000, -20_000, 40_000, 180_000, Rule::G33));
    assert_eq!(th[3], Move::variable_thread(29_000, -20_000, 20_000, 0, 500, 360_000, 0, Rule::G34));
    // The modal repeat W-2 with its own K.
    assert_eq!(th[4], Move::variable_thread(29_000, -22_000, 20_000, 0, 500, 360_000, 0, Rule::G34));
    // G32 is modal; a block without axis words only sets the feed; G33 P is not kept.
    let t = expand("G32 Z-5 F1\nF2\nZ-9\nG33 Z-12 P90000\nZ-15\n", c);
    let th = threads(&t);
    assert_eq!(
        th.iter().map(|m| (m.z, m.feed, m.angle, m.rule)).collect::<Vec<_>>(),
        [
            (-5_000, 10_000, 0, Rule::G32),
            (-9_000, 20_000, 0, Rule::G32),
            (-12_000, 20_000, 90_000, Rule::G33),
            (-15_000, 20_000, 0, Rule::G33),
        ]
    );
    // Inch: I is threads per inch.
    let inch = Config { grid: Grid { units: Units::Inch, increment: Increment::Isb }, ..c };
    assert_eq!(threads(&expand("G32 W-1 I20\n", inch))[0].feed, 5_000);
    let cases: &[(&str, Option<Alarm>)] = &[
        ("G32 Z-5", al(AlarmCode::MissingWord, b'F', Rule::ComLead, 1)),
        ("G34 Z-5 F1", al(AlarmCode::MissingWord, b'K', Rule::G34, 1)),
        ("G34 Z-5 F1 K0.1\nZ-6", al(AlarmCode::MissingWord, b'K', Rule::G34, 2)),
        ("G33 Z-5 F1 P360000", al(AlarmCode::OutOfRange, b'P', Rule::G33, 1)),
        ("G33 Z-5 F1 P1.5", al(AlarmCode::NotInteger, b'P', Rule::ComRanges, 1)),
        ("G32 Z-5 F1 P1", al(AlarmCode::WordNotAllowed, b'P', Rule::PrjWord, 1)),
        ("G32 Z-5 F1 K1", al(AlarmCode::WordNotAllowed, b'K', Rule::PrjWord, 1)),
        ("G34 Z-5 F1 K10000", al(AlarmCode::OutOfRange, b'K', Rule::G34, 1)),
        ("G32 X1 U1 F1", al(AlarmCode::Conflict, b'U', Rule::ComAbsInc, 1)),
        // 2 mm shrinking 0.1 mm/rev reaches 0 after 20 mm of Z: F² + K·s2 = 0.
        ("G34 Z-20 F2 K-0.1", al(AlarmCode::Geometry, b'K', Rule::G34, 1)),
        ("G34 Z-19.999 F2 K-0.1", None),
        // A face thread is legal; a move to the current position is not emitted.
        ("G32 X10 F1", None),
        ("G34 Z0 F1 K-5", None),
        // I0.0001 is a lead of 254 000 mm, above Fmax (9 999 mm): bounded only when K > 0.
        ("G34 W-1 I0.0001 K0", None),
        ("G34 W-1 I0.0001 K-0.1", None),
        ("G34 W-1 I0.0001 K0.0001", al(AlarmCode::Geometry, b'K', Rule::G34, 1)),
    ];
    for (src, expect) in cases {
        assert_eq!(alarm_of(src, c), *expect, "{src}");
    }
    assert!(expand("G34 Z0 F1 K-5", c).events.is_empty());
    // G32 ends a G92 run: the next G92 starts a new run (R and end point reset).
    let t = expand("G0 X40 Z5\nG92 X30 Z-10 F1 R-1\nG32 X40 Z5\nG92 X30 Z-10\n", c);
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(p.iter().map(|p| (p.index, p.diameter_depth)).collect::<Vec<_>>(), [(1, 12_000), (1, 10_000)]);
}
