//! TEST `g162_split_exact` (driver-only: not a Kani proof) — G162.PQ, G162.SPLIT, PRJ.MAXPASS.
//!
//! **Property.** For all legal P (thread depth) and Q (allowance), 1…N each, N = 999 999 999,
//! the production split `cycle_impl::g162::{first, next, pass_count}` is the register's
//! (docs/INTERPRETATION.md, "Depths"), computed here independently ([`model`]):
//!
//! - k = ⌊P/Q⌋ full passes at Q, 2Q, …, kQ (rule G162.PQ), then for the remainder
//!   D = P − kQ > 0 the targets kQ + D/2, kQ + 3D/4, kQ + 7D/8 and P, each rounded once half up
//!   (checked by its exact bracket 8t − 4 ≤ 8kQ + e·D < 8t + 4, no division), a target not
//!   deeper than the previous pass dropped (rule G162.SPLIT); D = 0: nothing after kQ;
//! - `first` is pass 1 of that sequence; for **every** full pass n (1 ≤ n ≤ k, symbolic),
//!   `next` of it is pass n + 1 of the sequence (so by induction from `first` every full pass
//!   is the model's, for all k up to 10⁹, without iterating); from the last full pass the tail
//!   (≤ 4 passes) is iterated whole;
//! - depths strictly increase, never pass P, the last pass is exactly at P (`last` exactly
//!   there, `None` after it), and the split cuts sum exactly to D (every split cut ≥ 1);
//! - `pass_count(p, limit)` is k + (kept targets) when that is ≤ `limit`, else `None`.
//!
//! **Not a Kani proof (yet).** Over the full ranges Kani 0.61.0 / CBMC 6.4.0 reached no verdict
//! in 1 289 s (issue #25). The bounded scope [`KANI`] below was prepared but not run to a verdict
//! (and would lose P, Q ≥ 2^12), so it is a TEST (its Kani harness is built only with `kani-attempts`).
//!
//! **TEST `g162_split_tail`** ([`tail_body`], also driver-only): the same split over the full
//! ranges, P formed as kQ + D so that no division is needed and `norm` stubbed by k and D
//! ([`stubs`]) — everything of [`body`] that is linear in P, k and D. Under Kani the base kQ is
//! drawn free of the product (`free_base`: a superset of the real cases, nothing lost) and the
//! rounding bracket is checked with each e a constant. Kani reached no verdict
//! on it either (CaDiCaL: 10 min; Kissat 4.0.1: 15 min; proofs/README.md); the harness that
//! was run is its `property!` (a proof harness with `kani-attempts`).
//!
//! **Intended Kani bounds.** P, Q ≤ 2^12 − 1 ([`KANI`]; n and `limit` symbolic over their whole ranges);
//! the drivers sample the full legal ranges ([`FULL`]). The only loops
//! are the tail iteration (≤ 5), the model's four targets and the production's four targets
//! (`split_after`, `pass_count`): `#[kani::unwind(6)]`.

use crate::source::{bounded_i64_upto, Outcome, Source};
use crate::{check, cover};
use cycle_impl::g162::{first, next, pass_count, SplitParams, Step};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::Rule;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest P and Q.
    pub max_len: i64,
}

/// What the drivers sample: the full legal ranges.
pub const FULL: Scope = Scope { max_len: MAX_LENGTH };

/// The bounded scope prepared for Kani (not run to a verdict; a proof harness only with `kani-attempts`): P, Q ≤ 2^12 − 1
/// (1.7·10^7 pairs, every full pass n and every limit symbolic). The full ranges are left to the drivers: checking ⌊P/Q⌋ and n·Q of
/// 30-bit words against the model bit-blasts to nonlinear equivalences (two dividers, two
/// multipliers) that did not finish in 1 289 s (issue #25).
pub const KANI: Scope = Scope { max_len: (1 << 12) - 1 };

/// The register's split, computed independently of `cycle-impl`.
pub mod model {
    /// Eighths of the remainder of the four split targets.
    pub const EIGHTHS: [i64; 4] = [4, 6, 7, 8];

