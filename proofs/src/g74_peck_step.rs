//! Harness `g74_peck_step` — G74.FORMAT, G74.PECK, G74.E, G74.COLUMN, G74.RELIEF, G75.FORMAT,
//! G75.PECK, G75.COLUMN, G75.RELIEF, PRJ.MAXPASS: the peck cycles G74/G75 of the production
//! expander (`cycle_impl::g74::cycle`, `Cycle::next_event`) by induction over their states.
//!
//! **Property.** For G74 and G75, every A and E (±2^60), every Δi, Δk, e, Δd (0…N), feed, both
//! g75.relief readings and every `max_passes`; in the frame of the peck axis p and the step axis
//! s (register, "G74 … and G75"), D = |E.p − A.p| and T = |E.s − A.s|, K the pecks of a column and
//! C the columns as `cycle` counts them (K = ⌈D / peck⌉, C = ⌈T / step⌉ + 1, or 1 without T —
//! lemma 16 below):
//!
//! - **refusal**: exactly in the register's order (no p travel: GEOMETRY; no peck: MISSING WORD;
//!   s travel without a step: MISSING WORD), then exactly when K·C > `max_passes` (TOO MANY
//!   PASSES, PRJ.MAXPASS); else the cycle counts exactly K and C;
//! - **start**: the first event is column 1's header; then the cycle is at peck 1 of column 0,
//!   the tool at A;
//! - **a peck before the last** (any column j < C, any peck 1 ≤ i < K, the tool where peck i − 1's
//!   return left it): one feed along p to A.p + c·i·peck — exactly one peck further than peck
//!   i − 1 (A.p for i = 1), so it **advances**, and short of E.p; then the return by e (none when
//!   e = 0), after which the cycle is exactly at peck i + 1 of the same column;
//! - **the last peck** (i = K): one feed to E.p **exactly** (advancing); the relief (from the
//!   second column on, when Δd > 0); the rapid back to A.p, after which the cycle is at column
//!   j's end (`Cycle::after_column`);
//! - **a column's end** (harness `g74_peck_column`): either column j + 2's header and the rapid
//!   to column j + 1 — which is **one step further** toward E.s (the last exactly at
//!   E.s, none past it) — after which the cycle is at its peck 1; or, after the last column (at
//!   E.s), the rapid home to A and `None`, twice.
//!
//! By induction from the start, every column has exactly pecks 1 … K, each advancing, none past
//! E.p, the last at E.p, and the columns are 1 … C, the last at E.s: the G74/G75 counts and
//! bounds, of the code's `next_event`.
//!
//! **What is trusted (Kani).** The product i·len (`cycle_impl::g74::span`) and the count
//! (`ceil_div`) are stubbed by the table of `peck_parts` (smt/ lemma 16, checked by the drivers
//! on every case). `Cycle::at_peck` (doc-hidden in impl) sets the column, the peck and the phase
//! of a real `cycle` — the state `next_event` itself reaches, as the steps above show. `fill`
//! (the batched writer) is not covered: the impl and fill tests compare it with `next_event`.

use crate::peck_parts::{along, consistent, counts_agree, trusted, Line};
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::g74::{cycle, PeckCode, Words};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{AlarmCode, Event, Move, Pass, PassKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |coordinate| of A and E.
    pub max_pos: i64,
    /// Largest Δi, Δk, e, Δd and feed.
    pub max_len: i64,
    /// Which states: 0 the start, 1 a peck before the last, 2 the last peck, 3 a column's end,
    /// 4 any of them.
    pub case: u32,
}

/// Lengths 0…N, positions within ±2^60 (a program of fewer than 2^30 blocks, lib.rs: beyond, the
/// header's 2·D may exceed 2^63 and saturate — a range the register does not reach).
pub const FULL: Scope = Scope { max_pos: 1 << 60, max_len: MAX_LENGTH, case: 4 };

/// The Kani harnesses: one per kind of state (the start, a peck before the last, the last peck,
/// a column's end).
pub const START: Scope = Scope { case: 0, ..FULL };
pub const STEP: Scope = Scope { case: 1, ..FULL };
pub const LAST: Scope = Scope { case: 2, ..FULL };
pub const COLUMN: Scope = Scope { case: 3, ..FULL };

/// The cycle's frame and words, as the register states them (`i128`).
struct Frame {
    g75: bool,
    a: (i128, i128),
    e: (i128, i128),
    c: i128,
    sigma: i128,
    peck: i128,
    step: i128,
    back: i128,
    relief: i128,
    relief_dir: i128,
}

