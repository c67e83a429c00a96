//! Unit tests of `bytes`.

use super::*;

#[test]
fn draws_stay_in_range_and_exhaustion_gives_the_low_end() {
    let data: Vec<u8> = (0..=255u8).cycle().take(4000).collect();
    let mut s = FuzzSource::new(&data);
    for (lo, hi) in [(0, 0), (-5, 5), (1, 999_999_999), (i128::from(i64::MIN), i128::from(i64::MAX)), (i128::MIN, i128::MAX)] {
        for _ in 0..50 {
            let v = s.bounded_i128(lo, hi);
            assert!(lo <= v && v <= hi, "{v} outside {lo}..={hi}");
        }
    }
    let mut empty = FuzzSource::new(&[]);
    assert_eq!(empty.bounded_i64(-3, 9), -3);
    assert_eq!(empty.draws, vec![-3]);
}

#[test]
fn modes_reach_both_edges() {
    // Mode 2 (high end), offset 0; mode 1 (low end), offset 3.
    let mut s = FuzzSource::new(&[2, 0, 1, 3]);
    assert_eq!(s.bounded_i64(10, 1_000), 1_000);
    assert_eq!(s.bounded_i64(10, 1_000), 13);
}

#[test]
fn encoded_draws_decode_to_themselves() {
    let draws = [0, 7, -705_032_702, i128::from(u64::MAX), i128::from(i64::MIN), 999_999_999];
    let bytes = FuzzSource::encode(&draws);
    let mut s = FuzzSource::new(&bytes);
    for &v in &draws {
        assert_eq!(s.bounded_i128(v.min(0) - 1, v.max(0) + 1), v);
    }
    // An out-of-range raw value is reduced into the range.
    let mut s = FuzzSource::new(&bytes[17..34]);
    assert_eq!(s.bounded_i64(0, 4), 2);
}
