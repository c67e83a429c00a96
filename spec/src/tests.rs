//! Hand-checked examples from the manuals' formulas, alarms, and robustness.

use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Event, Move, MoveKind, PassKind, Rule};

fn run(src: &str) -> Trace {
    expand(src.as_bytes(), &Config::default())
}

fn moves(t: &Trace) -> Vec<(MoveKind, i64, i64)> {
    t.moves().map(|m| (m.kind, m.x, m.z)).collect()
}

fn passes(t: &Trace) -> Vec<(u32, PassKind, i64, Rule)> {
    t.events
        .iter()
        .filter_map(|e| match e {
            Event::Pass(p) => Some((p.index, p.kind, p.diameter_depth, p.rule)),
            _ => None,
        })
        .collect()
}

/// G92.EXAMPLE (M002): four cycles from X65 Z5; each: rapid X to C, thread to Z−27 (K1 before
/// the end), pull-out to X(cut + 6) Z−28 (J3 radius), rapid X65, rapid Z5.
#[test]
fn g92_example() {
    let t = run(include_str!("../../corpus/g92_example.nc"));
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    use MoveKind::*;
    let mut expect = vec![(Rapid, 150_000, 50_000), (Rapid, 65_000, 5_000)];
    for x in [58_700, 57_700, 57_000, 56_900] {
        expect.extend([
            (Rapid, x, 5_000),
            (Thread, x, -27_000),
            (Thread, x + 6_000, -28_000),
            (Rapid, 65_000, -28_000),
            (Rapid, 65_000, 5_000),
        ]);
    }
    assert_eq!(m, expect);
    let p = passes(&t);
    let depths: Vec<i64> = p.iter().map(|p| p.2).collect();
    assert_eq!(depths, vec![6_300, 7_300, 8_000, 8_100]);
    assert_eq!(p.iter().map(|p| p.0).collect::<Vec<_>>(), vec![1, 2, 3, 4]);
    for mv in t.moves().filter(|m| m.kind == Thread) {
        assert_eq!(mv.feed, 30_000);
    }
    let pull: Vec<Rule> = t.moves().filter(|m| m.kind == Thread).map(|m| m.rule).collect();
    assert_eq!(pull[1], Rule::G92Pullout);
    assert!(t.to_gcode().contains("(PASS 1 ROUGH DEPTH 3.150)\nG00 X58.700 Z5.000\nG32 X58.700 Z-27.000 F3.0000\nG32 X64.700 Z-28.000 F3.0000\n"));
}

/// G76.EXAMPLE (M001): depths 1.8, 2.5 (k − d), FINISH 3, SPRING 3; X 62.4, 61.0, 60.0, 60.0;
/// Z = 10 − round(δ·tan 22.5°); pull-out J1.5 K2.
#[test]
fn g76_example() {
    let t = run(include_str!("../../corpus/g76_example.nc"));
    assert_eq!(t.alarm, None);
    assert_eq!(
        passes(&t),
        vec![
            (1, PassKind::Rough, 3_600, Rule::G76Depth1),
            (2, PassKind::Rough, 5_000, Rule::G76DepthLast),
            (3, PassKind::Finish, 6_000, Rule::G76Finish),
            (4, PassKind::Spring, 6_000, Rule::G76Finish),
        ]
    );
    use MoveKind::*;
    let m = moves(&t);
    // t(1.8) = 0.746, t(2.5) = 1.036 = t(T)
    let pass = |x: i64, z: i64| {
        vec![
            (Rapid, x, z),
            (Thread, x, z - 70_000 + 2_000),
            (Thread, x + 3_000, z - 70_000),
            (Rapid, 80_000, z - 70_000),
            (Rapid, 80_000, 10_000),
        ]
    };
    let mut expect = vec![(Rapid, 80_000, 10_000)];
    expect.extend(pass(62_400, 10_000 - 746));
    expect.extend(pass(61_000, 10_000 - 1_036));
    expect.extend(pass(60_000, 10_000 - 1_036));
    expect.extend(pass(60_000, 10_000 - 1_036));
    assert_eq!(m, expect);
    assert!(t.moves().filter(|m| m.kind == Thread).all(|m| m.feed == 3_000_000));
}

const F76_DEPTHS: [i64; 11] = [700, 990, 1_212, 1_400, 1_565, 1_715, 1_852, 1_980, 2_100, 2_214, 2_300];

