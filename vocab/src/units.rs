//! Lengths on the least-increment grid (COM.UNITS) and numbers as written in a program.

/// Input units (COM.UNITS).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum Units {
    Metric,
    Inch,
}

/// Increment system (COM.UNITS): ISB 0.001 mm / 0.0001 in, ISC 0.0001 mm / 0.00001 in.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum Increment {
    Isb,
    Isc,
}

/// The grid every length and lead lives on.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Grid {
    pub units: Units,
    pub increment: Increment,
}

impl Grid {
    pub const METRIC_ISB: Grid = Grid { units: Units::Metric, increment: Increment::Isb };

    /// Decimal places of one length increment: 3, 4 (metric ISB, ISC), 4, 5 (inch ISB, ISC).
    pub const fn decimals(self) -> u32 {
        match (self.units, self.increment) {
            (Units::Metric, Increment::Isb) => 3,
            (Units::Metric, Increment::Isc) | (Units::Inch, Increment::Isb) => 4,
            (Units::Inch, Increment::Isc) => 5,
        }
    }

    /// Decimal places of one lead count (COM.LEAD): 0.0001 mm, 0.00001 in, in ISB and ISC.
    pub const fn lead_decimals(self) -> u32 {
        match self.units {
            Units::Metric => 4,
            Units::Inch => 5,
        }
    }

    /// How many lead counts make one length increment (10 in ISB, 1 in ISC).
    pub const fn lead_counts_per_increment(self) -> i64 {
        match self.increment {
            Increment::Isb => 10,
            Increment::Isc => 1,
        }
    }

    /// The unit's name as printed in trace headers.
    pub const fn unit_name(self) -> &'static str {
        match self.units {
            Units::Metric => "MM",
            Units::Inch => "INCH",
        }
    }
}

/// A number exactly as written after an address letter: sign, decimal digits, and whether a
/// decimal point was written. `-1.50` is `{ negative, mantissa: 150, decimals: 2, point }`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Number {
    pub negative: bool,
    pub mantissa: u64,
    pub decimals: u8,
    pub point: bool,
}

/// Why a [`Number`] does not fit what was asked of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumberError {
    /// More decimal places than the grid holds (COM.UNITS).
    Precision,
    /// Too large for any legal value (COM.RANGES).
    Overflow,
    /// A decimal point where an integer is required.
    NotInteger,
}

impl Number {
    /// The number as an integer count of `10^-places`, exactly; an error if it has more
    /// decimals than `places` (non-zero digits beyond the grid) or does not fit.
    pub fn scaled(self, places: u32) -> Result<i64, NumberError> {
        let mut m = self.mantissa as u128;
        let d = self.decimals as u32;
        if d > places {
            let cut = 10u128.pow(d - places);
            if !m.is_multiple_of(cut) {
                return Err(NumberError::Precision);
            }
            m /= cut;
        } else {
            let shift = places - d;
            if shift > 30 {
                return if m == 0 { Ok(0) } else { Err(NumberError::Overflow) };
            }
            m = m.checked_mul(10u128.pow(shift)).ok_or(NumberError::Overflow)?;
        }
        let v = i64::try_from(m).map_err(|_| NumberError::Overflow)?;
        Ok(if self.negative { -v } else { v })
    }

    /// The number as an integer; an error when written with a decimal point.
    pub fn integer(self) -> Result<i64, NumberError> {
        if self.point {
            return Err(NumberError::NotInteger);
        }
        self.scaled(0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn n(negative: bool, mantissa: u64, decimals: u8, point: bool) -> Number {
        Number { negative, mantissa, decimals, point }
    }

    #[test]
    fn scaling_is_exact() {
        assert_eq!(n(false, 587, 1, true).scaled(3), Ok(58_700));
        assert_eq!(n(true, 28, 0, false).scaled(3), Ok(-28_000));
        assert_eq!(n(false, 58_7000, 4, true).scaled(3), Ok(58_700));
        assert_eq!(n(false, 58_7001, 4, true).scaled(3), Err(NumberError::Precision));
        assert_eq!(n(false, u64::MAX, 0, false).scaled(3), Err(NumberError::Overflow));
        assert_eq!(n(false, 5, 0, false).integer(), Ok(5));
        assert_eq!(n(false, 5, 0, true).integer(), Err(NumberError::NotInteger));
    }

    #[test]
    fn grid_decimals() {
        assert_eq!(Grid::METRIC_ISB.decimals(), 3);
        let inch_isc = Grid { units: Units::Inch, increment: Increment::Isc };
        assert_eq!(inch_isc.decimals(), 5);
        assert_eq!(inch_isc.lead_decimals(), 5);
        assert_eq!(inch_isc.lead_counts_per_increment(), 1);
    }
}
