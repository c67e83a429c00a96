use super::*;
extern crate std;
use std::vec::Vec;

fn depths(p: i64, q: i64) -> Vec<i64> {
    let sp = SplitParams { depth: p, allowance: q };
    let mut r = first(&sp);
    let mut out = std::vec![r.depth];
    while let Some(n) = next(&sp, &r) {
        assert_eq!(n.n, r.n + 1);
        out.push(n.depth);
        r = n;
    }
    assert!(r.last);
    assert_eq!(pass_count(&sp, u32::MAX), Some(u32::try_from(out.len()).unwrap()));
    out
}

/// G162.SPLIT: P2.5 Q1 — the manual's 1, 2, 2.25, 2.375, 2.4375, 2.5 on the ISC grid
/// (0.0001 mm) and 2.438 in place of 2.4375 on ISB (2.4375 rounds half up).
#[test]
fn manual_split() {
    assert_eq!(depths(25_000, 10_000), [10_000, 20_000, 22_500, 23_750, 24_375, 25_000]);
    assert_eq!(depths(2_500, 1_000), [1_000, 2_000, 2_250, 2_375, 2_438, 2_500]);
}

/// The register's examples: D = 0 (no split), a remainder below one increment per cut,
/// Q > P, and the worked example P1.2 Q0.5.
#[test]
fn register_examples() {
    assert_eq!(depths(3_000, 1_000), [1_000, 2_000, 3_000]);
    assert_eq!(depths(3, 2), [2, 3]);
    assert_eq!(depths(500, 1_000), [250, 375, 438, 500]);
    assert_eq!(depths(1_200, 500), [500, 1_000, 1_100, 1_150, 1_175, 1_200]);
    assert_eq!(depths(1, 1), [1]);
    assert_eq!(depths(1, 5), [1]);
    assert_eq!(depths(2, 5), [1, 2]);
    let sp = SplitParams { depth: 999_999_999, allowance: 1 };
    assert_eq!(pass_count(&sp, 10_000), None);
    assert_eq!(pass_count(&sp, u32::MAX), Some(999_999_999));
}

/// G162.F: the manual's cone — 2 mm along a cone 50 mm long with a 20 mm diameter
/// difference is F = 2·50/√(50² + 10²) = 1.96116… mm → 1.9612 (lead counts of 0.0001 mm),
/// the manual's 1.96. A cylinder keeps the pitch; a steep cone measures along X.
#[test]
fn manual_pitch_example() {
    assert_eq!(pitch_along_long_axis(20_000, 50, 10), Some(19_612));
    assert_eq!(pitch_along_long_axis(20_000, 50_000, 10_000), Some(19_612));
    assert_eq!(pitch_along_long_axis(20_000, 50, 0), Some(20_000));
    // 3-4-5: exactly 0.8·F; half-way cases round up: 5·4/5 = 4, 1·1/√2 = 0.707 → 1.
    assert_eq!(pitch_along_long_axis(5, 4, 3), Some(4));
    assert_eq!(pitch_along_long_axis(1, 1, 1), Some(1));
    assert_eq!(pitch_along_long_axis(1, 0, 0), None);
    // Brute force against the exact bracket for small values.
    for f in 1..40u64 {
        for l in 1..25u64 {
            for r in 0..25u64 {
                let m = u128::from(pitch_along_long_axis(f, l, r).unwrap());
                let (x2, s) = (4 * u128::from(f * f * l * l), u128::from(l * l + r * r));
                assert!(m == 0 || (2 * m - 1) * (2 * m - 1) * s <= x2, "{f} {l} {r}");
                assert!(x2 < (2 * m + 1) * (2 * m + 1) * s, "{f} {l} {r}");
            }
        }
    }
    // The largest values fit: F = 9999 mm, L and r = N.
    assert!(pitch_along_long_axis(99_990_000, 999_999_999, 999_999_999).is_some());
}

/// Every P, Q ≤ 60: strictly increasing depths ending exactly at P, full cuts of Q first,
/// split cuts summing to the remainder, each split target within half an increment of its
/// exact value, and the pass count agreeing with the iteration.
#[test]
fn split_properties_small() {
    for p in 1..=60i64 {
        for q in 1..=60i64 {
            let d = depths(p, q);
            assert!(d.windows(2).all(|w| w[0] < w[1]), "{p} {q} {d:?}");
            assert_eq!(d.last(), Some(&p));
            let k = p / q;
            for (i, &x) in d.iter().enumerate().take(usize::try_from(k).unwrap()) {
                assert_eq!(x, (i as i64 + 1) * q);
            }
            assert!(d.len() <= usize::try_from(k).unwrap() + 4);
        }
    }
}

mod programs;
mod random;
mod readings;

