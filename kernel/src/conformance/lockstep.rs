//! The relation applied while both traces go by: the reference's events arrive one at a time
//! ([`Lockstep::reference`]), each is compared with the candidate's next event pulled from its
//! stream, and [`Lockstep::finish`] compares the endings. Only the last [`CONTEXT`] reference
//! events are kept (the report's context), so a trace of any length is compared in constant
//! memory. After the first divergence both traces are still counted to their ends, for the
//! report's lengths and alarms.
//!
//! [`check`] is the same comparison of two whole traces.

use super::{alarm_field, Level, dwell_field, grid_name, move_field, pass_field, press_field, spindle_field, stop_field, variant, Divergence, DivergenceKind, CONTEXT, END};
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, Event, Grid, Rule};
use std::collections::VecDeque;

/// Checks that `candidate` conforms to `reference` (see the module documentation); the first
/// divergence otherwise.
// A divergence is the rare, reported path, and callers match on its fields: it stays unboxed.
#[allow(clippy::result_large_err)]
pub fn check(reference: &Trace, candidate: &Trace) -> Result<(), Divergence> {
    let stream = candidate.events.iter().copied().map(Ok).chain(candidate.alarm.map(Err));
    let mut lockstep = Lockstep::new(reference.grid, candidate.grid, stream);
    for &e in &reference.events {
        lockstep.reference(e);
    }
    lockstep.finish(reference.alarm)
}

/// The comparison of a reference trace arriving event by event with a candidate's stream
/// (its events, then its alarm as `Err`).
pub struct Lockstep<I> {
    grid: Grid,
    candidate: I,
    /// Reference events seen, candidate events read.
    seen: usize,
    read: usize,
    /// The candidate's ending, once its stream has ended: its alarm or none.
    candidate_end: Option<Option<Alarm>>,
    /// The last reference events, with their indices.
    recent: VecDeque<(usize, Event)>,
    first: Option<Divergence>,
    /// What is compared ([`Level`]): events the level does not compare are dropped from both
    /// traces before they are indexed.
    level: Level,
}

/// One step of the candidate's stream.
enum Next {
    Event(Event),
    End(Option<Alarm>),
}

impl<I: Iterator<Item = Result<Event, Alarm>>> Lockstep<I> {
    /// A comparison on the reference's grid of a candidate on `candidate_grid`: they must be
    /// the same grid.
    pub fn new(reference_grid: Grid, candidate_grid: Grid, candidate: I) -> Lockstep<I> {
        let mut l = Lockstep {
            grid: reference_grid,
            candidate,
            seen: 0,
            read: 0,
            candidate_end: None,
            recent: VecDeque::with_capacity(CONTEXT),
            first: None,
            level: Level::Full,
        };
        if reference_grid != candidate_grid {
            let (r, c) = (grid_name(reference_grid), grid_name(candidate_grid));
            l.found(0, DivergenceKind::GridMismatch, Some("grid"), r, c, None, Some(Rule::ComUnits));
        }
        l
    }

    /// The comparison at `level` ([`Level::Full`] unless set).
    pub fn at_level(mut self, level: Level) -> Lockstep<I> {
        self.level = level;
        self
    }

    /// Whether a divergence has been found.
    pub fn diverged(&self) -> bool {
        self.first.is_some()
    }

    fn next(&mut self) -> Next {
        if let Some(end) = self.candidate_end {
            return Next::End(end);
        }
        loop {
            match self.candidate.next() {
                Some(Ok(e)) if !self.level.compares(&e) => {}
                Some(Ok(e)) => {
                    self.read += 1;
                    return Next::Event(e);
                }
                Some(Err(a)) => return self.end(Some(a)),
                None => return self.end(None),
            }
        }
    }

    fn end(&mut self, alarm: Option<Alarm>) -> Next {
        self.candidate_end = Some(alarm);
        Next::End(alarm)
    }

    fn line(&self, e: &Event) -> String {
        Trace::event_line(self.grid, e)
    }

    /// Records the first divergence (lengths and alarms are filled in by [`Lockstep::finish`]).
    #[allow(clippy::too_many_arguments)]
    fn found(
        &mut self,
        index: usize,
        kind: DivergenceKind,
        field: Option<&'static str>,
        reference: String,
        candidate: String,
        values: Option<(String, String)>,
        rule: Option<Rule>,
    ) {
        let context = self.recent.iter().map(|(i, e)| (*i, self.line(e))).collect();
        self.first = Some(Divergence {
            index,
            kind,
            field,
            reference,
            candidate,
            values,
            rule,
            context,
            lengths: (0, 0),
            alarms: (None, None),
            level: self.level,
        });
    }

