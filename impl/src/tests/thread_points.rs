//! Group A points 1–4 (issue #29) on the whole expander: G78 J/K modal (G76's not kept), the
//! FANUC tool angle 40, No.5131 for G92 (JK.1 only), and G92 step ③ opposite to ① (DEPARTS:
//! GEOMETRY on J, rule G92.PATH, the last of the G92 checks, before any motion).
extern crate std;

use crate::tests::{expand, fanuc, moves, passes};
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, AlarmCode, Config, Event, Move, MoveKind, Params, Rule};
use std::vec::Vec;

fn geo(word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(AlarmCode::Geometry, Some(word), rule, line))
}

/// Each pull-out move as (its start, its end): the thread move before it ends where it starts.
fn pullouts(t: &Trace, rule: Rule) -> Vec<((i64, i64), (i64, i64))> {
    let m = moves(t);
    m.windows(2).filter(|w| w[1].rule == rule).map(|w| ((w[0].x, w[0].z), (w[1].x, w[1].z))).collect()
}

/// The pull-outs of cycle number `cycle` (0-based; a cycle starts at a pass header of index 1).
fn cycle_pullouts(t: &Trace, rule: Rule, cycle: usize) -> Vec<((i64, i64), (i64, i64))> {
    let mut out = Vec::new();
    let mut n = 0usize;
    let mut prev = None;
    for e in &t.events {
        match e {
            Event::Pass(p) if p.index == 1 => n += 1,
            Event::Move(m) if m.rule == rule && n == cycle + 1 => out.push((prev.unwrap(), (m.x, m.z))),
            _ => {}
        }
        if let Event::Move(m) = e {
            prev = Some((m.x, m.z));
        }
    }
    out
}

const G78_TWICE: &str = "G0 X70 Z5\nG78 X60 Z-60 P3 Q1.8 F3 J1.5 K2\nG78 X60 Z-60 P3 Q1.8\n";

/// Point 1: a G78 second block without J and K takes both from the last G78 second block that
/// wrote them (`000_…` lines 59, 61): J1.5 K2 pull out in both cycles — every pull-out starts
/// 2 mm before Z-60 and ends 3 mm out on the diameter.
#[test]
fn g78_j_and_k_are_modal() {
    let t = expand(G78_TWICE, Config::default());
    assert_eq!(t.alarm, None);
    for cycle in 0..2 {
        let p = cycle_pullouts(&t, Rule::G78Pullout, cycle);
        assert!(!p.is_empty(), "cycle {cycle}");
        for (from, to) in p {
            assert_eq!((from.1, to.1, to.0 - from.0), (-58_000, -60_000, 3_000), "cycle {cycle}");
        }
    }
    // Each word on its own: J1 is written, K2 kept.
    let t = expand(&std::format!("{G78_TWICE}G78 X60 Z-60 P3 Q1.8 J1\n"), Config::default());
    assert_eq!(t.alarm, None);
    for (from, to) in cycle_pullouts(&t, Rule::G78Pullout, 2) {
        assert_eq!((from.1, to.0 - from.0), (-58_000, 2_000));
    }
    // A first block in between keeps them (they belong to the second blocks, for the program).
    let t = expand("G0 X70 Z5\nG78 X60 Z-60 P3 Q1.8 F3 J1.5 K2\nG78 P010060\nG78 X60 Z-60 P3 Q1.8\n", Config::default());
    assert!(cycle_pullouts(&t, Rule::G78Pullout, 1).iter().all(|(f, to)| (f.1, to.0 - f.0) == (-58_000, 3_000)));
    // G92's J/K are apart from G78's: a G78 without J/K after a G92 J0.5 K0.5 takes 5130/5131
    // (one lead at 45°: 3 mm each way), and the G92 run keeps its own.
    let t = expand("G0 X70 Z5\nG92 X60 Z-60 F3 J0.5 K0.5\nG78 X60 Z-60 P3 Q1.8\n", Config::default());
    assert_eq!(t.alarm, None);
    assert!(pullouts(&t, Rule::G78Pullout).iter().all(|(f, to)| (f.1, to.0 - f.0) == (-57_000, 6_000)));
    assert_eq!(pullouts(&t, Rule::G92Pullout), [((60_000, -59_500), (61_000, -60_000))]);
}