/// `Cycle::at_pass(r)` (the proof harnesses' state constructor) is the state the running cycle
/// reaches after pass r's five moves: from there it emits exactly the rest of the real run, for
/// every pass of every P, Q ≤ 12; and the run's passes are `first`/`next`'s.
#[test]
fn at_pass_is_the_state_after_a_pass() {
    use cycle_vocab::Config;
    let run = |mut c: Cycle, pos: &mut (i64, i64)| {
        let mut out = Vec::new();
        while let Some(e) = c.next_event(pos) {
            out.push(e);
        }
        out
    };
    for p in 1..=12i64 {
        for q in 1..=12i64 {
            let w = Words { x: 1000, z: -5000, incremental: false, h: 100, split: Some(SplitParams { depth: p, allowance: q }), v: 10, taper: 40, a: 300, lead: 15_000, b: 0, i: 0, j: 360_000 };
            let start = (2000, 0);
            let c0 = cycle(&Config::default(), &crate::config::DEFAULTS, &w, start, 7).unwrap();
            let mut pos = start;
            let all = run(c0, &mut pos);
            let (mut passes, mut checked) = (0, 0);
            for (i, e) in all.iter().enumerate() {
                let Event::Pass(h) = e else { continue };
                passes += 1;
                // The pass before this header, as the cycle held it: the headers are 6 events apart.
                if let Some(Event::Pass(prev)) = i.checked_sub(6).map(|j| all[j]) {
                    let mut c = c0;
                    let mut at = start;
                    while c.pass().n != prev.index {
                        c.next_event(&mut at);
                    }
                    let r = c.pass();
                    assert_eq!(run(c0.at_pass(r), &mut start.clone()), all[i..], "P{p} Q{q} after pass {}", r.n);
                    checked += 1;
                }
                assert_eq!(h.index, passes);
            }
            assert_eq!(Some(passes), pass_count(&SplitParams { depth: p, allowance: q }, u32::MAX));
            assert_eq!(checked + 1, passes, "P{p} Q{q}: every pass after the first checked");
            // The cycle's passes (its own fast path for full passes included) are the split's.
            let run_depths: Vec<i64> = all.iter().filter_map(|e| if let Event::Pass(h) = e { Some(h.diameter_depth / 2) } else { None }).collect();
            assert_eq!(run_depths, depths(p, q), "P{p} Q{q}: the cycle's passes are first/next's");
        }
    }
}

/// The cycle steps its full passes Q, 2Q, …, kQ itself (`Cycle::next_pass`, no division) and
/// asks `split::next` only after pass k (k ≥ 1) — for the split passes and the end — so a whole
/// run calls `next` N − (k − 1) times for N passes (N when k = 0), through `next_event` and
/// through `fill` alike (`crate::probe` counts the calls on this thread). The positive control:
/// stepping with `first`/`next` alone calls `next` once per pass.
#[test]
fn full_passes_are_stepped_without_split_next() {
    use crate::probe;
    use cycle_vocab::Config;
    for (p, q) in [(2_500, 1_000), (3_000, 1_000), (12, 5), (7, 2), (5, 8), (40, 3)] {
        let sp = SplitParams { depth: p, allowance: q };
        let w = Words { x: 1000, z: -5000, incremental: false, h: 100, split: Some(sp), v: 10, taper: 40, a: 300, lead: 15_000, b: 0, i: 0, j: 360_000 };
        let start = (2000, 0);
        let c0 = cycle(&Config::default(), &crate::config::DEFAULTS, &w, start, 7).unwrap();
        let n = u64::try_from(depths(p, q).len()).unwrap();
        let k = u64::try_from(p / q).unwrap();
        let want = usize::try_from(n - k.saturating_sub(1)).unwrap();
        // The positive control: `depths` steps with `next` alone, once per pass.
        let before = probe::calls();
        depths(p, q);
        assert_eq!(probe::calls() - before, usize::try_from(n).unwrap(), "P{p} Q{q}: the control");
        let (mut c, mut pos, before) = (c0, start, probe::calls());
        while c.next_event(&mut pos).is_some() {}
        assert_eq!(probe::calls() - before, want, "P{p} Q{q}: next_event");
        for size in [1, 6, 7, 64] {
            let filler = Event::Move(Move::rapid(0, 0, Rule::PrjTrace));
            let (mut c, mut pos, mut out, before) = (c0, start, std::vec![filler; size], probe::calls());
            let mut calls = 0;
            while !c.fill(&mut pos, &mut out).1 {
                calls += 1;
                assert!(calls < 1_000, "P{p} Q{q}: fill, buffer of {size}: not done");
            }
            assert_eq!(probe::calls() - before, want, "P{p} Q{q}: fill, buffer of {size}");
        }
    }
}