    /// The reference's next event.
    pub fn reference(&mut self, r: Event) {
        if !self.level.compares(&r) {
            return;
        }
        if self.first.is_none() {
            self.compare(r);
        }
        if self.recent.len() == CONTEXT {
            self.recent.pop_front();
        }
        self.recent.push_back((self.seen, r));
        self.seen += 1;
    }

    fn compare(&mut self, r: Event) {
        let i = self.seen;
        match self.next() {
            Next::Event(c) => {
                let field = match (&r, &c) {
                    (Event::Pass(rp), Event::Pass(cp)) => pass_field(rp, cp).map(|f| (DivergenceKind::FieldMismatch, f)),
                    (Event::Move(rm), Event::Move(cm)) => move_field(rm, cm).map(|f| (DivergenceKind::FieldMismatch, f)),
                    (Event::Dwell(rd), Event::Dwell(cd)) => dwell_field(rd, cd).map(|f| (DivergenceKind::FieldMismatch, f)),
                    (Event::Spindle(rs), Event::Spindle(cs)) => spindle_field(rs, cs).map(|f| (DivergenceKind::FieldMismatch, f)),
                    (Event::Press(rp), Event::Press(cp)) => press_field(rp, cp).map(|f| (DivergenceKind::FieldMismatch, f)),
                    (Event::Stop(rs), Event::Stop(cs)) => stop_field(rs, cs).map(|f| (DivergenceKind::FieldMismatch, f)),
                    (Event::Resume(_), Event::Resume(_)) => None,
                    _ => Some((DivergenceKind::EventKindMismatch, ("event", variant(&r).to_string(), variant(&c).to_string()))),
                };
                if let Some((kind, (field, rv, cv))) = field {
                    self.found(i, kind, Some(field), self.line(&r), self.line(&c), Some((rv, cv)), Some(r.rule()));
                }
            }
            Next::End(Some(a)) => {
                self.found(i, DivergenceKind::UnexpectedAlarm, None, self.line(&r), Trace::alarm_line(&a), None, Some(r.rule()))
            }
            Next::End(None) => self.found(i, DivergenceKind::MissingEvents, None, self.line(&r), END.to_string(), None, Some(r.rule())),
        }
    }

    /// The reference ended with `alarm`: the endings are compared, the candidate read to its
    /// end, and the first divergence, if any, returned with both traces' lengths and alarms.
    #[allow(clippy::result_large_err)]
    pub fn finish(mut self, alarm: Option<Alarm>) -> Result<(), Divergence> {
        if self.first.is_none() {
            self.compare_end(alarm);
        }
        while let Next::Event(_) = self.next() {}
        match self.first.take() {
            None => Ok(()),
            Some(mut d) => {
                d.lengths = (self.seen, self.read);
                d.alarms = (alarm.as_ref().map(Trace::alarm_line), self.candidate_end.flatten().as_ref().map(Trace::alarm_line));
                Err(d)
            }
        }
    }

    fn compare_end(&mut self, alarm: Option<Alarm>) {
        let n = self.seen;
        let alarm_line = |a: &Alarm| Trace::alarm_line(a);
        match (self.next(), alarm) {
            (Next::Event(c), Some(a)) => self.found(n, DivergenceKind::MissingAlarm, None, alarm_line(&a), self.line(&c), None, Some(a.rule)),
            (Next::Event(c), None) => self.found(n, DivergenceKind::ExtraEvents, None, END.to_string(), self.line(&c), None, None),
            (Next::End(None), None) => {}
            (Next::End(Some(ca)), Some(ra)) => {
                let differs = match self.level {
                    Level::Full => alarm_field(&ra, &ca),
                    // The code only: word, line and rule are not compared.
                    Level::Motion => alarm_field(&ra, &ca).filter(|(field, ..)| *field == "code"),
                    Level::MotionAlarmPresence => None,
                };
                if let Some((field, rv, cv)) = differs {
                    self.found(n, DivergenceKind::AlarmMismatch, Some(field), alarm_line(&ra), alarm_line(&ca), Some((rv, cv)), Some(ra.rule));
                }
            }
            (Next::End(None), Some(ra)) => self.found(n, DivergenceKind::MissingAlarm, None, alarm_line(&ra), END.to_string(), None, Some(ra.rule)),
            (Next::End(Some(ca)), None) => self.found(n, DivergenceKind::UnexpectedAlarm, None, END.to_string(), alarm_line(&ca), None, None),
        }
    }
}
