//! The conformance relation between a reference trace (the spec's) and a candidate trace (the
//! production expander's, or a vendor's), in one place.
//!
//! # The relation
//!
//! A candidate **conforms** to the reference when the two traces are equal field by field:
//!
//! - the same grid (units and increment system);
//! - the same number of events, and at every index the same event variant (pass header or
//!   move) with the same fields: for a pass its `index`, `kind` and `diameter_depth`; for a move
//!   its `kind`, `x`, `z`, `feed`, `angle`, `lead_change`, `lead_change_angle` and
//!   `lead_floor` (the variable lead: lead at the start, its change over an angle, its floor);
//! - the same ending: both without an alarm, or both with an alarm of the same `code`, `word`,
//!   `line` and `rule`.
//!
//! The `rule` tag of an event is **not** compared: it is an annotation (which catalogue rule the
//! event realises), and two correct expanders may attribute a move differently. At a divergence
//! the reference's rule is reported, with its catalogue text, to point the reviewer at the rule
//! the candidate broke.
//!
//! # Why no tolerance
//!
//! Both engines compute on the integer grid (COM.UNITS): every length is a count of the least
//! increment, every lead a count of the lead grid, every angle a count of 0.001°. Every value the
//! manuals define by real arithmetic (√n·Δd, depth·tan(a/2), 25.4/I, …) is rounded exactly once,
//! half up, from its exact value (docs/INTERPRETATION.md, "Rounding"), so there is exactly one
//! right integer for each field and no floating-point noise to absorb. A candidate one increment
//! off has rounded differently (or computed in floating point) and is wrong: a tolerance would
//! hide exactly the errors certification is meant to find.
//!
//! # The diff
//!
//! [`check`] (whole traces) and [`Lockstep`] (the reference pushed event by event against the
//! candidate's pull stream, nothing collected) name the *first* divergence only — everything after it is likely a consequence —
//! as a [`Divergence`]: its kind, the event index, the field, both values as canonical G-code
//! lines (`cycle_vocab::text`), the reference's rule and a few events of context before it.

use crate::catalogue;
use cycle_vocab::{Alarm, AlarmCode, Dwell, Event, Grid, Move, MoveKind, Pass, Press, Rule, Spindle, Stop};
use std::fmt;

mod level;
mod lockstep;
pub use level::Level;
pub use lockstep::{check, Lockstep};

/// How many events before the divergence the report shows.
pub const CONTEXT: usize = 4;

/// What kind of difference was found first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum DivergenceKind {
    /// The traces are on different grids (units or increment system).
    GridMismatch,
    /// Same event variant at the index, a field differs.
    FieldMismatch,
    /// A pass header in one trace where the other has a move.
    EventKindMismatch,
    /// The candidate ends (without an alarm) where the reference has more events.
    MissingEvents,
    /// The candidate has events after the reference ended without an alarm.
    ExtraEvents,
    /// Both end in an alarm after the same events, but the alarms differ.
    AlarmMismatch,
    /// The candidate raises an alarm where the reference has an event or ends cleanly.
    UnexpectedAlarm,
    /// The reference raises an alarm where the candidate has an event or ends cleanly.
    MissingAlarm,
}

impl DivergenceKind {
    /// Every kind, in declaration order.
    pub const ALL: [DivergenceKind; 8] = [
        DivergenceKind::GridMismatch,
        DivergenceKind::FieldMismatch,
        DivergenceKind::EventKindMismatch,
        DivergenceKind::MissingEvents,
        DivergenceKind::ExtraEvents,
        DivergenceKind::AlarmMismatch,
        DivergenceKind::UnexpectedAlarm,
        DivergenceKind::MissingAlarm,
    ];

    /// A short name: `field mismatch`.
    pub const fn name(self) -> &'static str {
        match self {
            DivergenceKind::GridMismatch => "grid mismatch",
            DivergenceKind::FieldMismatch => "field mismatch",
            DivergenceKind::EventKindMismatch => "event kind mismatch",
            DivergenceKind::MissingEvents => "missing events",
            DivergenceKind::ExtraEvents => "extra events",
            DivergenceKind::AlarmMismatch => "alarm mismatch",
            DivergenceKind::UnexpectedAlarm => "unexpected alarm",
            DivergenceKind::MissingAlarm => "missing alarm",
        }
    }
}

impl fmt::Display for DivergenceKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// The first difference between a reference and a candidate trace.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Divergence {
    /// Index of the first divergent event; for a difference in the ending (alarm, missing or
    /// extra events) the index where the shorter trace ends. 0 for a grid mismatch.
    pub index: usize,
    pub kind: DivergenceKind,
    /// The field that differs (`x`, `diameter_depth`, `code`, `grid`, …), if one does.
    pub field: Option<&'static str>,
    /// The reference at `index`: a canonical G-code line (event or alarm), or `end of trace`.
    pub reference: String,
    /// The candidate at `index`, in the same form.
    pub candidate: String,
    /// The differing field's own values (reference, candidate), e.g. `("58700", "58702")`.
    pub values: Option<(String, String)>,
    /// The reference's rule at `index` (its event's or its alarm's), if it has one there.
    pub rule: Option<Rule>,
    /// Up to [`CONTEXT`] events before `index` (equal in both traces): index and G-code line.
    pub context: Vec<(usize, String)>,
    /// Event counts of the reference and the candidate.
    pub lengths: (usize, usize),
    /// Alarm lines of the reference and the candidate, if they end in one.
    pub alarms: (Option<String>, Option<String>),
    /// The comparison level ([`Level`]): below `full`, `index`, `context` and `lengths` count
    /// the events the level compares (the moves), not the whole traces'.
    pub level: Level,
}