    /// The split of P by Q: k, the remainder D, and the kept split targets (depth, eighths) in
    /// order, `count` of them.
    #[derive(Clone, Copy, Debug, PartialEq, Eq)]
    pub struct Split {
        pub k: i64,
        pub d: i64,
        pub tail: [(i64, i64); 4],
        pub count: usize,
    }

    /// kQ + e·D/8 rounded half up: ⌊(8kQ + e·D + 4) / 8⌋ (all non-negative, so the floor
    /// of the quotient by 8 is the shift by 3).
    pub fn target(kq: i64, d: i64, e: i64) -> i64 {
        (8 * kq + e * d + 4) >> 3
    }

    pub fn split(p: i64, q: i64) -> Split {
        let k = p / q;
        split_from(k, k * q, p - k * q)
    }

    /// The split given k = ⌊P/Q⌋, kQ and the remainder D = P − kQ (no division, no product).
    pub fn split_from(k: i64, kq: i64, d: i64) -> Split {
        let mut s = Split { k, d, tail: [(0, 0); 4], count: 0 };
        if d == 0 {
            return s;
        }
        let mut prev = kq;
        for e in EIGHTHS {
            let t = target(kq, d, e);
            if t > prev {
                if let Some(slot) = s.tail.get_mut(s.count) {
                    *slot = (t, e);
                }
                s.count += 1;
                prev = t;
            }
        }
        s
    }

    /// Whether t is kQ + e·D/8 rounded half up, by its bracket: 8t − 4 ≤ 8kQ + e·D < 8t + 4.
    pub fn is_rounded_target(t: i64, kq: i64, d: i64, e: i64) -> bool {
        let exact8 = i128::from(8 * kq) + i128::from(e) * i128::from(d);
        let t8 = 8 * i128::from(t);
        t8 - 4 <= exact8 && exact8 < t8 + 4
    }
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let p = src.bounded_i64(1, scope.max_len);
    let q = src.bounded_i64(1, scope.max_len);
    let limit = src.bounded_u32(0, u32::MAX);
    let sp = SplitParams { depth: p, allowance: q };
    let m = model::split(p, q);
    let kq = m.k * q;
    check!(src, kq + m.d == p && m.d >= 0 && m.d < q, "k = ⌊P/Q⌋ and 0 ≤ D < Q");
    // The e = 8 target is P itself; the model's tail ends there when D > 0.
    check!(src, m.d == 0 || (m.count >= 1 && m.tail.get(m.count - 1).map(|t| t.0) == Some(p)), "the split ends at P");

    // Pass 1.
    let f = first(&sp);
    let want_first = if m.k >= 1 { (q, Rule::G162Pq) } else { (m.tail[0].0, Rule::G162Split) };
    check!(
        src,
        f.n == 1 && (f.depth, f.rule) == want_first,
        "G162.PQ / G162.SPLIT: pass 1 is Q, or the first split target when Q > P"
    );
    check!(src, f.last == (f.depth == p), "last exactly at depth P (pass 1)");

    // Every full pass n: `next` is the model's pass n + 1.
    if m.k >= 1 {
        let n = bounded_i64_upto(src, 1, m.k, scope.max_len)?;
        let prev = Step { n: n as u32, depth: n * q, last: n * q == p, rule: Rule::G162Pq, stage: 0 };
        let nx = next(&sp, &prev);
        if n < m.k {
            let want =
                Step { n: n as u32 + 1, depth: (n + 1) * q, last: (n + 1) * q == p, rule: Rule::G162Pq, stage: 0 };
            check!(src, nx == Some(want), "G162.PQ: after full pass n < k comes full pass n + 1 at (n + 1)·Q");
        } else if m.d == 0 {
            check!(src, nx.is_none() && prev.last, "D = 0: the last full pass is at P and nothing follows");
        } else {
            check!(
                src,
                nx.is_some_and(|s| s.n == n as u32 + 1 && s.depth == m.tail[0].0),
                "after the last full pass comes the first split target"
            );
        }
        cover!(src, n < m.k, "a full pass before the last");
        cover!(src, n == m.k && m.d > 0, "the last full pass before a split");
    }

    split_tail(src, &sp, f, &m, (p, kq, limit))
}

