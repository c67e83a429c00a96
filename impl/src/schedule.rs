//! Depth schedule of the G76/G78 rough passes (G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST,
//! G78.DEPTHMODE), over exact integers: prepared once per cycle ([`Schedule::new`]), then a pure
//! step from one pass to the next ([`Schedule::next`]).
//!
//! All lengths are radius increments. With Δd = `first_cut`, Δdmin = `min_cut`,
//! T = `target` = k − d (docs/INTERPRETATION.md, "Depth schedule"):
//!
//! - degressive: pass n switches to minimum cuts at the first n ≥ 1 with
//!   (√n − √(n−1))·Δd < Δdmin, decided in integers as Δd² − Δdmin² < 0 or
//!   (Δd² − Δdmin²)² < 4·Δd²·Δdmin²·(n−1). Before the switch pass s the exact depth is √n·Δd,
//!   from s on √(s−1)·Δd + (n − s + 1)·Δdmin; each exact depth is rounded once, half up;
//! - constant (G78 D0): the exact depth is n·Δd;
//! - a rounded depth ≥ T becomes T and is the last rough pass.
//!
//! The schedule is total over every `i64`: parameters outside their domain are read as the
//! nearest legal value (Δd ≥ 1, Δdmin ≥ 0, T ≥ 1). Arithmetic is exact over that whole domain
//! (256-bit comparisons where products exceed 128 bits).

use crate::fixed::{mul_wide, sqrt_round};
use cycle_vocab::Rule;

/// Depth schedule of G76/G78 rough passes, all lengths radius increments.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScheduleParams {
    /// Δd ≥ 1: the first cut (G76 Q of the second block).
    pub first_cut: i64,
    /// Δdmin ≥ 0: the minimum cut (0 = no minimum).
    pub min_cut: i64,
    /// k − d ≥ 1: the depth of the last rough pass.
    pub target: i64,
    /// G78 depth mode 0: the depth of pass n is n·Δd.
    pub constant: bool,
}

/// One rough pass of the schedule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rough {
    /// 1-based pass number.
    pub n: u32,
    /// Radius depth from B, increments (rounded once, clamped to the target).
    pub depth: i64,
    /// Whether this is the last rough pass (its depth is the target).
    pub last: bool,
    /// The rule that set the depth: G76.DEPTH.1 (√n·Δd), G76.DEPTH.MIN (minimum cuts),
    /// G76.DEPTH.LAST (clamped to k − d) or G78.DEPTHMODE (constant n·Δd).
    pub rule: Rule,
}

/// The depth schedule of one cycle, prepared once: the parameters read into their domain and
/// the two pass numbers every pass is compared with (G76.DEPTH.MIN's switch pass, and the pass
/// whose depth first reaches T), so that a pass change costs a few multiplications and no
/// division (the running form of the rules; [`Schedule::next`] stays pure in the pass before).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Schedule {
    /// Δd ≥ 1.
    dd: u64,
    /// Δd² (< 2^126), the step of G76.DEPTH.1's radicand n·Δd².
    dd2: u128,
    /// Δdmin ≥ 0.
    dmin: u64,
    /// T ≥ 1.
    target: u64,
    /// The first n whose unclamped depth before the switch reaches T (G76.DEPTH.LAST):
    /// n·Δd² > T·(T − 1), i.e. round(√n·Δd) ≥ T; constant mode: n·Δd ≥ T. Capped at
    /// [`REACH_CAP`] (no pass number gets there).
    reach: u64,
    /// The switch pass s of G76.DEPTH.MIN; [`NEVER`] without a minimum or in constant mode.
    switch: u64,
    /// G78.DEPTHMODE 0: the depth of pass n is n·Δd.
    constant: bool,
}

/// A switch pass that no pass number reaches.
#[doc(hidden)]
pub const NEVER: u64 = u64::MAX;

/// Above every pass number (n < 2^32): a `reach` capped here is a count no limit allows.
#[doc(hidden)]
pub const REACH_CAP: u64 = 1 << 33;

/// The parts of a prepared [`Schedule`], for the proofs (`cycle-proofs`) that take a symbolic
/// schedule: not part of the API. Δd² is not a part: [`Schedule::from_parts`] forms it.
#[doc(hidden)]
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Parts {
    pub dd: u64,
    pub dmin: u64,
    pub target: u64,
    pub reach: u64,
    pub switch: u64,
    pub constant: bool,
}

