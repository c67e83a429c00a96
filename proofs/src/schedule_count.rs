//! Harness `schedule_count` — G76.DEPTH.LAST, G76.DEPTH.MIN, G78.DEPTHMODE, PRJ.MAXPASS: the
//! closed-form pass count `Schedule::rough_pass_count` agrees with stepping, on a *symbolic*
//! schedule (`schedule_parts`).
//!
//! **Property.** For legal Δd, Δdmin, T (1…N, Δdmin from 0), either mode, any limit, let L be
//! the count without a limit (`rough_pass_count(2^32 − 1)`): with a limit it is L when L ≤ limit,
//! else `None`; and for the pass q that `first` or `next` makes of an *exact* pass p = (n, depth)
//! (not last; before the switch pass s: n below reach and depth u(n); from s on (s ≤ reach):
//! depth u(n) = b + (n − s + 1)·Δdmin, b = round(√((s − 1)·Δd²)), smt/ lemma 08), q is last
//! exactly when q is pass L, and a pass that is not last is numbered below L (`None`: L beyond
//! 2^32 − 1, no pass numbered there is last). With `schedule_step`'s induction (every pass is
//! admissible, here exact) the schedule's passes are 1…L, the last one pass L: the closed form
//! is the stepped count (G76.DEPTH.LAST, PRJ.MAXPASS).
//!
//! **What is trusted (Kani).** Everything `schedule_step` trusts, and `switch_depth` and
//! `min_cuts` (the count's root b and quotient Q = ⌈(T − b)/Δdmin⌉) stubbed by lookups of b and
//! Q ([`stubs`], asserting they are asked for s − 1 and T − b only), assumed ([`spec`]): b < T
//! (lemma 05, s − 1 < reach), b = 0 at s = 1, b = u(s − 1) (the same root), 1 ≤ Q ≤ T, and for
//! the exact depth D of pass n ≥ s − 1: D ≥ T ⇔ n − s + 1 ≥ Q and D + Δdmin ≥ T ⇔ n − s + 2 ≥ Q
//! (Q is the least k with b + k·Δdmin ≥ T: lemma 11 with lemma 08's running form). The drivers
//! check each against the model's exact b, Q and depths.
//!
//! **Left to z3 and the drivers.** The values b, Q, reach and s (nonlinear); that the depth of
//! pass n ≥ s is b + (n − s + 1)·Δdmin (lemma 08; the drivers compute it exactly).

use crate::schedule_parts::{schedule, table, Table};
use crate::source::{Outcome, Source, Stop};
use crate::{check, cover};
use cycle_impl::schedule::{Parts, Rough, Schedule};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::Rule;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest Δd, Δdmin, T.
    pub max_len: u64,
    /// Largest pass number of `prev`.
    pub max_n: u32,
}

/// The legal words, every pass number: what Kani proves and the random driver samples.
pub const FULL: Scope = Scope { max_len: MAX_LENGTH as u64, max_n: u32::MAX - 1 };

/// The count's b = round(√((s − 1)·Δd²)) and Q = ⌈(T − b)/Δdmin⌉ (read only when s ≤ reach).
#[derive(Clone, Copy, Debug)]
pub struct Count {
    pub b: u64,
    pub q: u64,
}

/// Whether the count's branch with a switch applies: degressive, Δdmin ≥ 1, s ≤ reach.
fn switched(p: &Parts) -> bool {
    !p.constant && p.dmin >= 1 && p.switch <= p.reach
}

/// b and Q: under Kani symbolic (handed to the stubs), under the drivers the model's.
fn count<S: Source>(src: &mut S, p: &Parts) -> Result<Count, Stop> {
    #[cfg(kani)]
    let c = {
        let _ = src;
        let c = Count { b: kani::any(), q: kani::any() };
        stubs::set(p.switch.wrapping_sub(1), p.target, c);
        c
    };
    #[cfg(not(kani))]
    let c = if switched(p) {
        let b = crate::schedule_parts::exact_root(u128::from(p.switch - 1) * u128::from(p.dd) * u128::from(p.dd));
        let rest = p.target.checked_sub(b).ok_or(Stop::Failed("lemma 05: b < T"))?;
        let _ = src;
        Count { b, q: rest.div_ceil(p.dmin) }
    } else {
        Count { b: 0, q: 0 }
    };
    Ok(c)
}

