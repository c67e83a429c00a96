//! Hand-checked examples from the manuals and the register, on the whole expander.
extern crate std;

use crate::Expander;
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Dialect, Grid, Increment, Units};
use std::string::String;

pub fn expand(program: &str, config: Config) -> Trace {
    Trace::collect(config.grid, Expander::new(program.as_bytes(), config))
}

pub fn gcode(program: &str, config: Config) -> String {
    expand(program, config).to_gcode()
}

pub fn fanuc() -> Config {
    Config { dialect: Dialect::Fanuc, ..Config::default() }
}

pub fn inch() -> Config {
    Config { grid: Grid { units: Units::Inch, increment: Increment::Isb }, ..Config::default() }
}

/// Every example program expands without an alarm (the G78 example excepted, see
/// `g78_example_alarm`); `--nocapture` prints the traces for review.
#[test]
fn corpus_and_programs_expand() {
    for (name, src, cfg) in [
        ("g92", include_str!("../../corpus/g92_example.nc"), Config::default()),
        ("g76", include_str!("../../corpus/g76_example.nc"), Config::default()),
        ("g78", include_str!("../../corpus/g78_example.nc"), Config::default()),
        ("f76_ex1", include_str!("../../corpus/f76_ex1.nc"), Config::default()),
        ("f76_ex1_microns", include_str!("../../corpus/f76_ex1_microns.nc"), fanuc()),
        ("f76_ex2", include_str!("../../corpus/f76_ex2.nc"), Config::default()),
        ("g92_inch", include_str!("../../tests/programs/g92_inch.nc"), inch()),
        ("g76_multistart", include_str!("../../tests/programs/g76_multistart.nc"), Config::default()),
        ("g76_mode0", include_str!("../../tests/programs/g76_mode0.nc"), Config::default()),
        ("g76_mode1", include_str!("../../tests/programs/g76_mode1.nc"), Config::default()),
        ("g76_mode2", include_str!("../../tests/programs/g76_mode2.nc"), Config::default()),
        ("g78_mode0", include_str!("../../tests/programs/g78_mode0.nc"), Config::default()),
        ("g78_mode1", include_str!("../../tests/programs/g78_mode1.nc"), Config::default()),
        ("g78_mode2", include_str!("../../tests/programs/g78_mode2.nc"), Config::default()),
        ("g78_mode3", include_str!("../../tests/programs/g78_mode3.nc"), Config::default()),
        ("g78_mode4", include_str!("../../tests/programs/g78_mode4.nc"), Config::default()),
        ("g92_internal", include_str!("../../tests/programs/g92_internal.nc"), Config::default()),
        ("g92_taper", include_str!("../../tests/programs/g92_taper.nc"), Config::default()),
        ("g92_multistart", include_str!("../../tests/programs/g92_multistart.nc"), Config::default()),
        ("g76_internal", include_str!("../../tests/programs/g76_internal.nc"), Config::default()),
        ("g76_taper", include_str!("../../tests/programs/g76_taper.nc"), Config::default()),
        ("g76_inch", include_str!("../../tests/programs/g76_inch.nc"), inch()),
        ("g78_constant", include_str!("../../tests/programs/g78_constant.nc"), Config::default()),
    ] {
        let t = expand(src, cfg);
        assert_eq!(t.alarm.is_some(), name == "g78", "{name}");
        std::println!("== {name}\n{}", gcode(src, cfg));
    }
}

use cycle_vocab::{Alarm, AlarmCode, Event, Move, MoveKind, Params, Pass, PassKind, Rule};
use std::vec::Vec;

fn alarm(code: AlarmCode, word: Option<u8>, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, word, rule, line))
}

pub fn moves(t: &Trace) -> Vec<Move> {
    t.moves().copied().collect()
}

/// The Z of the first move of every pass (where each pass starts its cut).
pub fn pass_start_z(t: &Trace) -> Vec<i64> {
    t.events
        .windows(2)
        .filter_map(|w| match w {
            [Event::Pass(_), Event::Move(m)] => Some(m.z),
            _ => None,
        })
        .collect()
}

pub fn passes(t: &Trace) -> Vec<Pass> {
    t.events
        .iter()
        .filter_map(|e| match e {
            Event::Pass(p) => Some(*p),
            _ => None,
        })
        .collect()
}

fn threads(t: &Trace) -> Vec<(i64, i64)> {
    t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z)).collect()
}

/// G92.EXAMPLE: four cycles at X58.7, X57.7, X57, X56.9 to Z-27, pull-out J3 K1 to
/// (x + 6 mm on diameter, Z-28), lead 3 mm, back to X65 Z5 each time (G92.PATH, G92.PULLOUT,
/// G92.MODAL).
#[test]
fn g92_example() {
    let t = expand(include_str!("../../corpus/g92_example.nc"), Config::default());
    assert_eq!(t.alarm, None);
    let mut expect = std::vec![
        Move::rapid(150_000, 50_000, Rule::PrjModal),
        Move::rapid(65_000, 5_000, Rule::PrjModal),
    ];
    for x in [58_700, 57_700, 57_000, 56_900] {
        expect.push(Move::rapid(x, 5_000, Rule::G92Path));
        expect.push(Move::thread(x, -27_000, 30_000, 0, Rule::G92Path));
        expect.push(Move::thread(x + 6_000, -28_000, 30_000, 0, Rule::G92Pullout));
        expect.push(Move::rapid(65_000, -28_000, Rule::G92Path));
        expect.push(Move::rapid(65_000, 5_000, Rule::G92Path));
    }
    assert_eq!(moves(&t), expect);
    let p = passes(&t);
    assert_eq!(p.iter().map(|p| p.index).collect::<Vec<_>>(), [1, 2, 3, 4]);
    assert_eq!(p.iter().map(|p| p.diameter_depth).collect::<Vec<_>>(), [6_300, 7_300, 8_000, 8_100]);
    assert!(p.iter().all(|p| p.kind == PassKind::Rough));
    // The header precedes the cycle's moves.
    assert!(matches!(t.events[2], Event::Pass(Pass { index: 1, .. })));
}

