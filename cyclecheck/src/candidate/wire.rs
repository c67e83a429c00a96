//! A faster reading of the usual answer's trace. `Event` is an internally tagged enum, which
//! serde reads by buffering every field of every event before it knows the variant — most of an
//! answer's parsing time. Here each event is read at once into one flat record and checked to
//! hold exactly its variant's fields; an answer in any other form (a field of another variant,
//! an unknown field, a `null`) is left to the derived reading, so both readings agree wherever
//! this one answers.

use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, Button, Dwell, Event, Grid, Move, MoveKind, Pass, PassKind, Press, Resume, Rule, Spindle, SpindleState, Stop, StopReason};
use serde::{Deserialize, Deserializer};

/// A field that may be absent but is never `null`.
struct Field<T>(Option<T>);

impl<T> Default for Field<T> {
    fn default() -> Field<T> {
        Field(None)
    }
}

impl<'de, T: Deserialize<'de>> Deserialize<'de> for Field<T> {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Field<T>, D::Error> {
        T::deserialize(d).map(|v| Field(Some(v)))
    }
}

#[derive(Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
enum Tag {
    Pass,
    Move,
    Dwell,
    Spindle,
    Press,
    Stop,
    Resume,
}

/// `kind`: a move's or a pass's.
#[derive(Deserialize, Clone, Copy)]
enum Kind {
    #[serde(rename = "rapid")]
    Rapid,
    #[serde(rename = "feed")]
    Feed,
    #[serde(rename = "thread")]
    Thread,
    #[serde(rename = "arc_cw")]
    ArcCw,
    #[serde(rename = "arc_ccw")]
    ArcCcw,
    #[serde(rename = "ROUGH")]
    Rough,
    #[serde(rename = "SEMI")]
    Semi,
    #[serde(rename = "FINISH")]
    Finish,
    #[serde(rename = "SPRING")]
    Spring,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Flat {
    event: Tag,
    rule: Rule,
    #[serde(default)]
    kind: Field<Kind>,
    #[serde(default)]
    x: Field<i64>,
    #[serde(default)]
    z: Field<i64>,
    #[serde(default)]
    feed: Field<i64>,
    #[serde(default)]
    cx: Field<i64>,
    #[serde(default)]
    cz: Field<i64>,
    #[serde(default)]
    angle: Field<u32>,
    #[serde(default)]
    lead_change: Field<i64>,
    #[serde(default)]
    lead_change_angle: Field<u32>,
    #[serde(default)]
    lead_floor: Field<i64>,
    #[serde(default)]
    lead_steps: Field<bool>,
    #[serde(default)]
    index: Field<u32>,
    #[serde(default)]
    diameter_depth: Field<i64>,
    #[serde(default)]
    ms: Field<u32>,
    #[serde(default)]
    state: Field<SpindleState>,
    #[serde(default)]
    button: Field<Button>,
    #[serde(default)]
    reason: Field<StopReason>,
}

impl Flat {
    /// How many fields besides `event` and `rule` are present.
    fn present(&self) -> usize {
        let n = [self.x.0.is_some(), self.z.0.is_some(), self.feed.0.is_some(), self.cx.0.is_some(), self.cz.0.is_some()];
        let m = [self.lead_change.0.is_some(), self.lead_floor.0.is_some(), self.diameter_depth.0.is_some(), self.lead_steps.0.is_some()];
        let u = [self.angle.0.is_some(), self.lead_change_angle.0.is_some(), self.index.0.is_some(), self.ms.0.is_some()];
        let e = [self.kind.0.is_some(), self.state.0.is_some(), self.button.0.is_some(), self.reason.0.is_some()];
        n.iter().chain(&m).chain(&u).chain(&e).filter(|&&p| p).count()
    }

    /// The event, when exactly its variant's fields are present (those with a default may be
    /// left out).
    fn event(&self) -> Option<Event> {
        let rule = self.rule;
        let (event, fields) = match self.event {
            Tag::Move => {
                let kind = match self.kind.0? {
                    Kind::Rapid => MoveKind::Rapid,
                    Kind::Feed => MoveKind::Feed,
                    Kind::Thread => MoveKind::Thread,
                    Kind::ArcCw => MoveKind::ArcCw,
                    Kind::ArcCcw => MoveKind::ArcCcw,
                    _ => return None,
                };
                let optional = [
                    self.cx.0.is_some(),
                    self.cz.0.is_some(),
                    self.lead_change_angle.0.is_some(),
                    self.lead_floor.0.is_some(),
                    self.lead_steps.0.is_some(),
                ];
                let m = Move {
                    kind,
                    x: self.x.0?,
                    z: self.z.0?,
                    feed: self.feed.0?,
                    cx: self.cx.0.unwrap_or(0),
                    cz: self.cz.0.unwrap_or(0),
                    angle: self.angle.0?,
                    lead_change: self.lead_change.0?,
                    lead_change_angle: self.lead_change_angle.0.unwrap_or(0),
                    lead_floor: self.lead_floor.0.unwrap_or(0),
                    lead_steps: self.lead_steps.0.unwrap_or(false),
                    rule,
                };
                (Event::Move(m), 6 + optional.iter().filter(|&&p| p).count())
            }
            Tag::Pass => {
                let kind = match self.kind.0? {
                    Kind::Rough => PassKind::Rough,
                    Kind::Semi => PassKind::Semi,
                    Kind::Finish => PassKind::Finish,
                    Kind::Spring => PassKind::Spring,
                    _ => return None,
                };
                (Event::Pass(Pass { index: self.index.0?, kind, diameter_depth: self.diameter_depth.0?, rule }), 3)
            }
            Tag::Dwell => (Event::Dwell(Dwell { ms: self.ms.0?, rule }), 1),
            Tag::Spindle => (Event::Spindle(Spindle { state: self.state.0?, rule }), 1),
            Tag::Press => (Event::Press(Press { button: self.button.0?, x: self.x.0?, z: self.z.0?, rule }), 3),
            Tag::Stop => (Event::Stop(Stop { reason: self.reason.0?, rule }), 1),
            Tag::Resume => (Event::Resume(Resume { rule }), 0),
        };
        (self.present() == fields).then_some(event)
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FlatTrace {
    grid: Grid,
    events: Vec<Flat>,
    alarm: Option<Alarm>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FlatAnswer {
    id: u64,
    trace: FlatTrace,
}

/// The id and trace of an answer `{"id", "trace"}` in the usual form, if it is one.
pub(super) fn read(line: &[u8]) -> Option<(u64, Trace)> {
    let a: FlatAnswer = serde_json::from_slice(line).ok()?;
    let events = a.trace.events.iter().map(Flat::event).collect::<Option<Vec<Event>>>()?;
    Some((a.id, Trace { grid: a.trace.grid, events, alarm: a.trace.alarm }))
}

#[cfg(test)]
mod tests;
