//! The thread points of issue #29, Group A, by hand from docs/INTERPRETATION.md: G78 J/K modal,
//! FANUC a = 40, No.5131 for G92, G92 step ③, and the infeed Z of G76/G78 under each
//! `thread.zref` (the letter `start` the default). No number below is taken from the spec's output.

use crate::expand;
use crate::tests::util::{alarm_with, run, run_with, Expect};
use cycle_vocab::readings::ThreadZRef;
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Event, MoveKind, Params, PassKind, Readings, Rule};

fn zref(z: ThreadZRef) -> Config {
    Config { readings: Readings { thread_zref: z, ..Readings::default() }, ..Config::default() }
}

fn with_params(p: Params) -> Config {
    Config { params: p, ..Config::default() }
}

/// Each pass's infeed point Bn: the first move after its header, as (kind, X, Z).
fn infeeds(t: &Trace) -> Vec<(PassKind, i64, i64)> {
    let mut out = Vec::new();
    let mut kind = None;
    for e in &t.events {
        match e {
            Event::Pass(p) => kind = Some(p.kind),
            Event::Move(m) => {
                if let Some(k) = kind.take() {
                    out.push((k, m.x, m.z));
                }
            }
            _ => {}
        }
    }
    out
}

/// The pull-out moves as (ΔX, ΔZ) from the move before each.
fn pullouts(t: &Trace, rule: Rule) -> Vec<(i64, i64)> {
    let moves: Vec<_> = t.moves().collect();
    moves.windows(2).filter(|w| w[1].rule == rule).map(|w| (w[1].x - w[0].x, w[1].z - w[0].z)).collect()
}

/// G78 J and K are modal (`000_…` lines 59, 61): the register's example, both cycles pull out
/// J1.5 K2 (radius 1.5 on X = 3.000 on the diameter, 2 on Z before the end).
#[test]
fn g78_jk_modal() {
    let kept = run("G0 X70 Z5\nG78 X60 Z-60 P3 Q1.8 F3 J1.5 K2\nG78 X60 Z-60 P3 Q1.8\n");
    let written = run("G0 X70 Z5\nG78 X60 Z-60 P3 Q1.8 F3 J1.5 K2\nG78 X60 Z-60 P3 Q1.8 J1.5 K2\n");
    assert_eq!(kept, written);
    let p = pullouts(&kept, Rule::G78Pullout);
    assert!(p.len() > 2 && p.iter().all(|&d| d == (3_000, -2_000)), "{p:?}");
    // Each word on its own: K3 replaces K, J1.5 stays.
    let k3 = run("G0 X70 Z5\nG78 X60 Z-60 P3 Q1.8 F3 J1.5 K2\nG78 X60 Z-60 P3 Q1.8 K3\n");
    let second = pullouts(&k3, Rule::G78Pullout);
    assert_eq!(second.last(), Some(&(3_000, -3_000)));
    // G76 does not keep them (OPEN): the second G76 takes 5130/5131 (one lead, 45°: J = K = 3).
    let g76 = run("G0 X70 Z5\nG76 X60 Z-60 P3 Q1.8 F3 J1.5 K2\nG76 X60 Z-60 P3 Q1.8\n");
    assert_eq!(pullouts(&g76, Rule::G76Pullout).last(), Some(&(6_000, -3_000)));
    // G92's J/K are apart from G78's: a G92 J5 K1 does not reach G78.
    let g92_first = run("G0 X70 Z5\nG92 X60 Z-20 F3 J1 K1\nG0 X70 Z5\nG78 X60 Z-60 P3 Q1.8\n");
    assert_eq!(pullouts(&g92_first, Rule::G78Pullout).last(), Some(&(6_000, -3_000)));
    // A kept J0 means no pull-out in later cycles.
    let j0 = run("G0 X70 Z5\nG78 X60 Z-60 P3 Q1.8 F3 J0\nG78 X60 Z-60 P3 Q1.8\n");
    assert!(pullouts(&j0, Rule::G78Pullout).is_empty());
}

