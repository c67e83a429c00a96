//! The peck arithmetic of the peck-step harnesses (`g74_peck_step`, `g83_peck_step`): G74.PECK,
//! G74.COLUMN, G75.PECK, G75.COLUMN, G83.PECK, PRJ.MAXPASS.
//!
//! The production cycles place peck i (column j) at base + dir·min(i·len, total)
//! (`cycle_impl::g74::nth`, G83's `peck_end`) and count ⌈total / len⌉ of them
//! (`cycle_impl::g74::ceil_div`). The two nonlinear parts are functions of their own in impl:
//! the product i·len (`cycle_impl::g74::span`) and the count (`ceil_div`). A [`Line`] holds what a
//! harness needs of one of them (the pecks, or the columns): the count K and the products
//! S(m) = m·len for the three m = m₀, m₀ + 1, m₀ + 2 one step asks about.
//!
//! **Under Kani** K and S(m₀) are drawn symbolic, S(m₀ + 1) = S(m₀) + len and
//! S(m₀ + 2) = S(m₀ + 1) + len, under the assumptions [`Line::spec`] lists — each an instance of smt/ lemma 16
//! (`16_peck_count.smt2`: for total ≥ 1, len ≥ 1 and K = ⌈total / len⌉, m·len ≥ total ⇔ m ≥ K,
//! K ≥ 1, (K − 1)·len < total ≤ K·len) — and `span` and `ceil_div` are stubbed by lookups in the
//! lines ([`stubs`]), which *assert* that the cycle asks for nothing else (0·len and 1·len are
//! answered without the table).
//!
//! **Under the drivers** K is the real `ceil_div`, S(m) the exact product (`u128`), and every
//! assumption of [`Line::spec`] is *checked*: the specification the Kani stubs trust is tested
//! on every case the drivers run, over the full legal ranges.

use crate::source::{Outcome, Source, Stop};

/// One counted line: the pecks of a column (total = the depth, len = the peck) or the columns
/// (total = the step travel, len = the step).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Line {
    /// The total length (≥ 0) and the step length (≥ 0).
    pub total: u64,
    pub len: u64,
    /// ⌈total / len⌉ (only meaningful, and only asked for, when total ≥ 1 and len ≥ 1).
    pub count: u64,
    /// The first index of the table and S(m₀), S(m₀ + 1), S(m₀ + 2).
    pub m0: u64,
    pub s: [u64; 3],
}

impl Line {
    /// The line of `total` by `len` with its count (the table not yet drawn): under Kani any K,
    /// under the drivers the real `ceil_div` (0 when the cycle does not count this line).
    pub fn count<S: Source>(src: &mut S, total: u64, len: u64) -> Line {
        let _ = &src;
        #[cfg(kani)]
        let count = kani::any::<u64>();
        #[cfg(not(kani))]
        let count = if total >= 1 && len >= 1 { cycle_impl::g74::ceil_div(total as i64, len as i64) } else { 0 };
        Line { total, len, count, m0: 0, s: [0; 3] }
    }

    /// S(m) = m·len for m ∈ m₀ … m₀ + 2 (as `i128`).
    pub fn span(&self, m: u64) -> i128 {
        let k = m.wrapping_sub(self.m0);
        let v = if k == 0 { self.s[0] } else if k == 1 { self.s[1] } else { self.s[2] };
        i128::from(v)
    }

    /// The table at m₀ (see the module documentation), with [`Line::spec`] assumed (Kani) or
    /// checked (drivers).
    pub fn table<S: Source>(mut self, src: &mut S, m0: u64) -> Result<Line, Stop> {
        self.m0 = m0;
        #[cfg(kani)]
        {
            let s0 = kani::any::<u64>();
            let s1 = s0.checked_add(self.len);
            let s2 = s1.and_then(|v| v.checked_add(self.len));
            src.assume(s2.is_some())?;
            self.s = [s0, s1.unwrap_or(0), s2.unwrap_or(0)];
        }
        #[cfg(not(kani))]
        {
            let exact = |k: u64| u128::from(m0 + k) * u128::from(self.len);
            let s = [exact(0), exact(1), exact(2)];
            crate::check!(src, s[2] <= u128::from(u64::MAX), "m·len < 2^64 for the three products a step asks about");
            self.s = [s[0] as u64, s[1] as u64, s[2] as u64];
        }
        self.spec(src)?;
        Ok(self)
    }

    /// What the line satisfies (lemma 16; the drivers check what Kani assumes). No loop, so
    /// that the harnesses' unwind bound stays the cycle's.
    pub fn spec<S: Source>(&self, src: &mut S) -> Outcome {
        let (s, len, m0) = (self.s, u128::from(self.len), self.m0);
        trusted(src, u128::from(s[1]) == u128::from(s[0]) + len && u128::from(s[2]) == u128::from(s[1]) + len, "(m + 1)·len = m·len + len")?;
        trusted(src, (m0 != 0 || s[0] == 0) && (m0 != 1 || u128::from(s[0]) == len), "0·len = 0, 1·len = len")?;
        let counted = self.total >= 1 && self.len >= 1;
        let at = |k: u64| m0.checked_add(k).is_some_and(|m| m >= self.count);
        trusted(src, !counted || self.count >= 1, "lemma 16: K = ⌈total / len⌉ ≥ 1")?;
        trusted(src, !counted || (s[0] >= self.total) == at(0), "lemma 16: m·len ≥ total exactly from K on (m₀)")?;
        trusted(src, !counted || (s[1] >= self.total) == at(1), "lemma 16: m·len ≥ total exactly from K on (m₀ + 1)")?;
        trusted(src, !counted || (s[2] >= self.total) == at(2), "lemma 16: m·len ≥ total exactly from K on (m₀ + 2)")?;
        Ok(())
    }
}