/// The ranges the full-range harness `g162_split_tail` draws from.
#[derive(Clone, Copy, Debug)]
pub struct TailScope {
    /// Largest P and Q.
    pub max_len: i64,
    /// Draw k ≤ `max_len` / Q (the drivers: few cases discarded) rather than k ≤ `max_len`
    /// (Kani: constant bounds and no division in the harness; the assumption P ≤ `max_len`
    /// discards the rest). The same set of (P, Q) either way.
    pub k_below_quotient: bool,
}

/// The scope written for Kani: the full legal ranges (also run by a driver).
pub const TAIL_KANI: TailScope = TailScope { max_len: MAX_LENGTH, k_below_quotient: false };

/// What the drivers sample: the same ranges.
pub const TAIL_FULL: TailScope = TailScope { max_len: MAX_LENGTH, k_below_quotient: true };

/// The body of `g162_split_tail`: the split over the full legal ranges, with P formed as
/// kQ + D (so k = ⌊P/Q⌋ and D = P mod Q by definition, and no division is needed), checking
/// everything of [`body`] that is linear in P, k and D — pass 1, the order and numbering of the
/// full passes, the step from the last full pass into the split, the whole split (targets,
/// rounding, dropped targets, last exactly at P, cuts summing to D), the pass count — but not
/// the `last` flag of a full pass (whether nQ reaches P: a product against a product) nor pass
/// 1's `last` when Q ≤ P, which [`body`] checks (Kani: P, Q < 2^12; drivers: full ranges).
pub fn tail_body<S: Source>(src: &mut S, scope: &TailScope) -> Outcome {
    let (q, k, d, kq, p) = draw_pkd(src, scope)?;
    let limit = src.bounded_u32(0, u32::MAX);
    let sp = SplitParams { depth: p, allowance: q };
    let m = model::split_from(k, kq, d);
    check!(src, m.d == 0 || (m.count >= 1 && m.tail.get(m.count - 1).map(|t| t.0) == Some(p)), "the split ends at P");

    // Pass 1.
    let f = first(&sp);
    if k == 0 {
        check!(src, f.n == 1 && (f.depth, f.rule) == (m.tail[0].0, Rule::G162Split), "G162.SPLIT: with Q > P pass 1 is the first split target");
        check!(src, f.last == (f.depth == p), "last exactly at depth P (pass 1)");
    } else {
        check!(src, f.n == 1 && (f.depth, f.rule, f.stage) == (q, Rule::G162Pq, 0), "G162.PQ: pass 1 is Q when Q ≤ P");
    }

    // A full pass n < k (at any depth below P: the step reads its number): full pass n + 1.
    if k >= 2 {
        let n = bounded_i64_upto(src, 1, k - 1, scope.max_len)?;
        let depth = bounded_i64_upto(src, 0, p - 1, scope.max_len)?;
        let prev = Step { n: n as u32, depth, last: false, rule: Rule::G162Pq, stage: 0 };
        let nx = next(&sp, &prev);
        check!(src, nx.is_some(), "a full pass before the last has a successor");
        let Some(nx) = nx else { return Ok(()) };
        check!(src, nx.n == prev.n + 1 && nx.rule == Rule::G162Pq && nx.stage == 0, "G162.PQ: after full pass n < k comes full pass n + 1");
        // (n + 1)·Q, in the schedule's saturating form (the same value: (n + 1)·Q ≤ P < 2^63).
        // Under Kani `full_depth` is stubbed by one drawn value F ([`stubs::full_depth_spec`],
        // asked for n + 1 and Q only): its specification is F = (n + 1)·Q, and the only facts
        // the step uses are those the value satisfies, Q ≤ F ≤ kQ (2 ≤ n + 1 ≤ k) — drawn there,
        // so nothing is lost; the drivers run the real product.
        #[cfg(kani)]
        let want = {
            let f = bounded_i64_upto(src, q, kq, scope.max_len)?;
            stubs::set_full(n as u32 + 1, q, f);
            f
        };
        #[cfg(not(kani))]
        let want = i64::try_from(u64::from(nx.n).saturating_mul(q.max(1).unsigned_abs())).unwrap_or(i64::MAX);
        check!(src, nx.depth == want, "G162.PQ: full pass n + 1 is (n + 1)·Q deep");
        cover!(src, true, "a full pass before the last");
    }

    split_tail(src, &sp, f, &m, (p, kq, limit))
}

