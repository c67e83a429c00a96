//! The modal interpreter (PRJ.MODAL, PRJ.WORD, PRJ.SUPPORTED, PRJ.DIALECT, COM.ABSINC,
//! NC201.ABSINC, NC201.XMODE, COM.LEAD): one block in, at most one [`Run`] out, with the check
//! order of docs/INTERPRETATION.md — (2) G and M codes, conflicts, allowed words alphabetically;
//! (3) values alphabetically; (4) missing words; (5) the cycle's own checks.

use crate::config::Params;
use crate::fixed::sat;
use crate::contour::Contour;
use crate::g90::{CutCode, CutState};
use crate::g92::{G92State, PullMemo};
use crate::lex::{self, letter_bit, Block, Blocks};
use crate::multipass::{Code, FirstBlock};
use crate::run::Run;
use crate::sub::Flow;
use crate::thread_move::ThreadCode;
use crate::words::At;
use codes::Codes;
use contour_blocks::FirstValues;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, Rule};
use kind::{allowed, cycle_kind, Kind, COMMON};
pub(crate) use plain::Plain;

mod canned;
mod codes;
mod contour_blocks;
mod cycles;
mod flow;
mod kind;
mod plain;
mod values;

/// What the block interpreter may read besides the block: the running program's reader (a
/// G71/G72 reads its contour ahead; a G70 reads the running program again from its first block,
/// `origin`), the contour buffer, and whether a subprogram runs (SUB.RETURN).
pub struct Program<'p, 'a> {
    pub blocks: &'p mut Blocks<'a>,
    pub contour: &'p mut Contour,
    /// Where the running program's first block stands: the text's start, or the running
    /// subprogram's O block (CNT.FIND).
    pub origin: lex::Mark,
    pub in_subprogram: bool,
}

/// The modal motion mode. CYC.ONESHOT: G70–G75, G83, G84 have no mode here — their blocks
/// leave it, and so a G92/G90/G94 run, as it was before them.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Rapid,
    Feed,
    G92,
    /// G32, G33, G34 (PRJ.MODAL, M003).
    Thread(ThreadCode),
    /// G90, G94 (G90.MODAL, G94.MODAL).
    Cut(CutCode),
    /// G02 (clockwise, `true`), G03 (ARC.DIR).
    Arc(bool),
}

/// TNRC.CODES: the nose-radius compensation in force (G40 none, G41 left, G42 right).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Comp {
    Off,
    Left,
    Right,
}

/// The machine state carried from block to block.
#[derive(Clone, Copy, Debug)]
pub struct Machine {
    pub config: Config,
    /// The parameters in force (the configuration's, else the defaults).
    pub params: Params,
    /// Current position: X diameter, Z.
    pub pos: (i64, i64),
    mode: Mode,
    /// Modal feed / lead, lead counts (COM.LEAD).
    feed: Option<i64>,
    g92: G92State,
    /// The G90/G94 run.
    cut: CutState,
    /// The last G92 cycle's pull-out, reused while its inputs stay the same.
    g92_pull: PullMemo,
    g76: FirstBlock,
    g78: FirstBlock,
    /// G78 J and K are modal (`000_…` lines 59, 61): the J and the K last written in a G78
    /// second block, each kept on its own for the whole program (G76's are not kept).
    g78_jk: (Option<i64>, Option<i64>),
    /// NC201.ABSINC: G91 in force (`nc201` only).
    incremental: bool,
    /// TNRC.CODES: the nose-radius compensation in force.
    comp: Comp,
    /// G71.PARAM: the values of the last G71 and G72 first blocks.
    g71: FirstValues,
    g72: FirstValues,
    /// G74.E: the return e kept by the last G74 and G75 first blocks (radius increments).
    g74_e: i64,
    g75_e: i64,
    /// G73.FORMAT: Δi (radius), Δk, d kept by the last G73 first block.
    g73: canned::PatternValues,
    /// G84.FORMAT: rigid tapping armed (M29 since the last G80/G84 cycle).
    rigid: bool,
    /// G98 (feed per minute) in force; G99 at the start (G84.FORMAT).
    per_minute: bool,
    /// G96.SPEED: the spindle speed in rpm — the last S written under G97 outside a G50 block
    /// (G84.FORMAT: the speed of the lead under G98).
    spindle: Option<crate::number::Number>,
    /// G96.SPEED: G96 (constant surface speed) in force; G97 at the start.
    surface: bool,
    /// G50.SMAX: a maximum spindle speed was set (a G50 S).
    limited: bool,
    /// G96.SMAX: the block being read writes G96 with no maximum set in an earlier block (its
    /// alarm comes at the end of check step 4).
    smax_due: bool,
}

