//! The register's arithmetic, restated independently of `cycle-impl` for the harnesses'
//! expectations: rounded square roots by their bracket (no root is taken), the switch pass of
//! G76.DEPTH.MIN in closed form, half-up quotients. Loop-free except the 256-bit helpers
//! ([`W256`], loops over its four limbs: unwind 5 where a harness uses them).
//! Inputs are within the legal ranges (lengths ≤ N = 999 999 999 < 2^30), where every product
//! below fits `u128`.

/// Whether `r` is √`n` rounded half up: r − ½ ≤ √n < r + ½. For n = 0 that is r = 0; for
/// n ≥ 1 (so r ≥ 1) it is r(r − 1) < n ≤ r(r + 1) (squares of half-integers are never integers).
pub fn is_sqrt_round(r: u128, n: u128) -> bool {
    if n == 0 {
        return r == 0;
    }
    if r == 0 {
        return false;
    }
    let below = match r.checked_mul(r - 1) {
        Some(v) => v,
        None => return false, // r(r − 1) ≥ 2^128 > n
    };
    let above_ok = match r.checked_mul(r + 1) {
        Some(v) => n <= v,
        None => true,
    };
    below < n && above_ok
}

/// Whether √`n` rounded half up is at least `t` (t ≥ 1): √n ≥ t − ½ ⇔ n > t(t − 1).
pub fn sqrt_round_at_least(n: u128, t: u128) -> bool {
    match t.checked_mul(t - 1) {
        Some(v) => n > v,
        None => false,
    }
}

/// G76.DEPTH.MIN in closed form: the first pass s ≥ 1 at which (√s − √(s−1))·Δd < Δdmin, or
/// `None` when Δdmin = 0 (no minimum) or s would exceed `u32::MAX`.
///
/// The register decides pass n by Δd² − Δdmin² < 0, or (Δd² − Δdmin²)² < 4·Δd²·Δdmin²·(n − 1).
/// With a = Δd² − Δdmin² ≥ 0 and c = 4·Δd²·Δdmin² > 0 the second form is n − 1 > a²/c, so
/// s = ⌊a²/c⌋ + 2. (Legal Δd, Δdmin < 2^30: a² < 2^120, c < 2^122.)
pub fn switch_pass(first_cut: i64, min_cut: i64) -> Option<u32> {
    if min_cut <= 0 {
        return None;
    }
    let dd2 = (first_cut as u128) * (first_cut as u128);
    let dm2 = (min_cut as u128) * (min_cut as u128);
    if dd2 < dm2 {
        return Some(1);
    }
    let a = dd2 - dm2;
    let c = 4 * dd2 * dm2;
    let s = (a * a) / c + 2;
    u32::try_from(s).ok()
}

/// n·Δd²: the square of the exact depth √n·Δd of G76.DEPTH.1.
pub fn depth_square(n: u32, first_cut: i64) -> u128 {
    u128::from(n) * (first_cut as u128) * (first_cut as u128)
}

/// `num / den` rounded half up (den > 0): ⌊num/den + ½⌋ = ⌊(2·num + den) / (2·den)⌋, the q with
/// q − ½ ≤ num/den < q + ½. (num < 2^126.)
pub fn div_round_half_up(num: u128, den: u128) -> u128 {
    (2 * num + den) / (2 * den)
}

/// An unsigned 256-bit integer as four 64-bit limbs, least significant first: the harnesses'
/// own wide arithmetic (schoolbook over limbs), independent of `cycle_impl::fixed::U256`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct W256(pub [u64; 4]);

impl W256 {
    pub const fn from_u128(v: u128) -> W256 {
        W256([v as u64, (v >> 64) as u64, 0, 0])
    }

    /// The exact product of two `u128`.
    pub fn mul(a: u128, b: u128) -> W256 {
        let x = [a as u64, (a >> 64) as u64];
        let y = [b as u64, (b >> 64) as u64];
        let mut out = [0u64; 4];
        for (i, &xi) in x.iter().enumerate() {
            let mut carry = 0u128;
            for (j, &yj) in y.iter().enumerate() {
                let cur = u128::from(out[i + j]) + u128::from(xi) * u128::from(yj) + carry;
                out[i + j] = cur as u64;
                carry = cur >> 64;
            }
            out[i + 2] = carry as u64;
        }
        W256(out)
    }

    /// `self + other`, `None` on overflow past 256 bits.
    pub fn checked_add(self, other: W256) -> Option<W256> {
        let mut out = [0u64; 4];
        let mut carry = 0u128;
        for (i, o) in out.iter_mut().enumerate() {
            let cur = u128::from(self.0[i]) + u128::from(other.0[i]) + carry;
            *o = cur as u64;
            carry = cur >> 64;
        }
        (carry == 0).then_some(W256(out))
    }

    /// `self · 2^(64·k)` for k ≤ 3 (limbs shifted out are dropped).
    pub fn shift_limbs(self, k: usize) -> W256 {
        let mut out = [0u64; 4];
        out[k..].copy_from_slice(&self.0[..4 - k]);
        W256(out)
    }

    /// The high and low 128-bit halves.
    pub fn halves(self) -> (u128, u128) {
        (
            (u128::from(self.0[3]) << 64) | u128::from(self.0[2]),
            (u128::from(self.0[1]) << 64) | u128::from(self.0[0]),
        )
    }
}

impl PartialOrd for W256 {
    fn partial_cmp(&self, other: &W256) -> Option<core::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for W256 {
    fn cmp(&self, other: &W256) -> core::cmp::Ordering {
        let a = [self.0[3], self.0[2], self.0[1], self.0[0]];
        let b = [other.0[3], other.0[2], other.0[1], other.0[0]];
        a.cmp(&b)
    }
}

/// Whether `q` is `num / den` rounded half up (den ≥ 1): q − ½ ≤ num/den < q + ½, i.e.
/// 2·q·den ≤ 2·num + den and 2·num < 2·q·den + den, decided in 256 bits.
pub fn is_div_round(q: u128, num: u128, den: u128) -> bool {
    let qd = W256::mul(q, den);
    let two_qd = qd.checked_add(qd);
    let two_num = W256::mul(num, 2);
    let d = W256::from_u128(den);
    // 2·num + den < 2^130 always fits. 2·q·den ≥ 2^256 > 2·num + den means q is too large.
    match (two_qd, two_num.checked_add(d)) {
        (Some(two_qd), Some(rhs)) => two_qd <= rhs && two_qd.checked_add(d).is_some_and(|hi| two_num < hi),
        _ => false,
    }
}

/// [`is_div_round`] for operands that fit 64 bits, decided in `u128` with no loop: q·den < 2^128
/// always; when 2·q·den does not fit 128 bits it exceeds 2·num + den < 2^66, so q is too large.
/// The same bracket, 2·q·den ≤ 2·num + den and 2·num < 2·q·den + den; for a Kani harness whose
/// ranges fit 64 bits (the 256-bit helpers' loops cost a SAT solver far more than one product).
pub fn is_div_round_u64(q: u64, num: u64, den: u64) -> bool {
    let (q, num, den) = (u128::from(q), u128::from(num), u128::from(den));
    let Some(two_qd) = (q * den).checked_mul(2) else { return false };
    let rhs = 2 * num + den;
    // Evaluated only when two_qd ≤ rhs < 2^66: no overflow.
    two_qd <= rhs && 2 * num < two_qd + den
}

#[cfg(test)]
mod tests;
