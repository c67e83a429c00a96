//! A line's cut stepped from layer to layer without a division (G71.LAYER, G72.LAYER).
//!
//! On a line element from (a₀, b₀) to (a₁, b₁), layer k's cut is round(N_k / D) with
//! D = a₁ − a₀ and N_k = b₀·D + (a_k − a₀)·(b₁ − b₀) (`cut_on`). Consecutive layers stand
//! s·step apart (a_{k+1} − a_k = s·step, exactly: no a_k saturates, see the module's bounds), so
//! N_{k+1} = N_k + I with I = s·step·(b₁ − b₀), the same I for every layer on the element.
//!
//! **Exactness.** Normalise D > 0 (negate N, D and I together: the quotient is unchanged). Keep
//! N_k = q·D + r with 0 ≤ r < D (Euclidean division, done once when the sweep reaches the
//! element) and I = dq·D + dr with 0 ≤ dr < D. Then N_{k+1} = (q + dq)·D + (r + dr) with
//! 0 ≤ r + dr < 2D: one conditional subtraction of D (and q + 1) restores 0 ≤ r < D. So q and r
//! stay exactly ⌊N_k / D⌋ and N_k mod D, with no division per layer.
//!
//! **The same rounding as `div_round_signed`** (half away from zero on N/D): N ≥ 0 exactly when
//! q ≥ 0 (q ≥ 0 gives N = qD + r ≥ 0; q ≤ −1 gives N ≤ −D + r < 0). For N ≥ 0, N/D = q + r/D
//! rounds to q + 1 when r/D ≥ ½, i.e. 2r ≥ D — the test `div_round` makes on |N| mod D = r. For
//! N < 0, |N| = (−q − 1)·D + (D − r) when r > 0: its magnitude rounds up, to −q, when
//! 2(D − r) ≥ D, i.e. 2r ≤ D, giving −(−q) = q; else to −q − 1, giving q + 1. So the value is
//! q + 1 when 2r > D, else q (r = 0 is exact, q). Both cases are written below without
//! overflow as r ≥ D − r and r > D − r. The unit tests check every step against the division.
//!
//! **Bounds.** |N| < 2^127 and |D| < 2^64 (the module's bounds), |I| < 2^31·2^64; q and q + dq
//! stay the cut coordinate of a layer that crosses the element, within i64.

/// round(N_k / D) for consecutive layers k on one line element.
#[derive(Clone, Copy, Debug, Default)]
pub struct LineStep {
    q: i128,
    r: i128,
    den: i128,
    dq: i128,
    dr: i128,
}

impl LineStep {
    /// The quotient N / `den` and its step `inc` per layer; `None` when `den` = 0.
    pub fn new(num: i128, den: i128, inc: i128) -> Option<LineStep> {
        if den == 0 {
            return None;
        }
        let (num, den, inc) = if den < 0 { (-num, -den, -inc) } else { (num, den, inc) };
        Some(LineStep { q: num.div_euclid(den), r: num.rem_euclid(den), den, dq: inc.div_euclid(den), dr: inc.rem_euclid(den) })
    }

    /// round(N / D), half away from zero (the value `div_round_signed` gives).
    #[inline]
    pub fn value(&self) -> i128 {
        let half = self.den - self.r;
        let up = if self.q >= 0 { self.r >= half } else { self.r > half };
        if up {
            self.q + 1
        } else {
            self.q
        }
    }

    /// N ← N + I: the next layer.
    #[inline]
    pub fn advance(&mut self) {
        self.q += self.dq;
        self.r += self.dr;
        if self.r >= self.den {
            self.r -= self.den;
            self.q += 1;
        }
    }
}

#[cfg(test)]
mod tests;
