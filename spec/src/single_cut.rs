//! What G90 and G94 (M003) share: the modal run (G90.MODAL, G94.MODAL) and the reading of one
//! cycle's points. Each cycle's checks and path are in its own module ([`crate::g90`],
//! [`crate::g94`]).

use crate::family::{BlockIn, State};
use crate::words::alarm;
use cycle_vocab::{Alarm, AlarmCode, Rule};

/// A G90 or G94 modal run: the kept end X, end Z (absolute) and taper (I or K), and the index
/// of the last cycle cut.
#[derive(Clone, Copy, Debug, Default)]
pub struct Run {
    end_x: Option<i128>,
    end_z: Option<i128>,
    taper: i128,
    index: u32,
}

/// One cycle, its words resolved: A the start (and end), D the end point, the taper (G90 I
/// radius, G94 K), the modal feed, and its index within the run.
#[derive(Clone, Copy, Debug)]
pub struct Cut {
    pub a: (i128, i128),
    pub d: (i128, i128),
    pub taper: i128,
    pub feed: i64,
    pub index: u32,
    pub line: u32,
}

impl Run {
    /// G90.MODAL / G94.MODAL (M003): a new run (the code written after another motion mode)
    /// starts with the taper 0 and omitted end coordinates at the current position. F sets
    /// the modal feed and the `taper` word the kept taper; a block without axis words cuts
    /// nothing. A block with axis words needs a feed (`MISSING WORD F`, COM.LEAD) and cuts one
    /// cycle to D, an omitted end coordinate kept from the run.
    pub fn block(&mut self, st: &mut State, b: &BlockIn, taper: u8) -> Result<Option<Cut>, Alarm> {
        let v = b.values;
        if b.new_run {
            *self = Run::default();
        }
        st.take_feed(v);
        if let Some(t) = v.get(taper) {
            self.taper = t as i128;
        }
        if !b.kind.axes {
            return Ok(None);
        }
        let Some(feed) = st.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, b.line));
        };
        st.missing_words_checked()?;
        let a = st.position();
        let (x, z) = st.end_point(v);
        let d = (x.or(self.end_x).unwrap_or(a.0), z.or(self.end_z).unwrap_or(a.1));
        self.end_x = Some(d.0);
        self.end_z = Some(d.1);
        self.index = self.index.saturating_add(1);
        Ok(Some(Cut { a, d, taper: self.taper, feed, index: self.index, line: b.line }))
    }
}

/// G90.TAPER, G94.TAPER (M003), as G92.TAPER: a taper `t` against the travel `travel` of the
/// same axis (both in the same units) of the opposite sign may be at most as large as the
/// travel; of the same sign, or either 0, any size.
pub fn taper_ok(t: i128, travel: i128) -> bool {
    if t != 0 && travel != 0 && (t < 0) != (travel < 0) {
        t.abs() <= travel.abs()
    } else {
        true
    }
}
