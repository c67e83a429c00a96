//! Operator events (docs/INTERPRETATION.md, "Operator events: feed hold, cycle start, single
//! block, reset"): the interrupted run of a program under the configuration's script
//! (`Config::operator`, OP.SCRIPT).
//!
//! A layer between the generators and the caller: it reads the uninterrupted trace U from
//! [`Core`] one event ahead ([`source`]), counts U's event index, knows each event's block kind
//! and line, the cut boundaries, A, the pull-out S → E and the long axis from the generators'
//! state, and carries out the script's actions in order ([`hold`]). A cut abandoned by a
//! G92.HOLD/G76.HOLD retract is repeated from a fixed buffer of its events.
//!
//! **Fixed bounds** (no heap): the script, at most `SCRIPT_MAX` = 16 actions (a copy);
//! one cut, [`source::CUT_MAX`] = 7 events; one event of look-ahead; an output queue of
//! [`OUT_MAX`] = 8 events. **Work per event**: each step of the layer reads at most one event
//! of U (a G92.HOLD retract at most [`source::CUT_MAX`]), fires at most one action (single
//! block switches: at most `SCRIPT_MAX`) and writes at most 6 events; each output event
//! takes a bounded number of steps.

mod along;
pub mod geometry;
mod hold;
pub(crate) mod source;

use crate::stream::Core;
use along::Frac;
use cycle_vocab::{Action, Alarm, AlarmCode, Config, Event, Move, Resume, Rule, Script};
use source::{Item, Look, Source};

/// The most events one step of the layer writes: Press, the move to P, the pull-out-manner
/// move, two rapids and the stop of a G92.HOLD retract (6); a move and a single-block stop
/// and resume (3).
pub const OUT_MAX: usize = 8;

/// What the machine does after a feed-hold stop, once cycle start is pressed (OP.RESUME).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum After {
    /// OP.HOLD: the rest of the current move, from the fraction held at; `at_end`: the stop
    /// was at the move's end, where it replaced a single-block stop.
    Rest { from: Frac, at_end: bool },
    /// G92.HOLD/G76.HOLD, bit 6 = 0: the interrupted cut again from its first event.
    Repeat,
    /// A deferred stop (G92.HOLD bit 6 = 1, G162.NOSTOP): U goes on.
    Next,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    /// About to begin the next event of U.
    Next,
    /// Executing the current move from the fraction `from`; `at_end` as in [`After::Rest`].
    Move { from: Frac, at_end: bool },
    /// At a feed-hold stop, waiting for cycle start.
    Stopped(After),
    /// The run is over (the alarm, if any, is returned last).
    Done,
}

/// A fixed queue of output events.
struct Queue {
    events: [Event; OUT_MAX],
    head: u8,
    len: u8,
}

impl Queue {
    fn push(&mut self, e: Event) {
        let i = usize::from(self.head) + usize::from(self.len);
        if let Some(slot) = self.events.get_mut(i) {
            *slot = e;
            self.len += 1;
        }
    }

    fn pop(&mut self) -> Option<Event> {
        if self.len == 0 {
            self.head = 0;
            return None;
        }
        let e = self.events.get(usize::from(self.head)).copied();
        self.head += 1;
        self.len -= 1;
        e
    }
}

/// The operator layer: the interrupted run.
pub struct Layer {
    script: Script,
    /// The first action not fired.
    next: u8,
    /// Single-block mode (OP.SINGLE).
    single: bool,
    /// No.0018 bit 6 (G92.HOLD).
    bit6: bool,
    src: Source,
    /// The event of U being executed.
    cur: Item,
    /// Where the tool is.
    at: (i64, i64),
    phase: Phase,
    /// A feed-hold stop deferred to the end of the cut's last thread move (G92.HOLD, G76.HOLD,
    /// bit 6 = 1) or of G162's ③ (G162.NOSTOP): its rule.
    deferred: Option<Rule>,
    out: Queue,
    alarm: Option<Alarm>,
}

impl Layer {
    pub fn new(config: &Config) -> Layer {
        Layer {
            script: config.operator,
            next: 0,
            single: false,
            bit6: config.params.no18_bit6_hold == Some(1),
            src: Source::new(),
            cur: Item::NONE,
            at: (config.start_x, config.start_z),
            phase: Phase::Next,
            deferred: None,
            out: Queue { events: [Item::NONE.event; OUT_MAX], head: 0, len: 0 },
            alarm: None,
        }
    }

    /// The first action not fired.
    fn current(&self) -> Option<Action> {
        self.script.actions().get(usize::from(self.next)).copied()
    }

    fn fired(&mut self) {
        self.next = self.next.saturating_add(1);
    }

    /// The next event of the interrupted run, its alarm last.
    pub fn next(&mut self, core: &mut Core<'_>) -> Option<Result<Event, Alarm>> {
        loop {
            if let Some(e) = self.out.pop() {
                return Some(Ok(e));
            }
            if self.phase == Phase::Done {
                return self.alarm.take().map(Err);
            }
            self.step(core);
        }
    }

