//! The depth split of a multi-pass G162 (G162.PQ, G162.SPLIT) as a pure step function, its pass
//! count in closed form (PRJ.MAXPASS), and the programmer's pitch conversion along a cone
//! (G162.F).

use crate::fixed::{isqrt, mul_wide};
use cycle_vocab::Rule;

/// The depth split of a multi-pass G162: P = thread depth, Q = allowance per pass (radius).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SplitParams {
    /// P ≥ 1.
    pub depth: i64,
    /// Q ≥ 1.
    pub allowance: i64,
}

/// One pass of the split.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Step {
    /// 1-based pass number.
    pub n: u32,
    /// Radius depth from the thread's depth-0 line X0, increments.
    pub depth: i64,
    /// Whether this is the last pass (its depth is P).
    pub last: bool,
    /// G162.PQ (a full allowance Q) or G162.SPLIT (a part of the remainder).
    pub rule: Rule,
    /// 0: a full pass; 1…4: the split target D/2, 3D/4, 7D/8, P that set the depth.
    pub stage: u8,
}

/// The split's numbers in their domain (P, Q ≥ 1), as unsigned magnitudes. (Public, hidden
/// from the docs, only so that a Kani proof can stub `norm` by its specification:
/// proofs/src/g162_split.rs.)
#[doc(hidden)]
pub struct Norm {
    pub p: u64,
    pub q: u64,
    /// k = ⌊P / Q⌋ full passes.
    pub k: u64,
    /// D = P − kQ, the remainder (0 ≤ D < Q).
    pub d: u64,
}

pub(super) fn norm(sp: &SplitParams) -> Norm {
    let p = sp.depth.max(1).unsigned_abs();
    let q = sp.allowance.max(1).unsigned_abs();
    let k = p / q;
    Norm { p, q, k, d: p - k * q }
}

/// Eighths of the remainder reached by split target `stage` (1…4): D/2, D/2 + D/4, … + D/8, D.
const EIGHTHS: [u64; 4] = [4, 6, 7, 8];

/// G162.SPLIT: the depth of split target `stage` (1…4), kQ + D·e/8 rounded once half up (the
/// last target is P exactly). `None` for another stage.
fn target(q: &Norm, stage: u8) -> Option<u64> {
    let e = EIGHTHS.get(usize::from(stage).checked_sub(1)?)?;
    // D < Q ≤ 2^63, so D·8 + 4 fits u128 easily; the result is at most D.
    let part = (u128::from(q.d) * u128::from(*e) + 4) / 8;
    let part = u64::try_from(part).unwrap_or(u64::MAX);
    Some((q.p - q.d).saturating_add(part))
}

fn step(n: u32, depth: u64, q: &Norm, stage: u8) -> Step {
    let rule = if stage == 0 { Rule::G162Pq } else { Rule::G162Split };
    Step { n, depth: i64::try_from(depth).unwrap_or(i64::MAX), last: depth >= q.p, rule, stage }
}

/// The first split target after stage `from` deeper than `prev`, as pass `n`.
fn split_after(q: &Norm, from: u8, prev: u64, n: u32) -> Option<Step> {
    // At most four targets: bounded work.
    (from.saturating_add(1)..=4).find_map(|stage| {
        let t = target(q, stage)?;
        // OPEN (allowance below one increment): a target not deeper than the previous pass is
        // dropped, so depths strictly increase and no zero cut is made.
        (t > prev).then(|| step(n, t, q, stage))
    })
}

/// G162.PQ, G162.SPLIT: the first pass — Q when Q ≤ P, else the first split target of P.
pub fn first(sp: &SplitParams) -> Step {
    let q = norm(sp);
    if q.k >= 1 {
        return step(1, q.q, &q, 0);
    }
    // D = P ≥ 1: the target D/2 rounds to at least 1 > 0.
    split_after(&q, 0, 0, 1).unwrap_or(step(1, q.p, &q, 4))
}

/// G162.PQ, G162.SPLIT: the pass after `prev`, or `None` after the last (the pass at depth P).
/// Full passes Q, 2Q, …, kQ; then, for D = P − kQ > 0, the targets kQ + D/2, kQ + 3D/4,
/// kQ + 7D/8 and P, each rounded once half up, a target not deeper than the previous dropped.
pub fn next(sp: &SplitParams, prev: &Step) -> Option<Step> {
    #[cfg(test)]
    crate::probe::count();
    let q = norm(sp);
    let prev_depth = prev.depth.max(0).unsigned_abs();
    if prev_depth >= q.p {
        return None;
    }
    let n = prev.n.checked_add(1)?;
    if prev.stage == 0 && u64::from(prev.n) < q.k {
        // Full pass n at depth nQ ≤ kQ ≤ P.
        return Some(step(n, full_depth(n, q.q), &q, 0));
    }
    split_after(&q, prev.stage, prev_depth, n)
}

/// G162.PQ: full pass n's depth nQ (saturating; nQ ≤ kQ ≤ P for every full pass). The one
/// product of the split's step, shared by `next` and the cycle's own stepping. (Public, hidden:
/// the proof harness `g162_split_tail` in cycle-proofs stubs it by its specification.)
#[doc(hidden)]
#[inline(always)]
pub fn full_depth(n: u32, q: u64) -> u64 {
    u64::from(n).saturating_mul(q)
}

/// PRJ.MAXPASS: the number of passes, or `None` when it exceeds `limit`. Closed form: the k
/// full passes plus the split targets kept (at most four, found by stepping).
pub fn pass_count(sp: &SplitParams, limit: u32) -> Option<u32> {
    let q = norm(sp);
    let mut count = q.k;
    let mut prev = q.p - q.d; // kQ
    for stage in 1..=4u8 {
        if q.d == 0 {
            break;
        }
        if let Some(t) = target(&q, stage) {
            if t > prev {
                count += 1;
                prev = t;
            }
        }
    }
    u32::try_from(count).ok().filter(|&c| c <= limit)
}

/// G162.F, COM.LONGAXIS: the F to program for a pitch measured along a cone of long-axis
/// length `long` and radius difference `rise` (same length unit): F = pitch·L/√(L² + r²),
/// rounded once half up (the manual's example: 2 mm, L = 50, r = 10 → 1.9612 on the lead grid,
/// printed 1.96). The controller does not convert (register): this is the programmer's
/// conversion, exact in integers. `None` when L = r = 0 or a product does not fit 128 bits.
pub fn pitch_along_long_axis(pitch: u64, long: u64, rise: u64) -> Option<u64> {
    let (f, l, r) = (u128::from(pitch), u128::from(long), u128::from(rise));
    let den = l.checked_mul(l)?.checked_add(r.checked_mul(r)?)?;
    if den == 0 {
        return None;
    }
    // x² = F²L²/S exactly; m = ⌊x⌋ = ⌊√⌊F²L²/S⌋⌋; round up when 4F²L² ≥ (2m + 1)²·S.
    let fl = f.checked_mul(l)?;
    let num = fl.checked_mul(fl)?;
    let m = isqrt(num / den);
    let twice = 2 * m + 1;
    let lhs = mul_wide(2 * fl, 2 * fl);
    let rhs = mul_wide(twice * twice, den);
    let rounded = if lhs >= rhs { m + 1 } else { m };
    u64::try_from(rounded).ok()
}
