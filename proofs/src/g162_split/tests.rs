//! The unit tests of `g162_split` that are not its harness drivers.

use super::*;

/// The register's examples through the model: P2.5 Q1 (ISB and ISC), P0.003 Q0.002,
/// P0.5 Q1.
#[test]
fn model_is_the_register() {
    let depths = |p, q| {
        let m = model::split(p, q);
        let mut v: Vec<i64> = (1..=m.k).map(|n| n * q).collect();
        v.extend(m.tail[..m.count].iter().map(|t| t.0));
        v
    };
    assert_eq!(depths(2_500, 1_000), [1_000, 2_000, 2_250, 2_375, 2_438, 2_500]);
    assert_eq!(depths(25_000, 10_000), [10_000, 20_000, 22_500, 23_750, 24_375, 25_000]);
    assert_eq!(depths(3, 2), [2, 3]);
    assert_eq!(depths(500, 1_000), [250, 375, 438, 500]);
}
