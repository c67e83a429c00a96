//! The modal interpreter (PRJ.MODAL, PRJ.WORD, PRJ.SUPPORTED, PRJ.DIALECT, COM.ABSINC,
//! COM.LEAD): blocks in, trace events out.
//!
//! State carried from block to block: the position, the motion mode (G00, G01, G92, G32, G33,
//! G34), the modal feed/lead, the G92 modal words (J, K, L) and run (end X, end Z, R, pass
//! index), the first-block memory of G76 and of G78, and under `nc201` the G90/G91 mode
//! (docs/INTERPRETATION.md, "Program and modal state", "The `nc201` dialect").
//!
//! Check order within a block (docs/INTERPRETATION.md): (1) lexing (done by the spec's own
//! reader, [`crate::lex`]); (2) G and M codes supported, then conflicts (two motion codes;
//! G90/G91; X/U, Z/W, F/I except under `nc201`), then words allowed in alphabetical order;
//! (3) each word's value in alphabetical order; (4) missing words (lead F, then P, then Q; G162
//! and G34 as the register lists them); (5) the cycle's own checks.

use crate::emit::Out;
use crate::g162::{self, G162Block};
use crate::g92::{self, G92Cycle};
use crate::multipass::{self, Cycle, FirstBlock, SecondBlock};
use crate::thread_moves::{self, ThreadCode, ThreadMove};
use crate::words::{self, alarm, lead_max, JK_MAX, N};
use crate::lex::{Block, Number};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Rule, Units};

/// The modal motion mode (PRJ.MODAL).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Motion {
    G00,
    G01,
    G92,
    Thread(ThreadCode),
}

/// A motion or cycle code written in a block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Code {
    G00,
    G01,
    G92,
    G76,
    G78,
    Thread(ThreadCode),
    G162,
}

/// What a block is, after its codes and the modal state are known.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Rapid,
    Linear,
    G92,
    /// G76/G78 without X, U, Z, W (G76.FORMAT).
    First(Cycle),
    /// G76/G78 with any of X, U, Z, W.
    Second(Cycle),
    /// G32, G33, G34 (written or modal).
    Thread(ThreadCode),
    /// G162 (one-shot).
    G162,
}

/// A G92 modal run (G92.MODAL): kept end X, end Z (absolute), R, and the pass index.
#[derive(Clone, Copy, Debug, Default)]
struct Run {
    end_x: Option<i128>,
    end_z: Option<i128>,
    r: i128,
    index: u32,
}

/// The values of one block's words, by letter (lengths in increments, leads in lead counts).
#[derive(Clone, Copy, Debug, Default)]
struct Values([Option<i64>; 26]);

impl Values {
    fn get(&self, letter: u8) -> Option<i64> {
        self.0[(letter - b'A') as usize]
    }
    fn set(&mut self, letter: u8, v: i64) {
        self.0[(letter - b'A') as usize] = Some(v);
    }
}

/// The machine between blocks.
pub struct Machine<'c> {
    config: &'c Config,
    pub out: Out,
    motion: Motion,
    feed: Option<i64>,
    g92_j: Option<i64>,
    g92_k: Option<i64>,
    g92_l: u32,
    run: Run,
    first76: FirstBlock,
    first78: FirstBlock,
    /// NC201.ABSINC: G91 (X and Z are distances from the position before the block).
    incremental: bool,
}

/// Words every block accepts, without effect (PRJ.MODAL): N, O, M, S, T (G and M are checked
/// as codes).
const ALWAYS: &[u8] = b"MNOST";

