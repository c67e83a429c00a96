//! The model (src/model.rs) against the properties the lemmas state, directly: a wrong
//! transcription of the lemmas' definitions fails here even where production happens to agree.
//! Bounded-exhaustive over small parameters, and random with a fixed seed.

use cycle_smt::model::{self, is_root, root, switch_pass, switches, Model, Params, Phase, Pass, Rng, Variant, N};

/// The model's schedule by iterating its pass definition until the last pass (lemma 10).
fn iterate(m: &Model, most: i128) -> Option<Vec<Pass>> {
    let mut passes = Vec::new();
    for n in 1..=most {
        let pass = m.pass(n);
        passes.push(pass);
        if pass.last {
            return Some(passes);
        }
    }
    None
}

/// The done-when list of lemma 12 and the count of lemma 11 on one iterated schedule.
fn check_schedule(m: &Model, passes: &[Pass]) {
    let (t, dd, dm) = (i128::from(m.p.t), i128::from(m.p.dd), i128::from(m.p.dm));
    assert_eq!(m.rough_count(), passes.len() as i128, "{m:?}: closed-form count");
    let mut before = 0;
    for (i, pass) in passes.iter().enumerate() {
        let is_last = i + 1 == passes.len();
        let cut = pass.depth - before;
        assert_eq!(pass.n, i as i128 + 1);
        assert_eq!(pass.last, is_last, "{m:?}: only the final pass is last");
        assert!(pass.depth >= 1 && pass.depth <= t, "{m:?}: pass {} depth {}", pass.n, pass.depth);
        assert!(cut >= 0, "{m:?}: pass {} decreases", pass.n);
        if dm >= 1 || m.p.constant {
            assert!(cut >= 1, "{m:?}: pass {} does not increase", pass.n);
        }
        if is_last {
            assert_eq!(pass.depth, t, "{m:?}: the last depth is T");
        } else if m.p.constant {
            assert_eq!(cut, dd, "{m:?}: constant cut");
        } else {
            assert!(cut >= dm, "{m:?}: pass {} cuts {cut} < Δdmin", pass.n);
            if pass.phase == Phase::Min {
                assert_eq!(cut, dm, "{m:?}: pass {} after the switch", pass.n);
            }
        }
        before = pass.depth;
    }
}

/// round(√v) by the bracket (lemmas 01, 02): the model's root satisfies it and its neighbours
/// do not; it agrees with the correctly rounded f64 square root where that is exact enough.
#[test]
fn root_is_the_bracket() {
    let check = |v: i128| {
        let r = root(v, Variant::Exact);
        assert!(is_root(v, r) && !is_root(v, r - 1) && !is_root(v, r + 1), "v = {v}: {r}");
        if v < 1 << 50 {
            assert_eq!(r, (v as f64).sqrt().round() as i128, "v = {v}");
        }
    };
    (0..=300_000).for_each(check);
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for _ in 0..100_000 {
        let v = i128::from(rng.next_u64()) << (rng.next_u64() % 30) >> (rng.next_u64() % 64);
        check(v);
    }
    for r in [1i128, 2, 3, 1000, 1 << 20, 1 << 40, (1 << 46) + 7] {
        assert_eq!(root(r * r + r, Variant::Exact), r, "r² + r rounds down");
        assert_eq!(root(r * r + r + 1, Variant::Exact), r + 1);
        assert_eq!(root(r * r - r + 1, Variant::Exact), r);
        // The TiesUp variant is the one the mutant bracket describes, and it is wrong here.
        assert_eq!(root(r * r + r, Variant::TiesUp), r + 1);
        assert!(model::is_root_ties_up(r * r + r, r + 1) && !is_root(r * r + r, r + 1));
    }
}

/// The closed-form switch pass (lemma 07) is the first pass where the integer rule holds, and
/// the rule holds from then on; none without a minimum.
#[test]
fn switch_pass_is_the_first_switching_pass() {
    for dd in 1..=40 {
        for dm in 0..=40 {
            let p = Params { dd, dm, t: 1, constant: false };
            let first = (1..=2_000).find(|&n| switches(dd, dm, n));
            assert_eq!(switch_pass(&p, Variant::Exact), first, "Δd {dd} Δdmin {dm}");
            if let Some(s) = first {
                assert!((s..s + 50).all(|n| switches(dd, dm, n)), "Δd {dd} Δdmin {dm}: permanent");
            }
        }
    }
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    for _ in 0..100_000 {
        let (dd, dm) = (rng.range(1, N), rng.range(1, N));
        let s = switch_pass(&Params { dd, dm, t: 1, constant: false }, Variant::Exact).unwrap();
        assert!(switches(dd, dm, s) && switches(dd, dm, s + 1 + (rng.next_u64() % 1000) as i128));
        assert!(s == 1 || !switches(dd, dm, s - 1), "Δd {dd} Δdmin {dm}: {s} is the first");
        assert!(s <= 2 || !switches(dd, dm, 1 + (rng.next_u64() as i128 % (s - 1))));
    }
    assert_eq!(switch_pass(&Params { dd: 5, dm: 0, t: 1, constant: false }, Variant::Exact), None);
    assert!(!switches(N, 0, i128::from(u32::MAX)));
}

/// The closed-form count (lemma 11) is the iterated count, and the iterated schedule has every
/// property of lemma 12: every Δd ≤ 12, Δdmin ≤ 12, T ≤ 120, both modes.
#[test]
fn schedule_properties_bounded_exhaustive() {
    for dd in 1..=12 {
        for dm in 0..=12 {
            for t in 1..=120 {
                for constant in [false, true] {
                    let m = Model::new(Params { dd, dm, t, constant }, Variant::Exact);
                    check_schedule(&m, &iterate(&m, 20_000).expect("ends"));
                }
            }
        }
    }
}

/// The same on random legal words whose schedules have at most 100 000 passes.
#[test]
fn schedule_properties_random() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    let mut checked = 0;
    while checked < 3_000 {
        let p = Params { dd: rng.range(1, N), dm: rng.range(0, N), t: rng.range(1, N), constant: rng.next_u64() % 4 == 0 };
        let m = Model::new(p, Variant::Exact);
        if m.rough_count() <= 100_000 {
            check_schedule(&m, &iterate(&m, 100_000).expect("ends"));
            checked += 1;
        }
    }
}
