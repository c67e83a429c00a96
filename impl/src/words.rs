//! Word values: a written [`Number`] converted to an integer on its grid and checked against its
//! range (COM.UNITS, COM.RANGES, COM.LEAD, PRJ.DIALECT / F76.MICRONS). Each function names the
//! alarm of docs/INTERPRETATION.md, "Which alarm, exactly".

use crate::number::{Number, NumberError};
use cycle_vocab::{Alarm, AlarmCode, Grid, Rule, Units};

/// N: the largest length of any word or parameter, increments (COM.RANGES).
pub const MAX_LENGTH: i64 = 999_999_999;
/// G92 J and K: the largest magnitude, increments (COM.RANGES).
pub const MAX_G92_JK: i64 = 99_999_999;

/// Where a value error is reported: the word and the block's line.
#[derive(Clone, Copy, Debug)]
pub struct At {
    pub letter: u8,
    pub line: u32,
}

impl At {
    pub const fn alarm(self, code: AlarmCode, rule: Rule) -> Alarm {
        Alarm::new(code, Some(self.letter), rule, self.line)
    }

    /// OUT OF RANGE with the generic rule COM.RANGES.
    pub const fn out_of_range(self) -> Alarm {
        self.alarm(AlarmCode::OutOfRange, Rule::ComRanges)
    }
}

/// The alarm of a number that does not scale: `PRECISION` (COM.UNITS), `NOT INTEGER`
/// (COM.RANGES), or — a value beyond any machine word — `OUT OF RANGE` under `range`, the rule
/// that owns the word's range, as for any other value outside it (PRJ.LEX, "Values").
fn scale_error(e: NumberError, at: At, range: Rule) -> Alarm {
    match e {
        NumberError::Precision => at.alarm(AlarmCode::Precision, Rule::ComUnits),
        NumberError::Overflow => at.alarm(AlarmCode::OutOfRange, range),
        NumberError::NotInteger => at.alarm(AlarmCode::NotInteger, Rule::ComRanges),
    }
}

/// COM.UNITS: a length in increments of the grid. `increments` (F76.MICRONS: FANUC P/Q
/// without a decimal point) reads a number without a point as a count of increments.
pub fn length(n: Number, grid: Grid, increments: bool, at: At) -> Result<i64, Alarm> {
    let places = if increments && !n.point { 0 } else { grid.decimals() };
    n.scaled(places).map_err(|e| scale_error(e, at, Rule::ComRanges))
}

/// COM.RANGES: a length with `lo ≤ v ≤ hi`.
pub fn length_in(n: Number, grid: Grid, increments: bool, lo: i64, hi: i64, at: At) -> Result<i64, Alarm> {
    in_range(length(n, grid, increments, at)?, lo, hi, at)
}

/// COM.RANGES: `v` when `lo ≤ v ≤ hi`, else `OUT OF RANGE` at the word.
#[inline(always)]
fn in_range(v: i64, lo: i64, hi: i64, at: At) -> Result<i64, Alarm> {
    if v < lo || v > hi {
        return Err(at.out_of_range());
    }
    Ok(v)
}

/// COM.RANGES: a signed length |v| ≤ N (X, U, Z, W, R).
pub fn signed_length(n: Number, grid: Grid, at: At) -> Result<i64, Alarm> {
    signed_length_places(n, grid.decimals(), at)
}

/// [`signed_length`] with the grid's decimal places given (`grid.decimals()`, as [`length`]
/// takes them), for a caller that reads many blocks on one grid.
#[inline(always)]
pub fn signed_length_places(n: Number, places: u32, at: At) -> Result<i64, Alarm> {
    let v = n.scaled(places).map_err(|e| scale_error(e, at, Rule::ComRanges))?;
    in_range(v, -MAX_LENGTH, MAX_LENGTH, at)
}

/// COM.RANGES: an integer word (P of the first block, L, D) written without a decimal point
/// (`NOT INTEGER`, rule COM.RANGES) within `lo ≤ v ≤ hi` (`OUT OF RANGE` with `rule`, however
/// large the value).
pub fn integer_in(n: Number, lo: i64, hi: i64, rule: Rule, at: At) -> Result<i64, Alarm> {
    let v = n.integer().map_err(|e| scale_error(e, at, rule))?;
    if v < lo || v > hi {
        return Err(at.alarm(AlarmCode::OutOfRange, rule));
    }
    Ok(v)
}