/// Point 1: G76's J and K are not kept (OPEN): the second G76 takes 5130/5131 (3 mm, 45°).
#[test]
fn g76_j_and_k_are_not_kept() {
    let t = expand(&G78_TWICE.replace("G78", "G76"), Config::default());
    assert_eq!(t.alarm, None);
    // The passes move along the flank in Z (e = 0): the pull-out's own travel (ΔZ, ΔX) tells.
    assert!(cycle_pullouts(&t, Rule::G76Pullout, 0).iter().all(|(f, to)| (to.1 - f.1, to.0 - f.0) == (-2_000, 3_000)));
    let second = cycle_pullouts(&t, Rule::G76Pullout, 1);
    assert!(!second.is_empty());
    assert!(second.iter().all(|(f, to)| (to.1 - f.1, to.0 - f.0) == (-3_000, 6_000)));
}

/// Point 2: under `fanuc` the tool angle 40 is legal, in P and in 5143 (`003_…` line 5); the
/// infeed Z uses tan 20°: pass 1 at depth 0.4 shifts by round(400·0.36397) = 146.
#[test]
fn fanuc_tool_angle_40() {
    let t = expand("G0 X40 Z5\nG76 P011040 Q0.1 R0.05\nG76 X27.4 Z-20 P1.3 Q0.4 F2\n", fanuc());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t)[1], Move::rapid(29_200, 4_854, Rule::G76Path));
    let t = expand("G0 X40 Z5\nG76 P011045 Q0.1 R0.05\n", fanuc());
    assert_eq!(t.alarm, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'P'), Rule::F76Format, 2)));
    let with = |a: i64| Config { params: Params { p5143_tool_angle: Some(a), ..Params::default() }, ..fanuc() };
    assert_eq!(expand("G0 X40 Z5\n", with(40)).alarm, None);
    // 5143 = 40: the default angle of a FANUC first block without P.
    let t = expand("G0 X40 Z5\nG76 Q0.1 R0.05\nG76 X27.4 Z-20 P1.3 Q0.4 F2\n", with(40));
    assert_eq!(moves(&t)[1], Move::rapid(29_200, 4_854, Rule::G76Path));
    assert_eq!(expand("G0 X40 Z5\n", with(45)).alarm, Some(Alarm::new(AlarmCode::OutOfRange, None, Rule::F76Format, 0)));
}

/// Point 3: No.5131 for G92 — JK.1 (J and K omitted): K = c (No.19: one lead, 3 mm),
/// J = round(c·tan 5131°): 45° gives J = 3 (X64.7), 30° J = round(1.732 05) = 1.732 (X62.164);
/// JK.2 (K given) keeps J = c whatever 5131.
#[test]
fn no5131_for_g92() {
    let p5131 = |a: i64| Config { params: Params { p5131_chamfer_angle: Some(a), ..Params::default() }, ..Config::default() };
    let src = "G0 X65 Z5\nG92 X58.7 Z-28 F3\n";
    assert_eq!(pullouts(&expand(src, Config::default()), Rule::G92Pullout), [((58_700, -25_000), (64_700, -28_000))]);
    assert_eq!(pullouts(&expand(src, p5131(30)), Rule::G92Pullout), [((58_700, -25_000), (62_164, -28_000))]);
    // 5131 = 1°: J = round(3000·tan 1°) = round(52.36) = 52 µm.
    assert_eq!(pullouts(&expand(src, p5131(1)), Rule::G92Pullout), [((58_700, -25_000), (58_804, -28_000))]);
    let src = "G0 X65 Z5\nG92 X58.7 Z-28 F3 K1\n";
    assert_eq!(pullouts(&expand(src, p5131(30)), Rule::G92Pullout), [((58_700, -27_000), (64_700, -28_000))]);
}