/// F76.FORMAT: the FANUC tool angles 80, 60, 55, 40, 30, 29, 0 (`003_…` line 5), 40 included, in
/// P and in 5143. With a = 40, t(δ) = round(δ·tan 20°): depths 0.5, 0.707, 0.866, 0.9 shift
/// 0.182, 0.257, 0.315, 0.328 toward −Z (external, right flank); finishing at the last Z.
#[test]
fn fanuc_tool_angle_40() {
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    let src = "G0 X70 Z5\nG76 P011040 Q100 R0.1\nG76 X60 Z-30 P1000 Q500 F2\n";
    let t = run_with(src, &fanuc);
    let want = vec![
        (PassKind::Rough, 61_000, 4_818),
        (PassKind::Rough, 60_586, 4_743),
        (PassKind::Rough, 60_268, 4_685),
        (PassKind::Rough, 60_200, 4_672),
        (PassKind::Finish, 60_000, 4_672),
    ];
    assert_eq!(infeeds(&t), want);
    // FANUC G76 is the right flank only: both `thread.zref` readings give the same trace.
    let groove = Config { readings: Readings { thread_zref: ThreadZRef::Groove, ..Readings::default() }, ..fanuc };
    assert_eq!(expand(src.as_bytes(), &groove), t);
    // 45 is no FANUC angle, in P or in 5143; 40 in 5143 is.
    let bad: Expect = (AlarmCode::OutOfRange, Some('P'), Rule::F76Format, 2);
    assert_eq!(alarm_with("G0 X70 Z5\nG76 P011045 Q100 R0.1\n", &fanuc), bad);
    let p = |a| Config { params: Params { p5143_tool_angle: Some(a), ..Params::default() }, ..fanuc };
    assert_eq!(expand(b"G0 X70 Z5\nG76 X60 Z-30 P1000 Q500 F2\n", &p(40)).alarm, None);
    assert_eq!(expand(b"G0 X1\n", &p(45)).alarm, Some(Alarm::new(AlarmCode::OutOfRange, None, Rule::F76Format, 0)));
}

/// No.5131 for G92 (G92.JK.1): J = round(c·tan 5131°), K = c. `G92 X58.7 Z-28 F3` from X65 Z5:
/// c = 3 (No.19 = one lead); 45° ends the pull-out at X58.7 + 2·3 = 64.7; 30° at
/// X58.7 + 2·1.732 = 62.164; 60° at X58.7 + 2·5.196 = 69.092, beyond A.x: step ③ refuses it on J.
#[test]
fn g92_5131() {
    let src = "G0 X65 Z5\nG92 X58.7 Z-28 F3\n";
    let at = |a: i64| with_params(Params { p5131_chamfer_angle: Some(a), ..Params::default() });
    let ends = |t: &Trace| -> Vec<(i64, i64, Rule)> { t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z, m.rule)).collect() };
    assert_eq!(ends(&run(src)), vec![(58_700, -25_000, Rule::G92Path), (64_700, -28_000, Rule::G92Jk1)]);
    assert_eq!(run(src), run_with(src, &at(45)));
    assert_eq!(ends(&run_with(src, &at(30))), vec![(58_700, -25_000, Rule::G92Path), (62_164, -28_000, Rule::G92Jk1)]);
    assert_eq!(alarm_with(src, &at(60)), (AlarmCode::Geometry, Some('J'), Rule::G92Path, 2));
    // J omitted, K given (G92.JK.2): J = c whatever 5131.
    let k1 = "G0 X65 Z5\nG92 X58.7 Z-28 F3 K1\n";
    assert_eq!(ends(&run_with(k1, &at(30))), vec![(58_700, -27_000, Rule::G92Path), (64_700, -28_000, Rule::G92Jk2)]);
}