/// The converted words of one block; `None` where absent.
#[derive(Clone, Copy, Debug, Default)]
struct Vals {
    d: Option<i64>,
    e: Option<i64>,
    lead: Option<i64>,
    j: Option<i64>,
    k: Option<i64>,
    l: Option<i64>,
    p: Option<i64>,
    q: Option<i64>,
    r: Option<i64>,
    u: Option<i64>,
    w: Option<i64>,
    x: Option<i64>,
    z: Option<i64>,
    /// G162 words: A (tenths of a degree), B and J (0.001°, J in `j`), H (lead counts), I (pitch
    /// change, lead counts), V (radius).
    a: Option<i64>,
    b: Option<i64>,
    h: Option<i64>,
    pitch_change: Option<i64>,
    v: Option<i64>,
    /// G90 I (radius) or G94 K: the taper.
    taper: Option<i64>,
    /// Arc I (radius, increments); its K is `k`, its R `r`.
    i: Option<i64>,
    /// Δd of a G71 (U) or G72 (W) first block; its e is `r`.
    depth: Option<i64>,
}

impl Machine {
    pub fn new(config: Config) -> Machine {
        let params = crate::config::check(&config).unwrap_or(crate::config::DEFAULTS);
        Machine {
            config,
            params,
            pos: (config.start_x, config.start_z),
            mode: Mode::Rapid,
            feed: None,
            g92: G92State::new(),
            cut: CutState::new(),
            g92_pull: PullMemo::default(),
            g76: FirstBlock::defaults(&params, Code::G76),
            g78: FirstBlock::defaults(&params, Code::G78),
            g78_jk: (None, None),
            incremental: false,
            comp: Comp::Off,
            g71: FirstValues { depth: params.p5132_rough_depth, retract: params.p5133_rough_retract },
            g72: FirstValues { depth: params.p5132_rough_depth, retract: params.p5133_rough_retract },
            g74_e: params.p5139_peck_return,
            g75_e: params.p5139_peck_return,
            g73: canned::PatternValues::defaults(&params),
            rigid: false,
            per_minute: false,
            spindle: None,
            surface: false,
            limited: false,
            smax_due: false,
        }
    }

