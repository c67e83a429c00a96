use super::*;

fn depths(k: i64, d: i64, dd: i64, dmin: i64) -> Vec<i64> {
    rough_passes(k, d, dd, dmin, DepthMode::Degressive, 100_000).unwrap().iter().map(|p| p.depth).collect()
}

#[test]
fn g76_example() {
    // k 3, d 0.5, Δd 1.8, Δdmin 0.15: 1.8, then √2·1.8 = 2.546 ≥ 2.5 → 2.5.
    let p = rough_passes(3_000, 500, 1_800, 150, DepthMode::Degressive, 100).unwrap();
    assert_eq!(p, vec![Rough { depth: 1_800, rule: Rule::G76Depth1 }, Rough { depth: 2_500, rule: Rule::G76DepthLast }]);
}

#[test]
fn f76_ex1() {
    assert_eq!(
        depths(2_400, 100, 700, 100),
        vec![700, 990, 1_212, 1_400, 1_565, 1_715, 1_852, 1_980, 2_100, 2_214, 2_300]
    );
}

#[test]
fn minimum_switch_and_constant_mode() {
    // Δd 1, Δdmin 0.5: pass 2 cuts 0.414 < 0.5 → switch at 2: 1.0, 1.5, 2.0, …
    assert!(!cuts_minimum(1_000, 500, 1));
    assert!(cuts_minimum(1_000, 500, 2));
    assert_eq!(depths(3_000, 0, 1_000, 500), vec![1_000, 1_500, 2_000, 2_500, 3_000]);
    // Δdmin > Δd: minimum from pass 1.
    assert_eq!(depths(1_000, 0, 300, 400), vec![400, 800, 1_000]);
    let c = rough_passes(1_000, 100, 250, 0, DepthMode::Constant, 100).unwrap();
    assert_eq!(c.iter().map(|p| p.depth).collect::<Vec<_>>(), vec![250, 500, 750, 900]);
    assert_eq!(rough_passes(1_000_000, 0, 1, 0, DepthMode::Degressive, 10_000), Err(TooMany));
}

#[test]
fn schedule_properties() {
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = |m: u64| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        s % m
    };
    for case in 0..3_000 {
        let k = next(if case % 3 == 0 { 50 } else { 20_000 }) as i64 + 1;
        let d = next(k as u64) as i64;
        let dd = next(if case % 2 == 0 { 30 } else { 5_000 }) as i64 + 1;
        let dmin = next(if case % 5 == 0 { 3 } else { 2_000 }) as i64;
        let Ok(p) = rough_passes(k, d, dd, dmin, DepthMode::Degressive, 10_000) else { continue };
        let depths: Vec<i64> = p.iter().map(|r| r.depth).collect();
        assert_eq!(*depths.last().unwrap(), k - d, "{k} {d} {dd} {dmin}");
        assert_eq!(p.last().unwrap().rule, Rule::G76DepthLast);
        for (i, w) in depths.windows(2).enumerate() {
            assert!(w[0] <= w[1], "nondecreasing {k} {d} {dd} {dmin}: {depths:?}");
            if dmin >= 1 {
                assert!(w[0] < w[1], "strictly increasing {k} {d} {dd} {dmin}");
            }
            // every cut but the last rough one is ≥ Δdmin
            if i + 2 < depths.len() {
                assert!(w[1] - w[0] >= dmin, "min cut {k} {d} {dd} {dmin}: {depths:?}");
            }
        }
        if depths.len() >= 2 {
            assert!(depths[0] >= dmin, "first cut {k} {d} {dd} {dmin}");
        }
    }
}

/// G76.DEPTH.MIN (`001_…` line 29 and the register's "Depth schedule": the switch is the first n ≥
/// 1 with (√n − √(n−1))·Δd < Δdmin, strictly). Δd = Δdmin = 0.5: pass 1 cuts √1·Δd = Δd, not less,
/// so it is G76.DEPTH.1; pass 2 (√2 − 1 < 1) switches: 0.5 + 0.5. T = 2: 0.5, 1.0, 1.5, then 2.0 =
/// T.
#[test]
fn minimum_equal_to_first_cut_switches_at_pass_two() {
    assert!(!cuts_minimum(500, 500, 1));
    assert!(cuts_minimum(500, 500, 2));
    let r = rough_passes(2_000, 0, 500, 500, DepthMode::Degressive, 100).unwrap();
    let got: Vec<(i64, Rule)> = r.iter().map(|p| (p.depth, p.rule)).collect();
    assert_eq!(
        got,
        vec![(500, Rule::G76Depth1), (1_000, Rule::G76DepthMin), (1_500, Rule::G76DepthMin), (2_000, Rule::G76DepthLast)]
    );
}