/// Q, k, D, kQ and P = kQ + D (1…`max_len`) as `g162_split_tail` and `g162_split_target` draw
/// them; under Kani the base kQ is drawn free of the product ([`free_base`]) and `norm`'s stub
/// is told the values. (k, Q ≤ N < 2^30: no overflow.)
pub fn draw_pkd<S: Source>(src: &mut S, scope: &TailScope) -> Result<(i64, i64, i64, i64, i64), crate::source::Stop> {
    let q = src.bounded_i64(1, scope.max_len);
    let k_max = if scope.k_below_quotient { scope.max_len / q } else { scope.max_len };
    let k = src.bounded_i64(0, k_max);
    let d = bounded_i64_upto(src, 0, q - 1, scope.max_len)?;
    let kq = if cfg!(kani) { free_base(src, k, q, scope.max_len)? } else { i128::from(k) * i128::from(q) };
    let p = kq + i128::from(d);
    src.assume(1 <= p && p <= i128::from(scope.max_len))?;
    let (kq, p) = (kq as i64, p as i64);
    #[cfg(kani)]
    stubs::set_norm(p, q, k, d);
    Ok((q, k, d, kq, p))
}

/// The depth kQ of the last full pass as Kani draws it: 0 when k = 0, else any value in Q…`max`
/// — not the product k·Q. **Nothing is lost:** under Kani `norm` is stubbed ([`stubs`]) by the
/// drawn k and D, and the code reads P, Q, k and D only through `norm` (`first`, `next` and
/// `pass_count` never divide or multiply P by Q except (n + 1)·Q for a full pass, which the body
/// checks against the same product), so every real (P, Q) — base kQ with k = ⌊P/Q⌋ ≥ 1, so
/// kQ ≥ Q, or k = 0 and base 0 — is one of the drawn cases; the others are a superset on which
/// the same statements must hold. Dropping the product takes the only full-width multiplier out
/// of the query (the previous attempts, with base = k·Q, reached no verdict).
fn free_base<S: Source>(src: &mut S, k: i64, q: i64, max: i64) -> Result<i128, crate::source::Stop> {
    if k == 0 {
        return Ok(0);
    }
    let base = src.bounded_i64(1, max);
    src.assume(base >= q)?;
    Ok(i128::from(base))
}

/// The split, whole, from the last full pass (k ≥ 1, depth kQ) or from pass 1 `f` (k = 0), and
/// the pass count against `limit` — the end of both [`body`] and [`tail_body`].
fn split_tail<S: Source>(src: &mut S, sp: &SplitParams, f: Step, m: &model::Split, (p, kq, limit): (i64, i64, u32)) -> Outcome {
    let mut r =
        if m.k >= 1 { Step { n: m.k as u32, depth: kq, last: m.d == 0, rule: Rule::G162Pq, stage: 0 } } else { f };
    let mut i = if m.k >= 1 { 0 } else { 1 };
    let mut ended = r.last;
    let mut steps = 0;
    while !ended && steps < 5 {
        steps += 1;
        let Some(nx) = next(sp, &r) else {
            check!(src, false, "a pass that is not at P has a successor");
            return Ok(());
        };
        check!(src, nx.n == r.n + 1, "pass numbers count up by one");
        check!(src, nx.depth > r.depth && nx.depth <= p, "depths strictly increase and never pass P");
        check!(src, nx.rule == Rule::G162Split, "split passes name G162.SPLIT");
        let want = m.tail.get(i).copied();
        check!(src, want.map(|t| t.0) == Some(nx.depth), "the split passes are the model's kept targets");
        check!(src, nx.last == (nx.depth == p), "last exactly at depth P");
        i += 1;
        r = nx;
        ended = r.last;
    }
    // Each kept target (the depths just checked) is its exact value rounded once half up: the
    // bracket of every one of the four, e a constant here (a multiplier by a symbolic e, read
    // from the kept list, made the Kani query a full 128-bit product).
    if m.d > 0 {
        for e in model::EIGHTHS {
            check!(
                src,
                model::is_rounded_target(model::target(kq, m.d, e), kq, m.d, e),
                "each split depth is its exact target rounded once half up"
            );
        }
    }
    check!(src, ended && r.depth == p, "the last pass is exactly at P");
    check!(src, next(sp, &r).is_none(), "nothing after the pass at P");
    check!(src, i == m.count, "every kept target is cut");
    check!(src, m.d == 0 || r.depth - kq == m.d, "G162.SPLIT: the split cuts sum exactly to the remainder D");

    // PRJ.MAXPASS.
    let total = m.k + m.count as i64;
    let want_count = if total <= i64::from(limit) { Some(total as u32) } else { None };
    check!(
        src,
        pass_count(sp, limit) == want_count,
        "PRJ.MAXPASS: pass_count is k + the kept targets, None above the limit"
    );

    cover!(src, m.k == 0, "Q > P: only split passes");
    cover!(src, m.d == 0, "zero remainder");
    cover!(src, m.d > 0 && m.count < 4, "a target dropped (remainder below one increment per cut)");
    cover!(src, m.count == 4, "all four split passes");
    cover!(src, want_count.is_none(), "more passes than the limit");
    Ok(())
}