/// A number on the grid of `places` decimals (`PRECISION` as [`length`]) within
/// `lo ≤ v ≤ hi`, else `OUT OF RANGE` with `rule`, beyond 64 bits too (G162 B, H, J).
pub fn scaled_in(n: Number, places: u32, lo: i64, hi: i64, rule: Rule, at: At) -> Result<i64, Alarm> {
    let v = n.scaled(places).map_err(|e| scale_error(e, at, rule))?;
    if v < lo || v > hi {
        return Err(at.alarm(AlarmCode::OutOfRange, rule));
    }
    Ok(v)
}

/// ARC.R: an arc's R, a length 1 … N — R ≤ 0 is `OUT OF RANGE` under ARC.R, R > N under
/// COM.RANGES (the generic range of a length, however large: docs/INTERPRETATION.md, "Arcs").
pub fn arc_radius(n: Number, grid: Grid, at: At) -> Result<i64, Alarm> {
    let rule = if n.negative { Rule::ArcR } else { Rule::ComRanges };
    let v = n.scaled(grid.decimals()).map_err(|e| scale_error(e, at, rule))?;
    if v < 1 {
        return Err(at.alarm(AlarmCode::OutOfRange, Rule::ArcR));
    }
    if v > MAX_LENGTH {
        return Err(at.out_of_range());
    }
    Ok(v)
}

/// A signed value on the lead grid with |v| ≤ `max`, else `OUT OF RANGE` with `rule` (G34 K,
/// G162 I).
pub fn signed_lead(n: Number, grid: Grid, max: i64, rule: Rule, at: At) -> Result<i64, Alarm> {
    scaled_in(n, grid.lead_decimals(), -max, max, rule, at)
}

/// G162.A: the infeed angle in tenths of a degree — any tenth (more decimals: `PRECISION`,
/// G162.A, as the register's word table says for A), then |A| ≤ 89° (else `OUT OF RANGE`,
/// G162.A).
pub fn infeed_angle(n: Number, at: At) -> Result<i64, Alarm> {
    let tenths = n.scaled(1).map_err(|e| match e {
        NumberError::Precision => at.alarm(AlarmCode::Precision, Rule::G162A),
        e => scale_error(e, at, Rule::G162A),
    })?;
    if tenths.unsigned_abs() > 890 {
        return Err(at.alarm(AlarmCode::OutOfRange, Rule::G162A));
    }
    Ok(tenths)
}

/// COM.LEAD: F as lead counts (0.0001 mm / 0.00001 in), 1 … 99 990 000 (metric) or
/// 1 … 999 000 (inch).
pub fn lead_f(n: Number, grid: Grid, at: At) -> Result<i64, Alarm> {
    let v = n.scaled(grid.lead_decimals()).map_err(|e| scale_error(e, at, Rule::ComRanges))?;
    let max = match grid.units {
        Units::Metric => 99_990_000,
        Units::Inch => 999_000,
    };
    if !(1..=max).contains(&v) {
        return Err(at.out_of_range());
    }
    Ok(v)
}

/// COM.LEAD: I (threads per inch, at most 4 decimals, 0.0001 … 254 metric / 0.0001 … 100 inch)
/// as a lead, rounded once half up to the lead grid: 25.4/I mm or 1/I in.
pub fn lead_i(n: Number, grid: Grid, at: At) -> Result<i64, Alarm> {
    let tpi = n.scaled(4).map_err(|e| scale_error(e, at, Rule::ComRanges))?; // threads per 10 000 inches
    let (max, inch_in_counts) = match grid.units {
        // 25.4 mm = 254 000 counts of 0.0001 mm; ×10^4 for I in 0.0001 threads per inch.
        Units::Metric => (2_540_000, 2_540_000_000u128),
        // 1 in = 100 000 counts of 0.00001 in; ×10^4.
        Units::Inch => (1_000_000, 1_000_000_000u128),
    };
    if !(1..=max).contains(&tpi) {
        return Err(at.out_of_range());
    }
    let lead = crate::fixed::div_round(inch_in_counts, u128::from(tpi.unsigned_abs()));
    // lead ≤ 2.54·10^9 fits i64.
    Ok(i64::try_from(lead).unwrap_or(i64::MAX))
}

#[cfg(test)]
mod tests;
