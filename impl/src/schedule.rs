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
    #[cfg(test)]
    crate::probe::count_search();
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
    #[cfg(test)]
    crate::probe::count_root();
    u64::try_from(sqrt_round(v)).unwrap_or(u64::MAX)
}

/// TEST AID, never for production, used only with the feature `planted-depth-bug` (off by
/// default): a one-increment error in the G76.DEPTH.1 rounding — r + 1 instead of r when
/// v = r² + r (the comparison `≥ r` where `> r` is right: √(r² + r) < r + ½) — so that the
/// harness can be shown to find it (docs/FUZZING.md). With Δd = 1 increment this is pass 2
/// (√2 → 2 instead of 1).
fn planted_root(v: u128) -> u64 {
    let r = crate::fixed::isqrt(v);
    let up = r > 0 && v - r * r >= r;
    u64::try_from(r + u128::from(up)).unwrap_or(u64::MAX)
}

#[cfg(test)]
mod tests;