impl Frame {
    /// A frame point (p, s) on the machine (X, Z).
    fn machine(&self, p: i128, s: i128) -> (i64, i64) {
        let (p, s) = (p as i64, s as i64);
        if self.g75 { (p, s) } else { (s, p) }
    }
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let g75 = src.bool();
    let (m, n) = (scope.max_pos, scope.max_len);
    let a = (src.bounded_i64(-m, m), src.bounded_i64(-m, m));
    let end = (src.bounded_i64(-m, m), src.bounded_i64(-m, m));
    let (di, dk) = (src.bounded_i64(0, n), src.bounded_i64(0, n));
    let (e, relief) = (src.bounded_i64(0, n), src.bounded_i64(0, n));
    let feed = src.bounded_i64(1, n);
    let minus_z = src.bool();
    let max_passes = src.bounded_u32(1, u32::MAX);
    let line = 7;
    let code = if g75 { PeckCode::G75 } else { PeckCode::G74 };
    let w = Words { end, di, dk, relief, e, feed, relief_minus_z: minus_z };

    // The register: G74 p = Z, s = X (pecks Δk, steps 2Δi, returns e, relief 2Δd); G75 p = X,
    // s = Z (pecks 2Δi, steps Δk, returns 2e, relief Δd).
    let frame = |(x, z): (i64, i64)| if g75 { (i128::from(x), i128::from(z)) } else { (i128::from(z), i128::from(x)) };
    let (fa, fe) = (frame(a), frame(end));
    let (di, dk, e, relief) = (i128::from(di), i128::from(dk), i128::from(e), i128::from(relief));
    let (peck, step, back, relief) = if g75 { (2 * di, dk, 2 * e, relief) } else { (dk, 2 * di, e, 2 * relief) };
    let (depth, travel) = ((fe.0 - fa.0).abs(), (fe.1 - fa.1).abs());
    let (c, sigma) = ((fe.0 - fa.0).signum(), (fe.1 - fa.1).signum());
    let relief_dir = if g75 && minus_z { 1 } else { sigma };
    let f = Frame { g75, a: fa, e: fe, c, sigma, peck, step, back, relief, relief_dir };
    let (format, peck_rule, column_rule, relief_rule, return_rule) = if g75 {
        (Rule::G75Format, Rule::G75Peck, Rule::G75Column, Rule::G75Relief, Rule::G75Peck)
    } else {
        (Rule::G74Format, Rule::G74Peck, Rule::G74Column, Rule::G74Relief, Rule::G74E)
    };
    let (peck_word, step_word, p_axis) = if g75 { (b'P', b'Q', b'X') } else { (b'Q', b'P', b'Z') };

    let pecks = Line::count(src, depth as u64, peck as u64);
    let cols = Line::count(src, travel as u64, step as u64);
    let (k, columns) = (pecks.count, if travel == 0 { 1 } else { cols.count.saturating_add(1) });
    // The pecks' and the columns' lines may be one (total, len): `ceil_div`'s stub then answers
    // both from the pecks' line, so their counts must agree before the cycle counts.
    counts_agree(src, &pecks, &cols)?;
    #[cfg(kani)]
    {
        crate::peck_parts::stubs::set(0, &pecks);
        crate::peck_parts::stubs::set(1, &cols);
    }
    // The register's refusals before the pass bound, in its order.
    let earlier = if depth == 0 {
        Some((AlarmCode::Geometry, p_axis, format))
    } else if peck == 0 {
        Some((AlarmCode::MissingWord, peck_word, peck_rule))
    } else if travel != 0 && step == 0 {
        Some((AlarmCode::MissingWord, step_word, column_rule))
    } else {
        None
    };
    // The pass bound K·C > max_passes: checked by the drivers; under Kani left open (the code's
    // u128 product against the harness's would be a multiplier miter, which SAT does not decide).
    #[cfg(not(kani))]
    let over = Some(u128::from(k) * u128::from(columns) > u128::from(max_passes));
    #[cfg(kani)]
    let over: Option<bool> = None;
    let cy0 = match cycle(code, a, &w, max_passes, line) {
        Err(al) => {
            let got = (al.code, al.word, al.rule, al.line);
            let ok = match earlier {
                Some((c, word, rule)) => got == (c, Some(word), rule, line),
                None => got == (AlarmCode::TooManyPasses, Some(peck_word), Rule::PrjMaxPass, line) && over != Some(false),
            };
            check!(src, ok, "G74/G75 step 5: refused exactly as the register says, in its order, K·C > max_passes the last");
            cover!(src, earlier.is_none(), "refused: the pass bound");
            return Ok(());
        }
        Ok(cy) => cy,
    };
    check!(src, earlier.is_none() && over != Some(true), "G74/G75 step 5: accepted exactly when the register accepts");
    check!(src, cy0.counts() == (k, columns), "G74.PECK/G74.COLUMN: ⌈D/peck⌉ pecks per column, ⌈T/step⌉ + 1 columns (1 without T)");

