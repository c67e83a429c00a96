//! Steps (4) and (5) and the modal state of each cycle family: G92 (G92.MODAL, G92.FORMAT),
//! G76/G78 first and second blocks (G76.FORMAT, G76.REQUIRED), the thread moves G32/G33/G34,
//! G90/G94 (G90.MODAL, G94.MODAL) and G162 (G162.FORMAT); each writes what runs.

use super::{Machine, Mode, Vals};
use crate::arc::{self, Centre};
use crate::emit;
use crate::g162::{self, SplitParams};
use crate::g90::{self, CutCode};
use crate::g92;
use crate::multipass::{self, Code, FirstBlock, Second};
use crate::run::Run;
use crate::thread_move::{thread_move, ThreadCode, ThreadWords};
use cycle_vocab::readings::G94K;
use cycle_vocab::{Alarm, AlarmCode, Move, Rule};

impl Machine {
    /// G92.MODAL, G92.FORMAT: a block in G92 mode or with G92; its cycle, if any, written
    /// into `run`.
    #[inline(always)]
    pub(super) fn g92(&mut self, coded: bool, v: &Vals, axis: bool, line: u32, run: &mut Run) -> Result<(), Alarm> {
        // A `match`, not `?`: `?` copies the cycle (~300 bytes) once more on its way out.
        match self.g92_cycle(coded, v, axis, line) {
            Ok(Some(c)) => *run = Run::Multipass(c),
            Ok(None) => {}
            Err(a) => return Err(a),
        }
        Ok(())
    }

    /// [`Machine::g92`]'s cycle, returned (none without axis words); inlined, so that the
    /// caller builds it where it keeps it.
    #[inline(always)]
    pub(super) fn g92_cycle(&mut self, coded: bool, v: &Vals, axis: bool, line: u32) -> Result<Option<emit::Cycle>, Alarm> {
        if coded && self.mode != Mode::G92 {
            self.g92.new_run(self.pos);
        }
        self.mode = Mode::G92;
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let st = &mut self.g92;
        if let Some(r) = v.r {
            st.r = r;
        }
        if let Some(j) = v.j {
            st.j = j;
        }
        if let Some(k) = v.k {
            st.k = k;
        }
        if let Some(l) = v.l {
            st.starts = u32::try_from(l).unwrap_or(1);
        }
        if !axis {
            return Ok(None);
        }
        // G92.MODAL: an omitted end coordinate is the run's.
        st.end = Self::end_point(v, self.pos, st.end);
        // (4) COM.LEAD: the lead.
        let Some(lead) = self.feed else {
            return Err(no_lead(line));
        };
        self.speed_limit(line)?;
        let st = &mut self.g92;
        st.index = st.index.saturating_add(1);
        let st = *st;
        g92::cycle(&self.config, &self.params, &st, &mut self.g92_pull, self.pos, lead, line).map(Some)
    }

    /// G76.FORMAT: a first block replaces the kept values of its code; omitted words fall back
    /// to their defaults (G76.DEFAULTS, G78.MODE, G78.DEPTHMODE).
    pub(super) fn first(&mut self, code: Code, v: &Vals) {
        let mut f = FirstBlock::defaults(&self.params, code);
        if let Some(p) = v.p {
            // P is 0…999 999 here.
            let digit = |div: i64| u32::try_from((p / div) % 100).unwrap_or(0);
            f.m = digit(10_000);
            f.a = digit(1);
            match code {
                Code::G76 => f.r = Some(digit(100)),
                Code::G78 => f.mode = digit(100),
            }
        }
        if let Some(q) = v.q {
            f.dmin = q;
        }
        if let Some(r) = v.r {
            f.d = r;
        }
        if let Some(d) = v.d {
            match code {
                Code::G76 => f.mode = u32::try_from(d).unwrap_or(0),
                Code::G78 => f.degressive = d != 0,
            }
        }
        if let Some(l) = v.l {
            f.starts = u32::try_from(l).unwrap_or(1);
        }
        if let Some(e) = v.e {
            f.e = e;
        }
        match code {
            Code::G76 => self.g76 = f,
            Code::G78 => self.g78 = f,
        }
    }

