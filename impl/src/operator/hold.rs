//! What each action does where it fires (docs/INTERPRETATION.md, "Feed hold", "Single block",
//! "Reset"): OP.HOLD, G92.HOLD/G76.HOLD (bit 6 = 0: the retract; 1: run on to the end of the
//! cut's last thread move), G162.NOSTOP, OP.RESET/G92.RESET, and the stops decided at the end
//! of each event (OP.SINGLE, G92.SINGLE, G76.SINGLE, G162.NOSTOP).

use super::along::Frac;
use super::geometry::retract_targets;
use super::source::{CutInfo, Kind, Look, Role};
use super::{After, Layer, Phase};
use crate::stream::Core;
use cycle_vocab::{Button, Event, Move, Press, Resume, Rule, Stop, StopReason};

/// Whether a cut event is a thread move of the cut (the lead-in, the cut, the pull-out).
fn thread(c: &CutInfo) -> bool {
    matches!(c.role, Role::Thread | Role::Pullout)
}

/// The rule of a hold pressed on a move of this kind: G92.HOLD (G92) or G76.HOLD (G76, G78)
/// on a thread move of a cut, G162.NOSTOP on G162's ② and ③, OP.HOLD on every other move
/// (plain G00/G01, the rapids of a cut, G162's ①, ④, ⑤).
fn hold_rule(kind: &Kind) -> Rule {
    match kind {
        Kind::Cut(c) if thread(c) && c.g92 => Rule::G92Hold,
        Kind::Cut(c) if thread(c) => Rule::G76Hold,
        Kind::G162(2 | 3) => Rule::G162NoStop,
        _ => Rule::OpHold,
    }
}

impl Layer {
    fn press(&mut self, button: Button, p: (i64, i64), rule: Rule) {
        self.out.push(Event::Press(Press { button, x: p.0, z: p.1, rule }));
    }

    fn stop(&mut self, reason: StopReason, rule: Rule) {
        self.out.push(Event::Stop(Stop { reason, rule }));
    }

    /// The move `m` cut short at `p`: every field kept, the end at `p`; omitted without length.
    fn cut_to(&mut self, m: &Move, p: (i64, i64)) {
        self.move_to(Move { x: p.0, z: p.1, ..*m });
    }

    /// OP.RESET, G92.RESET: `Press(RESET, P)`, the move to P, and nothing after (no stop, no
    /// alarm, not even OP.REACH). G92.RESET on a thread move of a G92/G76/G78 cut, else
    /// OP.RESET.
    pub(super) fn reset(&mut self, m: &Move, p: (i64, i64)) {
        let rule = match &self.cur.kind {
            Kind::Cut(c) if thread(c) => Rule::G92Reset,
            _ => Rule::OpReset,
        };
        self.press(Button::Reset, p, rule);
        self.cut_to(m, p);
        self.end(None);
    }

    /// A Hold fires at `p` (fraction `f`) on the current move `m`.
    ///
    /// - A stop already deferred: recorded (`Press`), no stop added.
    /// - OP.HOLD: `Press(HOLD, P)`, the move to P, `Stop(FEED_HOLD)`; `Start` resumes the rest.
    /// - G92.HOLD / G76.HOLD with bit 6 = 0: [`Layer::retract`]; with bit 6 = 1, and
    ///   G162.NOSTOP: `Press`, the move runs on, the stop deferred ([`Layer::end_of_event`]).
    pub(super) fn hold(&mut self, core: &mut Core<'_>, m: &Move, p: (i64, i64), f: Frac) {
        let rule = hold_rule(&self.cur.kind);
        if self.deferred.is_some() {
            // The phase stays: the move runs on; another action may fire on it.
            return self.press(Button::Hold, p, rule);
        }
        match (rule, self.cur.kind) {
            (Rule::G92Hold | Rule::G76Hold, Kind::Cut(c)) if !self.bit6 => self.retract(core, m, p, &c, rule),
            (Rule::G92Hold | Rule::G76Hold | Rule::G162NoStop, _) => {
                self.press(Button::Hold, p, rule);
                self.deferred = Some(rule);
            }
            _ => {
                self.press(Button::Hold, p, Rule::OpHold);
                self.cut_to(m, p);
                self.stop(StopReason::FeedHold, Rule::OpHold);
                self.phase = Phase::Stopped(After::Rest { from: f, at_end: f.is_one() });
            }
        }
    }

