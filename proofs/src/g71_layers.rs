//! TEST `g71_layers` (issue #20; driver-only: not a Kani proof) — G71.LAYER, G72.LAYER,
//! PRJ.MAXPASS: the layer schedule of
//! the production G71/G72 cycle (`cycle_impl::rough::Roughing`: `new`, which counts the layers
//! and checks the pass bound before any motion, then `next_event` until `None`).
//!
//! **Scope: the layer positions only, below the contour geometry.** The contour is the ns block
//! (G00 or G01 from A along the layer axis to A′, A′.b = A.b) and one G01 block along the cut
//! axis to B (B.b ≠ A.b), shifted by any allowances (Δu, Δw). So every layer's cut ends at Q's
//! last point (no quotient, no root: the geometry of `cut_on` is not in this harness — it is
//! the contour tests' `layers_match_a_search_per_layer` and `cut_ends_round_once_half_away_from_zero`
//! in impl), while the layer positions, the layer count, its closed form and the pass bound are
//! exactly those of any contour whose layers all cut (D(Q₀) = s·(Q₀.a − A.a) and the step are
//! all the count and the positions depend on).
//!
//! **Property.** With s the direction toward the contour (sign of A′.a − A.a), step = Δd·p_a
//! (p_a = 2 for G71, whose layer axis X counts diameters; 1 for G72), D = D(Q₀) and the layers'
//! cut positive exactly when c·(Q_last.b − A.b) > 0:
//!
//! - PRJ.MAXPASS, before any motion: `new` refuses with TOO MANY PASSES on U (G71) / W (G72) on
//!   the cycle block's line exactly when the cut is positive and layer number `max_passes`
//!   exists (max_passes·step < D: K + 1 > max_passes, the semi-finish pass counted); else it
//!   accepts and the run emits:
//! - the layer headers ROUGH 1, 2, …, K in order, rule G71.LAYER / G72.LAYER, diameter depth
//!   2·k·Δd; each followed by its infeed to a_k on the layer axis (at A.b) and its cut to
//!   Q_last.b;
//! - a_1 = A.a + s·step and a_k = a_{k−1} + s·step: **strictly monotone toward the contour**,
//!   every depth step exactly Δd (on radius), so ≤ Δd; every layer strictly before Q₀
//!   (s·(a_k − A.a) < D);
//! - **the count is the closed form**: K = #{k ≥ 1 : k·step < D} = ⌈D/step⌉ − 1 (0 when D ≤
//!   step or D ≤ 0) when the cut is positive, else K = 0 — stated without a division: the last
//!   layer is before Q₀ and the next one would not be, K·step < D ≤ (K + 1)·step;
//! - then the semi-finish header SEMI K + 1 (G71.LASTPASS / G72.LASTPASS), and the run ends.
//!
//! The expectations are running sums here (no product): a_k is checked against the previous
//! layer plus s·step, the count against D by the next layer's position.
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 with Kissat 4.0.1, the scope `KANI` and the
//! stubs below: no verdict in 900 s (nine queries answered, 60–100 s each, the tenth open for
//! 3 min; CBMC 2.6 GB). Without the contour stubs CBMC's symbolic execution alone passed 7.6 GB
//! (the run's event loop unrolled 18 times, the buffer bit-blasted). proofs/README.md.
//!
//! **Two modes, one body.** `trace: true` (the drivers) runs the cycle and checks the events
//! above; `trace: false` (Kani, and the drivers too) checks the schedule itself without running
//! the cycle: K = `Roughing::count` (what `new` compared with `max_passes`) and
//! a_k = `Roughing::layer_at(k)` for every k = 1…K, with the same statements (monotone toward
//! the contour, step exactly Δd·p_a, before Q₀, the closed-form count, the refusal).
//!
//! **Kani bounds, as run** (`KANI`, `trace: false`): A, A′, B anywhere in ±2^60, Δd 1…N, e 0…N,
//! allowances ±N, any feed and line; `max_passes` ≤ 5, so an accepted cycle has K ≤ 4 layers,
//! each checked; the refusal is checked for every D (any number of layers beyond `max_passes`).
//! Loops: the harness's over the layers (≤ 4), `count`'s over the two elements and its
//! bisection (≤ 3 steps), `new`'s monotonicity loop (1): `#[kani::unwind(6)]`.
//! **Beyond that scope** (the drivers only, also when a Kani run succeeds): accepted cycles of K ≥ 5 layers and the run's events (the drivers:
//! `max_passes` up to 10^6, the trace checked), and the contour geometry (`cut_on`).
//!
//! **Kani stubs, as run** (`-Z stubbing`, see [`stubs`]): `Contour::{len, get, last}` return the two
//! elements the harness made (the 1 000-element buffer is never built: CBMC bit-blasts it, 8 GB
//! before the solver), and `cut_on` is called only on the harness's G01 along the cut axis,
//! where the real function returns b₀ (its `den == 0` branch). The drivers run the real ones.