    /// G76.FORMAT, G76.REQUIRED: a second block, (4) missing words — lead, P, Q — then the cycle.
    pub(super) fn second(&mut self, code: Code, v: &Vals, line: u32, run: &mut Run) -> Result<(), Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let missing = |word: u8, rule: Rule| Alarm::new(AlarmCode::MissingWord, Some(word), rule, line);
        let lead = self.feed.ok_or(missing(b'F', Rule::ComLead))?;
        let k = v.p.ok_or(missing(b'P', Rule::G76Required))?;
        let dd = v.q.ok_or(missing(b'Q', Rule::G76Required))?;
        self.speed_limit(line)?;
        // G78 J and K are modal, each word on its own; G76's belong to the block (OPEN).
        let (j, kk) = match code {
            Code::G76 => (v.j, v.k),
            Code::G78 => {
                let kept = &mut self.g78_jk;
                kept.0 = v.j.or(kept.0);
                kept.1 = v.k.or(kept.1);
                *kept
            }
        };
        let sec = Second { d: Self::end_point(v, self.pos, self.pos), i: v.r.unwrap_or(0), k, dd, j, kk, lead };
        let first = match code {
            Code::G76 => &self.g76,
            Code::G78 => &self.g78,
        };
        match multipass::cycle(&self.config, &self.params, code, first, self.pos, &sec, line) {
            Ok(c) => *run = Run::Multipass(c),
            Err(a) => return Err(a),
        }
        Ok(())
    }

    /// G32, G33, G34 (PRJ.MODAL, M003): modal thread moves. (4) a block with axis words needs a
    /// lead (COM.LEAD), G34 its K (G34); (5) the G34 lead bound; then the thread move, if any.
    #[inline(always)]
    pub(super) fn thread(
        &mut self,
        code: ThreadCode,
        coded: bool,
        v: &Vals,
        axis: bool,
        line: u32,
    ) -> Result<Option<Move>, Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        if coded {
            self.mode = Mode::Thread(code);
        }
        if !axis {
            return Ok(None);
        }
        let missing = |word: u8, rule: Rule| Alarm::new(AlarmCode::MissingWord, Some(word), rule, line);
        let lead = self.feed.ok_or(missing(b'F', Rule::ComLead))?;
        let k = match (code, v.k) {
            (ThreadCode::G34, None) => return Err(missing(b'K', Rule::G34)),
            (_, k) => k.unwrap_or(0),
        };
        self.speed_limit(line)?;
        // P is 0…359 999 here.
        let p = v.p.and_then(|p| u32::try_from(p).ok()).unwrap_or(0);
        let to = Self::end_point(v, self.pos, self.pos);
        let words = ThreadWords { lead, p, k };
        thread_move(code, self.pos, to, &words, self.config.grid, line).map(Some)
    }

    /// G90.MODAL, G94.MODAL, G90.FORMAT, G94.FORMAT: a block in the mode or with the code. A
    /// new run (the code after another motion mode) starts with taper 0 and the end at the
    /// current position; omitted end coordinates and taper are the run's; without axis words
    /// the block only sets the taper and the feed. (4) the lead (COM.LEAD), then the cycle.
    #[inline(always)]
    pub(super) fn cut(&mut self, code: CutCode, coded: bool, v: &Vals, axis: bool, line: u32, run: &mut Run) -> Result<(), Alarm> {
        if let Some(c) = self.cut_cycle(code, coded, v, axis, line)? {
            *run = Run::Cut(c);
        }
        Ok(())
    }

    /// [`Machine::cut`]'s cycle, returned (none without axis words); inlined, so that the
    /// caller builds it where it keeps it.
    #[inline(always)]
    pub(super) fn cut_cycle(&mut self, code: CutCode, coded: bool, v: &Vals, axis: bool, line: u32) -> Result<Option<g90::Cycle>, Alarm> {
        if coded && self.mode != Mode::Cut(code) {
            self.cut.new_run(self.pos);
        }
        self.mode = Mode::Cut(code);
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        if let Some(t) = v.taper {
            // G94.TAPER (declared reading g94.k): the run keeps k = C.z − D.z; the letter reads
            // K = end Z − start Z (C.z = D.z − K), `start-minus-end` K = C.z − D.z.
            let end_minus_start = self.config.readings.g94_k == G94K::EndMinusStart;
            self.cut.taper = if code == CutCode::G94 && end_minus_start { -t } else { t };
        }
        if !axis {
            return Ok(None);
        }
        self.cut.end = Self::end_point(v, self.pos, self.cut.end);
        let Some(feed) = self.feed else {
            return Err(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line));
        };
        self.speed_limit(line)?;
        self.cut.index = self.cut.index.saturating_add(1);
        g90::cycle(code, &self.cut, self.pos, feed, line).map(Some)
    }

    /// G162.FORMAT: (4) missing words — F (G162.F), H (G162.H), P/Q as a pair (G162.PQ), X, Z
    /// (G162.FORMAT) — then the cycle's checks and the cycle. F sets the modal feed; without F
    /// the modal feed is the lead whatever it was set for (G162.F).
    pub(super) fn g162(&mut self, v: &Vals, line: u32, run: &mut Run) -> Result<(), Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let missing = |word: u8, rule: Rule| Alarm::new(AlarmCode::MissingWord, Some(word), rule, line);
        let lead = self.feed.ok_or(missing(b'F', Rule::G162F))?;
        let h = v.h.ok_or(missing(b'H', Rule::G162H))?;
        let split = match (v.p, v.q) {
            (Some(depth), Some(allowance)) => Some(SplitParams { depth, allowance }),
            (None, Some(_)) => return Err(missing(b'P', Rule::G162Pq)),
            (Some(_), None) => return Err(missing(b'Q', Rule::G162Pq)),
            (None, None) => None,
        };
        let x = v.x.ok_or(missing(b'X', Rule::G162Format))?;
        let z = v.z.ok_or(missing(b'Z', Rule::G162Format))?;
        let angle = |a: Option<i64>, default: u32| a.and_then(|a| u32::try_from(a).ok()).unwrap_or(default);
        let words = g162::Words {
            x,
            z,
            incremental: self.incremental,
            h,
            split,
            v: v.v.unwrap_or(0),
            taper: v.w.unwrap_or(0),
            a: v.a.unwrap_or(0),
            lead,
            b: angle(v.b, 0),
            i: v.pitch_change.unwrap_or(0),
            // G162.J: omitted → one revolution.
            j: angle(v.j, 360_000),
        };
        match g162::cycle(&self.config, &self.params, &words, self.pos, line) {
            Ok(c) => *run = Run::G162(c),
            Err(a) => return Err(a),
        }
        Ok(())
    }

    /// ARC.FORMAT, ARC.*: a G02/G03 block (or one in the arc mode). Without axis words it only
    /// sets the feed; with them (4) the feed (COM.LEAD), then R or I/K (MISSING WORD R,
    /// ARC.FORMAT), then (5) the arc's checks and its move.
    pub(super) fn arc(&mut self, cw: bool, coded: bool, v: &Vals, axis: bool, line: u32) -> Result<Option<Move>, Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        if coded {
            self.mode = Mode::Arc(cw);
        }
        if !axis {
            return Ok(None);
        }
        let missing = |word: u8, rule: Rule| Alarm::new(AlarmCode::MissingWord, Some(word), rule, line);
        let feed = self.feed.ok_or(missing(b'F', Rule::ComLead))?;
        let words = match (v.r, v.i, v.k) {
            (Some(r), _, _) => Centre::R(r),
            (None, None, None) => return Err(missing(b'R', Rule::ArcFormat)),
            (None, i, k) => Centre::Ik(i.unwrap_or(0), k.unwrap_or(0)),
        };
        self.speed_limit(line)?;
        let to = Self::end_point(v, self.pos, self.pos);
        arc::arc_move(self.pos, to, cw, words, feed, self.params.arc_tolerance, line).map(Some)
    }
}

/// COM.LEAD: no lead in force. Out of line, so that the alarm comes back whole (`g92::refused`).
#[cold]
#[inline(never)]
fn no_lead(line: u32) -> Alarm {
    Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line)
}