/// How the end of a trace without an alarm is shown.
pub(crate) const END: &str = "end of trace (no alarm)";

pub(crate) fn variant(e: &Event) -> &'static str {
    match e {
        Event::Pass(_) => "pass",
        Event::Move(_) => "move",
        Event::Dwell(_) => "dwell",
        Event::Spindle(_) => "spindle",
        Event::Press(_) => "press",
        Event::Stop(_) => "stop",
        Event::Resume(_) => "resume",
    }
}

fn differ<T: PartialEq + ToString>(field: &'static str, r: T, c: T) -> Option<(&'static str, String, String)> {
    (r != c).then(|| (field, r.to_string(), c.to_string()))
}

/// The first differing field of two pass headers (the rule tag is not compared). Every field is
/// named, so a field added to `Pass` does not compile here until it is compared.
pub(crate) fn pass_field(r: &Pass, c: &Pass) -> Option<(&'static str, String, String)> {
    let Pass { index, kind, diameter_depth, rule: _ } = *r;
    differ("index", index, c.index)
        .or_else(|| differ("kind", kind.name(), c.kind.name()))
        .or_else(|| differ("diameter_depth", diameter_depth, c.diameter_depth))
}

/// The first differing field of two dwells (the rule tag is not compared).
pub(crate) fn dwell_field(r: &Dwell, c: &Dwell) -> Option<(&'static str, String, String)> {
    let Dwell { ms, rule: _ } = *r;
    differ("ms", ms, c.ms)
}

/// The first differing field of two spindle events (the rule tag is not compared).
pub(crate) fn spindle_field(r: &Spindle, c: &Spindle) -> Option<(&'static str, String, String)> {
    let Spindle { state, rule: _ } = *r;
    differ("state", format!("{state:?}"), format!("{:?}", c.state))
}

/// The first differing field of two button presses (the rule tag is not compared).
pub(crate) fn press_field(r: &Press, c: &Press) -> Option<(&'static str, String, String)> {
    let Press { button, x, z, rule: _ } = *r;
    differ("button", format!("{button:?}"), format!("{:?}", c.button)).or_else(|| differ("x", x, c.x)).or_else(|| differ("z", z, c.z))
}

/// The first differing field of two stops (the rule tag is not compared).
pub(crate) fn stop_field(r: &Stop, c: &Stop) -> Option<(&'static str, String, String)> {
    let Stop { reason, rule: _ } = *r;
    differ("reason", format!("{reason:?}"), format!("{:?}", c.reason))
}

fn move_kind(k: MoveKind) -> &'static str {
    match k {
        MoveKind::Rapid => "rapid (G00)",
        MoveKind::Feed => "feed (G01)",
        MoveKind::Thread => "thread (G32)",
        MoveKind::ArcCw => "arc clockwise (G02)",
        MoveKind::ArcCcw => "arc counter-clockwise (G03)",
    }
}

/// The first differing field of two moves (the rule tag is not compared). Every field is named,
/// so a field added to `Move` does not compile here until it is compared.
pub(crate) fn move_field(r: &Move, c: &Move) -> Option<(&'static str, String, String)> {
    let Move { kind, x, z, feed, cx, cz, angle, lead_change, lead_change_angle, lead_floor, lead_steps, rule: _ } = *r;
    differ("kind", move_kind(kind), move_kind(c.kind))
        .or_else(|| differ("x", x, c.x))
        .or_else(|| differ("z", z, c.z))
        .or_else(|| differ("feed", feed, c.feed))
        .or_else(|| differ("cx", cx, c.cx))
        .or_else(|| differ("cz", cz, c.cz))
        .or_else(|| differ("angle", angle, c.angle))
        .or_else(|| differ("lead_change", lead_change, c.lead_change))
        .or_else(|| differ("lead_change_angle", lead_change_angle, c.lead_change_angle))
        .or_else(|| differ("lead_floor", lead_floor, c.lead_floor))
        .or_else(|| differ("lead_steps", lead_steps, c.lead_steps))
}

/// The first differing field of two alarms: code, word, line, rule.
pub(crate) fn alarm_field(r: &Alarm, c: &Alarm) -> Option<(&'static str, String, String)> {
    let Alarm { code, word, line, rule } = *r;
    let word_of = |w: Option<u8>| w.map_or_else(|| "none".to_string(), word_text);
    differ("code", code_text(code), code_text(c.code))
        .or_else(|| differ("word", word_of(word), word_of(c.word)))
        .or_else(|| differ("line", line, c.line))
        .or_else(|| differ("rule", rule.id(), c.rule.id()))
}

