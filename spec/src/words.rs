//! Word → value (COM.UNITS, COM.RANGES, COM.LEAD, PRJ.DIALECT, F76.MICRONS).
//!
//! Every function takes a [`Number`] exactly as written (the spec's own reader, [`crate::lex`])
//! and returns an integer on its grid, or the alarm the register names (docs/INTERPRETATION.md,
//! "Values (check step 3)", "Numbers, units, grid" and "Ranges"). The arithmetic is exact
//! (BigInt): a value is out of range under its word's own rule however large it is.

use crate::lex::Number;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Grid, Rule, Units};
use num_bigint::BigInt;
use num_traits::{ToPrimitive, Zero};

/// N = 999 999 999 increments: the nine-digit range of every length word (COM.RANGES).
pub const N: i64 = 999_999_999;
/// G92 J and K: |v| ≤ 99 999 999 increments (COM.RANGES, M002).
pub const JK_MAX: i64 = 99_999_999;

/// An alarm on `word` at `line`.
pub fn alarm(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Alarm {
    Alarm::new(code, Some(word), rule, line)
}

fn pow10(n: u32) -> BigInt {
    num_traits::pow(BigInt::from(10), n as usize)
}

/// COM.UNITS (M000, M001): the value as a whole count of 10^−`p`. More decimals than that,
/// unless they are zeros, is `PRECISION` (never a rounding).
pub fn count(n: &Number, p: u32, word: u8, line: u32) -> Result<BigInt, Alarm> {
    let m = n.mantissa();
    if n.decimals <= p {
        return Ok(m * pow10(p - n.decimals));
    }
    let unit = pow10(n.decimals - p);
    if (&m % &unit).is_zero() {
        Ok(m / unit)
    } else {
        Err(alarm(AlarmCode::Precision, word, Rule::ComUnits, line))
    }
}

/// COM.RANGES: an integer word must be written without a decimal point, else `NOT INTEGER`.
pub fn whole(n: &Number, word: u8, line: u32) -> Result<BigInt, Alarm> {
    if n.point {
        Err(alarm(AlarmCode::NotInteger, word, Rule::ComRanges, line))
    } else {
        Ok(n.mantissa())
    }
}

/// COM.RANGES (M000, M001, M002): `lo ≤ v ≤ hi`, else `OUT OF RANGE` under `rule` however large
/// `v` is; never a clamp.
pub fn in_range(v: &BigInt, lo: i64, hi: i64, word: u8, rule: Rule, line: u32) -> Result<i64, Alarm> {
    match v.to_i64() {
        Some(v) if (lo..=hi).contains(&v) => Ok(v),
        _ => Err(alarm(AlarmCode::OutOfRange, word, rule, line)),
    }
}

/// COM.UNITS + COM.RANGES: a length word as a count of the least increment (a value without a
/// decimal point is in mm / inch, PRJ.DIALECT), in `lo…hi`.
pub fn length(n: &Number, word: u8, grid: Grid, lo: i64, hi: i64, line: u32) -> Result<i64, Alarm> {
    let v = count(n, grid.decimals(), word, line)?;
    in_range(&v, lo, hi, word, Rule::ComRanges, line)
}

/// F76.MICRONS (M003), PRJ.DIALECT: G76 P(k), Q(Δd), Q(Δdmin). Under `fanuc`, written without a
/// decimal point they are integers in the least increment; otherwise they are lengths.
pub fn micron_length(n: &Number, word: u8, config: &Config, lo: i64, hi: i64, line: u32) -> Result<i64, Alarm> {
    if config.dialect == Dialect::Fanuc && !n.point {
        in_range(&n.mantissa(), lo, hi, word, Rule::ComRanges, line)
    } else {
        length(n, word, config.grid, lo, hi, line)
    }
}

/// COM.RANGES: a count or digit word (L, P of the first block, D, G33 P), written without a
/// decimal point (`NOT INTEGER`), in `lo…hi` (`OUT OF RANGE` under `rule`).
pub fn integer(n: &Number, word: u8, lo: i64, hi: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = whole(n, word, line)?;
    in_range(&v, lo, hi, word, rule, line)
}

/// COM.LEAD (M001, M002): F is the lead, an integer count of 0.0001 mm (metric) or 0.00001 in
/// (inch) in both increment systems; range 0.0001…9999 mm / 0.00001…9.99 in.
pub fn lead_from_f(n: &Number, grid: Grid, line: u32) -> Result<i64, Alarm> {
    let v = count(n, grid.lead_decimals(), b'F', line)?;
    in_range(&v, 1, lead_max(grid), b'F', Rule::ComRanges, line)
}

/// COM.LEAD (M001, M002): I is threads per inch (0.0001…254 metric, 0.0001…100 inch, at most 4
/// decimals); it becomes a lead once, rounded half up to the lead grid: metric 25.4/I mm =
/// 2 540 000 000 / I₄ counts of 0.0001 mm, inch 1/I in = 1 000 000 000 / I₄ counts of
/// 0.00001 in, where I₄ is I in 0.0001 threads per inch.
pub fn lead_from_i(n: &Number, grid: Grid, line: u32) -> Result<i64, Alarm> {
    let i4 = count(n, 4, b'I', line)?;
    let (max, numerator) = match grid.units {
        Units::Metric => (254 * 10_000, 2_540_000_000i128),
        Units::Inch => (100 * 10_000, 1_000_000_000i128),
    };
    let i4 = in_range(&i4, 1, max, b'I', Rule::ComRanges, line)?;
    let lead = crate::exact::round_div(numerator, i4 as i128);
    Ok(lead as i64)
}

/// COM.LEAD (M001, M002): the largest lead, lead counts: 9999 mm (metric), 9.99 in (inch).
pub fn lead_max(grid: Grid) -> i64 {
    match grid.units {
        Units::Metric => 99_990_000,
        Units::Inch => 999_000,
    }
}

/// A signed value on the lead grid (G162 I, G34 K, docs/INTERPRETATION.md): `|v| ≤ max`, else
/// `OUT OF RANGE` under `rule`.
pub fn signed_lead(n: &Number, word: u8, grid: Grid, max: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = count(n, grid.lead_decimals(), word, line)?;
    in_range(&v, -max, max, word, rule, line)
}

/// A feed on the lead grid (G162.H): `1 ≤ v ≤ hi`, else `OUT OF RANGE` under `rule`.
pub fn feed(n: &Number, word: u8, grid: Grid, hi: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = count(n, grid.lead_decimals(), word, line)?;
    in_range(&v, 1, hi, word, rule, line)
}

/// An angle in degrees on the 0.001° grid (G162 B, J): `lo ≤ v ≤ hi` in 0.001°, else
/// `OUT OF RANGE` under `rule`.
pub fn millidegrees(n: &Number, word: u8, lo: i64, hi: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = count(n, 3, word, line)?;
    in_range(&v, lo, hi, word, rule, line)
}

/// G162.A (M004, docs/INTERPRETATION.md "A" row of the word table): the infeed angle in tenths
/// of a degree, any tenth legal. More than one decimal (`A27.35`) is `PRECISION` on A, rule
/// G162.A; then |A| > 89° is `OUT OF RANGE` on A, rule G162.A.
pub fn tenths_of_degree(n: &Number, word: u8, line: u32) -> Result<i64, Alarm> {
    let tenths = count(n, 1, word, line).map_err(|_| alarm(AlarmCode::Precision, word, Rule::G162A, line))?;
    in_range(&tenths, -890, 890, word, Rule::G162A, line)
}

/// How a word's value is read (check step 3): each family's word table names one per word.
#[derive(Clone, Copy, Debug)]
pub enum Read {
    /// A length on the grid in `lo…hi` increments (COM.UNITS, COM.RANGES).
    Length { lo: i64, hi: i64 },
    /// A length on the grid in `lo…hi` increments whose range a cycle rule owns (G71.DEPTH).
    RuledLength { lo: i64, hi: i64, rule: Rule },
    /// A signed length in X units, |v| ≤ N: a diameter, or under `nc201` with `x_radius` = 1 a
    /// radius counted twice (NC201.XMODE).
    XLength,
    /// A length, or under `fanuc` without a point an integer count of increments (F76.MICRONS).
    Microns { lo: i64, hi: i64 },
    /// F, the lead / feed (COM.LEAD).
    Lead,
    /// I, threads per inch, as a lead (COM.LEAD).
    ThreadsPerInch,
    /// An integer without a point in `lo…hi`, out of range under `rule`.
    Integer { lo: i64, hi: i64, rule: Rule },
    /// A signed value on the lead grid, |v| ≤ the F maximum, out of range under `rule`.
    SignedLead { rule: Rule },
    /// A feed on the lead grid in 1…`hi`, out of range under `rule`.
    Feed { hi: i64, rule: Rule },
    /// Degrees on the 0.001° grid in `lo…hi`, out of range under `rule`.
    Millidegrees { lo: i64, hi: i64, rule: Rule },
    /// G162.A: degrees on the 0.1° grid, in tenths.
    Tenths,
    /// A reader of the family's own (e.g. the digits of P(m)(r)(a)).
    Own(fn(&Number, u8, &Config, u32) -> Result<i64, Alarm>),
}

impl Read {
    /// The value of `n`, written as word `letter` on `line`, under `config`.
    pub fn value(self, n: &Number, letter: u8, config: &Config, line: u32) -> Result<i64, Alarm> {
        let grid = config.grid;
        match self {
            Read::Length { lo, hi } => length(n, letter, grid, lo, hi, line),
            Read::RuledLength { lo, hi, rule } => {
                let v = count(n, grid.decimals(), letter, line)?;
                in_range(&v, lo, hi, letter, rule, line)
            }
            Read::XLength => length(n, letter, grid, -N, N, line).map(|v| x_units(v, config)),
            Read::Microns { lo, hi } => micron_length(n, letter, config, lo, hi, line),
            Read::Lead => lead_from_f(n, grid, line),
            Read::ThreadsPerInch => lead_from_i(n, grid, line),
            Read::Integer { lo, hi, rule } => integer(n, letter, lo, hi, rule, line),
            Read::SignedLead { rule } => signed_lead(n, letter, grid, lead_max(grid), rule, line),
            Read::Feed { hi, rule } => feed(n, letter, grid, hi, rule, line),
            Read::Millidegrees { lo, hi, rule } => millidegrees(n, letter, lo, hi, rule, line),
            Read::Tenths => tenths_of_degree(n, letter, line),
            Read::Own(read) => read(n, letter, config, line),
        }
    }
}

/// NC201.XMODE (M004): under `nc201` with `x_radius` = 1 an X or W word is a radius, counted
/// twice on the diameter grid; otherwise the value is already a diameter.
pub fn x_units(v: i64, config: &Config) -> i64 {
    if config.dialect == Dialect::Nc201 && crate::config::params(config).x_radius == 1 {
        2 * v
    } else {
        v
    }
}

/// Common word tables: the axis words X U Z W and F as everywhere (COM.ABSINC, COM.LEAD).
pub const X: (u8, Read) = (b'X', Read::XLength);
pub const U: (u8, Read) = (b'U', Read::Length { lo: -N, hi: N });
pub const Z: (u8, Read) = (b'Z', Read::Length { lo: -N, hi: N });
pub const W: (u8, Read) = (b'W', Read::Length { lo: -N, hi: N });
pub const F: (u8, Read) = (b'F', Read::Lead);
/// I as threads per inch (thread blocks, COM.LEAD).
pub const I_TPI: (u8, Read) = (b'I', Read::ThreadsPerInch);

#[cfg(test)]
mod tests;
