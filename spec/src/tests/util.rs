//! What the spec's tests share: a clean run, its pass headers, an alarm as a tuple.

use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{AlarmCode, Config, Event, PassKind, Rule};

/// The trace of `src` under `config`, which must end without an alarm.
pub fn run_with(src: &str, config: &Config) -> Trace {
    let t = expand(src.as_bytes(), config);
    assert_eq!(t.alarm, None, "{}", t.to_gcode());
    t
}

/// The trace of `src` under the default configuration, without an alarm.
pub fn run(src: &str) -> Trace {
    run_with(src, &Config::default())
}

/// The pass headers as (index, kind, diameter depth, rule).
pub fn passes(t: &Trace) -> Vec<(u32, PassKind, i64, Rule)> {
    t.events.iter().filter_map(|e| if let Event::Pass(p) = e { Some((p.index, p.kind, p.diameter_depth, p.rule)) } else { None }).collect()
}

/// An alarm as (code, word, rule, line).
pub type Expect = (AlarmCode, Option<char>, Rule, u32);

/// The alarm `src` ends in under `config` (there must be one).
pub fn alarm_with(src: &str, config: &Config) -> Expect {
    let a = expand(src.as_bytes(), config).alarm.unwrap_or_else(|| panic!("no alarm for {src:?}"));
    (a.code, a.word.map(char::from), a.rule, a.line)
}

/// The alarm `src` ends in under the default configuration.
pub fn alarm_of(src: &str) -> Expect {
    alarm_with(src, &Config::default())
}
