//! The contour cycles in the block interpreter (docs/INTERPRETATION.md, "Contours, arcs and the
//! stock-removal cycles"): the G70 block and the two G71/G72 blocks (G70.FORMAT, G71.FORMAT,
//! G71.UW, G72.FORMAT), reading the contour — ahead from the program text for G71/G72, again
//! from the program's start for G70 (CNT.FIND, CNT.MAX) — and checking each of its blocks on its
//! own line (CNT.WORDS, CNT.NOSUB, ARC.*), then handing the cycle its checks and its run.

use super::{Comp, Kind, Machine, Vals};
use crate::arc::{self, Centre};
use crate::contour::{self, Contour, Element, Kind as ElementKind, MAX_BLOCKS};
use crate::lex::{letter_bit, letter_mask, Block, Blocks};
use crate::rough::{self, Axis, Roughing};
use crate::run::Run;
use crate::words::At;
use super::Program;
use crate::finish;
use cycle_vocab::{Alarm, AlarmCode, Rule};

/// G71.DEPTH, G71.RETRACT, G71.PARAM: the values a first block keeps for its code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FirstValues {
    /// Δd, radius increments (G71) or Z increments (G72).
    pub depth: i64,
    /// e, radius increments.
    pub retract: i64,
}

/// The letters a contour block may carry (CNT.WORDS): G and M are checked before.
const CONTOUR_WORDS: u32 = letter_mask(b"FIKNRSTUWXZ");
/// The words of a G00/G01 contour block, and of a G02/G03 one.
const LINEAR_WORDS: u32 = letter_mask(b"FNSTUWXZ");
const ARC_WORDS: u32 = letter_mask(b"FIKNRSTUWXZ");

/// What the contour reader carries from block to block.
struct Reading {
    /// The previous contour point (untranslated).
    pos: (i64, i64),
    /// The contour's own motion mode (CNT.FIRST: later blocks continue it).
    mode: Option<ElementKind>,
    /// F written since the last element (0: none).
    feed: u32,
}

/// A contour being read block by block (`Machine::collect`).
struct Collect {
    reading: Reading,
    /// The first of the blocks' alarms, returned once the whole contour is found.
    deferred: Option<Alarm>,
    /// The ns block's motion code (CNT.FIRST).
    first_motion: Option<u64>,
    /// Blocks read.
    count: usize,
    /// An element found no room (`CONTOUR TOO LONG`; not reached within CNT.MAX).
    overflow: bool,
}

impl Collect {
    fn new(start: (i64, i64)) -> Collect {
        Collect { reading: Reading { pos: start, mode: None, feed: 0 }, deferred: None, first_motion: None, count: 0, overflow: false }
    }

    /// The ns block's motion code, or the first block's alarm.
    fn finish(self) -> Result<Option<u64>, Alarm> {
        match self.deferred {
            Some(a) => Err(a),
            None => Ok(self.first_motion),
        }
    }
}