/// F76.EX1: rough radius depths 0.7·√n (n = 1…10), then k − d = 2.3, then one finish at 2.4:
/// twelve passes; the finishing pass cuts at the minor diameter X33.8 (G76.DEPTH.1,
/// G76.DEPTH.LAST, G76.FINISH). The micron form (F76.MICRONS) gives the same trace.
#[test]
fn f76_ex1() {
    let t = expand(include_str!("../../corpus/f76_ex1.nc"), Config::default());
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    let depths: Vec<i64> = p.iter().map(|p| p.diameter_depth / 2).collect();
    assert_eq!(depths, [700, 990, 1212, 1400, 1565, 1715, 1852, 1980, 2100, 2214, 2300, 2400]);
    assert_eq!(p.iter().map(|p| p.index).collect::<Vec<_>>(), (1..=12).collect::<Vec<u32>>());
    assert_eq!(p[11].kind, PassKind::Finish);
    assert_eq!(p[10].rule, Rule::G76DepthLast);
    assert!(p[..11].iter().all(|p| p.kind == PassKind::Rough));
    // Pass 1: X = 33.8 + 2·(2.4 − 0.7) = 37.2; Z = 10 − round(0.7·tan 30°) = 10 − 0.404.
    assert_eq!(t.moves().nth(1).map(|m| (m.kind, m.x, m.z)), Some((MoveKind::Rapid, 37_200, 9_596)));
    // The finishing cut at X33.8, at the Z of the last rough pass: 10 − round(2.3·tan 30°).
    let th = threads(&t);
    assert_eq!(th[th.len() - 2], (33_800, 8_672 - 70_000 + 4_000));
    // Chamfer r = 10 tenths of F4 = 4 mm, 5131 = 45°: J = K = 4 mm.
    assert_eq!(th[th.len() - 1], (33_800 + 8_000, 8_672 - 70_000));
    let micro = expand(include_str!("../../corpus/f76_ex1_microns.nc"), fanuc());
    assert_eq!(micro.events, t.events);
    assert_eq!(micro.alarm, None);
}

/// F76.EX2: three finishing passes (FINISH, SPRING, SPRING) at k = 2.5, chamfer 0.8 lead.
#[test]
fn f76_ex2() {
    let t = expand(include_str!("../../corpus/f76_ex2.nc"), Config::default());
    let p = passes(&t);
    let kinds: Vec<PassKind> = p.iter().map(|p| p.kind).collect();
    assert_eq!(kinds[kinds.len() - 3..], [PassKind::Finish, PassKind::Spring, PassKind::Spring]);
    assert_eq!(p.iter().map(|p| p.diameter_depth / 2).collect::<Vec<_>>(), [1000, 1414, 1732, 2000, 2236, 2300, 2500, 2500, 2500]);
    // K = 0.8·4 = 3.2 mm along Z, J = K (45°): 6.4 mm on diameter.
    let th = threads(&t);
    assert_eq!(th[1].0 - th[0].0, 6_400);
    assert_eq!(th[1].1 - th[0].1, -3_200);
}

/// G76.EXAMPLE: m = 2, a = 45°, Δd = 1.8, k − d = 2.5: two rough passes, FINISH, SPRING.
#[test]
fn g76_example() {
    let t = expand(include_str!("../../corpus/g76_example.nc"), Config::default());
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(
        p.iter().map(|p| (p.kind, p.diameter_depth)).collect::<Vec<_>>(),
        [(PassKind::Rough, 3_600), (PassKind::Rough, 5_000), (PassKind::Finish, 6_000), (PassKind::Spring, 6_000)]
    );
    // tan 22.5° = 0.41421…: t(1.8) = 0.746, t(2.5) = 1.036.
    let m = moves(&t);
    assert_eq!((m[1].x, m[1].z), (62_400, 9_254));
    assert_eq!(threads(&t)[..2], [(62_400, -58_746), (65_400, -60_746)]);
    assert_eq!(m.last().map(|m| (m.x, m.z)), Some((80_000, 10_000)));
}

/// G78.EXAMPLE: the manual's P020545 has infeed mode 05: OUT OF RANGE on P, G78.MODE, line 3,
/// after the rapid of line 2.
#[test]
fn g78_example_alarm() {
    let t = expand(include_str!("../../corpus/g78_example.nc"), Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::G78Mode, 3));
    assert_eq!(moves(&t), [Move::rapid(80_000, 10_000, Rule::PrjModal)]);
}

