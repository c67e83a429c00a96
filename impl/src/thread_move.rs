//! The single thread moves G32 (constant lead), G33 (start angle P) and G34 (lead change K per
//! revolution) of M003 (docs/INTERPRETATION.md, "G32, G33, G34 — thread moves").

use crate::g162::max_lead;
use cycle_vocab::{Alarm, AlarmCode, Grid, Move, Rule};

/// Which thread move.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ThreadCode {
    G32,
    G33,
    G34,
}

impl ThreadCode {
    /// Every code, in the order of the `g32` family's codes (`family::FAMILIES`).
    pub const ALL: [ThreadCode; 3] = [ThreadCode::G32, ThreadCode::G33, ThreadCode::G34];

    pub const fn rule(self) -> Rule {
        match self {
            ThreadCode::G32 => Rule::G32,
            ThreadCode::G33 => Rule::G33,
            ThreadCode::G34 => Rule::G34,
        }
    }
}

/// The largest G33 start angle P, 0.001°.
pub const MAX_START_ANGLE: i64 = 359_999;

/// The words of a thread move: the lead (lead counts), the G33 start angle `p` (0.001°, 0
/// otherwise) and the G34 lead change `k` (lead counts per revolution, 0 otherwise).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ThreadWords {
    pub lead: i64,
    pub p: u32,
    pub k: i64,
}

/// The thread move from `from` to `to` (X diameter). G34 lead bound (check step 5): with
/// s2 twice the long-axis travel in lead counts, L² = F² + K·s2 must stay > 0 (K < 0) and
/// ≤ Fmax² (K > 0), else `GEOMETRY` on K, rule G34. `words.k` is 0 for G32 and G33 (K is
/// not their word; `modal/values.rs` sets it only for G34).
#[inline(always)]
pub fn thread_move(
    code: ThreadCode,
    from: (i64, i64),
    to: (i64, i64),
    words: &ThreadWords,
    grid: Grid,
    line: u32,
) -> Result<Move, Alarm> {
    let ThreadWords { lead, p, k } = *words;
    let rule = code.rule();
    if code == ThreadCode::G34 {
        let dx = (i128::from(to.0) - i128::from(from.0)).abs(); // diameter
        let dz2 = 2 * (i128::from(to.1) - i128::from(from.1)).abs();
        let c = i128::from(grid.lead_counts_per_increment());
        // COM.LONGAXIS: Z long when |ΔZ| > |ΔX| as radius (at a tie both give the same s2).
        let s2 = if dz2 > dx { dz2 * c } else { dx * c };
        let f = i128::from(lead);
        let fmax = i128::from(max_lead(grid.units));
        // |K| ≤ 10^8 and s2 < 2^67: no overflow; saturating for safety only.
        let end2 = (f * f).saturating_add(i128::from(k).saturating_mul(s2));
        // The lead F is ≥ 1 (COM.LEAD), so for K ≥ 0 the end lead L² ≥ F² > 0: `end2 ≤ 0`
        // happens only for K < 0, and no test of K's sign is needed there. K = 0 passes both
        // tests (F may exceed Fmax when it comes from I: a constant lead is not bounded here)
        // and `Move::variable_thread` with a change of 0 is the constant form.
        if end2 <= 0 || (k > 0 && end2 > fmax * fmax) {
            return Err(Alarm::new(AlarmCode::Geometry, Some(b'K'), rule, line));
        }
        return Ok(Move::variable_thread(to.0, to.1, lead, 0, k, 360_000, 0, rule));
    }
    let angle = if code == ThreadCode::G33 { p } else { 0 };
    Ok(Move::thread(to.0, to.1, lead, angle, rule))
}

#[cfg(test)]
mod tests;
