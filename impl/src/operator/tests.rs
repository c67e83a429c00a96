//! Operator events (OP.*, G92.HOLD, G92.SINGLE, G92.RESET, G76.HOLD, G76.SINGLE, G162.NOSTOP)
//! on the whole expander: the register's worked example and the cases around it.
extern crate std;

use crate::tests::expand;
use std::vec;
use cycle_vocab::text::Trace;
use cycle_vocab::{Action, Alarm, AlarmCode, Along, Config, Dialect, Rule, Script};
use std::format;
use std::string::String;
use std::vec::Vec;

const G90: &str = "G0 X50 Z5\nG90 X40 Z-20 F0.2\nG0 X60\n";
pub(crate) const EXAMPLE: &str = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n";

pub(crate) fn hold(event: u32, num: u32, den: u32) -> Action {
    Action::Hold(Along { event, num, den })
}

pub(crate) fn reset(event: u32, num: u32, den: u32) -> Action {
    Action::Reset(Along { event, num, den })
}

pub(crate) fn single(on: bool, before: u32) -> Action {
    Action::SingleBlock { on, before }
}

pub(crate) fn with(config: Config, actions: &[Action]) -> Config {
    Config { operator: Script::of(actions).unwrap(), ..config }
}

pub(crate) fn bit6(v: i64) -> Config {
    let mut c = Config::default();
    c.params.no18_bit6_hold = Some(v);
    c
}

pub(crate) fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

/// Each event as canonical G-code with its rule, the alarm last.
pub(crate) fn lines(t: &Trace) -> Vec<String> {
    let mut v: Vec<String> =
        t.events.iter().map(|e| format!("{} {}", Trace::event_line(t.grid, e), e.rule())).collect();
    if let Some(a) = &t.alarm {
        v.push(Trace::alarm_line(a));
    }
    v
}

pub(crate) fn run(program: &str, config: Config, actions: &[Action]) -> Vec<String> {
    lines(&expand(program, with(config, actions)))
}

pub(crate) fn plain(program: &str, config: Config) -> Vec<String> {
    lines(&expand(program, config))
}

pub(crate) fn strs(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| String::from(*s)).collect()
}

/// The register's worked example, U as it lists it (0 … 6).
#[test]
fn worked_example_u() {
    assert_eq!(
        plain(EXAMPLE, Config::default()),
        strs(&[
            "G00 X65.000 Z5.000 PRJ.MODAL",
            "(PASS 1 ROUGH DEPTH 3.150) G92.PATH",
            "G00 X58.700 Z5.000 G92.PATH",
            "G32 X58.700 Z-27.000 F3.0000 G92.PATH",
            "G32 X64.700 Z-28.000 F3.0000 G92.PULLOUT",
            "G00 X65.000 Z-28.000 G92.PATH",
            "G00 X65.000 Z5.000 G92.PATH",
        ])
    );
}

/// G92.HOLD, bit 6 = 0 (the worked example): the thread move to P keeps its own rule (the
/// register: "a move cut short at P keeps every field of the original move"); the retract's
/// moves are tagged G92.HOLD; Start repeats the cut from the pass header.
#[test]
fn worked_example_bit6_0() {
    let u = plain(EXAMPLE, Config::default());
    let got = run(EXAMPLE, Config::default(), &[hold(3, 1, 2), Action::Start]);
    let mut want = u[..3].to_vec();
    want.extend(strs(&[
        "(PRESS HOLD AT X58.700 Z-11.000) G92.HOLD",
        "G32 X58.700 Z-11.000 F3.0000 G92.PATH",
        "G32 X64.700 Z-12.000 F3.0000 G92.HOLD",
        "G00 X65.000 Z-12.000 G92.HOLD",
        "G00 X65.000 Z5.000 G92.HOLD",
        "(STOP FEED HOLD) G92.HOLD",
        "(CYCLE START) OP.RESUME",
    ]));
    want.extend(u[1..].iter().cloned());
    assert_eq!(got, want);
}

/// G92.HOLD, bit 6 = 1 (the worked example): U runs on to the pull-out's end, then stops.
#[test]
fn worked_example_bit6_1() {
    let got = run(EXAMPLE, bit6(1), &[hold(3, 1, 2), Action::Start]);
    let u = plain(EXAMPLE, bit6(1));
    let mut want = u[..3].to_vec();
    want.push(String::from("(PRESS HOLD AT X58.700 Z-11.000) G92.HOLD"));
    want.extend(u[3..5].iter().cloned());
    want.extend(strs(&["(STOP FEED HOLD) G92.HOLD", "(CYCLE START) OP.RESUME"]));
    want.extend(u[5..].iter().cloned());
    assert_eq!(got, want);
}

