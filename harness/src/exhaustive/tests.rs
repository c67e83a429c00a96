//! Unit tests of `exhaustive`.

use super::*;
use crate::{check, cover};

#[test]
fn odometer_enumerates_every_path_once() {
    // Two dependent draws: a in 0..=3, then b in 0..=a. 1 + 2 + 3 + 4 = 10 paths.
    let mut seen = Vec::new();
    let r = exhaustive(8, 1000, |s| {
        let a = s.bounded_i64(0, 3);
        let b = s.bounded_i64(0, a);
        seen.push((a, b));
        Ok(())
    });
    assert_eq!(r.cases, 10);
    let mut sorted = seen.clone();
    sorted.sort();
    sorted.dedup();
    assert_eq!(sorted.len(), 10);
}

#[test]
fn wide_ranges_take_both_ends() {
    let mut seen = Vec::new();
    let r = exhaustive(2, 1000, |s| {
        seen.push(s.bounded_i64(1, 999_999_999));
        Ok(())
    });
    assert_eq!(r.cases, 4);
    assert_eq!(seen, vec![1, 2, 999_999_998, 999_999_999]);
    let mut seen = Vec::new();
    exhaustive(2, 1000, |s| {
        seen.push(s.bounded_i64(i64::MIN, i64::MAX));
        Ok(())
    });
    assert_eq!(seen, vec![i64::MIN, i64::MIN + 1, i64::MAX - 1, i64::MAX]);
}

#[test]
fn small_domains_are_enumerated_whole() {
    let r = exhaustive(1, 1000, |s| {
        s.every_u32(0, 178);
        s.bounded_u32(0, 178);
        Ok(())
    });
    assert_eq!(r.cases, 179 * 2);
}

#[test]
fn failures_carry_their_draws_and_budget_is_enforced() {
    let r = exhaustive(8, 1000, |s| {
        let a = s.bounded_i64(0, 5);
        s.assume(a != 1)?;
        check!(s, a < 4, "a below 4");
        Ok(())
    });
    let f = r.failure.clone().unwrap();
    assert_eq!((f.message, f.draws), ("a below 4", vec![4]));
    assert_eq!(r.rejected, 1);
    assert!(r.verdict().is_err());

    let r = exhaustive(8, 3, |s| {
        s.bounded_i64(0, 5);
        Ok(())
    });
    assert!(r.incomplete && r.verdict().is_err());
}

#[test]
fn uncovered_conditions_fail_the_exhaustive_driver() {
    let r = exhaustive(4, 100, |s| {
        let a = s.bounded_i64(0, 3);
        cover!(s, a == 2, "two");
        cover!(s, a == 9, "nine");
        Ok(())
    });
    assert_eq!(r.covers["two"], 1);
    assert!(r.verdict().unwrap_err().contains("nine"));
}
