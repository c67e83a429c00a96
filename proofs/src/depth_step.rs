//! TEST `depth_step` (driver-only: not a Kani proof) — G76.DEPTH.1, G76.DEPTH.MIN,
//! G76.DEPTH.LAST, G78.DEPTHMODE: one step of the production depth schedule
//! (`cycle_impl::schedule::Schedule::first`/`next`), over the full legal ranges, written for
//! Kani **modulo named stubs** (below).
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 with both stubs reached no verdict: CaDiCaL
//! 350 s, Kissat 4.0.1 450 s (proofs/README.md, "TESTs"); `Schedule::new`'s 128-bit reach
//! quotient stays in every path. The stubs and the harness that was run are kept for the next attempt (its `property!`,
//! a proof harness with `kani-attempts`); under `cargo test` the real functions run. Its
//! properties are Kani-proved on a symbolic schedule instead (`schedule_step`, `schedule_count`:
//! `from_parts` in place of `new`, the depths stubbed as the z3 lemmas constrain them).
//!
//! **Property.** For all legal Δd (1…N), Δdmin (0…N), T = k − d (1…N), N = 999 999 999,
//! degressive or constant, and every pass `prev` the schedule can be asked about (any pass
//! number 1 ≤ n ≤ 2^32 − 1, any depth 0 ≤ depth < T, not last; in constant mode the pass n
//! itself, depth n·Δd < T), or the first pass:
//!
//! - after a last pass, `next` is `None` (any number, any depth); from pass 2^32 − 1 it is
//!   `None` (no pass number left); otherwise it is `Some` pass n + 1;
//! - depth in 1…T; `last` ⇔ depth = T ⇔ rule G76.DEPTH.LAST (the clamp at k − d);
//! - G76.DEPTH.MIN only in degressive mode with Δdmin ≥ 1, and then depth = previous depth +
//!   Δdmin exactly (the running form √(s−1)·Δd + (n − s + 1)·Δdmin), so strictly deeper;
//! - G78.DEPTHMODE only in constant mode, depth = (n + 1)·Δd = previous depth + Δd;
//! - G76.DEPTH.1 only in degressive mode, depth = root((n + 1)·Δd²): the value the schedule's
//!   root returns for exactly that radicand (under the drivers: checked against the exact
//!   bracket of round(√((n + 1)·Δd²)), no root taken);
//! - G76.DEPTH.LAST: depth T, deeper than the previous pass;
//! - `first` is pass 1 of the same shape, from depth 0 (radicand Δd², constant depth Δd).
//!
//! So every step is monotone except possibly a G76.DEPTH.1 step, whose depth is the rounded
//! root of (n + 1)·Δd² — monotone in n by z3 (smt/ lemmas 03 root_monotone, 04
//! radicand_monotone), given that the previous pass was root(n·Δd²).
//!
//! **What a Kani run trusts here (stubs, `-Z stubbing`).** Under Kani the harness replaces two
//! functions of `cycle_impl::schedule` by their specifications; each is an over-approximation
//! (every value the real function can return is allowed), so a SUCCESSFUL verdict holds for
//! the real functions *provided the specifications hold of them*, which Kani does not check:
//!
//! 1. `root(v, hint)` (round(√v) half up, via a 64-bit walk from `hint` and `sqrt_round`) →
//!    [`stubs::root_spec`]: any r with r = 0 ⇔ v = 0, independent of `hint`. Where it is
//!    established: z3 smt/ lemmas 01–02 (the bracket is the rounded root; round(√v) ≥ 1 ⇔
//!    v ≥ 1), impl's unit test `root_with_any_guess_is_the_rounded_root` (every v ≤ 20 000
//!    with every guess, edges, random up to 2^126), the drivers of this body and of
//!    `depth_step_monotone` (exact bracket).
//! 2. `switch_pass(Δd, Δdmin)` (G76.DEPTH.MIN's switch pass: a 128-bit quotient a²/c², or a
//!    256-bit binary search) → [`stubs::switch_pass_spec`]: NEVER (u64::MAX) when Δdmin = 0,
//!    else any pass number s ≥ 1. The value of s is z3's (smt/ lemma 07) and impl's unit test
//!    `closed_form_switch_pass_is_the_searched_one`; the drivers check it (`depth_step_monotone`).
//!
//! `Schedule::new` is not stubbed: its reach pass ⌊T(T − 1)/Δd²⌋ + 1 (resp. ⌈T/Δd⌉) is computed
//! by the real code, with its overflow and division checks.
//!
//! **Left to z3 and the drivers.** Which rule applies at which n (the values of the switch pass
//! s and of the reach pass), the value of the rounded root, monotonicity of G76.DEPTH.1 steps,
//! the pass count (`rough_pass_count`; `depth_step_clamp`, `depth_bounds`, smt/ lemma 11).
//!
//! **Kani bounds.** All symbolic over the full legal ranges; no loop is left once `root` is
//! stubbed: `#[kani::unwind(2)]`.