    // A state: column j, peck i (the drivers' draws fall in the real counts).
    trusted(src, k >= 1 && columns >= 1, "lemma 16: K ≥ 1 (and C ≥ 1)")?;
    let j = src.bounded_u64(0, columns - 1);
    let i = src.bounded_u64(1, k);
    let pecks = pecks.table(src, i - 1)?;
    let cols = cols.table(src, j)?;
    consistent(src, &pecks, &cols)?;
    #[cfg(kani)]
    {
        crate::peck_parts::stubs::set(0, &pecks);
        crate::peck_parts::stubs::set(1, &cols);
    }
    // The register's points: peck m ends at A.p + c·min(m·peck, D), column m at
    // A.s + σ·min(m·step, T) (m·len from the table).
    let pe = |m: u64| f.a.0 + along(f.c, pecks.span(m).min(depth));
    let col = |m: u64| f.a.1 + along(f.sigma, cols.span(m).min(travel));
    let s = col(j);
    let from = if i == 1 { f.a.0 } else { pe(i - 1) - along(f.c, f.back) };
    let mut pos = f.machine(from, s);
    let feed_to = |p: i128, s: i128| Some(Event::Move(Move::feed(f.machine(p, s).0, f.machine(p, s).1, feed, peck_rule)));
    let rapid = |p: i128, s: i128, rule: Rule| Some(Event::Move(Move::rapid(f.machine(p, s).0, f.machine(p, s).1, rule)));
    let header = |index: u64| {
        let diameter_depth = if g75 { depth } else { 2 * depth } as i64;
        Some(Event::Pass(Pass { index: index as u32, kind: PassKind::Rough, diameter_depth, rule: column_rule }))
    };