/// G92.PATH step ③ (DEPARTS): X₃ beyond A.x is refused before the cycle's motion — on J when
/// the pull-out carried X there — after every other G92 check.
#[test]
fn g92_step3() {
    let geometry_j: Expect = (AlarmCode::Geometry, Some('J'), Rule::G92Path, 2);
    // The register's case: J5 ends the pull-out at X68.7 > X65. Only the G00 stands.
    let t = expand(b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J5 K1\n", &Config::default());
    assert_eq!(t.alarm.map(|a| (a.code, a.word, a.rule, a.line)), Some((AlarmCode::Geometry, Some(b'J'), Rule::G92Path, 2)));
    assert_eq!(t.events.len(), 1);
    // X₃ = A.x exactly (J3.15: 58.7 + 6.3 = 65): legal, ③ is no move.
    let t = run("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3.15 K1\n");
    let last3: Vec<(MoveKind, i64, i64)> = t.moves().skip(3).map(|m| (m.kind, m.x, m.z)).collect();
    assert_eq!(last3, vec![(MoveKind::Thread, 65_000, -28_000), (MoveKind::Rapid, 65_000, 5_000)]);
    // Internal (s = −1): the pull-out toward −X beyond A.x.
    assert_eq!(alarm_with("G0 X20 Z5\nG92 X26 Z-20 F2 J4\n", &Config::default()), geometry_j);
    assert_eq!(run("G0 X20 Z5\nG92 X26 Z-20 F2 J3\n").alarm, None);
    // A modal repeat is checked again: X57 with J5 still ends beyond X65 (57 + 10 = 67)…
    assert_eq!(
        alarm_with("G0 X65 Z5\nG92 X50 Z-28 F3 J5 K1\nX57\n", &Config::default()),
        (AlarmCode::Geometry, Some('J'), Rule::G92Path, 3)
    );
    // Order: K against the long axis, then the pass bound, then step ③.
    assert_eq!(alarm_with("G0 X65 Z5\nG92 X58.7 Z-28 F3 J5 K40\n", &Config::default()), (AlarmCode::Geometry, Some('K'), Rule::G92Pullout, 2));
    let one = with_params(Params { max_passes: Some(1), ..Params::default() });
    assert_eq!(alarm_with("G0 X65 Z5\nG92 X58.7 Z-28 F3 J5 K1 L2\n", &one), (AlarmCode::TooManyPasses, Some('L'), Rule::PrjMaxPass, 2));
}

/// The letter `thread.zref=start` (the default) against `groove`, G78 modes 4, 0, 3 and G76
/// e = 2 on one thread: k 1, d 0.1 (T 0.9), Δd 0.5, a 60°: depths 0.5, 0.707, 0.866, 0.9 with
/// t = 0.289, 0.408, 0.500, 0.520; external, σ = −1; X 61, 60.586, 60.268, 60.2, finish 60.
#[test]
fn infeed_z_by_reading() {
    let xs = [61_000, 60_586, 60_268, 60_200, 60_000];
    let case = |first: &str, second: &str, config: &Config| -> Vec<i64> {
        let t = run_with(&format!("G0 X70 Z5\n{first}\n{second}\n"), config);
        let pts = infeeds(&t);
        assert_eq!(pts.iter().map(|p| p.1).collect::<Vec<_>>(), xs);
        assert_eq!(pts.last().map(|p| p.0), Some(PassKind::Finish));
        pts.iter().map(|p| p.2).collect()
    };
    let (start, groove) = (zref(ThreadZRef::Start), zref(ThreadZRef::Groove));
    let g78 = |mode: &str| format!("G78 P01{mode}60 Q0.1 R0.1");
    let second78 = "G78 X60 Z-30 P1 Q0.5 F2 J0";
    // Mode 4, odd left, even right. start: left A.z + t, right A.z − t; finish at pass 4's Z.
    assert_eq!(case(&g78("04"), second78, &Config::default()), vec![5_289, 4_592, 5_500, 4_480, 4_480]);
    assert_eq!(case(&g78("04"), second78, &start), vec![5_289, 4_592, 5_500, 4_480, 4_480]);
    // groove: left A.z − (2·t(T) − t) = 5 − (1.040 − t).
    assert_eq!(case(&g78("04"), second78, &groove), vec![4_249, 4_592, 4_460, 4_480, 4_480]);
    // Mode 0, centre: A.z itself under the letter; A.z − t(T) under groove.
    assert_eq!(case(&g78("00"), second78, &Config::default()), vec![5_000; 5]);
    assert_eq!(case(&g78("00"), second78, &groove), vec![4_480; 5]);
    // Mode 3, odd right, even centre: the finishing Z follows pass 4 (centre).
    assert_eq!(case(&g78("03"), second78, &Config::default()), vec![4_711, 5_000, 4_500, 5_000, 5_000]);
    assert_eq!(case(&g78("03"), second78, &groove), vec![4_711, 4_480, 4_500, 4_480, 4_480]);
    // G76 e = 2 is G78 mode 4 again (the same degressive depths).
    let g76 = ("G76 P010060 Q0.1 R0.1 D2", "G76 X60 Z-30 P1 Q0.5 F2");
    assert_eq!(case(g76.0, g76.1, &Config::default()), vec![5_289, 4_592, 5_500, 4_480, 4_480]);
    assert_eq!(case(g76.0, g76.1, &groove), vec![4_249, 4_592, 4_460, 4_480, 4_480]);
    // The right flank (G76 e = 0, G78 mode 2) is the same under both.
    for (first, second) in [("G76 P010060 Q0.1 R0.1", "G76 X60 Z-30 P1 Q0.5 F2"), (g78("02").as_str(), second78)] {
        assert_eq!(case(first, second, &start), vec![4_711, 4_592, 4_500, 4_480, 4_480]);
        assert_eq!(case(first, second, &groove), vec![4_711, 4_592, 4_500, 4_480, 4_480]);
    }
    // Internal (s = −1, σ = +1): mode 1 (left) under the letter runs A.z − t.
    let t = run("G0 X50 Z5\nG78 P010160 Q0.1 R0.1\nG78 X60 Z-30 P1 Q0.5 F2 J0\n");
    let z: Vec<i64> = infeeds(&t).iter().map(|p| p.2).collect();
    assert_eq!(z, vec![4_711, 4_592, 4_500, 4_480, 4_480]);
}