/// G76.REQUIRED and COM.LEAD: the lead first, then P, then Q.
#[test]
fn g76_required() {
    let cases = [
        ("G0 X60 Z10\nG76 P011060\nG76 X33.8 Z-60 Q0.7 F4\n", b'P', Rule::G76Required),
        ("G0 X60 Z10\nG76 P011060\nG76 X33.8 Z-60 P2.4 F4\n", b'Q', Rule::G76Required),
        ("G0 X60 Z10\nG76 P011060\nG76 X33.8 Z-60 F4\n", b'P', Rule::G76Required),
        ("G0 X60 Z10\nG76 P011060\nG76 X33.8 Z-60\n", b'F', Rule::ComLead),
        ("G0 X60 Z10\nG78 P010060\nG78 X33.8 Z-60 P2.4 F4\n", b'Q', Rule::G76Required),
    ];
    for (src, word, rule) in cases {
        let t = expand(src, Config::default());
        assert_eq!(t.alarm, alarm(AlarmCode::MissingWord, Some(word), rule, 3), "{src}");
        assert_eq!(t.events.len(), 1);
    }
    // A modal lead from an earlier block serves.
    let t = expand("G0 X60 Z10 F4\nG76 X33.8 Z-60 P2.4 Q0.7\n", Config::default());
    assert_eq!(t.alarm, None);
}

