//! The driver: `cycle_impl::schedule` (the 64-bit production code) against the lemmas' model
//! (src/model.rs) — every pass's number, depth, `last` flag and rule, `None` after the last
//! pass, and `rough_pass_count` at limits around the count. Bounded-exhaustive over small
//! parameters (whole schedules), random over the full legal ranges with a fixed seed (passes
//! reached through `next`, which is pure in the pass before), and the edges. Negative control:
//! the wrong model variants disagree with production.

use cycle_impl::schedule::{Rough, Schedule, ScheduleParams};
use cycle_smt::model::{Model, Params, Pass, Phase, Rng, Variant, N};
use cycle_vocab::Rule;

/// The production schedule of the model's parameters.
fn production(m: &Model) -> Schedule {
    let p = m.p;
    Schedule::new(&ScheduleParams { first_cut: p.dd, min_cut: p.dm, target: p.t, constant: p.constant })
}

/// The model's pass as production's `Rough`: the rule that set the depth, G76.DEPTH.LAST when
/// clamped.
fn expected(pass: Pass) -> Rough {
    let rule = match pass.phase {
        _ if pass.last => Rule::G76DepthLast,
        Phase::Root => Rule::G76Depth1,
        Phase::Min => Rule::G76DepthMin,
        Phase::Constant => Rule::G78DepthMode,
    };
    let n = u32::try_from(pass.n).expect("pass number below 2^32");
    Rough { n, depth: i64::try_from(pass.depth).expect("depth ≤ T"), last: pass.last, rule }
}

/// Production's pass n ≥ 1 (n < 2^32): `first`, or `next` of the model's pass n − 1 (not last).
fn check_pass(m: &Model, s: &Schedule, n: i128) -> Result<(), String> {
    let got = if n == 1 { Some(s.first()) } else { s.next(&expected(m.pass(n - 1))) };
    let want = expected(m.pass(n));
    if got != Some(want) {
        return Err(format!("{:?}: pass {n}: production {got:?}, model {want:?}", m.p));
    }
    if want.last && s.next(&want).is_some() {
        return Err(format!("{:?}: a pass after the last one ({n})", m.p));
    }
    Ok(())
}

/// `rough_pass_count(limit)` is the model's count when it is ≤ limit, `None` above.
fn check_count(m: &Model, s: &Schedule) -> Result<(), String> {
    let count = m.rough_count();
    let near = [count - 1, count, count + 1].map(|c| u32::try_from(c.max(0)).unwrap_or(u32::MAX));
    for limit in near.into_iter().chain([0, 1, 10_000, u32::MAX]) {
        let want = u32::try_from(count).ok().filter(|&c| c <= limit);
        let got = s.rough_pass_count(limit);
        if got != want {
            return Err(format!("{:?}: rough_pass_count({limit}) = {got:?}, model count {count}", m.p));
        }
    }
    Ok(())
}

/// The whole schedule stepped from `first`, pass by pass, against the model, and the count.
fn check_whole(m: &Model) -> Result<(), String> {
    let s = production(m);
    let count = m.rough_count();
    let mut got = s.first();
    for n in 1..=count {
        let want = expected(m.pass(n));
        if got != want {
            return Err(format!("{:?}: pass {n}: production {got:?}, model {want:?}", m.p));
        }
        match s.next(&got) {
            Some(next) if n < count => got = next,
            None if n == count => {}
            other => return Err(format!("{:?}: after pass {n} of {count}: {other:?}", m.p)),
        }
    }
    check_count(m, &s)
}

/// The passes worth checking in a long schedule: the ends, around the switch, and random.
fn passes_of_interest(m: &Model, rng: &mut Rng) -> Vec<i128> {
    let top = m.rough_count().min(i128::from(u32::MAX));
    let s = m.s.unwrap_or(1);
    let mut ns = vec![1, 2, 3, s - 1, s, s + 1, s + 2, top - 1, top];
    ns.extend((0..6).map(|_| 1 + (i128::from(rng.next_u64()) % top)));
    ns.retain(|&n| (1..=top).contains(&n));
    ns
}

fn check_long(m: &Model, rng: &mut Rng) -> Result<(), String> {
    let s = production(m);
    for n in passes_of_interest(m, rng) {
        check_pass(m, &s, n)?;
    }
    check_count(m, &s)
}

fn exact(dd: i64, dm: i64, t: i64, constant: bool) -> Model {
    Model::new(Params { dd, dm, t, constant }, Variant::Exact)
}

/// Every Δd ≤ 20, Δdmin ≤ 20, T ≤ 200, both modes: every pass of every schedule.
#[test]
fn bounded_exhaustive_whole_schedules() {
    let mut passes = 0;
    for dd in 1..=20 {
        for dm in 0..=20 {
            for t in 1..=200 {
                for constant in [false, true] {
                    let m = exact(dd, dm, t, constant);
                    check_whole(&m).unwrap();
                    passes += m.rough_count();
                }
            }
        }
    }
    println!("bounded-exhaustive: 20 × 21 × 200 × 2 schedules, {passes} passes");
}

/// Random legal words (Δd, T in 1…N, Δdmin in 0…N, one in four constant), fixed seed: whole
/// schedules up to 5 000 passes, else the passes of interest through `next`.
#[test]
fn random_full_ranges() {
    let mut rng = Rng(0x0ddc_0ffe_e5ee_d123);
    for _ in 0..30_000 {
        let (dd, dm, t) = (rng.range(1, N), rng.range(0, N), rng.range(1, N));
        let m = exact(dd, dm, t, rng.next_u64() % 4 == 0);
        if m.rough_count() <= 5_000 {
            check_whole(&m).unwrap();
        } else {
            check_long(&m, &mut rng).unwrap();
        }
    }
}

