//! Single block (docs/INTERPRETATION.md, "Operator events", "Single block"): the mode, the
//! blocks where it is not modelled, and where its stops fall.

use super::note::{Scope, Uninterrupted};
use super::Player;
use cycle_vocab::{Action, Alarm, AlarmCode, Event, Resume, Rule, Stop, StopReason};

/// OP.SINGLE, G92.SINGLE, G76.SINGLE, G162.NOSTOP (PRJ, M002, M004): the rule of the single-block
/// stop due when U's event `i` ends, `None` where none is:
/// - OP.SINGLE: "after the last event of each plain G00/G01 block that emitted a move" (such a
///   block emits one move);
/// - G92.SINGLE (G92) / G76.SINGLE (G76, G78): "after each cut's return to A — never inside a
///   cut";
/// - G162.NOSTOP: "after each emitted move of segments ①, ④ and ⑤ of every pass; never after ②
///   or ③".
pub fn stop_after(u: &Uninterrupted, i: usize) -> Option<Rule> {
    let note = &u.notes[i];
    let is_move = matches!(u.events[i], Event::Move(_));
    let cut_ends = note.cut.is_some() && u.cut(i).end == i + 1;
    match note.scope {
        Scope::Plain if is_move => Some(Rule::OpSingle),
        Scope::G92 if cut_ends => Some(Rule::G92Single),
        Scope::G76 if cut_ends => Some(Rule::G76Single),
        Scope::G162 if is_move && matches!(note.segment, 1 | 4 | 5) => Some(Rule::G162NoStop),
        _ => None,
    }
}

impl Player<'_, '_> {
    /// OP.SCRIPT (PRJ): "`SingleBlock(on, b)`: single-block mode switched on or off when the
    /// machine is about to begin U's event b." Fires each such action that is next, in order.
    pub(super) fn switch_single_block(&mut self, i: usize) {
        while let Some(Action::SingleBlock { on, before }) = self.actions.get(self.next) {
            if *before as usize != i {
                return;
            }
            self.single = *on;
            self.next += 1;
        }
    }

    /// OP.SCOPE (PRJ): "any event of such a block about to begin while single-block mode is on,
    /// is the alarm `OPERATOR` on that block's line, no word, rule OP.SCOPE, in place of that
    /// event."
    pub(super) fn single_out_of_scope(&self, i: usize) -> Option<Alarm> {
        let note = &self.u.notes[i];
        (self.single && note.scope == Scope::Other).then(|| Alarm::new(AlarmCode::Operator, None, Rule::OpScope, note.line))
    }

    /// "A single-block stop is `Stop(SINGLE_BLOCK, rule)` followed at once by `Resume(rule)` […]
    /// It is decided when the event it follows ends, before the machine is about to begin the
    /// next one, by the mode in force then" (OP.SINGLE, G92.SINGLE, G76.SINGLE, G162.NOSTOP).
    pub(super) fn single_block_stop(&mut self, i: usize) {
        if !self.single {
            return;
        }
        if let Some(rule) = stop_after(self.u, i) {
            self.emit(Event::Stop(Stop { reason: StopReason::SingleBlock, rule }));
            self.emit(Event::Resume(Resume { rule }));
        }
    }
}