fn check_f76_ex1(t: &Trace) {
    assert_eq!(t.alarm, None);
    let p = passes(t);
    assert_eq!(p.len(), 12);
    for (n, d) in F76_DEPTHS.iter().enumerate() {
        assert_eq!((p[n].0, p[n].1, p[n].2), (n as u32 + 1, PassKind::Rough, 2 * d));
    }
    assert_eq!((p[11].0, p[11].1, p[11].2), (12, PassKind::Finish, 4_800));
    // r = 10 tenths of the 4 mm lead: K = 4, J = 4·tan 45° = 4 (radius).
    let first: Vec<_> = moves(t).into_iter().skip(1).take(5).collect();
    // t(0.7) = round(0.7·tan 30°) = 0.404
    use MoveKind::*;
    let x1 = 33_800 + 2 * (2_400 - 700);
    assert_eq!(
        first,
        vec![
            (Rapid, x1, 10_000 - 404),
            (Thread, x1, 10_000 - 404 - 70_000 + 4_000),
            (Thread, x1 + 8_000, 10_000 - 404 - 70_000),
            (Rapid, 60_000, 10_000 - 404 - 70_000),
            (Rapid, 60_000, 10_000),
        ]
    );
}

/// F76.EX1 (M003): eleven rough passes and one FINISH at 2.4, in mm and in the micron form.
#[test]
fn f76_ex1_both_forms() {
    let mm = run(include_str!("../../corpus/f76_ex1.nc"));
    check_f76_ex1(&mm);
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    let microns = expand(include_str!("../../corpus/f76_ex1_microns.nc").as_bytes(), &fanuc);
    check_f76_ex1(&microns);
    assert_eq!(mm, microns);
    let mm_fanuc = expand(include_str!("../../corpus/f76_ex1.nc").as_bytes(), &fanuc);
    assert_eq!(mm_fanuc, mm);
}

/// F76.EX2 runs (3 finishing passes: FINISH, SPRING, SPRING).
#[test]
fn f76_ex2() {
    let t = run(include_str!("../../corpus/f76_ex2.nc"));
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    let kinds: Vec<PassKind> = p.iter().rev().take(3).map(|p| p.1).collect();
    assert_eq!(kinds, vec![PassKind::Spring, PassKind::Spring, PassKind::Finish]);
    assert!(p.iter().rev().take(3).all(|p| p.2 == 5_000));
}

/// G78.EXAMPLE (M000): mode 05 is out of range: alarm on P, G78.MODE, line 3, after the G00.
#[test]
fn g78_example_alarm() {
    let t = run(include_str!("../../corpus/g78_example.nc"));
    assert_eq!(t.alarm, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'P'), Rule::G78Mode, 3)));
    assert_eq!(moves(&t), vec![(MoveKind::Rapid, 80_000, 10_000)]);
}

#[test]
fn g78_modes_run() {
    for mode in 0..5 {
        for d in 0..2 {
            let src = format!("G0 X80 Z10\nG78 P02{mode:02}60 Q0.15 R0.5 D{d}\nG78 X60 Z-60 P3 Q0.6 F2\n");
            let t = run(&src);
            assert_eq!(t.alarm, None, "{src}");
            // every mode ends its last rough pass at A.z + σ·t(T)
            let p = passes(&t);
            assert!(p.len() >= 3);
        }
    }
    let t = run("G0 X80 Z10\nG78 P020060 Q0.15 R0.5 D0\nG78 X60 Z-60 P3 Q0.6 F2\n");
    let depths: Vec<i64> = passes(&t).iter().map(|p| p.2 / 2).collect();
    assert_eq!(depths, vec![600, 1_200, 1_800, 2_400, 2_500, 3_000, 3_000]);
}

