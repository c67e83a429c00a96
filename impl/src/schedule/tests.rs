extern crate std;
use super::*;
use crate::tests::xorshift;
use std::vec::Vec;

mod parts;
mod root;
mod search;

fn first(p: &ScheduleParams) -> Rough {
    Schedule::new(p).first()
}

fn next(p: &ScheduleParams, prev: &Rough) -> Option<Rough> {
    Schedule::new(p).next(prev)
}

fn rough_pass_count(p: &ScheduleParams, limit: u32) -> Option<u32> {
    Schedule::new(p).rough_pass_count(limit)
}

/// G76.DEPTH.1: the guess only saves work — any guess gives the exact rounded root, also
/// one far from it (the guess is checked, not trusted). Every v ≤ 20 000 with every guess
/// up to √v + 3; large v (up to 2^126) with guesses within and just beyond the walk
/// below the root, above it, and at the extremes; the largest root from guesses about 2^63;
/// the 64-bit walk's edges (guesses about 2^31, v about 2^64).
#[test]
#[cfg(not(feature = "planted-depth-bug"))]
fn root_with_any_guess_is_the_rounded_root() {
    let exact = |v: u128| u64::try_from(sqrt_round(v)).unwrap();
    for v in 0..=20_000u128 {
        let isqrt = u64::try_from(crate::fixed::isqrt(v)).unwrap();
        for hint in (0..=isqrt + 3).chain([u64::MAX, 1 << 32, 1 << 63]) {
            assert_eq!(root(v, hint), exact(v), "v = {v}, guess {hint}");
        }
    }
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    for _ in 0..20_000 {
        let x = xorshift(&mut s);
        let v = (u128::from(x) << 62 ^ u128::from(x.rotate_left(17))) >> (x % 64);
        let e = exact(v);
        let below = (1..=ROOT_WALK + 1).map(|k| e.saturating_sub(u64::from(k)));
        for hint in below.chain([e, e + 1, e + 2, 0, u64::MAX]) {
            assert_eq!(root(v, hint), e, "v = {v}, guess {hint}");
        }
    }
    // The edges of the rounding: r² − r + 1 and r² + r round to r; r² + r + 1 to r + 1.
    for r in [1u64, 2, 3, 1_000, 1 << 40, (1 << 63) - 1] {
        let (rr, sq) = (u128::from(r), u128::from(r) * u128::from(r));
        for hint in [r - 1, r, r + 1, r.saturating_sub(3), r.saturating_sub(4)] {
            assert_eq!(root(sq - rr + 1, hint), r);
            assert_eq!(root(sq + rr, hint), r);
            assert_eq!(root(sq + rr + 1, hint), r + 1);
        }
    }
    let (top, m) = (u128::from(u64::MAX), u64::MAX);
    for hint in [m - 4, m - 3, m - 1, m, (1 << 63) - 1, 1 << 63] {
        assert_eq!(root(top * top + top, hint), m);
    }
    // The 64-bit walk's edges: guesses about 2^31 (c² + c near 2^62), v about 2^64.
    for r in [(1u64 << 31) - 2, (1 << 31) - 1, 1 << 31, (1 << 31) + 1, (1 << 32) - 1, 1 << 32] {
        let (rr, sq) = (u128::from(r), u128::from(r) * u128::from(r));
        for v in [sq - rr + 1, sq, sq + rr, sq + rr + 1] {
            for hint in [r - 3, r - 1, r, r + 1] {
                assert_eq!(root(v, hint), exact(v), "v = {v}, guess {hint}");
            }
        }
    }
    for v in [u128::from(u64::MAX) - 1, u128::from(u64::MAX), 1 << 64, (1 << 64) + 1] {
        let e = exact(v);
        for hint in [e - 2, e - 1, e] {
            assert_eq!(root(v, hint), e, "v = {v}, guess {hint}");
        }
    }
}

