//! The modal interpreter (PRJ.MODAL, PRJ.WORD, PRJ.SUPPORTED, PRJ.DIALECT, COM.ABSINC,
//! NC201.ABSINC, NC201.XMODE, COM.LEAD): one block in, at most one [`Run`] out, with the check
//! order of docs/INTERPRETATION.md — (2) G and M codes, conflicts, allowed words alphabetically;
//! (3) values alphabetically; (4) missing words; (5) the cycle's own checks.

use crate::config::Params;
use crate::fixed::sat;
use crate::g162::{self, max_lead, SplitParams};
use crate::g90::{self, CutCode, CutState};
use crate::g92::{self, G92State, PullMemo};
use crate::multipass::{self, Code, FirstBlock, Second};
use crate::thread_move::{thread_move, ThreadCode, ThreadWords, MAX_START_ANGLE};
use crate::words::{
    infeed_angle, integer_in, lead_f, lead_i, length_in, scaled_in, signed_length, signed_lead, At, MAX_G92_JK, MAX_LENGTH,
};
use crate::lex::{letter_bit, letter_mask, Block};
use crate::number::Number;
use crate::run::Run;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, Rule, Units};

/// The modal motion mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Rapid,
    Feed,
    G92,
    /// G32, G33, G34 (PRJ.MODAL, M003).
    Thread(ThreadCode),
    /// G90, G94 (G90.MODAL, G94.MODAL).
    Cut(CutCode),
}

/// How the block's words are read (its code, or the modal mode).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Rapid,
    Feed,
    G92,
    First(Code),
    Second(Code),
    Thread(ThreadCode),
    G162,
    Cut(CutCode),
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
    /// NC201.ABSINC: G91 in force (`nc201` only).
    incremental: bool,
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
    /// G162 words: A (half degrees), B and J (0.001°, J in `j`), H (lead counts), I (pitch
    /// change, lead counts), V (radius).
    a: Option<i64>,
    b: Option<i64>,
    h: Option<i64>,
    pitch_change: Option<i64>,
    v: Option<i64>,
    /// G90 I (radius) or G94 K: the taper.
    taper: Option<i64>,
}

/// Words every block accepts (no motion effect).
const COMMON: u32 = letter_mask(b"MNOST");

/// PRJ.WORD, PRJ.DIALECT: the words a block of `kind` accepts besides G and [`COMMON`].
fn allowed(kind: Kind, dialect: Dialect) -> u32 {
    match (kind, dialect) {
        // NC201.ABSINC: U and W are no incremental addresses under nc201.
        (Kind::Rapid | Kind::Feed, Dialect::Nc201) => const { letter_mask(b"FXZ") },
        (Kind::Rapid | Kind::Feed, _) => const { letter_mask(b"FUWXZ") },
        (Kind::Thread(ThreadCode::G32), _) => const { letter_mask(b"FIUWXZ") },
        (Kind::Thread(ThreadCode::G33), _) => const { letter_mask(b"FIPUWXZ") },
        (Kind::Thread(ThreadCode::G34), _) => const { letter_mask(b"FIKUWXZ") },
        (Kind::G162, _) => const { letter_mask(b"ABFHIJPQVWXZ") },
        (Kind::Cut(CutCode::G90), _) => const { letter_mask(b"FIUWXZ") },
        (Kind::Cut(CutCode::G94), _) => const { letter_mask(b"FKUWXZ") },
        (Kind::G92, _) => const { letter_mask(b"FIJKLRUWXZ") },
        (Kind::First(_), Dialect::Fanuc) => const { letter_mask(b"PQR") },
        (Kind::First(_), Dialect::Gsk | Dialect::Nc201) => const { letter_mask(b"DELPQR") },
        (Kind::Second(_), Dialect::Fanuc) => const { letter_mask(b"FIPQRUWXZ") },
        (Kind::Second(_), Dialect::Gsk | Dialect::Nc201) => const { letter_mask(b"FIJKPQRUWXZ") },
    }
}

