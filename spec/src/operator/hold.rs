//! Feed hold and reset at a point of a move (docs/INTERPRETATION.md, "Operator events": "Feed
//! hold", "Reset"): which rule a press falls under, and what the machine does.

use super::note::{Note, Scope};
use super::point::{ending_at, point, Fraction};
use super::{Flow, Player};
use crate::pullout::LongAxis;
use core::ops::ControlFlow;
use cycle_vocab::{Action, Alarm, AlarmCode, Along, Button, Event, Move, MoveKind, Press, Rule};

/// What a Hold on a move does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum HoldKind {
    /// OP.HOLD: the move ends at P and the machine stops.
    Stop,
    /// G92.HOLD / G76.HOLD (the rule): a thread move of a cut.
    Thread(Rule),
    /// G162.NOSTOP: segments ② and ③ run on to the end of ③.
    NoStop,
    /// OP.SCOPE: no operator event is modelled in this block.
    OutOfScope,
}

impl HoldKind {
    /// The rule of the `Press`.
    fn rule(self) -> Rule {
        match self {
            HoldKind::Stop => Rule::OpHold,
            HoldKind::Thread(rule) => rule,
            HoldKind::NoStop => Rule::G162NoStop,
            HoldKind::OutOfScope => Rule::OpScope,
        }
    }
}

/// OP.HOLD, G92.HOLD, G76.HOLD, G162.NOSTOP, OP.SCOPE (PRJ, M002, M004): "OP.HOLD — a plain
/// G00/G01 move; in G92/G76/G78 a rapid (①, ③, ④, the rapids to the lead-in point or to Bn); in
/// G162 segments ①, ④, ⑤"; G92.HOLD (G92) and G76.HOLD (G76, G78) — "a thread move of a cut: the
/// lead-in move (G76.LEADIN), the cut to the pull-out start (or to D without a pull-out), the
/// pull-out"; G162.NOSTOP — "G162 segments ② and ③"; any other block: OP.SCOPE.
pub fn hold_kind(note: &Note, m: &Move) -> HoldKind {
    let thread = m.kind == MoveKind::Thread;
    match note.scope {
        Scope::Plain => HoldKind::Stop,
        Scope::G92 if thread => HoldKind::Thread(Rule::G92Hold),
        Scope::G76 if thread => HoldKind::Thread(Rule::G76Hold),
        Scope::G92 | Scope::G76 => HoldKind::Stop,
        Scope::G162 if matches!(note.segment, 2 | 3) => HoldKind::NoStop,
        Scope::G162 => HoldKind::Stop,
        Scope::Other => HoldKind::OutOfScope,
    }
}

/// G92.RESET, OP.RESET (M002, PRJ): "The rule is G92.RESET on a thread move of a G92/G76/G78 cut
/// (M002 note 11: the thread cut decelerates and stops), OP.RESET elsewhere."
pub fn reset_rule(note: &Note, m: &Move) -> Rule {
    match note.scope {
        Scope::G92 | Scope::G76 if m.kind == MoveKind::Thread => Rule::G92Reset,
        _ => Rule::OpReset,
    }
}

impl Player<'_, '_> {
    /// OP.AT (PRJ): "when a pending Hold or Reset's event e is about to begin and it is not a
    /// move (a pass header, a dwell, a spindle event), the alarm `OPERATOR` (3005) on that
    /// block's line, no word, rule OP.AT, replaces it."
    pub(super) fn not_a_move(&self, i: usize) -> Option<Alarm> {
        let (Some(Action::Hold(along) | Action::Reset(along)), Some(event)) = (self.actions.get(self.next), self.u.events.get(i)) else {
            return None;
        };
        let at = along.event as usize == i && !matches!(event, Event::Move(_));
        at.then(|| Alarm::new(AlarmCode::Operator, None, Rule::OpAt, self.u.notes[i].line))
    }

    /// The Hold or Reset `action` fires on move `i` of U, `m`. `Continue(Some(f))`: the move was
    /// cut short at f and cycle start resumed it (its rest covers [f, 1]); `Continue(None)`: the
    /// move runs on; `Break`: the run goes elsewhere (a cut repeated) or ends.
    pub(super) fn fire(&mut self, i: usize, m: Move, action: Action) -> ControlFlow<Flow, Option<Fraction>> {
        let note = self.u.notes[i];
        let (Action::Hold(along) | Action::Reset(along)) = action else { return ControlFlow::Continue(None) };
        let kind = hold_kind(&note, &m);
        if kind == HoldKind::OutOfScope {
            // OP.SCOPE: "A Hold or Reset whose move belongs to any other block […] is the alarm
            // `OPERATOR` on that block's line, no word, rule OP.SCOPE, in place of that event."
            return ControlFlow::Break(Flow::End(Some(Alarm::new(AlarmCode::Operator, None, Rule::OpScope, note.line))));
        }
        let p = point(self.u.start(i), self.u.end(i), &along);
        if matches!(action, Action::Reset(_)) {
            return ControlFlow::Break(self.reset(m, p, reset_rule(&note, &m)));
        }
        if self.deferred.is_some() {
            // "A Hold pressed while a stop is already pending (bit 6 = 1, G162 ②–③) is recorded
            // (`Press`) and adds no stop."
            self.press(Button::Hold, p, kind.rule());
            return ControlFlow::Continue(None);
        }
        match kind {
            HoldKind::Thread(rule) if !self.bit6 => ControlFlow::Break(self.retract(i, m, p, rule)),
            HoldKind::Thread(rule) => {
                self.run_on(p, self.u.last_thread_move(i), rule);
                ControlFlow::Continue(None)
            }
            HoldKind::NoStop => {
                self.run_on(p, self.end_of_leg(i), Rule::G162NoStop);
                ControlFlow::Continue(None)
            }
            HoldKind::Stop | HoldKind::OutOfScope => self.stop_at(m, p, &along),
        }
    }

