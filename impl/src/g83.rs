//! G83, peck drilling along Z at the current X, read as FANUC lathe controls do (M003;
//! docs/INTERPRETATION.md, "G83 and G84"): the check (G83.FORMAT), the peck count in closed
//! form against `max_passes`, and the moves one at a time (G83.PECK): rapid to the R level; peck
//! k feeds to R + c·k·Q (the last exactly to the bottom), after every peck but the last a rapid
//! back to the R level and a rapid down to the depth reached; the dwell P at the bottom; a rapid
//! to the initial level.
//!
//! Bounds: Z, W, R, Q ≤ N < 2^30 and positions below 2^62 (lib.rs); a peck's offset is at most
//! the depth. State: O(1) — the peck being cut.

use crate::batch;
use crate::emit::emit;
use crate::g74::{ceil_div, span, toward};
use cycle_vocab::{Alarm, AlarmCode, Dwell, Event, Move, Pass, PassKind, Rule};

/// The drilling levels shared by G83 and G84: the current X, the initial level I, the R level
/// and the bottom, the direction c (±1) and the depth |bottom − R level|.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Levels {
    pub x: i64,
    pub initial: i64,
    pub r_level: i64,
    pub bottom: i64,
    pub c: i64,
    pub depth: i64,
}

impl Levels {
    /// From the position `a` (X, I), R (the signed distance to the R level) and the bottom Z:
    /// c = 0 (the bottom at the R level) is `GEOMETRY` on Z under `format` (G83.FORMAT,
    /// G84.FORMAT).
    pub fn new(a: (i64, i64), r: i64, bottom: i64, format: Rule, line: u32) -> Result<Levels, Alarm> {
        let r_level = a.1.saturating_add(r);
        let travel = bottom.saturating_sub(r_level);
        if travel == 0 {
            return Err(Alarm::new(AlarmCode::Geometry, Some(b'Z'), format, line));
        }
        Ok(Levels { x: a.0, initial: a.1, r_level, bottom, c: travel.signum(), depth: travel.saturating_abs() })
    }

    /// The pass header: index 1, ROUGH, the depth from the R level on diameter.
    pub fn header(&self, rule: Rule) -> Event {
        Event::Pass(Pass { index: 1, kind: PassKind::Rough, diameter_depth: self.depth.saturating_mul(2), rule })
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Phase {
    Header,
    ToR,
    Peck,
    Up,
    Down,
    Dwell,
    Home,
    Done,
}

/// A G83 cycle whose checks passed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cycle {
    lv: Levels,
    /// The peck Q, increments (0: one feed to the bottom).
    q: i64,
    pecks: u64,
    dwell: u32,
    feed: i64,
    peck_k: u64,
    phase: Phase,
}

/// The words of a drilling block, in increments: R (the signed distance from the initial level
/// to the R level), the bottom Z, the peck Q (G83; 0: none), the dwell P (ms), the feed.
#[derive(Clone, Copy, Debug)]
pub struct Words {
    pub r: i64,
    pub bottom: i64,
    pub q: i64,
    pub dwell: u32,
    pub feed: i64,
}

/// The cycle from `a` (step 5): the levels (G83.FORMAT), then the pecks — ⌈depth / Q⌉, one
/// without Q — against `max_passes` (`TOO MANY PASSES` on Q, PRJ.MAXPASS), before any motion.
pub fn cycle(a: (i64, i64), w: &Words, max_passes: u32, line: u32) -> Result<Cycle, Alarm> {
    let Words { r, bottom, q, dwell, feed } = *w;
    let lv = Levels::new(a, r, bottom, Rule::G83Format, line)?;
    let pecks = if q <= 0 { 1 } else { ceil_div(lv.depth, q) };
    if pecks > u64::from(max_passes) {
        return Err(Alarm::new(AlarmCode::TooManyPasses, Some(b'Q'), Rule::PrjMaxPass, line));
    }
    Ok(Cycle { lv, q, pecks, dwell, feed, peck_k: 1, phase: Phase::Header })
}

/// For the proofs (cycle-proofs `g83_peck_step`), not API: the count, and the cycle resumed at a
/// peck — the state `next_event` is in before it cuts peck `k`.
#[doc(hidden)]
impl Cycle {
    /// The pecks, as `cycle` counted them.
    pub fn pecks(&self) -> u64 {
        self.pecks
    }