    /// G92.HOLD / G76.HOLD, No.0018 bit 6 = 0: `Press(HOLD, P)`, the thread move to P (cut
    /// short, its own fields), then the retract, each move tagged with `rule`: in the pull-out
    /// manner (a thread move, the held move's lead and angle, to P + (E − S), or to E when the
    /// held move is the pull-out; none without a pull-out), a rapid on the short axis to A's
    /// coordinate (COM.LONGAXIS: Z long → X to A.x; X long → Z to A.z), a rapid on the long axis
    /// to A; `Stop(FEED_HOLD)`. `Start` repeats the cut from its first event (OP.RESUME).
    fn retract(&mut self, core: &mut Core<'_>, m: &Move, p: (i64, i64), c: &CutInfo, rule: Rule) {
        self.press(Button::Hold, p, rule);
        self.cut_to(m, p);
        let r = retract_targets(p, c.role == Role::Pullout, c.pull, c.a, c.z_long);
        if let Some(to) = r.manner {
            self.move_to(Move::thread(to.0, to.1, m.feed, m.angle, rule));
        }
        self.move_to(Move::rapid(r.short.0, r.short.1, rule));
        self.move_to(Move::rapid(r.end.0, r.end.1, rule));
        self.stop(StopReason::FeedHold, rule);
        // The rest of the cut is read now, for the repeat.
        self.src.drain(core);
        self.phase = Phase::Stopped(After::Repeat);
    }

    /// The current event has ended: a deferred feed-hold stop due here (it replaces a
    /// single-block stop), else the single-block stop due here when the mode is on — unless
    /// the event ended at a feed-hold stop (`at_end`), which replaced it. Then U goes on.
    pub(super) fn end_of_event(&mut self, core: &mut Core<'_>, at_end: bool) {
        let next = match self.src.peek(core) {
            Look::Item(it) => Some(it.kind),
            _ => None,
        };
        if let Some(rule) = self.deferred {
            if deferred_due(&self.cur.kind, next.as_ref()) {
                self.deferred = None;
                self.stop(StopReason::FeedHold, rule);
                self.phase = Phase::Stopped(After::Next);
                return;
            }
        }
        self.phase = Phase::Next;
        if !self.single || at_end {
            return;
        }
        if let Some(rule) = single_due(&self.cur.event, &self.cur.kind, next.as_ref()) {
            self.stop(StopReason::SingleBlock, rule);
            self.out.push(Event::Resume(Resume { rule }));
        }
    }
}

/// Whether `next` continues the cut of `c`.
fn same_cut(next: Option<&Kind>) -> Option<&CutInfo> {
    match next {
        Some(Kind::Cut(n)) if !n.begin => Some(n),
        _ => None,
    }
}

/// G92.HOLD/G76.HOLD bit 6 = 1: the deferred stop comes at the end of the cut's last thread
/// move (the pull-out's end E, or D without one), before the rapid ③. G162.NOSTOP: at the end
/// of ③ (of ② when ③ is not emitted).
fn deferred_due(cur: &Kind, next: Option<&Kind>) -> bool {
    match cur {
        Kind::Cut(c) if thread(c) => !same_cut(next).is_some_and(thread),
        Kind::G162(2 | 3) => !matches!(next, Some(Kind::G162(3))),
        _ => true,
    }
}

/// The single-block stop due after an event, with its rule: OP.SINGLE after the move of a
/// plain G00/G01 block; G92.SINGLE (G92) / G76.SINGLE (G76, G78) after a cut's return to A
/// (its last event), never inside a cut; G162.NOSTOP after each move of ①, ④, ⑤, never after
/// ② or ③.
fn single_due(event: &Event, cur: &Kind, next: Option<&Kind>) -> Option<Rule> {
    let moved = matches!(event, Event::Move(_));
    match cur {
        Kind::Plain if moved => Some(Rule::OpSingle),
        Kind::Cut(c) if same_cut(next).is_none() => Some(if c.g92 { Rule::G92Single } else { Rule::G76Single }),
        Kind::G162(1 | 4 | 5) if moved => Some(Rule::G162NoStop),
        _ => None,
    }
}