#[test]
fn alarms() {
    let missing_p = run("G0 X80 Z10\nG76 X60 Z-60 Q1.8 F3\n");
    assert_eq!(missing_p.alarm, Some(Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 2)));
    let missing_q = run("G0 X80 Z10\nG76 X60 Z-60 P3 F3\n");
    assert_eq!(missing_q.alarm, Some(Alarm::new(AlarmCode::MissingWord, Some(b'Q'), Rule::G76Required, 2)));
    let missing_f = run("G0 X80 Z10\nG76 X60 Z-60 P3 Q1\n");
    assert_eq!(missing_f.alarm, Some(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 2)));
    let missing_f92 = run("G0 X65 Z5\nG92 X58.7 Z-28\n");
    assert_eq!(missing_f92.alarm, Some(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 2)));
    let range = run("G0 X1000000\n");
    assert_eq!(range.alarm, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'X'), Rule::ComRanges, 1)));
    let precision = run("G0 X58.7001\n");
    assert_eq!(precision.alarm, Some(Alarm::new(AlarmCode::Precision, Some(b'X'), Rule::ComUnits, 1)));
    let g = run("G0 X1\nG65 X5\n");
    assert_eq!(g.alarm, Some(Alarm::new(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 2)));
    assert_eq!(g.events.len(), 1);
    let conflict = run("G0 G1 X1\n");
    assert_eq!(conflict.alarm, Some(Alarm::new(AlarmCode::Conflict, Some(b'G'), Rule::PrjWord, 1)));
    let xu = run("G0 X1 U1\n");
    assert_eq!(xu.alarm, Some(Alarm::new(AlarmCode::Conflict, Some(b'U'), Rule::ComAbsInc, 1)));
    let notallowed = run("G0 X1 R2\n");
    assert_eq!(notallowed.alarm, Some(Alarm::new(AlarmCode::WordNotAllowed, Some(b'R'), Rule::PrjWord, 1)));
    let g01 = run("G1 X1\n");
    assert_eq!(g01.alarm, Some(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 1)));
    let face = run("G0 X65 Z5\nG92 X58.7 F3\n");
    assert_eq!(face.alarm, Some(Alarm::new(AlarmCode::Geometry, Some(b'Z'), Rule::G92Format, 2)));
    let taper = run("G0 X65 Z5\nG92 X58.7 Z-28 R4 F3\n");
    assert_eq!(taper.alarm, Some(Alarm::new(AlarmCode::Geometry, Some(b'R'), Rule::G92Taper, 2)));
    let d_ge_k = run("G0 X80 Z10\nG76 P010060 R3\nG76 X60 Z-60 P3 Q1 F3\n");
    assert_eq!(d_ge_k.alarm, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'R'), Rule::G76DepthLast, 3)));
    let m0 = run("G76 P000060\n");
    assert_eq!(m0.alarm, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'P'), Rule::G76Finish, 1)));
    let e3 = run("G76 P010060 D3\n");
    assert_eq!(e3.alarm, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'D'), Rule::G76Mode, 1)));
    let many = run("G0 X80 Z10\nG76 P010060 Q0 R0\nG76 X60 Z-60 P9 Q0.001 F3\n");
    assert_eq!(many.alarm, Some(Alarm::new(AlarmCode::TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, 3)));
    assert_eq!(many.events.len(), 1);
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    let g78 = expand(b"G78 P010060\n", &fanuc);
    assert_eq!(g78.alarm, Some(Alarm::new(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjDialect, 1)));
    let angle = expand(b"G76 P010045\n", &fanuc);
    assert_eq!(angle.alarm, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'P'), Rule::F76Format, 1)));
    let e = expand(b"G76 P010060 E1\n", &fanuc);
    assert_eq!(e.alarm, Some(Alarm::new(AlarmCode::WordNotAllowed, Some(b'E'), Rule::F76Format, 1)));
}

#[test]
fn program_end_and_modal_rules() {
    // M30 ends the program: the bad byte after it is never read.
    let t = run("G0 X1 M30\nG0 X2 #\n");
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t), vec![(MoveKind::Rapid, 1_000, 0)]);
    // PRJ.NOOP: a move to the current position is not emitted.
    let t = run("G0 X0 Z0\nG1 X1 F0.2\nX1\n");
    assert_eq!(t.events, vec![Event::Move(Move::feed(1_000, 0, 2_000, Rule::PrjModal))]);
    // G92 modal run keeps Z and R; a new run starts at R 0.
    let t = run("G0 X65 Z5\nG92 X58 Z-20 R-1 F2 J0\nX57\nG0 X65\nG92 X57 Z-20\n");
    assert_eq!(t.alarm, None);
    let threads: Vec<(i64, i64)> = t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z)).collect();
    assert_eq!(threads, vec![(58_000, -20_000), (57_000, -20_000), (57_000, -20_000)]);
    let rapids_to_c: Vec<i64> = passes(&t).iter().map(|p| p.2).collect();
    assert_eq!(rapids_to_c, vec![9_000, 10_000, 8_000]);
}

#[test]
fn multistart_angles() {
    let t = run("G0 X65 Z5\nG92 X58 Z-20 F2 L3\n");
    let angles: Vec<u32> = t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| m.angle).collect();
    assert_eq!(angles, vec![0, 0, 120_000, 120_000, 240_000, 240_000]);
}