use crate::schedule::Schedule;
use crate::source::{bounded_i64_upto, Outcome, Source};
use crate::{check, cover};
use cycle_impl::schedule::{Rough, ScheduleParams};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::Rule;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest Δd, Δdmin, T.
    pub max_len: i64,
    /// Largest pass number of `prev`.
    pub max_n: u32,
}

/// What Kani proves and the random driver samples: the legal ranges, every pass number.
pub const FULL: Scope = Scope { max_len: MAX_LENGTH, max_n: u32::MAX };

/// Whether pass `r` (not clamped) has the depth root((`n`)·Δd²) for Δd = `dd`.
///
/// Under Kani: the stubbed `root` was last called with exactly that radicand and returned
/// `r.depth` (the stub's value, [`stubs::last_root`]). Under the drivers: `r.depth` is
/// round(√(n·Δd²)) by its exact bracket ([`crate::model::is_sqrt_round`]).
fn is_root_depth(r: &Rough, n: u32, dd: u64) -> bool {
    // The radicand as the schedule forms it: n · Δd² (Δd² < 2^60, n < 2^32).
    let radicand = u128::from(n) * (u128::from(dd) * u128::from(dd));
    #[cfg(kani)]
    {
        stubs::last_root().is_some_and(|(v, root)| v == radicand && u128::from(root) == r.depth as u128)
    }
    #[cfg(not(kani))]
    {
        r.depth >= 0 && crate::model::is_sqrt_round(r.depth as u128, radicand)
    }
}

/// The harness body (see the module documentation).
pub fn body<S: Source, Sch: Schedule>(src: &mut S, sch: &Sch, scope: &Scope) -> Outcome {
    let first_cut = src.bounded_i64(1, scope.max_len);
    let min_cut = src.bounded_i64(0, scope.max_len);
    let target = src.bounded_i64(1, scope.max_len);
    let constant = src.bool();
    let p = ScheduleParams { first_cut, min_cut, target, constant };
    // Δd as the schedule reads it (the same expression, so that products formed from it here
    // and in the schedule are the same circuit for a SAT solver).
    let dd = first_cut.max(1).unsigned_abs();

    let (got, before) = match src.choose(3) {
        0 => (sch.first(&p), 0),
        1 => {
            // After a last pass: nothing, whatever its number and depth.
            let n = src.bounded_u32(1, scope.max_n);
            let depth = src.bounded_i64(0, scope.max_len);
            let prev = Rough { n, depth, last: true, rule: Rule::G76DepthLast };
            check!(src, sch.next(&p, &prev).is_none(), "G76.DEPTH.LAST: no rough pass after the last one");
            return Ok(());
        }
        _ => {
            let n = src.bounded_u32(1, scope.max_n);
            let depth = if constant {
                // The pass n of constant mode: depth n·Δd, not yet at T — written
                // (n + 1)·Δd − Δd with n + 1 formed as the schedule forms it, so that the
                // schedule's product for pass n + 1 is the same circuit for a SAT solver.
                // (n = 2^32 − 1: no pass n + 1; any depth below T.)
                match n.checked_add(1) {
                    Some(m) => {
                        let d = u128::from(m) * u128::from(dd) - u128::from(dd);
                        src.assume(d < target as u128)?;
                        d as i64
                    }
                    None => bounded_i64_upto(src, 0, target - 1, scope.max_len)?,
                }
            } else {
                bounded_i64_upto(src, 0, target - 1, scope.max_len)?
            };
            let rule = if constant { Rule::G78DepthMode } else { Rule::G76Depth1 };
            let prev = Rough { n, depth, last: false, rule };
            let got = sch.next(&p, &prev);
            if n == u32::MAX {
                check!(src, got.is_none(), "no pass after pass number 2^32 − 1");
                return Ok(());
            }
            check!(src, got.is_some(), "a pass that is not the last has a successor");
            let Some(got) = got else { return Ok(()) };
            check!(src, got.n == n + 1, "pass numbers count up by one");
            (got, depth)
        }
    };
    let r = got;
    let t = target;
    check!(src, 1 <= r.depth && r.depth <= t, "G76.DEPTH.LAST: every rough depth lies in 1…k − d");
    check!(src, r.last == (r.depth == t), "G76.DEPTH.LAST: last exactly at depth k − d (the clamp)");
    check!(src, r.last == (r.rule == Rule::G76DepthLast), "G76.DEPTH.LAST names exactly the clamped pass");
    check!(src, r.n >= 1, "pass numbers start at 1");
    match r.rule {
        Rule::G76DepthLast => {
            check!(src, r.depth > before, "G76.DEPTH.LAST: the clamped pass is deeper than the one before");
        }
        Rule::G76DepthMin => {
            check!(src, !constant && min_cut >= 1, "G76.DEPTH.MIN only in degressive mode with Δdmin ≥ 1");
            check!(src, r.depth == before + min_cut, "G76.DEPTH.MIN: a minimum cut adds exactly Δdmin");
        }
        Rule::G78DepthMode => {
            check!(src, constant, "G78.DEPTHMODE only in constant mode");
            let want = u128::from(r.n) * u128::from(dd);
            check!(src, r.depth as u128 == want, "G78.DEPTHMODE: pass n is n·Δd deep");
            check!(src, r.depth == before + first_cut, "G78.DEPTHMODE: each pass adds exactly Δd");
        }
        Rule::G76Depth1 => {
            check!(src, !constant, "G76.DEPTH.1 only in degressive mode");
            check!(src, is_root_depth(&r, r.n, dd), "G76.DEPTH.1: pass n is round(√(n·Δd²)) deep");
        }
        _ => {
            check!(src, false, "a rough pass names a depth rule");
        }
    }
    cover!(src, r.rule == Rule::G76DepthMin, "a minimum-cut step");
    cover!(src, r.rule == Rule::G76Depth1, "a square-root step");
    cover!(src, r.rule == Rule::G78DepthMode, "a constant step");
    cover!(src, r.last, "a clamped step");
    Ok(())
}