impl<'c> Machine<'c> {
    /// PRJ.MODAL (PRJ): the machine starts at the configured start point, in G00, with no feed.
    pub fn new(config: &'c Config) -> Machine<'c> {
        Machine {
            config,
            out: Out::new(config.start_x, config.start_z),
            motion: Motion::G00,
            feed: None,
            g92_j: None,
            g92_k: None,
            g92_l: 1,
            run: Run::default(),
            first76: FirstBlock::default(),
            first78: FirstBlock::default(),
            incremental: false,
        }
    }

    /// Executes one block. `Ok(true)` when the block ends the program (M02, M30).
    pub fn block(&mut self, b: &Block) -> Result<bool, Alarm> {
        let (code, end) = self.codes(b)?;
        let kind = self.kind(b, code);
        conflicts(b, self.config.dialect, kind)?;
        self.words_allowed(b, kind)?;
        let v = self.values(b, kind)?;
        self.absolute_or_incremental(b);
        match kind {
            Kind::Rapid | Kind::Linear => self.linear(b, kind, &v)?,
            Kind::G92 => self.g92(b, code == Some(Code::G92), &v)?,
            Kind::First(cycle) => self.first_block(cycle, &v),
            Kind::Second(cycle) => self.second_block(b, cycle, &v)?,
            Kind::Thread(code) => self.thread(b, code, &v)?,
            Kind::G162 => self.g162(b, &v)?,
        }
        Ok(end)
    }

    /// PRJ.SUPPORTED (PRJ), COM.UNITS (M000, M001), PRJ.DIALECT (PRJ): every G and M code of the block is supported.
    /// Under `nc201`: G00, G01, G162, G90, G91 and the no-motion codes; G92, G76, G78, G32,
    /// G33, G34 are refused (PRJ.DIALECT), as G162 is under `gsk` and `fanuc`.
    /// Returns the motion/cycle code written (if one) and whether the block ends the program.
    fn codes(&self, b: &Block) -> Result<(Option<Code>, bool), Alarm> {
        let line = b.line;
        let nc201 = self.config.dialect == Dialect::Nc201;
        let mut motion = None;
        for g in b.g_codes() {
            let unsupported = alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, line);
            let other_dialect = alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, line);
            // A G with a decimal point (G1.0, G92.1) or a sign is not a supported code.
            let Some(g) = code_value(g) else { return Err(unsupported) };
            let code = match g {
                0 => Some(Code::G00),
                1 => Some(Code::G01),
                32 | 33 | 34 | 76 | 78 | 92 if nc201 => return Err(other_dialect),
                162 if nc201 => Some(Code::G162),
                162 => return Err(other_dialect),
                90 | 91 if nc201 => None,
                32 => Some(Code::Thread(ThreadCode::G32)),
                33 => Some(Code::Thread(ThreadCode::G33)),
                34 => Some(Code::Thread(ThreadCode::G34)),
                92 => Some(Code::G92),
                76 => Some(Code::G76),
                78 if self.config.dialect == Dialect::Fanuc => {
                    // PRJ.DIALECT: G78 is a GSK code.
                    return Err(alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, line));
                }
                78 => Some(Code::G78),
                18 | 40 | 97 | 99 => None,
                20 | 21 => {
                    // COM.UNITS: the grid of a trace is fixed for the whole program.
                    let wanted = if g == 20 { Units::Inch } else { Units::Metric };
                    if wanted != self.config.grid.units {
                        return Err(alarm(AlarmCode::Unsupported, b'G', Rule::ComUnits, line));
                    }
                    None
                }
                _ => return Err(unsupported),
            };
            if motion.is_none() {
                motion = code;
            }
        }
        let mut end = false;
        if let Some(m) = b.get(b'M') {
            if m.point {
                return Err(alarm(AlarmCode::NotInteger, b'M', Rule::ComRanges, line));
            }
            let m = code_value(m).filter(|&m| m <= 99);
            let Some(m) = m else {
                return Err(alarm(AlarmCode::UnsupportedCode, b'M', Rule::PrjSupported, line));
            };
            // PRJ.MODAL: M02 and M30 end the program.
            end = m == 2 || m == 30;
        }
        Ok((motion, end))
    }

    /// The block's kind: its written code, else the modal motion mode; G76/G78 blocks are first
    /// blocks without X, U, Z, W and second blocks with any of them (G76.FORMAT, M001; PRJ.MODAL,
    /// PRJ).
    fn kind(&self, b: &Block, code: Option<Code>) -> Kind {
        let axes = has_axis(b);
        match code {
            Some(Code::G00) => Kind::Rapid,
            Some(Code::G01) => Kind::Linear,
            Some(Code::G92) => Kind::G92,
            Some(Code::G76) if axes => Kind::Second(Cycle::G76),
            Some(Code::G76) => Kind::First(Cycle::G76),
            Some(Code::G78) if axes => Kind::Second(Cycle::G78),
            Some(Code::G78) => Kind::First(Cycle::G78),
            Some(Code::Thread(t)) => Kind::Thread(t),
            Some(Code::G162) => Kind::G162,
            None => match self.motion {
                Motion::G00 => Kind::Rapid,
                Motion::G01 => Kind::Linear,
                Motion::G92 => Kind::G92,
                Motion::Thread(t) => Kind::Thread(t),
            },
        }
    }

    /// PRJ.WORD (PRJ), F76.FORMAT (M003): the words each kind of block accepts, checked in alphabetical order.
    fn words_allowed(&self, b: &Block, kind: Kind) -> Result<(), Alarm> {
        let fanuc = self.config.dialect == Dialect::Fanuc;
        let nc201 = self.config.dialect == Dialect::Nc201;
        let (own, gsk_own): (&[u8], &[u8]) = match kind {
            // NC201.ABSINC: U and W are no incremental addresses under nc201.
            Kind::Rapid | Kind::Linear if nc201 => (b"XZF", b"XZF"),
            Kind::Rapid | Kind::Linear => (b"XUZWF", b"XUZWF"),
            Kind::Thread(ThreadCode::G32) => (b"XUZWFI", b"XUZWFI"),
            Kind::Thread(ThreadCode::G33) => (b"XUZWFIP", b"XUZWFIP"),
            Kind::Thread(ThreadCode::G34) => (b"XUZWFIK", b"XUZWFIK"),
            Kind::G162 => (b"ABFHIJPQVWXZ", b"ABFHIJPQVWXZ"),
            Kind::G92 => (b"XUZWRFIJKL", b"XUZWRFIJKL"),
            Kind::First(Cycle::G76) if fanuc => (b"PQR", b"PQRDLE"),
            Kind::First(_) => (b"PQRDLE", b"PQRDLE"),
            Kind::Second(Cycle::G76) if fanuc => (b"XUZWRPQFI", b"XUZWRPQJKFI"),
            Kind::Second(_) => (b"XUZWRPQJKFI", b"XUZWRPQJKFI"),
        };
        for letter in b.letters() {
            if ALWAYS.contains(&letter) || own.contains(&letter) {
                continue;
            }
            let rule = if gsk_own.contains(&letter) { Rule::F76Format } else { Rule::PrjWord };
            return Err(alarm(AlarmCode::WordNotAllowed, letter, rule, b.line));
        }
        Ok(())
    }

    /// COM.UNITS, COM.RANGES, COM.LEAD (M000, M001, M002), PRJ.DIALECT (PRJ): each word's value, in alphabetical order.
    fn values(&self, b: &Block, kind: Kind) -> Result<Values, Alarm> {
        let cfg = self.config;
        let grid = cfg.grid;
        let line = b.line;
        let mut v = Values::default();
        for letter in b.letters() {
            if ALWAYS.contains(&letter) {
                continue;
            }
            let Some(n) = b.get(letter) else { continue };
            let value = match (kind, letter) {
                // G162 (M004, docs/INTERPRETATION.md): X and W by x_radius; the other words.
                (Kind::G162, b'X' | b'W') => self.x_units(words::length(n, letter, grid, -N, N, line)?),
                (Kind::G162, b'Z') => words::length(n, letter, grid, -N, N, line)?,
                (Kind::G162, b'P' | b'Q') => words::length(n, letter, grid, 1, N, line)?,
                (Kind::G162, b'V') => words::length(n, letter, grid, 0, N, line)?,
                (Kind::G162, b'H') => words::feed(n, letter, grid, N, Rule::G162H, line)?,
                (Kind::G162, b'I') => words::signed_lead(n, letter, grid, lead_max(grid), Rule::G162I, line)?,
                (Kind::G162, b'A') => words::half_degrees(n, letter, line)?,
                (Kind::G162, b'B') => words::millidegrees(n, letter, 0, 360_000, Rule::G162B, line)?,
                (Kind::G162, b'J') => words::millidegrees(n, letter, 1, N, Rule::G162J, line)?,
                // G33 P start angle (0.001°), G34 K lead change per revolution (M003).
                (Kind::Thread(_), b'P') => words::integer(n, letter, 0, 359_999, Rule::G33, line)?,
                (Kind::Thread(_), b'K') => words::signed_lead(n, letter, grid, lead_max(grid), Rule::G34, line)?,
                // NC201.XMODE: X of G00/G01 by x_radius.
                (_, b'X') => self.x_units(words::length(n, letter, grid, -N, N, line)?),
                (_, b'U' | b'Z' | b'W') => words::length(n, letter, grid, -N, N, line)?,
                (_, b'F') => words::lead_from_f(n, grid, line)?,
                (_, b'I') => words::lead_from_i(n, grid, line)?,
                // G92: R signed length; J, K |v| ≤ 99 999 999; L 1…99.
                (Kind::G92, b'R') => words::length(n, letter, grid, -N, N, line)?,
                (Kind::G92, b'J' | b'K') => words::length(n, letter, grid, -JK_MAX, JK_MAX, line)?,
                (Kind::G92, b'L') => words::integer(n, letter, 1, 99, Rule::ComRanges, line)?,
                // G76/G78 first block.
                (Kind::First(cycle), b'P') => {
                    let p = words::integer(n, letter, 0, 999_999, Rule::ComRanges, line)?;
                    multipass::check_p_digits(cycle, p, cfg.dialect, line)?;
                    p
                }
                (Kind::First(_), b'Q') => words::micron_length(n, letter, cfg, 0, N, line)?,
                (Kind::First(_), b'R' | b'E') => words::length(n, letter, grid, 0, N, line)?,
                (Kind::First(Cycle::G76), b'D') => words::integer(n, letter, 0, 2, Rule::G76Mode, line)?,
                (Kind::First(Cycle::G78), b'D') => words::integer(n, letter, 0, 1, Rule::G78DepthMode, line)?,
                (Kind::First(_), b'L') => words::integer(n, letter, 1, 999, Rule::ComRanges, line)?,
                // G76/G78 second block.
                (Kind::Second(_), b'R') => words::length(n, letter, grid, -N, N, line)?,
                (Kind::Second(_), b'P' | b'Q') => words::micron_length(n, letter, cfg, 1, N, line)?,
                (Kind::Second(_), b'J' | b'K') => words::length(n, letter, grid, 0, N, line)?,
                // Not reachable: words_allowed refused every other letter.
                _ => return Err(alarm(AlarmCode::WordNotAllowed, letter, Rule::PrjWord, line)),
            };
            v.set(letter, value);
        }
        Ok(v)
    }

    /// NC201.XMODE (M004): under `nc201` with `x_radius` = 1 an X or W word is a radius, counted
    /// twice on the diameter grid; otherwise the value is already a diameter.
    fn x_units(&self, v: i64) -> i64 {
        if self.config.dialect == Dialect::Nc201 && crate::config::params(self.config).x_radius == 1 {
            2 * v
        } else {
            v
        }
    }

    /// NC201.ABSINC (M004): G90 / G91 written in the block set the mode, for this block on.
    fn absolute_or_incremental(&mut self, b: &Block) {
        for g in b.g_codes() {
            match code_value(g) {
                Some(90) => self.incremental = false,
                Some(91) => self.incremental = true,
                _ => {}
            }
        }
    }

    /// COM.LEAD (M001, M002): F and I set one modal feed value (F and I never both: conflicts).
    fn take_lead(&mut self, v: &Values) {
        if let Some(f) = v.get(b'F').or(v.get(b'I')) {
            self.feed = Some(f);
        }
    }

    /// COM.ABSINC (M001, M002): the end point of X(U) and Z(W), `None` for an omitted axis.
    /// NC201.ABSINC (M004): under `nc201`, X and Z are positions (G90) or distances from the
    /// current position (G91).
    fn end_point(&self, v: &Values) -> (Option<i128>, Option<i128>) {
        if self.config.dialect == Dialect::Nc201 {
            let (bx, bz) = if self.incremental { (self.out.x as i128, self.out.z as i128) } else { (0, 0) };
            return (v.get(b'X').map(|x| bx + x as i128), v.get(b'Z').map(|z| bz + z as i128));
        }
        let x = v.get(b'X').map(i128::from).or(v.get(b'U').map(|u| self.out.x as i128 + u as i128));
        let z = v.get(b'Z').map(i128::from).or(v.get(b'W').map(|w| self.out.z as i128 + w as i128));
        (x, z)
    }

    /// G00 / G01 (PRJ.MODAL, PRJ): one move to the end point, both axes together; G01 at the modal
    /// feed (COM.LEAD: `MISSING WORD F` when a G01 block moves with no feed set).
    fn linear(&mut self, b: &Block, kind: Kind, v: &Values) -> Result<(), Alarm> {
        self.take_lead(v);
        let moving = has_axis(b);
        if kind == Kind::Linear && moving && self.feed.is_none() {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, b.line));
        }
        self.motion = if kind == Kind::Linear { Motion::G01 } else { Motion::G00 };
        if !moving {
            return Ok(());
        }
        let (x, z) = self.end_point(v);
        let x = x.unwrap_or(self.out.x as i128);
        let z = z.unwrap_or(self.out.z as i128);
        match (kind, self.feed) {
            (Kind::Linear, Some(f)) => self.out.feed(x, z, f, Rule::PrjModal, b.line),
            _ => self.out.rapid(x, z, Rule::PrjModal, b.line),
        }
    }

    /// G92.MODAL (M002): G92 is a motion mode. A block with axis words (and G92, or no motion
    /// code in G92 mode) cuts one cycle; end X, end Z and R are kept within the run, F/I, J, K,
    /// L for the whole program. A new run starts with R = 0 and the end point at the current
    /// position. A block without axis words does not cut.
    fn g92(&mut self, b: &Block, written: bool, v: &Values) -> Result<(), Alarm> {
        let line = b.line;
        if written && self.motion != Motion::G92 {
            self.run = Run::default();
        }
        self.motion = Motion::G92;
        self.take_lead(v);
        if let Some(j) = v.get(b'J') {
            self.g92_j = Some(j);
        }
        if let Some(k) = v.get(b'K') {
            self.g92_k = Some(k);
        }
        if let Some(l) = v.get(b'L') {
            self.g92_l = l as u32;
        }
        if let Some(r) = v.get(b'R') {
            self.run.r = r as i128;
        }
        if !has_axis(b) {
            return Ok(());
        }
        // G92.FORMAT / COM.LEAD: the lead is required.
        let Some(lead) = self.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        let a = (self.out.x as i128, self.out.z as i128);
        let (x, z) = self.end_point(v);
        let dx = x.or(self.run.end_x).unwrap_or(a.0);
        let dz = z.or(self.run.end_z).unwrap_or(a.1);
        self.run.end_x = Some(dx);
        self.run.end_z = Some(dz);
        self.run.index = self.run.index.saturating_add(1);
        let cycle = G92Cycle {
            a,
            d: (dx, dz),
            r: self.run.r,
            lead,
            j: self.g92_j,
            k: self.g92_k,
            l: self.g92_l,
            index: self.run.index,
            line,
        };
        g92::expand(&cycle, &crate::config::params(self.config), self.config.grid, &mut self.out)
    }

    /// G76.FORMAT (M001) / G78.FORMAT (M000): a first block replaces that code's memory; omitted words fall
    /// back to their defaults again.
    fn first_block(&mut self, cycle: Cycle, v: &Values) {
        let mem = FirstBlock {
            p: v.get(b'P'),
            q_min: v.get(b'Q'),
            r_finish: v.get(b'R'),
            d_mode: v.get(b'D'),
            l_starts: v.get(b'L'),
            e_leadin: v.get(b'E'),
        };
        match cycle {
            Cycle::G76 => self.first76 = mem,
            Cycle::G78 => self.first78 = mem,
        }
    }

    /// G76.FORMAT (M001) / G78.FORMAT (M000) second block, G76.REQUIRED (M001): missing words (lead F, then P, then Q), then the
    /// cycle. G76/G78 do not change the motion mode.
    fn second_block(&mut self, b: &Block, cycle: Cycle, v: &Values) -> Result<(), Alarm> {
        let line = b.line;
        self.take_lead(v);
        let Some(lead) = self.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        let Some(k) = v.get(b'P') else {
            return Err(alarm(AlarmCode::MissingWord, b'P', Rule::G76Required, line));
        };
        let Some(dd) = v.get(b'Q') else {
            return Err(alarm(AlarmCode::MissingWord, b'Q', Rule::G76Required, line));
        };
        let a = (self.out.x as i128, self.out.z as i128);
        let (x, z) = self.end_point(v);
        let second = SecondBlock {
            a,
            d: (x.unwrap_or(a.0), z.unwrap_or(a.1)),
            i: v.get(b'R').unwrap_or(0) as i128,
            k,
            dd,
            j: v.get(b'J'),
            k_pull: v.get(b'K'),
            lead,
            line,
        };
        let first = match cycle {
            Cycle::G76 => self.first76,
            Cycle::G78 => self.first78,
        };
        multipass::expand(cycle, &first, &second, self.config, &mut self.out)
    }

    /// G32, G33, G34 (M003): modal thread moves. The lead is the modal feed (`MISSING WORD F`,
    /// COM.LEAD, in a block that moves), G34 needs its K (`MISSING WORD K`, G34); G33 P and G34
    /// K are not kept. A block without axis words moves nothing.
    fn thread(&mut self, b: &Block, code: ThreadCode, v: &Values) -> Result<(), Alarm> {
        let line = b.line;
        self.take_lead(v);
        self.motion = Motion::Thread(code);
        if !has_axis(b) {
            return Ok(());
        }
        let Some(lead) = self.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        let k = match code {
            ThreadCode::G34 => match v.get(b'K') {
                Some(k) => k,
                None => return Err(alarm(AlarmCode::MissingWord, b'K', Rule::G34, line)),
            },
            _ => 0,
        };
        let from = (self.out.x as i128, self.out.z as i128);
        let (x, z) = self.end_point(v);
        let angle = v.get(b'P').unwrap_or(0) as u32;
        let m = ThreadMove { code, from, to: (x.unwrap_or(from.0), z.unwrap_or(from.1)), lead, angle, k, line };
        thread_moves::expand(&m, self.config.grid, &mut self.out)
    }

    /// G162 (M004): one-shot. F sets the modal feed; without F the modal feed is the lead
    /// (G162.F). Missing words in the register's order: F, H, P/Q (a pair), X, Z.
    fn g162(&mut self, b: &Block, v: &Values) -> Result<(), Alarm> {
        let line = b.line;
        let missing = |word: u8, rule: Rule| Err(alarm(AlarmCode::MissingWord, word, rule, line));
        if let Some(f) = v.get(b'F') {
            self.feed = Some(f);
        }
        let Some(lead) = self.feed else { return missing(b'F', Rule::G162F) };
        let Some(h) = v.get(b'H') else { return missing(b'H', Rule::G162H) };
        let depth = match (v.get(b'P'), v.get(b'Q')) {
            (Some(p), Some(q)) => Some((p, q)),
            (None, Some(_)) => return missing(b'P', Rule::G162Pq),
            (Some(_), None) => return missing(b'Q', Rule::G162Pq),
            (None, None) => None,
        };
        let (x, z) = self.end_point(v);
        let Some(x0) = x else { return missing(b'X', Rule::G162Format) };
        let Some(ze) = z else { return missing(b'Z', Rule::G162Format) };
        let cycle = G162Block {
            s: (self.out.x as i128, self.out.z as i128),
            x0,
            ze,
            h,
            depth,
            v: v.get(b'V').unwrap_or(0),
            wd: v.get(b'W').unwrap_or(0) as i128,
            a_half: v.get(b'A').unwrap_or(0),
            lead,
            b: v.get(b'B').unwrap_or(0),
            i: v.get(b'I').unwrap_or(0),
            j: v.get(b'J').unwrap_or(360_000),
            line,
        };
        g162::expand(&cycle, self.config, &mut self.out)
    }
}

