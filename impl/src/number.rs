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
mod tests {
    use super::*;
    use crate::tests::xorshift;

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

    /// The scaling as first written, in 128 bits with `pow`: the reference for the table-based
    /// one (valid for up to 38 decimal places, beyond which its `pow` overflows).
    fn scaled_in_128_bits(n: Number, places: u32) -> Result<i64, NumberError> {
        let mut m = n.mantissa as u128;
        let d = n.decimals as u32;
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
        Ok(if n.negative { -v } else { v })
    }

    /// The table-based scaling equals the 128-bit one: random mantissas of every width and
    /// their multiples of powers of ten, decimals 0…38, places 0…38, the edges of i64 and u64.
    #[test]
    fn scaling_matches_the_128_bit_reference() {
        let mut state = 0x5ca1_ed00_d1e5_0001u64;
        let edges = [0, 1, 9, 10, i64::MAX as u64 / 10, i64::MAX as u64, i64::MAX as u64 + 1, u64::MAX / 10, u64::MAX];
        for round in 0..200_000u32 {
            let r = xorshift(&mut state);
            let mantissa = match round % 4 {
                0 => edges[(r % edges.len() as u64) as usize],
                1 => r >> (r % 64),
                // A multiple of a power of ten: exact divisions.
                2 => ((r >> 40) % 100_000) * 10u64.pow((r % 14) as u32),
                _ => r % 1_000_000,
            };
            let s = xorshift(&mut state);
            let number = n(s & 1 == 1, mantissa, ((s >> 8) % 39) as u8, s & 2 == 2);
            let places = ((s >> 16) % 39) as u32;
            assert_eq!(number.scaled(places), scaled_in_128_bits(number, places), "{number:?} at {places} places");
        }
        // Beyond the 128-bit reference's reach: decimals up to 255.
        assert_eq!(n(false, 0, 255, true).scaled(3), Ok(0));
        assert_eq!(n(false, 1, 255, true).scaled(3), Err(NumberError::Precision));
        assert_eq!(n(false, 1, 0, false).scaled(40), Err(NumberError::Overflow));
        assert_eq!(n(true, 0, 0, false).scaled(40), Ok(0));
    }
}