/// G76.DEPTH.MIN: the closed-form switch pass ⌊a²/c²⌋ + 2 (legal words) is the one the
/// binary search finds with 256-bit products, on random values and at the tie Δd = Δdmin;
/// and the search's pass is the first where the test holds, also where a and c exceed
/// 64 bits.
#[test]
fn closed_form_switch_pass_is_the_searched_one() {
    let searched = |dd: u64, dmin: u64| {
        let (d, m) = (u128::from(dd), u128::from(dmin));
        if d * d < m * m {
            1
        } else {
            switch_search(d * d - m * m, 2 * d * m)
        }
    };
    let within_search = |s: u64| if s > 1 << 32 { NEVER } else { s };
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = || xorshift(&mut s);
    for _ in 0..20_000 {
        // Δd, Δdmin < 2^31: a and c fit 64 bits.
        let dd = 1 + ((next() >> 33) >> (next() % 31));
        let dmin = 1 + ((next() >> 33) >> (next() % 31));
        assert_eq!(within_search(switch_pass(dd, dmin)), searched(dd, dmin), "Δd {dd} Δdmin {dmin}");
    }
    for d in [1u64, 7, 1000, 999_999_999] {
        assert_eq!(switch_pass(d, d), 2, "Δd = Δdmin: pass 1 ties (no switch), pass 2 switches");
        assert_eq!(searched(d, d), 2);
    }
    assert_eq!(switch_pass(5, 0), NEVER);
    for _ in 0..2_000 {
        let (a, c) = (u128::from(next()) << (next() % 62), 1 + (u128::from(next()) << (next() % 63)));
        let found = switch_search(a, c);
        if found != NEVER {
            assert!(switch_test(a, c, found - 1), "{a} {c}: holds at {found}");
            assert!(found == 1 || !switch_test(a, c, found - 2), "{a} {c}: not before {found}");
        } else {
            assert!(!switch_test(a, c, (1 << 32) - 1), "{a} {c}: never within 2^32");
        }
    }
}

fn all(p: &ScheduleParams) -> Vec<Rough> {
    let mut v = Vec::new();
    let mut r = first(p);
    loop {
        v.push(r);
        match next(p, &r) {
            Some(n) => r = n,
            None => break,
        }
        assert!(v.len() < 1_000_000);
    }
    v
}

fn depths(p: &ScheduleParams) -> Vec<i64> {
    all(p).iter().map(|r| r.depth).collect()
}

/// F76.EX1: Δd = 0.7, Δdmin = 0.1, k − d = 2.4 − 0.1 = 2.3 (µm).
#[test]
fn f76_ex1() {
    let p = ScheduleParams { first_cut: 700, min_cut: 100, target: 2300, constant: false };
    assert_eq!(depths(&p), [700, 990, 1212, 1400, 1565, 1715, 1852, 1980, 2100, 2214, 2300]);
    let rs = all(&p);
    assert!(rs[..10].iter().all(|r| r.rule == Rule::G76Depth1 && !r.last));
    assert_eq!((rs[10].n, rs[10].last, rs[10].rule), (11, true, Rule::G76DepthLast));
    assert_eq!(rough_pass_count(&p, 10_000), Some(11));
    assert_eq!(rough_pass_count(&p, 11), Some(11));
    assert_eq!(rough_pass_count(&p, 10), None);
}

/// G76.EXAMPLE: Δd = 1.8, Δdmin = 0.15, k − d = 3 − 0.5 = 2.5 mm.
#[test]
fn g76_example() {
    let p = ScheduleParams { first_cut: 1800, min_cut: 150, target: 2500, constant: false };
    // √2·1.8 = 2.5456 ≥ 2.5: clamped at pass 2.
    assert_eq!(depths(&p), [1800, 2500]);
}

/// G76.DEPTH.MIN: Δd = 1, Δdmin = 0.3. (√n − √(n−1)) < 0.3 first at n = 4
/// (√4 − √3 = 0.268); from then each cut is 0.3 from √3 = 1.732.
#[test]
fn switch_to_minimum() {
    let p = ScheduleParams { first_cut: 1000, min_cut: 300, target: 3000, constant: false };
    let rs = all(&p);
    let d: Vec<i64> = rs.iter().map(|r| r.depth).collect();
    assert_eq!(d, [1000, 1414, 1732, 2032, 2332, 2632, 2932, 3000]);
    assert_eq!(rs[2].rule, Rule::G76Depth1);
    assert_eq!(rs[3].rule, Rule::G76DepthMin);
    assert_eq!(rs[7].rule, Rule::G76DepthLast);
}

