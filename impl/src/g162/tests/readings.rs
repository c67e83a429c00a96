//! Group A point 9 (issue #29): G162 under the declared reading g162.lead (`steps`, the letter,
//! and `continuous`) with the growing-pitch bound of each, the single pass's X as the END of
//! segment ② (G162.X), and A on the 0.1° grid (G162.A).
extern crate std;

use super::programs::continuous;
use crate::tests::{expand, moves};
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, MoveKind, Rule};
use std::vec::Vec;

fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

fn threads(t: &Trace) -> Vec<Move> {
    t.moves().filter(|m| m.kind == MoveKind::Thread).copied().collect()
}

fn alarm_of(src: &str, c: Config) -> Option<Alarm> {
    expand(src, c).alarm
}

const GROWING_I: Option<Alarm> = Some(Alarm::new(AlarmCode::Geometry, Some(b'I'), Rule::G162I, 2));

/// `steps` (the letter): the thread move carries I, J, the floor and `lead_steps`; a constant
/// lead (I = 0, or a shrinking F ≤ |I|) stays a plain thread move. `continuous`: the same fields
/// without `lead_steps`.
#[test]
fn stepped_lead() {
    let src = "G0 X50 Z5\nG162 X44 Z-30 H600 F3 I-0.5 J180 B90\n";
    let want = Move::variable_thread(44_000, -30_000, 30_000, 90_000, -5_000, 180_000, 5_000, Rule::G162F);
    let th = threads(&expand(src, nc201()));
    assert_eq!(th, [want.stepped()]);
    assert!(th[0].lead_steps);
    assert_eq!(threads(&expand(src, continuous())), [want]);
    let th = threads(&expand("G0 X50 Z5\nG162 X44 Z-30 H600 F2 I0.01\n", nc201()));
    assert_eq!(th, [Move::variable_thread(44_000, -30_000, 20_000, 0, 100, 360_000, 0, Rule::G162F).stepped()]);
    for constant in ["F0.5 I-0.5", "F0.5 I-0.6", "F2 I0", "F2 J90"] {
        let th = threads(&expand(&std::format!("G0 X50 Z5\nG162 X44 Z-30 H600 {constant}\n"), nc201()));
        assert_eq!((th[0].lead_change, th[0].lead_steps), (0, false), "{constant}");
    }
    // Every pass of a multi-pass cycle is stepped.
    let th = threads(&expand("G0 X50 Z5\nG162 X44 Z-30 H600 P1 Q0.3 F3 I-0.5\n", nc201()));
    // P1 Q0.3: 0.3, 0.6, 0.9, then 0.95, 0.975, 0.988, 1.0 (G162.SPLIT).
    assert_eq!(th.len(), 7);
    assert!(th.iter().all(|m| m.lead_steps && m.lead_change == -5_000 && m.lead_floor == 5_000));
}

/// The growing-pitch bound under `steps`: with k* = ⌊(Fmax − F)/I⌋ + 1 the first step above
/// Fmax, (2·k*·F + I·k*·(k* − 1))·J < 360 000·s2 is GEOMETRY on I (G162.I).
#[test]
fn stepped_growing_bound() {
    let (steps, cont) = (nc201(), continuous());
    // F = Fmax, I = 1 count: k* = 1, the step comes after one revolution = 9999 mm of travel;
    // s2 = 20·|ΔZ| (ISB): 2·F·360 000 = 360 000·s2 exactly at |ΔZ| = 9999 mm — not refused
    // (the step falls at the end of ②); one increment more is. Continuous refuses any growth.
    let f_max = |z: &str| std::format!("G0 X50 Z5\nG162 X44 Z{z} H600 F9999 I0.0001\n");
    assert_eq!(alarm_of(&f_max("-30"), steps), None);
    assert_eq!(alarm_of(&f_max("-30"), cont), GROWING_I);
    assert_eq!(alarm_of(&f_max("-9994"), steps), None);
    assert_eq!(alarm_of(&f_max("-9994.001"), steps), GROWING_I);
    // F = Fmax − 10 counts, I = 10 counts, J = 0.001°: k* = 2, (4F + 2I)·1 = 399 959 980 against
    // 7 200 000·|ΔZ|: |ΔZ| = 55 increments fits, 56 does not. Continuous refuses 55 already:
    // 360 000·I·s2 = 3.96·10^9 > J·(Fmax² − F²) = 1 999 799 900.
    let edge = |z: &str| std::format!("G0 X50 Z5\nG162 X44 Z{z} H600 F9998.999 I0.001 J0.001\n");
    assert_eq!(alarm_of(&edge("4.945"), steps), None);
    assert_eq!(alarm_of(&edge("4.944"), steps), GROWING_I);
    assert_eq!(alarm_of(&edge("4.945"), cont), GROWING_I);
    // X the long axis (|Wd| = 4 mm > 2·|ΔZ|): s2 = 40 000 counts, 360 000·s2 = 1.44·10^10;
    // k* = 1 at F = Fmax: 2·F·J = 199 980 000 at J0.001 is less (refused), 7.2·10^13 at J360
    // is not.
    let x_long = |j: &str| std::format!("G0 X50 Z5\nG162 X44 Z4.999 W4 H600 F9999 I0.0001 J{j}\n");
    assert_eq!(alarm_of(&x_long("0.001"), steps), GROWING_I);
    assert_eq!(alarm_of(&x_long("360"), steps), None);
    // A shrinking pitch is never bounded.
    assert_eq!(alarm_of("G0 X50 Z5\nG162 X44 Z-9000 H600 F9999 I-0.0001 J0.001\n", steps), None);
    // Nor a constant one (I0, G162.I: only I > 0 is checked), where a growth of one count per
    // 0.001° would be refused after 0.028 mm: k* = 1, 2·F·J = 199 980 000 < 7.2·10^6·|ΔZ|.
    let constant = |i: &str| std::format!("G0 X50 Z5\nG162 X44 Z-30 H600 F9999 I{i} J0.001\n");
    assert_eq!(alarm_of(&constant("0"), steps), None);
    assert_eq!(alarm_of(&constant("0.0001"), steps), GROWING_I);
    // One step goes beyond Fmax (F1 I9999: k* = 1, no step of I·k*(k* − 1) before it): the
    // step comes after one revolution, 1 mm of Z (s2 = 20 000 = 2F) — allowed exactly there
    // (the step falls at the end of ②), refused one increment further and far beyond.
    let one_step = |z: &str| std::format!("G0 X50 Z5\nG162 X44 Z{z} H600 F1 I9999\n");
    assert_eq!(alarm_of(&one_step("4"), steps), None);
    assert_eq!(alarm_of(&one_step("3.999"), steps), GROWING_I);
    assert_eq!(alarm_of(&one_step("-30"), steps), GROWING_I);
}

