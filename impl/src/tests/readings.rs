//! Group A points 5–8 (issue #29): the declared readings g94.k, g73.c, g75.relief and
//! thread.zref on the whole expander, a test per value (the letter is the default).
extern crate std;

use crate::tests::{expand, fanuc, moves, pass_start_z, passes};
use cycle_vocab::readings::{G73C, G75Relief, G94K, ThreadZRef};
use cycle_vocab::{Alarm, AlarmCode, Config, Event, Move, MoveKind, PassKind, Rule};
use std::vec::Vec;

fn with(f: impl Fn(&mut Config)) -> Config {
    let mut c = Config::default();
    f(&mut c);
    c
}

/// Point 5, both values: `end-minus-start` (the letter) C.z = D.z − K, `start-minus-end`
/// C.z = D.z + K; the taper check on k = C.z − D.z against W.
#[test]
fn g94_k_both_readings() {
    let sme = with(|c| c.readings.g94_k = G94K::StartMinusEnd);
    let first = |src: &str, c: Config| {
        let t = expand(src, c);
        (t.alarm, moves(&t).get(1).copied())
    };
    let src = "G0 X50 Z2\nG94 X20 Z-5 K-2 F0.2\n";
    assert_eq!(first(src, Config::default()), (None, Some(Move::rapid(50_000, -3_000, Rule::G94Taper))));
    assert_eq!(first(src, sme), (None, Some(Move::rapid(50_000, -7_000, Rule::G94Taper))));
    // W = −7: the letter refuses K−7.001 (k = +7.001), start-minus-end K7.001.
    let geo = Some(Alarm::new(AlarmCode::Geometry, Some(b'K'), Rule::G94Taper, 2));
    for (k, letter, other) in [("-7.001", geo, None), ("7.001", None, geo), ("-7", None, None), ("7", None, None)] {
        let src = std::format!("G0 X50 Z2\nG94 X40 Z-5 K{k} F0.3\n");
        assert_eq!((expand(&src, Config::default()).alarm, expand(&src, sme).alarm), (letter, other), "K{k}");
    }
    // K is kept by the run as written: the next block reads it the same way.
    let t = expand("G0 X50 Z2\nG94 X20 Z-5 K-2 F0.2\nZ-8\n", Config::default());
    assert_eq!(moves(&t)[5], Move::rapid(50_000, -6_000, Rule::G94Taper));
    // K0: no taper, ① tagged G94.PATH under both.
    for c in [Config::default(), sme] {
        assert_eq!(moves(&expand("G0 X50 Z2\nG94 X20 Z-5 K0 F0.2\n", c))[1], Move::rapid(50_000, -5_000, Rule::G94Path));
    }
}

const G73_ONE: &str = "G00 X40 Z5\nG73 U6 W2 R1\nG73 P10 Q40 U0.4 W0.1 F0.2\nN10 G00 X10 Z1\nN20 G01 Z-10\n\
    N30 G02 X20 Z-15 R5\nN40 G01 X30 Z-25\nG00 X60 Z50\n";