    /// PRJ.TRACE: "`Press {button: HOLD | RESET, x, z, rule}`: the button was pressed with the
    /// tool at P. It comes before the (rest of the) move during which it was pressed."
    fn press(&mut self, button: Button, p: (i64, i64), rule: Rule) {
        self.emit(Event::Press(Press { button, x: p.0, z: p.1, rule }));
    }

    /// OP.HOLD, OP.RESUME (PRJ): "`Press(HOLD, P, OP.HOLD)`, the move to P,
    /// `Stop(FEED_HOLD, OP.HOLD)`. `Start`: `Resume(OP.RESUME)`, the rest of the move to its end,
    /// and U goes on."
    fn stop_at(&mut self, m: Move, p: (i64, i64), along: &Along) -> ControlFlow<Flow, Option<Fraction>> {
        self.press(Button::Hold, p, Rule::OpHold);
        self.go(ending_at(m, p));
        match self.feed_hold_stop(Rule::OpHold, Flow::Begin(0)) {
            Flow::End(alarm) => ControlFlow::Break(Flow::End(alarm)),
            Flow::Begin(_) => ControlFlow::Continue(Some(Fraction::of(along))),
        }
    }

    /// G92.HOLD, G76.HOLD with bit 6 = 1 (M002 note 1): "`Press(HOLD, P, rule)`, U runs on to the
    /// end of the cut's last thread move (the pull-out's end E, or D without one), then
    /// `Stop(FEED_HOLD, rule)`"; G162.NOSTOP: "U runs on to the end of ③ (of ② when ③ is not
    /// emitted), then `Stop(FEED_HOLD, G162.NOSTOP)`". The stop waits at the end of event `until`.
    fn run_on(&mut self, p: (i64, i64), until: usize, rule: Rule) {
        self.press(Button::Hold, p, rule);
        self.deferred = Some((until, rule));
    }

    /// G162.NOSTOP (M004): the last event of segments ②–③ from move `i`: ③ when it follows.
    fn end_of_leg(&self, i: usize) -> usize {
        let leg_follows = self.u.notes[i].segment == 2 && self.u.notes.get(i + 1).is_some_and(|n| n.segment == 3);
        if leg_follows {
            i + 1
        } else {
            i
        }
    }

    /// G92.HOLD, G76.HOLD with bit 6 = 0 (M002 note 9), OP.RESUME: "`Press(HOLD, P, rule)`, the
    /// thread move to P, then the retract, each move tagged with the rule: 1. pull-out manner
    /// […] to P + (E − S) […] when the held move is before the pull-out, or to E when the held
    /// move is the pull-out […] No pull-out: no such move. 2. a rapid on the short axis to A's
    /// coordinate: Z long (COM.LONGAXIS, the cycle's own decision) → X to A.x; X long → Z to A.z;
    /// 3. a rapid on the long axis to A; 4. `Stop(FEED_HOLD, rule)`. `Start`: `Resume(OP.RESUME)`,
    /// then the interrupted cut again from its first event". The move cut short at P keeps its
    /// own rule ("A move cut short at P keeps every field of the original move"); the retract's
    /// moves carry `rule`.
    fn retract(&mut self, i: usize, m: Move, p: (i64, i64), rule: Rule) -> Flow {
        let Some(cut) = self.u.notes[i].cut else {
            // Not reachable: every move of G92, G76, G78 belongs to a cut.
            return Flow::End(self.unreached());
        };
        let a = self.u.start(cut.first);
        self.press(Button::Hold, p, rule);
        self.go(ending_at(m, p));
        if let Some(pullout) = self.u.pullout(i) {
            let (s, e) = (self.u.start(pullout), self.u.end(pullout));
            let to = if pullout == i { e } else { (p.0 + (e.0 - s.0), p.1 + (e.1 - s.1)) };
            self.go(Move { rule, ..ending_at(m, to) });
        }
        let short = match cut.long {
            LongAxis::Z => (a.0, self.at.1),
            LongAxis::X => (self.at.0, a.1),
        };
        self.go(Move::rapid(short.0, short.1, rule));
        self.go(Move::rapid(a.0, a.1, rule));
        self.feed_hold_stop(rule, Flow::Begin(cut.first))
    }

    /// OP.RESET, G92.RESET (PRJ, M002 note 11): "`Press(RESET, P, rule)`, the move to P, and the
    /// trace ends there: no stop, no alarm, nothing after." ("After a reset nothing follows, not
    /// even OP.REACH.")
    fn reset(&mut self, m: Move, p: (i64, i64), rule: Rule) -> Flow {
        self.press(Button::Reset, p, rule);
        self.go(ending_at(m, p));
        Flow::End(None)
    }
}
