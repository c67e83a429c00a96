//! G76.DEPTH.1's `root` walks up from its guess and takes the square root only where the walk
//! does not find the rounded root. Both give the same value
//! (`root_with_any_guess_is_the_rounded_root`), so `crate::probe` counts the square roots taken.
use super::*;
use crate::probe;

/// `root(v, hint)` and the square roots it took.
fn root_counted(v: u128, hint: u64) -> (u64, usize) {
    let before = probe::roots();
    let r = root(v, hint);
    (r, probe::roots() - before)
}

#[test]
fn the_walk_finds_the_root_near_its_guess() {
    // From the guess 0 the walk checks 0, 1, 2, 3: round(√v) for every 1 ≤ v ≤ 3² + 3 = 12
    // (v = 0 fails c² − c < v at c = 0 and takes the square root).
    assert_eq!(root_counted(0, 0), (0, 1));
    for v in 1..=12u128 {
        assert_eq!(root_counted(v, 0), (u64::try_from(sqrt_round(v)).unwrap(), 0), "v {v}");
    }
    // v = 13 rounds to 4, beyond the walk: the square root.
    assert_eq!(root_counted(13, 0), (4, 1));
    // G76.DEPTH.1 with Δd = 10 increments, each pass guessed at the depth before (as the
    // schedule does): depths 10, 14, 17, 20, 22, … Pass 1 (0 → 10) and pass 2 (10 → 14) are
    // beyond the walk; from pass 3 on a depth grows by at most round(10·(√3 − √2) = 3.18) = 3.
    let mut depth = 0;
    let mut roots = 0;
    for n in 1..=2_000u128 {
        let (d, taken) = root_counted(n * 100, depth);
        assert_eq!(u128::from(d), sqrt_round(n * 100), "pass {n}");
        (depth, roots) = (d, roots + taken);
    }
    assert_eq!(roots, 2);
}
