//! Harness `g71_layer_step` (issue #33) — G71.LAYER, G72.LAYER, PRJ.MAXPASS: the G71/G72 layer
//! schedule of the production cycle (`cycle_impl::rough::Roughing`: `new`, which counts the
//! layers (`count`) and refuses before any motion, the count it keeps for the run, and
//! `layer_at`, the layer coordinate every infeed of the run goes to), with its two arithmetic
//! functions stubbed by their specifications. A Kani proof: SUCCESSFUL (proofs/README.md).
//!
//! **Property.** With s the direction toward the contour (sign of A′.a − A.a), step = Δd·p_a
//! (p_a = 2 for G71, whose layer axis X counts diameters; 1 for G72), D = D(Q₀) = s·(Q₀.a − A.a)
//! (Q₀ = A′ shifted by the allowances) and the layers' cut positive exactly when
//! c·(Q_last.b − A.b) > 0; q = ⌊(D − 1)/step⌋ = ⌈D/step⌉ − 1, the number of k ≥ 1 with
//! k·step < D:
//!
//! - PRJ.MAXPASS, before any motion: `new` refuses with TOO MANY PASSES on U (G71) / W (G72) on
//!   the cycle block's line exactly when the cut is positive, D ≥ 1 and q ≥ `max_passes` (layer
//!   number `max_passes` exists: K + 1 > `max_passes` with the semi-finish pass); else it accepts
//!   and `count` = K = q when the cut is positive and D ≥ 1, else 0 — **the closed form**, and
//!   K < `max_passes`;
//! - for **every** layer k = 1…K (symbolic): layer k stands at A.a + s·o(k), o(k) = k·step
//!   (layer 1 at A.a + s·step); layer k + 1 stands exactly s·step further (**strictly monotone
//!   toward the contour, every step exactly Δd** on radius); 0 < s·(a_k − A.a) < D (strictly
//!   between A and Q₀: **no layer past the contour plus the allowance**); and layer K + 1 would
//!   reach Q₀ (s·(a_{K+1} − A.a) ≥ D: no layer is missing). By induction from layer 1 these
//!   are the register's layers 1…K.
//!
//! **Scope: below the contour geometry**, as `g71_layers`: the contour is the ns block (G00 or
//! G01 from A along the layer axis to A′) and one G01 along the cut axis to B, shifted by any
//! allowances, so every layer's cut ends at Q's last point and no `cut_on` is reached (its
//! stub asserts so). The layer positions, the count and the refusal depend only on D and the
//! cut's sign, which this contour takes at every value.
//!
//! **Stubs (Kani, `-Z stubbing`; see [`stubs`]).** The contour's `len`/`get`/`last` as in
//! `g71_layers` (the 1 000-element buffer is never built); `cycle_impl::rough::layers_within`
//! (⌊r/step⌋, an `i128` division) by a table q(D − 1), q(D) — the only two arguments `count`
//! asks for on this contour, which the stub asserts; `cycle_impl::rough::layer_offset` (k·step)
//! by a table o(k₀), o(k₀ + 1) = o(k₀) + step for the layer k₀ drawn (the stub asserts no other
//! layer is asked for). The tables' assumptions ([`q_spec`], [`o_spec`]): q(D) ≥ q(D − 1) ≥ 0;
//! q(x) ≥ 1 ⇔ step ≤ x and q(x) ≤ x, for x = D − 1 and D (the floor at m = 1, linear: without
//! it the table could hand `count` a quotient ≥ 1 where the real one is 0 — the counterexample
//! of the FAILED run); o(k₀) ≥ step, o(1) = step; o(m) ≤ D − 1 ⇔ m ≤ q(D − 1) for m = k₀,
//! k₀ + 1 — integer facts (distributivity; ⌊x/y⌋ is the largest m with m·y ≤ x, 0 ≤ ⌊x/y⌋ ≤ x:
//! smt/ lemma 14), the linear instances of the floor bracket q·step ≤ x < (q + 1)·step, which
//! the drivers check in full on every case against the exact products and the exact floor.
//!
//! **Kani bounds.** A, A′, B anywhere in ±2^60, Δd 1…N, e 0…N, allowances ±N, any feed and line,
//! `max_passes` 1…10^6 (its whole range), every layer k₀. Loops: `count`'s two elements and its
//! bisection (≤ 20 halvings of an interval ≤ 10^6 < 2^20), `new`'s monotonicity loop (1):
//! `#[kani::unwind(23)]`. **Left to the drivers**: the run's events (`g71_layers`, which walks
//! the run: headers 1…K in order, each infeed at `layer_at(k)`), and the contour geometry.

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::contour::{Contour, Element, Kind};
use cycle_impl::rough::{Axis, Roughing, Words};
use cycle_impl::MAX_LENGTH;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |coordinate| of A, A′, B.
    pub max_pos: i64,
    /// Largest Δd, e, |Δu|, |Δw|, feed and line.
    pub max_len: i64,
    /// Largest `max_passes`.
    pub max_passes: u32,
}

