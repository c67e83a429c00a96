//! The tangent tables' cross-checks (plain tests: no symbolic input, so not a harness).

use super::*;

/// Small δ at every angle against `f64::tan` (a coarse cross-check, test only): the exact
/// δ·tan lies within 10^-9 of the f64 value here, so a correct rounding is within ½ + 10^-9.
#[test]
fn tangent_matches_f64_for_small_delta() {
    for h in 0..=TAN_MAX_INDEX {
        let tan = (f64::from(h) * 0.5).to_radians().tan();
        for delta in (0..2000u64).chain([10_000, 123_457, 1_000_000]) {
            let t = mul_tan(delta, h) as f64;
            let exact = delta as f64 * tan;
            assert!((t - exact).abs() <= 0.5 + 1e-6, "h {h} δ {delta}: {t} vs {exact}");
        }
    }
}

/// An unsigned big integer, base 2^64, least significant limb first (test only).
#[derive(Clone, Debug, PartialEq, Eq)]
struct Big(Vec<u64>);

impl Big {
    fn from_u128(v: u128) -> Big {
        Big(vec![v as u64, (v >> 64) as u64]).trim()
    }
    fn trim(mut self) -> Big {
        while self.0.len() > 1 && self.0.last() == Some(&0) {
            self.0.pop();
        }
        self
    }
    fn mul(&self, o: &Big) -> Big {
        let mut out = vec![0u64; self.0.len() + o.0.len()];
        for (i, &a) in self.0.iter().enumerate() {
            let mut carry = 0u128;
            for (j, &b) in o.0.iter().enumerate() {
                let cur = u128::from(out[i + j]) + u128::from(a) * u128::from(b) + carry;
                out[i + j] = cur as u64;
                carry = cur >> 64;
            }
            out[i + o.0.len()] = carry as u64;
        }
        Big(out).trim()
    }
    fn add(&self, o: &Big) -> Big {
        let n = self.0.len().max(o.0.len()) + 1;
        let mut out = vec![0u64; n];
        let mut carry = 0u128;
        for (i, slot) in out.iter_mut().enumerate() {
            let cur = u128::from(*self.0.get(i).unwrap_or(&0)) + u128::from(*o.0.get(i).unwrap_or(&0)) + carry;
            *slot = cur as u64;
            carry = cur >> 64;
        }
        Big(out).trim()
    }
    /// self − o, requires self ≥ o.
    fn sub(&self, o: &Big) -> Big {
        assert!(self >= o);
        let mut out = self.0.clone();
        let mut borrow = 0i128;
        for (i, slot) in out.iter_mut().enumerate() {
            let cur = i128::from(*slot) - i128::from(*o.0.get(i).unwrap_or(&0)) - borrow;
            borrow = i128::from(cur < 0);
            *slot = cur.rem_euclid(1i128 << 64) as u64;
        }
        Big(out).trim()
    }
    fn pow2(bits: usize) -> Big {
        let mut v = vec![0u64; bits / 64 + 1];
        v[bits / 64] = 1 << (bits % 64);
        Big(v)
    }
}

impl PartialOrd for Big {
    fn partial_cmp(&self, o: &Big) -> Option<std::cmp::Ordering> {
        Some(self.cmp(o))
    }
}

impl Ord for Big {
    fn cmp(&self, o: &Big) -> std::cmp::Ordering {
        self.0.len().cmp(&o.0.len()).then_with(|| self.0.iter().rev().cmp(o.0.iter().rev()))
    }
}

/// The table entry as A = ⌊tan·2^128⌋; the true tangent lies in [A, A + 1)·2^-128 (exactly A
/// at 0° and 45°).
fn entry(h: u32) -> Big {
    let (int, frac) = tan_half_degrees(h).unwrap();
    Big::from_u128(u128::from(int)).mul(&Big::pow2(128)).add(&Big::from_u128(frac))
}

/// Each entry against its neighbour by tan(x + y)·(1 − tan x·tan y) = tan x + tan y with
/// y = 0.5°, in exact interval arithmetic on the table's enclosures (scaled by 2^384):
/// C·(2^256 − (A+1)(B+1)) ≤ (A + B + 2)·2^256 and (A + B)·2^256 ≤ (C + 1)·(2^256 − A·B).
/// Chained from tan 0 = 0 through tan 45° = 1 (exact) to 89°: an entry off by more than a
/// few units of 2^-128 (a few thousand near 89°, where the intervals widen with tan², still
/// below 2^-116) breaks the chain; tan 0.5° itself is pinned by landing on 1 at 45°.
#[test]
fn tangent_table_satisfies_the_addition_formula() {
    assert_addition_chain(entry, TAN_MAX_INDEX, 90, 2.0);
}