/// Point 6, `visit` (the letter): one rapid A → C = A + (2Δi + Δu, Δk + Δw) before pass 1's
/// header (rule G73.PATH); signed values; no move when C = A.
#[test]
fn g73_c_visit() {
    let t = expand(G73_ONE, Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(t.events[1], Event::Move(Move::rapid(52_400, 7_100, Rule::G73Path)));
    assert!(matches!(t.events[2], Event::Pass(p) if p.index == 1));
    assert_eq!(t.events[3], Event::Move(Move::rapid(40_400, 5_100, Rule::G73Path)));
    // Negative Δi, Δk: C = (40 − 6 + 0.4, 5 − 1 + 0.1).
    let t = expand(&G73_ONE.replace("U6 W2", "U-3 W-1"), Config::default());
    assert_eq!(t.events[1], Event::Move(Move::rapid(34_400, 4_100, Rule::G73Path)));
    // Format (b) with its own I, K and two passes: C once, before pass 1 only.
    let src = "G00 X50 Z5\nG73 P1 Q2 I4.5 K1.5 D2 U1 W0.5 F0.2\nN1 G1 X16 Z2\nN2 X40 Z-30\n";
    let t = expand(src, Config::default());
    assert_eq!(t.events[1], Event::Move(Move::rapid(60_000, 7_000, Rule::G73Path)));
    assert_eq!(moves(&t).iter().filter(|m| (m.x, m.z) == (60_000, 7_000)).count(), 1);
    // C = A (all zero): no move, the trace is skip's.
    let zero = "G00 X40 Z5\nG73 U0 W0 R1\nG73 P10 Q20 F0.2\nN10 G01 X10 Z1\nN20 Z-10\n";
    let skip = with(|c| c.readings.g73_c = G73C::Skip);
    assert_eq!(expand(zero, Config::default()), expand(zero, skip));
    assert!(matches!(expand(zero, Config::default()).events[1], Event::Pass(_)));
}

/// Point 6, `skip`: no rapid to C; pass 1's rapid starts at A; the offsets are visit's.
#[test]
fn g73_c_skip() {
    let skip = with(|c| c.readings.g73_c = G73C::Skip);
    let t = expand(G73_ONE, skip);
    assert_eq!(t.alarm, None);
    assert!(matches!(t.events[1], Event::Pass(p) if p.index == 1));
    assert_eq!(t.events[2], Event::Move(Move::rapid(40_400, 5_100, Rule::G73Path)));
    // Everything but the one rapid is the same.
    let mut visit = expand(G73_ONE, Config::default());
    visit.events.remove(1);
    assert_eq!(visit.events, t.events);
}

/// G75 reliefs (Z) of a program, under `c`.
fn reliefs(src: &str, c: Config) -> Vec<i64> {
    let t = expand(src, c);
    assert_eq!(t.alarm, None, "{src}");
    moves(&t).iter().filter(|m| m.rule == Rule::G75Relief).map(|m| m.z).collect()
}

/// Point 7: `minus-z` (the letter) relieves toward −Z whatever the step; `against-step` against
/// it. Grooves stepping toward −Z differ; toward +Z both relieve toward −Z. G74 is unchanged.
#[test]
fn g75_relief_both_readings() {
    let against = with(|c| c.readings.g75_relief = G75Relief::AgainstStep);
    let minus_step = "G00 X52 Z-10\nG75 R0.5\nG75 X40 Z-20 P2 Q3 R0.3 F0.05\n";
    assert_eq!(reliefs(minus_step, Config::default()), [-13_300, -16_300, -19_300, -20_300]);
    assert_eq!(reliefs(minus_step, against), [-12_700, -15_700, -18_700, -19_700]);
    let plus_step = "G00 X52 Z10\nG75 R0.5\nG75 X40 Z20 P2 Q3 R0.3 F0.05\n";
    assert_eq!(reliefs(plus_step, Config::default()), [12_700, 15_700, 18_700, 19_700]);
    assert_eq!(reliefs(plus_step, against), [12_700, 15_700, 18_700, 19_700]);
    // The relief is a rapid from the groove bottom; the next move goes back along X from there.
    let m = moves(&expand(minus_step, Config::default()));
    let i = m.iter().position(|m| m.rule == Rule::G75Relief).unwrap();
    assert_eq!(m[i - 1..=i + 1], [
        Move::feed(40_000, -13_000, 500, Rule::G75Peck),
        Move::rapid(40_000, -13_300, Rule::G75Relief),
        Move::rapid(52_000, -13_300, Rule::G75Column),
    ]);
    // R0: no relief; one groove: none either.
    assert!(reliefs(&minus_step.replace("R0.3", "R0"), Config::default()).is_empty());
    assert!(reliefs("G00 X52 Z-10\nG75 X40 P2 R0.3 F0.05\n", Config::default()).is_empty());
    // G74 relieves against its step under both readings.
    let g74 = "G00 X20 Z1\nG74 R0.5\nG74 X40 Z-5 P3 Q2 R1 F0.1\n";
    assert_eq!(expand(g74, Config::default()), expand(g74, against));
}

/// The flank of rough pass `n` (1-based) of G76 e / G78 mode (G76.MODE, G78.MODE): +1 right,
/// 0 centre, −1 left.
fn flank(g78: bool, mode: u32, n: usize) -> i64 {
    let odd = n % 2 == 1;
    match (g78, mode) {
        (false, 0) | (true, 2) => 1,
        (false, 1) | (true, 3) => if odd { 1 } else { 0 },
        (false, 2) | (true, 4) => if odd { -1 } else { 1 },
        (true, 0) => 0,
        _ => -1, // G78 mode 1
    }
}

const MODES: &str = "G00 X40 Z5;\nG76 P011060 Q0.08 R0.05 D0;\nG76 X27.4 Z-20 P1.3 Q0.4 F2 J1 K1;\n";

/// The start Z of every pass (rough and finishing) and the rough depths, of G76 e = `mode` or
/// G78 mode `mode`, under `c`.
fn pass_starts(g78: bool, mode: u32, c: Config) -> (Vec<i64>, Vec<(PassKind, i64)>) {
    let src = if g78 {
        MODES.replace("G76", "G78").replace("P011060", &std::format!("P010{mode}60")).replace("D0", "D1")
    } else {
        MODES.replace("D0", &std::format!("D{mode}"))
    };
    let t = expand(&src, c);
    assert_eq!(t.alarm, None, "{src}");
    (pass_start_z(&t), passes(&t).iter().map(|p| (p.kind, p.diameter_depth / 2)).collect())
}

/// Point 8, `start` (the letter): every mode measures from B.z = A.z — right A.z + σ·t(δ),
/// centre A.z, left A.z − σ·t(δ) (σ = −1 here); the finishing pass at the last rough pass's Z.
#[test]
fn thread_zref_start() {
    let t = |d: i64| (d as f64 * 30f64.to_radians().tan()).round() as i64;
    for (g78, mode) in [(false, 0), (false, 1), (false, 2), (true, 0), (true, 1), (true, 2), (true, 3), (true, 4)] {
        let (z, p) = pass_starts(g78, mode, Config::default());
        let rough: Vec<i64> = p.iter().filter(|(k, _)| *k == PassKind::Rough).map(|(_, d)| *d).collect();
        assert_eq!(z.len(), rough.len() + 1, "{g78} {mode}");
        for (i, d) in rough.iter().enumerate() {
            assert_eq!(z[i], 5_000 - flank(g78, mode, i + 1) * t(*d), "G78 {g78} mode {mode} pass {}", i + 1);
        }
        assert_eq!(z[rough.len()], z[rough.len() - 1], "G78 {g78} mode {mode}: finishing at the last rough Z");
    }
    // The register's samples: G76 e = 2 pass 1 left 5.231, pass 2 right 4.673; G78 mode 0
    // radial at Z5 throughout.
    assert_eq!(pass_starts(false, 2, Config::default()).0[..2], [5_231, 4_673]);
    assert!(pass_starts(true, 0, Config::default()).0.iter().all(|&z| z == 5_000));
}

/// Point 8, `groove`: the modes end their last rough pass and the finish at A.z + σ·t(T)
/// (t(T) = round(1.25·tan 30°) = 0.722): centre A.z + σ·t(T), left the mirror of right.
#[test]
fn thread_zref_groove() {
    let groove = with(|c| c.readings.thread_zref = ThreadZRef::Groove);
    let t = |d: i64| (d as f64 * 30f64.to_radians().tan()).round() as i64;
    for (g78, mode) in [(false, 0), (false, 1), (false, 2), (true, 0), (true, 1), (true, 2), (true, 3), (true, 4)] {
        let (z, p) = pass_starts(g78, mode, groove);
        let rough: Vec<i64> = p.iter().filter(|(k, _)| *k == PassKind::Rough).map(|(_, d)| *d).collect();
        for (i, d) in rough.iter().enumerate() {
            let off = match flank(g78, mode, i + 1) {
                1 => t(*d),
                0 => 722,
                _ => 2 * 722 - t(*d),
            };
            assert_eq!(z[i], 5_000 - off, "G78 {g78} mode {mode} pass {}", i + 1);
        }
        assert_eq!(z[rough.len() - 1..], [4_278, 4_278], "G78 {g78} mode {mode}");
    }
}

/// Point 8: the right flank only (G76 e = 0, G78 mode 2, FANUC G76) is the same under both
/// readings (the last rough pass of a right flank is at t(T) either way).
#[test]
fn thread_zref_right_flank_coincides() {
    let groove = with(|c| c.readings.thread_zref = ThreadZRef::Groove);
    let fanuc_groove = Config { readings: groove.readings, ..fanuc() };
    for (src, c, g) in [
        (include_str!("../../../corpus/f76_ex1_microns.nc"), fanuc(), fanuc_groove),
        (include_str!("../../../corpus/f76_ex1.nc"), Config::default(), groove),
        (include_str!("../../../corpus/f76_ex2.nc"), Config::default(), groove),
        (include_str!("../../../tests/programs/g76_mode0.nc"), Config::default(), groove),
        (include_str!("../../../tests/programs/g78_mode2.nc"), Config::default(), groove),
    ] {
        let (a, b) = (expand(src, c), expand(src, g));
        assert_eq!(a.alarm, None, "{src}");
        assert!(a.moves().any(|m| m.kind == MoveKind::Thread), "{src}");
        assert_eq!(a, b, "{src}");
    }
    // Internal threads (σ = +1) too, and a mode that differs (G76 e = 1) does differ.
    let src = include_str!("../../../tests/programs/g76_internal.nc");
    assert_eq!(expand(src, Config::default()), expand(src, groove));
    assert_ne!(pass_starts(false, 1, Config::default()).0, pass_starts(false, 1, groove).0);
}
