//! Infeed points Bn of G76 (M001) and G78 (M000): G76.INFEED.X, G76.INFEED.Z, G76.MODE,
//! G78.MODE, G76.FINISH.Z (docs/INTERPRETATION.md, "Infeed X", "Infeed Z and the modes").

use super::Cycle;
use crate::tangent::round_mul_tan_half_angle;
use cycle_vocab::readings::ThreadZRef;

/// Which flank a rough pass follows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flank {
    Right,
    Centre,
    Left,
}

/// G76.MODE (M001): e = 0 right flank; 1 odd passes right, even centre; 2 odd left, even right.
/// G78.MODE (M000): 0 centre; 1 left; 2 right; 3 odd right, even centre; 4 odd left, even right.
/// `n` is the pass index among the rough passes (1-based).
pub fn flank(cycle: Cycle, mode: u32, n: u64) -> Flank {
    let odd = n % 2 == 1;
    match (cycle, mode) {
        (Cycle::G76, 1) | (Cycle::G78, 3) => {
            if odd {
                Flank::Right
            } else {
                Flank::Centre
            }
        }
        (Cycle::G76, 2) | (Cycle::G78, 4) => {
            if odd {
                Flank::Left
            } else {
                Flank::Right
            }
        }
        (Cycle::G78, 0) => Flank::Centre,
        (Cycle::G78, 1) => Flank::Left,
        _ => Flank::Right,
    }
}

/// G76.INFEED.X (M001): pass at radius depth δ: X = D.x + i + s·(k − δ) (radius), on diameter
/// D.x + 2i + 2s(k − δ) = C.x + 2s(k − δ).
pub fn infeed_x(c_x: i128, s: i128, k: i64, depth: i64) -> i128 {
    c_x + 2 * s * (k as i128 - depth as i128)
}

/// t(δ) = round(δ·tan(a/2)) (G76.INFEED.Z), exact (see [`crate::tangent`]); a ≤ 99.
pub fn t(depth: i64, a: u32) -> i128 {
    round_mul_tan_half_angle(depth, a).unwrap_or(0) as i128
}

/// G76.INFEED.Z (M001, M000) with the modes, under the declared reading `thread.zref`; σ = −s
/// (positive infeed shifts +Z, negative −Z); t(δ) this pass's shift, t(T) the last rough pass's.
/// * `start` (the letter: one reference point B at the start's Z, one formula Z start ± X depth
///   × tan(a/2), `001_…` line 117, `000_…` lines 138, 169–181): right flank Z = A.z + σ·t(δ);
///   centre Z = A.z (radial along B's line); left flank Z = A.z − σ·t(δ).
/// * `groove` (the reading before): right flank A.z + σ·t(δ); centre A.z + σ·t(T); left flank
///   A.z + σ·(2·t(T) − t(δ)), the mirror of the right flank about the centre, so every mode
///   ends its last rough pass on the same groove.
pub fn infeed_z(a_z: i128, s: i128, t_depth: i128, t_last: i128, flank: Flank, zref: ThreadZRef) -> i128 {
    let sigma = -s;
    match (zref, flank) {
        (_, Flank::Right) => a_z + sigma * t_depth,
        (ThreadZRef::Start, Flank::Centre) => a_z,
        (ThreadZRef::Start, Flank::Left) => a_z - sigma * t_depth,
        (ThreadZRef::Groove, Flank::Centre) => a_z + sigma * t_last,
        (ThreadZRef::Groove, Flank::Left) => a_z + sigma * (2 * t_last - t_depth),
    }
}

#[cfg(test)]
mod tests;
