//! Step (3) of the check order: each word's value for a block of its kind (COM.RANGES,
//! COM.UNITS, COM.LEAD, F76.MICRONS, G76.MODE, G78.MODE, G78.DEPTHMODE, G76.FINISH, F76.FORMAT,
//! NC201.XMODE, the G162 word table, G33, G34, G90.FORMAT, G94.FORMAT).

use super::{Kind, Machine, Vals};
use crate::config::FANUC_ANGLES;
use crate::g162::max_lead;
use crate::g90::CutCode;
use crate::multipass::Code;
use crate::rough::Axis;
use crate::number::Number;
use crate::thread_move::{ThreadCode, MAX_START_ANGLE};
use crate::words::{
    arc_radius, infeed_angle, integer_in, lead_f, lead_i, length_in, scaled_in, signed_length, signed_lead, At, MAX_G92_JK, MAX_LENGTH,
};
use cycle_vocab::{Alarm, AlarmCode, Dialect, Rule};

impl Machine {
    /// (3) One word's value for a block of `kind` (COM.RANGES, COM.UNITS, COM.LEAD,
    /// F76.MICRONS, G76.MODE, G78.MODE, G78.DEPTHMODE, G76.FINISH, F76.FORMAT).
    pub(super) fn value(&self, kind: Kind, letter: u8, n: Number, at: At, v: &mut Vals) -> Result<(), Alarm> {
        let grid = self.config.grid;
        // F76.MICRONS: FANUC G76 P(k), Q(Δd), Q(Δdmin) without a decimal point are increments.
        let micro = self.config.dialect == Dialect::Fanuc;
        let n_max = MAX_LENGTH;
        let n_len = |lo: i64, rule: Rule| scaled_in(n, grid.decimals(), lo, MAX_LENGTH, rule, at);
        // G50.SMAX, COM.RANGES: S in every kind of block under gsk and fanuc (under nc201 the
        // section "Spindle speed" does not apply: S takes any number, PRJ.LEX "What the words
        // mean").
        if letter == b'S' && self.config.dialect != Dialect::Nc201 {
            return self.speed_word(kind == Kind::G50, n, at);
        }
        if kind == Kind::G162 {
            return self.value_g162(letter, n, at, v);
        }
        match (kind, letter) {
            (_, b'F') => v.lead = Some(lead_f(n, grid, at)?),
            // ARC.FORMAT: I (radius) and K signed lengths; ARC.R: R a length 1 … N (R ≤ 0
            // under ARC.R, R > N under COM.RANGES).
            (Kind::Arc(_), b'I') => v.i = Some(signed_length(n, grid, at)?),
            (Kind::Arc(_), b'K') => v.k = Some(signed_length(n, grid, at)?),
            (Kind::Arc(_), b'R') => v.r = Some(arc_radius(n, grid, at)?),
            // CNT.PQ: sequence numbers, integers 1 … 99 999.
            (Kind::G70 | Kind::RoughSecond(_), b'P') => v.p = Some(integer_in(n, 1, 99_999, Rule::CntPq, at)?),
            (Kind::G70 | Kind::RoughSecond(_), b'Q') => v.q = Some(integer_in(n, 1, 99_999, Rule::CntPq, at)?),
            // G71.DEPTH, G71.RETRACT, G72.DEPTH: Δd 1 … N, e 0 … N.
            (Kind::RoughFirst(Axis::G71), b'U') => v.depth = Some(n_len(1, Rule::G71Depth)?),
            (Kind::RoughFirst(Axis::G71), b'R') => v.r = Some(n_len(0, Rule::G71Retract)?),
            (Kind::RoughFirst(Axis::G72), b'W') => v.depth = Some(n_len(1, Rule::G72Depth)?),
            (Kind::RoughFirst(Axis::G72), b'R') => v.r = Some(n_len(0, Rule::G72Depth)?),
            // G74.FORMAT, G75.FORMAT (G74.UNITS): e, Δd, P (Δi), Q (Δk) unsigned lengths 0 … N,
            // mm without a decimal point in every dialect.
            (Kind::PeckFirst(_) | Kind::PeckSecond(_), b'R') => v.r = Some(n_len(0, Rule::ComRanges)?),
            (Kind::PeckSecond(_), b'P') => v.p = Some(n_len(0, Rule::ComRanges)?),
            (Kind::PeckSecond(_), b'Q') => v.q = Some(n_len(0, Rule::ComRanges)?),
            // G73.FORMAT, G73.COUNT: d (R of the first block, D of format (b)) an integer ≥ 1;
            // format (b)'s I (Δi, radius) and K signed lengths; P, Q sequence numbers.
            (Kind::PatternFirst, b'R') => v.r = Some(integer_in(n, 1, MAX_LENGTH, Rule::G73Count, at)?),
            (Kind::PatternSecond(_), b'D') => v.d = Some(integer_in(n, 1, MAX_LENGTH, Rule::G73Count, at)?),
            (Kind::PatternSecond(_), b'I') => v.i = Some(signed_length(n, grid, at)?),
            (Kind::PatternSecond(_), b'K') => v.k = Some(signed_length(n, grid, at)?),
            (Kind::PatternSecond(_), b'P') => v.p = Some(integer_in(n, 1, 99_999, Rule::CntPq, at)?),
            (Kind::PatternSecond(_), b'Q') => v.q = Some(integer_in(n, 1, 99_999, Rule::CntPq, at)?),
            // G83/G84: R a signed length; Q (G83) the peck in increments, an integer 0 … N
            // (0: one feed); P the dwell in ms, an integer 0 … 99 999 999.
            (Kind::G83 | Kind::G84, b'R') => v.r = Some(signed_length(n, grid, at)?),
            (Kind::G83, b'Q') => v.q = Some(integer_in(n, 0, MAX_LENGTH, Rule::ComRanges, at)?),
            (Kind::G83 | Kind::G84, b'P') => v.p = Some(integer_in(n, 0, 99_999_999, Rule::ComRanges, at)?),
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

    /// NC201.XMODE: an X (or G162 W) word under nc201 as a diameter count, |v| ≤ N as written.
    pub(super) fn x_word(&self, n: Number, at: At) -> Result<i64, Alarm> {
        let v = signed_length(n, self.config.grid, at)?;
        Ok(if self.params.x_radius == 1 { 2 * v } else { v })
    }
}
