//! The uninterrupted trace U as the operator layer reads it (OP.SCRIPT): each event of
//! [`Core`] with its index in U, the position it starts from, its block's line and what the
//! running generator says it is ([`Kind`]); one event of look-ahead; and the events of the
//! current G92/G76/G78 cut, kept so that the cut can be repeated after a G92.HOLD/G76.HOLD
//! retract without expanding the program again.

use crate::emit::START_EVENTS;
use crate::run::Run;
use crate::stream::Core;
use cycle_vocab::{Alarm, Event, MoveKind, Resume, Rule};

/// The most events of one cut (G92.HOLD: a pass header, the rapid to Bn or to the lead-in
/// point, the lead-in, the cut, the pull-out, two rapids): [`START_EVENTS`] = 7.
pub const CUT_MAX: usize = START_EVENTS;

/// What a move of a G92/G76/G78 cut is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// The pass header.
    Header,
    /// A rapid: to Bn or the lead-in point, ③, ④ (OP.HOLD).
    Rapid,
    /// The lead-in (G76.LEADIN) or the cut to the pull-out start (G92.HOLD, G76.HOLD).
    Thread,
    /// The pull-out (G92.PULLOUT, G76.PULLOUT).
    Pullout,
}

/// An event of a G92/G76/G78 cut, with what the cycle knows of it (G92.HOLD, G76.HOLD).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CutInfo {
    /// G92 (else G76, G78, FANUC G76).
    pub g92: bool,
    pub role: Role,
    /// The cut's first event: the pass header (first start), else its first move.
    pub begin: bool,
    /// The start (COM.MULTISTART) the cut belongs to.
    pub start: u32,
    /// The cycle's start point A.
    pub a: (i64, i64),
    /// COM.LONGAXIS, the cycle's own decision: Z is the long axis.
    pub z_long: bool,
    /// The pass's pull-out S → E; `None`: no pull-out.
    pub pull: Option<((i64, i64), (i64, i64))>,
}

/// What kind of block an event of U belongs to (OP.SCOPE).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Kind {
    /// The move of a plain G00/G01 block.
    Plain,
    /// A G92/G76/G78 cycle.
    Cut(CutInfo),
    /// A G162 cycle: the segment ①–⑤ of a move (G162.PATH), 0 for a pass header.
    G162(u8),
    /// Any other block: operator events are not modelled there (OP.SCOPE).
    Other,
}

/// One event of U.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Item {
    pub event: Event,
    /// 0-based index in U, pass headers included.
    pub index: u32,
    /// Where the machine stands in U before the event (a move's start S).
    pub from: (i64, i64),
    /// The line of the block it belongs to.
    pub line: u32,
    pub kind: Kind,
}

impl Item {
    /// A placeholder for the buffer's unused slots.
    pub const NONE: Item =
        Item { event: Event::Resume(Resume { rule: Rule::OpResume }), index: 0, from: (0, 0), line: 0, kind: Kind::Other };
}

/// The next event of U, pulled ahead.
#[derive(Clone, Copy, Debug)]
pub enum Look {
    /// Not pulled yet.
    Empty,
    Item(Item),
    /// U is over: its end, or its alarm.
    End(Option<Alarm>),
}

/// U, read one event ahead, with the events of the current cut for a repeat.
pub struct Source {
    /// The events of the current cut read from [`Core`] so far (all of it after [`Source::drain`]).
    cut: [Item; CUT_MAX],
    cut_len: u8,
    /// Repeating the cut: the next position in `cut`.
    replay: Option<u8>,
    /// The next event of [`Core`].
    look: Look,
    /// U's index of the next event of [`Core`].
    index: u32,
    /// The start of the last cut event read from [`Core`]; `None` after any other event.
    last_start: Option<u32>,
}

impl Source {
    pub const fn new() -> Source {
        Source { cut: [Item::NONE; CUT_MAX], cut_len: 0, replay: None, look: Look::Empty, index: 0, last_start: None }
    }

    /// Pulls [`Core`]'s next event into the look-ahead, if it is empty. Bounded work: one
    /// event of U.
    fn fill(&mut self, core: &mut Core<'_>) {
        if !matches!(self.look, Look::Empty) {
            return;
        }
        self.look = match core.pull() {
            None => Look::End(None),
            Some(Err(a)) => Look::End(Some(a)),
            Some(Ok(mut it)) => {
                it.index = self.index;
                self.index = self.index.saturating_add(1);
                match &mut it.kind {
                    Kind::Cut(c) => {
                        c.begin = c.role == Role::Header || self.last_start != Some(c.start);
                        self.last_start = Some(c.start);
                    }
                    _ => self.last_start = None,
                }
                Look::Item(it)
            }
        };
    }