/// The Kani scope: the full ranges.
pub const KANI: Scope = Scope { max_pos: 1 << 60, max_len: MAX_LENGTH, max_passes: 1_000_000 };

/// Positions within ±2^14, so that many layers occur (a random driver's scope).
pub const NEAR: Scope = Scope { max_pos: 1 << 14, max_len: 1 << 8, max_passes: 1_000_000 };

/// The specification of `layers_within`'s table (assumed under Kani, checked by the drivers):
/// q0 = q(D − 1), q1 = q(D), for D ≥ 1.
#[allow(clippy::int_plus_one)] // x = D − 1, as lemma 14 states it
pub fn q_spec(d0: i128, step: i128, q0: i128, q1: i128) -> [(bool, &'static str); 4] {
    [
        (d0 < 1 || (q0 >= 0 && q1 >= q0), "⌊x/step⌋ ≥ 0 for x ≥ 0, monotone in x"),
        // Lemma 14 at m = 1 (1·step = step: no product): q ≥ 1 exactly when step ≤ x — so q = 0
        // whenever x < step, the case `count` reaches without a layer (the cut not positive,
        // D ≤ step) and returns min(q(D − 1), max_passes) as it stands.
        (d0 < 1 || ((q0 >= 1) == (step <= d0 - 1) && (q1 >= 1) == (step <= d0)), "lemma 14 at m = 1: q ≥ 1 ⇔ step ≤ x"),
        // q ≤ x (q·step ≤ x with step ≥ 1), so the table stays within the real quotients' range.
        (d0 < 1 || (q0 <= d0 - 1 && q1 <= d0), "⌊x/step⌋ ≤ x for step ≥ 1"),
        // The exact bracket (products of two symbolic values) only in the drivers; under Kani the
        // rows above and `o_spec`'s at k₀, k₀ + 1 are its linear instances.
        (d0 < 1 || cfg!(kani) || (q0 * step <= d0 - 1 && d0 - 1 < (q0 + 1) * step && q1 * step <= d0 && d0 < (q1 + 1) * step), "q is the floor: q·step ≤ x < (q + 1)·step"),
    ]
}

/// The specification of `layer_offset`'s table at k₀ ≥ 1 (assumed under Kani, checked by the
/// drivers): o0 = o(k₀) = k₀·step, o1 = o(k₀ + 1).
#[allow(clippy::int_plus_one)] // x = D − 1, as lemma 14 states it
pub fn o_spec(d0: i128, step: i128, q0: i128, k0: u32, o0: i128, o1: i128) -> [(bool, &'static str); 4] {
    let k0 = i128::from(k0);
    [
        (o1 == o0 + step && o0 >= step, "(k + 1)·step = k·step + step, k·step ≥ step for k ≥ 1"),
        (k0 != 1 || o0 == step, "1·step = step"),
        (d0 < 1 || ((o0 <= d0 - 1) == (k0 <= q0) && (o1 <= d0 - 1) == (k0 + 1 <= q0)), "lemma 14: m·step ≤ x ⇔ m ≤ ⌊x/step⌋"),
        (cfg!(kani) || (o0 == k0 * step && o1 == (k0 + 1) * step), "the table holds the exact products"),
    ]
}

/// An assumption the Kani stubs trust (Kani: assumed) that the drivers check.
fn trusted<S: Source>(src: &mut S, spec: &[(bool, &'static str)]) -> Outcome {
    for &(ok, msg) in spec {
        if cfg!(kani) {
            src.assume(ok)?;
        } else {
            src.verdict(ok, msg)?;
        }
    }
    Ok(())
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let axis = if src.bool() { Axis::G72 } else { Axis::G71 };
    let word = match axis {
        Axis::G71 => b'U',
        Axis::G72 => b'W',
    };
    // (a, b) frame: G71 a = X, b = Z; G72 a = Z, b = X.
    let pt = |a: i64, b: i64| match axis {
        Axis::G71 => (a, b),
        Axis::G72 => (b, a),
    };
    let (fa, fb) = match axis {
        Axis::G71 => (0, 1),
        Axis::G72 => (1, 0),
    };
    let p_a: i64 = match axis {
        Axis::G71 => 2,
        Axis::G72 => 1,
    };

    let a_a = src.bounded_i64(-scope.max_pos, scope.max_pos);
    let a_b = src.bounded_i64(-scope.max_pos, scope.max_pos);
    let q_a = src.bounded_i64(-scope.max_pos, scope.max_pos);
    let end_b = src.bounded_i64(-scope.max_pos, scope.max_pos);
    src.assume(q_a != a_a && end_b != a_b)?;
    let depth = src.bounded_i64(1, scope.max_len);
    let retract = src.bounded_i64(0, scope.max_len);
    let allowance = [src.bounded_i64(-scope.max_len, scope.max_len), src.bounded_i64(-scope.max_len, scope.max_len)];
    let feed = src.bounded_i64(1, scope.max_len);
    let rapid_ns = src.bool();
    let max_passes = src.bounded_u32(1, scope.max_passes);
    let line = src.bounded_u32(1, u32::try_from(scope.max_len).unwrap_or(u32::MAX));

    let start = pt(a_a, a_b);
    let ns = Element { x: pt(q_a, a_b).0, z: pt(q_a, a_b).1, cx: 0, cz: 0, feed: 0, line: 1, kind: if rapid_ns { Kind::Rapid } else { Kind::Feed } };
    let b = Element { x: pt(q_a, end_b).0, z: pt(q_a, end_b).1, cx: 0, cz: 0, feed: 0, line: 2, kind: Kind::Feed };
    #[cfg_attr(kani, allow(unused_mut))]
    let mut contour = Contour::new();
    #[cfg(kani)]
    crate::g71_layers::stubs::set_contour(ns, b);
    #[cfg(not(kani))]
    check!(src, contour.push(ns) && contour.push(b), "the contour buffer takes two elements");
    let words = Words { depth, retract, allowance: (allowance[0], allowance[1]), feed };

    // The register's values, in i128 (every term below 2^62).
    let s: i128 = if q_a > a_a { 1 } else { -1 };
    let c: i128 = if end_b > a_b { 1 } else { -1 };
    // Signs applied by negation, not by a product (no multiplier circuit for the solver).
    let signed = |sign: i128, v: i128| if sign > 0 { v } else { -v };
    let d0 = signed(s, i128::from(q_a) + i128::from(allowance[fa]) - i128::from(a_a));
    let cuts = signed(c, i128::from(end_b) + i128::from(allowance[fb]) - i128::from(a_b)) > 0;
    let step = if p_a == 2 { 2 * i128::from(depth) } else { i128::from(depth) };

    // The table of ⌊x/step⌋ at x = D − 1 and D (D ≥ 1).
    let (q0, q1) = if cfg!(kani) {
        (i128::from(src.bounded_i64(0, i64::MAX)), i128::from(src.bounded_i64(0, i64::MAX)))
    } else if d0 >= 1 {
        ((d0 - 1) / step, d0 / step)
    } else {
        (0, 0)
    };
    trusted(src, &q_spec(d0, step, q0, q1))?;
    #[cfg(kani)]
    stubs::set_quotients(d0, step, q0, q1);

    let layers = cuts && d0 >= 1;
    let r = Roughing::new(axis, start, &words, &contour, max_passes, line);
    let too_many = layers && q0 >= i128::from(max_passes);
    let Some(cycle) = crate::g71_layers::admitted(src, r, too_many, word, line)? else {
        return Ok(());
    };
    // K as `new` stored it for the run (`count`'s value there; calling `count` again on the
    // returned cycle would make CBMC unroll its element loop to the unwind bound: the contour's
    // length is no longer a constant to it there).
    let kk = cycle.layer_count();
    check!(src, i128::from(kk) == if layers { q0 } else { 0 }, "G71.LAYER: K is the closed form ⌈D/step⌉ − 1 (0 when the cut is not positive)");
    check!(src, kk < max_passes, "PRJ.MAXPASS: an accepted cycle has fewer layers than max_passes");
    cover!(src, kk == 0 && cuts, "no layer, the cut positive (Q₀ within one step)");
    cover!(src, kk == 0 && !cuts, "no layer: the cut not positive");
    if kk == 0 {
        return Ok(());
    }

    // Layer k₀, any of 1…K, and the next.
    let k0 = src.bounded_u32(1, kk);
    let (o0, o1) = if cfg!(kani) {
        let o0 = i128::from(src.bounded_i64(0, i64::MAX));
        (o0, o0 + step)
    } else {
        (i128::from(k0) * step, i128::from(k0 + 1) * step)
    };
    trusted(src, &o_spec(d0, step, q0, k0, o0, o1))?;
    #[cfg(kani)]
    stubs::set_offsets(k0, o0 as i64, step as i64);

    let a0 = i128::from(cycle.layer_at(k0));
    let a1 = i128::from(cycle.layer_at(k0 + 1));
    let from_a = |a: i128| signed(s, a - i128::from(a_a));
    check!(src, from_a(a0) == o0, "G71.LAYER: layer k stands at A.a + s·k·Δd·p_a");
    check!(src, k0 != 1 || from_a(a0) == step, "G71.LAYER: layer 1 stands one step from A");
    check!(src, from_a(a1) - from_a(a0) == step && step > 0, "G71.LAYER: layers strictly monotone toward the contour, each step exactly Δd (on radius)");
    check!(src, from_a(a0) > 0 && from_a(a0) < d0, "G71.LAYER: every layer lies strictly between A and Q₀ (never past the contour plus the allowance)");
    check!(src, (k0 < kk) == (from_a(a1) < d0), "G71.LAYER: layer k + 1 exists exactly when it lies before Q₀ (K is the count of layers before Q₀)");
    cover!(src, k0 == 1, "layer 1");
    cover!(src, k0 == kk && kk >= 2, "the last of several layers");
    cover!(src, kk + 1 == max_passes, "as many passes as allowed");
    Ok(())
}

/// The Kani stubs of `cycle_impl::rough::{layers_within, layer_offset, cut_on}`: lookups in the
/// tables the body drew (TRUSTED specification: [`q_spec`], [`o_spec`]; checked by the drivers).
#[cfg(kani)]
pub mod stubs {
    use core::sync::atomic::{AtomicI64, AtomicU32, Ordering::SeqCst};
    use cycle_impl::contour::Kind;
    use cycle_impl::rough::Axis;

    static D0: AtomicI64 = AtomicI64::new(0);
    static STEP: AtomicI64 = AtomicI64::new(0);
    static Q: [AtomicI64; 2] = [AtomicI64::new(0), AtomicI64::new(0)];
    static K0: AtomicU32 = AtomicU32::new(0);
    static O0: AtomicI64 = AtomicI64::new(0);

    /// Records q(D − 1), q(D) (D < 2^62, q ≤ D: all within i64).
    pub fn set_quotients(d0: i128, step: i128, q0: i128, q1: i128) {
        D0.store(d0 as i64, SeqCst);
        STEP.store(step as i64, SeqCst);
        Q[0].store(q0 as i64, SeqCst);
        Q[1].store(q1 as i64, SeqCst);
    }

    /// Records o(k₀) (o(k₀ + 1) = o(k₀) + step).
    pub fn set_offsets(k0: u32, o0: i64, step: i64) {
        K0.store(k0, SeqCst);
        O0.store(o0, SeqCst);
        STEP.store(step, SeqCst);
    }

    /// `layers_within(reach, step)` = ⌊reach/step⌋, asked for D − 1 or D only.
    pub fn layers_within_spec(reach: i128, step: i128) -> i128 {
        let d0 = i128::from(D0.load(SeqCst));
        kani::assert(step == i128::from(STEP.load(SeqCst)), "count divides by the layer step");
        kani::assert(d0 >= 1 && (reach == d0 - 1 || reach == d0), "count asks for the layers within D(Q₀) − 1 or D(Q₀) only");
        i128::from(Q[usize::from(reach == d0)].load(SeqCst))
    }

    /// `layer_offset(k, step)` = k·step, asked for k₀ or k₀ + 1 only.
    pub fn layer_offset_spec(k: u32, step: i64) -> i64 {
        let k0 = K0.load(SeqCst);
        kani::assert(step == STEP.load(SeqCst), "layer_at multiplies the layer step");
        kani::assert(k == k0 || Some(k) == k0.checked_add(1), "layer_at is asked for k₀ or k₀ + 1 only");
        O0.load(SeqCst) + if k == k0 { 0 } else { step }
    }

    /// `cut_on`: not reached on this contour (every layer's cut ends at Q's last point).
    pub fn cut_on_unreached(_axis: Axis, _kind: Kind, _from: (i64, i64), _to: (i64, i64), _centre: (i64, i64), _ak: i64) -> i64 {
        kani::assert(false, "cut_on is not reached on the harness's contour");
        0
    }
}

cycle_harness::property! {
    pub const PROPERTY = g71_layer_step in crate::PROPERTIES {
        rules: ["G71.LAYER", "G72.LAYER", "PRJ.MAXPASS"],
        states: "The G71/G72 layer schedule below the contour geometry, for every layer k: TOO MANY PASSES before motion exactly when layer max_passes exists; the count K the closed form ⌈D/step⌉ − 1 (0 when the cut is not positive), below max_passes; layer k at A.a + s·k·Δd·p_a, layer k + 1 exactly one step further toward the contour, every layer strictly between A and Q₀, layer K + 1 at or past Q₀.",
        body: |src, scope| body(src, &scope),
        /// The Kani proof (`-Z stubbing`: the contour, `layers_within`, `layer_offset`, `cut_on`).
        kani: proof(KANI) { unwind: 23, stubs: [cycle_impl::contour::Contour::get => crate::g71_layers::stubs::contour_get, cycle_impl::contour::Contour::len => crate::g71_layers::stubs::contour_len, cycle_impl::contour::Contour::last => crate::g71_layers::stubs::contour_last, cycle_impl::rough::layers_within => stubs::layers_within_spec, cycle_impl::rough::layer_offset => stubs::layer_offset_spec, cycle_impl::rough::cut_on => stubs::cut_on_unreached], measured: "SUCCESSFUL (985 checks, 14 unreachable; 6/6 covers), 333.3 s, 0.93 GB" },
        tests {
            /// Positions ±6, Δd and allowances ≤ 2, max_passes ≤ 12 (each draw's 2 values at each end).
            fn g71_layer_step_exhaustive = exhaustive(2, 4_000_000) on Scope { max_pos: 6, max_len: 2, max_passes: 12 };
            /// The Kani scope's edges.
            fn g71_layer_step_exhaustive_kani_edges = exhaustive(1, 4_000_000) on KANI;
            fn g71_layer_step_random = random(0x5eed_0076, 8) on KANI, random(0x5eed_0077, 8) on NEAR;
        }
    }
}