impl Schedule {
    /// Prepares the schedule of `p`; values outside their domain are read as the nearest
    /// legal value (Δd ≥ 1, Δdmin ≥ 0, T ≥ 1).
    pub fn new(p: &ScheduleParams) -> Schedule {
        let dd = p.first_cut.max(1).unsigned_abs();
        let dmin = p.min_cut.max(0).unsigned_abs();
        let target = p.target.max(1).unsigned_abs();
        let (t, d) = (u128::from(target), u128::from(dd));
        // T < 2^63 and Δd < 2^63: T·(T − 1) and Δd² are below 2^126.
        let dd2 = d * d;
        let (reach, switch) = if p.constant {
            (t.div_ceil(d), NEVER)
        } else {
            (t * (t - 1) / dd2 + 1, switch_pass(dd, dmin))
        };
        let reach = u64::try_from(reach).unwrap_or(REACH_CAP).min(REACH_CAP);
        Schedule { dd, dd2, dmin, target, reach, switch, constant: p.constant }
    }

    /// The parts of this schedule (for the proofs; not part of the API).
    #[doc(hidden)]
    pub fn parts(&self) -> Parts {
        let Schedule { dd, dmin, target, reach, switch, constant, .. } = *self;
        Parts { dd, dmin, target, reach, switch, constant }
    }

    /// The schedule with these parts when they have the shape [`Schedule::new`] gives them
    /// (Δd, T in 1…2^63 − 1, Δdmin < 2^63, reach in 1…[`REACH_CAP`], the switch pass ≥ 1 and
    /// [`NEVER`] without a minimum or in constant mode), else `None`. That reach and the switch
    /// pass are *the* passes of G76.DEPTH.LAST and G76.DEPTH.MIN is not checked: a proof that
    /// takes a symbolic schedule assumes it (for the proofs; not part of the API).
    #[doc(hidden)]
    pub fn from_parts(p: Parts) -> Option<Schedule> {
        let top = i64::MAX.unsigned_abs();
        let shaped = (1..=top).contains(&p.dd)
            && (1..=top).contains(&p.target)
            && p.dmin <= top
            && (1..=REACH_CAP).contains(&p.reach)
            && p.switch >= 1
            && (p.switch == NEVER || (p.dmin >= 1 && !p.constant));
        let dd2 = u128::from(p.dd) * u128::from(p.dd);
        let Parts { dd, dmin, target, reach, switch, constant } = p;
        shaped.then_some(Schedule { dd, dd2, dmin, target, reach, switch, constant })
    }

    /// The first rough pass (G76.DEPTH.1; G76.DEPTH.MIN when Δd < Δdmin; G78.DEPTHMODE).
    pub fn first(&self) -> Rough {
        self.pass(1, 0)
    }

    /// The rough pass after `prev` (G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST, G78.DEPTHMODE);
    /// `None` when `prev` was the last one (or its number cannot grow).
    ///
    /// Pure in `prev`: before the switch the depth is computed from n (`prev.depth` only serves
    /// as a checked guess at the root); at and after the switch pass s the exact depth
    /// √(s−1)·Δd + (n − s + 1)·Δdmin is the previous pass's rounded, unclamped depth plus Δdmin
    /// (rounding commutes with adding an integer), so `prev.depth` is used.
    #[inline]
    pub fn next(&self, prev: &Rough) -> Option<Rough> {
        if prev.last {
            return None;
        }
        let n = prev.n.checked_add(1)?;
        Some(self.pass(n, prev.depth.max(0).unsigned_abs()))
    }

    /// Pass n, given the depth of pass n − 1 (0 for n = 1).
    #[inline]
    fn pass(&self, n: u32, before: u64) -> Rough {
        let at = u64::from(n);
        if at >= self.switch {
            // G76.DEPTH.MIN (the switch is monotone in n: every pass from s on).
            return self.clamp(n, u128::from(before) + u128::from(self.dmin), Rule::G76DepthMin);
        }
        if at >= self.reach {
            return self.clamp(n, u128::from(self.target), Rule::G76DepthLast);
        }
        if self.constant {
            // G78.DEPTHMODE 0; n < reach: n·Δd < T.
            return self.clamp(n, constant_depth(n, self.dd), Rule::G78DepthMode);
        }
        // G76.DEPTH.1; n < reach: n·Δd² ≤ T·(T − 1) < 2^126.
        self.clamp(n, u128::from(root_depth(n, self.dd2, before)), Rule::G76Depth1)
    }