/// Rounding ties: radicands n·Δd² = r² + r (round down to r) and r² + r + 1 (up to r + 1),
/// with r = j·Δd² (then n = j·(j·Δd² + 1)), T around r; Δd = 1 reaches every radicand.
#[test]
fn edges_rounding_ties() {
    let mut rng = Rng(7);
    for dd in [1i64, 2, 3, 7, 10, 1000, 31_622] {
        for j in [1i64, 2, 5, 100, 10_000] {
            let r = i128::from(j) * i128::from(dd) * i128::from(dd);
            if r + 2 > i128::from(N) {
                continue;
            }
            let n = i128::from(j) * (r + 1);
            for t in [r - 1, r, r + 1, r + 2, i128::from(N)].map(|t| t as i64).into_iter().filter(|&t| t >= 1) {
                let m = exact(dd, 0, t, false);
                let s = production(&m);
                assert_eq!(m.depth_u(n).0, r, "tie rounds down");
                assert_eq!(m.depth_u(n + 1).0, r + 1);
                for k in [n - 1, n, n + 1, n + 2] {
                    if k >= 1 && k <= m.rough_count() && k <= i128::from(u32::MAX) {
                        check_pass(&m, &s, k).unwrap();
                    }
                }
                check_long(&m, &mut rng).unwrap();
            }
        }
    }
}

/// The switch pass: Δdmin = Δd (s = 2), Δdmin = Δd + 1 (s = 1), Δdmin = 1 (s large), and
/// random pairs; passes s − 1, s, s + 1 with T far and T just past the depth at s.
#[test]
fn edges_switch_pass() {
    let mut rng = Rng(11);
    let mut pairs = vec![(1, 1), (1, 2), (N, N), (N - 1, N), (N, 1), (700, 100), (1000, 300)];
    pairs.extend((0..2_000).map(|_| (rng.range(1, N), rng.range(1, N))));
    for (dd, dm) in pairs {
        let far = exact(dd, dm, N, false);
        let s = far.s.expect("a minimum");
        if s <= i128::from(u32::MAX) - 2 {
            let at_s = far.depth_u(s).0;
            for t in [N, at_s as i64, at_s as i64 + 1, at_s as i64 - 1].into_iter().filter(|t| (1..=N).contains(t)) {
                check_long(&exact(dd, dm, t, false), &mut rng).unwrap();
            }
        }
    }
}

/// T reached exactly: T = the unclamped depth of some pass (that pass is last at T, not
/// clamped from above), and T one more (the next pass clamps).
#[test]
fn edges_target_reached_exactly() {
    let mut rng = Rng(13);
    for _ in 0..5_000 {
        let (dd, dm, constant) = (rng.range(1, N), rng.range(0, N), rng.next_u64() % 4 == 0);
        let far = exact(dd, dm, N, constant);
        let n = 1 + i128::from(rng.next_u64()) % far.rough_count().min(i128::from(u32::MAX) - 1);
        let u = far.depth_u(n).0 as i64;
        for t in [u, u + 1].into_iter().filter(|t| (1..=N).contains(t)) {
            let m = exact(dd, dm, t, constant);
            let s = production(&m);
            assert_eq!(m.pass(n).depth, i128::from(u), "T = u: depth exactly T; T = u + 1: below");
            for k in [n, n + 1].into_iter().filter(|&k| k <= m.rough_count()) {
                check_pass(&m, &s, k).unwrap();
            }
            check_long(&m, &mut rng).unwrap();
        }
    }
}

/// The largest words and the smallest: every combination of {1, 2, N − 1, N} for Δd and T and
/// {0, 1, N − 1, N} for Δdmin, both modes (counts up to about 10^18: `None` for every limit).
#[test]
fn edges_largest_words() {
    let mut rng = Rng(17);
    for dd in [1, 2, N - 1, N] {
        for dm in [0, 1, N - 1, N] {
            for t in [1, 2, N - 1, N] {
                for constant in [false, true] {
                    check_long(&exact(dd, dm, t, constant), &mut rng).unwrap();
                }
            }
        }
    }
}

/// Negative control: each wrong model variant disagrees with production somewhere in the
/// bounded domain (so agreement with the exact model is not vacuous).
#[test]
fn negative_control_wrong_models_disagree() {
    for variant in [Variant::TiesUp, Variant::SwitchLate] {
        let found = (1..=8).find_map(|dd| {
            (0..=8).find_map(|dm| (1..=60).find_map(|t| check_whole(&Model::new(Params { dd, dm, t, constant: false }, variant)).err()))
        });
        println!("negative control {variant:?}: {}", found.as_deref().unwrap_or("NO DISAGREEMENT"));
        assert!(found.is_some(), "{variant:?} agrees with production everywhere");
    }
}

/// Where the 64-bit code and the model part (not a defect, and out of reach): production's
/// pass numbers are `u32`, so a schedule longer than 2^32 − 1 passes (Δdmin = 0, T ≫ Δd) ends
/// with `None` after pass 2^32 − 1 where the model goes on. PRJ.MAXPASS (at most 1 000 000
/// passes, checked first with `rough_pass_count`, which says `None` here) keeps it unreachable.
#[test]
fn pass_numbers_end_at_u32_max() {
    let m = exact(1, 0, N, false);
    let s = production(&m);
    let top = i128::from(u32::MAX);
    assert!(m.rough_count() > top && !m.pass(top).last);
    check_pass(&m, &s, top).unwrap();
    assert_eq!(s.next(&expected(m.pass(top))), None);
    assert_eq!(s.rough_pass_count(u32::MAX), None);
}
