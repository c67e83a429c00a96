//! G74 (face peck drilling / grooving) and G75 (OD grooving), M003 (docs/INTERPRETATION.md,
//! "G74 … and G75"): the cycle's checks (step 5: G74.FORMAT/G75.FORMAT, G74.PECK/G75.PECK,
//! G74.COLUMN/G75.COLUMN, then PRJ.MAXPASS), the counts of columns and pecks in closed form, and
//! the moves one at a time (G74.PECK, G74.E, G74.RELIEF, G74.COLUMN and G75's).
//!
//! Both cycles are one code in a frame of two axes: the **peck axis** p (G74: Z; G75: X, a
//! diameter count) along which the tool pecks toward the bottom, and the **step axis** s (G74: X;
//! G75: Z) along which the columns (grooves) stand. Every radius length (G74 Δi, Δd; G75 Δi, e)
//! enters X doubled.
//!
//! Bounds: every word is at most N < 2^30 increments and a position stays below 2^62 (lib.rs),
//! so a column's or a peck's offset `min(j·step, travel)` is at most the travel (< 2^63 as an
//! unsigned difference); products of counts are taken in `u128`. Saturating operations only keep
//! an impossible overflow from panicking. State: O(1) — the column and peck being cut.

use crate::batch;
use crate::emit::emit;
use cycle_vocab::{Alarm, AlarmCode, Event, Move, Pass, PassKind, Rule};

/// Which grooving cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PeckCode {
    /// Pecks along Z, columns stepped in X.
    G74,
    /// Pecks along X, grooves stepped in Z.
    G75,
}

/// The words of a second block, in increments: the end point E (absolute, an omitted axis = A's),
/// Δi (P, radius), Δk (Q), Δd (R, radius for G74), the kept return e, and G75's relief reading
/// (declared reading g75.relief: `minus-z`, the letter, relieves toward −Z whatever the step;
/// false: against the step; G74 always against the step).
#[derive(Clone, Copy, Debug)]
pub struct Words {
    pub end: (i64, i64),
    pub di: i64,
    pub dk: i64,
    pub relief: i64,
    pub e: i64,
    pub feed: i64,
    pub relief_minus_z: bool,
}

/// Where the cycle is in its path.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    Header,
    ToColumn,
    Peck,
    Return,
    Relief,
    Back,
    Home,
    Done,
}

/// A G74/G75 cycle whose checks passed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cycle {
    code: PeckCode,
    /// A in the frame: (p, s).
    a: (i64, i64),
    /// Peck direction c and step direction σ (−1, 0, 1).
    c: i64,
    sigma: i64,
    /// |E.p − A.p| and |E.s − A.s|, in the frame's counts.
    depth: i64,
    travel: i64,
    /// The peck length and the column step, in the frame's counts (> 0; the step is unused
    /// without step travel).
    peck: i64,
    step: i64,
    /// The return after a peck and the relief, in the frame's counts.
    e: i64,
    relief: i64,
    /// The relief goes toward −relief_dir on the step axis: σ (against the step), or +1 (toward
    /// −Z) for G75 under g75.relief = minus-z.
    relief_dir: i64,
    feed: i64,
    pecks: u64,
    columns: u64,
    diameter_depth: i64,
    /// The column (0-based) and the peck (1-based) being cut.
    col: u64,
    peck_i: u64,
    phase: Phase,
}

/// `base + dir·min(i·len, max)`: the i-th point from `base` toward `dir`, the last exactly at
/// `base + dir·max`. Public for the proofs (cycle-proofs `peck_step`), not API.
#[doc(hidden)]
pub fn nth(base: i64, dir: i64, i: u64, len: i64, max: i64) -> i64 {
    let off = span(i, len).min(max.unsigned_abs().into());
    let off = i64::try_from(off).unwrap_or(i64::MAX);
    base.saturating_add(toward(dir, off))
}

/// i·|len|, exact (a 64 × 64-bit product fits `u128`): the offset of the i-th peck or column
/// before the clamp (G74.PECK, G74.COLUMN, G83.PECK). A function of its own so that the proofs
/// can stand the product in by what the SMT lemmas prove of it (cycle-proofs `peck_parts`);
/// not API.
#[doc(hidden)]
pub fn span(i: u64, len: i64) -> u128 {
    u128::from(i) * u128::from(len.unsigned_abs())
}

/// dir·len, saturating, for a direction dir ∈ {−1, 0, 1}: a length along an axis. A function of
/// its own so that the proofs can stand the product in by what `peck_toward` proves of it
/// (cycle-proofs); not API.
#[doc(hidden)]
pub fn toward(dir: i64, len: i64) -> i64 {
    dir.saturating_mul(len)
}

/// ⌈a / b⌉ for a ≥ 0, b > 0: the pecks of a column, the column steps (G74/G75) and G83's pecks.
/// Public for the proofs (cycle-proofs `peck_parts`), not API.
#[doc(hidden)]
pub fn ceil_div(a: i64, b: i64) -> u64 {
    let (a, b) = (a.unsigned_abs(), b.unsigned_abs().max(1));
    a / b + u64::from(!a.is_multiple_of(b))
}