/// Whether the block has an axis word X, U, Z or W.
fn has_axis(b: &Block) -> bool {
    b.has(b'X') || b.has(b'U') || b.has(b'Z') || b.has(b'W')
}

/// How many of `codes` the block writes.
fn code_count(b: &Block, codes: &[u64]) -> usize {
    b.g_codes().filter(|g| code_value(g).is_some_and(|g| codes.contains(&g))).count()
}

/// PRJ.SUPPORTED: the value of a G or M code, `None` when it has a decimal point or a sign (no
/// code) or more digits than any code.
fn code_value(n: &Number) -> Option<u64> {
    if n.point || n.negative {
        return None;
    }
    if n.digits.is_empty() {
        return Some(0);
    }
    n.digits.parse().ok()
}

/// PRJ.WORD (PRJ), NC201.ABSINC (M004), COM.ABSINC, COM.LEAD (M001, M002): two motion codes;
/// two of G90/G91; X with U; Z with W; F with I in a thread block (G92, G76, G78, G32, G33,
/// G34, written or modal), where I is threads per inch. Under `nc201` U, W and I are no
/// incremental or lead addresses, so the three pair conflicts do not exist there.
fn conflicts(b: &Block, dialect: Dialect, kind: Kind) -> Result<(), Alarm> {
    let line = b.line;
    if code_count(b, &[0, 1, 92, 76, 78, 32, 33, 34, 162]) > 1 {
        return Err(alarm(AlarmCode::Conflict, b'G', Rule::PrjWord, line));
    }
    if code_count(b, &[90, 91]) > 1 {
        return Err(alarm(AlarmCode::Conflict, b'G', Rule::Nc201AbsInc, line));
    }
    if dialect == Dialect::Nc201 {
        return Ok(());
    }
    if b.has(b'X') && b.has(b'U') {
        return Err(alarm(AlarmCode::Conflict, b'U', Rule::ComAbsInc, line));
    }
    if b.has(b'Z') && b.has(b'W') {
        return Err(alarm(AlarmCode::Conflict, b'W', Rule::ComAbsInc, line));
    }
    let thread = matches!(kind, Kind::G92 | Kind::First(_) | Kind::Second(_) | Kind::Thread(_));
    if thread && b.has(b'F') && b.has(b'I') {
        return Err(alarm(AlarmCode::Conflict, b'I', Rule::ComLead, line));
    }
    Ok(())
}
