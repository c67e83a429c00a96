use super::*;

/// Lines: a rounded quotient, ties half away from zero.
#[test]
fn line_crossings() {
    // Example 1's Q from X11.5 Z−15.3 to X17.5 Z−25.3 at X17: −15 300 − 5 500·10 000/6 000.
    assert_eq!(line_crossing(11_500, -15_300, 17_500, -25_300, 17_000), -24_467);
    assert_eq!(line_crossing(11_500, -15_300, 17_500, -25_300, 13_000), -17_800);
    // Ties: from (0, 0) to (2, −1) at p = 1: −½ → −1; to (2, 1): ½ → 1; to (−2, 3) at −1: 1.5 → 2.
    assert_eq!(line_crossing(0, 0, 2, -1, 1), -1);
    assert_eq!(line_crossing(0, 0, 2, 1, 1), 1);
    assert_eq!(line_crossing(0, 0, -2, 3, -1), 2);
}

/// G71.LAYER: "Layer k = 1, 2, … stands at X_k = A.x + s·2k·Δd. It exists while s·(X_k − Q₀.x) <
/// 0 (strictly between A.x and Q₀.x) and its cut is positive" — asked for any k. A = X50 Z2,
/// s = c = −1, Δd = 2 mm (step 4 000 on the diameter count); Q: Q₀ = X20 Z2, a line to X20 Z-10,
/// a line to X50 Z-20. Layers 1 … 7 at X46 … X22; layer 1 leaves Q on the second line at
/// Z-10 + 26 000·(−10 000)/30 000 = Z-18.667 (rounded once), layer 7 at Z-10.667; no layer 0
/// (at A itself) and no layer 8 (X18, past Q₀).
#[test]
fn layers_exist_only_between_a_and_q0() {
    use crate::contour::{Contour, Element, Mode};
    use crate::stock_removal::{Axes, Cycle};
    let line = |start, end| Element { mode: Mode::Feed, written: Some(1), moves: true, start, end, centre: None, feed: None, line: 1 };
    let q = Contour { elements: vec![line((50_000, 2_000), (20_000, 2_000)), line((20_000, 2_000), (20_000, -10_000)), line((20_000, -10_000), (50_000, -20_000))] };
    let cy = Cycle { ax: Axes::G71, a: (50_000, 2_000), q, s: -1, c: -1, depth: 2_000, retract: 0, feed: 1, line: 1 };
    let rough = Roughing::new(&cy);
    assert_eq!(rough.layer(0), None);
    assert_eq!(rough.layer(1), Some((46_000, -18_667)));
    assert_eq!(rough.layer(7), Some((22_000, -10_667)));
    assert_eq!(rough.layer(8), None);
    assert_eq!(rough.count(100), 7);
}
