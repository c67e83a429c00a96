//! Operator events (docs/INTERPRETATION.md, "Operator events"), plain moves and G92: every
//! interrupted run below is worked out by hand from the register, not taken from the spec.

use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{Action, Alarm, AlarmCode, Along, Config, Event, Params, Rule, Script};

/// The register's worked example. U: 0 `G00 X65 Z5`; 1 the pass header; 2 `G00 X58.7 Z5`;
/// 3 `G32 X58.7 Z-27`; 4 the pull-out `G32 X64.7 Z-28`; 5 `G00 X65 Z-28`; 6 `G00 X65 Z5`.
pub const EXAMPLE: &str = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n";

pub fn hold(event: u32, num: u32, den: u32) -> Action {
    Action::Hold(Along { event, num, den })
}

pub fn reset(event: u32, num: u32, den: u32) -> Action {
    Action::Reset(Along { event, num, den })
}

pub fn single(on: bool, before: u32) -> Action {
    Action::SingleBlock { on, before }
}

pub fn bit6(v: i64) -> Config {
    Config { params: Params { no18_bit6_hold: Some(v), ..Params::default() }, ..Config::default() }
}

pub fn play(src: &str, config: &Config, actions: &[Action]) -> Trace {
    expand(src.as_bytes(), &Config { operator: Script::of(actions).unwrap(), ..*config })
}

/// The trace's lines without its header, each event's rule appended after ` ; `.
pub fn lines(t: &Trace) -> Vec<String> {
    t.to_gcode().lines().skip(1).zip(&t.events).map(|(l, e)| format!("{l} ; {}", e.rule().id())).collect()
}

/// The lines of U, the uninterrupted trace.
pub fn u_lines(src: &str, config: &Config) -> Vec<String> {
    lines(&expand(src.as_bytes(), config))
}

pub fn operator_alarm(rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(AlarmCode::Operator, None, rule, line))
}

/// G92.HOLD bit 6 = 0, OP.RESUME: the register's example, event by event.
#[test]
fn worked_example_bit6_0() {
    let t = play(EXAMPLE, &bit6(0), &[hold(3, 1, 2), Action::Start]);
    let u = u_lines(EXAMPLE, &Config::default());
    let interrupted = [
        "(PRESS HOLD AT X58.700 Z-11.000) ; G92.HOLD",
        "G32 X58.700 Z-11.000 F3.0000 ; G92.PATH",
        "G32 X64.700 Z-12.000 F3.0000 ; G92.HOLD",
        "G00 X65.000 Z-12.000 ; G92.HOLD",
        "G00 X65.000 Z5.000 ; G92.HOLD",
        "(STOP FEED HOLD) ; G92.HOLD",
        "(CYCLE START) ; OP.RESUME",
    ];
    let expected: Vec<String> = u[..3].iter().cloned().chain(interrupted.map(String::from)).chain(u[1..].iter().cloned()).collect();
    assert_eq!(lines(&t), expected);
    assert_eq!(t.alarm, None);
}

/// G92.HOLD bit 6 = 1: runs on to the pull-out's end, stops before ③.
#[test]
fn worked_example_bit6_1() {
    let t = play(EXAMPLE, &bit6(1), &[hold(3, 1, 2), Action::Start]);
    let u = u_lines(EXAMPLE, &Config::default());
    let mut expected = u[..3].to_vec();
    expected.push("(PRESS HOLD AT X58.700 Z-11.000) ; G92.HOLD".into());
    expected.extend(u[3..5].iter().cloned());
    expected.push("(STOP FEED HOLD) ; G92.HOLD".into());
    expected.push("(CYCLE START) ; OP.RESUME".into());
    expected.extend(u[5..].iter().cloned());
    assert_eq!(lines(&t), expected);
}