    /// Clamps a rounded depth to the target (G76.DEPTH.LAST) and builds the pass.
    fn clamp(&self, n: u32, depth: u128, rule: Rule) -> Rough {
        // Both below 2^63 when the depth is kept: they fit i64.
        if depth >= u128::from(self.target) {
            Rough { n, depth: i64::try_from(self.target).unwrap_or(i64::MAX), last: true, rule: Rule::G76DepthLast }
        } else {
            Rough { n, depth: i64::try_from(depth).unwrap_or(i64::MAX), last: false, rule }
        }
    }

    /// The number of rough passes, or `None` when it exceeds `limit` (PRJ.MAXPASS).
    ///
    /// Closed form, so that the pass bound is checked before any motion without stepping
    /// through every pass (the time to the first move does not grow with the pass count):
    /// the pass `reach` where the depth reaches T when that comes before the switch pass s
    /// (constant mode: ⌈T / Δd⌉), else (s − 1) + ⌈(T − round(√(s−1)·Δd)) / Δdmin⌉.
    pub fn rough_pass_count(&self, limit: u32) -> Option<u32> {
        let count = if self.reach < self.switch {
            u128::from(self.reach)
        } else {
            // s ≤ reach: (s − 1)·Δd² ≤ T·(T − 1) < 2^126; the depth of pass s − 1 is below T,
            // and Δdmin ≥ 1 because a switch exists.
            let before = switch_depth(self.switch - 1, self.dd2);
            u128::from(self.switch - 1) + min_cuts(u128::from(self.target) - before, self.dmin)
        };
        u32::try_from(count).ok().filter(|&c| c <= limit)
    }
}

/// G78.DEPTHMODE 0: the depth n·Δd of pass n (a function of its own, so that a proof can
/// replace the product by its specification).
#[inline]
fn constant_depth(n: u32, dd: u64) -> u128 {
    u128::from(n) * u128::from(dd)
}

/// G76.DEPTH.1: the depth round(√(n·Δd²)) of pass n, `before` the guess (a function of its
/// own, so that a proof can replace the product and the root by their specification).
#[inline]
fn root_depth(n: u32, dd2: u128, before: u64) -> u64 {
    root(u128::from(n) * dd2, before)
}

/// G76.DEPTH.MIN: the depth round(√((s − 1)·Δd²)) of the pass before the switch pass s, given
/// s − 1 (a function of its own, so that a proof can replace it by its specification).
#[inline]
fn switch_depth(before_switch: u64, dd2: u128) -> u128 {
    sqrt_round(u128::from(before_switch) * dd2)
}

/// G76.DEPTH.MIN: the number ⌈rest / Δdmin⌉ of minimum cuts that cover `rest` (Δdmin read as
/// ≥ 1; a function of its own, so that a proof can replace the quotient by its specification).
#[inline]
fn min_cuts(rest: u128, dmin: u64) -> u128 {
    rest.div_ceil(u128::from(dmin.max(1)))
}

/// G76.DEPTH.MIN: the switch pass s, the first n ≥ 1 with (√n − √(n−1))·Δd < Δdmin, decided in
/// integers as Δd² < Δdmin² or a² < c²·(n − 1) with a = Δd² − Δdmin², c = 2·Δd·Δdmin; [`NEVER`]
/// when Δdmin = 0 (the strict inequality never holds).
///
/// The least m with c²·m > a² is ⌊a²/c²⌋ + 1, so s = ⌊a²/c²⌋ + 2: one division where a and c
/// fit 64 bits (every legal word: Δd, Δdmin < 2^30). Otherwise the test is monotone in n and a
/// binary search over the pass numbers finds s with 256-bit products.
fn switch_pass(dd: u64, dmin: u64) -> u64 {
    if dmin == 0 {
        return NEVER;
    }
    let (dd, dmin) = (u128::from(dd), u128::from(dmin));
    // Δd, Δdmin < 2^63: the squares are below 2^126.
    let (dd2, dmin2) = (dd * dd, dmin * dmin);
    if dd2 < dmin2 {
        return 1;
    }
    let a = dd2 - dmin2; // < 2^126
    let c = 2 * dd * dmin; // < 2^127, ≥ 2
    match (u64::try_from(a), u64::try_from(c)) {
        (Ok(a), Ok(c)) => {
            let (a, c) = (u128::from(a), u128::from(c));
            // a² / c² + 2 ≤ 2^128 / 4 + 2: fits u128; beyond u64 no pass gets there.
            u64::try_from((a * a) / (c * c) + 2).unwrap_or(NEVER)
        }
        _ => switch_search(a, c),
    }
}

