//! The plain block: no G code and no word but N, U, W, X, Z, outside nc201, under a modal
//! G00, G01, G32/G33/G34, G90/G94 or G92 — a thread's next move, a single cut's or G92's next
//! pass. Read without the general interpreter's steps that cannot apply to it, with the same
//! checks in the same order (docs/INTERPRETATION.md, check order) and the same result:
//! - (2) no G or M code, no S or T, so no code check, no conflict but X with U and Z with W
//!   (COM.ABSINC; F/I and ARC.FORMAT need words it has not), and every word is allowed in every
//!   mode it runs under (U W X Z in each kind's list, N common);
//! - (3) U, W, X, Z (alphabetically) signed lengths (COM.RANGES), N without a value rule;
//! - (4), (5) the mode's own handler, as written for a block without its code; G96.SMAX cannot
//!   apply (no G96 written: `smax_due` is cleared as the interpreter clears it), G96.RAPID does
//!   under G00.
//!
//! The move of a G00/G01/G32 block is returned, not stored in [`Run`], so that the stream writes
//! it straight into the caller's buffer ([`crate::Expander::fill`]).

use super::{Kind, Machine, Mode, Vals};
use crate::emit;
use crate::g90::{self, CutCode};
use crate::lex::{letter_mask, Block};
use crate::run::Run;
use crate::words::{signed_length_places, At};
use cycle_vocab::{Alarm, AlarmCode, Dialect, Move, Rule};

/// The words a plain block may have.
const PLAIN: u32 = letter_mask(b"NUWXZ");

/// What a plain block is read as: its mode's kind; G00, G01, G32/G33/G34 give at most one
/// move ([`Machine::plain_move`]), G90/G94 and G92 write their cycle into [`Run`]
/// ([`Machine::plain_cycle`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Plain {
    kind: Kind,
}

impl Plain {
    /// The block gives at most one move (G00, G01, G32/G33/G34), else a cycle (G90/G94, G92).
    #[inline(always)]
    pub(crate) fn is_move(self) -> bool {
        matches!(self.kind, Kind::Rapid | Kind::Feed | Kind::Thread(_))
    }

    /// The block is a pass of the G92 mode ([`Machine::plain_g92`]).
    #[inline(always)]
    pub(crate) fn is_g92(self) -> bool {
        self.kind == Kind::G92
    }

    /// The G90/G94 code of a block that is a pass of that mode ([`Machine::plain_cut`]).
    #[inline(always)]
    pub(crate) fn cut(self) -> Option<CutCode> {
        match self.kind {
            Kind::Cut(code) => Some(code),
            _ => None,
        }
    }
}

/// The axis words of a plain block, each a checked signed length.
struct Axes {
    u: Option<i64>,
    w: Option<i64>,
    x: Option<i64>,
    z: Option<i64>,
}

impl Axes {
    fn any(&self) -> bool {
        self.u.is_some() || self.w.is_some() || self.x.is_some() || self.z.is_some()
    }
}

impl Machine {
    /// Whether `b` is a plain block under the mode in force, and how it is read; `None` (the
    /// general interpreter reads it) for any other block, an arc mode or nc201.
    #[inline(always)]
    pub(crate) fn plain(&self, b: &Block) -> Option<Plain> {
        if b.has_g() || b.mask() & !PLAIN != 0 || self.config.dialect == Dialect::Nc201 {
            return None;
        }
        let kind = match self.mode {
            Mode::Rapid => Kind::Rapid,
            Mode::Feed => Kind::Feed,
            Mode::Thread(code) => Kind::Thread(code),
            Mode::G92 => Kind::G92,
            Mode::Cut(code) => Kind::Cut(code),
            Mode::Arc(_) => return None,
        };
        Some(Plain { kind })
    }

    /// Whether `b`, read right after a plain block, is a plain block of the same kind:
    /// [`Machine::plain`] without the machine's part, which a plain block leaves as it found it
    /// (a move's handler keeps the mode, G90/G94's and G92's set the one they run under; the
    /// dialect is the configuration's).
    #[inline(always)]
    pub(crate) fn plain_again(b: &Block) -> bool {
        !b.has_g() && b.mask() & !PLAIN == 0
    }

