//! Word → value (COM.UNITS, COM.RANGES, COM.LEAD, PRJ.DIALECT, F76.MICRONS).
//!
//! Every function takes a [`Number`] exactly as written and returns an integer on its grid, or
//! the alarm the register names (docs/INTERPRETATION.md, "Numbers, units, grid" and "Ranges").

use cycle_vocab::units::NumberError;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Grid, Number, Rule, Units};

/// N = 999 999 999 increments: the nine-digit range of every length word (COM.RANGES).
pub const N: i64 = 999_999_999;
/// G92 J and K: |v| ≤ 99 999 999 increments (COM.RANGES, M002).
pub const JK_MAX: i64 = 99_999_999;

/// An alarm on `word` at `line`.
pub fn alarm(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Alarm {
    Alarm::new(code, Some(word), rule, line)
}

/// COM.UNITS (M000, M001) / COM.RANGES: a number that does not fit its grid. More decimals than
/// the grid is `PRECISION` (never a rounding); too large is `OUT OF RANGE`; a decimal point in an
/// integer word is `NOT INTEGER`.
fn number_alarm(e: NumberError, word: u8, line: u32) -> Alarm {
    match e {
        NumberError::Precision => alarm(AlarmCode::Precision, word, Rule::ComUnits, line),
        NumberError::Overflow => alarm(AlarmCode::OutOfRange, word, Rule::ComRanges, line),
        NumberError::NotInteger => alarm(AlarmCode::NotInteger, word, Rule::ComRanges, line),
    }
}

/// COM.RANGES (M000, M001, M002): `lo ≤ v ≤ hi`, else `OUT OF RANGE` under `rule`; never a clamp.
pub fn within(v: i64, lo: i64, hi: i64, word: u8, rule: Rule, line: u32) -> Result<i64, Alarm> {
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(alarm(AlarmCode::OutOfRange, word, rule, line))
    }
}

/// COM.UNITS + COM.RANGES: a length word as a count of the least increment (a value without a
/// decimal point is in mm / inch, PRJ.DIALECT), in `lo…hi`.
pub fn length(n: Number, word: u8, grid: Grid, lo: i64, hi: i64, line: u32) -> Result<i64, Alarm> {
    let v = n.scaled(grid.decimals()).map_err(|e| number_alarm(e, word, line))?;
    within(v, lo, hi, word, Rule::ComRanges, line)
}

/// F76.MICRONS (M003), PRJ.DIALECT: G76 P(k), Q(Δd), Q(Δdmin). Under `fanuc`, written without a
/// decimal point they are integers in the least increment; otherwise they are lengths.
pub fn micron_length(n: Number, word: u8, config: &Config, lo: i64, hi: i64, line: u32) -> Result<i64, Alarm> {
    if config.dialect == Dialect::Fanuc && !n.point {
        let v = n.integer().map_err(|e| number_alarm(e, word, line))?;
        within(v, lo, hi, word, Rule::ComRanges, line)
    } else {
        length(n, word, config.grid, lo, hi, line)
    }
}

/// COM.RANGES: a count or digit word (L, P of the first block, D), written without a decimal
/// point (`NOT INTEGER`), in `lo…hi` (`OUT OF RANGE` under `rule`).
pub fn integer(n: Number, word: u8, lo: i64, hi: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = n.integer().map_err(|e| number_alarm(e, word, line))?;
    within(v, lo, hi, word, rule, line)
}

/// COM.LEAD (M001, M002): F is the lead, an integer count of 0.0001 mm (metric) or 0.00001 in
/// (inch) in both increment systems; range 0.0001…9999 mm / 0.00001…9.99 in.
pub fn lead_from_f(n: Number, grid: Grid, line: u32) -> Result<i64, Alarm> {
    let v = n.scaled(grid.lead_decimals()).map_err(|e| number_alarm(e, b'F', line))?;
    within(v, 1, lead_max(grid), b'F', Rule::ComRanges, line)
}

