//! Unit tests of `replay`.

use super::*;

#[test]
fn replays_listed_draws_then_low_ends() {
    let mut s = ReplaySource::new(vec![3, -2]);
    assert_eq!((s.bounded_i64(0, 9), s.bounded_i64(-5, 5), s.bounded_i64(4, 8)), (3, -2, 4));
    assert_eq!(s.finish(), Ok(()));
}

#[test]
fn misfits_and_unused_draws_are_reported() {
    let mut s = ReplaySource::new(vec![30]);
    assert_eq!(s.bounded_i64(0, 9), 0);
    assert!(s.finish().unwrap_err().contains("draw 0 is 30, outside 0..=9"));
    let mut s = ReplaySource::new(vec![1, 2]);
    s.bounded_i64(0, 9);
    assert!(s.finish().unwrap_err().contains("drew 1 values, the case lists 2"));
}
