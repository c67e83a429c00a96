//! G00/G01 blocks (PRJ.MODAL), G50 (G50.COORD) and the end point of a block's axis words
//! (COM.ABSINC, NC201.ABSINC).

use super::{Kind, Machine, Mode, Vals};
use crate::fixed::sat;
use cycle_vocab::{Alarm, AlarmCode, Dialect, Move, Rule};

impl Machine {
    /// COM.ABSINC: the end point from X(U), Z(W): U and W are added to the position `from`; an
    /// omitted axis takes `kept`.
    pub(super) fn end_point(v: &Vals, from: (i64, i64), kept: (i64, i64)) -> (i64, i64) {
        let x = match (v.x, v.u) {
            (Some(x), _) => x,
            (None, Some(u)) => sat(i128::from(from.0) + i128::from(u)),
            (None, None) => kept.0,
        };
        let z = match (v.z, v.w) {
            (Some(z), _) => z,
            (None, Some(w)) => sat(i128::from(from.1) + i128::from(w)),
            (None, None) => kept.1,
        };
        (x, z)
    }

    /// NC201.ABSINC: the end point of a G00/G01 block under nc201 — X (a diameter count,
    /// NC201.XMODE) and Z absolute under G90, distances from `from` under G91; an omitted axis
    /// stays.
    pub(super) fn nc201_end_point(&self, v: &Vals, from: (i64, i64)) -> (i64, i64) {
        let axis = |word: Option<i64>, here: i64| match word {
            Some(w) if self.incremental => sat(i128::from(here) + i128::from(w)),
            Some(w) => w,
            None => here,
        };
        (axis(v.x, from.0), axis(v.z, from.1))
    }

    /// PRJ.MODAL: G00 / G01 blocks (and non-motion blocks in those modes); the move, if any.
    pub(super) fn linear(&mut self, kind: Kind, coded: bool, v: &Vals, axis: bool, line: u32) -> Result<Option<Move>, Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        if coded {
            self.mode = if kind == Kind::Feed { Mode::Feed } else { Mode::Rapid };
        }
        if !axis {
            return Ok(None);
        }
        let (x, z) = if self.config.dialect == Dialect::Nc201 {
            self.nc201_end_point(v, self.pos)
        } else {
            Self::end_point(v, self.pos, self.pos)
        };
        if kind == Kind::Feed {
            // COM.LEAD: G01 with axis words needs a feed.
            let Some(f) = self.feed else {
                return Err(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line));
            };
            return Ok(Some(Move::feed(x, z, f, Rule::PrjModal)));
        }
        Ok(Some(Move::rapid(x, z, Rule::PrjModal)))
    }

    /// G50.COORD: X and Z make the current position (work coordinates from now on); an omitted
    /// axis keeps its value. No motion, no event; the motion mode and any run go on.
    pub(super) fn g50(&mut self, v: &Vals) {
        self.pos = (v.x.unwrap_or(self.pos.0), v.z.unwrap_or(self.pos.1));
    }
}