/// Kani stubs of `g162_split_tail` (TRUSTED, see the README): `norm` (k = ⌊P/Q⌋, D = P − kQ)
/// replaced by the harness's own k and D, for which P = kQ + D, 0 ≤ D < Q holds by
/// construction — so the stub returns exactly ⌊P/Q⌋ and P mod Q; what is trusted is that the
/// real `norm` computes them (Rust's `/` on `u64` and a subtraction that cannot wrap).
#[cfg(kani)]
pub mod stubs {
    use core::sync::atomic::{AtomicI64, Ordering::SeqCst};
    use cycle_impl::g162::{Norm, SplitParams};

    static P: AtomicI64 = AtomicI64::new(0);
    static Q: AtomicI64 = AtomicI64::new(0);
    static K: AtomicI64 = AtomicI64::new(0);
    static D: AtomicI64 = AtomicI64::new(0);

    /// Records the harness's P = kQ + D (all ≥ 0, Q ≥ 1).
    pub fn set_norm(p: i64, q: i64, k: i64, d: i64) {
        P.store(p, SeqCst);
        Q.store(q, SeqCst);
        K.store(k, SeqCst);
        D.store(d, SeqCst);
    }

    static FULL_N: AtomicI64 = AtomicI64::new(0);
    static FULL_Q: AtomicI64 = AtomicI64::new(0);
    static FULL: AtomicI64 = AtomicI64::new(0);

    /// Records F = (n + 1)·Q for full pass n + 1 (`g162_split_tail`).
    pub fn set_full(n: u32, q: i64, f: i64) {
        FULL_N.store(i64::from(n), SeqCst);
        FULL_Q.store(q, SeqCst);
        FULL.store(f, SeqCst);
    }

    /// `cycle_impl::g162::split::full_depth(n, Q)` = nQ, asked for the recorded full pass only.
    pub fn full_depth_spec(n: u32, q: u64) -> u64 {
        kani::assert(i64::from(n) == FULL_N.load(SeqCst) && q as i64 == FULL_Q.load(SeqCst), "full_depth is asked for full pass n + 1 and Q only");
        FULL.load(SeqCst) as u64
    }

    /// `cycle_impl::g162::split::norm` for the recorded P and Q: (P, Q, k, D).
    pub fn norm_spec(sp: &SplitParams) -> Norm {
        let p = sp.depth.max(1).unsigned_abs();
        let q = sp.allowance.max(1).unsigned_abs();
        kani::assert(p as i64 == P.load(SeqCst) && q as i64 == Q.load(SeqCst), "norm is asked only about the harness's P and Q");
        Norm { p, q, k: K.load(SeqCst) as u64, d: D.load(SeqCst) as u64 }
    }
}

