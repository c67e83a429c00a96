//! The modal interpreter (PRJ.MODAL, PRJ.WORD, PRJ.SUPPORTED, PRJ.DIALECT, COM.ABSINC,
//! COM.LEAD): blocks in, trace events out.
//!
//! State carried from block to block: the position, the motion mode (G00, G01 or G92), the
//! modal feed/lead, the G92 modal words (J, K, L) and run (end X, end Z, R, pass index), and the
//! first-block memory of G76 and of G78 (docs/INTERPRETATION.md, "Program and modal state").
//!
//! Check order within a block (docs/INTERPRETATION.md): (1) lexing (done by
//! [`cycle_vocab::Blocks`]); (2) G and M codes supported, then conflicts (two motion codes; X/U;
//! Z/W; F/I), then words allowed in alphabetical order; (3) each word's value in alphabetical
//! order; (4) missing words (lead F, then P, then Q); (5) the cycle's own checks.

use crate::emit::Out;
use crate::g92::{self, G92Cycle};
use crate::multipass::{self, Cycle, FirstBlock, SecondBlock};
use crate::words::{self, alarm, JK_MAX, N};
use cycle_vocab::{Alarm, AlarmCode, Block, Config, Dialect, Rule, Units};

/// The modal motion mode (PRJ.MODAL).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Motion {
    G00,
    G01,
    G92,
}

/// A motion or cycle code written in a block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Code {
    G00,
    G01,
    G92,
    G76,
    G78,
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
        }
    }

    /// Executes one block. `Ok(true)` when the block ends the program (M02, M30).
    pub fn block(&mut self, b: &Block) -> Result<bool, Alarm> {
        let (code, end) = self.codes(b)?;
        conflicts(b, code_count(b))?;
        let kind = self.kind(b, code);
        self.words_allowed(b, kind)?;
        let v = self.values(b, kind)?;
        match kind {
            Kind::Rapid | Kind::Linear => self.linear(b, kind, &v)?,
            Kind::G92 => self.g92(b, code == Some(Code::G92), &v)?,
            Kind::First(cycle) => self.first_block(cycle, &v),
            Kind::Second(cycle) => self.second_block(b, cycle, &v)?,
        }
        Ok(end)
    }

    /// PRJ.SUPPORTED (PRJ), COM.UNITS (M000, M001), PRJ.DIALECT (PRJ): every G and M code of the block is supported.
    /// Returns the motion/cycle code written (if one) and whether the block ends the program.
    fn codes(&self, b: &Block) -> Result<(Option<Code>, bool), Alarm> {
        let line = b.line;
        let mut motion = None;
        for g in b.g_codes() {
            let unsupported = alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, line);
            // A G with a decimal point (G1.0, G92.1) or a sign is not a supported code.
            if g.point || g.negative {
                return Err(unsupported);
            }
            let code = match g.mantissa {
                0 => Some(Code::G00),
                1 => Some(Code::G01),
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
                    let wanted = if g.mantissa == 20 { Units::Inch } else { Units::Metric };
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
            if m.negative || m.mantissa > 99 {
                return Err(alarm(AlarmCode::UnsupportedCode, b'M', Rule::PrjSupported, line));
            }
            // PRJ.MODAL: M02 and M30 end the program.
            end = m.mantissa == 2 || m.mantissa == 30;
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
            None => match self.motion {
                Motion::G00 => Kind::Rapid,
                Motion::G01 => Kind::Linear,
                Motion::G92 => Kind::G92,
            },
        }
    }

    /// PRJ.WORD (PRJ), F76.FORMAT (M003): the words each kind of block accepts, checked in alphabetical order.
    fn words_allowed(&self, b: &Block, kind: Kind) -> Result<(), Alarm> {
        let fanuc = self.config.dialect == Dialect::Fanuc;
        let (own, gsk_own): (&[u8], &[u8]) = match kind {
            Kind::Rapid | Kind::Linear => (b"XUZWF", b"XUZWF"),
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
                (_, b'X' | b'U' | b'Z' | b'W') => words::length(n, letter, grid, -N, N, line)?,
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

    /// COM.LEAD (M001, M002): F and I set one modal feed value (F and I never both: conflicts).
    fn take_lead(&mut self, v: &Values) {
        if let Some(f) = v.get(b'F').or(v.get(b'I')) {
            self.feed = Some(f);
        }
    }

    /// COM.ABSINC (M001, M002): the end point of X(U) and Z(W), `None` for an omitted axis.
    fn end_point(&self, v: &Values) -> (Option<i128>, Option<i128>) {
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
        g92::expand(&cycle, &self.config.params, self.config.grid, &mut self.out)
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
}

/// Whether the block has an axis word X, U, Z or W.
fn has_axis(b: &Block) -> bool {
    b.has(b'X') || b.has(b'U') || b.has(b'Z') || b.has(b'W')
}

/// How many motion/cycle codes (G0, G1, G92, G76, G78) the block writes.
fn code_count(b: &Block) -> usize {
    b.g_codes()
        .iter()
        .filter(|g| !g.point && !g.negative && matches!(g.mantissa, 0 | 1 | 92 | 76 | 78))
        .count()
}

/// PRJ.WORD (PRJ), COM.ABSINC, COM.LEAD (M001, M002): two motion codes; X with U; Z with W; F with I.
fn conflicts(b: &Block, motion_codes: usize) -> Result<(), Alarm> {
    let line = b.line;
    if motion_codes > 1 {
        return Err(alarm(AlarmCode::Conflict, b'G', Rule::PrjWord, line));
    }
    if b.has(b'X') && b.has(b'U') {
        return Err(alarm(AlarmCode::Conflict, b'U', Rule::ComAbsInc, line));
    }
    if b.has(b'Z') && b.has(b'W') {
        return Err(alarm(AlarmCode::Conflict, b'W', Rule::ComAbsInc, line));
    }
    if b.has(b'F') && b.has(b'I') {
        return Err(alarm(AlarmCode::Conflict, b'I', Rule::ComLead, line));
    }
    Ok(())
}
