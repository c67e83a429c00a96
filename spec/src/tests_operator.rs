//! Operator events (docs/INTERPRETATION.md, "Operator events"): hand-checked interrupted runs.

use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{Action, Along, Config, Params, Script};

const EXAMPLE: &str = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n";

fn hold(event: u32, num: u32, den: u32) -> Action {
    Action::Hold(Along { event, num, den })
}

fn with(config: &Config, actions: &[Action]) -> Config {
    Config { operator: Script::of(actions).unwrap(), ..*config }
}

fn bit6(v: i64) -> Config {
    Config { params: Params { no18_bit6_hold: Some(v), ..Params::default() }, ..Config::default() }
}

fn play(src: &str, config: &Config, actions: &[Action]) -> Trace {
    expand(src.as_bytes(), &with(config, actions))
}

#[test]
fn dump() {
    let t = play(EXAMPLE, &bit6(0), &[hold(3, 1, 2), Action::Start]);
    println!("{}", t.to_gcode());
    let t = play(EXAMPLE, &bit6(1), &[hold(3, 1, 2), Action::Start]);
    println!("{}", t.to_gcode());
}
