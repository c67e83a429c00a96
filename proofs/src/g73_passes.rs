//! Harness `g73_passes` (issue #33) — G73.DEPTH, G73.PATH, PRJ.MAXPASS: the passes of the
//! production G73 cycle (`cycle_impl::g73::Cycle`, below the lexer), at a symbolic pass n₀, with
//! the offsets' rounded quotients stubbed by their specification. A TEST until a Kani run
//! reports SUCCESSFUL (proofs/README.md: what was measured).
//!
//! **Property.** For A anywhere in ±2^60, Δi, Δk, Δu, Δw within ±N, d 1…N, any feed, line,
//! `max_passes` (1…10^6), either g73.c reading, the count word R or D, and a contour element of
//! any kind (G00, G01, G02/G03 with any centre): `Cycle::new` refuses with TOO MANY PASSES on the
//! count word, PRJ.MAXPASS, on the cycle block's line exactly when d > `max_passes`; else, for
//! **every** pass n₀ = 1…d (pass 1 from `new`, with the rapid to C = A + (2Δi + Δu, Δk + Δw)
//! first under g73.c = visit; pass n₀ ≥ 2 entered as `end_pass` enters it), with
//! e(n) = (round(Δi·(d − n)/d), round(Δk·(d − n)/d)) and T(n) = (2·e_i(n) + Δu, e_k(n) + Δw):
//!
//! - pass n₀'s header: index n₀, ROUGH, diameter depth |2·e_i(n₀)|, rule G73.DEPTH; then the rapid
//!   to A + T(n₀) and the contour element translated by T(n₀) in its own mode (centre too),
//!   rule G73.PATH (each not emitted when the tool is already there, PRJ.NOOP);
//! - after it, exactly when n₀ < d, pass n₀ + 1's header and its rapid to A + T(n₀ + 1), with
//!   **|T(n₀ + 1) − (Δu, Δw)| ≤ |T(n₀) − (Δu, Δw)|** on each axis, on the side of (Δi, Δk)
//!   (the offsets never grow, toward the allowance); when n₀ = d: **T(d) = (Δu, Δw)** (the last
//!   pass at the allowance), then the rapid back to A and `None`. By induction from pass 1:
//!   **exactly d passes**, numbered 1…d.
//!
//! **Stub (Kani, `-Z stubbing`; see [`stubs`]).** `cycle_impl::g73::escape` (two products and
//! two rounded `i128` quotients) by a table e(n₀), e(n₀ + 1) — the only passes the run asks for
//! (asserted) — assumed as smt/ lemma 15 proves ([`spec`]): e(n) between 0 and v (v = Δi, Δk),
//! e(n₀ + 1) no farther from 0 than e(n₀) when n₀ < d, e(d) = 0. The drivers run the real
//! `escape` with the table holding the exact quotients (rounded by `2|x| + d` over `2d`, not
//! impl's code), checking every assumption. The contour's `len`/`get` return the one element
//! drawn (the 1 000-element buffer is never built; the drivers push it and run the real ones).
//!
//! **Bounds.** The escapes are drawn in ±N: lemma 15 puts e between 0 and Δi (Δk), |Δi| ≤ N, so
//! nothing is lost. The machine position before pass n₀ ≥ 2 is any point in ±2^62 (a superset
//! of where pass n₀ − 1 ends). Loops: the events read (≤ 7) and `next_event`'s retries:
//! `#[kani::unwind(6)]` (below). **Left to the drivers and impl's tests**: `fill` (the batched path,
//! compared with `next_event` event for event by impl's tests), contours of more elements (each
//! element is translated the same way; `elem` steps 0…len).
//!
//! **Unwind 6.** A call of `next_event` loops at most five times (from the rapid to the start:
//! it, the element, the end of the pass and the return to A may each be a skipped move or a
//! phase change before `None`); the harness itself has no loop.

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::contour::{Contour, Element, Kind};
use cycle_impl::g73::{Cycle, Words};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{AlarmCode, Event, Move, Pass, PassKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |coordinate| of A.
    pub max_a: i64,
    /// Largest |coordinate| of the contour element.
    pub max_pos: i64,
    /// Largest |Δi|, |Δk|, |Δu|, |Δw|, feed and line.
    pub max_len: i64,
    /// Largest d.
    pub max_d: i64,
    /// Largest `max_passes`.
    pub max_passes: u32,
}

