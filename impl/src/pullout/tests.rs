use super::*;

#[test]
fn g92_jk_table() {
    let c = 30;
    assert_eq!(g92_amounts(None, None, c, 45), Some(Amounts { j: 30, k: 30 }));
    // No.5131 for G92: JK.1 only; J = round(30·tan 30°) = round(17.32) = 17.
    assert_eq!(g92_amounts(None, None, c, 30), Some(Amounts { j: 17, k: 30 }));
    assert_eq!(g92_amounts(None, Some(5), c, 30), Some(Amounts { j: 30, k: 5 }));
    assert_eq!(g92_amounts(None, Some(0), c, 30), Some(Amounts { j: 30, k: 30 }));
    assert_eq!(g92_amounts(Some(4), None, c, 30), Some(Amounts { j: 4, k: 4 }));
    assert_eq!(g92_amounts(None, Some(5), c, 45), Some(Amounts { j: 30, k: 5 }));
    assert_eq!(g92_amounts(None, Some(0), c, 45), Some(Amounts { j: 30, k: 30 }));
    assert_eq!(g92_amounts(Some(0), None, c, 45), None);
    assert_eq!(g92_amounts(Some(0), Some(7), c, 45), None);
    assert_eq!(g92_amounts(Some(4), None, c, 45), Some(Amounts { j: 4, k: 4 }));
    assert_eq!(g92_amounts(Some(4), Some(0), c, 45), Some(Amounts { j: 4, k: 4 }));
    assert_eq!(g92_amounts(Some(4), Some(9), c, 45), Some(Amounts { j: 4, k: 9 }));
    assert_eq!(g92_amounts(None, None, 0, 45), None);
}

#[test]
fn multi_table() {
    // 5131 = 45°: J = K.
    assert_eq!(multi_amounts(None, None, 2000, 45), Some(Amounts { j: 2000, k: 2000 }));
    // 30°: J = round(2000·0.57735) = 1155.
    assert_eq!(multi_amounts(None, Some(2000), 0, 30), Some(Amounts { j: 1155, k: 2000 }));
    assert_eq!(multi_amounts(Some(1500), None, 0, 45), Some(Amounts { j: 1500, k: 1500 }));
    assert_eq!(multi_amounts(Some(1500), Some(0), 0, 45), Some(Amounts { j: 1500, k: 1500 }));
    assert_eq!(multi_amounts(Some(1500), Some(2000), 0, 45), Some(Amounts { j: 1500, k: 2000 }));
    assert_eq!(multi_amounts(None, None, 0, 45), None); // P010060: r = 0 input
    assert_eq!(multi_amounts(Some(0), Some(2000), 0, 45), None);
    assert_eq!(multi_amounts(None, Some(0), 100, 45), None);
}

/// "A resolved amount of 0 means no pull-out" (docs/INTERPRETATION.md, G92.JK.*; "A resolved J
/// or K of 0: no pull-out", G76.PULLOUT): a J that resolves to 0 while K does not. G92.JK.2
/// with No.19 = 0 (J = c = 0); JK.1 and G76/G78's J = round(K·tan 5131°) with K = 1 increment
/// and 5131 = 1° (tan 1° ≈ 0.017: J rounds to 0).
#[test]
fn a_resolved_j_of_0_is_no_pull_out() {
    assert_eq!(g92_amounts(None, Some(5), 0, 45), None);
    assert_eq!(g92_amounts(None, None, 1, 1), None);
    assert_eq!(multi_amounts(None, Some(1), 100, 1), None);
    assert_eq!(multi_amounts(None, None, 1, 1), None);
    // The same amounts with a J of 1 make a pull-out.
    assert_eq!(g92_amounts(None, Some(5), 1, 45), Some(Amounts { j: 1, k: 5 }));
    assert_eq!(multi_amounts(None, Some(100), 0, 1), Some(Amounts { j: 2, k: 100 }));
}

#[test]
fn chamfer_widths() {
    // r = 10 tenths of a 4 mm lead = 4 mm; No.19 = 10 of 3 mm = 3 mm (ISB: 10 counts/inc).
    assert_eq!(tenths_of_lead(10, 40_000, Grid::METRIC_ISB), 4_000);
    assert_eq!(tenths_of_lead(8, 40_000, Grid::METRIC_ISB), 3_200);
    // 5 tenths of 1.5875 mm = 0.79375 → 0.794.
    assert_eq!(tenths_of_lead(5, 15_875, Grid::METRIC_ISB), 794);
}

/// G92.EXAMPLE: X58.7 Z-28 from X65 Z5, J3 K1: start 1 mm before the end on Z, end
/// 3 mm (radius) out.
#[test]
fn g92_example_geometry() {
    let o = offsets(Amounts { j: 3_000, k: 1_000 }, -33_000, 0, 1);
    assert_eq!(o, Offsets { start: (0, 1_000), end: (6_000, 0) });
    // Taper R = −2 mm over W = −35 mm, K = 1: X = end − round(2·1/35) = −0.057 radius.
    let o = offsets(Amounts { j: 1_000, k: 1_000 }, -35_000, -2_000, 1);
    assert_eq!(o.start, (-114, 1_000));
    // X long: R = 10, W = −4, K = 2, J = 1: start X end + 2 (radius), Z end + round(4·2/10).
    let o = offsets(Amounts { j: 1_000, k: 2_000 }, -4_000, 10_000, 1);
    assert_eq!(o, Offsets { start: (4_000, 800), end: (0, 1_000) });
}