/// Boundary of the switch: (√n − √(n−1))·Δd = Δdmin exactly is not a switch (strict <).
/// Δd = 2, Δdmin = 2(√2 − 1) is irrational; use n = 1: Δd = Δdmin is no switch.
#[test]
fn equal_first_cut_and_minimum() {
    let p = ScheduleParams { first_cut: 500, min_cut: 500, target: 10_000, constant: false };
    let rs = all(&p);
    assert_eq!(rs[0].rule, Rule::G76Depth1);
    // n = 2: (√2 − 1)·500 = 207 < 500: switch, depth = 500 + 500.
    assert_eq!(rs[1].depth, 1000);
    assert_eq!(rs[1].rule, Rule::G76DepthMin);
    assert_eq!(rs.last().unwrap().depth, 10_000);
    assert_eq!(rs.len(), 20);
    // Δd < Δdmin: minimum from the first pass.
    let p = ScheduleParams { first_cut: 100, min_cut: 300, target: 1000, constant: false };
    assert_eq!(depths(&p), [300, 600, 900, 1000]);
    assert_eq!(first(&p).rule, Rule::G76DepthMin);
}

/// Δdmin = 0: no minimum, the depths follow √n·Δd to the target.
#[test]
fn no_minimum() {
    let p = ScheduleParams { first_cut: 10, min_cut: 0, target: 100, constant: false };
    let d = depths(&p);
    // round(10·√n) ≥ 100 first at n = 100 (n = 99: 99.499 → 99).
    assert_eq!(d.len(), 100);
    assert_eq!(d[98], 99);
    assert_eq!(d[99], 100);
    assert!(d.windows(2).all(|w| w[0] <= w[1]));
    // The pass count grows as (T/Δd)²: bounded by the limit.
    let p = ScheduleParams { first_cut: 1, min_cut: 0, target: 999_999_999, constant: false };
    assert_eq!(rough_pass_count(&p, 10_000), None);
    assert_eq!(rough_pass_count(&p, 0), None);
}

/// The k − d comparison is made on the rounded depth: 0.7·√10.796 … rounds to T.
#[test]
fn rounded_depth_reaching_target_is_last() {
    // Δd = 1000, n = 2: √2·1000 = 1414.21 → 1414. T = 1414: pass 2 is last at 1414.
    let p = ScheduleParams { first_cut: 1000, min_cut: 0, target: 1414, constant: false };
    assert_eq!(depths(&p), [1000, 1414]);
    assert!(all(&p)[1].last);
    // T = 1415: 1414 < 1415, pass 3 (1732) clamps.
    let p = ScheduleParams { target: 1415, ..p };
    assert_eq!(depths(&p), [1000, 1414, 1415]);
    // √n·Δd = 1414.5 exactly cannot happen; half up: 0.5·√... use Δd = 1, n = 2: 1.414 → 1.
    let p = ScheduleParams { first_cut: 1, min_cut: 0, target: 5, constant: false };
    assert_eq!(depths(&p), [1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 3, 3, 4, 4, 4, 4, 4, 4, 4, 4, 5]);
}

/// G78.DEPTHMODE 0: n·Δd, the last clamped.
#[test]
fn constant_mode() {
    let p = ScheduleParams { first_cut: 400, min_cut: 80, target: 1250, constant: true };
    assert_eq!(depths(&p), [400, 800, 1200, 1250]);
    let rs = all(&p);
    assert_eq!(rs[0].rule, Rule::G78DepthMode);
    assert_eq!(rs[3].rule, Rule::G76DepthLast);
    let p = ScheduleParams { first_cut: 400, min_cut: 80, target: 1200, constant: true };
    assert_eq!(depths(&p), [400, 800, 1200]);
    assert_eq!(rough_pass_count(&p, 3), Some(3));
    assert_eq!(rough_pass_count(&p, 2), None);
}

/// A first cut at or beyond the target is the only rough pass.
#[test]
fn single_pass() {
    for constant in [false, true] {
        let p = ScheduleParams { first_cut: 5000, min_cut: 100, target: 1, constant };
        let r = first(&p);
        assert_eq!((r.n, r.depth, r.last), (1, 1, true));
        assert_eq!(next(&p, &r), None);
        assert_eq!(rough_pass_count(&p, 1), Some(1));
        assert_eq!(rough_pass_count(&p, 0), None);
    }
}