    /// [`crate::Expander::fill`] with a script: the events of [`Layer::next`].
    pub fn fill(&mut self, core: &mut Core<'_>, out: &mut [Event]) -> Result<usize, Alarm> {
        let mut n = 0;
        for slot in out.iter_mut() {
            match self.next(core) {
                Some(Ok(e)) => {
                    *slot = e;
                    n += 1;
                }
                Some(Err(a)) if n == 0 => return Err(a),
                Some(Err(a)) => {
                    self.alarm = Some(a);
                    break;
                }
                None => break,
            }
        }
        Ok(n)
    }

    fn step(&mut self, core: &mut Core<'_>) {
        match self.phase {
            Phase::Next => self.begin(core),
            Phase::Move { from, at_end } => self.run_move(core, from, at_end),
            Phase::Stopped(after) => self.stopped(after),
            Phase::Done => {}
        }
    }

    /// The run ends with `alarm`, if any.
    fn end(&mut self, alarm: Option<Alarm>) {
        self.alarm = alarm;
        self.phase = Phase::Done;
    }

    /// OP.REACH: the run ends (the program's end, a feed-hold stop not followed by `Start`);
    /// actions not fired are the alarm `OPERATOR` on line 0, no word.
    fn end_reached(&mut self) {
        let alarm = self.current().map(|_| Alarm::new(AlarmCode::Operator, None, Rule::OpReach, 0));
        self.end(alarm);
    }

    /// OP.AT, OP.SCOPE: the alarm `OPERATOR` on `line`, no word, in place of the event.
    fn refuse(&mut self, line: u32, rule: Rule) {
        self.end(Some(Alarm::new(AlarmCode::Operator, None, rule, line)));
    }

    /// The machine is about to begin the next event of U: single-block switches (OP.SCRIPT),
    /// then OP.AT and OP.SCOPE, then the event. U's end ends the run (OP.REACH); U's alarm is
    /// the one alarm.
    fn begin(&mut self, core: &mut Core<'_>) {
        let item = match self.src.take(core) {
            Look::Item(it) => it,
            Look::End(Some(a)) => return self.end(Some(a)),
            Look::End(None) | Look::Empty => return self.end_reached(),
        };
        self.cur = item;
        self.at = item.from;
        // OP.SCRIPT: single-block mode switched before event `before`.
        while let Some(Action::SingleBlock { on, before }) = self.current() {
            if before != item.index {
                break;
            }
            self.single = on;
            self.fired();
        }
        let is_move = matches!(item.event, Event::Move(_));
        let other = item.kind == source::Kind::Other;
        if let Some(Action::Hold(p) | Action::Reset(p)) = self.current() {
            if p.event == item.index && !is_move {
                return self.refuse(item.line, Rule::OpAt);
            }
            if p.event == item.index && other {
                return self.refuse(item.line, Rule::OpScope);
            }
        }
        if self.single && other {
            return self.refuse(item.line, Rule::OpScope);
        }
        if is_move {
            self.phase = Phase::Move { from: Frac::ZERO, at_end: false };
        } else {
            self.out.push(item.event);
            self.end_of_event(core, false);
        }
    }

    /// The current move from `from`: the next action that fires on it, else the (rest of the)
    /// move and the end of the event.
    fn run_move(&mut self, core: &mut Core<'_>, from: Frac, at_end: bool) {
        let Event::Move(m) = self.cur.event else {
            self.phase = Phase::Next;
            return;
        };
        if let Some((reset, f)) = self.firing(from) {
            self.fired();
            let p = along::point(self.cur.from, (m.x, m.z), f);
            if reset {
                return self.reset(&m, p);
            }
            self.hold(core, &m, p, f);
            // OP.SCRIPT: a press on a move that runs on (a deferred stop) leaves the rest of the
            // move covering [f, 1]: nothing fires behind the tool.
            if let Phase::Move { from, .. } = &mut self.phase {
                *from = f;
            }
            return;
        }
        self.move_to(m);
        self.end_of_event(core, at_end);
    }

    /// The current action when it is a Hold or Reset (`true`) that fires on the current move,
    /// executed from `from`: its event is this one and the part executed covers its fraction.
    fn firing(&self, from: Frac) -> Option<(bool, Frac)> {
        let (reset, p) = match self.current()? {
            Action::Hold(p) => (false, p),
            Action::Reset(p) => (true, p),
            _ => return None,
        };
        let f = Frac::of(&p);
        (p.event == self.cur.index && f.at_least(from)).then_some((reset, f))
    }

    /// At a feed-hold stop: `Start` resumes (OP.RESUME); anything else ends the run (OP.REACH).
    fn stopped(&mut self, after: After) {
        if self.current() != Some(Action::Start) {
            return self.end_reached();
        }
        self.fired();
        self.out.push(Event::Resume(Resume { rule: Rule::OpResume }));
        self.phase = match after {
            After::Rest { from, at_end } => Phase::Move { from, at_end },
            After::Repeat => {
                self.src.repeat();
                Phase::Next
            }
            After::Next => Phase::Next,
        };
    }

    /// `m` to its end point, unless the tool is there (PRJ.NOOP).
    fn move_to(&mut self, m: Move) {
        if (m.x, m.z) != self.at {
            self.at = (m.x, m.z);
            self.out.push(Event::Move(m));
        }
    }
}

#[cfg(test)]
mod tests;
