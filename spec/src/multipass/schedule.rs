//! The rough depth schedule of G76 (M001) and G78 (M000): G76.DEPTH.1, G76.DEPTH.MIN,
//! G76.DEPTH.LAST, G78.DEPTHMODE (docs/INTERPRETATION.md, "Depth schedule").
//!
//! Depths are radius increments measured from B. T = k − d is the depth of the last rough pass.
//! Each exact depth is rounded once (half up); the comparison with T is made on the rounded
//! depth.

use crate::exact::round_sqrt;
use cycle_vocab::Rule;
use num_bigint::BigInt;

/// How rough depths grow (G78.DEPTHMODE; G76 is always degressive).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum DepthMode {
    /// G78 D0: rough depth n is n·Δd.
    Constant,
    /// G76, G78 D1: rough depth n is √n·Δd, then minimum cuts.
    Degressive,
}

/// One rough pass: its radius depth and the rule that set it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Rough {
    pub depth: i64,
    pub rule: Rule,
}

/// More rough passes than the bound (PRJ.MAXPASS).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TooMany;

/// G76.DEPTH.MIN (M001): pass n cuts the minimum when (√n − √(n−1))·Δd < Δdmin, decided exactly
/// in integers: Δd² − Δdmin² < 0, or (Δd² − Δdmin²)² < 4·Δd²·Δdmin²·(n−1).
/// (From √n·Δd − Δdmin < √(n−1)·Δd, squared twice; both sides are non-negative where squared.)
pub fn cuts_minimum(dd: i64, dmin: i64, n: u64) -> bool {
    if dmin <= 0 {
        // Δdmin = 0: the left side Δd² > 0 and the right side 0, so never (no minimum).
        return false;
    }
    let dd2 = BigInt::from(dd) * BigInt::from(dd);
    let m2 = BigInt::from(dmin) * BigInt::from(dmin);
    let lhs = &dd2 - &m2;
    if lhs < BigInt::from(0) {
        return true;
    }
    &lhs * &lhs < BigInt::from(4) * dd2 * m2 * BigInt::from(n - 1)
}

/// G76.DEPTH.1 (M001): the exact depth √n·Δd, rounded once: round(√(n·Δd²)).
pub fn depth_sqrt(dd: i64, n: u64) -> i128 {
    let dd = dd as u128;
    round_sqrt(n as u128 * dd * dd) as i128
}

/// G76.DEPTH.MIN (M001): from the switch pass s on, the exact depth is
/// √(s−1)·Δd + (n − s + 1)·Δdmin; the integer part added does not change the rounding.
pub fn depth_min(dd: i64, dmin: i64, s: u64, n: u64) -> i128 {
    depth_sqrt(dd, s - 1) + (n - s + 1) as i128 * dmin as i128
}

/// G78.DEPTHMODE 0 (M000): rough depth n is n·Δd (exact).
pub fn depth_constant(dd: i64, n: u64) -> i128 {
    n as i128 * dd as i128
}

/// The rough passes for total depth k, finishing allowance d (d < k), first cut Δd ≥ 1 and
/// minimum cut Δdmin ≥ 0. G76.DEPTH.LAST (M001): a rounded depth ≥ T = k − d becomes T and is
/// the last rough pass. More than `limit` rough passes: [`TooMany`] (PRJ.MAXPASS), found after
/// computing at most `limit + 1` depths.
pub fn rough_passes(k: i64, d: i64, dd: i64, dmin: i64, mode: DepthMode, limit: u64) -> Result<Vec<Rough>, TooMany> {
    let t = (k - d) as i128;
    let mut passes = Vec::new();
    let mut switch: Option<u64> = None;
    let mut n: u64 = 0;
    loop {
        n += 1;
        if passes.len() as u64 >= limit {
            return Err(TooMany);
        }
        let (depth, rule) = match mode {
            DepthMode::Constant => (depth_constant(dd, n), Rule::G78DepthMode),
            DepthMode::Degressive => {
                if switch.is_none() && cuts_minimum(dd, dmin, n) {
                    switch = Some(n);
                }
                match switch {
                    None => (depth_sqrt(dd, n), Rule::G76Depth1),
                    Some(s) => (depth_min(dd, dmin, s, n), Rule::G76DepthMin),
                }
            }
        };
        if depth >= t {
            passes.push(Rough { depth: t as i64, rule: Rule::G76DepthLast });
            return Ok(passes);
        }
        passes.push(Rough { depth: depth as i64, rule });
    }
}

#[cfg(test)]
mod tests;