    /// Reads one block: writes what it asks of the expander into `run` (in place: a cycle
    /// is not copied on its way out) and returns what comes next: the next block, the end
    /// (M02, M30), a subprogram call (M98) or return (M99).
    pub fn block(&mut self, b: &Block, run: &mut Run, prog: &mut Program<'_, '_>) -> Result<Flow, Alarm> {
        *run = Run::Idle;
        // A plain block (no G code, only N U W X Z) under a modal move or cycle: the same checks
        // and result, without the steps that cannot apply to it (`plain`).
        if let Some(plain) = self.plain(b) {
            if plain.is_move() {
                *run = self.plain_move(plain, b, self.config.grid.decimals())?.map_or(Run::Idle, Run::Move);
            } else {
                self.plain_cycle(plain, b, run)?;
            }
            return Ok(Flow::Next);
        }
        let line = b.line;
        let at = |letter: u8| At { letter, line };
        let Codes { motion, family, end, absinc, g80, g96, sub } = self.codes(b, prog.in_subprogram)?;
        // G84.FORMAT: G80 ends rigid tapping, then an M29 of this block arms it.
        self.rigid = (self.rigid && !g80) || b.get(b'M').is_some_and(|m| m.is(29));
        // G96.SMAX: the maximum must come from an earlier block.
        self.smax_due = g96 && !self.limited;
        let nc201 = self.config.dialect == Dialect::Nc201;
        let axis = if nc201 {
            b.has(b'X') || b.has(b'Z')
        } else {
            b.has(b'X') || b.has(b'U') || b.has(b'Z') || b.has(b'W')
        };
        let kind = match (family, motion) {
            (Some(f), Some(code)) => cycle_kind(f, code, b, axis).ok_or_else(|| {
                Alarm::new(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, line)
            })?,
            (_, Some(50)) => Kind::G50,
            (_, Some(2)) => Kind::Arc(true),
            (_, Some(3)) => Kind::Arc(false),
            (_, Some(1)) => Kind::Feed,
            (_, Some(_)) => Kind::Rapid,
            (_, None) => match self.mode {
                Mode::Rapid => Kind::Rapid,
                Mode::Feed => Kind::Feed,
                Mode::G92 => Kind::G92,
                Mode::Thread(code) => Kind::Thread(code),
                Mode::Cut(code) => Kind::Cut(code),
                Mode::Arc(cw) => Kind::Arc(cw),
            },
        };
        // G50.SMAX, G96.SPEED: S in the block's state after its G codes — with G50 the maximum,
        // else under G96 a surface speed, else (G97) the spindle speed in rpm.
        if let Some(s) = b.get(b'S') {
            if kind == Kind::G50 {
                self.limited = true;
            } else if !self.surface {
                self.spindle = Some(s);
            }
        }
        // (2) conflicts: X/U, Z/W, and F/I in a thread block, where I is threads per inch (the
        // two-motion-code and G90/G91 conflicts are found in `codes`). Under nc201 U and W are
        // no incremental addresses and I is G162's pitch change, so none of these pairs exists
        // there (NC201.ABSINC). Elsewhere I is another word or not allowed (COM.LEAD).
        let thread = matches!(kind, Kind::G92 | Kind::First(_) | Kind::Second(_) | Kind::Thread(_));
        for (first, second, rule, applies) in [
            (b'X', b'U', Rule::ComAbsInc, true),
            (b'Z', b'W', Rule::ComAbsInc, true),
            (b'F', b'I', Rule::ComLead, thread),
        ] {
            if !nc201 && applies && b.has(first) && b.has(second) {
                return Err(at(second).alarm(AlarmCode::Conflict, rule));
            }
        }
        // ARC.FORMAT: R with I or K in an arc block.
        if matches!(kind, Kind::Arc(_)) && b.has(b'R') && (b.has(b'I') || b.has(b'K')) {
            return Err(at(b'R').alarm(AlarmCode::Conflict, Rule::ArcFormat));
        }
        if let Some(incremental) = absinc {
            // NC201.ABSINC: modal, in force from the block that writes it.
            self.incremental = incremental;
        }
        // SUB.CALL, SUB.RETURN: an M98/M99 block's words, P, and the call or return.
        if let Some(call) = sub {
            return self.sub_block(b, call);
        }
        // (2) allowed words, alphabetically.
        let refused = b.mask() & !(allowed(kind, self.config.dialect) | COMMON);
        if refused != 0 {
            let l = b'A' + refused.trailing_zeros() as u8; // the first alphabetically
            // A GSK word that F76.FORMAT leaves out is refused by that format; any other by PRJ.WORD.
            let gsk_only = allowed(kind, Dialect::Gsk) & letter_bit(l) != 0;
            let rule = if self.config.dialect == Dialect::Fanuc && gsk_only { Rule::F76Format } else { Rule::PrjWord };
            return Err(at(l).alarm(AlarmCode::WordNotAllowed, rule));
        }
        // (3) values, alphabetically.
        let mut v = Vals::default();
        for l in b.letters() {
            if let Some(n) = b.get(l) {
                self.value(kind, l, n, at(l), &mut v)?;
            }
        }
        // (4), (5) and what runs.
        match kind {
            Kind::Rapid | Kind::Feed => {
                *run = self.linear(kind, motion.is_some(), &v, axis, line)?.map_or(Run::Idle, Run::Move);
            }
            Kind::G92 => self.g92(motion.is_some(), &v, axis, line, run)?,
            Kind::First(code) => self.first(code, &v),
            Kind::Second(code) => self.second(code, &v, line, run)?,
            Kind::Thread(code) => {
                *run = self.thread(code, motion.is_some(), &v, axis, line)?.map_or(Run::Idle, Run::Move);
            }
            Kind::G162 => self.g162(&v, line, run)?,
            Kind::Cut(code) => self.cut(code, motion.is_some(), &v, axis, line, run)?,
            Kind::G50 => self.g50(&v),
            Kind::Arc(cw) => {
                *run = self.arc(cw, motion.is_some(), &v, axis, line)?.map_or(Run::Idle, Run::Move);
            }
            Kind::G70 => self.g70(&v, line, run, prog)?,
            Kind::RoughFirst(code) => self.rough_first(code, &v),
            Kind::RoughSecond(code) => self.rough_second(code, &v, line, run, prog)?,
            Kind::PeckFirst(code) => self.peck_first(code, &v),
            Kind::PeckSecond(code) => self.peck_second(code, &v, line, run)?,
            Kind::PatternFirst => self.pattern_first(&v),
            Kind::PatternSecond(b_format) => self.pattern_second(b_format, &v, line, run, prog)?,
            Kind::G83 => self.g83(&v, line, run)?,
            Kind::G84 => self.g84(&v, line, run)?,
        }
        // G96.SMAX for a block whose handler has no step 5 (or did not reach it), then
        // G96.RAPID.
        self.speed_limit(line)?;
        if kind == Kind::Rapid && axis {
            self.rapid_under_g96(line)?;
        }
        Ok(if end { Flow::End } else { Flow::Next })
    }