impl PeckCode {
    /// (format, peck, column, relief, return) rules.
    const fn rules(self) -> (Rule, Rule, Rule, Rule, Rule) {
        match self {
            PeckCode::G74 => (Rule::G74Format, Rule::G74Peck, Rule::G74Column, Rule::G74Relief, Rule::G74E),
            PeckCode::G75 => (Rule::G75Format, Rule::G75Peck, Rule::G75Column, Rule::G75Relief, Rule::G75Peck),
        }
    }

    /// A machine point (X, Z) in the frame (p, s), and back.
    const fn frame(self, (x, z): (i64, i64)) -> (i64, i64) {
        match self {
            PeckCode::G74 => (z, x),
            PeckCode::G75 => (x, z),
        }
    }

    const fn machine(self, (p, s): (i64, i64)) -> (i64, i64) {
        match self {
            PeckCode::G74 => (s, p),
            PeckCode::G75 => (p, s),
        }
    }
}

/// The cycle from A = `a` with `w`: step 5 in the register's order — G74: no Z travel
/// (`GEOMETRY` on Z, G74.FORMAT), Δk = 0 (`MISSING WORD Q`, G74.PECK), X travel with Δi = 0
/// (`MISSING WORD P`, G74.COLUMN); G75 the same with the axes and P/Q exchanged — then the pecks
/// of all columns against `max_passes` (`TOO MANY PASSES` on Q / P, PRJ.MAXPASS), before any
/// motion.
pub fn cycle(code: PeckCode, a: (i64, i64), w: &Words, max_passes: u32, line: u32) -> Result<Cycle, Alarm> {
    let (format, peck_rule, column_rule, _, _) = code.rules();
    let alarm = |c: AlarmCode, word: u8, rule: Rule| Alarm::new(c, Some(word), rule, line);
    // Frame lengths: G74 pecks Δk along Z, steps 2Δi in X, returns e, relief 2Δd;
    // G75 pecks 2Δi along X, steps Δk in Z, returns 2e, relief Δd.
    let (peck, step, e, relief, peck_word, step_word, p_axis) = match code {
        PeckCode::G74 => (w.dk, w.di.saturating_mul(2), w.e, w.relief.saturating_mul(2), b'Q', b'P', b'Z'),
        PeckCode::G75 => (w.di.saturating_mul(2), w.dk, w.e.saturating_mul(2), w.relief, b'P', b'Q', b'X'),
    };
    let fa = code.frame(a);
    let fe = code.frame(w.end);
    let dp = fe.0.saturating_sub(fa.0);
    let ds = fe.1.saturating_sub(fa.1);
    if dp == 0 {
        return Err(alarm(AlarmCode::Geometry, p_axis, format));
    }
    if peck == 0 {
        return Err(alarm(AlarmCode::MissingWord, peck_word, peck_rule));
    }
    if ds != 0 && step == 0 {
        return Err(alarm(AlarmCode::MissingWord, step_word, column_rule));
    }
    let depth = dp.saturating_abs();
    let travel = ds.saturating_abs();
    let pecks = ceil_div(depth, peck);
    let columns = if travel == 0 { 1 } else { ceil_div(travel, step).saturating_add(1) };
    if u128::from(pecks) * u128::from(columns) > u128::from(max_passes) {
        return Err(alarm(AlarmCode::TooManyPasses, peck_word, Rule::PrjMaxPass));
    }
    let diameter_depth = match code {
        PeckCode::G74 => depth.saturating_mul(2),
        PeckCode::G75 => depth,
    };
    Ok(Cycle {
        code,
        a: fa,
        c: dp.signum(),
        sigma: ds.signum(),
        depth,
        travel,
        peck,
        step,
        e,
        relief,
        relief_dir: if code == PeckCode::G75 && w.relief_minus_z { 1 } else { ds.signum() },
        feed: w.feed,
        pecks,
        columns,
        diameter_depth,
        col: 0,
        peck_i: 1,
        phase: Phase::Header,
    })
}

/// For the proofs (cycle-proofs `g74_peck_step`), not API: the counts, and the cycle resumed at
/// a peck — the state `next_event` is in before it cuts peck `i` of column `col` — or after a
/// column.
#[doc(hidden)]
impl Cycle {
    /// The pecks per column and the columns, as `cycle` counted them.
    pub fn counts(&self) -> (u64, u64) {
        (self.pecks, self.columns)
    }

    /// This cycle about to cut peck `i` (1-based) of column `col` (0-based).
    pub fn at_peck(&self, col: u64, i: u64) -> Cycle {
        Cycle { col, peck_i: i, phase: Phase::Peck, ..*self }
    }