/// G162.X: a single pass's X word is the END of segment ②, which starts at X − Wd; the side, the
/// checks and the path use that start. Without a taper nothing changes.
#[test]
fn single_pass_x_is_the_end() {
    let h = 5_000_000;
    let t = expand("G0 X30 Z5\nG162 X23 Z-20 W2 H500 F1.5\n", nc201());
    assert_eq!(t.alarm, None);
    assert_eq!(
        moves(&t)[1..],
        [
            Move::feed(21_000, 5_000, h, Rule::G162Path),
            Move::thread(23_000, -20_000, 15_000, 0, Rule::G162F),
            Move::feed(30_000, -20_000, h, Rule::G162Retract),
            Move::feed(30_000, 5_000, h, Rule::G162Path),
        ]
    );
    assert_eq!(expand("G0 X30 Z5\nG91 G162 X-7 Z-25 W2 H500 F1.5\n", nc201()), t);
    // A negative taper starts above X; the leg leaves from the end.
    let m = moves(&expand("G0 X30 Z5\nG162 X23 Z-20 W-2 V1 H500 F1.5\n", nc201()));
    assert_eq!([(m[1].x, m[1].z), (m[2].x, m[2].z), (m[3].x, m[3].z)], [(25_000, 5_000), (23_000, -19_000), (25_000, -20_000)]);
    // The side from the start X − Wd: S.x = 21 is no side; from S.x = 22 (external) the end
    // X23 lies beyond S on the retract side.
    let geo_x = Some(Alarm::new(AlarmCode::Geometry, Some(b'X'), Rule::G162Retract, 2));
    assert_eq!(alarm_of("G0 X21 Z5\nG162 X23 Z-20 W2 H500 F1.5\n", nc201()), geo_x);
    assert_eq!(alarm_of("G0 X22 Z5\nG162 X23 Z-20 W2 H500 F1.5\n", nc201()), geo_x);
    // Multi-pass: X is the depth-0 line at the start, as before.
    let th = threads(&expand("G0 X30 Z5\nG162 X23 Z-20 W2 H500 P1 Q1 F1.5\n", nc201()));
    assert_eq!((th[0].x, th[0].z), (23_000, -20_000));
    let m = moves(&expand("G0 X30 Z5\nG162 X23 Z-20 W2 H500 P1 Q1 F1.5\n", nc201()));
    assert_eq!(m[1], Move::feed(21_000, 5_000, h, Rule::G162Path));
    let m = moves(&expand("G0 X30 Z5\nG162 X23 Z-20 W4 H500 P1 Q1 F1.5\n", nc201()));
    assert_eq!((m[1].x, m[2].x), (21_000, 25_000));
}

/// G162.A on the 0.1° grid: any tenth, t(d) = round(d·tan|A|) exact.
#[test]
fn infeed_angle_in_tenths() {
    let z = |a: &str, pass: usize| {
        let t = expand(&std::format!("G0 X30 Z5\nG162 X24 Z-20 H500 P1.2 Q0.5 A{a} F1.5\n"), nc201());
        assert_eq!(t.alarm, None, "A{a}");
        threads(&t)[pass].z + 20_000
    };
    // tan 27.3° = 0.516 138: t(0.5) = 258, t(1.0) = 516.
    assert_eq!((z("27.3", 0), z("27.3", 1)), (258, 516));
    // tan 0.1° = 0.001 745 3: t(0.5) = round(0.87) = 1, t(1.2) = round(2.09) = 2; A−0.1 mirrors.
    assert_eq!((z("0.1", 0), z("0.1", 5), z("-0.1", 0)), (1, 2, -1));
    // tan 88.9° = 52.080 67: t(1.0) = 52 081; tan 89° = 57.289 96: t(0.5) = 28 645.
    assert_eq!((z("88.9", 1), z("89", 0), z("-89.0", 0)), (52_081, 28_645, -28_645));
    // Half degrees as before: A29.5 → t(0.5) = 283; A30 → 289.
    assert_eq!((z("29.5", 0), z("30", 0)), (283, 289));
    let bad = |a: &str, code: AlarmCode| {
        let src = std::format!("G0 X30 Z5\nG162 X24 Z-20 H500 A{a} F1.5\n");
        assert_eq!(alarm_of(&src, nc201()), Some(Alarm::new(code, Some(b'A'), Rule::G162A, 2)), "A{a}");
    };
    bad("27.35", AlarmCode::Precision);
    bad("89.1", AlarmCode::OutOfRange);
    bad("-89.1", AlarmCode::OutOfRange);
}