use crate::source::{Outcome, Source, Stop};
use crate::{check, cover};
use cycle_impl::contour::{Contour, Element, Kind};
use cycle_impl::rough::{Axis, Roughing, Words};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{Alarm, AlarmCode, Event, PassKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |coordinate| of A, A′, B.
    pub max_pos: i64,
    /// Largest Δd, e, |Δu|, |Δw|.
    pub max_len: i64,
    /// Largest `max_passes` (≤ 10^6, the parameter's range).
    pub max_passes: u32,
    /// Largest e, feed and line number (retract from 0, the others from 1).
    pub max_other: i64,
    /// The most events read from the run (a bound the accepted runs stay within: 5K + 4).
    pub max_events: u32,
    /// Check the run's events (`true`), or only the layer schedule itself — `count` and
    /// `layer_at` for every layer 1…K — without running the cycle (`false`: the Kani scope).
    pub trace: bool,
}

/// The scope written for Kani (see the module documentation); also run by the drivers.
pub const KANI: Scope = Scope { max_pos: 1 << 60, max_len: MAX_LENGTH, max_passes: 5, max_other: MAX_LENGTH, max_events: 0, trace: false };

/// The drivers' scope over the full ranges (events: 5·10^6 + 4 at most).
pub const FULL: Scope = Scope { max_pos: 1 << 60, max_len: MAX_LENGTH, max_passes: 1_000_000, max_other: MAX_LENGTH, max_events: 5_000_004, trace: true };

/// Positions within ±2^14, so that runs of many layers occur (a random driver's scope).
pub const NEAR: Scope = Scope { max_pos: 1 << 14, max_len: 1 << 8, max_passes: 1_000_000, max_other: MAX_LENGTH, max_events: 5_000_004, trace: true };

