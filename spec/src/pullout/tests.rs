use super::*;

#[test]
fn g92_example_pullout() {
    // G92 X58.7 Z-28 F3 J3 K1 from X65 Z5: end (58.7, −28), R 0, W −33, external.
    let l = ThreadLine { end_x: 58_700, end_z: -28_000, r: 0, w: -33_000, s: 1 };
    let seg = segment(&l, Amounts { j: 3_000, k: 1_000 }).unwrap();
    assert_eq!(seg, ((58_700, -27_000), (64_700, -28_000)));
    assert_eq!(segment(&l, Amounts { j: 1, k: 33_000 }), Err(KTooLong));
}

#[test]
fn taper_and_x_long() {
    // R = −1 (start X smaller), W −10, K 3: X at the pull-out start = end + round(−1·3/10)
    let l = ThreadLine { end_x: 50_000, end_z: -10_000, r: -1_000, w: -10_000, s: 1 };
    let ((sx, sz), _) = segment(&l, Amounts { j: 1_000, k: 3_000 }).unwrap();
    assert_eq!((sx, sz), (50_000 - 600, -7_000));
    // X long: R 10 (radius), W −4; K 3 along X, J 1 along Z toward A (+Z).
    let l = ThreadLine { end_x: 20_000, end_z: -4_000, r: 10_000, w: -4_000, s: 1 };
    let seg = segment(&l, Amounts { j: 1_000, k: 3_000 }).unwrap();
    assert_eq!(seg, ((26_000, -2_800), (20_000, -3_000)));
}
