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
//! [`check`] names the *first* divergence only — everything after it is likely a consequence —
//! as a [`Divergence`]: its kind, the event index, the field, both values as canonical G-code
//! lines (`cycle_vocab::text`), the reference's rule and a few events of context before it.

use crate::catalogue;
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, AlarmCode, Event, Grid, Move, MoveKind, Pass, Rule};
use std::fmt;

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
}

/// Checks that `candidate` conforms to `reference` (see the module documentation); the first
/// divergence otherwise.
// A divergence is the rare, reported path, and callers match on its fields: it stays unboxed.
#[allow(clippy::result_large_err)]
pub fn check(reference: &Trace, candidate: &Trace) -> Result<(), Divergence> {
    let grid = reference.grid;
    let div = |index: usize,
               kind: DivergenceKind,
               field: Option<&'static str>,
               r: String,
               c: String,
               values: Option<(String, String)>,
               rule: Option<Rule>| {
        let from = index.saturating_sub(CONTEXT);
        let context = if kind == DivergenceKind::GridMismatch {
            Vec::new()
        } else {
            (from..index)
                .filter_map(|i| reference.events.get(i).map(|e| (i, Trace::event_line(grid, e))))
                .collect()
        };
        Err(Divergence {
            index,
            kind,
            field,
            reference: r,
            candidate: c,
            values,
            rule,
            context,
            lengths: (reference.events.len(), candidate.events.len()),
            alarms: (reference.alarm.as_ref().map(Trace::alarm_line), candidate.alarm.as_ref().map(Trace::alarm_line)),
        })
    };

    if reference.grid != candidate.grid {
        return div(
            0,
            DivergenceKind::GridMismatch,
            Some("grid"),
            grid_name(reference.grid),
            grid_name(candidate.grid),
            None,
            Some(Rule::ComUnits),
        );
    }

    let line = |e: &Event| Trace::event_line(grid, e);
    for (i, (r, c)) in reference.events.iter().zip(&candidate.events).enumerate() {
        match (r, c) {
            (Event::Pass(rp), Event::Pass(cp)) => {
                if let Some((field, rv, cv)) = pass_field(rp, cp) {
                    return div(i, DivergenceKind::FieldMismatch, Some(field), line(r), line(c), Some((rv, cv)), Some(rp.rule));
                }
            }
            (Event::Move(rm), Event::Move(cm)) => {
                if let Some((field, rv, cv)) = move_field(rm, cm) {
                    return div(i, DivergenceKind::FieldMismatch, Some(field), line(r), line(c), Some((rv, cv)), Some(rm.rule));
                }
            }
            _ => {
                let values = Some((variant(r).to_string(), variant(c).to_string()));
                return div(i, DivergenceKind::EventKindMismatch, Some("event"), line(r), line(c), values, Some(r.rule()));
            }
        }
    }

    let n = reference.events.len().min(candidate.events.len());
    let end = |alarm: &Option<Alarm>| match alarm {
        Some(a) => Trace::alarm_line(a),
        None => END.to_string(),
    };
    match (reference.events.get(n), candidate.events.get(n)) {
        (Some(r), None) => match &candidate.alarm {
            Some(a) => div(n, DivergenceKind::UnexpectedAlarm, None, line(r), Trace::alarm_line(a), None, Some(r.rule())),
            None => div(n, DivergenceKind::MissingEvents, None, line(r), END.to_string(), None, Some(r.rule())),
        },
        (None, Some(c)) => match &reference.alarm {
            Some(a) => div(n, DivergenceKind::MissingAlarm, None, Trace::alarm_line(a), line(c), None, Some(a.rule)),
            None => div(n, DivergenceKind::ExtraEvents, None, END.to_string(), line(c), None, None),
        },
        _ => match (&reference.alarm, &candidate.alarm) {
            (None, None) => Ok(()),
            (Some(ra), Some(ca)) => match alarm_field(ra, ca) {
                None => Ok(()),
                Some((field, rv, cv)) => div(
                    n,
                    DivergenceKind::AlarmMismatch,
                    Some(field),
                    Trace::alarm_line(ra),
                    Trace::alarm_line(ca),
                    Some((rv, cv)),
                    Some(ra.rule),
                ),
            },
            (Some(ra), None) => {
                div(n, DivergenceKind::MissingAlarm, None, Trace::alarm_line(ra), end(&candidate.alarm), None, Some(ra.rule))
            }
            (None, Some(ca)) => {
                div(n, DivergenceKind::UnexpectedAlarm, None, end(&reference.alarm), Trace::alarm_line(ca), None, None)
            }
        },
    }
}

