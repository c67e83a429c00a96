//! Numbers as written after an address letter (PRJ.LEX) and their exact value on a grid of
//! decimal places (COM.UNITS): the production lexer's number type.

/// A number exactly as written: sign, decimal digits, and whether a decimal point was written.
/// `-1.50` is `{ negative, mantissa: 150, decimals: 2, point }`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Number {
    pub negative: bool,
    pub mantissa: u64,
    pub decimals: u8,
    pub point: bool,
}

/// 10^0 … 10^19: every power of ten that fits a `u64`.
const POW10: [u64; 20] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
    1_000_000_000,
    10_000_000_000,
    100_000_000_000,
    1_000_000_000_000,
    10_000_000_000_000,
    100_000_000_000_000,
    1_000_000_000_000_000,
    10_000_000_000_000_000,
    100_000_000_000_000_000,
    1_000_000_000_000_000_000,
    10_000_000_000_000_000_000,
];

/// 10^`e`, when it fits a `u64`.
fn pow10(e: u32) -> Option<u64> {
    POW10.get(usize::try_from(e).ok()?).copied()
}

/// Why a [`Number`] does not fit what was asked of it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NumberError {
    /// More decimal places than the grid holds (COM.UNITS).
    Precision,
    /// Beyond any machine word: out of the word's range, whatever its range is.
    Overflow,
    /// A decimal point where an integer is required.
    NotInteger,
}

impl Number {
    /// The number as an integer count of `10^-places`, exactly, in 64-bit arithmetic; an error
    /// if it has more decimals than `places` (non-zero digits beyond the grid) or does not fit.
    pub fn scaled(self, places: u32) -> Result<i64, NumberError> {
        let m = self.mantissa;
        let d = u32::from(self.decimals);
        let m = if d > places {
            // A power of ten beyond the table exceeds every u64: only 0 is a multiple of it.
            match pow10(d - places) {
                Some(cut) if m.is_multiple_of(cut) => m / cut,
                None if m == 0 => 0,
                _ => return Err(NumberError::Precision),
            }
        } else {
            // Beyond the table (10^20 and up) only 0 fits.
            match pow10(places - d) {
                Some(p) => m.checked_mul(p).ok_or(NumberError::Overflow)?,
                None if m == 0 => 0,
                None => return Err(NumberError::Overflow),
            }
        };
        let v = i64::try_from(m).map_err(|_| NumberError::Overflow)?;
        Ok(if self.negative { -v } else { v })
    }

    /// Whether the number's exact value is `p` (`50`, `050`, `+50`, `50.0` are 50; `-50`, `50.5`
    /// are not): mantissa = p · 10^decimals.
    pub fn is(self, p: u64) -> bool {
        !self.negative && pow10(u32::from(self.decimals)).and_then(|s| p.checked_mul(s)) == Some(self.mantissa)
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
mod tests;