cycle_harness::property! {
    pub const EXACT = g162_split_exact in crate::PROPERTIES {
        rules: ["G162.PQ", "G162.SPLIT", "PRJ.MAXPASS"],
        states: "The G162 depth split is the register's: k = ⌊P/Q⌋ full passes, the remainder split at D/2, 3D/4, 7D/8, D each rounded once half up (a target not deeper dropped), last exactly at P, the pass count.",
        body: |src, scope| body(src, &scope),
        /// The Kani attempt on the bounded scope (a TEST: not run to a verdict; a harness only with `kani-attempts`).
        kani: test(KANI) { unwind: 6, why: "no verdict in 1 289 s over the full ranges; the bounded scope P, Q ≤ 2^12 − 1 (`KANI`) was not run to a verdict (and would lose P, Q ≥ 2^12), so it is a TEST (its Kani harness is built only with `kani-attempts`)" },
        tests {
            /// Every P, Q ≤ 40 with every full pass n and the 20 smallest and largest `limit`s.
            fn g162_split_exact_exhaustive = exhaustive(20, 2_000_000) on Scope { max_len: 40 };
            /// The edges of the legal ranges.
            fn g162_split_exact_exhaustive_edges = exhaustive(4, 1_000_000) on FULL;
            fn g162_split_exact_random = random(0x5eed_0162, 2) on FULL;
        }
    }
}

cycle_harness::property! {
    pub const TAIL = g162_split_tail in crate::PROPERTIES {
        rules: ["G162.PQ", "G162.SPLIT", "PRJ.MAXPASS"],
        states: "The G162 split over the full legal ranges with P formed as kQ + D (norm stubbed by k and D): pass 1, full pass n + 1 after n < k at (n + 1)·Q, the split targets kQ + e·D/8 rounded once half up (a target not deeper dropped), last exactly at P, the cuts summing to D, the pass count against the limit.",
        body: |src, scope| tail_body(src, &scope),
        /// The Kani harness that was run (Kissat; also tried with CaDiCaL): no verdict, so a TEST, a
        /// proof harness only with `kani-attempts` (`-Z stubbing`).
        kani: test(TAIL_KANI) { unwind: 6, solver: kissat, stubs: [cycle_impl::g162::split::norm => stubs::norm_spec, cycle_impl::g162::split::target => crate::g162_split_target::target_spec, cycle_impl::g162::split::full_depth => stubs::full_depth_spec], why: "no verdict: with `full_depth` (a full pass's nQ, the last product) stubbed too (issue #33, this session: 0.46 M variables, 1.36 M clauses), Kissat 4.0.1: seven queries answered at 9–12 s each, the eighth open for 4 min 40 s, stopped by hand at 7 min (CBMC 0.70 GB by `ps`); before, without that stub (the base kQ free of the product, `target` stubbed by `g162_split_target`'s lemma: 0.51 M variables, 1.62 M clauses), Kissat 4.0.1: 900 s (eight queries answered at 11–23 s each, the ninth open for 10 min; CBMC 0.68 GB by `ps`), CaDiCaL 1.5.3: 900 s (seven queries answered, the eighth open for 14 min; CBMC 0.77 GB by `ps`), load 2–6; with the base free but the real `target` (1.10 M variables, 4.25 M clauses), CaDiCaL 1.5.3: twelve queries answered in 5 min 29 s, stopped by hand; before (base k·Q, real `target`), CaDiCaL: 10 min of CBMC (1.25 M variables, 5.13 M clauses; eleven queries answered, the twelfth open for 7 min; 1.97 GB), stopped by hand, and Kissat 4.0.1: 900 s (eight queries answered at 30–70 s each, the ninth open for 9 min; CBMC 1.23 GB by `ps`)" },
        tests {
            /// `g162_split_tail`'s body: P, Q ≤ 40 (k ≤ 40 / Q); each draw its 6 smallest and largest values.
            fn g162_split_tail_exhaustive = exhaustive(6, 2_000_000) on TailScope { max_len: 40, k_below_quotient: true };
            fn g162_split_tail_exhaustive_edges = exhaustive(4, 1_000_000) on TAIL_FULL;
            fn g162_split_tail_random = random(0x5eed_0163, 2) on TAIL_FULL;
            /// The Kani scope's draws (k ≤ N, most cases discarded) still reach every case.
            fn g162_split_tail_kani_scope_random = random(0x5eed_0164, 8) on TAIL_KANI;
        }
    }
}

#[cfg(test)]
mod tests;
