//! `Schedule::from_parts` (for the proofs): it accepts exactly the shape its doc states —
//! Δd and T in 1…2^63 − 1, Δdmin < 2^63, reach in 1…`REACH_CAP`, the switch pass ≥ 1, and
//! `NEVER` without a minimum or in constant mode — each bound tried on both sides, and an
//! accepted schedule gives its parts back.
use super::*;

#[test]
fn from_parts_takes_exactly_the_stated_shape() {
    let top = i64::MAX.unsigned_abs();
    let base = Parts { dd: 5, dmin: 2, target: 20, reach: 3, switch: 4, constant: false };
    let cases: [(Parts, bool); 22] = [
        (base, true),
        (Parts { dd: 0, ..base }, false),
        (Parts { dd: 1, ..base }, true),
        (Parts { dd: top, ..base }, true),
        (Parts { dd: top + 1, ..base }, false),
        (Parts { target: 0, ..base }, false),
        (Parts { target: 1, ..base }, true),
        (Parts { target: top, ..base }, true),
        (Parts { target: top + 1, ..base }, false),
        (Parts { dmin: top, ..base }, true),
        (Parts { dmin: top + 1, ..base }, false),
        (Parts { reach: 0, ..base }, false),
        (Parts { reach: 1, ..base }, true),
        (Parts { reach: REACH_CAP, ..base }, true),
        (Parts { reach: REACH_CAP + 1, ..base }, false),
        (Parts { switch: 0, ..base }, false),
        (Parts { switch: 1, ..base }, true),
        // A switch pass needs a minimum (Δdmin ≥ 1) and the degressive mode.
        (Parts { dmin: 0, ..base }, false),
        (Parts { dmin: 1, ..base }, true),
        (Parts { dmin: 0, switch: NEVER, ..base }, true),
        (Parts { constant: true, ..base }, false),
        (Parts { constant: true, switch: NEVER, ..base }, true),
    ];
    for (p, ok) in cases {
        let got = Schedule::from_parts(p);
        assert_eq!(got.is_some(), ok, "{p:?}");
        if let Some(s) = got {
            assert_eq!(s.parts(), p);
            assert_eq!(s.dd2, u128::from(p.dd) * u128::from(p.dd));
        }
    }
}