/// COM.LEAD (M001, M002): I is threads per inch (0.0001…254 metric, 0.0001…100 inch, at most 4
/// decimals); it becomes a lead once, rounded half up to the lead grid: metric 25.4/I mm =
/// 2 540 000 000 / I₄ counts of 0.0001 mm, inch 1/I in = 1 000 000 000 / I₄ counts of
/// 0.00001 in, where I₄ is I in 0.0001 threads per inch.
pub fn lead_from_i(n: Number, grid: Grid, line: u32) -> Result<i64, Alarm> {
    let i4 = n.scaled(4).map_err(|e| number_alarm(e, b'I', line))?;
    let (max, numerator) = match grid.units {
        Units::Metric => (254 * 10_000, 2_540_000_000i128),
        Units::Inch => (100 * 10_000, 1_000_000_000i128),
    };
    let i4 = within(i4, 1, max, b'I', Rule::ComRanges, line)?;
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
pub fn signed_lead(n: Number, word: u8, grid: Grid, max: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = n.scaled(grid.lead_decimals()).map_err(|e| number_alarm(e, word, line))?;
    within(v, -max, max, word, rule, line)
}

/// A feed on the lead grid (G162.H): `1 ≤ v ≤ hi`, else `OUT OF RANGE` under `rule`.
pub fn feed(n: Number, word: u8, grid: Grid, hi: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = n.scaled(grid.lead_decimals()).map_err(|e| number_alarm(e, word, line))?;
    within(v, 1, hi, word, rule, line)
}

/// An angle in degrees on the 0.001° grid (G162 B, J): `lo ≤ v ≤ hi` in 0.001°, else
/// `OUT OF RANGE` under `rule`.
pub fn millidegrees(n: Number, word: u8, lo: i64, hi: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    let v = n.scaled(3).map_err(|e| number_alarm(e, word, line))?;
    within(v, lo, hi, word, rule, line)
}

/// G162.A (M004, docs/INTERPRETATION.md): the infeed angle in half degrees. Read on the 0.1°
/// grid (generic number errors); a value that is not a multiple of 0.5° is `PRECISION` on A,
/// rule G162.A; |A| > 89° is `OUT OF RANGE` on A, rule G162.A.
pub fn half_degrees(n: Number, word: u8, line: u32) -> Result<i64, Alarm> {
    let tenths = n.scaled(1).map_err(|e| number_alarm(e, word, line))?;
    if tenths % 5 != 0 {
        return Err(alarm(AlarmCode::Precision, word, Rule::G162A, line));
    }
    within(tenths, -890, 890, word, Rule::G162A, line).map(|t| t / 5)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn num(s: &str) -> Number {
        let src = format!("X{s}");
        match cycle_vocab::Blocks::new(src.as_bytes()).next() {
            Some(Ok(b)) => b.get(b'X').expect("X"),
            _ => panic!("bad test number {s}"),
        }
    }

    #[test]
    fn lengths_and_leads() {
        let g = Grid::METRIC_ISB;
        assert_eq!(length(num("58.7"), b'X', g, -N, N, 1), Ok(58_700));
        assert_eq!(length(num("60"), b'X', g, -N, N, 1), Ok(60_000));
        assert_eq!(
            length(num("58.7001"), b'X', g, -N, N, 1),
            Err(alarm(AlarmCode::Precision, b'X', Rule::ComUnits, 1))
        );
        assert_eq!(
            length(num("1000000"), b'X', g, -N, N, 1),
            Err(alarm(AlarmCode::OutOfRange, b'X', Rule::ComRanges, 1))
        );
        assert_eq!(lead_from_f(num("3"), g, 1), Ok(30_000));
        assert_eq!(lead_from_i(num("24"), g, 1), Ok(10_583)); // 25.4/24 = 1.05833
        assert_eq!(lead_from_i(num("254"), g, 1), Ok(1_000));
        let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
        assert_eq!(micron_length(num("2400"), b'P', &fanuc, 1, N, 1), Ok(2_400));
        assert_eq!(micron_length(num("2.4"), b'P', &fanuc, 1, N, 1), Ok(2_400));
        assert_eq!(micron_length(num("2400"), b'P', &Config::default(), 1, N, 1), Ok(2_400_000));
    }

    #[test]
    fn g162_angles_feeds_and_signed_leads() {
        let g = Grid::METRIC_ISB;
        assert_eq!(half_degrees(num("27.5"), b'A', 1), Ok(55));
        assert_eq!(half_degrees(num("-30"), b'A', 1), Ok(-60));
        assert_eq!(half_degrees(num("30.00"), b'A', 1), Ok(60));
        assert_eq!(half_degrees(num("27.3"), b'A', 1), Err(alarm(AlarmCode::Precision, b'A', Rule::G162A, 1)));
        assert_eq!(half_degrees(num("27.25"), b'A', 1), Err(alarm(AlarmCode::Precision, b'A', Rule::ComUnits, 1)));
        assert_eq!(half_degrees(num("89.5"), b'A', 1), Err(alarm(AlarmCode::OutOfRange, b'A', Rule::G162A, 1)));
        assert_eq!(millidegrees(num("90.5"), b'B', 0, 360_000, Rule::G162B, 1), Ok(90_500));
        assert_eq!(
            millidegrees(num("360.001"), b'B', 0, 360_000, Rule::G162B, 1),
            Err(alarm(AlarmCode::OutOfRange, b'B', Rule::G162B, 1))
        );
        assert_eq!(signed_lead(num("-0.5"), b'I', g, lead_max(g), Rule::G162I, 1), Ok(-5_000));
        assert_eq!(
            signed_lead(num("10000"), b'K', g, lead_max(g), Rule::G34, 1),
            Err(alarm(AlarmCode::OutOfRange, b'K', Rule::G34, 1))
        );
        assert_eq!(feed(num("500"), b'H', g, N, Rule::G162H, 1), Ok(5_000_000));
        assert_eq!(feed(num("0"), b'H', g, N, Rule::G162H, 1), Err(alarm(AlarmCode::OutOfRange, b'H', Rule::G162H, 1)));
    }
}