    let case = if scope.case < 4 { scope.case } else { src.choose(4) };
    match case {
        0 => {
            // The start: column 1's header, then peck 1 of column 0 with the tool at A.
            src.assume(i == 1 && j == 0)?;
            let (mut cy, mut pos) = (cy0, a);
            check!(src, cy.next_event(&mut pos) == header(1), "G74.COLUMN: the cycle starts with column 1's header");
            check!(src, cy == cy0.at_peck(0, 1) && pos == a && s == f.a.1, "then it is at peck 1 of column 0 (at A.s), the tool at A");
        }
        1 => {
            // A peck before the last, then its return.
            src.assume(i < k)?;
            let mut cy = cy0.at_peck(j, i);
            let p = pe(i);
            check!(src, cy.next_event(&mut pos) == feed_to(p, s), "G74.PECK: a peck is one feed along the peck axis to A.p + c·min(i·peck, D)");
            check!(src, p == pe(i - 1) + along(f.c, f.peck), "G74.PECK: each peck before the last ends exactly one peck further");
            check!(src, along(f.c, p - pe(i - 1)) > 0, "G74.PECK: every peck advances toward E.p");
            check!(src, along(f.c, f.e.0 - p) > 0, "G74.PECK: a peck before the last stops short of E.p");
            let mut next = cy0.at_peck(j, i + 1);
            if f.back > 0 {
                check!(src, cy.next_event(&mut pos) == rapid(p - along(f.c, f.back), s, return_rule), "G74.E: after a peck but the last, a rapid back by e");
                check!(src, cy == next, "then the cycle is at peck i + 1 of the column");
            } else {
                let mut at = pos;
                check!(src, cy.next_event(&mut pos) == next.next_event(&mut at) && cy == next && pos == at, "G74.E with e = 0: no return move; the cycle goes on as at peck i + 1");
            }
            cover!(src, i >= 2 && j >= 1, "a middle peck of a later column");
        }
        2 => {
            // The last peck of column j, then the relief and the way back to A.p.
            src.assume(i == k)?;
            let mut cy = cy0.at_peck(j, i);
            check!(src, pe(k) == f.e.0, "G74.PECK: the last peck's end is E.p");
            check!(src, cy.next_event(&mut pos) == feed_to(f.e.0, s), "G74.PECK: the last peck is one feed to E.p exactly");
            check!(src, along(f.c, f.e.0 - pe(k - 1)) > 0, "G74.PECK: the last peck advances too");
            let mut s_now = s;
            if j >= 1 && f.relief > 0 {
                s_now = s - along(f.relief_dir, f.relief);
                check!(src, cy.next_event(&mut pos) == rapid(f.e.0, s_now, relief_rule), "G74.RELIEF: from the second column on, the relief by Δd at the bottom");
            }
            check!(src, cy.next_event(&mut pos) == rapid(f.a.0, s_now, column_rule), "G74.COLUMN: a rapid along the peck axis back to A.p");
            check!(src, cy == cy0.after_column(j) && pos == f.machine(f.a.0, s_now), "then the cycle is at column j's end, the tool at A.p");
            cover!(src, j >= 1 && f.relief > 0, "a relief");
        }
        _ => {
            // A column's end (after its way back to A.p, the tool there, after any relief): the
            // next column, or home.
            src.assume(i == k)?;
            let mut cy = cy0.after_column(j);
            let s_now = if j >= 1 && f.relief > 0 { s - along(f.relief_dir, f.relief) } else { s };
            pos = f.machine(f.a.0, s_now);
            if j + 1 < columns {
                check!(src, cy.next_event(&mut pos) == header(j + 2), "G74.COLUMN: one header per column, numbered");
                let s1 = col(j + 1);
                check!(src, along(f.sigma, s1 - s) > 0 && along(f.sigma, f.e.1 - s1) >= 0, "G74.COLUMN: each column one step toward E.s, none past it");
                check!(src, s1 == if j + 2 == columns { f.e.1 } else { s + along(f.sigma, f.step) }, "G74.COLUMN: a full step, the last column exactly at E.s");
                let mut next = cy0.at_peck(j + 1, 1);
                let to = f.machine(f.a.0, s1);
                if pos != to {
                    check!(src, cy.next_event(&mut pos) == rapid(f.a.0, s1, column_rule), "G74.COLUMN: a rapid along the step axis to the next column");
                    check!(src, cy == next, "then the cycle is at peck 1 of the next column");
                } else {
                    let mut at = pos;
                    check!(src, cy.next_event(&mut pos) == next.next_event(&mut at) && cy == next && pos == at, "already there: the cycle goes on as at peck 1 of the next column");
                }
                cover!(src, j >= 1 && f.relief > 0, "a relief, then a next column");
            } else {
                check!(src, s == f.e.1, "G74.COLUMN: the last column stands at E.s");
                if pos != a {
                    check!(src, cy.next_event(&mut pos) == rapid(f.a.0, f.a.1, column_rule), "G74.COLUMN: a rapid home to A");
                }
                check!(src, cy.next_event(&mut pos).is_none() && cy.next_event(&mut pos).is_none(), "the cycle ends, and stays ended");
                check!(src, pos == a, "the cycle ends at A");
                cover!(src, j >= 1 && k >= 2, "the end of a cycle of several columns and pecks");
            }
        }
    }
    cover!(src, g75, "G75");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = g74_peck_step in crate::PROPERTIES {
        rules: ["G74.FORMAT", "G74.PECK", "G74.E", "G74.COLUMN", "G74.RELIEF", "G75.FORMAT", "G75.PECK", "G75.COLUMN", "G75.RELIEF", "PRJ.MAXPASS"],
        states: "The G74/G75 cycle by induction over its states (i·len and ⌈D/len⌉ stubbed by smt/ lemma 16's table, checked by the drivers): refused exactly in the register's order, K·C > max_passes last; counts K pecks, C columns; from the start, from any peck before the last (one peck further, advancing, short of E, its return, then at peck i + 1) and from the last peck (exactly at E, relief, back, then the next column one step further — the last at E.s — or home and None).",
        body: |src, scope| body(src, &scope),
        /// The Kani proof of the peck before the last (START, LAST and COLUMN: below). Unwind 3:
        /// `next_event`'s loop runs at most two phases per call (skipped return, relief or rapid to the column, then a move); the harness has no loop.
        kani: proof(STEP) { unwind: 3, stubs: [cycle_impl::g74::span => crate::peck_parts::stubs::span_spec, cycle_impl::g74::ceil_div => crate::peck_parts::stubs::ceil_div_spec, cycle_impl::g74::toward => crate::peck_parts::stubs::toward_spec], measured: "SUCCESSFUL (2138 checks, 31 unreachable: the other states'; 3/5 covers, 2 unreachable: the other states'), 810.4 s, 1.96 GB" },
        tests {
            /// Positions −2, −1, 1, 2 and lengths 0…2 (each draw's 2 smallest and largest), both
            /// codes, both readings, every state.
            fn g74_peck_step_exhaustive_small = exhaustive(2, 8_000_000) on Scope { max_pos: 2, max_len: 2, case: 4 };
            /// The full ranges (one draw in eight an edge); and small ones, where cycles have few pecks
            /// and columns.
            fn g74_peck_step_random = random(0x5eed_0741, 2) on FULL, random(0x5eed_0742, 2) on Scope { max_pos: 40, max_len: 12, case: 4 };
        }
    }
}