/// Random bytes and random word soups never panic.
#[test]
fn random_input_never_panics() {
    let mut s = 0x1234_5678_9abc_def0u64;
    let mut next = || {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        s
    };
    let alphabet = b"GXZUWRPQFIJKLDEMN0123456789.-  \n;";
    let configs = [
        Config::default(),
        Config { dialect: Dialect::Fanuc, ..Config::default() },
        Config { start_x: i64::MAX, start_z: i64::MIN, ..Config::default() },
    ];
    for round in 0..600 {
        let len = (next() % 120) as usize;
        let bytes: Vec<u8> = if round % 3 == 0 {
            (0..len).map(|_| next() as u8).collect()
        } else {
            (0..len).map(|_| alphabet[(next() % alphabet.len() as u64) as usize]).collect()
        };
        for c in &configs {
            let _ = expand(&bytes, c);
        }
    }
    let mut wild = Config::default();
    wild.params.p5131_chamfer_angle = Some(90);
    wild.params.max_passes = Some((u32::MAX) as i64);
    wild.params.p5140_min_cut = Some(-5);
    wild.params.no19_pullout = Some(9_999);
    for src in ["G0 X80 Z10\nG76 X60 Z-60 P3 Q1 F3\n", "G0 X65 Z5\nG92 X58 Z-20 F2\n"] {
        assert!(expand(src.as_bytes(), &wild).alarm.is_some());
    }
}

/// COM.UNITS, COM.LEAD on the other grids: inch ISC lengths with 5 decimals, I as threads per
/// inch, metric ISC.
#[test]
fn other_grids() {
    use cycle_vocab::{Grid, Increment, Units};
    let inch = Config { grid: Grid { units: Units::Inch, increment: Increment::Isc }, ..Config::default() };
    let t = expand(b"G20\nG0 X2.5 Z0.2\nG92 X2.3 Z-1 I20 J0\n", &inch);
    assert_eq!(t.alarm, None);
    let th: Vec<&Move> = t.moves().filter(|m| m.kind == MoveKind::Thread).collect();
    assert_eq!((th[0].x, th[0].z, th[0].feed), (230_000, -100_000, 5_000)); // 1/20 in
    let metric_isc = Config { grid: Grid { units: Units::Metric, increment: Increment::Isc }, ..Config::default() };
    let t = expand(b"G0 X65 Z5\nG92 X58.7001 Z-28 F3\n", &metric_isc);
    assert_eq!(t.alarm, None);
    // No.19 = 10: pull-out one lead (3 mm) on both axes.
    let th: Vec<(i64, i64)> = t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z)).collect();
    assert_eq!(th, vec![(587_001, -250_000), (587_001 + 60_000, -280_000)]);
    let units = expand(b"G20\n", &Config::default());
    assert_eq!(units.alarm, Some(Alarm::new(AlarmCode::Unsupported, Some(b'G'), Rule::ComUnits, 1)));
}

/// G76 internal thread (s = −1) with lead-in E: Z shifts +, X grows with depth.
#[test]
fn g76_internal_with_leadin() {
    let t = run("G0 X20 Z5\nG76 P011060 Q0.1 R0.1 E1\nG76 X26 Z-20 P1.2 Q0.5 F2 R-0.5\n");
    assert_eq!(t.alarm, None);
    let m: Vec<(MoveKind, i64, i64, Rule)> = t.moves().skip(1).take(6).map(|m| (m.kind, m.x, m.z, m.rule)).collect();
    // C.x = 26 − 1 = 25; δ 0.5 → X 25 − 2·0.7 = 23.6; Z = 5 + round(0.5·tan 30°) = 5.289;
    // chamfer r 10 → K 2, J 2 (45°); En = (24.6, −19.711); pull-out start X = En.x + 2·round(−0.5·2/25).
    assert_eq!(
        m,
        vec![
            (MoveKind::Rapid, 21_600, 5_289, Rule::G76LeadIn),
            (MoveKind::Thread, 23_600, 5_289, Rule::G76LeadIn),
            (MoveKind::Thread, 24_600 - 80, -17_711, Rule::G76Path),
            (MoveKind::Thread, 24_600 - 4_000, -19_711, Rule::G76Pullout),
            (MoveKind::Rapid, 20_000, -19_711, Rule::G76Path),
            (MoveKind::Rapid, 20_000, 5_000, Rule::G76Path),
        ]
    );
}

/// PRJ.MAXPASS at the largest legal bound stays fast: the count is found by iterating the
/// schedule at most max_passes + 1 times, before any motion.
#[test]
fn max_passes_bound_is_cheap() {
    let mut c = Config::default();
    c.params.max_passes = Some(1_000_000);
    let t = expand(b"G0 X200 Z10\nG76 P010060 Q0 R0\nG76 X60 Z-60 P50 Q0.001 F3\n", &c);
    assert_eq!(t.alarm, Some(Alarm::new(AlarmCode::TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, 3)));
    assert_eq!(t.events.len(), 1);
}

// The crate's tests by subject; `util` is what they share.
mod arc;
mod contour;
mod g162;
mod g71;
mod g73;
mod g74;
mod g76_edges;
mod g83;
mod g90;
mod lex;
mod m003_words;
mod operator;
mod operator_cycles;
mod props;
mod shared;
mod spindle;
mod sub;
mod threads_a;
mod util;
