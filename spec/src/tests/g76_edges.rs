//! G76/G78 edges the spec-alone mutation run left open (docs/MUTATION.md, "G76/G78 completed
//! (fifth session…)"), each worked by hand from docs/INTERPRETATION.md, "G76, G78".

use crate::expand;
use crate::tests::util::{alarm_with, passes, run};
use cycle_vocab::{AlarmCode, Config, Dialect, MoveKind, PassKind, Rule};

/// COM.POINTS (INTERPRETATION.md line 250, "Points": B.x = C.x + s·k, A must not lie between B and
/// C: s·(A.x − B.x) ≥ 0). C.x = 60, k = 1: B.x = 62. A at X62 is B itself: legal. A at X61.999 lies
/// between: GEOMETRY on X. And with E = 0 (no lead-in, G76.LEADIN) the pass starts with one rapid
/// to Bn (G76.INFEED.X), then the thread (G76.PATH): δ 0.5 → X = 60 + 2·(1 − 0.5) = 61, Z = 5 −
/// round(0.5·tan 30°) = 4.711, W = −25 → thread to Z −20.289.
#[test]
fn g76_start_on_b_is_legal() {
    let t = run("G0 X62 Z5\nG76 P010060 Q0 R0.1\nG76 X60 Z-20 P1 Q0.5 F2\n");
    let m: Vec<_> = t
        .moves()
        .skip(1)
        .take(2)
        .map(|m| (m.kind, m.x, m.z, m.rule))
        .collect();
    assert_eq!(
        m,
        vec![
            (MoveKind::Rapid, 61_000, 4_711, Rule::G76InfeedX),
            (MoveKind::Thread, 61_000, -20_289, Rule::G76Path)
        ]
    );
    let between = alarm_with(
        "G0 X61.999 Z5\nG76 P010060 Q0 R0.1\nG76 X60 Z-20 P1 Q0.5 F2\n",
        &Config::default(),
    );
    assert_eq!(
        between,
        (AlarmCode::Geometry, Some('X'), Rule::ComPoints, 3)
    );
}

/// PRJ.MAXPASS (INTERPRETATION.md line 264: (rough passes + m) × L must not exceed `max_passes`). T
/// = 1 − 0.1 = 0.9, Δd 0.5: rough depths √n·Δd (`001_…` line 29) 0.5, 0.707, 0.866, then 1.0 ≥ T →
/// 0.9: 4 rough passes; m = 2: 6 passes. A bound of 6 runs, 5 is TOO MANY PASSES on Q.
#[test]
fn g76_pass_bound_is_rough_plus_finish() {
    let src = "G0 X62 Z5\nG76 P020060 Q0 R0.1\nG76 X60 Z-20 P1 Q0.5 F2\n";
    let mut c = Config::default();
    c.params.max_passes = Some(6);
    let t = expand(src.as_bytes(), &c);
    assert_eq!(t.alarm, None);
    let kinds: Vec<PassKind> = passes(&t).iter().map(|p| p.1).collect();
    use PassKind::*;
    assert_eq!(kinds, vec![Rough, Rough, Rough, Rough, Finish, Spring]);
    c.params.max_passes = Some(5);
    assert_eq!(
        alarm_with(src, &c),
        (AlarmCode::TooManyPasses, Some('Q'), Rule::PrjMaxPass, 3)
    );
}

/// F76.FORMAT (register "PRJ.DIALECT — FANUC G76 words", line 46): the FANUC second block has no
/// pull-out words (`003_…` line 135: G76 X(U) Z(W) Ri Pk QΔd Ff); J and K are refused under the
/// FANUC dialect (WORD NOT ALLOWED), and are the pull-out under GSK.
#[test]
fn f76_second_block_refuses_j_and_k() {
    let fanuc = Config {
        dialect: Dialect::Fanuc,
        ..Config::default()
    };
    for w in ['J', 'K'] {
        let src = format!("G0 X60 Z10\nG76 P011060 Q0.1 R0.1\nG76 X33.8 Z-60 P2.4 Q0.7 F4 {w}1\n");
        assert_eq!(
            alarm_with(&src, &fanuc),
            (AlarmCode::WordNotAllowed, Some(w), Rule::F76Format, 3)
        );
        assert_eq!(expand(src.as_bytes(), &Config::default()).alarm, None);
    }
}
