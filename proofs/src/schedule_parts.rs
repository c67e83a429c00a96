//! A depth schedule from its parts, for the harnesses that take it symbolic (`schedule_step`):
//! G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST, G78.DEPTHMODE.
//!
//! **Under Kani** the schedule is `cycle_impl::schedule::Schedule::from_parts` of Δd, Δdmin, T
//! (legal words), any reach pass in 1…2^33 and any switch pass ≥ 1 (NEVER without a minimum or
//! in constant mode) — no `Schedule::new`, so no 128-bit quotient T(T − 1)/Δd² and no switch
//! search in the path. What ties reach and the switch pass to the depths is the [`Table`]: the
//! unclamped depths u(n₀), u(n₀ + 1) of the two passes a harness asks about, drawn symbolic
//! under the assumptions [`spec`] states, each one a lemma proved by z3 (smt/, named there). The
//! two functions of `cycle_impl::schedule` that compute those depths are stubbed by lookups in
//! the table ([`stubs`]), which *assert* that the schedule asks for no other pass.
//!
//! **Under the drivers** the schedule is `Schedule::new` (checked to be rebuilt exactly by
//! `from_parts`, its switch pass the model's), the table holds the model's exact depths
//! (rounded roots by bracket, no root of impl's) and every assumption of [`spec`] is *checked*
//! against them: the specifications the Kani stubs trust are tested on every case the drivers
//! run, over the full legal ranges.

use crate::source::{Outcome, Source, Stop};
use cycle_impl::schedule::{Parts, Schedule};
#[cfg(kani)]
use cycle_impl::schedule::{NEVER, REACH_CAP};

/// The unclamped depths of passes n₀ and n₀ + 1: G76.DEPTH.1 round(√(n·Δd²)) (`r`), G78.DEPTHMODE
/// n·Δd (`c`). Both are filled in either mode; each mode reads only its own.
#[derive(Clone, Copy, Debug)]
pub struct Table {
    pub n0: u32,
    pub r: [u64; 2],
    pub c: [u128; 2],
}

impl Table {
    /// The unclamped depth of pass `m` (n₀ or n₀ + 1) in the schedule's mode.
    pub fn depth(&self, m: u32, constant: bool) -> u128 {
        let i = usize::from(m != self.n0);
        if constant { self.c[i] } else { u128::from(self.r[i]) }
    }
}

/// The schedule of Δd, Δdmin, T (see the module documentation for Kani and the drivers).
pub fn schedule<S: Source>(src: &mut S, dd: u64, dmin: u64, target: u64, constant: bool) -> Result<Schedule, Stop> {
    #[cfg(kani)]
    {
        let reach = src.bounded_u64(1, REACH_CAP);
        let switch = if constant || dmin == 0 { NEVER } else { src.bounded_u64(1, NEVER) };
        let sch = Schedule::from_parts(Parts { dd, dmin, target, reach, switch, constant });
        src.assume(sch.is_some())?;
        sch.ok_or(Stop::Rejected)
    }
    #[cfg(not(kani))]
    {
        use cycle_impl::schedule::ScheduleParams;
        let p = ScheduleParams { first_cut: dd as i64, min_cut: dmin as i64, target: target as i64, constant };
        let sch = Schedule::new(&p);
        let parts = sch.parts();
        crate::check!(src, Schedule::from_parts(parts) == Some(sch), "from_parts rebuilds the schedule new prepared");
        crate::check!(src, (parts.dd, parts.dmin, parts.target) == (dd, dmin, target), "new keeps legal words");
        // G76.DEPTH.MIN: the switch pass is the model's closed form (smt/ lemma 07).
        let model = if constant { None } else { crate::model::switch_pass(dd as i64, dmin as i64) };
        let within = (parts.switch <= u64::from(u32::MAX)).then_some(parts.switch);
        crate::check!(src, within == model.map(u64::from), "the switch pass is lemma 07's s (NEVER: none)");
        Ok(sch)
    }
}

/// The table for passes n₀ and n₀ + 1 of `sch`, with [`spec`]'s assumptions: under Kani drawn
/// symbolic, assumed and handed to the stubs; under the drivers the model's values, checked.
pub fn table<S: Source>(src: &mut S, sch: &Schedule, n0: u32) -> Result<Table, Stop> {
    let p = sch.parts();
    #[cfg(kani)]
    let t = {
        let _ = p;
        let c0 = u128::from(kani::any::<u64>());
        Table { n0, r: [kani::any(), kani::any()], c: [c0, c0 + u128::from(p.dd)] }
    };
    #[cfg(not(kani))]
    let t = {
        let r = |m: u64| exact_root(u128::from(m) * u128::from(p.dd) * u128::from(p.dd));
        let c = |m: u64| u128::from(m) * u128::from(p.dd);
        let m = u64::from(n0);
        Table { n0, r: [r(m), r(m + 1)], c: [c(m), c(m + 1)] }
    };
    for (ok, msg) in spec(&p, &t) {
        trusted(src, ok, msg)?;
    }
    #[cfg(kani)]
    stubs::set(t);
    Ok(t)
}

