//! The modal interpreter (PRJ.MODAL, PRJ.WORD, PRJ.SUPPORTED, COM.ABSINC, COM.LEAD): one block
//! in, at most one action out, with the check order of docs/INTERPRETATION.md — (2) G and M
//! codes, conflicts, allowed words alphabetically; (3) values alphabetically; (4) missing words;
//! (5) the cycle's own checks.

use crate::emit::Cycle;
use crate::g92::{self, G92State};
use crate::multipass::{self, Code, FirstBlock, Second};
use crate::words::{integer_in, lead_f, lead_i, length_in, signed_length, At, MAX_G92_JK};
use cycle_vocab::params::MAX_LENGTH;
use cycle_vocab::{Alarm, AlarmCode, Block, Config, Dialect, Move, Rule, Units};

/// The modal motion mode.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    Rapid,
    Feed,
    G92,
}

/// What a block asks of the expander.
// No heap: the cycle state is moved once into the expander; boxing is not an option.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Copy, Debug)]
pub enum Action {
    Nothing,
    Move(Move),
    Cycle(Cycle),
}

/// How the block's words are read (its code, or the modal mode).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Rapid,
    Feed,
    G92,
    First(Code),
    Second(Code),
}

/// The machine state carried from block to block.
#[derive(Clone, Copy, Debug)]
pub struct Machine {
    pub config: Config,
    /// Current position: X diameter, Z.
    pub pos: (i64, i64),
    mode: Mode,
    /// Modal feed / lead, lead counts (COM.LEAD).
    feed: Option<i64>,
    g92: G92State,
    g76: FirstBlock,
    g78: FirstBlock,
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
}

/// Words every block accepts (no motion effect).
const COMMON: &[u8] = b"MNOST";

/// PRJ.WORD, PRJ.DIALECT: the words a block of `kind` accepts besides G and [`COMMON`].
fn allowed(kind: Kind, dialect: Dialect) -> &'static [u8] {
    match (kind, dialect) {
        (Kind::Rapid | Kind::Feed, _) => b"FUWXZ",
        (Kind::G92, _) => b"FIJKLRUWXZ",
        (Kind::First(_), Dialect::Fanuc) => b"PQR",
        (Kind::First(_), Dialect::Gsk | Dialect::Nc201) => b"DELPQR",
        (Kind::Second(_), Dialect::Fanuc) => b"FIPQRUWXZ",
        (Kind::Second(_), Dialect::Gsk | Dialect::Nc201) => b"FIJKPQRUWXZ",
    }
}

/// FANUC tool angles (F76.FORMAT).
pub const FANUC_ANGLES: [u32; 6] = [80, 60, 55, 30, 29, 0];

fn sat(v: i128) -> i64 {
    i64::try_from(v).unwrap_or(if v < 0 { i64::MIN } else { i64::MAX })
}

impl Machine {
    pub fn new(config: Config) -> Machine {
        Machine {
            config,
            pos: (config.start_x, config.start_z),
            mode: Mode::Rapid,
            feed: None,
            g92: G92State::new(),
            g76: FirstBlock::defaults(&config, Code::G76),
            g78: FirstBlock::defaults(&config, Code::G78),
        }
    }

