//! Operator events: feed hold, cycle start, single block, reset (docs/INTERPRETATION.md,
//! "Operator events"; OP.*, G92.HOLD, G92.SINGLE, G92.RESET, G76.HOLD, G76.SINGLE, G162.NOSTOP).
//!
//! With a script the spec first expands U, the uninterrupted trace (the same program and
//! configuration with an empty script), with a [`note::Note`] per event that the cycles record
//! as they emit it. Then the [`Player`] walks U from its first event, applying the actions in
//! order, and emits the interrupted run. Memory is proportional to U (the reference keeps it
//! whole, for clarity); U itself is bounded as every trace is (PRJ.MAXPASS).
//!
//! | module | rules |
//! |---|---|
//! | [`note`] | what U's events are: block, scope, cut, pull-out, G162 segment |
//! | [`point`] | OP.SCRIPT: the point P, "passes", the check with the configuration |
//! | [`hold`] | OP.HOLD, OP.RESUME, OP.RESET, OP.AT, OP.SCOPE, G92.HOLD, G92.RESET, G76.HOLD, G162.NOSTOP |
//! | [`single`] | OP.SINGLE, G92.SINGLE, G76.SINGLE, G162.NOSTOP, OP.SCOPE |

pub mod hold;
pub mod note;
pub mod point;
pub mod single;

use crate::emit::Sink;
use core::ops::ControlFlow;
use cycle_vocab::{Action, Alarm, AlarmCode, Config, Event, Move, Resume, Rule, Script, Stop, StopReason};
use note::Uninterrupted;
use point::Fraction;

/// Expands `program` under `config` (already checked, with a script) into the interrupted run.
pub fn play(program: &[u8], config: &Config, sink: Sink) -> Option<Alarm> {
    let u = uninterrupted(program, config);
    let bit6 = crate::config::params(config).no18_bit6_hold == 1;
    Player { u: &u, actions: config.operator.actions(), next: 0, single: false, bit6, at: (config.start_x, config.start_z), sink, broke: false, deferred: None }
        .run()
}

/// OP.SCRIPT (PRJ): "U, the uninterrupted trace: the trace of the same program and configuration
/// with an empty script." Expanded with a note per event.
pub fn uninterrupted(program: &[u8], config: &Config) -> Uninterrupted {
    let plain = Config { operator: Script::EMPTY, ..*config };
    let mut events = Vec::new();
    let mut collect = |e| {
        events.push(e);
        ControlFlow::Continue(())
    };
    let mut machine = crate::program::Machine::new(&plain, &mut collect);
    machine.st.out.record();
    let alarm = crate::run_blocks(program, &mut machine);
    let notes = machine.st.out.take_notes();
    drop(machine);
    Uninterrupted { events, notes, alarm }
}

/// What comes after an event of U.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Flow {
    /// The machine is about to begin U's event with this index.
    Begin(usize),
    /// The run ends, with this alarm or none.
    End(Option<Alarm>),
}

/// The machine running U under the script.
struct Player<'u, 's> {
    u: &'u Uninterrupted,
    actions: &'u [Action],
    /// The first action not fired yet: "each waits for its moment, which comes after the
    /// previous action has fired".
    next: usize,
    /// Single-block mode.
    single: bool,
    /// No.0018 bit 6 (G92.HOLD).
    bit6: bool,
    /// Where the tool is (X diameter, Z).
    at: (i64, i64),
    sink: Sink<'s>,
    /// The sink asked to stop.
    broke: bool,
    /// A feed-hold stop pending at the end of U's event (index, rule): G92.HOLD / G76.HOLD with
    /// bit 6 = 1, G162.NOSTOP.
    deferred: Option<(usize, Rule)>,
}

impl Player<'_, '_> {
    /// Walks U from its first event to the end of the run.
    fn run(mut self) -> Option<Alarm> {
        let mut flow = Flow::Begin(0);
        while let Flow::Begin(i) = flow {
            if self.broke {
                return None;
            }
            flow = self.event(i);
        }
        match flow {
            Flow::End(alarm) if !self.broke => alarm,
            _ => None,
        }
    }