/// The least n in 1..=2^32 with a² < c²·(n − 1), by binary search ([`switch_test`] is monotone
/// in n); [`NEVER`] when there is none (no pass number gets there).
fn switch_search(a: u128, c: u128) -> u64 {
    let holds = |n: u64| switch_test(a, c, n - 1);
    let cap = 1u64 << 32;
    if !holds(cap) {
        return NEVER;
    }
    // Invariant: lo = 0 or !holds(lo); holds(hi).
    let (mut lo, mut hi) = (0u64, cap);
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if holds(mid) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

/// a² < c²·m with a < 2^126, c < 2^127: 256-bit products; a right side beyond 2^256 exceeds a².
fn switch_test(a: u128, c: u128, m: u64) -> bool {
    let lhs = mul_wide(a, a); // (Δd² − Δdmin²)²
    let c2 = mul_wide(c, c); // 4·Δd²·Δdmin² < 2^254
    match c2.checked_mul_u64(m) {
        Some(rhs) => lhs < rhs,
        None => true,
    }
}

/// The most candidates [`root`] checks, from its guess upward, before it takes the square root.
const ROOT_WALK: u32 = 4;

/// round(√v), half up (`fixed::sqrt_round`). From one pass to the next the root grows by
/// Δd·(√n − √(n−1)) ≤ Δd / (2√(n−1)), so for most passes it is within a few increments above
/// the previous depth, `hint`: the candidates `hint`, `hint + 1`, … are checked exactly
/// (round(√v) = c ⇔ c² − c < v ≤ c² + c), at most [`ROOT_WALK`] of them, before the root is
/// taken. Walking up, the first c with v ≤ c² + c is the root if c² − c < v holds for it;
/// otherwise the guess was above the root. The walk is in 64 bits: a guess from 2^31 on, or
/// v from 2^64 on (words beyond the legal ranges), goes straight to the square root.
fn root(v: u128, hint: u64) -> u64 {
    if cfg!(feature = "planted-depth-bug") {
        return planted_root(v);
    }
    // Guesses below 2^31 and v below 2^64 (every legal word: depths below 2^30, so
    // v = n·Δd² ≤ T·(T − 1) < 2^60): each candidate is checked in 64 bits (c² + c < 2^63).
    if let (Ok(v), true) = (u64::try_from(v), hint < 1 << 31) {
        for c in hint..hint + u64::from(ROOT_WALK) {
            let sq = c * c;
            if v <= sq + c {
                // The first candidate with v ≤ c² + c: the root, or the guess was above it.
                if sq - c < v {
                    return c;
                }
                break;
            }
        }
    }
    // v < 2^128: the root is at most 2^64 − 1 (rounded half up, still below 2^64 + 1).
    u64::try_from(sqrt_round(v)).unwrap_or(u64::MAX)
}

/// TEST AID, never for production, used only with the feature `planted-depth-bug` (off by
/// default): a one-increment error in the G76.DEPTH.1 rounding — r + 1 instead of r when
/// v = r² + r (the comparison `≥ r` where `> r` is right: √(r² + r) < r + ½) — so that the
/// harness can be shown to find it (README, "Fuzzing"). With Δd = 1 increment this is pass 2
/// (√2 → 2 instead of 1).
fn planted_root(v: u128) -> u64 {
    let r = crate::fixed::isqrt(v);
    let up = r > 0 && v - r * r >= r;
    u64::try_from(r + u128::from(up)).unwrap_or(u64::MAX)
}

#[cfg(test)]
mod tests {
    extern crate std;
    use super::*;
    use crate::tests::xorshift;
    use std::vec::Vec;

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
}
