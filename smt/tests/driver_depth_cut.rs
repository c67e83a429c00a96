//! The driver of lemmas 14 and 15: the production functions the Kani harnesses `g71_layer_step`
//! and `g73_passes` stub (`cycle_impl::rough::{layers_within, layer_offset}`,
//! `cycle_impl::g73::escape`) against the lemmas' model — SMT-LIB's `div` (the floor for a
//! positive divisor, written here with `div_euclid`) and round_away(x, d) = sign(x)·⌊(2|x| + d)/(2d)⌋
//! — over the edges and random legal values with a fixed seed. Negative control: a model that
//! rounds half down disagrees with production.

use cycle_impl::g73::{escape, Words};
use cycle_impl::rough::{layer_offset, layers_within};
use cycle_smt::model::{Rng, N};

/// Lemma 15's `round_away`.
fn round_away(x: i128, d: i128) -> i128 {
    let mag = (2 * x.abs() + d).div_euclid(2 * d);
    if x < 0 { -mag } else { mag }
}

/// Lemma 14: `layers_within(x, step)` is `(div x step)` and the largest m with m·step ≤ x;
/// `layer_offset(k, step)` = k·step.
fn check_rough(x: i128, step: i64, k: u32) {
    let q = layers_within(x, i128::from(step));
    assert_eq!(q, x.div_euclid(i128::from(step)), "layers_within({x}, {step})");
    assert!(q * i128::from(step) <= x && x < (q + 1) * i128::from(step), "bracket ({x}, {step})");
    assert_eq!(i128::from(layer_offset(k, step)), i128::from(k) * i128::from(step), "layer_offset({k}, {step})");
}

/// Lemma 15: `escape(w, n)` is round_away(v·(d − n), d) for v = Δi, Δk.
fn check_escape(di: i64, dk: i64, d: i64, n: i64, model: fn(i128, i128) -> i128) -> bool {
    let w = Words { di, dk, d, allowance: (0, 0), feed: 1, count_word: b'R', visit_c: false };
    let left = i128::from(d - n);
    let want = (model(i128::from(di) * left, i128::from(d)), model(i128::from(dk) * left, i128::from(d)));
    let (ei, ek) = escape(&w, n);
    (i128::from(ei), i128::from(ek)) == want
}

#[test]
fn production_matches_lemmas_14_and_15() {
    let mut rng = Rng(0x14_15);
    // D(Q₀) − 1 up to 2^63 (positions below 2^62 each), step = Δd·p_a ≤ 2N, k ≤ 10^6 + 1.
    for x in [0i128, 1, 2, 3, 1 << 40, (1 << 63) - 1] {
        for step in [1i64, 2, 3, N, 2 * N] {
            check_rough(x, step, 1_000_001);
        }
    }
    for _ in 0..200_000 {
        let x = i128::from(rng.range(0, i64::MAX));
        check_rough(x, rng.range(1, 2 * N), rng.range(0, 1_000_001) as u32);
        let d = rng.range(1, N);
        let n = rng.range(1, d);
        assert!(check_escape(rng.range(-N, N), rng.range(-N, N), d, n, round_away), "escape, d {d} n {n}");
    }
    for (v, d) in [(N, N), (-N, N), (N, 1), (1, 2), (-1, 2), (3, 2), (-3, 2), (0, 7)] {
        for n in 1..=d.min(10) {
            assert!(check_escape(v, -v, d, n, round_away), "escape edge v {v} d {d} n {n}");
        }
    }
}

/// Negative control: rounding half down (⌊(2|x| + d − 1)/(2d)⌋) disagrees with production at a tie.
#[test]
fn negative_control_half_down_disagrees() {
    fn half_down(x: i128, d: i128) -> i128 {
        let mag = (2 * x.abs() + d - 1).div_euclid(2 * d);
        if x < 0 { -mag } else { mag }
    }
    // Δi = 1, d = 2, n = 1: 1·1/2 = ½, a tie: production rounds away from zero (1).
    assert!(!check_escape(1, 1, 2, 1, half_down));
    assert!(check_escape(1, 1, 2, 1, round_away));
}
