//! What the spec knows about each event of U, the uninterrupted trace (docs/INTERPRETATION.md,
//! "Operator events"): the block it belongs to and the block's scope, the cut of a thread cycle
//! (G92, G76, G78) and whether the move is that cut's pull-out, the G162 segment. The cycles
//! record these as they emit ([`crate::emit::Out`]); the operator player reads them.

use crate::pullout::LongAxis;
use cycle_vocab::{Event, MoveKind};

/// Which operator rules the events of a block fall under.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Scope {
    /// A plain `G00` / `G01` block (OP.HOLD, OP.SINGLE).
    Plain,
    /// A G92 cycle (G92.HOLD, G92.SINGLE, G92.RESET).
    G92,
    /// A G76 (every dialect's) or G78 cycle (G76.HOLD, G76.SINGLE, G92.RESET).
    G76,
    /// A G162 cycle (G162.NOSTOP).
    G162,
    /// Any other block: no operator event is modelled there (OP.SCOPE).
    #[default]
    Other,
}

/// OP.SCOPE (PRJ): "operator events are modelled for plain `G00`/`G01` blocks and the thread
/// cycles G92, G76, G78 (every dialect's G76) and G162. A Hold or Reset whose move belongs to
/// any other block (G90, G94, G70–G75, G83, G84, G02/G03, G32/G33/G34) […] is the alarm
/// `OPERATOR`". The scope of a block whose motion or cycle code is `g` (a family's code; G00,
/// G01 are [`Scope::Plain`], G02/G03 [`Scope::Other`]).
pub fn scope_of_cycle(g: u32) -> Scope {
    match g {
        92 => Scope::G92,
        76 | 78 => Scope::G76,
        162 => Scope::G162,
        _ => Scope::Other,
    }
}

/// The cut an event belongs to (G92.HOLD: "one start's pass: U's events from its first (the
/// pass header when it is the pass's first start, else its first move) to its return to A").
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CutNote {
    /// The index in U of the cut's first event.
    pub first: usize,
    /// COM.LONGAXIS, the cycle's own decision.
    pub long: LongAxis,
}

/// The note of one event of U.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Note {
    /// The line of the block that emitted the event.
    pub line: u32,
    /// Where the tool is when the event begins (X diameter, Z): the end of the move before it,
    /// or the position a no-motion block set (G50.COORD).
    pub start: (i64, i64),
    pub scope: Scope,
    /// The cut (G92, G76, G78), `None` outside one.
    pub cut: Option<CutNote>,
    /// The move is its cut's pull-out S → E.
    pub pullout: bool,
    /// G162: the segment ① … ⑤ of a move, 0 for the pass header and outside G162.
    pub segment: u8,
}

impl Note {
    /// A new block's note: nothing known yet but its line and scope.
    pub fn block(line: u32, scope: Scope) -> Note {
        Note { line, scope, ..Note::default() }
    }
}

/// U: the uninterrupted trace of the program and configuration with an empty script, each event
/// with its note.
#[derive(Clone, Debug, Default)]
pub struct Uninterrupted {
    pub events: Vec<Event>,
    pub notes: Vec<Note>,
    /// The program alarm that ends U, if any.
    pub alarm: Option<cycle_vocab::Alarm>,
}

impl Uninterrupted {
    /// Where the tool is when event `i` begins.
    pub fn start(&self, i: usize) -> (i64, i64) {
        self.notes[i].start
    }

    /// The events of the cut event `i` belongs to (empty outside a cut): from its first event to
    /// its return to A, its last.
    pub fn cut(&self, i: usize) -> core::ops::Range<usize> {
        let Some(cut) = self.notes[i].cut else { return i..i };
        let same = |j: &usize| self.notes[*j].cut.map(|c| c.first) == Some(cut.first);
        let end = (cut.first..self.notes.len()).take_while(same).last().map_or(cut.first, |j| j + 1);
        cut.first..end
    }

    /// G92.HOLD bit 6 = 1: the cut's last thread move ("the pull-out's end E, or D without one").
    pub fn last_thread_move(&self, i: usize) -> usize {
        self.cut(i).rev().find(|&j| matches!(self.events[j], Event::Move(m) if m.kind == MoveKind::Thread)).unwrap_or(i)
    }

    /// The index of the pull-out of event `i`'s cut, `None` when the cut has none.
    pub fn pullout(&self, i: usize) -> Option<usize> {
        self.cut(i).find(|&j| self.notes[j].pullout)
    }

    /// The end point of event `i` when it is a move.
    pub fn end(&self, i: usize) -> (i64, i64) {
        match self.events[i] {
            Event::Move(m) => (m.x, m.z),
            _ => self.start(i),
        }
    }
}