/// The Kani stubs (TRUSTED specifications, see the module documentation) and the record of
/// the last `root` call that [`is_root_depth`] reads.
#[cfg(kani)]
pub mod stubs {
    use core::sync::atomic::{AtomicBool, AtomicU64, Ordering::SeqCst};

    static ROOT_CALLED: AtomicBool = AtomicBool::new(false);
    static ROOT_V_HI: AtomicU64 = AtomicU64::new(0);
    static ROOT_V_LO: AtomicU64 = AtomicU64::new(0);
    static ROOT_R: AtomicU64 = AtomicU64::new(0);

    /// `cycle_impl::schedule::root`'s specification: round(√v) half up is 0 exactly for v = 0
    /// (smt/ lemmas 01–02), whatever the guess. Any such value; the call is recorded.
    pub fn root_spec(v: u128, _hint: u64) -> u64 {
        let r: u64 = kani::any();
        kani::assume((r == 0) == (v == 0));
        ROOT_CALLED.store(true, SeqCst);
        ROOT_V_HI.store((v >> 64) as u64, SeqCst);
        ROOT_V_LO.store(v as u64, SeqCst);
        ROOT_R.store(r, SeqCst);
        r
    }

    /// The radicand and value of the last `root` call, if any.
    pub fn last_root() -> Option<(u128, u64)> {
        ROOT_CALLED.load(SeqCst).then(|| {
            let v = (u128::from(ROOT_V_HI.load(SeqCst)) << 64) | u128::from(ROOT_V_LO.load(SeqCst));
            (v, ROOT_R.load(SeqCst))
        })
    }

    /// `cycle_impl::schedule::switch_pass`'s specification: NEVER (u64::MAX) without a minimum
    /// cut (its first line), else some pass number s ≥ 1 (smt/ lemma 07 has which).
    pub fn switch_pass_spec(_dd: u64, dmin: u64) -> u64 {
        if dmin == 0 {
            return u64::MAX;
        }
        let s: u64 = kani::any();
        kani::assume(s >= 1);
        s
    }
}

cycle_harness::property! {
    pub const PROPERTY = depth_step in crate::PROPERTIES {
        rules: ["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE"],
        states: "One step of the production depth schedule (first, or next of any pass) over the full legal ranges, with root and switch_pass stubbed by their specifications (z3 lemmas 01, 02, 07; impl's unit tests): numbered n + 1, depth in 1…k − d, last exactly at k − d and named G76.DEPTH.LAST, a minimum cut adds exactly Δdmin, a constant step adds Δd (depth n·Δd), a G76.DEPTH.1 depth is the root of n·Δd², nothing after the last or past pass 2^32 − 1.",
        body: |src, scope| body(src, &crate::schedule::Production, &scope),
        /// The Kani harness that was run (Kissat; also tried with CaDiCaL): no verdict, so a TEST,
        /// a proof harness only with `kani-attempts` (`-Z stubbing`).
        kani: test(FULL) { unwind: 2, solver: kissat, stubs: [cycle_impl::schedule::root => stubs::root_spec, cycle_impl::schedule::switch_pass => stubs::switch_pass_spec], why: "no verdict: CaDiCaL, 350 s of CBMC (454 979 variables, 2.26 M clauses; ten queries answered, the eleventh open for 4 min; 0.59 GB); Kissat 4.0.1, 450 s (thirteen queries, the fourteenth open for 6 min; 0.25 GB) — stopped by hand to free the machine" },
        tests {
            /// Δd, Δdmin, T ≤ 6 whole, pass numbers and depths their 4 smallest and largest values.
            fn depth_step_exhaustive_small = exhaustive(4, 2_000_000) on Scope { max_len: 6, max_n: 40 };
            /// The edges of the legal ranges.
            fn depth_step_exhaustive_edges = exhaustive(2, 2_000_000) on FULL;
            fn depth_step_random = random(0x5eed_0011, 2) on FULL;
        }
    }
}