/// OP.HOLD on a plain rapid (from X0 Z0 to X65 Z5), resumed.
#[test]
fn hold_on_a_rapid_and_resume() {
    let t = play(EXAMPLE, &bit6(0), &[hold(0, 1, 4), Action::Start]);
    let u = u_lines(EXAMPLE, &Config::default());
    let mut expected: Vec<String> = [
        "(PRESS HOLD AT X16.250 Z1.250) ; OP.HOLD",
        "G00 X16.250 Z1.250 ; PRJ.MODAL",
        "(STOP FEED HOLD) ; OP.HOLD",
        "(CYCLE START) ; OP.RESUME",
    ]
    .map(String::from)
    .to_vec();
    expected.extend(u.iter().cloned());
    assert_eq!(lines(&t), expected);
    // A G92 rapid (①, event 2: X65 → X58.7) is OP.HOLD too: 65 − trunc(6.3/3) = 62.9.
    let t = play(EXAMPLE, &bit6(0), &[hold(2, 1, 3), Action::Start]);
    assert_eq!(lines(&t)[2..6], ["(PRESS HOLD AT X62.900 Z5.000) ; OP.HOLD", "G00 X62.900 Z5.000 ; G92.PATH", "(STOP FEED HOLD) ; OP.HOLD", "(CYCLE START) ; OP.RESUME"]);
    assert_eq!(lines(&t)[6..], u[2..]);
}

/// Two holds on the same move: the second one lies in the rest [1/4, 1]. Placed before the
/// first's point, it is never passed again (OP.REACH).
#[test]
fn two_holds_on_one_move() {
    let t = play(EXAMPLE, &bit6(0), &[hold(0, 1, 4), Action::Start, hold(0, 1, 2), Action::Start]);
    let l = lines(&t);
    assert_eq!(
        l[..8],
        [
            "(PRESS HOLD AT X16.250 Z1.250) ; OP.HOLD",
            "G00 X16.250 Z1.250 ; PRJ.MODAL",
            "(STOP FEED HOLD) ; OP.HOLD",
            "(CYCLE START) ; OP.RESUME",
            "(PRESS HOLD AT X32.500 Z2.500) ; OP.HOLD",
            "G00 X32.500 Z2.500 ; PRJ.MODAL",
            "(STOP FEED HOLD) ; OP.HOLD",
            "(CYCLE START) ; OP.RESUME",
        ]
    );
    assert_eq!(l[8], "G00 X65.000 Z5.000 ; PRJ.MODAL");
    assert_eq!(t.alarm, None);
    // The same fraction twice: passed again at the very point where the rest begins.
    let t = play(EXAMPLE, &bit6(0), &[hold(0, 1, 2), Action::Start, hold(0, 2, 4), Action::Start]);
    assert_eq!(t.events.iter().filter(|e| matches!(e, Event::Press(_))).count(), 2);
    assert_eq!(t.alarm, None);
    // Behind the first point: not passed by the rest [1/2, 1].
    let t = play(EXAMPLE, &bit6(0), &[hold(0, 1, 2), Action::Start, hold(0, 1, 4), Action::Start]);
    assert_eq!(t.alarm, operator_alarm(Rule::OpReach, 0));
    assert_eq!(lines(&t)[4..], u_lines(EXAMPLE, &Config::default())[..]);
}