/// COM.UNITS: inch and ISC grids; G92 in threads per inch.
#[test]
fn grids() {
    // g92_inch: 20 TPI = 0.05 in = 5000 lead counts; No.19 = 10 → pull-out 0.05 in.
    let t = expand(include_str!("../../tests/programs/g92_inch.nc"), inch());
    assert_eq!(t.alarm, None);
    assert_eq!(threads(&t), [(9_500, -7_500), (10_500, -8_000), (9_400, -7_500), (10_400, -8_000)]);
    assert!(t.moves().filter(|m| m.kind == MoveKind::Thread).all(|m| m.feed == 5_000));
    // G20 on a metric machine is refused; G21 on a metric machine is fine.
    let t = expand("G20\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Unsupported, Some(b'G'), Rule::ComUnits, 1));
    assert_eq!(expand("G21 G0 X1\n", Config::default()).alarm, None);
    // ISC metric: four decimals are on the grid; ISB refuses them.
    let isc = Config { grid: Grid { units: Units::Metric, increment: Increment::Isc }, ..Config::default() };
    let t = expand("G0 X58.7001 Z1\n", isc);
    assert_eq!(moves(&t), [Move::rapid(587_001, 10_000, Rule::PrjModal)]);
    let t = expand("G0 X58.7001 Z1\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Precision, Some(b'X'), Rule::ComUnits, 1));
    // ISC: the No.19 pull-out of F1.5 is 1.5 mm = 15 000 increments (1 lead count each).
    let t = expand("G0 X16 Z3\nG92 X20.5 Z-25 F1.5\n", isc);
    assert_eq!(threads(&t), [(205_000, -235_000), (175_000, -250_000)]);
    // Inch ISC: 0.00001 in increments, I16 = 0.0625 in.
    let inch_isc = Config { grid: Grid { units: Units::Inch, increment: Increment::Isc }, ..Config::default() };
    let t = expand("G0 X1.2 Z0.2\nG92 X0.9 Z-1 I16 J0\n", inch_isc);
    assert_eq!(threads(&t), [(90_000, -100_000)]);
    assert_eq!(t.moves().find(|m| m.kind == MoveKind::Thread).map(|m| m.feed), Some(6_250));
}

/// G92.TAPER, G76 taper (R(i)), COM.LONGAXIS with X long.
#[test]
fn tapers() {
    let t = expand(include_str!("../../tests/programs/g92_taper.nc"), Config::default());
    assert_eq!(t.alarm, None);
    // C.x = 40 − 4 = 36; K = 1 before the end: X = 40 + 2·round(−2·1/35) = 39.886.
    assert_eq!(threads(&t)[..2], [(39_886, -29_000), (42_000, -30_000)]);
    assert_eq!(moves(&t)[1], Move::rapid(36_000, 5_000, Rule::G92Path));
    // R and U of different signs with 2|R| > |U|: GEOMETRY on R.
    let t = expand("G0 X50 Z5\nG92 X40 Z-30 R6 F2\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Geometry, Some(b'R'), Rule::G92Taper, 2));
    // 2|R| = |U| is allowed.
    let t = expand("G0 X50 Z5\nG92 X40 Z-30 R5 F2 J0\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Geometry, Some(b'X'), Rule::ComSide, 2));
    let t = expand("G0 X50 Z5\nG92 X40 Z-30 R4 F2 J0\n", Config::default());
    assert_eq!(t.alarm, None);
    // X long: R = 10 (radius) over W = −4; J1 K2: the pull-out starts at X = D.x + 2·10/…
    // sign(R)·K = +2 radius and Z = D.z + round(4·2/10) = −3.2; it ends at D.x, Z = D.z + 1.
    let t = expand("G0 X100 Z0\nG92 X50 Z-4 R10 F2 J1 K2\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(threads(&t), [(54_000, -3_200), (50_000, -3_000)]);
    // K not below the long-axis travel: GEOMETRY on K.
    let t = expand("G0 X100 Z0\nG92 X50 Z-4 R10 F2 J1 K10\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Geometry, Some(b'K'), Rule::G92Pullout, 2));
    // G76 taper: i = −3, r = 10 tenths of F2: K = J = 2 mm.
    let t = expand(include_str!("../../tests/programs/g76_taper.nc"), Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t)[1], Move::rapid(45_600, 4_711, Rule::G76Path));
    assert_eq!(threads(&t)[..2], [(51_334, -38_289), (55_600, -40_289)]);
}

/// COM.SIDE: internal threads infeed +X and shift +Z; the pull-out goes toward A.
#[test]
fn internal_threads() {
    let t = expand(include_str!("../../tests/programs/g76_internal.nc"), Config::default());
    assert_eq!(t.alarm, None);
    // s = −1: Bn.x = 30 − 2·(1.2 − 0.4) = 28.4, Z = 5 + round(0.4·tan 30°) = 5.231.
    assert_eq!(moves(&t)[1], Move::rapid(28_400, 5_231, Rule::G76Path));
    assert_eq!(threads(&t)[..2], [(28_400, -28_769), (27_400, -29_769)]);
    let p = passes(&t);
    assert_eq!(p.last().map(|p| (p.kind, p.diameter_depth)), Some((PassKind::Finish, 2_400)));
    let t = expand(include_str!("../../tests/programs/g92_internal.nc"), Config::default());
    assert_eq!(t.alarm, None);
    // No.19 = 10: J = K = one lead (1.5 mm), toward A (−X).
    assert_eq!(threads(&t)[..2], [(20_500, -23_500), (17_500, -25_000)]);
}

/// COM.MULTISTART: start angles round(360 000·j/L); one header per pass, then L starts.
#[test]
fn multistart() {
    let t = expand(include_str!("../../tests/programs/g76_multistart.nc"), Config::default());
    assert_eq!(t.alarm, None);
    let angles: Vec<u32> = t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| m.angle).collect();
    assert_eq!(angles[..12], [0, 0, 0, 120_000, 120_000, 120_000, 240_000, 240_000, 240_000, 0, 0, 0]);
    // Lead-in E0.5: rapid to Bn.x + 1 mm, synchronized X move to Bn.
    let m = moves(&t);
    assert_eq!((m[1].kind, m[1].x), (MoveKind::Rapid, 30_100));
    assert_eq!((m[2].kind, m[2].x, m[2].z, m[2].rule), (MoveKind::Thread, 29_100, m[1].z, Rule::G76LeadIn));
    // (From X36: the default pull-out, J = one lead, ends at X35.2 — beyond X35, G92.PATH ③.)
    let t = expand("G0 X36 Z5\nG92 X29.2 Z-20 F3 L7\n", Config::default());
    let angles: Vec<u32> = t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| m.angle).collect();
    assert_eq!(angles.len(), 14);
    assert_eq!(angles[2], 51_429);
    assert_eq!(passes(&t).len(), 1);
}

/// G76.MODE / G78.MODE under thread.zref = groove: flank sequences; every mode ends the last
/// rough pass and the finish at A.z + σ·t(T). (The letter, `start`: `readings_tests`.)
#[test]
fn infeed_modes() {
    let mut groove = Config::default();
    groove.readings.thread_zref = cycle_vocab::readings::ThreadZRef::Groove;
    let base = "G00 X40 Z5;\nG76 P011060 Q0.08 R0.05 D0;\nG76 X27.4 Z-20 P1.3 Q0.4 F2 J1 K1;\n";
    let mut finish_z = Vec::new();
    for (code, mode) in [("G76", 0), ("G76", 1), ("G76", 2), ("G78", 0), ("G78", 1), ("G78", 2), ("G78", 3), ("G78", 4)] {
        let src = if code == "G76" {
            base.replace("D0", &std::format!("D{mode}"))
        } else {
            base.replace("G76", "G78").replace("P011060", &std::format!("P010{mode}60")).replace("D0", "D1")
        };
        let t = expand(&src, groove);
        assert_eq!(t.alarm, None, "{src}");
        let z = pass_start_z(&t);
        // t(T) = round(1.25·tan 30°) = 0.722.
        assert_eq!(z[z.len() - 2], 5_000 - 722, "{src}");
        finish_z.push(z[z.len() - 1]);
        // Pass 1 (odd): right 5 − t(0.4) = 4.769, left 5 − (2·0.722 − 0.231) = 3.787,
        // centre 5 − 0.722.
        let expect_first = match (code, mode) {
            ("G76", 0 | 1) | ("G78", 2 | 3) => 4_769,
            ("G76", 2) | ("G78", 1 | 4) => 3_787,
            _ => 4_278,
        };
        assert_eq!(z[0], expect_first, "{src}");
        // Pass 2 (even): right 5 − round(0.566·tan 30°) = 5 − 0.327.
        let expect_second = match (code, mode) {
            ("G76", 0 | 2) | ("G78", 2 | 4) => 4_673,
            ("G76", 1) | ("G78", 0 | 3) => 4_278,
            _ => 5_000 - (1_444 - 327),
        };
        assert_eq!(z[1], expect_second, "{src}");
    }
    assert!(finish_z.iter().all(|&z| z == 4_278));
}

/// G78.DEPTHMODE 0: n·Δd, the last clamped to k − d.
#[test]
fn g78_constant_depth() {
    let t = expand(include_str!("../../tests/programs/g78_constant.nc"), Config::default());
    let d: Vec<i64> = passes(&t).iter().map(|p| p.diameter_depth / 2).collect();
    assert_eq!(d, [400, 800, 1200, 1250, 1300]);
}

/// PRJ.MAXPASS: the bound is checked before any motion of the cycle; earlier moves stay.
#[test]
fn pass_bound() {
    let mut params = Params { max_passes: Some(12), ..Params::default() };
    let cfg = Config { params, ..Config::default() };
    let t = expand(include_str!("../../corpus/f76_ex1.nc"), cfg);
    assert_eq!(t.alarm, None);
    params.max_passes = Some(11);
    let cfg = Config { params, ..Config::default() };
    let t = expand(include_str!("../../corpus/f76_ex1.nc"), cfg);
    assert_eq!(t.alarm, alarm(AlarmCode::TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, 4));
    assert_eq!(t.events.len(), 1);
    // Δdmin = 0 with Δd = 1 increment: ~10^18 passes, refused at once.
    let t = expand("G0 X100 Z5\nG76 P010060 Q0 R0\nG76 X0 Z-10 P49.999 Q0.001 F1\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, 3));
    // Starts count: 12 passes × L3 = 36 > 30.
    let cfg = Config { params: Params { max_passes: Some(30), ..Params::default() }, ..Config::default() };
    let t = expand("G0 X60 Z10\nG76 P011060 Q0.1 R0.1 L3\nG76 X33.8 Z-60 P2.4 Q0.7 F4\n", cfg);
    assert_eq!(t.alarm, alarm(AlarmCode::TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, 3));
    // G92: L > max_passes.
    let cfg = Config { params: Params { max_passes: Some(2), ..Params::default() }, ..Config::default() };
    let t = expand("G0 X36 Z5\nG92 X29.2 Z-20 F3 L3\n", cfg);
    assert_eq!(t.alarm, alarm(AlarmCode::TooManyPasses, Some(b'L'), Rule::PrjMaxPass, 2));
    // G92: L = max_passes is allowed.
    let t = expand("G0 X36 Z5\nG92 X29.2 Z-20 F3 L2\n", cfg);
    assert_eq!((t.alarm, passes(&t).len()), (None, 1));
}

/// G92.JK.2 / G76.PULLOUT: a pull-out amount that comes out 0 (No.19 = 0 with K alone; J from
/// K·tan(1°) below half an increment) means no pull-out, not a zero-length one.
#[test]
fn zero_pullout_amounts_mean_no_pullout() {
    let cfg = Config { params: Params { no19_pullout: Some(0), ..Params::default() }, ..Config::default() };
    let t = expand("G0 X65 Z5\nG92 X58.7 Z-28 F3 K1\n", cfg);
    assert_eq!(t.alarm, None);
    assert_eq!(threads(&t), [(58_700, -28_000)]);
    let cfg = Config { params: Params { p5131_chamfer_angle: Some(1), ..Params::default() }, ..Config::default() };
    let t = expand("G0 X40 Z5\nG76 P011060 Q0.1 R0.1\nG76 X27.4 Z-20 P1.095 Q0.3 F2 K0.001\n", cfg);
    assert_eq!(t.alarm, None);
    assert!(t.moves().all(|m| m.rule != Rule::G76Pullout), "{}", t.to_gcode());
    assert_eq!(t.moves().filter(|m| m.kind == MoveKind::Thread).count(), passes(&t).len());
}

/// PRJ.SUPPORTED: M codes up to M99 are read (M02/M30 end the program), M100 is refused; M99
/// in the main program is UNSUPPORTED (SUB.RETURN).
#[test]
fn m_code_range() {
    let t = expand("G0 X1 Z1 M97\nG0 X2\n", Config::default());
    assert_eq!((t.alarm, moves(&t).len()), (None, 2));
    let t = expand("G0 X1 Z1\nM99\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Unsupported, Some(b'M'), Rule::SubReturn, 2));
    let t = expand("G0 X1 Z1\nM100\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::UnsupportedCode, Some(b'M'), Rule::PrjSupported, 2));
}

/// The sign helper of the pull-out: −1, 0, 1.
#[test]
fn sign_of_zero_is_zero() {
    use crate::pullout::sign;
    assert_eq!((sign(-5), sign(0), sign(5)), (-1, 0, 1));
}

/// The check order of a block and the alarm each check names.
#[test]
fn check_order() {
    let c = Config::default();
    let a = |src: &str| expand(src, c).alarm;
    assert_eq!(a("G5 X1"), alarm(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1));
    assert_eq!(a("G1.0 X1"), alarm(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1));
    assert_eq!(a("G0 G0"), alarm(AlarmCode::Conflict, Some(b'G'), Rule::PrjWord, 1));
    assert_eq!(a("G0 G1 G5"), alarm(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1));
    assert_eq!(a("G0 G1 M100"), alarm(AlarmCode::UnsupportedCode, Some(b'M'), Rule::PrjSupported, 1));
    assert_eq!(a("M3.5"), alarm(AlarmCode::NotInteger, Some(b'M'), Rule::ComRanges, 1));
    assert_eq!(a("G0 X1 U1 Z1 W1"), alarm(AlarmCode::Conflict, Some(b'U'), Rule::ComAbsInc, 1));
    assert_eq!(a("G0 Z1 W1 F1 I1"), alarm(AlarmCode::Conflict, Some(b'W'), Rule::ComAbsInc, 1));
    assert_eq!(a("G92 F1 I1 Q1"), alarm(AlarmCode::Conflict, Some(b'I'), Rule::ComLead, 1));
    assert_eq!(a("G0 X1 R1 I1"), alarm(AlarmCode::WordNotAllowed, Some(b'I'), Rule::PrjWord, 1));
    assert_eq!(a("G76 P011060 F2"), alarm(AlarmCode::WordNotAllowed, Some(b'F'), Rule::PrjWord, 1));
    assert_eq!(a("G76 X1 Z1 L2"), alarm(AlarmCode::WordNotAllowed, Some(b'L'), Rule::PrjWord, 1));
    // Values alphabetically: X before Z.
    assert_eq!(a("G0 Z1.0001 X1.0001"), alarm(AlarmCode::Precision, Some(b'X'), Rule::ComUnits, 1));
    assert_eq!(a("G0 X1000000"), alarm(AlarmCode::OutOfRange, Some(b'X'), Rule::ComRanges, 1));
    assert_eq!(a("G76 P011060 D3"), alarm(AlarmCode::OutOfRange, Some(b'D'), Rule::G76Mode, 1));
    assert_eq!(a("G76 P011060 D1.0"), alarm(AlarmCode::NotInteger, Some(b'D'), Rule::ComRanges, 1));
    assert_eq!(a("G78 P010060 D2"), alarm(AlarmCode::OutOfRange, Some(b'D'), Rule::G78DepthMode, 1));
    assert_eq!(a("G76 P001060"), alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::G76Finish, 1));
    assert_eq!(a("G76 P1000000"), alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::ComRanges, 1));
    assert_eq!(a("G76 Q-1"), alarm(AlarmCode::OutOfRange, Some(b'Q'), Rule::ComRanges, 1));
    assert_eq!(a("G76 X1 Z1 P0 Q1"), alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::ComRanges, 1));
    assert_eq!(a("G76 X1 Z1 J-1 P1 Q1"), alarm(AlarmCode::OutOfRange, Some(b'J'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 L100"), alarm(AlarmCode::OutOfRange, Some(b'L'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 J100000"), alarm(AlarmCode::OutOfRange, Some(b'J'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 F0"), alarm(AlarmCode::OutOfRange, Some(b'F'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 I255"), alarm(AlarmCode::OutOfRange, Some(b'I'), Rule::ComRanges, 1));
    assert_eq!(a("G1 X1"), alarm(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 1));
    assert_eq!(a("G1"), None);
    assert_eq!(a("G92 X1 Z1"), alarm(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 1));
    // Step 5 of G76: d ≥ k, W = 0, side, COM.POINTS, pass bound, K.
    let g76 = |second: &str| expand(&std::format!("G0 X60 Z10\nG76 P011060 Q0.1 R0.1\nG76 {second}\n"), c).alarm;
    assert_eq!(g76("X33.8 Z-60 P0.1 Q0.7 F4"), alarm(AlarmCode::OutOfRange, Some(b'R'), Rule::G76DepthLast, 3));
    assert_eq!(g76("X33.8 Z10 P0.1 Q0.7 F4"), alarm(AlarmCode::OutOfRange, Some(b'R'), Rule::G76DepthLast, 3));
    assert_eq!(g76("X33.8 Z10 P2.4 Q0.7 F4"), alarm(AlarmCode::Geometry, Some(b'Z'), Rule::G76Format, 3));
    let g78 = expand("G0 X60 Z10\nG78 P010060 Q0.1 R0.1\nG78 X33.8 Z10 P2.4 Q0.7 F4\n", c).alarm;
    assert_eq!(g78, alarm(AlarmCode::Geometry, Some(b'Z'), Rule::G78Format, 3));
    assert_eq!(g76("X60 Z-60 P2.4 Q0.7 F4"), alarm(AlarmCode::Geometry, Some(b'X'), Rule::ComSide, 3));
    assert_eq!(g76("X58 Z-60 P2.4 Q0.7 F4"), alarm(AlarmCode::Geometry, Some(b'X'), Rule::ComPoints, 3));
    assert_eq!(g76("X55.2 Z-60 P2.4 Q0.7 F4 J1"), None); // A exactly at B is allowed
    assert_eq!(g76("X33.8 Z-60 P2.4 Q0.7 F4 J1 K69.999"), None);
    assert_eq!(g76("X33.8 Z-60 P2.4 Q0.7 F4 J1 K70"), alarm(AlarmCode::Geometry, Some(b'K'), Rule::G76Pullout, 3));
    // Config first, on line 0.
    let bad = Config { start_z: 1_000_000_000, ..Config::default() };
    assert_eq!(expand("G0 X1\n#", bad).alarm, alarm(AlarmCode::OutOfRange, Some(b'Z'), Rule::ComRanges, 0));
    let bad = Config { params: Params { p5131_chamfer_angle: Some(0), ..Params::default() }, ..Config::default() };
    assert_eq!(expand("", bad).alarm, alarm(AlarmCode::OutOfRange, None, Rule::G76Pullout, 0));
    let bad = Config { dialect: Dialect::Fanuc, params: Params { p5143_tool_angle: Some(45), ..Params::default() }, ..Config::default() };
    assert_eq!(expand("", bad).alarm, alarm(AlarmCode::OutOfRange, None, Rule::F76Format, 0));
    // No.107 ≠ 0 refused when a G92 cycle runs.
    let n107 = Config { params: Params { no107_pullout_speed: Some(5), ..Params::default() }, ..Config::default() };
    assert_eq!(expand("G0 X35 Z5\nG92 F3\nG92 X29 Z-20", n107).alarm, alarm(AlarmCode::Unsupported, None, Rule::G92Jk8, 3));
}

/// PRJ.DIALECT under FANUC: G78 refused, J/K/D/E/L refused, tool angles restricted.
#[test]
fn fanuc_dialect() {
    let f = fanuc();
    let a = |src: &str| expand(src, f).alarm;
    assert_eq!(a("G78 P010060"), alarm(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjDialect, 1));
    assert_eq!(a("G76 P010060 L2"), alarm(AlarmCode::WordNotAllowed, Some(b'L'), Rule::F76Format, 1));
    assert_eq!(a("G76 X1 Z1 K1"), alarm(AlarmCode::WordNotAllowed, Some(b'K'), Rule::F76Format, 1));
    assert_eq!(a("G76 P010045"), alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::F76Format, 1));
    assert_eq!(a("G76 P010029"), None);
}

/// G92.MODAL: a run keeps X, Z, R; J/K/L for the program; a new run resets R and the end.
#[test]
fn g92_modal() {
    let c = Config::default();
    // A block with only F in G92 mode cuts nothing; G76 between G92 blocks keeps the run.
    let t = expand("G0 X50 Z5\nG92 X40 Z-30 R-2 F2 J0\nF2\nG76 P010060\nX39\n", c);
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t).iter().map(|p| p.index).collect::<Vec<_>>(), [1, 2]);
    assert_eq!(threads(&t), [(40_000, -30_000), (39_000, -30_000)]);
    assert_eq!(moves(&t)[5], Move::rapid(35_000, 5_000, Rule::G92Path)); // R kept
    // A new run after G00: R = 0, the omitted Z at the current position → W = 0.
    let t = expand("G0 X50 Z5\nG92 X40 Z-30 R-2 F2\nG0 X50\nG92 X39\n", c);
    assert_eq!(t.alarm, alarm(AlarmCode::Geometry, Some(b'Z'), Rule::G92Format, 4));
    // U and W are relative to the start point.
    let t = expand("G0 X50 Z5\nG92 U-10 W-35 F2 J0\n", c);
    assert_eq!(threads(&t), [(40_000, -30_000)]);
    // J0: no pull-out; J and K modal for the whole program.
    let t = expand("G0 X50 Z5\nG92 X40 Z-30 F2 J0\nG0 X50\nG92 X40 Z-30\n", c);
    assert_eq!(threads(&t), [(40_000, -30_000), (40_000, -30_000)]);
}

/// PRJ.NOOP, M30, streaming after an alarm.
#[test]
fn stream_rules() {
    let c = Config::default();
    assert!(expand("G0 X0 Z0\nG1 X0 F1\n", c).events.is_empty());
    let t = expand("G0 X1\nM30\n#\n", c);
    assert_eq!((t.events.len(), t.alarm), (1, None));
    let t = expand("G0 X1 M02 (end)\nG0 X2\n", c);
    assert_eq!(moves(&t), [Move::rapid(1_000, 0, Rule::PrjModal)]);
    let mut e = Expander::new(b"G0 X1\nG0 X2 #\nG0 X3\n", c);
    assert!(matches!(e.next(), Some(Ok(_))));
    assert_eq!(e.next(), Some(Err(Alarm::new(AlarmCode::BadCharacter, Some(b'#'), Rule::PrjLex, 2))));
    assert_eq!(e.next(), None);
    assert_eq!(e.next(), None);
    // G01 carries the modal feed (from a G92 I lead, too).
    let t = expand("G92 F2\nG1 X5 Z-1\n", c);
    assert_eq!(moves(&t), [Move::feed(5_000, -1_000, 20_000, Rule::PrjModal)]);
}

/// A fixed-seed xorshift generator for the random drivers (here, in `g162_tests` and in
/// `schedule`'s tests).
pub fn xorshift(state: &mut u64) -> u64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    *state
}

/// The grid of round `round` of a random driver: every units/increment pair in turn.
pub fn grid_of_round(round: u32) -> Grid {
    Grid {
        units: if round.is_multiple_of(2) { Units::Metric } else { Units::Inch },
        increment: if round % 4 < 2 { Increment::Isb } else { Increment::Isc },
    }
}

/// No input panics: random bytes, random word soups, random and extreme configurations.
#[test]
fn no_panic_on_random_input() {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let extremes = [0i64, 1, -1, 999_999_999, -999_999_999, 1_000_000_000, i64::MAX, i64::MIN];
    let alphabet = b"GXZUWRPQFIJKLDEMNOST0123456789.-  ;\n(";
    for round in 0..20_000u32 {
        let mut params = Params::default();
        if round % 3 == 0 {
            let r = xorshift(&mut s);
            params.no19_pullout = Some((r % 300) as i64);
            params.p5130_chamfer = Some(((r >> 9) as u32 % 120) as i64);
            params.p5131_chamfer_angle = Some(((r >> 17) as u32 % 95) as i64);
            params.p5140_min_cut = Some(extremes[(r >> 24) as usize % extremes.len()]);
            params.p5141_finish_allowance = Some(extremes[(r >> 28) as usize % extremes.len()]);
            params.p5142_finish_passes = Some(((r >> 32) as u32 % 120) as i64);
            params.p5143_tool_angle = Some(((r >> 40) as u32 % 110) as i64);
            params.max_passes = Some(([0, 1, 50, 10_000, u32::MAX][(r >> 48) as usize % 5]) as i64);
        }
        let r = xorshift(&mut s);
        let cfg = Config {
            dialect: if r & 1 == 0 { Dialect::Gsk } else { Dialect::Fanuc },
            grid: Grid {
                units: if r & 2 == 0 { Units::Metric } else { Units::Inch },
                increment: if r & 4 == 0 { Increment::Isb } else { Increment::Isc },
            },
            params,
            start_x: if r & 8 == 0 { 0 } else { extremes[(r >> 8) as usize % extremes.len()] },
            start_z: if r & 16 == 0 { 0 } else { extremes[(r >> 16) as usize % extremes.len()] },
            operator: cycle_vocab::Script::EMPTY,
            readings: cycle_vocab::Readings::default(),
        };
        let mut buf = [0u8; 96];
        let soup = round % 2 == 0;
        for b in buf.iter_mut() {
            let v = xorshift(&mut s);
            *b = if soup { alphabet[(v % alphabet.len() as u64) as usize] } else { (v >> 32) as u8 };
        }
        let mut n = 0;
        for _ in Expander::new(&buf, cfg) {
            n += 1;
            if n > 200_000 {
                break;
            }
        }
    }
}

/// Legal cycles with random extreme words never panic and end where they started.
#[test]
fn no_panic_on_extreme_cycles() {
    let mut s = 0x1234_5678_9abc_def1u64;
    let vals = ["0", "0.001", "1", "-1", "999999.999", "-999999.999", "0.5", "2.4", "99999.999", "-50"];
    let leads = ["1", "9999", "0.0001", "4"];
    for _ in 0..3_000 {
        let mut r = || xorshift(&mut s);
        let mut w: Vec<String> = Vec::new();
        for _ in 0..16 {
            w.push(String::from(vals[(r() % vals.len() as u64) as usize]));
        }
        let u = |i: usize| w[i].trim_start_matches('-');
        let (p, l, f1, f2) = (10_000 + r() % 990_000, 1 + r() % 3, leads[(r() % 4) as usize], leads[(r() % 4) as usize]);
        let src = std::format!(
            "G0 X{} Z{}\nG76 P{p:06} Q{} R{} L{l}\nG76 X{} Z{} R{} P{} Q{} F{f1} J{} K{}\nG92 X{} Z{} R{} F{f2} J{} K{}\nX{}\n",
            w[0], w[1], u(2), u(3), w[4], w[5], w[6], u(7), u(8), u(9), u(10), w[11], w[12], w[13], w[14], w[15], w[0],
        );
        let cfg = Config { params: Params { max_passes: Some(2_000), ..Params::default() }, ..Config::default() };
        let t = expand(&src, cfg);
        // With no alarm the cycles returned to the start point.
        if t.alarm.is_none() {
            // The start point: the first rapid of line 1, or X0 Z0 when it moved nothing.
            let start = match t.moves().next() {
                Some(m) if m.rule == Rule::PrjModal => (m.x, m.z),
                _ => (0, 0),
            };
            if let Some(last) = t.moves().last() {
                assert_eq!(start, (last.x, last.z), "{src}");
            }
        }
    }
}

/// Random legal G76/G78 cycles in every grid: rough depths never decrease (strictly increase
/// with Δdmin ≥ 1), the last rough depth is k − d, the finishing passes are at k and share the
/// Z of the last rough pass, and the cycle ends at its start point.
#[test]
fn random_legal_multipass_cycles() {
    let mut s = 0x0bad_cafe_dead_beefu64;
    let mut checked = 0;
    for round in 0..1_500u32 {
        let mut r = || xorshift(&mut s);
        let grid = grid_of_round(round);
        let dec = grid.decimals();
        let len = |v: i64| cycle_vocab::text::fixed(v, dec);
        let k = 2 + (r() % 3_000) as i64;
        let d = (r() % k as u64) as i64;
        let dd = 1 + (r() % 1_500) as i64;
        let dmin = (r() % 200) as i64;
        let i = (r() % 2_000) as i64 - 1_000;
        let dx = 10_000 + (r() % 50_000) as i64; // end X, diameter
        let external = r() % 2 == 0;
        let margin = 2 * (k + i.abs()) + 2 * (r() % 5_000) as i64 + 2;
        let ax = if external { dx + margin } else { (dx - margin).max(-999_000) };
        let az = (r() % 10_000) as i64;
        let w = -(1_000 + (r() % 80_000) as i64);
        let (code, p_mid, dword) = if r() % 2 == 0 {
            ("G76", r() % 100, std::format!("D{}", r() % 3))
        } else {
            ("G78", r() % 5, std::format!("D{}", r() % 2))
        };
        let p = 10_000 * (1 + r() % 3) + 100 * p_mid + r() % 100;
        let src = std::format!(
            "G0 X{} Z{}\n{code} P{p:06} Q{} R{} {dword} L{}\n{code} X{} W{} R{} P{} Q{} F{}\n",
            len(ax), len(az), len(dmin), len(d), 1 + r() % 2, len(dx), len(w), len(i), len(k), len(dd),
            cycle_vocab::text::fixed(1 + (r() % 20_000) as i64, grid.lead_decimals()),
        );
        let cfg = Config { grid, params: Params { max_passes: Some(5_000), ..Params::default() }, ..Config::default() };
        let t = expand(&src, cfg);
        if let Some(a) = t.alarm {
            // Only the pass bound or the chamfer pull-out may refuse these programs.
            assert!(matches!(a.code, AlarmCode::TooManyPasses | AlarmCode::Geometry), "{src}\n{a}");
            continue;
        }
        checked += 1;
        let ps = passes(&t);
        let m = usize::try_from(p / 10_000).unwrap();
        let rough: Vec<i64> = ps[..ps.len() - m].iter().map(|p| p.diameter_depth / 2).collect();
        assert!(rough.windows(2).all(|w| w[0] < w[1] || (dmin == 0 && w[0] <= w[1])), "{src}");
        assert_eq!(rough.last().copied(), Some(k - d), "{src}");
        assert!(ps[ps.len() - m..].iter().all(|p| p.diameter_depth == 2 * k));
        let first_z: Vec<i64> = t
            .events
            .windows(2)
            .filter_map(|w| match w {
                [Event::Pass(_), Event::Move(m)] => Some(m.z),
                _ => None,
            })
            .collect();
        let n = first_z.len();
        assert!(first_z[n - m - 1..].iter().all(|&z| z == first_z[n - 1]), "{src}");
        let last = t.moves().last().unwrap();
        assert_eq!((last.x, last.z), (ax, az), "{src}");
    }
    assert!(checked > 500, "{checked}");
}