/// The chain of the addition formula over a table whose entry `i` is tan(i / `per_degree`
/// degrees) as ⌊tan·2^128⌋ (exact at 0 and at `exact45`, the index of 45°), each entry
/// against the one before with y = one step (see the test above).
fn assert_addition_chain(entry: impl Fn(u32) -> Big, max: u32, exact45: u32, per_degree: f64) {
    let one = Big::pow2(256);
    let b = entry(1);
    let b1 = b.add(&Big::from_u128(1));
    let exact = |i: u32| i == 0 || i == exact45;
    for i in 1..=max {
        let a = entry(i - 1);
        let c = entry(i);
        let a_hi = if exact(i - 1) { a.clone() } else { a.add(&Big::from_u128(1)) };
        let c_hi = if exact(i) { c.clone() } else { c.add(&Big::from_u128(1)) };
        let ab_lo = a.mul(&b);
        let ab_hi = a_hi.mul(&b1);
        assert!(ab_hi < one, "tan x·tan y < 1 below 90°");
        // LHS interval [c·(1 − ab_hi), c_hi·(1 − ab_lo)], RHS [(a + b), (a_hi + b1)], scaled.
        let lhs_lo = c.mul(&one.sub(&ab_hi));
        let lhs_hi = c_hi.mul(&one.sub(&ab_lo));
        let rhs_lo = a.add(&b).mul(&one);
        let rhs_hi = a_hi.add(&b1).mul(&one);
        let deg = |i: u32| f64::from(i) / per_degree;
        assert!(lhs_lo <= rhs_hi && rhs_lo <= lhs_hi, "tan({}°) inconsistent with tan({}°)", deg(i), deg(i - 1));
    }
}

/// The table on the 0.1° grid (G162.A), by the same addition formula with y = 0.1°: each
/// tenth against the one before, chained from tan 0 = 0 through tan 45° = 1 (exact) to 89°
/// (tan 0.1° is pinned by landing on 1 at 45°); and every tenth against `f64::tan` for
/// small δ (a coarse, independent cross-check).
#[test]
fn tenths_table_satisfies_the_addition_formula() {
    let entry_t = |t: u32| {
        let (int, frac) = tan_tenths(t).unwrap();
        Big::from_u128(u128::from(int)).mul(&Big::pow2(128)).add(&Big::from_u128(frac))
    };
    assert_addition_chain(entry_t, TAN_MAX_TENTHS, 450, 10.0);
    for t in 0..=TAN_MAX_TENTHS {
        let tan = (f64::from(t) * 0.1).to_radians().tan();
        for delta in (0..200u64).chain([10_000, 123_457]) {
            let v = cycle_impl::fixed::mul_tan_tenths(delta, t) as f64;
            assert!((v - delta as f64 * tan).abs() <= 0.5 + 1e-6, "t {t} δ {delta}");
        }
    }
}

/// The check above rejects an entry moved by 8 units of 2^-128 (at 30.5°).
#[test]
fn addition_formula_check_is_sharp() {
    let one = Big::pow2(256);
    let b = entry(1);
    let b1 = b.add(&Big::from_u128(1));
    let h = 61u32;
    let a = entry(h - 1);
    let consistent = |c: &Big| {
        let (a_hi, c_hi) = (a.add(&Big::from_u128(1)), c.add(&Big::from_u128(1)));
        let lhs_lo = c.mul(&one.sub(&a_hi.mul(&b1)));
        let lhs_hi = c_hi.mul(&one.sub(&a.mul(&b)));
        let rhs_lo = a.add(&b).mul(&one);
        let rhs_hi = a_hi.add(&b1).mul(&one);
        lhs_lo <= rhs_hi && rhs_lo <= lhs_hi
    };
    assert!(consistent(&entry(h)));
    assert!(!consistent(&entry(h).add(&Big::from_u128(8))));
    assert!(!consistent(&entry(h).sub(&Big::from_u128(8))));
}
