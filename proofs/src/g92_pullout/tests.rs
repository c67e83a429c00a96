//! The unit tests of `g92_pullout` that are not its harness drivers.

use super::*;

#[test]
fn table_is_the_register() {
    let c = 7;
    assert_eq!(table(None, None, c), Some((7, 7)));
    assert_eq!(table(None, Some(0), c), Some((7, 7)));
    assert_eq!(table(None, Some(-3), c), Some((7, 3)));
    assert_eq!(table(Some(0), None, c), None);
    assert_eq!(table(Some(0), Some(5), c), None);
    assert_eq!(table(Some(-4), None, c), Some((4, 4)));
    assert_eq!(table(Some(4), Some(0), c), Some((4, 4)));
    assert_eq!(table(Some(4), Some(-2), c), Some((4, 2)));
    assert_eq!(table(None, None, 0), None);
    assert_eq!(table(None, Some(3), 0), None);
}