cycle_harness::property! {
    pub const START_PROPERTY = g74_peck_start in crate::PROPERTIES {
        rules: ["G74.FORMAT", "G74.PECK", "G74.E", "G74.COLUMN", "G74.RELIEF", "G75.FORMAT", "G75.PECK", "G75.COLUMN", "G75.RELIEF", "PRJ.MAXPASS"],
        states: "The G74/G75 cycle's start (the induction base of g74_peck_step; stubs as there): refused exactly in the register's order, the counts K and C, then column 1's header and the state at peck 1 of column 0, the tool at A.",
        body: |src, scope| body(src, &scope),
        /// The Kani proof of the start (unwind as `g74_peck_step`).
        kani: proof(START) { unwind: 3, stubs: [cycle_impl::g74::span => crate::peck_parts::stubs::span_spec, cycle_impl::g74::ceil_div => crate::peck_parts::stubs::ceil_div_spec, cycle_impl::g74::toward => crate::peck_parts::stubs::toward_spec], measured: "SUCCESSFUL (2138 checks, 47 unreachable: the other states'; 2/5 covers, 3 unreachable: the other states'), 132.6 s, 0.97 GB" },
        tests {
            fn g74_peck_start_random = random(0x5eed_0744, 4) on START, random(0x5eed_0745, 4) on Scope { max_pos: 40, max_len: 12, case: 0 };
        }
    }
}

cycle_harness::property! {
    pub const LAST_PROPERTY = g74_peck_last in crate::PROPERTIES {
        rules: ["G74.FORMAT", "G74.PECK", "G74.E", "G74.COLUMN", "G74.RELIEF", "G75.FORMAT", "G75.PECK", "G75.COLUMN", "G75.RELIEF", "PRJ.MAXPASS"],
        states: "The G74/G75 cycle's last peck of any column (the rest of g74_peck_step's induction; stubs as there): one feed exactly to E.p, advancing; the relief from the second column; back to A.p; then the cycle at that column's end (g74_peck_column).",
        body: |src, scope| body(src, &scope),
        /// The Kani proof of the last peck (unwind as `g74_peck_step`).
        kani: proof(LAST) { unwind: 3, stubs: [cycle_impl::g74::span => crate::peck_parts::stubs::span_spec, cycle_impl::g74::ceil_div => crate::peck_parts::stubs::ceil_div_spec, cycle_impl::g74::toward => crate::peck_parts::stubs::toward_spec], measured: "SUCCESSFUL (2236 checks, 38 unreachable: the other states'; 3/6 covers, 3 unreachable: the other states'), 330.8 s, 1.57 GB" },
        tests {
            fn g74_peck_last_random = random(0x5eed_0746, 4) on LAST, random(0x5eed_0747, 4) on Scope { max_pos: 40, max_len: 12, case: 2 };
        }
    }
}

cycle_harness::property! {
    pub const COLUMN_PROPERTY = g74_peck_column in crate::PROPERTIES {
        rules: ["G74.FORMAT", "G74.PECK", "G74.E", "G74.COLUMN", "G74.RELIEF", "G75.FORMAT", "G75.PECK", "G75.COLUMN", "G75.RELIEF", "PRJ.MAXPASS"],
        states: "The G74/G75 cycle at a column's end (`Cycle::after_column`; the rest of g74_peck_step's induction; stubs as there): the next column's header and its peck 1 one step further toward E.s (the last at E.s), or home to A and None.",
        body: |src, scope| body(src, &scope),
        /// The Kani proof of a column's end (unwind as `g74_peck_step`).
        kani: proof(COLUMN) { unwind: 3, stubs: [cycle_impl::g74::span => crate::peck_parts::stubs::span_spec, cycle_impl::g74::ceil_div => crate::peck_parts::stubs::ceil_div_spec, cycle_impl::g74::toward => crate::peck_parts::stubs::toward_spec], measured: "SUCCESSFUL (2236 checks, 28 unreachable: the other states'; 4/6 covers, 2 unreachable: the other states'), 464.7 s, 3.44 GB" },
        tests {
            fn g74_peck_column_random = random(0x5eed_0748, 4) on COLUMN, random(0x5eed_0749, 4) on Scope { max_pos: 40, max_len: 12, case: 3 };
        }
    }
}