    /// Reads one block; returns its action and whether it ends the program (M02, M30).
    pub fn block(&mut self, b: &Block) -> Result<(Action, bool), Alarm> {
        let line = b.line;
        let at = |letter: u8| At { letter, line };
        let (motion, end) = self.codes(b)?;
        // (2) conflicts: X/U, Z/W, F/I (the two-motion-code conflict is found in `codes`).
        for (first, second, rule) in
            [(b'X', b'U', Rule::ComAbsInc), (b'Z', b'W', Rule::ComAbsInc), (b'F', b'I', Rule::ComLead)]
        {
            if b.has(first) && b.has(second) {
                return Err(at(second).alarm(AlarmCode::Conflict, rule));
            }
        }
        let axis = b.has(b'X') || b.has(b'U') || b.has(b'Z') || b.has(b'W');
        let kind = match motion {
            Some(76) if axis => Kind::Second(Code::G76),
            Some(76) => Kind::First(Code::G76),
            Some(78) if axis => Kind::Second(Code::G78),
            Some(78) => Kind::First(Code::G78),
            Some(92) => Kind::G92,
            Some(1) => Kind::Feed,
            Some(_) => Kind::Rapid,
            None => match self.mode {
                Mode::Rapid => Kind::Rapid,
                Mode::Feed => Kind::Feed,
                Mode::G92 => Kind::G92,
            },
        };
        // (2) allowed words, alphabetically.
        let ok = allowed(kind, self.config.dialect);
        if let Some(l) = b.letters().find(|l| !ok.contains(l) && !COMMON.contains(l)) {
            // A GSK word that F76.FORMAT leaves out is refused by that format; any other by PRJ.WORD.
            let gsk_only = allowed(kind, Dialect::Gsk).contains(&l);
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
        // (4), (5) and the action.
        let action = match kind {
            Kind::Rapid | Kind::Feed => self.linear(kind, motion.is_some(), &v, axis, line)?,
            Kind::G92 => self.g92(motion.is_some(), &v, axis, line)?,
            Kind::First(code) => {
                self.first(code, &v);
                Action::Nothing
            }
            Kind::Second(code) => self.second(code, &v, line)?,
        };
        Ok((action, end))
    }

    /// (2) PRJ.SUPPORTED, COM.UNITS, PRJ.WORD: the G codes in the order written, then M; the
    /// block's motion/cycle code and whether it ends the program.
    fn codes(&self, b: &Block) -> Result<(Option<u64>, bool), Alarm> {
        let line = b.line;
        let g_alarm = |code: AlarmCode, rule: Rule| Alarm::new(code, Some(b'G'), rule, line);
        let mut motion = None;
        let mut motions = 0u32;
        for g in b.g_codes() {
            if g.point || g.negative {
                return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjSupported));
            }
            match g.mantissa {
                0 | 1 | 92 | 76 => {}
                78 if self.config.dialect == Dialect::Gsk => {}
                78 => return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjDialect)),
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
        Ok((motion, end))
    }

    /// (3) One word's value for a block of `kind` (COM.RANGES, COM.UNITS, COM.LEAD,
    /// F76.MICRONS, G76.MODE, G78.MODE, G78.DEPTHMODE, G76.FINISH, F76.FORMAT).
    fn value(&self, kind: Kind, letter: u8, n: cycle_vocab::Number, at: At, v: &mut Vals) -> Result<(), Alarm> {
        let grid = self.config.grid;
        // F76.MICRONS: FANUC G76 P(k), Q(Δd), Q(Δdmin) without a decimal point are increments.
        let micro = self.config.dialect == Dialect::Fanuc;
        let n_max = MAX_LENGTH;
        match (kind, letter) {
            (_, b'F') => v.lead = Some(lead_f(n, grid, at)?),
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

    /// PRJ.MODAL: G00 / G01 blocks (and non-motion blocks in those modes).
    fn linear(&mut self, kind: Kind, coded: bool, v: &Vals, axis: bool, line: u32) -> Result<Action, Alarm> {
        if let Some(f) = v.lead {
            self.feed = Some(f);
        }
        if coded {
            self.mode = if kind == Kind::Feed { Mode::Feed } else { Mode::Rapid };
        }
        if !axis {
            return Ok(Action::Nothing);
        }
        let (x, z) = Self::end_point(v, self.pos, self.pos);
        if kind == Kind::Feed {
            // COM.LEAD: G01 with axis words needs a feed.
            let Some(f) = self.feed else {
                return Err(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line));
            };
            return Ok(Action::Move(Move::feed(x, z, f, Rule::PrjModal)));
        }
        Ok(Action::Move(Move::rapid(x, z, Rule::PrjModal)))
    }

    /// G92.MODAL, G92.FORMAT: a block in G92 mode or with G92.
    fn g92(&mut self, coded: bool, v: &Vals, axis: bool, line: u32) -> Result<Action, Alarm> {
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
            return Ok(Action::Nothing);
        }
        // G92.MODAL: an omitted end coordinate is the run's.
        st.end = Self::end_point(v, self.pos, st.end);
        // (4) COM.LEAD: the lead.
        let Some(lead) = self.feed else {
            return Err(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, line));
        };
        st.index = st.index.saturating_add(1);
        let st = *st;
        Ok(Action::Cycle(g92::cycle(&self.config, &st, self.pos, lead, line)?))
    }

    /// G76.FORMAT: a first block replaces the kept values of its code; omitted words fall back
    /// to their defaults (G76.DEFAULTS, G78.MODE, G78.DEPTHMODE).
    fn first(&mut self, code: Code, v: &Vals) {
        let mut f = FirstBlock::defaults(&self.config, code);
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
    fn second(&mut self, code: Code, v: &Vals, line: u32) -> Result<Action, Alarm> {
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
        Ok(Action::Cycle(multipass::cycle(&self.config, code, first, self.pos, &sec, line)?))
    }
}
