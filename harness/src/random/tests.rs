//! Unit tests of `random`.

use super::*;
use crate::check;

#[test]
fn random_stays_in_range_and_hits_edges() {
    let (mut lo_hit, mut hi_hit) = (false, false);
    let r = random(7, 2000, |s| {
        let v = s.bounded_i64(-5, 999_999_999);
        check!(s, (-5..=999_999_999).contains(&v), "in range");
        lo_hit |= v == -5;
        hi_hit |= v == 999_999_999;
        Ok(())
    });
    r.assert_ok();
    assert!(lo_hit && hi_hit);
}