/// Fractions 0 and 1: the move to P, or the rest, has no length and is omitted (PRJ.NOOP).
#[test]
fn hold_at_fraction_0_and_1() {
    let u = u_lines(EXAMPLE, &Config::default());
    let t = play(EXAMPLE, &bit6(0), &[hold(0, 0, 7), Action::Start]);
    assert_eq!(lines(&t)[..3], ["(PRESS HOLD AT X0.000 Z0.000) ; OP.HOLD", "(STOP FEED HOLD) ; OP.HOLD", "(CYCLE START) ; OP.RESUME"]);
    assert_eq!(lines(&t)[3..], u[..]);
    let t = play(EXAMPLE, &bit6(0), &[hold(0, 7, 7), Action::Start]);
    let l = lines(&t);
    assert_eq!(l[..4], ["(PRESS HOLD AT X65.000 Z5.000) ; OP.HOLD", "G00 X65.000 Z5.000 ; PRJ.MODAL", "(STOP FEED HOLD) ; OP.HOLD", "(CYCLE START) ; OP.RESUME"]);
    assert_eq!(l[4..], u[1..]);
    // "a feed-hold stop at the end of an event where a single-block stop is due replaces it"
    let t = play(EXAMPLE, &bit6(0), &[single(true, 0), hold(0, 1, 1), Action::Start, single(false, 1)]);
    assert_eq!(lines(&t)[4..], u[1..]);
    // At fraction 1/2 the single-block stop follows the rest of the move.
    let t = play(EXAMPLE, &bit6(0), &[single(true, 0), hold(0, 1, 2), Action::Start, single(false, 1)]);
    assert_eq!(lines(&t)[4..7], ["G00 X65.000 Z5.000 ; PRJ.MODAL", "(STOP SINGLE BLOCK) ; OP.SINGLE", "(CYCLE START) ; OP.SINGLE"]);
}

/// G92.HOLD on the pull-out itself (event 4, X58.7 Z-27 → X64.7 Z-28) at 1/2: the pull-out
/// manner goes to E.
#[test]
fn hold_on_the_pullout() {
    let t = play(EXAMPLE, &bit6(0), &[hold(4, 1, 2), Action::Start]);
    let u = u_lines(EXAMPLE, &Config::default());
    assert_eq!(lines(&t)[..4], u[..4]);
    assert_eq!(
        lines(&t)[4..11],
        [
            "(PRESS HOLD AT X61.700 Z-27.500) ; G92.HOLD",
            "G32 X61.700 Z-27.500 F3.0000 ; G92.PULLOUT",
            "G32 X64.700 Z-28.000 F3.0000 ; G92.HOLD",
            "G00 X65.000 Z-28.000 ; G92.HOLD",
            "G00 X65.000 Z5.000 ; G92.HOLD",
            "(STOP FEED HOLD) ; G92.HOLD",
            "(CYCLE START) ; OP.RESUME",
        ]
    );
    assert_eq!(lines(&t)[11..], u[1..]);
}

/// G92 with X the long axis (|W| 5 < |R| 30): the retract goes on Z first. U: 0 `G00 X100 Z5`;
/// 1 header; 2 `G00 X80 Z5`; 3 the cut to the pull-out start X22 Z0.167 (K 1 of X travel,
/// round(5·1/30) = 0.167 of Z); 4 the pull-out to X20 Z1 (J 1 toward A on Z); 5, 6 the rapids.
/// Hold at 1/2 of 3: P = (80 − 29, 5 − trunc(4.833/2)) = (51, 2.584); P + (E − S) = (49, 3.417).
#[test]
fn x_long_hold_retracts_z_first() {
    let src = "G0 X100 Z5\nG92 X20 Z0 R30 F1\n";
    let t = play(src, &bit6(0), &[hold(3, 1, 2), Action::Start]);
    let u = u_lines(src, &Config::default());
    assert_eq!(u[3..5], ["G32 X22.000 Z0.167 F1.0000 ; G92.PATH", "G32 X20.000 Z1.000 F1.0000 ; G92.JK.1"]);
    assert_eq!(
        lines(&t)[3..11],
        [
            "(PRESS HOLD AT X51.000 Z2.584) ; G92.HOLD",
            "G32 X51.000 Z2.584 F1.0000 ; G92.PATH",
            "G32 X49.000 Z3.417 F1.0000 ; G92.HOLD",
            "G00 X49.000 Z5.000 ; G92.HOLD",
            "G00 X100.000 Z5.000 ; G92.HOLD",
            "(STOP FEED HOLD) ; G92.HOLD",
            "(CYCLE START) ; OP.RESUME",
            "(PASS 1 ROUGH DEPTH 10.000) ; G92.PATH",
        ]
    );
    assert_eq!(lines(&t)[10..], u[1..]);
}