/// What the table's values satisfy, each a z3 lemma about round(√v) and the switch and reach
/// passes that `Schedule::new` computes (smt/README.md), for passes m ∈ {n₀, n₀ + 1}, n₀ ≥ 1.
pub fn spec(p: &Parts, t: &Table) -> [(bool, &'static str); 8] {
    let (r, c, dmin, tt) = (t.r, t.c, p.dmin, u128::from(p.target));
    let (m0, m1) = (u64::from(t.n0), u64::from(t.n0) + 1);
    let degressive = !p.constant;
    [
        (!degressive || (r[0] >= 1 && r[0] <= r[1]), "lemmas 02, 03, 04: round(√(nΔd²)) ≥ 1 and monotone in n"),
        (!degressive || m0 != 1 || r[0] == p.dd, "lemma 01: round(√(Δd²)) = Δd"),
        (!degressive || m1 >= p.switch || u128::from(r[1]) >= u128::from(r[0]) + u128::from(dmin), "lemmas 09, 07: a step before the switch pass cuts ≥ Δdmin"),
        (!degressive || ((u128::from(r[0]) >= tt) == (m0 >= p.reach) && (u128::from(r[1]) >= tt) == (m1 >= p.reach)), "lemmas 05, 11: round(√(nΔd²)) ≥ T exactly from the reach pass on"),
        ((p.switch == 1) == (degressive && dmin > p.dd), "lemma 07 at n = 1: the switch pass is 1 exactly when Δd < Δdmin"),
        (!p.constant || (c[0] >= u128::from(p.dd) && c[1] == c[0] + u128::from(p.dd)), "G78.DEPTHMODE: n·Δd ≥ Δd, (n + 1)·Δd = n·Δd + Δd"),
        (!p.constant || m0 != 1 || c[0] == u128::from(p.dd), "G78.DEPTHMODE: 1·Δd = Δd"),
        (!p.constant || ((c[0] >= tt) == (m0 >= p.reach) && (c[1] >= tt) == (m1 >= p.reach)), "lemma 11 (constant mode): n·Δd ≥ T exactly from ⌈T/Δd⌉ on"),
    ]
}

/// An assumption the Kani stubs trust (Kani: assumed) that the drivers check.
fn trusted<S: Source>(src: &mut S, ok: bool, msg: &'static str) -> Outcome {
    if cfg!(kani) {
        src.assume(ok)
    } else {
        src.verdict(ok, msg)
    }
}

/// round(√v) half up, by the bracket (`model::is_sqrt_round`) around a bit-by-bit integer root:
/// the drivers' expectation, independent of `cycle_impl::fixed`.
#[cfg(not(kani))]
pub fn exact_root(v: u128) -> u64 {
    let mut r = 0u128;
    for bit in (0..64).rev() {
        let c = r | 1 << bit;
        if c.checked_mul(c).is_some_and(|sq| sq <= v) {
            r = c;
        }
    }
    // r = ⌊√v⌋; half up: r + 1 when v − r² > r.
    let r = if v - r * r > r { r + 1 } else { r };
    debug_assert!(crate::model::is_sqrt_round(r, v));
    r as u64
}

/// The Kani stubs of `cycle_impl::schedule::{root_depth, constant_depth}`: lookups in the table
/// that [`table`] drew (TRUSTED specification: [`spec`]; checked by the drivers).
#[cfg(kani)]
pub mod stubs {
    use super::Table;
    use core::sync::atomic::{AtomicU32, AtomicU64, Ordering::SeqCst};

    static N0: AtomicU32 = AtomicU32::new(0);
    static R: [AtomicU64; 2] = [AtomicU64::new(0), AtomicU64::new(0)];
    /// c[0] (< 2^64 as drawn); c[1] = c[0] + Δd is rebuilt from it.
    static C0: AtomicU64 = AtomicU64::new(0);

    pub fn set(t: Table) {
        N0.store(t.n0, SeqCst);
        R[0].store(t.r[0], SeqCst);
        R[1].store(t.r[1], SeqCst);
        C0.store(t.c[0] as u64, SeqCst);
    }

    fn index(n: u32) -> usize {
        let n0 = N0.load(SeqCst);
        kani::assert(n == n0 || Some(n) == n0.checked_add(1), "the schedule asks for the depth of pass n0 or n0 + 1 only");
        usize::from(n != n0)
    }

    /// `root_depth(n, Δd², guess)` = round(√(n·Δd²)), whatever the guess.
    pub fn root_depth_spec(n: u32, _dd2: u128, _before: u64) -> u64 {
        R[index(n)].load(SeqCst)
    }

    /// `constant_depth(n, Δd)` = n·Δd.
    pub fn constant_depth_spec(n: u32, dd: u64) -> u128 {
        u128::from(C0.load(SeqCst)) + if index(n) == 1 { u128::from(dd) } else { 0 }
    }
}