/// Point 4: G92 step ③ opposite to ① (DEPARTS) — the register's program ends its pull-out at
/// X68.7, beyond A.x = 65: GEOMETRY on J, rule G92.PATH, before any motion of the cycle;
/// X₃ = A.x is legal (③ is then no move); internal threads mirror it.
#[test]
fn g92_step_3_opposite_to_step_1() {
    let t = expand("G0 X65 Z5\nG92 X58.7 Z-28 F3 J5 K1\n", Config::default());
    assert_eq!((t.alarm, t.events.len()), (geo(b'J', Rule::G92Path, 2), 1));
    // X₃ = 58.7 + 2·3.15 = 65 = A.x: legal, ③ not emitted (PRJ.NOOP): ④ follows the pull-out.
    let t = expand("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3.15 K1\n", Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[3..], [Move::thread(65_000, -28_000, 30_000, 0, Rule::G92Pullout), Move::rapid(65_000, 5_000, Rule::G92Path)]);
    assert_eq!(expand("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3.151 K1\n", Config::default()).alarm, geo(b'J', Rule::G92Path, 2));
    // Internal (s = −1): X₃ = 26 − 8 = 18 below A.x = 20.
    assert_eq!(expand("G0 X20 Z5\nG92 X26 Z-28 F3 J4 K1\n", Config::default()).alarm, geo(b'J', Rule::G92Path, 2));
    assert_eq!(expand("G0 X20 Z5\nG92 X26 Z-28 F3 J3 K1\n", Config::default()).alarm, None);
    // The default pull-out (J = one lead) counts too: X29.2 + 6 = 35.2 beyond X35.
    assert_eq!(expand("G0 X35 Z5\nG92 X29.2 Z-20 F3\n", Config::default()).alarm, geo(b'J', Rule::G92Path, 2));
    // X long (|R| ≥ |W|: the pull-out's short axis is Z): X₃ = D.x = 45, not beyond A.x = 46
    // (J5 on X would end at X55).
    assert_eq!(expand("G0 X46 Z5\nG92 X45 Z3 R-8 F1 J5 K1\n", Config::default()).alarm, None);
    // In a modal run the earlier cycles stay; the refused one has no event.
    let t = expand("G0 X65 Z5\nG92 X60 Z-28 F3 J2 K1\nX62\n", Config::default());
    assert_eq!((t.alarm, passes(&t).len()), (geo(b'J', Rule::G92Path, 3), 1));
    assert_eq!(t.events.last(), Some(&Event::Move(Move::rapid(65_000, 5_000, Rule::G92Path))));
}

/// Point 4, the check order: step ③ is checked last — after W = 0 (G92.FORMAT), the taper, the
/// side, No.107, K against the travel (G92.PULLOUT) and the pass bound (PRJ.MAXPASS).
#[test]
fn g92_step_3_is_the_last_check() {
    let c = Config::default();
    assert_eq!(expand("G0 X65 Z5\nG92 X58.7 Z5 F3 J5 K1\n", c).alarm, geo(b'Z', Rule::G92Format, 2));
    assert_eq!(expand("G0 X65 Z5\nG92 X58.7 Z-28 F3 J5 K40\n", c).alarm, geo(b'K', Rule::G92Pullout, 2));
    let few = Config { params: Params { max_passes: Some(2), ..Params::default() }, ..c };
    assert_eq!(
        expand("G0 X65 Z5\nG92 X58.7 Z-28 F3 J5 K1 L3\n", few).alarm,
        Some(Alarm::new(AlarmCode::TooManyPasses, Some(b'L'), Rule::PrjMaxPass, 2))
    );
    let no107 = Config { params: Params { no107_pullout_speed: Some(1), ..Params::default() }, ..c };
    assert_eq!(
        expand("G0 X65 Z5\nG92 X58.7 Z-28 F3 J5 K1\n", no107).alarm,
        Some(Alarm::new(AlarmCode::Unsupported, None, Rule::G92Jk8, 2))
    );
    // G76/G78 are not affected: their step (5) says only "rapid along X".
    let t = expand("G0 X65 Z5\nG76 X58.7 Z-28 P1 Q0.4 F3 J5 K1\n", c);
    assert_eq!(t.alarm, None);
    assert!(t.moves().any(|m| m.kind == MoveKind::Thread && m.x == 68_700));
}