/// FANUC tool angles (F76.FORMAT).
pub const FANUC_ANGLES: [u32; 6] = [80, 60, 55, 30, 29, 0];

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
            incremental: false,
        }
    }

    /// Reads one block: writes what it asks of the expander into `run` (in place: a cycle
    /// is not copied on its way out) and returns whether it ends the program (M02, M30).
    pub fn block(&mut self, b: &Block, run: &mut Run) -> Result<bool, Alarm> {
        *run = Run::Idle;
        let line = b.line;
        let at = |letter: u8| At { letter, line };
        let (motion, end, absinc) = self.codes(b)?;
        let nc201 = self.config.dialect == Dialect::Nc201;
        let axis = if nc201 {
            b.has(b'X') || b.has(b'Z')
        } else {
            b.has(b'X') || b.has(b'U') || b.has(b'Z') || b.has(b'W')
        };
        let kind = match motion {
            Some(76) if axis => Kind::Second(Code::G76),
            Some(76) => Kind::First(Code::G76),
            Some(78) if axis => Kind::Second(Code::G78),
            Some(78) => Kind::First(Code::G78),
            Some(92) => Kind::G92,
            Some(32) => Kind::Thread(ThreadCode::G32),
            Some(33) => Kind::Thread(ThreadCode::G33),
            Some(34) => Kind::Thread(ThreadCode::G34),
            Some(162) => Kind::G162,
            Some(90) => Kind::Cut(CutCode::G90),
            Some(94) => Kind::Cut(CutCode::G94),
            Some(1) => Kind::Feed,
            Some(_) => Kind::Rapid,
            None => match self.mode {
                Mode::Rapid => Kind::Rapid,
                Mode::Feed => Kind::Feed,
                Mode::G92 => Kind::G92,
                Mode::Thread(code) => Kind::Thread(code),
                Mode::Cut(code) => Kind::Cut(code),
            },
        };
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
        if let Some(incremental) = absinc {
            // NC201.ABSINC: modal, in force from the block that writes it.
            self.incremental = incremental;
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
        }
        Ok(end)
    }

    /// (2) PRJ.SUPPORTED, PRJ.DIALECT, COM.UNITS, PRJ.WORD, NC201.ABSINC: the G codes in the
    /// order written, then M; the block's motion/cycle code, whether it ends the program, and
    /// its G90 (`Some(false)`) / G91 (`Some(true)`) under nc201.
    fn codes(&self, b: &Block) -> Result<(Option<u64>, bool, Option<bool>), Alarm> {
        let line = b.line;
        let g_alarm = |code: AlarmCode, rule: Rule| Alarm::new(code, Some(b'G'), rule, line);
        let dialect = self.config.dialect;
        let nc201 = dialect == Dialect::Nc201;
        let mut motion = None;
        let mut motions = 0u32;
        let mut absinc = None;
        let mut absincs = 0u32;
        for g in b.g_codes() {
            if g.point || g.negative {
                return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjSupported));
            }
            match g.mantissa {
                0 | 1 => {}
                // M003 / M001 / M002 codes are not defined for the M004 controller, and G162 only
                // for it (PRJ.DIALECT).
                92 | 76 | 32 | 33 | 34 | 90 | 94 if !nc201 => {}
                78 if dialect == Dialect::Gsk => {}
                162 if nc201 => {}
                // Under nc201 G90 is the absolute mode (below) and G94 is not defined.
                32 | 33 | 34 | 76 | 78 | 92 | 94 | 162 => {
                    return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjDialect))
                }
                90 | 91 if nc201 => {
                    absincs += 1;
                    absinc = Some(g.mantissa == 91);
                    continue;
                }
                20 if self.config.grid.units != Units::Inch => {
                    return Err(g_alarm(AlarmCode::Unsupported, Rule::ComUnits))
                }
                21 if self.config.grid.units != Units::Metric => {
                    return Err(g_alarm(AlarmCode::Unsupported, Rule::ComUnits))
                }
                18 | 20 | 21 | 40 | 97 | 99 => continue,
                _ => return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjSupported)),
            }
            motions += 1;
            motion = Some(g.mantissa);
        }
        let mut end = false;
        if let Some(m) = b.get(b'M') {
            let at = At { letter: b'M', line };
            if m.point {
                return Err(at.alarm(AlarmCode::NotInteger, Rule::ComRanges));
            }
            if m.negative || m.mantissa > 99 {
                return Err(at.alarm(AlarmCode::UnsupportedCode, Rule::PrjSupported));
            }
            end = m.mantissa == 2 || m.mantissa == 30;
        }
        if motions > 1 {
            return Err(g_alarm(AlarmCode::Conflict, Rule::PrjWord));
        }
        // NC201.ABSINC: G90 with G91, or either twice.
        if absincs > 1 {
            return Err(g_alarm(AlarmCode::Conflict, Rule::Nc201AbsInc));
        }
        Ok((motion, end, absinc))
    }

    /// (3) One word's value for a block of `kind` (COM.RANGES, COM.UNITS, COM.LEAD,
    /// F76.MICRONS, G76.MODE, G78.MODE, G78.DEPTHMODE, G76.FINISH, F76.FORMAT).
    fn value(&self, kind: Kind, letter: u8, n: Number, at: At, v: &mut Vals) -> Result<(), Alarm> {
        let grid = self.config.grid;
        // F76.MICRONS: FANUC G76 P(k), Q(Δd), Q(Δdmin) without a decimal point are increments.
        let micro = self.config.dialect == Dialect::Fanuc;
        let n_max = MAX_LENGTH;
        if kind == Kind::G162 {
            return self.value_g162(letter, n, at, v);
        }
        match (kind, letter) {
            (_, b'F') => v.lead = Some(lead_f(n, grid, at)?),
            // NC201.XMODE: X of G00/G01 by `x_radius`.
            (_, b'X') if self.config.dialect == Dialect::Nc201 => v.x = Some(self.x_word(n, at)?),
            // G90.FORMAT, G94.FORMAT: the taper, a signed length (I is no lead here).
            (Kind::Cut(CutCode::G90), b'I') | (Kind::Cut(CutCode::G94), b'K') => {
                v.taper = Some(signed_length(n, grid, at)?);
            }
            (_, b'I') => v.lead = Some(lead_i(n, grid, at)?),
            (_, b'U') => v.u = Some(signed_length(n, grid, at)?),
            (_, b'W') => v.w = Some(signed_length(n, grid, at)?),
            (_, b'X') => v.x = Some(signed_length(n, grid, at)?),
            (_, b'Z') => v.z = Some(signed_length(n, grid, at)?),
            // G92.JK.7: |J|, |K| ≤ 99 999 999, negative taken as positive.
            (Kind::G92, b'J') => {
                v.j = Some(length_in(n, grid, false, -MAX_G92_JK, MAX_G92_JK, at)?.abs());
            }
            (Kind::G92, b'K') => {
                v.k = Some(length_in(n, grid, false, -MAX_G92_JK, MAX_G92_JK, at)?.abs());
            }
            (Kind::G92, b'L') => v.l = Some(integer_in(n, 1, 99, Rule::ComRanges, at)?),
            (Kind::G92, b'R') => v.r = Some(signed_length(n, grid, at)?),
            (Kind::First(code), b'D') => {
                let (hi, rule) = match code {
                    Code::G76 => (2, Rule::G76Mode),
                    Code::G78 => (1, Rule::G78DepthMode),
                };
                v.d = Some(integer_in(n, 0, hi, rule, at)?);
            }
            (Kind::First(_), b'E') => v.e = Some(length_in(n, grid, false, 0, n_max, at)?),
            (Kind::First(_), b'L') => v.l = Some(integer_in(n, 1, 999, Rule::ComRanges, at)?),
            (Kind::First(code), b'P') => {
                let p = integer_in(n, 0, 999_999, Rule::ComRanges, at)?;
                let out = |rule: Rule| Err(at.alarm(AlarmCode::OutOfRange, rule));
                // m = 0 (OPEN): a thread whose finishing allowance is never cut.
                if p / 10_000 == 0 {
                    return out(Rule::G76Finish);
                }
                if code == Code::G78 && (p / 100) % 100 > 4 {
                    return out(Rule::G78Mode);
                }
                if micro {
                    let a = u32::try_from(p % 100).unwrap_or(u32::MAX);
                    if !FANUC_ANGLES.contains(&a) {
                        return out(Rule::F76Format);
                    }
                }
                v.p = Some(p);
            }
            (Kind::First(_), b'Q') => v.q = Some(length_in(n, grid, micro, 0, n_max, at)?),
            (Kind::First(_), b'R') => v.r = Some(length_in(n, grid, false, 0, n_max, at)?),
            (Kind::Second(_), b'J') => v.j = Some(length_in(n, grid, false, 0, n_max, at)?),
            (Kind::Second(_), b'K') => v.k = Some(length_in(n, grid, false, 0, n_max, at)?),
            (Kind::Second(_), b'P') => v.p = Some(length_in(n, grid, micro, 1, n_max, at)?),
            (Kind::Second(_), b'Q') => v.q = Some(length_in(n, grid, micro, 1, n_max, at)?),
            (Kind::Second(_), b'R') => v.r = Some(signed_length(n, grid, at)?),
            // G33: the start angle, integer 0.001°.
            (Kind::Thread(ThreadCode::G33), b'P') => {
                v.p = Some(integer_in(n, 0, MAX_START_ANGLE, Rule::G33, at)?);
            }
            // G34: the lead change per revolution, lead grid, signed.
            (Kind::Thread(ThreadCode::G34), b'K') => {
                v.k = Some(signed_lead(n, grid, max_lead(grid.units), Rule::G34, at)?);
            }
            // M was checked with the codes; N, O, S, T have no value rule.
            _ => {}
        }
        Ok(())
    }

    /// COM.ABSINC: the end point from X(U), Z(W): U and W are added to the position `from`; an
    /// omitted axis takes `kept`.
    fn end_point(v: &Vals, from: (i64, i64), kept: (i64, i64)) -> (i64, i64) {
        let x = match (v.x, v.u) {
            (Some(x), _) => x,
            (None, Some(u)) => sat(i128::from(from.0) + i128::from(u)),
            (None, None) => kept.0,
        };
        let z = match (v.z, v.w) {
            (Some(z), _) => z,
            (None, Some(w)) => sat(i128::from(from.1) + i128::from(w)),
            (None, None) => kept.1,
        };
        (x, z)
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

    /// NC201.XMODE: an X (or G162 W) word under nc201 as a diameter count, |v| ≤ N as written.
    fn x_word(&self, n: Number, at: At) -> Result<i64, Alarm> {
        let v = signed_length(n, self.config.grid, at)?;
        Ok(if self.params.x_radius == 1 { 2 * v } else { v })
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

    /// G92.MODAL, G92.FORMAT: a block in G92 mode or with G92.
    fn g92(&mut self, coded: bool, v: &Vals, axis: bool, line: u32, run: &mut Run) -> Result<(), Alarm> {
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
        if v.j.is_some() {
            st.j = v.j;
        }
        if v.k.is_some() {
            st.k = v.k;
        }
        if let Some(l) = v.l {
            st.starts = u32::try_from(l).unwrap_or(1);
        }
        if !axis {
            return Ok(());
        }
        // G92.MODAL: an omitted end coordinate is the run's.
        st.end = Self::end_point(v, self.pos, st.end);
        // (4) COM.LEAD: the lead.
        let Some(lead) = self.feed else {
            return Err(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line));
        };
        st.index = st.index.saturating_add(1);
        let st = *st;
        // A `match`, not `?`: `?` copies the cycle (~300 bytes) once more on its way out.
        match g92::cycle(&self.config, &self.params, &st, &mut self.g92_pull, self.pos, lead, line) {
            Ok(c) => *run = Run::Multipass(c),
            Err(a) => return Err(a),
        }
        Ok(())
    }

    /// G76.FORMAT: a first block replaces the kept values of its code; omitted words fall back
    /// to their defaults (G76.DEFAULTS, G78.MODE, G78.DEPTHMODE).
    fn first(&mut self, code: Code, v: &Vals) {
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
    fn second(&mut self, code: Code, v: &Vals, line: u32, run: &mut Run) -> Result<(), Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        let missing = |word: u8, rule: Rule| Alarm::new(AlarmCode::MissingWord, Some(word), rule, line);
        let lead = self.feed.ok_or(missing(b'F', Rule::ComLead))?;
        let k = v.p.ok_or(missing(b'P', Rule::G76Required))?;
        let dd = v.q.ok_or(missing(b'Q', Rule::G76Required))?;
        let sec = Second {
            d: Self::end_point(v, self.pos, self.pos),
            i: v.r.unwrap_or(0),
            k,
            dd,
            j: v.j,
            kk: v.k,
            lead,
        };
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

    /// (3) One word of a G162 block (docs/INTERPRETATION.md, "Block and words"): the word
    /// table's grids and ranges, each out-of-range value naming its rule.
    fn value_g162(&self, letter: u8, n: Number, at: At, v: &mut Vals) -> Result<(), Alarm> {
        let grid = self.config.grid;
        let length = |lo: i64| length_in(n, grid, false, lo, MAX_LENGTH, at);
        match letter {
            b'A' => v.a = Some(infeed_angle(n, at)?),
            b'B' => v.b = Some(scaled_in(n, 3, 0, 360_000, Rule::G162B, at)?),
            b'F' => v.lead = Some(lead_f(n, grid, at)?),
            b'H' => v.h = Some(scaled_in(n, grid.lead_decimals(), 1, MAX_LENGTH, Rule::G162H, at)?),
            b'I' => v.pitch_change = Some(signed_lead(n, grid, max_lead(grid.units), Rule::G162I, at)?),
            b'J' => v.j = Some(scaled_in(n, 3, 1, MAX_LENGTH, Rule::G162J, at)?),
            b'P' => v.p = Some(length(1)?),
            b'Q' => v.q = Some(length(1)?),
            b'V' => v.v = Some(length(0)?),
            // NC201.XMODE: the taper W in X units.
            b'W' => v.w = Some(self.x_word(n, at)?),
            b'X' => v.x = Some(self.x_word(n, at)?),
            b'Z' => v.z = Some(signed_length(n, grid, at)?),
            // M was checked with the codes; N, O, S, T have no value rule.
            _ => {}
        }
        Ok(())
    }

    /// G32, G33, G34 (PRJ.MODAL, M003): modal thread moves. (4) a block with axis words needs a
    /// lead (COM.LEAD), G34 its K (G34); (5) the G34 lead bound; then the thread move, if any.
    fn thread(
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
    fn cut(&mut self, code: CutCode, coded: bool, v: &Vals, axis: bool, line: u32, run: &mut Run) -> Result<(), Alarm> {
        if coded && self.mode != Mode::Cut(code) {
            self.cut.new_run(self.pos);
        }
        self.mode = Mode::Cut(code);
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        if let Some(t) = v.taper {
            self.cut.taper = t;
        }
        if !axis {
            return Ok(());
        }
        self.cut.end = Self::end_point(v, self.pos, self.cut.end);
        let Some(feed) = self.feed else {
            return Err(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line));
        };
        self.cut.index = self.cut.index.saturating_add(1);
        *run = Run::Cut(g90::cycle(code, &self.cut, self.pos, feed, line)?);
        Ok(())
    }

    /// G162.FORMAT: (4) missing words — F (G162.F), H (G162.H), P/Q as a pair (G162.PQ), X, Z
    /// (G162.FORMAT) — then the cycle's checks and the cycle. F sets the modal feed; without F
    /// the modal feed is the lead whatever it was set for (G162.F).
    fn g162(&mut self, v: &Vals, line: u32, run: &mut Run) -> Result<(), Alarm> {
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
}