/// PRJ.MAXPASS at [`Roughing::new`] (for this harness and `g71_layer_step`): refused exactly
/// when layer `max_passes` exists (`too_many`), with TOO MANY PASSES on U (G71) / W (G72) on the
/// cycle block's line; `None` after a refusal, which ends the body.
pub fn admitted<S: Source>(
    src: &mut S,
    r: Result<Roughing, Alarm>,
    too_many: bool,
    word: u8,
    line: u32,
) -> Result<Option<Roughing>, Stop> {
    match r {
        Err(al) => {
            check!(src, too_many, "PRJ.MAXPASS: refused only when layer max_passes exists");
            check!(
                src,
                al.code == AlarmCode::TooManyPasses && al.word == Some(word) && al.rule == Rule::PrjMaxPass && al.line == line,
                "PRJ.MAXPASS: TOO MANY PASSES on U (G71) / W (G72), on the cycle block's line"
            );
            cover!(src, true, "refused: too many passes");
            Ok(None)
        }
        Ok(cycle) => {
            check!(src, !too_many, "PRJ.MAXPASS: a cycle with max_passes layers or more is refused before motion");
            Ok(Some(cycle))
        }
    }
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let axis = if src.bool() { Axis::G72 } else { Axis::G71 };
    let (layer_rule, semi_rule, word) = match axis {
        Axis::G71 => (Rule::G71Layer, Rule::G71Lastpass, b'U'),
        Axis::G72 => (Rule::G72Layer, Rule::G72Lastpass, b'W'),
    };
    // (a, b) frame: G71 a = X, b = Z; G72 a = Z, b = X.
    let pt = |a: i64, b: i64| match axis {
        Axis::G71 => (a, b),
        Axis::G72 => (b, a),
    };
    let fa = |p: (i64, i64)| match axis {
        Axis::G71 => p.0,
        Axis::G72 => p.1,
    };
    let fb = |p: (i64, i64)| match axis {
        Axis::G71 => p.1,
        Axis::G72 => p.0,
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
    let retract = src.bounded_i64(0, scope.max_other);
    let allowance = (src.bounded_i64(-scope.max_len, scope.max_len), src.bounded_i64(-scope.max_len, scope.max_len));
    let feed = src.bounded_i64(1, scope.max_other.max(1));
    let rapid_ns = src.bool();
    let max_passes = src.bounded_u32(1, scope.max_passes);
    let line = src.bounded_u32(1, u32::try_from(scope.max_other.max(1)).unwrap_or(u32::MAX));

    let start = pt(a_a, a_b);
    #[cfg_attr(kani, allow(unused_mut))]
    let mut contour = Contour::new();
    let ns = Element { x: pt(q_a, a_b).0, z: pt(q_a, a_b).1, cx: 0, cz: 0, feed: 0, line: 1, kind: if rapid_ns { Kind::Rapid } else { Kind::Feed } };
    let b = Element { x: pt(q_a, end_b).0, z: pt(q_a, end_b).1, cx: 0, cz: 0, feed: 0, line: 2, kind: Kind::Feed };
    // Under Kani the contour is the stubs' ([`stubs`]): the buffer's 1 000 elements are never
    // built (CBMC would bit-blast the whole array: 8 GB before the solver).
    #[cfg(kani)]
    stubs::set_contour(ns, b);
    #[cfg(not(kani))]
    check!(src, contour.push(ns) && contour.push(b), "the contour buffer takes two elements");
    let words = Words { depth, retract, allowance, feed };

    // The register's values, in i128 (no overflow: every term below 2^62).
    let s: i128 = if q_a > a_a { 1 } else { -1 };
    let c: i128 = if end_b > a_b { 1 } else { -1 };
    let shift_a = i128::from(fa(allowance));
    let shift_b = i128::from(fb(allowance));
    let d0 = s * (i128::from(q_a) + shift_a - i128::from(a_a));
    let last_b = i128::from(end_b) + shift_b;
    let cuts = c * (last_b - i128::from(a_b)) > 0;
    let step = i128::from(depth) * i128::from(p_a);

    let r = Roughing::new(axis, start, &words, &contour, max_passes, line);
    // Layer number `max_passes` exists: max_passes·step < D (and the cut is positive).
    let too_many = cuts && i128::from(max_passes) * step < d0;
    let Some(mut cycle) = admitted(src, r, too_many, word, line)? else {
        return Ok(());
    };

    if !scope.trace {
        // The schedule itself: K = count (what `new` compared with max_passes), a_k = layer_at(k).
        let kk = cycle.count(&contour, max_passes);
        check!(src, kk < max_passes, "PRJ.MAXPASS: an accepted cycle has fewer layers than max_passes");
        let (mut reach, mut prev_a, mut j) = (0i128, i128::from(a_a), 1u32);
        while j <= kk {
            reach += step;
            let a = i128::from(cycle.layer_at(j));
            check!(src, s * (a - prev_a) > 0, "G71.LAYER: layers strictly monotone toward the contour");
            check!(src, s * (a - prev_a) == step, "G71.LAYER: each depth step is Δd (on radius)");
            check!(src, s * (a - i128::from(a_a)) == reach, "G71.LAYER: layer k stands at A.a + s·k·Δd·p_a");
            check!(src, cuts && reach < d0, "G71.LAYER: every layer lies strictly before Q₀ and cuts");
            prev_a = a;
            j += 1;
        }
        check!(src, if cuts { reach + step >= d0 } else { kk == 0 }, "G71.LAYER: K is the closed-form count (the next layer would reach Q₀)");
        cover!(src, kk == 0, "no layer");
        cover!(src, kk == 1, "one layer");
        cover!(src, kk >= 2, "two layers or more");
        cover!(src, kk + 1 == max_passes, "as many passes as allowed");
        cover!(src, !cuts, "no layer cuts (the contour's end behind A.b)");
        return Ok(());
    }

    let mut pos = start;
    // The expected layer: its number, s·(a_k − A.a) = k·step and 2·k·Δd, as running sums.
    let mut k: u32 = 0;
    let mut reach: i128 = 0;
    let mut dia: i128 = 0;
    let mut prev_a = i128::from(a_a);
    // 0: expect a header; 1: the infeed; 2: the cut; 3: the rest of the layer (retract, back).
    let mut stage = 0u8;
    let mut semi = false;
    let mut events = 0u32;
    while let Some(ev) = cycle.next_event(&mut pos, &contour) {
        events += 1;
        if events > scope.max_events {
            check!(src, false, "an accepted run ends within 5K + 4 events");
            return Ok(());
        }
        if semi {
            continue;
        }
        match ev {
            Event::Pass(p) if p.kind == PassKind::Rough => {
                check!(src, stage == 0 || stage == 3, "a layer header follows a whole layer");
                k += 1;
                reach += step;
                dia += 2 * i128::from(depth);
                check!(src, p.index == k && p.rule == layer_rule, "G71.LAYER: layer headers ROUGH 1, 2, … in order");
                check!(src, i128::from(p.diameter_depth) == dia, "G71.LAYER: layer k is 2·k·Δd deep on diameter");
                check!(src, cuts && reach < d0, "G71.LAYER: every layer lies strictly before Q₀ and cuts");
                stage = 1;
            }
            Event::Pass(p) => {
                check!(src, p.kind == PassKind::Semi && stage != 1 && stage != 2, "after the layers, the semi-finish pass");
                check!(src, p.index == k + 1 && p.rule == semi_rule, "G71.LASTPASS: the semi-finish pass is K + 1");
                // The closed form: K = #{k ≥ 1 : k·step < D} when the cut is positive, else 0.
                check!(src, if cuts { reach + step >= d0 } else { k == 0 }, "G71.LAYER: K is the closed-form count (the next layer would reach Q₀)");
                semi = true;
            }
            Event::Move(m) => match stage {
                1 => {
                    let a = i128::from(fa((m.x, m.z)));
                    check!(src, fb((m.x, m.z)) == a_b && m.rule == layer_rule, "G71.LAYER: the infeed stays at A.b");
                    check!(src, s * (a - prev_a) > 0, "G71.LAYER: layers strictly monotone toward the contour");
                    check!(src, s * (a - prev_a) == step, "G71.LAYER: each depth step is Δd (on radius)");
                    check!(src, s * (a - i128::from(a_a)) == reach, "G71.LAYER: layer k stands at A.a + s·k·Δd·p_a");
                    prev_a = a;
                    stage = 2;
                }
                2 => {
                    check!(src, i128::from(fb((m.x, m.z))) == last_b && i128::from(fa((m.x, m.z))) == prev_a, "G71.LAYER: the cut runs along b to Q's last point");
                    stage = 3;
                }
                _ => check!(src, stage == 3, "moves of a layer follow its header"),
            },
            _ => check!(src, false, "a G71/G72 run emits passes and moves only"),
        }
    }
    check!(src, semi, "the run ends with the semi-finish pass");
    cover!(src, k == 0, "no layer");
    cover!(src, k == 1, "one layer");
    cover!(src, k >= 2, "two layers or more");
    cover!(src, !cuts, "no layer cuts (the contour's end behind A.b)");
    Ok(())
}

/// The Kani stubs (TRUSTED, see the module documentation). `Contour::get`: the buffer is
/// 1 000 elements, which CBMC keeps as an array whose reads are symbolic, so that every
/// element kind — arcs and their root loops included — would be explored; the stub returns the
/// two elements the harness pushed, as the real `get` does (element i for i < len, else
/// `Element::ZERO`). Where that is established: impl's contour tests and this body's drivers,
/// which run the real `get`.
#[cfg(kani)]
pub mod stubs {
    use core::sync::atomic::{AtomicBool, AtomicI64, Ordering::SeqCst};
    use cycle_impl::contour::{Contour, Element, Kind};
    use cycle_impl::rough::Axis;

    static NS_X: AtomicI64 = AtomicI64::new(0);
    static NS_Z: AtomicI64 = AtomicI64::new(0);
    static NS_RAPID: AtomicBool = AtomicBool::new(false);
    static B_X: AtomicI64 = AtomicI64::new(0);
    static B_Z: AtomicI64 = AtomicI64::new(0);

    /// Records the harness's two elements (the ns block on line 1, B's G01 block on line 2).
    pub fn set_contour(ns: Element, b: Element) {
        NS_X.store(ns.x, SeqCst);
        NS_Z.store(ns.z, SeqCst);
        NS_RAPID.store(ns.kind == Kind::Rapid, SeqCst);
        B_X.store(b.x, SeqCst);
        B_Z.store(b.z, SeqCst);
    }

    /// `cycle_impl::rough::cut_on` where this harness calls it: the element after Q₀ is the
    /// harness's G01 along the cut axis (both ends at the same a), for which the real function's
    /// line branch returns b₀ (den = a₁ − a₀ = 0: `sat(b0)`, its first test) — never an arc.
    pub fn cut_on_spec(axis: Axis, kind: Kind, from: (i64, i64), to: (i64, i64), _centre: (i64, i64), _ak: i64) -> i64 {
        let a = |p: (i64, i64)| match axis {
            Axis::G71 => p.0,
            Axis::G72 => p.1,
        };
        let b = |p: (i64, i64)| match axis {
            Axis::G71 => p.1,
            Axis::G72 => p.0,
        };
        kani::assert(!matches!(kind, Kind::Arc(_)), "the harness's contour has no arc");
        kani::assert(a(from) == a(to), "the harness's cut element runs along the cut axis only");
        b(from)
    }

    /// `Contour::len`: the harness's two elements.
    pub fn contour_len(_c: &Contour) -> usize {
        2
    }

    /// `Contour::last`: element 1, B's block.
    pub fn contour_last(c: &Contour) -> Element {
        contour_get(c, 1)
    }

    /// `Contour::get` on the harness's contour of two elements.
    pub fn contour_get(_c: &Contour, i: usize) -> Element {
        match i {
            0 => Element {
                x: NS_X.load(SeqCst),
                z: NS_Z.load(SeqCst),
                cx: 0,
                cz: 0,
                feed: 0,
                line: 1,
                kind: if NS_RAPID.load(SeqCst) { Kind::Rapid } else { Kind::Feed },
            },
            1 => Element { x: B_X.load(SeqCst), z: B_Z.load(SeqCst), cx: 0, cz: 0, feed: 0, line: 2, kind: Kind::Feed },
            _ => Element::ZERO,
        }
    }
}

cycle_harness::property! {
    pub const PROPERTY = g71_layers in crate::PROPERTIES {
        rules: ["G71.LAYER", "G72.LAYER", "PRJ.MAXPASS"],
        states: "The G71/G72 layer schedule below the contour geometry: TOO MANY PASSES before motion exactly when layer max_passes exists; layers strictly monotone toward the contour, each depth step exactly Δd, every layer before Q₀, the count the closed form ⌈D/step⌉ − 1 (0 when the cut is not positive); the run's headers, infeeds and cuts.",
        body: |src, scope| body(src, &scope),
        /// The Kani harness that was run (Kissat): no verdict, so a TEST, a proof harness only with
        /// `kani-attempts` (`-Z stubbing`).
        kani: test(KANI) { unwind: 6, solver: kissat, stubs: [cycle_impl::contour::Contour::get => stubs::contour_get, cycle_impl::contour::Contour::len => stubs::contour_len, cycle_impl::contour::Contour::last => stubs::contour_last, cycle_impl::rough::cut_on => stubs::cut_on_spec], why: "no verdict with the schedule-only scope (`KANI`: `max_passes` ≤ 5, `count` and `layer_at` without the run, four stubs, unwind 6), Kissat 4.0.1: 900 s (nine queries answered at 60–100 s each, the tenth open for 3 min; CBMC 2.6 GB, Kissat up to 2.3 GB by `ps`); before that, with the run's events (unwind 18) and without the contour stubs, CBMC's symbolic execution alone passed 7.6 GB in 4.6 min (stopped), and Kissat aborted (exit 134) next to an 8 GB CBMC when the 1 000-element buffer was built" },
        tests {
            /// Positions ±6, Δd and allowances ≤ 1 or 2, e 0…1, max_passes ≤ 12 (draws' 2 or 3 values
            /// at each end): every combination.
            fn g71_layers_exhaustive_small = exhaustive(2, 4_000_000) on Scope { max_pos: 6, max_len: 1, max_passes: 12, max_other: 1, max_events: 64, trace: true }, exhaustive(3, 4_000_000) on Scope { max_pos: 3, max_len: 2, max_passes: 12, max_other: 1, max_events: 64, trace: true }, exhaustive(3, 4_000_000) on Scope { max_pos: 3, max_len: 2, max_passes: 12, max_other: 1, max_events: 64, trace: false };
            /// The Kani scope's edges.
            fn g71_layers_exhaustive_kani_edges = exhaustive(1, 4_000_000) on KANI;
            /// Full ranges (most cases refused); positions within ±2^14 so that runs of many layers occur.
            fn g71_layers_random = random(0x5eed_0071, 32) on FULL, random(0x5eed_0072, 64) on NEAR, random(0x5eed_0074, 64) on Scope { trace: false, ..NEAR };
            fn g71_layers_random_kani_scope = random(0x5eed_0073, 32) on KANI, random(0x5eed_0075, 32) on Scope { trace: true, max_events: 24, ..KANI };
        }
    }
}
