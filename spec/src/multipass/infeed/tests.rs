use super::*;

#[test]
fn g76_example_infeed() {
    // C.x 60, external, k 3: depths 1.8, 2.5, 3 → X 62.4, 61.0, 60.0
    assert_eq!(infeed_x(60_000, 1, 3_000, 1_800), 62_400);
    assert_eq!(infeed_x(60_000, 1, 3_000, 2_500), 61_000);
    assert_eq!(infeed_x(60_000, 1, 3_000, 3_000), 60_000);
    // a = 45: tan 22.5° = 0.41421…; 1.8 → 0.746, 2.5 → 1.036
    assert_eq!(t(1_800, 45), 746);
    assert_eq!(t(2_500, 45), 1_036);
    let g = ThreadZRef::Groove;
    assert_eq!(infeed_z(10_000, 1, 746, 1_036, Flank::Right, g), 9_254);
    assert_eq!(infeed_z(10_000, 1, 746, 1_036, Flank::Left, g), 10_000 - 1_326);
    assert_eq!(infeed_z(10_000, -1, 746, 1_036, Flank::Centre, g), 11_036);
}

/// `thread.zref=start` (the letter, the default): every mode measured from A.z; the right
/// flank is the same under both readings.
#[test]
fn start_reference() {
    let st = ThreadZRef::Start;
    assert_eq!(ThreadZRef::default(), st);
    assert_eq!(infeed_z(10_000, 1, 746, 1_036, Flank::Right, st), 9_254);
    assert_eq!(infeed_z(10_000, 1, 746, 1_036, Flank::Centre, st), 10_000);
    assert_eq!(infeed_z(10_000, 1, 746, 1_036, Flank::Left, st), 10_746);
    assert_eq!(infeed_z(10_000, -1, 746, 1_036, Flank::Left, st), 9_254);
    assert_eq!(infeed_z(10_000, -1, 746, 1_036, Flank::Centre, st), 10_000);
    for s in [-1, 1] {
        for t in [0, 746] {
            let right = |zref| infeed_z(10_000, s, t, 1_036, Flank::Right, zref);
            assert_eq!(right(ThreadZRef::Start), right(ThreadZRef::Groove));
        }
    }
}

#[test]
fn modes() {
    assert_eq!(flank(Cycle::G76, 0, 2), Flank::Right);
    assert_eq!(flank(Cycle::G76, 1, 2), Flank::Centre);
    assert_eq!(flank(Cycle::G76, 2, 1), Flank::Left);
    assert_eq!(flank(Cycle::G78, 0, 1), Flank::Centre);
    assert_eq!(flank(Cycle::G78, 4, 2), Flank::Right);
}