/// Brute-force cross-check against a direct reading of the register on small values:
/// the switch pass found by exact comparison of squares, then the depth formula.
#[test]
fn matches_direct_formula() {
    fn direct(dd: i64, dmin: i64, t: i64) -> Vec<i64> {
        let (dd, dmin, t) = (dd as i128, dmin as i128, t as i128);
        let isqrt_round = |n: i128| -> i128 {
            let mut r = 0i128;
            while (r + 1) * (r + 1) <= n {
                r += 1;
            }
            if n - r * r > r { r + 1 } else { r }
        };
        let mut s: Option<i128> = None;
        let mut out = Vec::new();
        let mut n = 1i128;
        loop {
            if s.is_none() {
                let a = dd * dd - dmin * dmin;
                if dmin > 0 && (a < 0 || a * a < 4 * dd * dd * dmin * dmin * (n - 1)) {
                    s = Some(n);
                }
            }
            let d = match s {
                None => isqrt_round(n * dd * dd),
                Some(s) => isqrt_round((s - 1) * dd * dd) + (n - s + 1) * dmin,
            };
            if d >= t {
                out.push(t as i64);
                return out;
            }
            out.push(d as i64);
            n += 1;
        }
    }
    for dd in 1..=12 {
        for dmin in 0..=12 {
            for t in 1..=60 {
                let p = ScheduleParams { first_cut: dd, min_cut: dmin, target: t, constant: false };
                let got = depths(&p);
                assert_eq!(got, direct(dd, dmin, t), "dd {dd} dmin {dmin} t {t}");
                if dmin >= 1 {
                    assert!(got.windows(2).all(|w| w[0] < w[1]));
                }
                let count = u32::try_from(got.len()).unwrap();
                assert_eq!(rough_pass_count(&p, count), Some(count));
                assert_eq!(rough_pass_count(&p, count - 1), None);
            }
        }
    }
}

/// The closed-form pass count equals the count found by stepping through the schedule, on
/// small values exhaustively and on large ones at random, with limits around the count.
#[test]
fn closed_form_count_matches_steps() {
    fn by_steps(p: &ScheduleParams, limit: u32) -> Option<u32> {
        let mut r = first(p);
        let mut count = 1u32;
        while !r.last {
            if count > limit {
                return None;
            }
            r = next(p, &r)?;
            count += 1;
        }
        (count <= limit).then_some(count)
    }
    let check = |p: ScheduleParams| {
        let full = by_steps(&p, 20_001);
        for limit in [0, 1, 2, 10, 1000, 20_000] {
            let expected = full.filter(|&c| c <= limit);
            assert_eq!(rough_pass_count(&p, limit), expected, "{p:?} limit {limit}");
        }
        if let Some(c) = full {
            assert_eq!(rough_pass_count(&p, c), Some(c), "{p:?}");
            assert_eq!(rough_pass_count(&p, c - 1), None, "{p:?}");
        }
    };
    for dd in 1..=9 {
        for dmin in 0..=9 {
            for t in 1..=90 {
                for constant in [false, true] {
                    check(ScheduleParams { first_cut: dd, min_cut: dmin, target: t, constant });
                }
            }
        }
    }
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let mut rnd = |max: u64| 1 + (xorshift(&mut s) % max) as i64;
    for _ in 0..2000 {
        let scale = [10, 1000, 100_000, 999_999_999][rnd(4) as usize - 1];
        let p = ScheduleParams {
            first_cut: rnd(scale),
            min_cut: rnd(scale) - 1,
            target: rnd(999_999_999),
            constant: rnd(4) == 1,
        };
        check(p);
    }
}

/// Extreme values: total, no panic, ends at the target.
#[test]
fn extremes() {
    for (dd, dmin, t) in [
        (i64::MAX, i64::MAX, i64::MAX),
        (1, i64::MAX, i64::MAX),
        (i64::MAX, 1, i64::MAX),
        (1, 1, i64::MAX),
        (i64::MIN, i64::MIN, i64::MIN),
        (999_999_999, 999_999_999, 999_999_999),
        (1, 0, 999_999_999),
    ] {
        for constant in [false, true] {
            let p = ScheduleParams { first_cut: dd, min_cut: dmin, target: t, constant };
            let _ = rough_pass_count(&p, 1000);
            let mut r = first(&p);
            for _ in 0..1000 {
                match next(&p, &r) {
                    Some(n) => {
                        assert!(n.depth >= r.depth);
                        r = n;
                    }
                    None => break,
                }
            }
        }
    }
    let p = ScheduleParams { first_cut: 1, min_cut: 0, target: 10, constant: false };
    let r = Rough { n: u32::MAX, depth: 5, last: false, rule: Rule::G76Depth1 };
    assert_eq!(next(&p, &r), None);
}
