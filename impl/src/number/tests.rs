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