    /// This cycle about to cut peck `k` (1-based).
    pub fn at_peck(&self, k: u64) -> Cycle {
        Cycle { peck_k: k, phase: Phase::Peck, ..*self }
    }
}

impl Cycle {
    /// The depth of peck `k`: R + c·min(k·Q, depth).
    fn peck_end(&self, k: u64) -> i64 {
        let off = if self.q <= 0 {
            self.lv.depth
        } else {
            let off = span(k, self.q).min(self.lv.depth.unsigned_abs().into());
            i64::try_from(off).unwrap_or(i64::MAX)
        };
        self.lv.r_level.saturating_add(toward(self.lv.c, off))
    }

    /// The next event, updating the machine position; `None` when the cycle is done. PRJ.NOOP:
    /// a move to the current position is not emitted. Bounded work: at most four phases per
    /// call (only the rapid to the R level and the rapid home can be skipped).
    pub fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        let rule = Rule::G83Peck;
        loop {
            let m = match self.phase {
                Phase::Header => {
                    self.phase = Phase::ToR;
                    return Some(self.lv.header(rule));
                }
                Phase::ToR => {
                    self.phase = Phase::Peck;
                    Move::rapid(self.lv.x, self.lv.r_level, rule)
                }
                Phase::Peck => {
                    self.phase = if self.peck_k < self.pecks { Phase::Up } else { Phase::Dwell };
                    Move::feed(self.lv.x, self.peck_end(self.peck_k), self.feed, rule)
                }
                Phase::Up => {
                    self.phase = Phase::Down;
                    Move::rapid(self.lv.x, self.lv.r_level, rule)
                }
                Phase::Down => {
                    self.phase = Phase::Peck;
                    let z = self.peck_end(self.peck_k);
                    self.peck_k += 1;
                    Move::rapid(self.lv.x, z, rule)
                }
                Phase::Dwell => {
                    self.phase = Phase::Home;
                    if self.dwell > 0 {
                        return Some(Event::Dwell(Dwell { ms: self.dwell, rule }));
                    }
                    continue;
                }
                Phase::Home => {
                    self.phase = Phase::Done;
                    Move::rapid(self.lv.x, self.lv.initial, rule)
                }
                Phase::Done => return None,
            };
            if let Some(e) = emit(m, pos) {
                return Some(e);
            }
        }
    }
}

impl Cycle {
    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`]:
    /// the pecks before the last with their rapids up and down (the bulk of the cycle) built in
    /// place three at a time, every other event through `next_event`. How many, and whether the
    /// cycle is done. Bounded work: `out.len()` events.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
        batch::fill_bulk(self, pos, out)
    }

    /// The pecks before the last, each with its rapid up to the R level and down to the depth
    /// reached, while three events fit: as `next_event`'s `Peck`, `Up` and `Down` phases.
    /// Returns how many events were written.
    #[inline]
    fn write_pecks(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> usize {
        let rule = Rule::G83Peck;
        let x = self.lv.x;
        let mut at = *pos;
        let mut n = 0;
        while self.peck_k < self.pecks && out.len().saturating_sub(n) >= 3 {
            let z = self.peck_end(self.peck_k);
            self.peck_k += 1;
            for m in [Move::feed(x, z, self.feed, rule), Move::rapid(x, self.lv.r_level, rule), Move::rapid(x, z, rule)] {
                if let Some(e) = emit(m, &mut at) {
                    if let Some(slot) = out.get_mut(n) {
                        *slot = e;
                        n += 1;
                    }
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
        self.phase == Phase::Peck && self.peck_k < self.pecks
    }
    fn write_bulk(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> usize {
        self.write_pecks(pos, out)
    }
}

#[cfg(test)]
mod tests;