/// The empty script changes nothing, on every corpus program under every dialect; nor does a
/// script whose one action (single block off before event 0) changes no mode: the layer then
/// passes U through, its alarm included.
#[test]
fn empty_script_is_u() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../corpus");
    let mut n = 0;
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().and_then(|e| e.to_str()) != Some("nc") {
            continue;
        }
        let src = std::fs::read_to_string(&path).unwrap();
        for dialect in [Dialect::Gsk, Dialect::Fanuc, Dialect::Nc201] {
            let config = Config { dialect, ..Config::default() };
            let u = plain(&src, config);
            assert_eq!(run(&src, config, &[]), u, "{path:?}");
            if u.len() > 1 {
                assert_eq!(run(&src, config, &[single(false, 0)]), u, "{path:?} {dialect:?}");
            }
            n += 1;
        }
    }
    assert!(n >= 48, "{n}");
}

fn alarm(code: AlarmCode, rule: Rule, line: u32) -> String {
    Trace::alarm_line(&Alarm::new(code, None, rule, line))
}

fn op(rule: Rule, line: u32) -> String {
    alarm(AlarmCode::Operator, rule, line)
}

/// `u[range]` followed by `rest`.
pub(crate) fn cat(parts: &[&[String]]) -> Vec<String> {
    parts.iter().flat_map(|p| p.iter().cloned()).collect()
}