/// How the end of a trace without an alarm is shown.
const END: &str = "end of trace (no alarm)";

fn variant(e: &Event) -> &'static str {
    match e {
        Event::Pass(_) => "pass",
        Event::Move(_) => "move",
    }
}

fn differ<T: PartialEq + ToString>(field: &'static str, r: T, c: T) -> Option<(&'static str, String, String)> {
    (r != c).then(|| (field, r.to_string(), c.to_string()))
}

/// The first differing field of two pass headers (the rule tag is not compared). Every field is
/// named, so a field added to `Pass` does not compile here until it is compared.
fn pass_field(r: &Pass, c: &Pass) -> Option<(&'static str, String, String)> {
    let Pass { index, kind, diameter_depth, rule: _ } = *r;
    differ("index", index, c.index)
        .or_else(|| differ("kind", kind.name(), c.kind.name()))
        .or_else(|| differ("diameter_depth", diameter_depth, c.diameter_depth))
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
fn move_field(r: &Move, c: &Move) -> Option<(&'static str, String, String)> {
    let Move { kind, x, z, feed, cx, cz, angle, lead_change, lead_change_angle, lead_floor, rule: _ } = *r;
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
}

/// The first differing field of two alarms: code, word, line, rule.
fn alarm_field(r: &Alarm, c: &Alarm) -> Option<(&'static str, String, String)> {
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
        let ending = |n: usize, alarm: &Option<String>| match alarm {
            Some(a) => format!("{n} events, then {a}"),
            None => format!("{n} events, no alarm"),
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
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use cycle_vocab::{Increment, PassKind, Units};

    fn rapid(x: i64, z: i64) -> Event {
        Event::Move(Move::rapid(x, z, Rule::G92Path))
    }
    fn thread(x: i64, z: i64) -> Event {
        Event::Move(Move::thread(x, z, 30_000, 0, Rule::G92Pullout))
    }
    fn pass(index: u32, depth: i64) -> Event {
        Event::Pass(Pass { index, kind: PassKind::Rough, diameter_depth: depth, rule: Rule::G76Depth1 })
    }
    fn alarm(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
        Some(Alarm::new(code, Some(word), rule, line))
    }

    /// The manual's first G92 cycle (G92.EXAMPLE), by hand.
    fn g92() -> Trace {
        Trace {
            grid: Grid::METRIC_ISB,
            events: vec![
                rapid(65_000, 5_000),
                pass(1, 6_300),
                rapid(58_700, 5_000),
                thread(58_700, -27_000),
                thread(64_700, -28_000),
                rapid(65_000, -28_000),
                rapid(65_000, 5_000),
            ],
            alarm: None,
        }
    }

    fn with(events: Vec<Event>, alarm: Option<Alarm>) -> Trace {
        Trace { grid: Grid::METRIC_ISB, events, alarm }
    }

    #[test]
    fn equal_traces_conform() {
        assert_eq!(check(&g92(), &g92()), Ok(()));
        let a = alarm(AlarmCode::MissingWord, b'P', Rule::G76Required, 3);
        assert_eq!(check(&with(vec![rapid(1, 2)], a), &with(vec![rapid(1, 2)], a)), Ok(()));
        assert_eq!(check(&with(vec![], None), &with(vec![], None)), Ok(()));
    }

    #[test]
    fn rule_tags_are_not_compared() {
        let mut c = g92();
        for e in &mut c.events {
            match e {
                Event::Move(m) => m.rule = Rule::PrjTrace,
                Event::Pass(p) => p.rule = Rule::PrjTrace,
            }
        }
        assert_eq!(check(&g92(), &c), Ok(()));
    }

    #[test]
    fn grid_mismatch() {
        let mut c = g92();
        c.grid = Grid { units: Units::Metric, increment: Increment::Isc };
        let d = check(&g92(), &c).unwrap_err();
        assert_eq!((d.kind, d.index, d.field), (DivergenceKind::GridMismatch, 0, Some("grid")));
        assert_eq!((d.reference.as_str(), d.candidate.as_str()), ("MM GRID 0.001", "MM GRID 0.0001"));
        assert!(d.context.is_empty());
        let text = d.to_string();
        assert!(text.contains("grid mismatch") && text.contains("MM GRID 0.0001"), "{text}");
    }

    #[test]
    fn field_mismatch_names_field_values_rule_and_context() {
        let mut c = g92();
        c.events[3] = thread(58_702, -27_000);
        let d = check(&g92(), &c).unwrap_err();
        assert_eq!((d.kind, d.index, d.field), (DivergenceKind::FieldMismatch, 3, Some("x")));
        assert_eq!(d.reference, "G32 X58.700 Z-27.000 F3.0000");
        assert_eq!(d.candidate, "G32 X58.702 Z-27.000 F3.0000");
        assert_eq!(d.values, Some(("58700".to_string(), "58702".to_string())));
        assert_eq!(d.rule, Some(Rule::G92Pullout));
        assert_eq!(d.context.len(), 3);
        assert_eq!(d.context[0], (0, "G00 X65.000 Z5.000".to_string()));
        assert_eq!(d.context[2], (2, "G00 X58.700 Z5.000".to_string()));
        let text = d.to_string();
        for part in [
            "field mismatch at event 3, field `x`",
            "reference: G32 X58.700 Z-27.000 F3.0000",
            "candidate: G32 X58.702 Z-27.000 F3.0000",
            "x differs: reference 58700, candidate 58702 (grid increments)",
            "rule: G92.PULLOUT (M002, impl): K before the end",
            "(PASS 1 ROUGH DEPTH 3.150)",
        ] {
            assert!(text.contains(part), "missing {part:?} in\n{text}");
        }
    }

    /// The event with one field changed: a number one more, a kind another variant.
    fn with_field_changed(event: &Event, field: &str) -> Event {
        let mut json = serde_json::to_value(event).unwrap();
        let value = json[field].clone();
        if let Some(n) = value.as_i64() {
            json[field] = (n + 1).into();
            return serde_json::from_value(json).unwrap();
        }
        for variant in ["rapid", "feed", "thread", "ROUGH", "FINISH", "SPRING"] {
            json[field] = variant.into();
            match serde_json::from_value::<Event>(json.clone()) {
                Ok(changed) if changed != *event => return changed,
                _ => {}
            }
        }
        panic!("no other value for {field} = {value}")
    }

    /// Every field of a move and of a pass but the rule tag, changed alone, is a divergence
    /// naming it. The fields are those the event serializes, so a field added to `Move` or
    /// `Pass` is tried without a change here.
    #[test]
    fn a_change_in_any_single_field_diverges_naming_it() {
        let m = Event::Move(Move::variable_thread(1_000, -2_000, 30_000, 120_000, -5, 90_000, 5, Rule::G76Path));
        let p = Event::Pass(Pass { index: 2, kind: PassKind::Finish, diameter_depth: 4_800, rule: Rule::G76Finish });
        for (event, fields) in [(m, 8), (p, 3)] {
            let json = serde_json::to_value(event).unwrap();
            let names: Vec<&String> = json.as_object().unwrap().keys().filter(|k| *k != "event" && *k != "rule").collect();
            assert!(names.len() >= fields, "{names:?}");
            for field in names {
                let changed = with_field_changed(&event, field);
                let d = check(&with(vec![event], None), &with(vec![changed], None)).unwrap_err();
                assert_eq!((d.kind, d.index, d.field), (DivergenceKind::FieldMismatch, 0, Some(field.as_str())), "{changed:?}");
                assert_eq!(d.rule, Some(event.rule()));
            }
        }
    }

    /// A variable lead that differs only in how it changes is a divergence naming that field,
    /// with its unit.
    #[test]
    fn lead_change_divergence_is_reported() {
        let r = Move::variable_thread(24_000, -18_000, 15_000, 0, 500, 180_000, 0, Rule::G162F);
        let c = Move { lead_change_angle: 360_000, ..r };
        let d = check(&with(vec![Event::Move(r)], None), &with(vec![Event::Move(c)], None)).unwrap_err();
        assert_eq!((d.kind, d.field, d.rule), (DivergenceKind::FieldMismatch, Some("lead_change_angle"), Some(Rule::G162F)));
        let text = d.to_string();
        assert!(text.contains("lead_change_angle differs: reference 180000, candidate 360000 (0.001°)"), "{text}");
        assert!(text.contains("K0.0500 J180000"), "{text}");
    }

    #[test]
    fn event_kind_mismatch() {
        let mut c = g92();
        c.events.remove(1); // the pass header is missing: a move stands at index 1
        let d = check(&g92(), &c).unwrap_err();
        assert_eq!((d.kind, d.index, d.field), (DivergenceKind::EventKindMismatch, 1, Some("event")));
        assert_eq!(d.reference, "(PASS 1 ROUGH DEPTH 3.150)");
        assert_eq!(d.candidate, "G00 X58.700 Z5.000");
        assert_eq!(d.rule, Some(Rule::G76Depth1));
        assert!(d.to_string().contains("event kind mismatch at event 1"), "{d}");
    }

    #[test]
    fn missing_events() {
        let mut c = g92();
        c.events.truncate(5);
        let d = check(&g92(), &c).unwrap_err();
        assert_eq!((d.kind, d.index, d.field), (DivergenceKind::MissingEvents, 5, None));
        assert_eq!(d.reference, "G00 X65.000 Z-28.000");
        assert_eq!(d.candidate, END);
        assert_eq!(d.lengths, (7, 5));
        assert_eq!(d.rule, Some(Rule::G92Path));
        // An empty candidate (the production expander before it exists) diverges at event 0.
        let d = check(&g92(), &with(vec![], None)).unwrap_err();
        assert_eq!((d.kind, d.index), (DivergenceKind::MissingEvents, 0));
        assert!(d.to_string().contains("context: none"), "{d}");
    }

    #[test]
    fn extra_events() {
        let mut c = g92();
        c.events.push(rapid(0, 0));
        let d = check(&g92(), &c).unwrap_err();
        assert_eq!((d.kind, d.index), (DivergenceKind::ExtraEvents, 7));
        assert_eq!((d.reference.as_str(), d.candidate.as_str()), (END, "G00 X0.000 Z0.000"));
        assert_eq!(d.rule, None);
        assert_eq!(d.context.len(), CONTEXT);
    }

    #[test]
    fn alarm_mismatch_in_every_field() {
        let r = Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3);
        let cases: [(&str, Alarm); 5] = [
            ("code", Alarm { code: AlarmCode::OutOfRange, ..r }),
            ("word", Alarm { word: Some(b'Q'), ..r }),
            ("word", Alarm { word: None, ..r }),
            ("line", Alarm { line: 4, ..r }),
            ("rule", Alarm { rule: Rule::ComLead, ..r }),
        ];
        for (field, c) in cases {
            let d = check(&with(vec![rapid(1, 1)], Some(r)), &with(vec![rapid(1, 1)], Some(c))).unwrap_err();
            assert_eq!((d.kind, d.index, d.field), (DivergenceKind::AlarmMismatch, 1, Some(field)));
            assert_eq!(d.rule, Some(Rule::G76Required));
            assert_eq!(d.reference, "(ALARM 2001 LINE 3 WORD P RULE G76.REQUIRED)");
        }
        let d = check(&with(vec![], Some(r)), &with(vec![], Some(Alarm { code: AlarmCode::OutOfRange, ..r }))).unwrap_err();
        assert_eq!(d.values, Some(("2001 MISSING WORD".to_string(), "2002 OUT OF RANGE".to_string())));
        assert!(d.to_string().contains("rule: G76.REQUIRED (M001, impl): P(k) or Q(Δd) missing"), "{d}");
    }

    #[test]
    fn unexpected_alarm() {
        let a = alarm(AlarmCode::Geometry, b'K', Rule::G92Pullout, 2);
        // Where the reference ends cleanly…
        let d = check(&g92(), &with(g92().events, a)).unwrap_err();
        assert_eq!((d.kind, d.index), (DivergenceKind::UnexpectedAlarm, 7));
        assert_eq!((d.reference.as_str(), d.candidate.as_str()), (END, "(ALARM 3001 LINE 2 WORD K RULE G92.PULLOUT)"));
        // …and where it goes on.
        let d = check(&g92(), &with(g92().events[..2].to_vec(), a)).unwrap_err();
        assert_eq!((d.kind, d.index), (DivergenceKind::UnexpectedAlarm, 2));
        assert_eq!(d.reference, "G00 X58.700 Z5.000");
        assert_eq!(d.rule, Some(Rule::G92Path));
    }

    #[test]
    fn missing_alarm() {
        let a = alarm(AlarmCode::OutOfRange, b'P', Rule::G78Mode, 3);
        let r = with(vec![rapid(80_000, 10_000)], a);
        // The candidate ends cleanly where the reference alarms…
        let d = check(&r, &with(vec![rapid(80_000, 10_000)], None)).unwrap_err();
        assert_eq!((d.kind, d.index), (DivergenceKind::MissingAlarm, 1));
        assert_eq!((d.reference.as_str(), d.candidate.as_str()), ("(ALARM 2002 LINE 3 WORD P RULE G78.MODE)", END));
        assert_eq!(d.rule, Some(Rule::G78Mode));
        // …or goes on moving.
        let d = check(&r, &with(vec![rapid(80_000, 10_000), pass(1, 10)], None)).unwrap_err();
        assert_eq!((d.kind, d.index), (DivergenceKind::MissingAlarm, 1));
        assert_eq!(d.candidate, "(PASS 1 ROUGH DEPTH 0.005)");
        assert!(d.to_string().contains("rule: G78.MODE (M000, impl)"), "{d}");
    }

    #[test]
    fn every_kind_is_reachable() {
        // The kinds above, once more through one table, so that a kind no test reaches shows.
        let mut seen = std::collections::BTreeSet::new();
        let a = alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, 1);
        let b = alarm(AlarmCode::MissingWord, b'P', Rule::G76Required, 1);
        let isc = Trace { grid: Grid { units: Units::Inch, increment: Increment::Isc }, ..with(vec![], None) };
        let pairs = [
            (with(vec![], None), isc),
            (with(vec![rapid(1, 1)], None), with(vec![rapid(1, 2)], None)),
            (with(vec![rapid(1, 1)], None), with(vec![pass(1, 1)], None)),
            (with(vec![rapid(1, 1)], None), with(vec![], None)),
            (with(vec![], None), with(vec![rapid(1, 1)], None)),
            (with(vec![], a), with(vec![], b)),
            (with(vec![], None), with(vec![], a)),
            (with(vec![], a), with(vec![], None)),
        ];
        for (r, c) in &pairs {
            seen.insert(check(r, c).unwrap_err().kind);
        }
        assert_eq!(seen.into_iter().collect::<Vec<_>>(), DivergenceKind::ALL.to_vec());
    }

    #[test]
    fn alarm_texts() {
        let a = Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3);
        assert_eq!(alarm_summary(&a), "ALARM 2001 MISSING WORD: word P, rule G76.REQUIRED, line 3");
        assert_eq!(alarm_short(&a), "alarm 2001 P G76.REQUIRED");
        let b = Alarm::new(AlarmCode::TooManyPasses, None, Rule::PrjMaxPass, 2);
        assert_eq!(alarm_summary(&b), "ALARM 3002 TOO MANY PASSES: rule PRJ.MAXPASS, line 2");
        let c = Alarm::new(AlarmCode::BadCharacter, Some(0x80), Rule::PrjLex, 1);
        assert_eq!(alarm_summary(&c), "ALARM 1001 BAD CHARACTER: word 0x80, rule PRJ.LEX, line 1");
        assert_eq!(code_name(AlarmCode::WordNotAllowed), "WORD NOT ALLOWED");
    }

    #[test]
    fn json_form() {
        let mut c = g92();
        c.events[3] = thread(58_702, -27_000);
        let j = to_json(&check(&g92(), &c).unwrap_err());
        assert_eq!(j["kind"], "field mismatch");
        assert_eq!(j["index"], 3);
        assert_eq!(j["field"], "x");
        assert_eq!(j["rule"], "G92.PULLOUT");
        assert_eq!(j["values"]["candidate"], "58702");
    }
}