/// Two lines of equal len agree where their tables overlap, and equal (total, len) have equal
/// counts (one function each, `span` and `ceil_div`): assumed under Kani, checked by the drivers.
pub fn consistent<S: Source>(src: &mut S, p: &Line, q: &Line) -> Outcome {
    counts_agree(src, p, q)?;
    let agree = |a: &Line, b: &Line| {
        let d = b.m0.wrapping_sub(a.m0);
        b.m0 < a.m0 || d > 2 || a.span(b.m0) == i128::from(b.s[0])
    };
    trusted(src, p.len != q.len || (agree(p, q) && agree(q, p)), "span is a function")
}

/// Equal (total, len) have equal counts (`ceil_div` is a function): assumed under Kani, checked
/// by the drivers — before the cycle counts, since its stub answers a call from either line.
pub fn counts_agree<S: Source>(src: &mut S, p: &Line, q: &Line) -> Outcome {
    let same_count = (p.total, p.len) != (q.total, q.len) || p.count == q.count || p.total == 0 || p.len == 0;
    trusted(src, same_count, "ceil_div is a function")
}

/// dir·x for a direction dir ∈ {−1, 0, 1}, without a multiplier (the harnesses' own arithmetic).
pub fn along(dir: i128, x: i128) -> i128 {
    if dir < 0 {
        -x
    } else if dir == 0 {
        0
    } else {
        x
    }
}

/// An assumption the Kani stubs trust (Kani: assumed) that the drivers check.
pub fn trusted<S: Source>(src: &mut S, ok: bool, msg: &'static str) -> Outcome {
    if cfg!(kani) {
        src.assume(ok)
    } else {
        src.verdict(ok, msg)
    }
}

/// The Kani stubs of `cycle_impl::g74::{span, ceil_div}`: lookups in the lines the harness set
/// (TRUSTED specification: [`Line::spec`], lemma 16; checked by the drivers). Line 0 is the
/// pecks, line 1 the columns (G83: unused, never matches).
#[cfg(kani)]
pub mod stubs {
    use super::Line;
    use core::sync::atomic::{AtomicBool, AtomicU64, Ordering::SeqCst};

    static USED: [AtomicBool; 2] = [AtomicBool::new(false), AtomicBool::new(false)];
    /// total, len, count, m₀, s₀, s₁, s₂ of each line.
    static LINE: [[AtomicU64; 7]; 2] = [
        [AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0)],
        [AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0), AtomicU64::new(0)],
    ];

    /// Sets line `i` (0: pecks, 1: columns).
    pub fn set(i: usize, l: &Line) {
        let v = [l.total, l.len, l.count, l.m0, l.s[0], l.s[1], l.s[2]];
        let slot = &LINE[i];
        slot[0].store(v[0], SeqCst);
        slot[1].store(v[1], SeqCst);
        slot[2].store(v[2], SeqCst);
        slot[3].store(v[3], SeqCst);
        slot[4].store(v[4], SeqCst);
        slot[5].store(v[5], SeqCst);
        slot[6].store(v[6], SeqCst);
        USED[i].store(true, SeqCst);
    }

    fn get(i: usize, k: usize) -> u64 {
        LINE[i][k].load(SeqCst)
    }

    fn count_of(i: usize, a: u64, b: u64) -> Option<u64> {
        (USED[i].load(SeqCst) && a == get(i, 0) && b == get(i, 1)).then(|| get(i, 2))
    }

    fn span_of(i: usize, m: u64, len: u64) -> Option<u128> {
        if !USED[i].load(SeqCst) || len != get(i, 1) || m < get(i, 3) {
            return None;
        }
        let k = m - get(i, 3);
        if k > 2 {
            return None;
        }
        Some(u128::from(get(i, 4 + k as usize)))
    }

    /// `ceil_div(a, b)` = ⌈a / b⌉: the line's count.
    pub fn ceil_div_spec(a: i64, b: i64) -> u64 {
        let (a, b) = (a.unsigned_abs(), b.unsigned_abs());
        let k = count_of(0, a, b).or_else(|| count_of(1, a, b));
        kani::assert(k.is_some() && a >= 1 && b >= 1, "the cycle counts only the pecks and the columns, of a length ≥ 1 by a step ≥ 1");
        k.unwrap_or(0)
    }

    /// `toward(dir, len)` = dir·len for dir ∈ {−1, 0, 1} (asserted), without a multiplier: the
    /// specification the Kani proof `peck_toward` proves of the real function.
    pub fn toward_spec(dir: i64, len: i64) -> i64 {
        kani::assert((-1..=1).contains(&dir), "toward is asked only for a direction −1, 0, 1");
        crate::peck_toward::spec(dir, len)
    }

    /// `span(i, len)` = i·|len|: 0 and |len| for i = 0, 1 (no product), else the line's table.
    pub fn span_spec(i: u64, len: i64) -> u128 {
        let len = len.unsigned_abs();
        if i <= 1 {
            return if i == 0 { 0 } else { u128::from(len) };
        }
        let v = span_of(0, i, len).or_else(|| span_of(1, i, len));
        kani::assert(v.is_some(), "the cycle asks only for the products of the pecks and columns in the table");
        v.unwrap_or(0)
    }
}
