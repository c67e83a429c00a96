//! Hand-checked examples of the thread cycles G92, G76, G78 and FANUC G76 from the manuals and
//! the register, on the whole expander; random legal G76/G78 cycles.
use super::*;

/// G92.EXAMPLE: four cycles at X58.7, X57.7, X57, X56.9 to Z-27, pull-out J3 K1 to
/// (x + 6 mm on diameter, Z-28), lead 3 mm, back to X65 Z5 each time (G92.PATH, G92.PULLOUT,
/// G92.MODAL).
#[test]
fn g92_example() {
    let t = expand(include_str!("../../../corpus/g92_example.nc"), Config::default());
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
    let t = expand(include_str!("../../../corpus/f76_ex1.nc"), Config::default());
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
    let micro = expand(include_str!("../../../corpus/f76_ex1_microns.nc"), fanuc());
    assert_eq!(micro.events, t.events);
    assert_eq!(micro.alarm, None);
}

/// F76.EX2: three finishing passes (FINISH, SPRING, SPRING) at k = 2.5, chamfer 0.8 lead.
#[test]
fn f76_ex2() {
    let t = expand(include_str!("../../../corpus/f76_ex2.nc"), Config::default());
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
    let t = expand(include_str!("../../../corpus/g76_example.nc"), Config::default());
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
    let t = expand(include_str!("../../../corpus/g78_example.nc"), Config::default());
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
    let t = expand(include_str!("../../../tests/programs/g92_inch.nc"), inch());
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
    let t = expand(include_str!("../../../tests/programs/g92_taper.nc"), Config::default());
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
    // U = 0 (D.x = A.x) has no sign, so any R is allowed; J0: ③ starts at A.x (G92.PATH).
    // R−3: C.x = 50 − 6 = 44, s = +1; R3: C.x = 56, s = −1.
    for (r, cx) in [("R-3", 44_000), ("R3", 56_000)] {
        let t = expand(&std::format!("G0 X50 Z5\nG92 X50 Z-30 {r} F2 J0\n"), Config::default());
        assert_eq!(t.alarm, None, "{r}");
        assert_eq!(moves(&t)[1], Move::rapid(cx, 5_000, Rule::G92Path), "{r}");
        assert_eq!(threads(&t), [(50_000, -30_000)], "{r}");
    }
    // X long: R = 10 (radius) over W = −4; J1 K2: the pull-out starts at X = D.x + 2·10/…
    // sign(R)·K = +2 radius and Z = D.z + round(4·2/10) = −3.2; it ends at D.x, Z = D.z + 1.
    let t = expand("G0 X100 Z0\nG92 X50 Z-4 R10 F2 J1 K2\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(threads(&t), [(54_000, -3_200), (50_000, -3_000)]);
    // K not below the long-axis travel: GEOMETRY on K.
    let t = expand("G0 X100 Z0\nG92 X50 Z-4 R10 F2 J1 K10\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Geometry, Some(b'K'), Rule::G92Pullout, 2));
    // G76 taper: i = −3, r = 10 tenths of F2: K = J = 2 mm.
    let t = expand(include_str!("../../../tests/programs/g76_taper.nc"), Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t)[1], Move::rapid(45_600, 4_711, Rule::G76Path));
    assert_eq!(threads(&t)[..2], [(51_334, -38_289), (55_600, -40_289)]);
}

/// COM.SIDE: internal threads infeed +X and shift +Z; the pull-out goes toward A.
#[test]
fn internal_threads() {
    let t = expand(include_str!("../../../tests/programs/g76_internal.nc"), Config::default());
    assert_eq!(t.alarm, None);
    // s = −1: Bn.x = 30 − 2·(1.2 − 0.4) = 28.4, Z = 5 + round(0.4·tan 30°) = 5.231.
    assert_eq!(moves(&t)[1], Move::rapid(28_400, 5_231, Rule::G76Path));
    assert_eq!(threads(&t)[..2], [(28_400, -28_769), (27_400, -29_769)]);
    let p = passes(&t);
    assert_eq!(p.last().map(|p| (p.kind, p.diameter_depth)), Some((PassKind::Finish, 2_400)));
    let t = expand(include_str!("../../../tests/programs/g92_internal.nc"), Config::default());
    assert_eq!(t.alarm, None);
    // No.19 = 10: J = K = one lead (1.5 mm), toward A (−X).
    assert_eq!(threads(&t)[..2], [(20_500, -23_500), (17_500, -25_000)]);
}

/// COM.MULTISTART: start angles round(360 000·j/L); one header per pass, then L starts.
#[test]
fn multistart() {
    let t = expand(include_str!("../../../tests/programs/g76_multistart.nc"), Config::default());
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
/// rough pass and the finish at A.z + σ·t(T). (The letter, `start`: `super::readings`.)
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
    let t = expand(include_str!("../../../tests/programs/g78_constant.nc"), Config::default());
    let d: Vec<i64> = passes(&t).iter().map(|p| p.diameter_depth / 2).collect();
    assert_eq!(d, [400, 800, 1200, 1250, 1300]);
}

/// PRJ.MAXPASS: the bound is checked before any motion of the cycle; earlier moves stay.
#[test]
fn pass_bound() {
    let mut params = Params { max_passes: Some(12), ..Params::default() };
    let cfg = Config { params, ..Config::default() };
    let t = expand(include_str!("../../../corpus/f76_ex1.nc"), cfg);
    assert_eq!(t.alarm, None);
    params.max_passes = Some(11);
    let cfg = Config { params, ..Config::default() };
    let t = expand(include_str!("../../../corpus/f76_ex1.nc"), cfg);
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

/// The sign helper of the pull-out: −1, 0, 1.
#[test]
fn sign_of_zero_is_zero() {
    use crate::pullout::sign;
    assert_eq!((sign(-5), sign(0), sign(5)), (-1, 0, 1));
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