/// OP.HOLD on a plain rapid, then OP.RESUME: the rest of the move, and U goes on.
#[test]
fn hold_on_a_rapid() {
    let u = plain(EXAMPLE, Config::default());
    let got = run(EXAMPLE, Config::default(), &[hold(0, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X32.500 Z2.500) OP.HOLD",
        "G00 X32.500 Z2.500 PRJ.MODAL",
        "(STOP FEED HOLD) OP.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&held, &u]));
    // A cycle's rapid (G92.PATH ①) is OP.HOLD too: P = 65 + trunc(−6.3/2) on X.
    let got = run(EXAMPLE, Config::default(), &[hold(2, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X61.850 Z5.000) OP.HOLD",
        "G00 X61.850 Z5.000 G92.PATH",
        "(STOP FEED HOLD) OP.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..2], &held, &u[2..]]));
}

/// Two holds on the same move: the second fires on the rest [1/4, 1]; in the other order the
/// second (1/4) is not on the rest [1/2, 1] and is never reached (OP.REACH).
#[test]
fn two_holds_on_one_move() {
    let u = plain(EXAMPLE, Config::default());
    let got = run(EXAMPLE, Config::default(), &[hold(0, 1, 4), Action::Start, hold(0, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X16.250 Z1.250) OP.HOLD",
        "G00 X16.250 Z1.250 PRJ.MODAL",
        "(STOP FEED HOLD) OP.HOLD",
        "(CYCLE START) OP.RESUME",
        "(PRESS HOLD AT X32.500 Z2.500) OP.HOLD",
        "G00 X32.500 Z2.500 PRJ.MODAL",
        "(STOP FEED HOLD) OP.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&held, &u]));
    let got = run(EXAMPLE, Config::default(), &[hold(0, 1, 2), Action::Start, hold(0, 1, 4), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X32.500 Z2.500) OP.HOLD",
        "G00 X32.500 Z2.500 PRJ.MODAL",
        "(STOP FEED HOLD) OP.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&held, &u, &[op(Rule::OpReach, 0)]]));
    // The same point twice: the rest resumed at 1/2 covers 1/2.
    let got = run(EXAMPLE, Config::default(), &[hold(0, 1, 2), Action::Start, hold(0, 2, 4), Action::Start]);
    assert_eq!(got[4], "(PRESS HOLD AT X32.500 Z2.500) OP.HOLD");
    assert_eq!(got[5..7], strs(&["(STOP FEED HOLD) OP.HOLD", "(CYCLE START) OP.RESUME"])[..]);
}

/// Fractions 0 and 1: the move to P, or the rest, has no length and is omitted (PRJ.NOOP). A
/// feed-hold stop at the end of a move replaces the single-block stop due there.
#[test]
fn holds_at_zero_and_one() {
    let u = plain(EXAMPLE, Config::default());
    let got = run(EXAMPLE, Config::default(), &[hold(0, 0, 1), Action::Start]);
    let held =
        strs(&["(PRESS HOLD AT X0.000 Z0.000) OP.HOLD", "(STOP FEED HOLD) OP.HOLD", "(CYCLE START) OP.RESUME"]);
    assert_eq!(got, cat(&[&held, &u]));
    let got = run(EXAMPLE, Config::default(), &[hold(0, 7, 7), Action::Start]);
    let held = strs(&["(PRESS HOLD AT X65.000 Z5.000) OP.HOLD"]);
    let stop = strs(&["(STOP FEED HOLD) OP.HOLD", "(CYCLE START) OP.RESUME"]);
    assert_eq!(got, cat(&[&held, &u[..1], &stop, &u[1..]]));
    // Single block on: the feed-hold stop at the end replaces OP.SINGLE's stop.
    let got = run(EXAMPLE, Config::default(), &[single(true, 0), hold(0, 1, 1), Action::Start]);
    let sb = strs(&["(STOP SINGLE BLOCK) G92.SINGLE", "(CYCLE START) G92.SINGLE"]);
    assert_eq!(got, cat(&[&held, &u[..1], &stop, &u[1..], &sb]));
    // At 1/2 the rest ends the block: OP.SINGLE's stop follows it.
    let got = run(EXAMPLE, Config::default(), &[single(true, 0), hold(0, 1, 2), Action::Start]);
    assert_eq!(
        got[4..7],
        strs(&["G00 X65.000 Z5.000 PRJ.MODAL", "(STOP SINGLE BLOCK) OP.SINGLE", "(CYCLE START) OP.SINGLE"])[..]
    );
}

/// G92.HOLD on the pull-out itself (bit 6 = 0): the retract's thread move goes to E.
#[test]
fn hold_on_the_pullout() {
    let u = plain(EXAMPLE, Config::default());
    let got = run(EXAMPLE, Config::default(), &[hold(4, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X61.700 Z-27.500) G92.HOLD",
        "G32 X61.700 Z-27.500 F3.0000 G92.PULLOUT",
        "G32 X64.700 Z-28.000 F3.0000 G92.HOLD",
        "G00 X65.000 Z-28.000 G92.HOLD",
        "G00 X65.000 Z5.000 G92.HOLD",
        "(STOP FEED HOLD) G92.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..4], &held, &u[1..]]));
}

/// OP.AT: a hold on a pass header (G92's, line 2) replaces it with the alarm.
#[test]
fn hold_on_a_header() {
    let u = plain(EXAMPLE, Config::default());
    assert_eq!(run(EXAMPLE, Config::default(), &[hold(1, 1, 2)]), cat(&[&u[..1], &[op(Rule::OpAt, 2)]]));
    assert_eq!(run(EXAMPLE, Config::default(), &[reset(1, 0, 1)]), cat(&[&u[..1], &[op(Rule::OpAt, 2)]]));
}

/// OP.SCOPE: a hold on a G90 or G71 move, and single block on when a G90 block begins.
#[test]
fn out_of_scope() {
    let u = plain(G90, Config::default());
    assert_eq!(run(G90, Config::default(), &[hold(3, 1, 2)]), cat(&[&u[..3], &[op(Rule::OpScope, 2)]]));
    let sb = strs(&["(STOP SINGLE BLOCK) OP.SINGLE", "(CYCLE START) OP.SINGLE"]);
    assert_eq!(run(G90, Config::default(), &[single(true, 0)]), cat(&[&u[..1], &sb, &[op(Rule::OpScope, 2)]]));
    // Off again before the G90 block: no alarm; the G0 after it stops (OP.SINGLE) once on.
    let got = run(G90, Config::default(), &[single(true, 0), single(false, 1), single(true, 6)]);
    assert_eq!(got, cat(&[&u[..1], &sb, &u[1..], &sb]));
    // A hold on a G90 pass header with single block on: OP.AT (the hold's own check comes
    // before the single-block scope check; the register names both).
    let got = run(G90, Config::default(), &[single(true, 1), hold(1, 1, 2)]);
    assert_eq!(got, cat(&[&u[..1], &[op(Rule::OpAt, 2)]]));
    // A thread move G32 is no plain block either.
    let g32 = "G0 X40 Z5\nG32 X40 Z-20 F2\n";
    let u32 = plain(g32, Config::default());
    assert_eq!(run(g32, Config::default(), &[reset(1, 1, 2)]), cat(&[&u32[..1], &[op(Rule::OpScope, 2)]]));
    let g71 = include_str!("../../../corpus/g71_example.nc");
    let u = plain(g71, Config::default());
    let got = run(g71, Config::default(), &[hold(3, 1, 2)]);
    assert_eq!(got, cat(&[&u[..3], &[op(Rule::OpScope, 8)]]));
}

/// OP.REACH: a hold never reached; a hold then a hold without Start (the run ends at the first
/// stop); Start with no stop; a last hold without Start ends the run with no alarm.
#[test]
fn unreached() {
    let u = plain(EXAMPLE, Config::default());
    assert_eq!(run(EXAMPLE, Config::default(), &[hold(99, 1, 2)]), cat(&[&u, &[op(Rule::OpReach, 0)]]));
    assert_eq!(run(EXAMPLE, Config::default(), &[Action::Start]), cat(&[&u, &[op(Rule::OpReach, 0)]]));
    assert_eq!(run(EXAMPLE, Config::default(), &[single(true, 7)]), cat(&[&u, &[op(Rule::OpReach, 0)]]));
    let held = strs(&[
        "(PRESS HOLD AT X32.500 Z2.500) OP.HOLD",
        "G00 X32.500 Z2.500 PRJ.MODAL",
        "(STOP FEED HOLD) OP.HOLD",
    ]);
    assert_eq!(run(EXAMPLE, Config::default(), &[hold(0, 1, 2), hold(2, 1, 2)]), cat(&[&held, &[op(Rule::OpReach, 0)]]));
    assert_eq!(run(EXAMPLE, Config::default(), &[hold(0, 1, 2)]), held);
    // A program alarm of U is the one alarm, no OP.REACH.
    let bad = "G0 X65 Z5\nG92 X58.7 Z-28 J3 K1\n";
    let ub = plain(bad, Config::default());
    assert_eq!(ub.last().unwrap(), &alarm_with_word(AlarmCode::MissingWord, b'F', Rule::ComLead, 2));
    assert_eq!(run(bad, Config::default(), &[hold(5, 1, 2)]), ub);
}

fn alarm_with_word(code: AlarmCode, word: u8, rule: Rule, line: u32) -> String {
    Trace::alarm_line(&Alarm::new(code, Some(word), rule, line))
}

/// OP.SCRIPT: den 0, den > 1 000 000, num > den: OUT OF RANGE on line 0, before any event,
/// after the other configuration checks.
#[test]
fn script_check() {
    let out = alarm(AlarmCode::OutOfRange, Rule::OpScript, 0);
    for bad in [hold(0, 0, 0), reset(0, 3, 2), hold(0, 1, 1_000_001)] {
        assert_eq!(run(EXAMPLE, Config::default(), &[Action::Start, bad]), vec![out.clone()]);
    }
    assert_eq!(run(EXAMPLE, Config::default(), &[hold(0, 1_000_000, 1_000_000), Action::Start]).len(), 10);
    let mut c = Config::default();
    c.params.p5142_finish_passes = Some(0);
    let got = run(EXAMPLE, c, &[hold(0, 0, 0)]);
    assert_eq!(got, vec![alarm(AlarmCode::OutOfRange, Rule::G76Defaults, 0)]);
}

/// Random scripts on the corpus and the cycles here: no panic, the stream ends, and it is no
/// longer than U's events repeated once per action plus the layer's own events.
#[test]
fn random_scripts_end() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../corpus");
    let mut progs: Vec<(String, Config)> = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let src = std::fs::read_to_string(&path).unwrap();
        let config = if src.contains("G162") { nc201() } else { Config::default() };
        progs.push((src, config));
    }
    progs.push((String::from(EXAMPLE), Config::default()));
    progs.push((String::from(EXAMPLE), bit6(1)));
    let mut seed = 0x5eed_u64;
    for round in 0..3000 {
        let (src, base) = &progs[round % progs.len()];
        let n_u = crate::tests::expand(src, *base).events.len() as u64;
        let mut actions = Vec::new();
        let count = 1 + crate::tests::xorshift(&mut seed) % 6;
        for _ in 0..count {
            let r = crate::tests::xorshift(&mut seed);
            let event = (r % (n_u + 2)) as u32;
            let den = 1 + ((r >> 20) % 8) as u32;
            let num = ((r >> 30) % u64::from(den + 1)) as u32;
            actions.push(match (r >> 40) % 5 {
                0 | 1 => hold(event, num, den),
                2 => Action::Start,
                3 => single((r >> 50) & 1 == 0, event),
                _ => reset(event, num, den),
            });
        }
        let t = expand(src, with(*base, &actions));
        assert!(t.events.len() as u64 <= (n_u + 8) * (count + 1), "{src} {actions:?}");
    }
}

mod cycles;
