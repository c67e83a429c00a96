//! The canned cycles of M003 in the block interpreter (docs/INTERPRETATION.md, "G73, G74, G75,
//! G83, G84"): the first blocks' kept values (G74.E, G73.FORMAT), step (4) of each cycle block
//! and the hand-over to the cycle's own checks (step 5) and run. All are one-shot (CYC.ONESHOT):
//! the motion mode and any G92/G90/G94 run stay as they were; F written in the block becomes the
//! modal feed.

use super::{Machine, Vals};
use crate::config::Params;
use crate::contour;
use crate::g73;
use crate::g83;
use crate::g84;
use crate::g74::{self, PeckCode};
use crate::run::Run;
use super::Program;
use cycle_vocab::{Alarm, AlarmCode, Rule};
use cycle_vocab::readings::{G73C, G75Relief};

/// G73.FORMAT: the values a G73 first block keeps — Δi (radius) and Δk, increments, and d.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PatternValues {
    pub di: i64,
    pub dk: i64,
    pub d: i64,
}

impl PatternValues {
    /// Parameters 5135, 5136, 5137 (the values before any first block).
    pub fn defaults(p: &Params) -> PatternValues {
        PatternValues { di: p.p5135_escape_x, dk: p.p5136_escape_z, d: i64::from(p.p5137_count) }
    }
}

impl Machine {
    /// (4) COM.LEAD: the feed of a cycle block (its F, else the modal feed), which becomes the
    /// modal feed; then G96.SMAX, the end of step 4.
    pub(super) fn cycle_feed(&mut self, v: &Vals, line: u32) -> Result<i64, Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let feed = self.feed.ok_or(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line))?;
        self.speed_limit(line)?;
        Ok(feed)
    }

    /// G74.FORMAT, G74.E: a first block keeps e for its code (G74's and G75's apart); R omitted
    /// falls back to parameter 5139.
    pub(super) fn peck_first(&mut self, code: PeckCode, v: &Vals) {
        let e = v.r.unwrap_or(self.params.p5139_peck_return);
        match code {
            PeckCode::G74 => self.g74_e = e,
            PeckCode::G75 => self.g75_e = e,
        }
    }

    /// G74.FORMAT / G75.FORMAT, second block: (4) the feed; (5) the cycle's checks; the run.
    /// E from X(U), Z(W), an omitted axis at A's; P, Q, R default to 0.
    pub(super) fn peck_second(&mut self, code: PeckCode, v: &Vals, line: u32, run: &mut Run) -> Result<(), Alarm> {
        let feed = self.cycle_feed(v, line)?;
        let e = match code {
            PeckCode::G74 => self.g74_e,
            PeckCode::G75 => self.g75_e,
        };
        let words = g74::Words {
            end: Self::end_point(v, self.pos, self.pos),
            di: v.p.unwrap_or(0),
            dk: v.q.unwrap_or(0),
            relief: v.r.unwrap_or(0),
            e,
            feed,
            relief_minus_z: self.config.readings.g75_relief == G75Relief::MinusZ,
        };
        *run = Run::Peck(g74::cycle(code, self.pos, &words, self.params.max_passes, line)?);
        Ok(())
    }
}

impl Machine {
    /// G73.FORMAT (format (a)'s first block): replaces G73's kept Δi, Δk, d; an omitted word
    /// falls back to its parameter (5135, 5136, 5137).
    pub(super) fn pattern_first(&mut self, v: &Vals) {
        let p = PatternValues::defaults(&self.params);
        self.g73 = PatternValues { di: v.u.unwrap_or(p.di), dk: v.w.unwrap_or(p.dk), d: v.r.unwrap_or(p.d) };
    }

    /// G73.FORMAT, G73.UW: format (a)'s second block (`b_format` false: the kept Δi, Δk, d) or
    /// format (b) (its own I, K, D, which do not change the kept ones). (4) the feed, P, Q, then
    /// in format (b) I, K, D; (5) the contour read ahead (CNT.FIND as G71, CNT.MAX), each of its
    /// blocks' checks, CNT.FIRST, then the pass bound (`g73::Cycle::new`). G73.USE: any contour
    /// is taken, arcs included — no check like G71.MONOTONE / G72.MONOTONE is made.
    pub(super) fn pattern_second(&mut self, b_format: bool, v: &Vals, line: u32, run: &mut Run, prog: &mut Program<'_, '_>) -> Result<(), Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let (feed, ns, nf) = self.cycle_words(v, line)?;
        let (values, count_word) = if b_format {
            let missing = |word: u8| Alarm::new(AlarmCode::MissingWord, Some(word), Rule::G73Format, line);
            let di = v.i.ok_or(missing(b'I'))?;
            let dk = v.k.ok_or(missing(b'K'))?;
            let d = v.d.ok_or(missing(b'D'))?;
            (PatternValues { di, dk, d }, b'D')
        } else {
            (self.g73, b'R')
        };
        self.speed_limit(line)?;
        let first = self.read_contour(prog.blocks, self.pos, ns, nf, true, line, prog.contour)?;
        contour::check_first(first, prog.contour.get(0).line)?;
        let words = g73::Words {
            di: values.di,
            dk: values.dk,
            d: values.d,
            allowance: (v.u.unwrap_or(0), v.w.unwrap_or(0)),
            feed,
            count_word,
            visit_c: self.config.readings.g73_c == G73C::Visit,
        };
        *run = Run::Pattern(g73::Cycle::new(self.pos, &words, prog.contour, self.params.max_passes, line)?);
        Ok(())
    }
}

impl Machine {
    /// A drilling block's words: the bottom from Z (absolute) or W (from the initial level) —
    /// omitted, the initial level; R, Q, P omitted 0 (P is 0 … 99 999 999 here).
    fn drill_words(&self, v: &Vals, feed: i64) -> g83::Words {
        g83::Words {
            r: v.r.unwrap_or(0),
            bottom: Self::end_point(v, self.pos, self.pos).1,
            q: v.q.unwrap_or(0),
            dwell: v.p.and_then(|p| u32::try_from(p).ok()).unwrap_or(0),
            feed,
        }
    }

    /// G83.FORMAT, G83.PECK: (4) the feed; (5) the levels and the pass bound; the run.
    pub(super) fn g83(&mut self, v: &Vals, line: u32, run: &mut Run) -> Result<(), Alarm> {
        let feed = self.cycle_feed(v, line)?;
        let c = g83::cycle(self.pos, &self.drill_words(v, feed), self.params.max_passes, line)?;
        *run = Run::Drill(c);
        Ok(())
    }

    /// G84.FORMAT, G84.PATH: (4) the feed; (5) rigid tapping armed (M29, else `UNSUPPORTED` on
    /// G), under G98 the rpm in force (`tapping_rpm`: under G96 `UNSUPPORTED` on G; none:
    /// `MISSING WORD S`; an integer 1 … 99 999, else `OUT OF RANGE` on S), the lead, the levels;
    /// the run. The rigid-tapping mode ends with the cycle.
    pub(super) fn g84(&mut self, v: &Vals, line: u32, run: &mut Run) -> Result<(), Alarm> {
        let feed = self.cycle_feed(v, line)?;
        if !self.rigid {
            return Err(Alarm::new(AlarmCode::Unsupported, Some(b'G'), Rule::G84Format, line));
        }
        self.rigid = false;
        let speed = if self.per_minute { Some(self.tapping_rpm(line)?) } else { None };
        *run = Run::Tap(g84::cycle(self.pos, &self.drill_words(v, feed), speed, line)?);
        Ok(())
    }
}