/// A grid as the trace header names it: `MM GRID 0.001`.
pub fn grid_name(grid: Grid) -> String {
    format!("{} GRID {}", grid.unit_name(), cycle_vocab::text::fixed(1, grid.decimals()))
}

/// An alarm code's name as the register writes it: `MISSING WORD`, `OUT OF RANGE`.
pub fn code_name(code: AlarmCode) -> String {
    match serde_json::to_value(code) {
        Ok(serde_json::Value::String(s)) => s.replace('_', " "),
        _ => format!("{code:?}"),
    }
}

/// An alarm code with its number: `2001 MISSING WORD`.
pub fn code_text(code: AlarmCode) -> String {
    format!("{} {}", code.number(), code_name(code))
}

/// An alarm word as the machinist reads it: the letter, or `0xNN` for a byte that is none.
pub fn word_text(byte: u8) -> String {
    if byte.is_ascii_graphic() {
        (byte as char).to_string()
    } else {
        format!("0x{byte:02X}")
    }
}

/// One line naming an alarm's code, number, word, rule and line:
/// `ALARM 2001 MISSING WORD: word P, rule G76.REQUIRED, line 3`.
pub fn alarm_summary(alarm: &Alarm) -> String {
    let word = alarm.word.map(|w| format!("word {}, ", word_text(w))).unwrap_or_default();
    format!("ALARM {}: {word}rule {}, line {}", code_text(alarm.code), alarm.rule, alarm.line)
}

/// A short form for one-line reports: `alarm 2002 P G78.MODE`.
pub fn alarm_short(alarm: &Alarm) -> String {
    let word = alarm.word.map(|w| format!(" {}", word_text(w))).unwrap_or_default();
    format!("alarm {}{word} {}", alarm.code.number(), alarm.rule)
}

impl fmt::Display for Divergence {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "DIVERGENCE: {} at event {}", self.kind, self.index)?;
        if self.level != Level::Full {
            write!(f, " of the moves-only traces (comparison level {}: other events dropped from both before indexing)", self.level)?;
        }
        if let Some(field) = self.field {
            write!(f, ", field `{field}`")?;
        }
        writeln!(f)?;
        writeln!(f, "  reference: {}", self.reference)?;
        writeln!(f, "  candidate: {}", self.candidate)?;
        if let (Some(field), Some((r, c))) = (self.field, &self.values) {
            let unit = match field {
                "x" | "z" | "diameter_depth" => " (grid increments)",
                "feed" | "lead_change" | "lead_floor" => " (lead counts)",
                "angle" | "lead_change_angle" => " (0.001°)",
                _ => "",
            };
            writeln!(f, "  {field} differs: reference {r}, candidate {c}{unit}")?;
        }
        match self.rule {
            Some(rule) => match catalogue::entry(rule) {
                Some(e) => writeln!(f, "  rule: {} ({}, {}): {}", rule, e.source, e.status, e.text)?,
                None => writeln!(f, "  rule: {rule}")?,
            },
            None => writeln!(f, "  rule: none (the reference has no event here)")?,
        }
        let unit = if self.level == Level::Full { "events" } else { "moves" };
        let ending = |n: usize, alarm: &Option<String>| match alarm {
            Some(a) => format!("{n} {unit}, then {a}"),
            None => format!("{n} {unit}, no alarm"),
        };
        writeln!(f, "  reference trace: {}", ending(self.lengths.0, &self.alarms.0))?;
        writeln!(f, "  candidate trace: {}", ending(self.lengths.1, &self.alarms.1))?;
        match (self.context.first(), self.context.last()) {
            (Some((first, _)), Some((last, _))) => {
                writeln!(f, "  context (events {first}…{last}, equal in both):")?;
                for (i, line) in &self.context {
                    writeln!(f, "    {i:>6}  {line}")?;
                }
                write!(f, "    {:>6}  reference: {}", self.index, self.reference)?;
            }
            _ if self.kind == DivergenceKind::GridMismatch => write!(f, "  context: none (the grids differ)")?,
            _ => write!(f, "  context: none (the divergence is at the first event)")?,
        }
        Ok(())
    }
}

impl std::error::Error for Divergence {}

/// The divergence as JSON (for `cyclecheck --format json`).
pub fn to_json(d: &Divergence) -> serde_json::Value {
    serde_json::json!({
        "kind": d.kind.name(),
        "index": d.index,
        "field": d.field,
        "reference": d.reference,
        "candidate": d.candidate,
        "values": d.values.as_ref().map(|(r, c)| serde_json::json!({"reference": r, "candidate": c})),
        "rule": d.rule.map(Rule::id),
        "context": d.context.iter().map(|(i, l)| serde_json::json!({"index": i, "line": l})).collect::<Vec<_>>(),
        "lengths": {"reference": d.lengths.0, "candidate": d.lengths.1},
        "alarms": {"reference": d.alarms.0, "candidate": d.alarms.1},
        "level": d.level.name(),
    })
}

#[cfg(test)]
mod tests;
