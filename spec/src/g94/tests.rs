use super::*;

#[test]
fn cut_start_and_taper() {
    for reading in [G94K::EndMinusStart, G94K::StartMinusEnd] {
        assert_eq!(cut_start_z(-3_500, 0, reading), -3_500);
    }
    // `G94 X20 Z-5 K-2`: the letter starts the cut at Z−3, FANUC at Z−7.
    assert_eq!(cut_start_z(-5_000, -2_000, G94K::EndMinusStart), -3_000);
    assert_eq!(cut_start_z(-5_000, -2_000, G94K::StartMinusEnd), -7_000);
    assert_eq!(cut_start_z(-4_000, 2_000, G94K::StartMinusEnd), -2_000); // K > 0: above the end
    assert_eq!(cut_start_z(-4_000, 2_000, G94K::EndMinusStart), -6_000);
    assert_eq!(G94K::default(), G94K::EndMinusStart); // the letter is the default
    // W = −6: K up to +6 against it, any K with it.
    assert!(taper_ok(6_000, -6_000));
    assert!(!taper_ok(6_001, -6_000));
    assert!(taper_ok(-60_000, -6_000));
}
