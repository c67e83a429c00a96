//! The trace being built (PRJ.TRACE) and the machine position it implies (PRJ.MODAL).
//!
//! Each event goes to a sink as it is emitted ([`crate::expand_into`]); [`crate::expand`]
//! collects them. A sink that answers `Break` gets no further event: the rest of the block is
//! still computed (the position stays right), and the program stops after that block.

use crate::operator::note::{CutNote, Note, Scope};
use crate::pullout::LongAxis;
use core::ops::ControlFlow;
use cycle_vocab::{Alarm, AlarmCode, Dwell, Event, Move, MoveKind, Pass, PassKind, Rule, Spindle, SpindleState};

/// Where emitted events go.
pub type Sink<'s> = &'s mut dyn FnMut(Event) -> ControlFlow<()>;

/// The sink of emitted events and the current position (X diameter, Z, increments).
pub struct Out<'s> {
    sink: Sink<'s>,
    /// The sink answered `Break`: later events are dropped.
    stopped: bool,
    pub x: i64,
    pub z: i64,
    /// The index the next emitted event has in the trace.
    count: usize,
    /// What the operator player needs to know about the events being emitted (its notes are
    /// kept only when recording U, [`Out::record`]).
    note: Note,
    notes: Option<Vec<Note>>,
}

/// A coordinate that leaves the i64 range of the trace (possible only for extreme configured
/// start points): `OUT OF RANGE` on the axis (COM.RANGES).
fn coordinate(v: i128, word: u8, line: u32) -> Result<i64, Alarm> {
    i64::try_from(v).map_err(|_| Alarm::new(AlarmCode::OutOfRange, Some(word), Rule::ComRanges, line))
}

impl<'s> Out<'s> {
    pub fn new(x: i64, z: i64, sink: Sink<'s>) -> Out<'s> {
        Out { sink, stopped: false, x, z, count: 0, note: Note::default(), notes: None }
    }

    /// Keeps a [`Note`] for every event emitted from now on: the spec records U, the
    /// uninterrupted trace, for the operator player (OP.SCRIPT).
    pub fn record(&mut self) {
        self.notes = Some(Vec::new());
    }

    /// The notes kept since [`Out::record`], one per event emitted.
    pub fn take_notes(&mut self) -> Vec<Note> {
        self.notes.take().unwrap_or_default()
    }

    /// OP.SCOPE: the events from here on belong to the block on `line`, of `scope`.
    pub fn note_block(&mut self, line: u32, scope: Scope) {
        self.note = Note::block(line, scope);
    }

    /// G92.HOLD, G76.HOLD: a cut (one start's pass) begins with the next event emitted; its
    /// long axis is `long` (COM.LONGAXIS).
    pub fn begin_cut(&mut self, long: LongAxis) {
        self.note.cut = Some(CutNote { first: self.count, long });
    }

    /// G162.NOSTOP: the next events are segment `n` (① … ⑤; 0 for the pass header).
    pub fn segment(&mut self, n: u8) {
        self.note.segment = n;
    }

    /// Whether the sink asked to stop.
    pub fn stopped(&self) -> bool {
        self.stopped
    }

    /// PRJ.TRACE: hands `event` to the sink, unless it asked to stop.
    fn emit(&mut self, event: Event) {
        if self.stopped {
            return;
        }
        if let Some(notes) = &mut self.notes {
            notes.push(Note { start: (self.x, self.z), ..self.note });
        }
        self.count += 1;
        if (self.sink)(event).is_break() {
            self.stopped = true;
        }
    }

    /// PRJ.TRACE (PRJ): a pass header; `diameter_depth` is twice the radius depth.
    pub fn pass(&mut self, index: u32, kind: PassKind, diameter_depth: i128, rule: Rule, line: u32) -> Result<(), Alarm> {
        let diameter_depth = coordinate(diameter_depth, b'X', line)?;
        self.emit(Event::Pass(Pass { index, kind, diameter_depth, rule }));
        Ok(())
    }

    /// PRJ.NOOP (PRJ): a move to the current position is not emitted. Otherwise the move is appended
    /// and becomes the current position.
    #[allow(clippy::too_many_arguments)]
    fn go(&mut self, kind: MoveKind, x: i128, z: i128, feed: i64, angle: u32, rule: Rule, line: u32) -> Result<(), Alarm> {
        let x = coordinate(x, b'X', line)?;
        let z = coordinate(z, b'Z', line)?;
        let m = Move { kind, x, z, feed, cx: 0, cz: 0, angle, lead_change: 0, lead_change_angle: 0, lead_floor: 0, lead_steps: false, rule };
        self.push(m);
        Ok(())
    }

    /// PRJ.NOOP: appends `m` unless it ends at the current position.
    fn push(&mut self, m: Move) {
        if m.x == self.x && m.z == self.z {
            return;
        }
        self.emit(Event::Move(m));
        self.x = m.x;
        self.z = m.z;
    }

    /// A rapid (`G00`) to (x, z).
    pub fn rapid(&mut self, x: i128, z: i128, rule: Rule, line: u32) -> Result<(), Alarm> {
        self.go(MoveKind::Rapid, x, z, 0, 0, rule, line)
    }

    /// A linear feed (`G01`) to (x, z) at `feed` lead counts.
    pub fn feed(&mut self, x: i128, z: i128, feed: i64, rule: Rule, line: u32) -> Result<(), Alarm> {
        self.go(MoveKind::Feed, x, z, feed, 0, rule, line)
    }

    /// An arc at `feed` to `end` about `centre` (ARC.DIR: clockwise for G02, else G03), both
    /// absolute, X on diameter. Its start is the current position; it is never a no-op (a
    /// full circle is an alarm, ARC.TOL).
    pub fn arc(&mut self, cw: bool, end: (i128, i128), centre: (i128, i128), feed: i64, rule: Rule, line: u32) -> Result<(), Alarm> {
        let (x, z) = (coordinate(end.0, b'X', line)?, coordinate(end.1, b'Z', line)?);
        let (cx, cz) = (coordinate(centre.0, b'X', line)?, coordinate(centre.1, b'Z', line)?);
        self.push(Move::arc(cw, x, z, cx, cz, feed, rule));
        Ok(())
    }

    /// A spindle-synchronized move (`G32`) with `lead` and start `angle` (0.001°).
    pub fn thread(&mut self, x: i128, z: i128, lead: i64, angle: u32, rule: Rule, line: u32) -> Result<(), Alarm> {
        self.go(MoveKind::Thread, x, z, lead, angle, rule, line)
    }

    /// The pull-out of a cut (G92.PULLOUT, G76.PULLOUT, G78.PULLOUT): a thread move, noted as
    /// the cut's pull-out S → E for G92.HOLD's retract.
    pub fn pullout(&mut self, x: i128, z: i128, lead: i64, angle: u32, rule: Rule, line: u32) -> Result<(), Alarm> {
        self.note.pullout = true;
        let done = self.thread(x, z, lead, angle, rule, line);
        self.note.pullout = false;
        done
    }
}

impl Out<'_> {
    /// PRJ.TRACE (M003, "Trace (OPEN)"): a dwell of `ms` milliseconds (`G04 P<ms>`).
    pub fn dwell(&mut self, ms: u32, rule: Rule) {
        self.emit(Event::Dwell(Dwell { ms, rule }));
    }