    /// This cycle after column `col`'s way back to A.p (its `Back` phase): the next column's
    /// header ahead, or the way home after the last column.
    pub fn after_column(&self, col: u64) -> Cycle {
        let next = col.saturating_add(1);
        Cycle { col: next, peck_i: 1, phase: if next < self.columns { Phase::Header } else { Phase::Home }, ..*self }
    }
}

impl Cycle {
    /// The step-axis position of column `j` (G74.COLUMN).
    fn column(&self, j: u64) -> i64 {
        nth(self.a.1, self.sigma, j, self.step, self.travel)
    }

    /// The end of peck `i` on the peck axis (G74.PECK).
    fn peck_end(&self, i: u64) -> i64 {
        nth(self.a.0, self.c, i, self.peck, self.depth)
    }

    /// The next event, updating the machine position; `None` when the cycle is done. A move to
    /// the current position is not emitted (PRJ.NOOP). Bounded work: at most six phases per
    /// call (a skipped return is followed by a peck, which always moves).
    pub fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        let (_, peck_rule, column_rule, relief_rule, return_rule) = self.code.rules();
        loop {
            let s = self.column(self.col);
            let (p, s, rapid, rule) = match self.phase {
                Phase::Header => {
                    self.phase = if self.col == 0 { Phase::Peck } else { Phase::ToColumn };
                    let index = u32::try_from(self.col.saturating_add(1)).unwrap_or(u32::MAX);
                    let kind = PassKind::Rough;
                    return Some(Event::Pass(Pass { index, kind, diameter_depth: self.diameter_depth, rule: column_rule }));
                }
                Phase::ToColumn => {
                    self.phase = Phase::Peck;
                    (self.a.0, s, true, column_rule)
                }
                Phase::Peck => {
                    self.phase = if self.peck_i < self.pecks { Phase::Return } else { Phase::Relief };
                    (self.peck_end(self.peck_i), s, false, peck_rule)
                }
                Phase::Return => {
                    self.phase = Phase::Peck;
                    let back = self.peck_end(self.peck_i).saturating_sub(toward(self.c, self.e));
                    self.peck_i += 1;
                    (back, s, true, return_rule)
                }
                Phase::Relief => {
                    self.phase = Phase::Back;
                    if self.col == 0 || self.relief == 0 {
                        continue;
                    }
                    let s = s.saturating_sub(toward(self.relief_dir, self.relief));
                    (self.peck_end(self.pecks), s, true, relief_rule)
                }
                Phase::Back => {
                    self.col += 1;
                    self.peck_i = 1;
                    self.phase = if self.col < self.columns { Phase::Header } else { Phase::Home };
                    // Along the peck axis only, from where the tool stands (after any relief).
                    (self.a.0, self.code.frame(*pos).1, true, column_rule)
                }
                Phase::Home => {
                    self.phase = Phase::Done;
                    (self.a.0, self.a.1, true, column_rule)
                }
                Phase::Done => return None,
            };
            let (x, z) = self.code.machine((p, s));
            let m = if rapid { Move::rapid(x, z, rule) } else { Move::feed(x, z, self.feed, rule) };
            if let Some(e) = emit(m, pos) {
                return Some(e);
            }
        }
    }
}

impl Cycle {
    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`]:
    /// the pecks of a column and their returns (the bulk of the cycle) built in place two at a
    /// time, every other event through `next_event`. How many, and whether the cycle is done.
    /// Bounded work: `out.len()` events.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
        batch::fill_bulk(self, pos, out)
    }

    /// The pecks before the column's last and their returns, while two events fit: as
    /// `next_event`'s `Peck` and `Return` phases. Returns how many events were written.
    #[inline]
    fn write_pecks(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> usize {
        let (_, peck_rule, _, _, return_rule) = self.code.rules();
        let s = self.column(self.col);
        let back = toward(self.c, self.e);
        let mut at = *pos;
        let mut n = 0;
        while self.peck_i < self.pecks && out.len().saturating_sub(n) >= 2 {
            let end = self.peck_end(self.peck_i);
            self.peck_i += 1;
            let (x, z) = self.code.machine((end, s));
            if let Some(e) = emit(Move::feed(x, z, self.feed, peck_rule), &mut at) {
                if let Some(slot) = out.get_mut(n) {
                    *slot = e;
                    n += 1;
                }
            }
            let (x, z) = self.code.machine((end.saturating_sub(back), s));
            if let Some(e) = emit(Move::rapid(x, z, return_rule), &mut at) {
                if let Some(slot) = out.get_mut(n) {
                    *slot = e;
                    n += 1;
                }
            }
        }
        *pos = at;
        n
    }
}

impl batch::Bulk for Cycle {
    fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        Cycle::next_event(self, pos)
    }
    fn in_bulk(&self) -> bool {
        self.phase == Phase::Peck && self.peck_i < self.pecks
    }
    fn write_bulk(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> usize {
        self.write_pecks(pos, out)
    }
}

#[cfg(test)]
mod tests;