    /// U's event `i`, from the moment the machine is about to begin it to its end.
    fn event(&mut self, i: usize) -> Flow {
        let Some(&event) = self.u.events.get(i) else { return Flow::End(self.program_end()) };
        // Everything before event i is done (or a retract returned to the cut's start A): the
        // tool is where U has it (a no-motion block such as G50 may have renamed the position).
        self.at = self.u.start(i);
        self.switch_single_block(i);
        if let Some(alarm) = self.not_a_move(i).or_else(|| self.single_out_of_scope(i)) {
            return Flow::End(Some(alarm));
        }
        let held_at_end = match event {
            Event::Move(m) => match self.run_move(i, m) {
                ControlFlow::Continue(held_at_end) => held_at_end,
                ControlFlow::Break(flow) => return flow,
            },
            other => {
                self.emit(other);
                false
            }
        };
        self.end_of_event(i, held_at_end)
    }

    /// Move `i` of U, `m`, from its start: each Hold or Reset placed on it whose point the part
    /// being executed passes fires in turn; then the (rest of the) move to its end. `Continue`
    /// says whether a feed-hold stop took place at the move's end (fraction 1).
    fn run_move(&mut self, i: usize, m: Move) -> ControlFlow<Flow, bool> {
        let mut from = Fraction::START;
        let mut held_at_end = false;
        while let Some(action) = self.point_action(i, from) {
            self.next += 1;
            match self.fire(i, m, action)? {
                Some(resumed_from) => {
                    from = resumed_from;
                    held_at_end |= from.is_end();
                }
                // OP.SCRIPT: "An action fired at the fraction f′ of a move that runs on […] leaves
                // the rest of that move covering [f′, 1] for the actions after it: nothing fires
                // behind the tool."
                None => {
                    if let Action::Hold(along) | Action::Reset(along) = action {
                        from = Fraction::of(&along);
                    }
                }
            }
        }
        self.go(m);
        ControlFlow::Continue(held_at_end)
    }

    /// The next action when it is a Hold or Reset on move `i` whose point the part of the move
    /// from `from` passes (OP.SCRIPT).
    fn point_action(&self, i: usize, from: Fraction) -> Option<Action> {
        match self.actions.get(self.next)? {
            a @ (Action::Hold(along) | Action::Reset(along)) if along.event as usize == i && point::covers(from, along) => Some(*a),
            _ => None,
        }
    }

    /// The end of U's event `i`: a pending feed-hold stop there, else the single-block stop due.
    fn end_of_event(&mut self, i: usize, held_at_end: bool) -> Flow {
        if let Some((at, rule)) = self.deferred {
            if at == i {
                self.deferred = None;
                return self.feed_hold_stop(rule, Flow::Begin(i + 1));
            }
        }
        // "Only one stop at one moment: a feed-hold stop at the end of an event where a
        // single-block stop is due replaces it."
        if !held_at_end {
            self.single_block_stop(i);
        }
        Flow::Begin(i + 1)
    }

    /// OP.RESUME (PRJ): `Stop(FEED_HOLD, rule)`, then the machine waits: "`Start`: cycle start,
    /// pressed at the next feed-hold stop" gives `Resume(OP.RESUME)` and `then`; any other next
    /// action, or none, ends the run (OP.REACH).
    fn feed_hold_stop(&mut self, rule: Rule, then: Flow) -> Flow {
        self.emit(Event::Stop(Stop { reason: StopReason::FeedHold, rule }));
        if self.actions.get(self.next) != Some(&Action::Start) {
            return Flow::End(self.unreached());
        }
        self.next += 1;
        self.emit(Event::Resume(Resume { rule: Rule::OpResume }));
        then
    }

    /// OP.REACH (PRJ): "when the run ends (the program's end, or a feed-hold stop not followed
    /// by `Start`) with actions not fired, the alarm `OPERATOR` on line 0, no word, rule
    /// OP.REACH, ends the trace."
    fn unreached(&self) -> Option<Alarm> {
        (self.next < self.actions.len()).then(|| Alarm::new(AlarmCode::Operator, None, Rule::OpReach, 0))
    }

    /// The end of U (OP.REACH): "A program alarm of U ends the interrupted run too, when the run
    /// gets there; it is then the one alarm (no OP.REACH)."
    fn program_end(&self) -> Option<Alarm> {
        self.u.alarm.or_else(|| self.unreached())
    }

    /// PRJ.TRACE: hands `event` to the sink, unless it asked to stop.
    fn emit(&mut self, event: Event) {
        if !self.broke && (self.sink)(event).is_break() {
            self.broke = true;
        }
    }

    /// PRJ.NOOP (PRJ): a move to where the tool is is not emitted; otherwise the tool moves.
    /// ("Either is omitted when it has no length".)
    fn go(&mut self, m: Move) {
        if (m.x, m.z) != self.at {
            self.emit(Event::Move(m));
            self.at = (m.x, m.z);
        }
    }
}