/// The Kani scope: the full ranges.
pub const KANI: Scope = Scope { max_a: 1 << 60, max_pos: 1 << 60, max_len: MAX_LENGTH, max_d: MAX_LENGTH, max_passes: 1_000_000 };

/// round(v·(d − n)/d) half away from zero, as the register states it (⌊(2|x| + d)/(2d)⌋ with
/// the sign of x; not impl's code): the drivers' table.
pub fn model_escape(v: i64, d: i64, n: i64) -> i64 {
    let x = i128::from(v) * i128::from(d - n);
    let d = i128::from(d);
    let mag = (2 * x.abs() + d) / (2 * d);
    (if x < 0 { -mag } else { mag }) as i64
}

/// Smt/ lemma 15 at passes n₀ and n₀ + 1 for one component: `v` = Δi or Δk, `e` = [e(n₀),
/// e(n₀ + 1)] (assumed under Kani, checked by the drivers).
pub fn spec(v: i64, d: i64, n0: i64, e: [i64; 2]) -> [(bool, &'static str); 4] {
    let between = |x: i64| if v >= 0 { 0 <= x && x <= v } else { v <= x && x <= 0 };
    [
        (between(e[0]) && (n0 >= d || between(e[1])), "lemma 15: e(n) between 0 and v"),
        (n0 >= d || (if v >= 0 { e[1] <= e[0] } else { e[1] >= e[0] }), "lemma 15: e(n + 1) no farther from 0 than e(n)"),
        (n0 != d || e[0] == 0, "lemma 15: e(d) = 0"),
        (cfg!(kani) || (e[0] == model_escape(v, d, n0) && (n0 >= d || e[1] == model_escape(v, d, n0 + 1))), "the table holds the exact quotients"),
    ]
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let pos_range = |src: &mut S| src.bounded_i64(-scope.max_pos, scope.max_pos);
    let a = (src.bounded_i64(-scope.max_a, scope.max_a), src.bounded_i64(-scope.max_a, scope.max_a));
    let di = src.bounded_i64(-scope.max_len, scope.max_len);
    let dk = src.bounded_i64(-scope.max_len, scope.max_len);
    let d = src.bounded_i64(1, scope.max_d);
    let allowance = (src.bounded_i64(-scope.max_len, scope.max_len), src.bounded_i64(-scope.max_len, scope.max_len));
    let feed = src.bounded_i64(1, scope.max_len);
    let count_word = if src.bool() { b'R' } else { b'D' };
    let visit_c = src.bool();
    let max_passes = src.bounded_u32(1, scope.max_passes);
    let line = src.bounded_u32(1, u32::try_from(scope.max_len).unwrap_or(u32::MAX));
    let kind = match src.bounded_u32(0, 3) {
        0 => Kind::Rapid,
        1 => Kind::Feed,
        k => Kind::Arc(k == 2),
    };
    let (x, z) = (pos_range(src), pos_range(src));
    let (cx, cz) = if matches!(kind, Kind::Arc(_)) { (pos_range(src), pos_range(src)) } else { (0, 0) };
    let el = Element { x, z, cx, cz, feed: 0, line: 2, kind };
    #[cfg_attr(kani, allow(unused_mut))]
    let mut contour = Contour::new();
    #[cfg(kani)]
    stubs::set_element(el);
    #[cfg(not(kani))]
    check!(src, contour.push(el), "the contour buffer takes one element");

    let w = Words { di, dk, d, allowance, feed, count_word, visit_c };
    let mut cycle = match Cycle::new(a, &w, &contour, max_passes, line) {
        Err(al) => {
            check!(src, d > i64::from(max_passes), "PRJ.MAXPASS: refused only when d > max_passes");
            check!(
                src,
                al.code == AlarmCode::TooManyPasses && al.word == Some(count_word) && al.rule == Rule::PrjMaxPass && al.line == line,
                "PRJ.MAXPASS: TOO MANY PASSES on the count word, on the cycle block's line"
            );
            cover!(src, true, "refused: d > max_passes");
            return Ok(());
        }
        Ok(c) => c,
    };
    check!(src, d <= i64::from(max_passes), "PRJ.MAXPASS: d > max_passes is refused before motion");

    // Pass n₀ and the table of its escapes and the next pass's.
    let n0 = src.bounded_i64(1, d);
    let (ei, ek) = if cfg!(kani) {
        let mut e = || src.bounded_i64(-MAX_LENGTH, MAX_LENGTH);
        ([e(), e()], [e(), e()])
    } else {
        let next = |v: i64| if n0 < d { model_escape(v, d, n0 + 1) } else { 0 };
        ([model_escape(di, d, n0), next(di)], [model_escape(dk, d, n0), next(dk)])
    };
    // (No loop: the harness's loops would raise the unwind bound of `next_event`'s.)
    let [si, sk] = [spec(di, d, n0, ei), spec(dk, d, n0, ek)];
    if cfg!(kani) {
        let all = |s: &[(bool, &str); 4]| s[0].0 && s[1].0 && s[2].0 && s[3].0;
        src.assume(all(&si) && all(&sk))?;
    } else {
        for (ok, msg) in si.into_iter().chain(sk) {
            src.verdict(ok, msg)?;
        }
    }
    #[cfg(kani)]
    stubs::set_escapes(n0, ei, ek);

    let offset = |i: usize| (2 * ei[i] + allowance.0, ek[i] + allowance.1);
    let plus = |p: (i64, i64), t: (i64, i64)| (p.0 + t.0, p.1 + t.1);
    let mut pos = a;
    if n0 == 1 {
        if visit_c {
            let c = plus(a, (2 * di + allowance.0, dk + allowance.1));
            if c != a {
                let ev = cycle.next_event(&mut pos, &contour);
                check!(src, ev == Some(Event::Move(Move::rapid(c.0, c.1, Rule::G73Path))), "G73 point C: the rapid A → C first (g73.c = visit)");
            }
            check!(src, pos == c, "G73 point C: the tool at C before pass 1");
        }
        // Under Kani pass 1 is entered again as `end_pass` would (a no-op on the state `new`
        // and the C move leave: pass 1's header next, which the drivers check by running on):
        // after `new`'s refusal branch CBMC's symbolic execution no longer knows the phase, and
        // would unroll every phase in every iteration of `next_event`.
        if cfg!(kani) {
            cycle.enter_pass(1);
        }
    } else {
        cycle.enter_pass(n0);
        // Where pass n₀ − 1 ended: under Kani any point (a superset), under the drivers the
        // element translated by T(n₀ − 1) (the escapes' model).
        pos = if cfg!(kani) {
            (src.bounded_i64(-(1 << 62), 1 << 62), src.bounded_i64(-(1 << 62), 1 << 62))
        } else {
            (el.x + 2 * model_escape(di, d, n0 - 1) + allowance.0, el.z + model_escape(dk, d, n0 - 1) + allowance.1)
        };
    }

    // Pass n₀: header, rapid to A + T(n₀), the element translated by T(n₀).
    let t0 = offset(0);
    let header = |n: i64, e: i64| Event::Pass(Pass { index: n as u32, kind: PassKind::Rough, diameter_depth: (2 * e).abs(), rule: Rule::G73Depth });
    check!(src, cycle.next_event(&mut pos, &contour) == Some(header(n0, ei[0])), "G73.DEPTH: pass n's header, index n, diameter depth |2·e_i(n)|");
    let start = plus(a, t0);
    if pos != start {
        let ev = cycle.next_event(&mut pos, &contour);
        check!(src, ev == Some(Event::Move(Move::rapid(start.0, start.1, Rule::G73Path))), "G73.PATH: the rapid to A + T(n)");
    }
    let end = plus((el.x, el.z), t0);
    let centre = plus((el.cx, el.cz), t0);
    let want = match kind {
        Kind::Rapid => Move::rapid(end.0, end.1, Rule::G73Path),
        Kind::Feed => Move::feed(end.0, end.1, feed, Rule::G73Path),
        Kind::Arc(cw) => Move::arc(cw, end.0, end.1, centre.0, centre.1, feed, Rule::G73Path),
    };
    if pos != end {
        let ev = cycle.next_event(&mut pos, &contour);
        check!(src, ev == Some(Event::Move(want)), "G73.PATH: the contour translated by T(n), in its own mode");
    }
    check!(src, pos == end, "G73.PATH: the pass ends on the translated contour");

    if n0 < d {
        // Pass n₀ + 1: its header and its offset, never larger.
        let t1 = offset(1);
        check!(src, cycle.next_event(&mut pos, &contour) == Some(header(n0 + 1, ei[1])), "G73.COUNT: pass n + 1 follows pass n < d");
        let start1 = plus(a, t1);
        if pos != start1 {
            let ev = cycle.next_event(&mut pos, &contour);
            check!(src, ev == Some(Event::Move(Move::rapid(start1.0, start1.1, Rule::G73Path))), "G73.PATH: the rapid to A + T(n + 1)");
        }
        let (g0, g1) = ((t0.0 - allowance.0, t0.1 - allowance.1), (t1.0 - allowance.0, t1.1 - allowance.1));
        check!(src, g1.0.abs() <= g0.0.abs() && g1.1.abs() <= g0.1.abs(), "G73.DEPTH: the offsets never grow");
        check!(src, g1.0 * di.signum() >= 0 && g1.1 * dk.signum() >= 0 && (di != 0 || g1.0 == 0) && (dk != 0 || g1.1 == 0), "G73.DEPTH: each pass on the side of (Δi, Δk), toward the allowance");
        cover!(src, g1.0.abs() < g0.0.abs(), "the X offset shrinks");
        cover!(src, n0 == 1, "pass 1 → 2");
        cover!(src, n0 >= 2, "pass n ≥ 2 → n + 1");
    } else {
        check!(src, t0 == allowance, "G73.DEPTH: the last pass d stands at the allowance (Δu, Δw)");
        if pos != a {
            check!(src, cycle.next_event(&mut pos, &contour) == Some(Event::Move(Move::rapid(a.0, a.1, Rule::G73Path))), "G73.PATH: after pass d, the rapid back to A");
        }
        check!(src, cycle.next_event(&mut pos, &contour).is_none() && pos == a, "G73.COUNT: no pass after pass d; the cycle ends at A");
        cover!(src, d == 1, "one pass");
        cover!(src, d >= 2, "the last of several passes");
    }
    Ok(())
}

/// The Kani stubs of `cycle_impl::g73::escape` and the contour (TRUSTED specification:
/// [`spec`], smt/ lemma 15; checked by the drivers).
#[cfg(kani)]
pub mod stubs {
    use core::sync::atomic::{AtomicBool, AtomicI64, AtomicU8, Ordering::SeqCst};
    use cycle_impl::contour::{Contour, Element, Kind};
    use cycle_impl::g73::Words;

    static N0: AtomicI64 = AtomicI64::new(0);
    static EI: [AtomicI64; 2] = [AtomicI64::new(0), AtomicI64::new(0)];
    static EK: [AtomicI64; 2] = [AtomicI64::new(0), AtomicI64::new(0)];
    static EL: [AtomicI64; 4] = [AtomicI64::new(0), AtomicI64::new(0), AtomicI64::new(0), AtomicI64::new(0)];
    static KIND: AtomicU8 = AtomicU8::new(0);
    static CW: AtomicBool = AtomicBool::new(false);

    pub fn set_escapes(n0: i64, ei: [i64; 2], ek: [i64; 2]) {
        N0.store(n0, SeqCst);
        let [[i0, i1], [k0, k1]] = [ei, ek];
        EI[0].store(i0, SeqCst);
        EI[1].store(i1, SeqCst);
        EK[0].store(k0, SeqCst);
        EK[1].store(k1, SeqCst);
    }

    pub fn set_element(e: Element) {
        EL[0].store(e.x, SeqCst);
        EL[1].store(e.z, SeqCst);
        EL[2].store(e.cx, SeqCst);
        EL[3].store(e.cz, SeqCst);
        let (k, cw) = match e.kind {
            Kind::Rapid => (0, false),
            Kind::Feed => (1, false),
            Kind::Arc(cw) => (2, cw),
        };
        KIND.store(k, SeqCst);
        CW.store(cw, SeqCst);
    }

    /// `escape(w, n)` for n = n₀ or n₀ + 1 (asserted).
    pub fn escape_spec(_w: &Words, n: i64) -> (i64, i64) {
        let n0 = N0.load(SeqCst);
        kani::assert(n == n0 || n == n0 + 1, "the run asks for the escapes of pass n₀ or n₀ + 1 only");
        let i = usize::from(n != n0);
        (EI[i].load(SeqCst), EK[i].load(SeqCst))
    }

    /// `Contour::len`: the one element drawn.
    pub fn contour_len(_c: &Contour) -> usize {
        1
    }

    /// `Contour::get`: the element drawn at 0 (the run asks for no other).
    pub fn contour_get(_c: &Contour, i: usize) -> Element {
        kani::assert(i == 0, "the run reads element 0 only");
        let kind = match KIND.load(SeqCst) {
            0 => Kind::Rapid,
            1 => Kind::Feed,
            _ => Kind::Arc(CW.load(SeqCst)),
        };
        Element { x: EL[0].load(SeqCst), z: EL[1].load(SeqCst), cx: EL[2].load(SeqCst), cz: EL[3].load(SeqCst), feed: 0, line: 2, kind }
    }
}

cycle_harness::property! {
    pub const PROPERTY = g73_passes in crate::PROPERTIES {
        rules: ["G73.DEPTH", "G73.PATH", "G73.COUNT", "PRJ.MAXPASS"],
        states: "The G73 passes at every pass n: TOO MANY PASSES before motion exactly when d > max_passes; pass n's header and the contour translated by T(n) = (2·round(Δi(d − n)/d) + Δu, round(Δk(d − n)/d) + Δw); pass n + 1 exactly when n < d, its offset never larger, toward the allowance; pass d exactly at the allowance, then the rapid to A and the end: exactly d passes.",
        body: |src, scope| body(src, &scope),
        /// The Kani harness (`-Z stubbing`: `escape`, the contour): SUCCESSFUL at 7d2b095 (the
        /// escape table under smt/ lemma 15); one pass too many planted in `end_pass` FAILED.
        kani: proof(KANI) { unwind: 6, stubs: [cycle_impl::g73::escape => stubs::escape_spec, cycle_impl::contour::Contour::len => stubs::contour_len, cycle_impl::contour::Contour::get => stubs::contour_get], measured: "SUCCESSFUL (1250 checks; 6/6 covers), 440.1 s, 2.22 GB" },
        tests {
            /// A at 0 (every position is A plus offsets: translation moves all alike), the element
            /// within ±1, lengths ≤ 1, d and max_passes ≤ 4: every combination.
            fn g73_passes_exhaustive = exhaustive(2, 4_000_000) on Scope { max_a: 0, max_pos: 1, max_len: 1, max_d: 4, max_passes: 4 };
            /// The edges of A, d, n₀ and max_passes (two values at each end; d ≤ 10^6, the counts
            /// max_passes accepts), lengths ≤ 1, the element at 0.
            fn g73_passes_exhaustive_kani_edges = exhaustive(2, 4_000_000) on Scope { max_a: 1 << 60, max_pos: 0, max_len: 1, max_d: 1_000_000, max_passes: 1_000_000 };
            fn g73_passes_random = random(0x5eed_0730, 8) on KANI, random(0x5eed_0731, 8) on Scope { max_a: 1 << 10, max_pos: 1 << 10, max_len: 1 << 10, max_d: 64, max_passes: 1_000_000 };
        }
    }
}