    /// COM.ABSINC: the end point from X(U), Z(W): U and W are added to the position `from`; an
    /// omitted axis takes `kept`.
    #[inline(always)]
    fn end_point(v: &Vals, from: (i64, i64), kept: (i64, i64)) -> (i64, i64) {
        let x = match (v.x, v.u) {
            (Some(x), _) => x,
            (None, Some(u)) => Self::moved(from.0, u),
            (None, None) => kept.0,
        };
        let z = match (v.z, v.w) {
            (Some(z), _) => z,
            (None, Some(w)) => Self::moved(from.1, w),
            (None, None) => kept.1,
        };
        (x, z)
    }

    /// `from + d`, saturated as the exact sum ([`Machine::end_point`]'s U and W); out of line,
    /// so that a block without U or W does not compute it.
    #[cold]
    #[inline(never)]
    fn moved(from: i64, d: i64) -> i64 {
        from.saturating_add(d)
    }

    /// NC201.ABSINC: the end point of a G00/G01 block under nc201 — X (a diameter count,
    /// NC201.XMODE) and Z absolute under G90, distances from `from` under G91; an omitted axis
    /// stays.
    fn nc201_end_point(&self, v: &Vals, from: (i64, i64)) -> (i64, i64) {
        let axis = |word: Option<i64>, here: i64| match word {
            Some(w) if self.incremental => sat(i128::from(here) + i128::from(w)),
            Some(w) => w,
            None => here,
        };
        (axis(v.x, from.0), axis(v.z, from.1))
    }

    /// PRJ.MODAL: G00 / G01 blocks (and non-motion blocks in those modes); the move, if any.
    fn linear(&mut self, kind: Kind, coded: bool, v: &Vals, axis: bool, line: u32) -> Result<Option<Move>, Alarm> {
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
    fn g50(&mut self, v: &Vals) {
        self.pos = (v.x.unwrap_or(self.pos.0), v.z.unwrap_or(self.pos.1));
    }
}


#[cfg(test)]
mod tests;
