//! Operator events (OP.*, G92.HOLD, G92.SINGLE, G92.RESET, G76.HOLD, G76.SINGLE, G162.NOSTOP)
//! on the whole expander: the register's worked example and the cases around it.
extern crate std;

use crate::tests::{expand, xorshift};
use cycle_vocab::text::Trace;
use cycle_vocab::{Action, Alarm, AlarmCode, Along, Config, Dialect, Event, Rule, Script};
use std::format;
use std::string::String;
use std::vec::Vec;

const EXAMPLE: &str = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n";

fn hold(event: u32, num: u32, den: u32) -> Action {
    Action::Hold(Along { event, num, den })
}

fn reset(event: u32, num: u32, den: u32) -> Action {
    Action::Reset(Along { event, num, den })
}

fn single(on: bool, before: u32) -> Action {
    Action::SingleBlock { on, before }
}

fn with(config: Config, actions: &[Action]) -> Config {
    Config { operator: Script::of(actions).unwrap(), ..config }
}

fn bit6(v: i64) -> Config {
    let mut c = Config::default();
    c.params.no18_bit6_hold = Some(v);
    c
}

fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

/// Each event as canonical G-code with its rule, the alarm last.
fn lines(t: &Trace) -> Vec<String> {
    let mut v: Vec<String> =
        t.events.iter().map(|e| format!("{} {}", Trace::event_line(t.grid, e), e.rule())).collect();
    if let Some(a) = &t.alarm {
        v.push(Trace::alarm_line(a));
    }
    v
}

fn run(program: &str, config: Config, actions: &[Action]) -> Vec<String> {
    lines(&expand(program, with(config, actions)))
}

fn plain(program: &str, config: Config) -> Vec<String> {
    lines(&expand(program, config))
}

fn strs(v: &[&str]) -> Vec<String> {
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