    /// PRJ.TRACE (M003): the spindle turns `state` from here on (`M03` / `M04`).
    pub fn spindle(&mut self, state: SpindleState, rule: Rule) {
        self.emit(Event::Spindle(Spindle { state, rule }));
    }
}

/// A variable lead (G34, G162.I, docs/INTERPRETATION.md "Trace"): `change` lead counts per
/// `change_angle` (0.001°), held once a shrinking lead is ≤ `floor` (0: none); continuous, or in
/// steps when `stepped` ("Stepped lead": G162 under `g162.lead=steps`). All 0: constant.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LeadLaw {
    pub change: i64,
    pub change_angle: u32,
    pub floor: i64,
    pub stepped: bool,
}

impl Out<'_> {
    /// A spindle-synchronized move whose lead starts at `lead` and follows `law`.
    #[allow(clippy::too_many_arguments)]
    pub fn variable_thread(&mut self, x: i128, z: i128, lead: i64, angle: u32, law: LeadLaw, rule: Rule, line: u32) -> Result<(), Alarm> {
        let x = coordinate(x, b'X', line)?;
        let z = coordinate(z, b'Z', line)?;
        let m = Move::variable_thread(x, z, lead, angle, law.change, law.change_angle, law.floor, rule);
        self.push(if law.stepped { m.stepped() } else { m });
        Ok(())
    }
}

/// COM.MULTISTART (M001, M002): the spindle start angle of start j of L, round(360 000·j / L)
/// in 0.001°, half up.
pub fn start_angle(j: u32, l: u32) -> u32 {
    let v = crate::exact::round_div(360_000 * j as i128, l.max(1) as i128);
    u32::try_from(v).unwrap_or(0)
}

#[cfg(test)]
mod tests;
