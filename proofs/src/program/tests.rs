//! Unit tests of `program`.

use super::*;

fn render(f: impl FnOnce(&mut Program)) -> String {
    let mut p = Program::new();
    f(&mut p);
    assert!(!p.overflowed());
    String::from_utf8(p.bytes().to_vec()).unwrap()
}

#[test]
fn numbers_are_written_exactly() {
    assert_eq!(render(|p| p.fixed(-1500, 3)), "-1.500");
    assert_eq!(render(|p| p.fixed(7, 3)), "0.007");
    assert_eq!(render(|p| p.fixed(0, 0)), "0");
    assert_eq!(render(|p| p.fixed(0, 5)), "0.00000");
    assert_eq!(render(|p| p.fixed(999_999_999, 4)), "99999.9999");
    assert_eq!(render(|p| p.fixed(i64::MIN, 0)), "-9223372036854775808");
    assert_eq!(render(|p| p.int_word(b'G', 76)), "G76");
    assert_eq!(render(|p| p.six_digits(b'P', 2, 5, 60)), "P020560");
    assert_eq!(render(|p| p.len_word(b'W', -60_000, 3)), "W-60.000");
}

#[test]
fn overflow_is_reported_not_panicked() {
    let mut p = Program::new();
    for _ in 0..300 {
        p.byte(b'X');
    }
    assert!(p.overflowed());
    assert_eq!(p.len(), CAPACITY);
}