    /// Steps (2) and (3) of a plain block: X with U, Z with W (COM.ABSINC), then U, W, X, Z.
    #[inline(always)]
    fn axes(&mut self, b: &Block, places: u32) -> Result<Axes, Alarm> {
        // G96.SMAX: no G96 in this block (the interpreter's `g96 && !limited`).
        self.smax_due = false;
        let line = b.line;
        let (ux, wz) = (const { letter_mask(b"UX") }, const { letter_mask(b"WZ") });
        if b.mask() & ux == ux || b.mask() & wz == wz {
            let second = if b.mask() & ux == ux { b'U' } else { b'W' };
            return Err(Alarm::new(AlarmCode::Conflict, Some(second), Rule::ComAbsInc, line));
        }
        let word = |letter: u8| match b.get(letter) {
            Some(n) => signed_length_places(n, places, At { letter, line }).map(Some),
            None => Ok(None),
        };
        Ok(Axes { u: word(b'U')?, w: word(b'W')?, x: word(b'X')?, z: word(b'Z')? })
    }

    /// A plain block that gives a move ([`Plain::is_move`]): its move, if any, with every check
    /// of the general path (the mode's handler, then G96.RAPID under G00).
    #[inline(always)]
    pub(crate) fn plain_move(&mut self, plain: Plain, b: &Block, places: u32) -> Result<Option<Move>, Alarm> {
        let kind = plain.kind;
        let a = self.axes(b, places)?;
        let axis = a.any();
        let v = Vals { u: a.u, w: a.w, x: a.x, z: a.z, ..Vals::default() };
        let line = b.line;
        match kind {
            Kind::Thread(code) => self.thread(code, false, &v, axis, line),
            _ => {
                let m = self.linear(kind, false, &v, axis, line)?;
                if kind == Kind::Rapid && axis {
                    self.rapid_under_g96(line)?;
                }
                Ok(m)
            }
        }
    }

    /// A plain block of the G90/G94 mode `code` ([`Plain::cut`]): its cycle, returned (none
    /// without axis words) for the caller to build where it keeps it; inlined for that.
    #[inline(always)]
    pub(crate) fn plain_cut(&mut self, code: CutCode, b: &Block, places: u32) -> Result<Option<g90::Cycle>, Alarm> {
        let a = self.axes(b, places)?;
        let axis = a.any();
        let v = Vals { u: a.u, w: a.w, x: a.x, z: a.z, ..Vals::default() };
        self.cut_cycle(code, false, &v, axis, b.line)
    }

    /// A plain block of the G92 mode ([`Plain::is_g92`]): its cycle, returned (none without
    /// axis words) for the caller to build where it keeps it; inlined for that.
    #[inline(always)]
    pub(crate) fn plain_g92(&mut self, b: &Block, places: u32) -> Result<Option<emit::Cycle>, Alarm> {
        // A modal run's usual pass: X alone (N aside). No conflict, no other axis; the same steps.
        if let (Some(n), true) = (b.get(b'X'), b.mask() & !const { letter_mask(b"NX") } == 0) {
            #[cfg(test)]
            crate::probe::count_short();
            self.smax_due = false;
            let x = signed_length_places(n, places, At { letter: b'X', line: b.line })?;
            let v = Vals { x: Some(x), ..Vals::default() };
            return self.g92_cycle(false, &v, true, b.line);
        }
        let a = self.axes(b, places)?;
        let axis = a.any();
        let v = Vals { u: a.u, w: a.w, x: a.x, z: a.z, ..Vals::default() };
        self.g92_cycle(false, &v, axis, b.line)
    }

    /// A plain block that is no move: the G90/G94 or G92 handler writes its cycle into `run`
    /// (nothing runs without axis words).
    pub(crate) fn plain_cycle(&mut self, plain: Plain, b: &Block, run: &mut Run) -> Result<(), Alarm> {
        let kind = plain.kind;
        *run = Run::Idle;
        let a = self.axes(b, self.config.grid.decimals())?;
        let axis = a.any();
        let v = Vals { u: a.u, w: a.w, x: a.x, z: a.z, ..Vals::default() };
        match kind {
            Kind::Cut(code) => self.cut(code, false, &v, axis, b.line, run),
            _ => self.g92(false, &v, axis, b.line, run),
        }
    }
}

#[cfg(test)]
mod tests;
