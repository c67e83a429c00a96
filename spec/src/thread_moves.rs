//! G32, G33, G34 — single thread moves (M003), under `gsk` and `fanuc`.
//!
//! One spindle-synchronized move from the current position to the end point: G32 at a constant
//! lead, G33 with a spindle start angle P, G34 with a lead change K per revolution. They are
//! modal motion codes (handled by [`crate::program`]); this module checks one move (check step
//! 5) and emits it (docs/INTERPRETATION.md, "G32, G33, G34").

use crate::emit::{LeadLaw, Out};
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::g162::long_travel_twice;
use crate::words::{alarm, lead_max, Read, F, I_TPI, U, W, X, Z};
use cycle_vocab::{Alarm, AlarmCode, Dialect, Grid, Rule};

/// G32, G33, G34 as a family of the interpreter: modal thread moves; P (G33) and K (G34) are
/// not kept.
#[derive(Debug, Default)]
pub struct ThreadMoves;

/// G32 words: X(U) Z(W) F|I.
const G32_WORDS: Words = Words::of(&[F, I_TPI, U, W, X, Z]);
/// G33 also P, the start angle in 0.001°, 0…359 999 (rule G33).
const G33_WORDS: Words =
    Words::of(&[F, I_TPI, (b'P', Read::Integer { lo: 0, hi: 359_999, rule: Rule::G33 }), U, W, X, Z]);
/// G34 also K, the signed lead change per revolution on the lead grid (rule G34).
const G34_WORDS: Words = Words::of(&[F, I_TPI, (b'K', Read::SignedLead { rule: Rule::G34 }), U, W, X, Z]);

impl Family for ThreadMoves {
    fn modal(&self) -> bool {
        true
    }
    fn thread(&self) -> bool {
        true
    }
    fn words(&self, kind: Kind, _: Dialect) -> Words {
        match kind.g {
            33 => G33_WORDS,
            34 => G34_WORDS,
            _ => G32_WORDS,
        }
    }

    /// G32, G33, G34 (M003): the lead is the modal feed (`MISSING WORD F`, COM.LEAD, in a block
    /// that moves), G34 needs its K (`MISSING WORD K`, G34). A block without axis words moves
    /// nothing.
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        let (v, line) = (b.values, b.line);
        let code = match b.kind.g {
            33 => ThreadCode::G33,
            34 => ThreadCode::G34,
            _ => ThreadCode::G32,
        };
        st.take_lead(v);
        if !b.kind.axes {
            return Ok(());
        }
        let Some(lead) = st.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        let k = match code {
            ThreadCode::G34 => match v.get(b'K') {
                Some(k) => k,
                None => return Err(alarm(AlarmCode::MissingWord, b'K', Rule::G34, line)),
            },
            _ => 0,
        };
        st.missing_words_checked()?;
        let from = st.position();
        let (x, z) = st.end_point(v);
        let angle = v.get(b'P').unwrap_or(0) as u32;
        let m = ThreadMove { code, from, to: (x.unwrap_or(from.0), z.unwrap_or(from.1)), lead, angle, k, line };
        expand(&m, st.config.grid, &mut st.out)
    }
}

/// Which thread move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThreadCode {
    G32,
    G33,
    G34,
}

impl ThreadCode {
    /// The rule each move is tagged with.
    pub fn rule(self) -> Rule {
        match self {
            ThreadCode::G32 => Rule::G32,
            ThreadCode::G33 => Rule::G33,
            ThreadCode::G34 => Rule::G34,
        }
    }
}

/// One thread move, its words resolved.
#[derive(Clone, Copy, Debug)]
pub struct ThreadMove {
    pub code: ThreadCode,
    /// The current position (X diameter, Z).
    pub from: (i128, i128),
    /// The end point (X diameter, Z).
    pub to: (i128, i128),
    /// The lead (modal feed), lead counts.
    pub lead: i64,
    /// G33 P: the spindle start angle, 0.001° (0 when omitted or not G33).
    pub angle: u32,
    /// G34 K: lead change per revolution, lead counts (0 otherwise).
    pub k: i64,
    pub line: u32,
}

/// G34 (M003): the lead at the end of the move, L² = F² + K·s2 (s2 twice the long-axis travel in
/// lead counts), must stay above 0 (K < 0) and within the F range (K > 0); else `GEOMETRY` on K.
pub fn lead_stays_legal(lead: i64, k: i64, s2: i128, grid: Grid, line: u32) -> Result<(), Alarm> {
    let (f, fmax) = (lead as i128, lead_max(grid) as i128);
    let end_squared = f * f + k as i128 * s2;
    let legal = match k.signum() {
        -1 => end_squared > 0,
        1 => end_squared <= fmax * fmax,
        _ => true,
    };
    if legal {
        Ok(())
    } else {
        Err(alarm(AlarmCode::Geometry, b'K', Rule::G34, line))
    }
}

/// G34 (M003): the trace's lead law, K per revolution (360 000 in 0.001°), no floor.
pub fn g34_law(k: i64) -> LeadLaw {
    if k == 0 {
        LeadLaw::default()
    } else {
        LeadLaw { change: k, change_angle: 360_000, floor: 0, stepped: false }
    }
}

/// G32 / G33 / G34 (M003): checks a G34 lead, then emits the one move (PRJ.NOOP: not when it
/// ends at the current position).
pub fn expand(m: &ThreadMove, grid: Grid, out: &mut Out) -> Result<(), Alarm> {
    let law = match m.code {
        ThreadCode::G34 => {
            let s2 = long_travel_twice(m.to.1 - m.from.1, m.to.0 - m.from.0, grid);
            lead_stays_legal(m.lead, m.k, s2, grid, m.line)?;
            g34_law(m.k)
        }
        ThreadCode::G32 | ThreadCode::G33 => LeadLaw::default(),
    };
    out.variable_thread(m.to.0, m.to.1, m.lead, m.angle, law, m.code.rule(), m.line)
}

#[cfg(test)]
mod tests;