/// What b and Q satisfy (see the module documentation), for the exact pass (n, D), n ≥ 0
/// (n = 0: before pass 1, D = 0).
pub fn spec(p: &Parts, t: &Table, c: &Count, n: u32, d: u128) -> [(bool, &'static str); 4] {
    let (s, tt, dmin) = (u128::from(p.switch), u128::from(p.target), u128::from(p.dmin));
    let (b, q) = (u128::from(c.b), u128::from(c.q));
    let n0 = u128::from(t.n0);
    let k = (u128::from(n) + 1).checked_sub(s);
    let on = switched(p);
    [
        (!on || (b < tt && (s != 1 || b == 0)), "lemma 05: b < T (s − 1 < reach); round(√0) = 0"),
        (!on || ((n0 + 1 != s || u128::from(t.r[0]) == b) && (n0 + 2 != s || u128::from(t.r[1]) == b)), "b is u(s − 1), the same root"),
        (!on || (1 <= q && q <= tt), "⌈(T − b)/Δdmin⌉ lies in 1…T"),
        (!on || k.is_none_or(|k| ((d >= tt) == (k >= q)) && ((d + dmin >= tt) == (k + 1 >= q))), "lemmas 11, 08: Q is the least k with b + k·Δdmin ≥ T"),
    ]
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let dd = src.bounded_u64(1, scope.max_len);
    let dmin = src.bounded_u64(0, scope.max_len);
    let target = src.bounded_u64(1, scope.max_len);
    let constant = src.bool();
    let sch: Schedule = schedule(src, dd, dmin, target, constant)?;
    let p = sch.parts();
    let limit = src.bounded_u32(0, u32::MAX);
    let c = count(src, &p)?;

    // The exact pass (n, D) before q; n = 0: before the first pass.
    let n = if src.bool() { 0 } else { src.bounded_u32(1, scope.max_n) };
    let tab = table(src, &sch, n.max(1))?;
    let d = if n == 0 {
        0
    } else if u64::from(n) < p.switch {
        src.assume(u64::from(n) < p.reach)?;
        tab.depth(n, constant)
    } else {
        src.assume(switched(&p))?;
        min_depth(src, &p, &c, n)?
    };
    src.assume(d < u128::from(target))?;
    for (ok, msg) in spec(&p, &tab, &c, n, d) {
        if cfg!(kani) {
            src.assume(ok)?;
        } else {
            src.verdict(ok, msg)?;
        }
    }
    let q = if n == 0 {
        sch.first()
    } else {
        let prev = Rough { n, depth: d as i64, last: false, rule: Rule::G76DepthMin };
        let Some(q) = sch.next(&prev) else {
            check!(src, false, "a pass that is not the last has a successor");
            return Ok(());
        };
        q
    };

    let whole = sch.rough_pass_count(u32::MAX);
    check!(src, sch.rough_pass_count(limit) == whole.filter(|&l| l <= limit), "PRJ.MAXPASS: the count within the limit, else none");
    check!(src, q.last == (whole == Some(q.n)), "G76.DEPTH.LAST: the pass numbered by the closed-form count is the last");
    check!(src, q.last || whole.is_none_or(|l| q.n < l), "the passes before the last are numbered below the count");

    cover!(src, q.last && u64::from(q.n) > p.switch, "the last pass after minimum cuts");
    cover!(src, q.last && u64::from(q.n) < p.switch && !constant, "the last pass before the switch");
    cover!(src, q.last && constant && q.n >= 2, "the last pass in constant mode");
    cover!(src, !q.last && whole.is_some(), "a pass before the last");
    Ok(())
}

/// The exact depth of pass n ≥ s (lemma 08's running form b + (n − s + 1)·Δdmin): under the
/// drivers computed; under Kani any depth, tied to Q by [`spec`].
fn min_depth<S: Source>(src: &mut S, p: &Parts, c: &Count, n: u32) -> Result<u128, Stop> {
    #[cfg(kani)]
    {
        let _ = (c, n);
        // Below T ≤ N: drawn in 0…N, the bound below T assumed by the body.
        let _ = p;
        Ok(u128::from(src.bounded_u64(0, MAX_LENGTH as u64)))
    }
    #[cfg(not(kani))]
    {
        let _ = src;
        Ok(u128::from(c.b) + u128::from(u64::from(n) + 1 - p.switch) * u128::from(p.dmin))
    }
}

/// The Kani stubs of `cycle_impl::schedule::{switch_depth, min_cuts}`: lookups of b and Q
/// (TRUSTED specification: [`spec`]; checked by the drivers).
#[cfg(kani)]
pub mod stubs {
    use super::Count;
    use core::sync::atomic::{AtomicU64, Ordering::SeqCst};

    static S1: AtomicU64 = AtomicU64::new(0);
    static T: AtomicU64 = AtomicU64::new(0);
    static B: AtomicU64 = AtomicU64::new(0);
    static Q: AtomicU64 = AtomicU64::new(0);

    pub fn set(s_minus_1: u64, t: u64, c: Count) {
        S1.store(s_minus_1, SeqCst);
        T.store(t, SeqCst);
        B.store(c.b, SeqCst);
        Q.store(c.q, SeqCst);
    }

    /// `switch_depth(s − 1, Δd²)` = b.
    pub fn switch_depth_spec(before_switch: u64, _dd2: u128) -> u128 {
        kani::assert(before_switch == S1.load(SeqCst), "the count asks for the depth of pass s − 1 only");
        u128::from(B.load(SeqCst))
    }

    /// `min_cuts(T − b, Δdmin)` = Q.
    pub fn min_cuts_spec(rest: u128, dmin: u64) -> u128 {
        let want = u128::from(T.load(SeqCst)).wrapping_sub(u128::from(B.load(SeqCst)));
        kani::assert(rest == want && dmin >= 1, "the count asks for ⌈(T − b)/Δdmin⌉ only, Δdmin ≥ 1");
        u128::from(Q.load(SeqCst))
    }
}

cycle_harness::property! {
    pub const PROPERTY = schedule_count in crate::PROPERTIES {
        rules: ["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        states: "The closed-form pass count agrees with stepping on a symbolic schedule (the count's root and quotient stubbed by b and Q whose assumptions are z3 lemmas 05, 08, 11, checked by the drivers): the pass after an exact pass is last exactly when it is numbered by the count, earlier passes are numbered below it, and a limit gives the count or none.",
        body: |src, scope| body(src, &scope),
        /// Kani: the count against the step over the legal words, every pass number and limit.
        /// Unwind 10: the only loops are over the eight and four assumptions.
        kani: proof(FULL) { unwind: 10, stubs: [cycle_impl::schedule::root_depth => crate::schedule_parts::stubs::root_depth_spec, cycle_impl::schedule::constant_depth => crate::schedule_parts::stubs::constant_depth_spec, cycle_impl::schedule::switch_depth => stubs::switch_depth_spec, cycle_impl::schedule::min_cuts => stubs::min_cuts_spec], measured: "SUCCESSFUL (878 checks, 1 unreachable; 4/4 covers), 13.0 s, 0.48 GB" },
        tests {
            /// Δd, Δdmin, T ≤ 6 whole, pass numbers ≤ 40 and limits their 3 smallest and largest.
            fn schedule_count_exhaustive_small = exhaustive(3, 2_000_000) on Scope { max_len: 6, max_n: 40 };
            /// The edges of the legal ranges, pass numbers and limits.
            fn schedule_count_exhaustive_edges = exhaustive(2, 2_000_000) on FULL;
            /// The full ranges; and pass numbers ≤ 300, where the exact passes are not last.
            fn schedule_count_random = random(0x5eed_0033, 4) on FULL, random(0x5eed_0034, 4) on Scope { max_len: MAX_LENGTH as u64, max_n: 300 };
        }
    }
}