    /// The next event of U without taking it (from the cut being repeated, else [`Core`]).
    pub fn peek(&mut self, core: &mut Core<'_>) -> Look {
        if let Some(it) = self.replay.and_then(|i| self.buffered(i)) {
            return Look::Item(it);
        }
        self.fill(core);
        self.look
    }

    fn buffered(&self, i: u8) -> Option<Item> {
        if i < self.cut_len {
            self.cut.get(usize::from(i)).copied()
        } else {
            None
        }
    }

    /// Takes the next event of U.
    pub fn take(&mut self, core: &mut Core<'_>) -> Look {
        if let Some(i) = self.replay {
            let it = self.buffered(i);
            let next = i.saturating_add(1);
            self.replay = (next < self.cut_len).then_some(next);
            if let Some(it) = it {
                return Look::Item(it);
            }
        }
        self.fill(core);
        let l = core::mem::replace(&mut self.look, Look::Empty);
        if let Look::Item(it) = &l {
            self.record(it);
        }
        l
    }

    /// Keeps an event read from [`Core`] as part of the current cut (a new cut empties it).
    fn record(&mut self, it: &Item) {
        match it.kind {
            Kind::Cut(c) => {
                if c.begin {
                    self.cut_len = 0;
                }
                if let Some(slot) = self.cut.get_mut(usize::from(self.cut_len)) {
                    *slot = *it;
                    self.cut_len += 1;
                }
            }
            _ => self.cut_len = 0,
        }
    }

    /// G92.HOLD/G76.HOLD with bit 6 = 0: reads the rest of the current cut from [`Core`] into
    /// the cut (nothing when it is being repeated: it is whole). Bounded work: [`CUT_MAX`]
    /// events of U.
    pub fn drain(&mut self, core: &mut Core<'_>) {
        for _ in 0..CUT_MAX {
            if self.replay.is_some() {
                return;
            }
            self.fill(core);
            match self.look {
                Look::Item(it) if matches!(it.kind, Kind::Cut(c) if !c.begin) => {
                    self.record(&it);
                    self.look = Look::Empty;
                }
                _ => return,
            }
        }
    }

    /// OP.RESUME after a G92.HOLD/G76.HOLD retract: U again from the cut's first event.
    pub fn repeat(&mut self) {
        self.replay = (self.cut_len > 0).then_some(0);
    }
}

impl Core<'_> {
    /// The next event of U with what the generator that made it says it is (OP.SCOPE, the cut
    /// roles of G92.HOLD/G76.HOLD, the segments of G162.NOSTOP); `None` at the end of the
    /// program. The same stream as [`Core::next_slow`].
    pub(crate) fn pull(&mut self) -> Option<Result<Item, Alarm>> {
        if self.done {
            return None;
        }
        if !self.checked {
            self.checked = true;
            if let Err(a) = self.check() {
                self.done = true;
                return Some(Err(a));
            }
        }
        loop {
            let from = self.machine.pos;
            let plain = matches!(&self.run, Run::Move(m) if matches!(m.kind, MoveKind::Rapid | MoveKind::Feed));
            if let Some(event) = self.run.next_event(&mut self.machine.pos, &self.contour) {
                let kind = classify(&self.run, plain, &event);
                return Some(Ok(Item { event, index: 0, from, line: self.block.line, kind }));
            }
            self.run = Run::Idle;
            match self.read_block() {
                Ok(true) => {}
                Ok(false) => return None,
                Err(a) => {
                    self.done = true;
                    self.run = Run::Idle;
                    return Some(Err(a));
                }
            }
        }
    }
}

/// OP.SCOPE and the cut roles: what `run` has just emitted (`plain`: it was the move of a
/// G00/G01 block, now done).
fn classify(run: &Run, plain: bool, e: &Event) -> Kind {
    let header = matches!(e, Event::Pass(_));
    match run {
        Run::Multipass(c) => {
            let st = c.state();
            let role = match (header, st.step) {
                (true, _) => Role::Header,
                (false, 1 | 2) => Role::Thread,
                (false, 3) => Role::Pullout,
                _ => Role::Rapid,
            };
            Kind::Cut(CutInfo { g92: st.g92, role, begin: false, start: st.start, a: st.a, z_long: st.z_long, pull: st.pull })
        }
        Run::G162(c) => Kind::G162(if header { 0 } else { c.segment() }),
        _ if plain => Kind::Plain,
        _ => Kind::Other,
    }
}