/// G92.SINGLE in a modal run, OP.SINGLE on plain blocks. U: 0 `G00 X65 Z5`; 1–6 the first cycle;
/// 7–12 the second (`X57.7`); 13 `G00 X70`.
#[test]
fn single_block_in_a_g92_run() {
    let src = "G0 X65 Z5\nG92 X58.7 Z-28 F3\nX57.7\nG0 X70\n";
    let t = play(src, &Config::default(), &[single(true, 0)]);
    let u = u_lines(src, &Config::default());
    let stops: Vec<usize> = (0..u.len()).filter(|&i| [0, 6, 12, 13].contains(&i)).collect();
    let mut expected = Vec::new();
    for (i, l) in u.iter().enumerate() {
        expected.push(l.clone());
        if stops.contains(&i) {
            let rule = if i == 0 || i == 13 { "OP.SINGLE" } else { "G92.SINGLE" };
            expected.push(format!("(STOP SINGLE BLOCK) ; {rule}"));
            expected.push(format!("(CYCLE START) ; {rule}"));
        }
    }
    assert_eq!(lines(&t), expected);
    assert_eq!(t.alarm, None);
    // Decided by the mode in force when the event ends: switched on before event 1, no stop
    // after event 0; switched off before event 7, the stop after event 6 is still due.
    let t = play(src, &Config::default(), &[single(true, 1), single(false, 7)]);
    let mut expected = u[..7].to_vec();
    expected.extend(["(STOP SINGLE BLOCK) ; G92.SINGLE", "(CYCLE START) ; G92.SINGLE"].map(String::from));
    expected.extend(u[7..].iter().cloned());
    assert_eq!(lines(&t), expected);
}

/// G92.HOLD on the second of two starts (COM.MULTISTART: L2, the second at 180°). U: 0 `G00 X65
/// Z5`; 1 the header; start 1: 2 – 6 as in the example; start 2: 7 `G00 X58.7 Z5`, 8 the cut,
/// 9 the pull-out, 10, 11 the rapids. A cut is one start's pass, "from its first (the pass
/// header when it is the pass's first start, else its first move)": held at 8, 1/2 (P = Z-11),
/// the cut is repeated from 7, not from the header. G92.SINGLE: a stop after each start's
/// return to A (after 6 and 11).
#[test]
fn second_start_is_its_own_cut() {
    let src = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1 L2\n";
    let u = u_lines(src, &Config::default());
    assert_eq!(u[7..9], ["G00 X58.700 Z5.000 ; G92.PATH", "G32 X58.700 Z-27.000 F3.0000 Q180000 ; G92.PATH"]);
    let t = play(src, &bit6(0), &[hold(8, 1, 2), Action::Start]);
    assert_eq!(lines(&t)[..8], u[..8]);
    assert_eq!(
        lines(&t)[8..15],
        [
            "(PRESS HOLD AT X58.700 Z-11.000) ; G92.HOLD",
            "G32 X58.700 Z-11.000 F3.0000 Q180000 ; G92.PATH",
            "G32 X64.700 Z-12.000 F3.0000 Q180000 ; G92.HOLD",
            "G00 X65.000 Z-12.000 ; G92.HOLD",
            "G00 X65.000 Z5.000 ; G92.HOLD",
            "(STOP FEED HOLD) ; G92.HOLD",
            "(CYCLE START) ; OP.RESUME",
        ]
    );
    assert_eq!(lines(&t)[15..], u[7..]);
    let t = play(src, &Config::default(), &[single(true, 1)]);
    let stops: Vec<usize> = lines(&t).iter().enumerate().filter(|(_, l)| l.starts_with("(STOP SINGLE BLOCK) ; G92.SINGLE")).map(|(i, _)| i).collect();
    assert_eq!(stops, [7, 14]);
}