impl Machine {
    /// G70.FORMAT, G70.UW, G70.FEED: (4) the feed (COM.LEAD), P, Q (CNT.PQ); (5) the contour
    /// before the G70 block (CNT.FIND, CNT.MAX), each of its blocks' checks, CNT.FIRST; then the
    /// finishing run.
    pub(super) fn g70(&mut self, v: &Vals, line: u32, run: &mut Run, prog: &mut Program<'_, '_>) -> Result<(), Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let (feed, ns, nf) = self.cycle_words(v, line)?;
        self.speed_limit(line)?;
        let src = prog.blocks.source();
        // The G70 block is the last block the running program's reader read, counted from that
        // program's first block (the main program's, or the subprogram's O block).
        let before = prog.blocks.blocks_read().saturating_sub(1);
        // The contour's blocks are read in the search's own pass (each block lexed once).
        prog.contour.clear();
        let mut collect = Collect::new(self.pos);
        let contour = &mut *prog.contour;
        contour::find_before(src, prog.origin, before, ns, nf, line, |block| self.collect(&mut collect, block, contour))?;
        if collect.overflow {
            return Err(contour::too_long(line));
        }
        let first = collect.finish()?;
        // CNT.FIRST on the ns block's line (element 0 is always the ns block).
        contour::check_first(first, prog.contour.get(0).line)?;
        let shift = (v.u.unwrap_or(0), v.w.unwrap_or(0));
        *run = Run::Finish(finish::Cycle::new(self.pos, shift, feed, prog.contour));
        Ok(())
    }

    /// G71.FORMAT / G72.FORMAT, first block: Δd and e, each falling back to its parameter
    /// (5132, 5133) when omitted (G71.PARAM); G71 and G72 keep theirs apart.
    pub(super) fn rough_first(&mut self, axis: Axis, v: &Vals) {
        let values = FirstValues {
            depth: v.depth.unwrap_or(self.params.p5132_rough_depth),
            retract: v.r.unwrap_or(self.params.p5133_rough_retract),
        };
        match axis {
            Axis::G71 => self.g71 = values,
            Axis::G72 => self.g72 = values,
        }
    }

    /// G71/G72 second block: (4) the feed, P, Q; (5) the contour read ahead (CNT.FIND, CNT.MAX),
    /// each of its blocks' checks, then the cycle's own checks (`rough::Roughing::new`).
    pub(super) fn rough_second(&mut self, axis: Axis, v: &Vals, line: u32, run: &mut Run, prog: &mut Program<'_, '_>) -> Result<(), Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let (feed, ns, nf) = self.cycle_words(v, line)?;
        self.speed_limit(line)?;
        let first = self.read_contour(prog.blocks, self.pos, ns, nf, true, line, prog.contour)?;
        contour::check_first(first, prog.contour.get(0).line)?;
        let values = match axis {
            Axis::G71 => self.g71,
            Axis::G72 => self.g72,
        };
        let words = rough::Words {
            depth: values.depth,
            retract: values.retract,
            allowance: (v.u.unwrap_or(0), v.w.unwrap_or(0)),
            feed,
        };
        let cycle = Roughing::new(axis, self.pos, &words, prog.contour, self.params.max_passes, line)?;
        *run = Run::Rough(cycle);
        Ok(())
    }

    /// (4) of a cycle's P/Q block: the feed (neither F nor a modal feed: `MISSING WORD F`,
    /// COM.LEAD), then P, then Q (`MISSING WORD`, CNT.PQ).
    pub(super) fn cycle_words(&self, v: &Vals, line: u32) -> Result<(i64, u64, u64), Alarm> {
        let missing = |word: u8, rule: Rule| Alarm::new(AlarmCode::MissingWord, Some(word), rule, line);
        let feed = self.feed.ok_or(missing(b'F', Rule::ComLead))?;
        let p = v.p.ok_or(missing(b'P', Rule::CntPq))?;
        let q = v.q.ok_or(missing(b'Q', Rule::CntPq))?;
        // P and Q are 1 … 99 999 here.
        Ok((feed, p.unsigned_abs(), q.unsigned_abs()))
    }

    /// CNT.RANGE, CNT.FIND, CNT.MAX: reads the contour N(ns) … N(nf) from `reader` into
    /// `contour`, the contour starting at `start`. `ahead` (G71/G72): the reader's next block
    /// must be N(ns) (else `BLOCK NOT FOUND` on P). A lexing alarm is that alarm; the program
    /// ending before N(nf) is `BLOCK NOT FOUND` on Q; a 1 001st block `CONTOUR TOO LONG` on Q.
    /// Each block's own checks are made as it is read, but the first of their alarms is returned
    /// only once the whole contour has been found (find first, then the blocks' checks in
    /// order). Returns the ns block's motion code (CNT.FIRST). Work: one pass over at most
    /// [`MAX_BLOCKS`] blocks, each read once.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn read_contour(
        &self,
        reader: &mut Blocks<'_>,
        start: (i64, i64),
        ns: u64,
        nf: u64,
        ahead: bool,
        line: u32,
        contour: &mut Contour,
    ) -> Result<Option<u64>, Alarm> {
        contour.clear();
        let mut block = Block::new();
        let mut collect = Collect::new(start);
        loop {
            if !reader.read(&mut block)? {
                return Err(contour::not_found(if collect.count == 0 { b'P' } else { b'Q' }, line));
            }
            if collect.count == 0 && ahead && !block.is_sequence(ns) {
                return Err(contour::not_found(b'P', line));
            }
            if collect.count >= MAX_BLOCKS {
                return Err(contour::too_long(line));
            }
            self.collect(&mut collect, &block, contour);
            if collect.overflow {
                return Err(contour::too_long(line));
            }
            if block.is_sequence(nf) {
                break;
            }
        }
        collect.finish()
    }

    /// One block of the contour into `contour` (its checks, its element if it moves): the
    /// first of the blocks' alarms is kept in `c` and later blocks only counted.
    fn collect(&self, c: &mut Collect, block: &Block, contour: &mut Contour) {
        c.count += 1;
        let first = c.count == 1;
        if first {
            c.first_motion = block.g_codes().last().map(|g| g.mantissa);
        }
        if c.deferred.is_none() {
            match self.contour_block(block, &mut c.reading, first) {
                // Within CNT.MAX the buffer has room: one element per block at most.
                Ok(Some(e)) => c.overflow |= !contour.push(e),
                Ok(None) => {}
                Err(a) => c.deferred = Some(a),
            }
        }
    }

    /// One contour block's checks — steps (2)–(5) as for any block, on its own line, with the
    /// contour's words (CNT.WORDS, CNT.NOSUB) and without `MISSING WORD F` — and its element, if
    /// it moves (a block without axis words moves nothing; nor does a line to where the contour
    /// stands, except the ns block, which is always element 0). The contour's state changes;
    /// the machine's does not (CNT.MODAL).
    fn contour_block(&self, b: &Block, reading: &mut Reading, first: bool) -> Result<Option<Element>, Alarm> {
        let line = b.line;
        let at = |letter: u8| At { letter, line };
        // (2) G codes: only G00–G03 (any other, supported elsewhere or not: CNT.WORDS).
        let mut motion = None;
        for g in b.g_codes() {
            if g.point || g.negative || g.mantissa > 3 {
                return Err(at(b'G').alarm(AlarmCode::WordNotAllowed, Rule::CntWords));
            }
            motion = Some(g.mantissa);
        }
        // M: no subprogram call (CNT.NOSUB), no other M code (CNT.WORDS).
        if let Some(m) = b.get(b'M') {
            let rule = if m.is(98) || m.is(99) { Rule::CntNosub } else { Rule::CntWords };
            return Err(at(b'M').alarm(AlarmCode::WordNotAllowed, rule));
        }
        if b.g_codes().len() > 1 {
            return Err(at(b'G').alarm(AlarmCode::Conflict, Rule::PrjWord));
        }
        // TNRC.SWITCH: a T word while G41 or G42 is in force (no G40–G42 can stand here).
        if b.has(b'T') && self.comp != Comp::Off {
            return Err(at(b'T').alarm(AlarmCode::WordNotAllowed, Rule::TnrcSwitch));
        }
        let kind = match motion {
            Some(0) => ElementKind::Rapid,
            Some(1) => ElementKind::Feed,
            Some(2) => ElementKind::Arc(true),
            Some(3) => ElementKind::Arc(false),
            // Before the contour has a mode (an ns block without one, refused by CNT.FIRST
            // after these checks) a block is checked as a G00/G01 one.
            _ => reading.mode.unwrap_or(ElementKind::Rapid),
        };
        let arc = match kind {
            ElementKind::Arc(cw) => Some(cw),
            _ => None,
        };
        for (first, second) in [(b'X', b'U'), (b'Z', b'W')] {
            if b.has(first) && b.has(second) {
                return Err(at(second).alarm(AlarmCode::Conflict, Rule::ComAbsInc));
            }
        }
        if arc.is_some() && b.has(b'R') && (b.has(b'I') || b.has(b'K')) {
            return Err(at(b'R').alarm(AlarmCode::Conflict, Rule::ArcFormat));
        }
        // Words allowed, alphabetically: outside the contour's words CNT.WORDS, arc words in a
        // G00/G01 block PRJ.WORD (as in any block).
        let allowed = if arc.is_some() { ARC_WORDS } else { LINEAR_WORDS };
        let refused = b.mask() & !allowed;
        if refused != 0 {
            let l = b'A' + refused.trailing_zeros() as u8;
            let rule = if CONTOUR_WORDS & letter_bit(l) != 0 { Rule::PrjWord } else { Rule::CntWords };
            return Err(at(l).alarm(AlarmCode::WordNotAllowed, rule));
        }
        // (3) values, alphabetically, as in a block of the same motion code.
        let value_kind = match kind {
            ElementKind::Arc(cw) => Kind::Arc(cw),
            ElementKind::Feed => Kind::Feed,
            ElementKind::Rapid => Kind::Rapid,
        };
        let mut v = Vals::default();
        for l in b.letters() {
            if let Some(n) = b.get(l) {
                self.value(value_kind, l, n, at(l), &mut v)?;
            }
        }
        if motion.is_some() {
            reading.mode = Some(kind);
        }
        if let Some(f) = v.lead {
            // Lead counts ≤ 99 990 000 fit u32.
            reading.feed = u32::try_from(f).unwrap_or(u32::MAX);
        }
        let axis = b.has(b'X') || b.has(b'U') || b.has(b'Z') || b.has(b'W');
        if !axis && !first {
            return Ok(None);
        }
        let from = reading.pos;
        let to = Self::end_point(&v, from, from);
        let mut e = Element { x: to.0, z: to.1, cx: 0, cz: 0, feed: 0, line, kind };
        if let (Some(cw), true) = (arc, axis) {
            // (4) R or I/K (no feed is needed in a contour); (5) the arc's checks.
            let words = match (v.r, v.i, v.k) {
                (Some(r), _, _) => Centre::R(r),
                (None, None, None) => return Err(at(b'R').alarm(AlarmCode::MissingWord, Rule::ArcFormat)),
                (None, i, k) => Centre::Ik(i.unwrap_or(0), k.unwrap_or(0)),
            };
            let ((cx, cz), _) = arc::centre(from, to, cw, words, self.params.arc_tolerance, line)?;
            (e.cx, e.cz) = (cx, cz);
        } else if to == from && !first {
            // A line to where the contour stands moves nothing (PRJ.NOOP); its F waits.
            return Ok(None);
        }
        e.feed = core::mem::take(&mut reading.feed);
        reading.pos = to;
        Ok(Some(e))
    }
}
