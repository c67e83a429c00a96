//! Harness `g83_peck_step` — G83.FORMAT, G83.PECK, PRJ.MAXPASS: the G83 peck drilling cycle of
//! the production expander (`cycle_impl::g83::cycle`, `Cycle::next_event`) by induction over its
//! states.
//!
//! **Property.** For every position (X, I) (±2^60), R (±N), bottom Z (±2^60), peck Q (0…N; 0:
//! none), dwell P, feed and `max_passes`; with the R level L = I + R, D = |Z − L|, c the sign of
//! Z − L and K the pecks as `cycle` counts them (⌈D / Q⌉, 1 without Q — lemma 16 below):
//!
//! - **refusal**: D = 0 is GEOMETRY on Z (G83.FORMAT); then exactly when K > `max_passes` (TOO
//!   MANY PASSES on Q, PRJ.MAXPASS); else the cycle counts exactly K;
//! - **start**: the header (index 1, ROUGH, 2D), then the rapid to L (none when the tool is
//!   there), after which the cycle is at peck 1, the tool at (X, L);
//! - **a peck before the last** (1 ≤ k < K, the tool at the depth reached, L for k = 1): one feed
//!   along Z to L + c·k·Q — exactly Q further than peck k − 1, so it **advances**, and short of
//!   the bottom; the rapid up to L and down to the depth reached; then the cycle is at peck k + 1;
//! - **the last peck** (k = K): one feed to the bottom **exactly** (advancing); the dwell P (only
//!   when P > 0); the rapid to I (none when there); then `None`, twice, the tool at (X, I).
//!
//! By induction from the start the pecks are 1 … K, each advancing, none past the bottom, the
//! last at it: G83's count and bounds, of the code's `next_event`.
//!
//! **What is trusted (Kani).** k·Q (`cycle_impl::g74::span`, which G83 shares) and ⌈D / Q⌉
//! (`ceil_div`) are stubbed by `peck_parts`'s table (smt/ lemma 16, checked by the drivers on
//! every case). `Cycle::at_peck` (doc-hidden in impl) sets the peck and the phase of a real
//! `cycle`. `fill` is not covered (the impl and fill tests compare it with `next_event`).

use crate::peck_parts::{along, trusted, Line};
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::g83::{cycle, Words};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{AlarmCode, Dwell, Event, Move, Pass, PassKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |X|, |I| and |Z|.
    pub max_pos: i64,
    /// Largest |R|, Q and feed.
    pub max_len: i64,
    /// Which states: 0 the start, 1 a peck before the last, 2 the last peck, 3 any of them.
    pub case: u32,
}

/// R, Q 0…N, positions within ±2^60 (a program of fewer than 2^30 blocks, lib.rs: beyond, the
/// header's 2·D may exceed 2^63 and saturate — a range the register does not reach).
pub const FULL: Scope = Scope { max_pos: 1 << 60, max_len: MAX_LENGTH, case: 3 };

/// The Kani harnesses: one per kind of state (the start, a peck before the last, the last peck).
pub const START: Scope = Scope { case: 0, ..FULL };
pub const STEP: Scope = Scope { case: 1, ..FULL };
pub const LAST: Scope = Scope { case: 2, ..FULL };

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let (m, n) = (scope.max_pos, scope.max_len);
    let a = (src.bounded_i64(-m, m), src.bounded_i64(-m, m));
    let r = src.bounded_i64(-n, n);
    let bottom = src.bounded_i64(-m, m);
    let q = src.bounded_i64(0, n);
    let dwell = src.bounded_u32(0, u32::MAX);
    let feed = src.bounded_i64(1, n);
    let max_passes = src.bounded_u32(1, u32::MAX);
    let line = 9;
    let rule = Rule::G83Peck;
    let w = Words { r, bottom, q, dwell, feed };

    // The register, in i128.
    let level = i128::from(a.1) + i128::from(r);
    let (c, depth) = ((i128::from(bottom) - level).signum(), (i128::from(bottom) - level).abs());
    let qq = i128::from(q);
    let pecks = Line::count(src, depth as u64, q as u64);
    #[cfg(kani)]
    crate::peck_parts::stubs::set(0, &pecks);
    let k = if q == 0 { 1 } else { pecks.count };
    let want = if depth == 0 {
        Some((AlarmCode::Geometry, b'Z', Rule::G83Format))
    } else if k > u64::from(max_passes) {
        Some((AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass))
    } else {
        None
    };
    let cy0 = match cycle(a, &w, max_passes, line) {
        Err(al) => {
            check!(src, want.is_some_and(|(c, word, rule)| (al.code, al.word, al.rule, al.line) == (c, Some(word), rule, line)), "G83: refused exactly as the register says, in its order, K > max_passes the last");
            cover!(src, depth != 0, "refused: the pass bound");
            return Ok(());
        }
        Ok(cy) => cy,
    };
    check!(src, want.is_none(), "G83: accepted exactly when the register accepts");
    check!(src, cy0.pecks() == k, "G83.PECK: ⌈D/Q⌉ pecks (1 without Q)");

    trusted(src, k >= 1, "lemma 16: K ≥ 1")?;
    let i = src.bounded_u64(1, k);
    let pecks = pecks.table(src, i - 1)?;
    #[cfg(kani)]
    crate::peck_parts::stubs::set(0, &pecks);
    // Peck m ends at L + c·min(m·Q, D) (the bottom without Q).
    let pe = |m: u64| if q == 0 && m >= 1 { i128::from(bottom) } else { level + along(c, pecks.span(m).min(depth)) };
    let x = a.0;
    let z = |v: i128| v as i64;
    let at_level = (x, z(level));

    let case = if scope.case < 3 { scope.case } else { src.choose(3) };
    match case {
        0 => {
            // The start: the header, the rapid to L, then peck 1 with the tool at L.
            src.assume(i == 1)?;
            let (mut cy, mut pos) = (cy0, a);
            let header = Pass { index: 1, kind: PassKind::Rough, diameter_depth: (2 * depth) as i64, rule };
            check!(src, cy.next_event(&mut pos) == Some(Event::Pass(header)), "G83.PECK: one ROUGH header, 2D deep on diameter");
            let mut next = cy0.at_peck(1);
            if pos != at_level {
                check!(src, cy.next_event(&mut pos) == Some(Event::Move(Move::rapid(x, z(level), rule))), "G83.PECK: a rapid to the R level");
                check!(src, cy == next, "then the cycle is at peck 1");
            } else {
                let mut at = pos;
                check!(src, cy.next_event(&mut pos) == next.next_event(&mut at) && cy == next && pos == at, "at the R level already: the cycle goes on as at peck 1");
            }
        }
        1 => {
            // A peck before the last, the rapid up to L and down to the depth reached.
            src.assume(i < k)?;
            let mut cy = cy0.at_peck(i);
            let mut pos = (x, z(pe(i - 1)));
            let p = pe(i);
            check!(src, cy.next_event(&mut pos) == Some(Event::Move(Move::feed(x, z(p), feed, rule))), "G83.PECK: a peck is one feed along Z to L + c·min(k·Q, D)");
            check!(src, p == pe(i - 1) + along(c, qq), "G83.PECK: each peck before the last ends exactly Q further");
            check!(src, along(c, p - pe(i - 1)) > 0, "G83.PECK: every peck advances toward the bottom");
            check!(src, along(c, i128::from(bottom) - p) > 0, "G83.PECK: a peck before the last stops short of the bottom");
            check!(src, cy.next_event(&mut pos) == Some(Event::Move(Move::rapid(x, z(level), rule))), "G83.PECK: a rapid back to the R level");
            check!(src, cy.next_event(&mut pos) == Some(Event::Move(Move::rapid(x, z(p), rule))), "G83.PECK: a rapid down to the depth reached");
            check!(src, cy == cy0.at_peck(i + 1), "then the cycle is at peck k + 1");
            cover!(src, i >= 2, "a middle peck");
        }
        _ => {
            // The last peck, the dwell, home.
            src.assume(i == k)?;
            let mut cy = cy0.at_peck(i);
            let mut pos = (x, z(pe(i - 1)));
            check!(src, pe(k) == i128::from(bottom), "G83.PECK: the last peck's end is the bottom");
            check!(src, cy.next_event(&mut pos) == Some(Event::Move(Move::feed(x, bottom, feed, rule))), "G83.PECK: the last peck is one feed to the bottom exactly");
            check!(src, along(c, i128::from(bottom) - pe(k - 1)) > 0, "G83.PECK: the last peck advances too");
            if dwell > 0 {
                check!(src, cy.next_event(&mut pos) == Some(Event::Dwell(Dwell { ms: dwell, rule })), "G83.PECK: the dwell P at the bottom");
            }
            if pos != a {
                check!(src, cy.next_event(&mut pos) == Some(Event::Move(Move::rapid(x, a.1, rule))), "G83.PECK: a rapid to the initial level");
            }
            check!(src, cy.next_event(&mut pos).is_none() && cy.next_event(&mut pos).is_none(), "the cycle ends, and stays ended");
            check!(src, pos == a, "the cycle ends at (X, I)");
            cover!(src, k >= 2 && dwell > 0, "the end of several pecks, with a dwell");
        }
    }
    cover!(src, q == 0, "no Q: one feed");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = g83_peck_step in crate::PROPERTIES {
        rules: ["G83.FORMAT", "G83.PECK", "PRJ.MAXPASS"],
        states: "The G83 cycle by induction over its states (k·Q and ⌈D/Q⌉ stubbed by smt/ lemma 16's table, checked by the drivers): refused exactly in the register's order (no depth, then K > max_passes); counts K pecks; from the start (header, to L), from any peck before the last (Q further, advancing, short of the bottom, up and down, then at peck k + 1) and from the last peck (exactly at the bottom, the dwell only when P > 0, home to I, None).",
        body: |src, scope| body(src, &scope),
        /// The Kani harness of the peck before the last (START and LAST: below). Unwind 3:
        /// `next_event`'s loop runs at most two phases per call (skipped rapid or dwell, then an event); the harness has no loop.
        kani: proof(STEP) { unwind: 3, stubs: [cycle_impl::g74::span => crate::peck_parts::stubs::span_spec, cycle_impl::g74::ceil_div => crate::peck_parts::stubs::ceil_div_spec, cycle_impl::g74::toward => crate::peck_parts::stubs::toward_spec], measured: "SUCCESSFUL (1572 checks, 17 unreachable: the other states'; 2/4 covers: 1 unreachable, the other states', and the cover of no Q unsatisfiable here — without Q K = 1, no peck before the last), 172.7 s, not measured alone (same run; the other two harnesses peaked at 0.89 and 1.05 GB)" },
        tests {
            /// Positions, R and the bottom in ±3, Q 0…3 (each draw's 3 smallest and largest).
            fn g83_peck_step_exhaustive_small = exhaustive(3, 3_000_000) on Scope { max_pos: 3, max_len: 3, case: 3 };
            /// The edges of the legal ranges.
            fn g83_peck_step_exhaustive_edges = exhaustive(2, 2_000_000) on FULL;
            /// The full ranges; and small ones, where cycles have few pecks.
            fn g83_peck_step_random = random(0x5eed_0831, 2) on FULL, random(0x5eed_0832, 2) on Scope { max_pos: 40, max_len: 12, case: 3 };
        }
    }
}

cycle_harness::property! {
    pub const START_PROPERTY = g83_peck_start in crate::PROPERTIES {
        rules: ["G83.FORMAT", "G83.PECK", "PRJ.MAXPASS"],
        states: "The G83 cycle's start (the induction base of g83_peck_step; stubs as there): refused exactly in the register's order, the count K, then the header, the rapid to L and the state at peck 1.",
        body: |src, scope| body(src, &scope),
        /// The Kani harness of the start (unwind as `g83_peck_step`).
        kani: proof(START) { unwind: 3, stubs: [cycle_impl::g74::span => crate::peck_parts::stubs::span_spec, cycle_impl::g74::ceil_div => crate::peck_parts::stubs::ceil_div_spec, cycle_impl::g74::toward => crate::peck_parts::stubs::toward_spec], measured: "SUCCESSFUL (1572 checks, 35 unreachable: the other states'; 2/4 covers, 2 unreachable: the other states'), 71.6 s, 0.89 GB" },
        tests {
            fn g83_peck_start_random = random(0x5eed_0833, 4) on START, random(0x5eed_0834, 4) on Scope { max_pos: 40, max_len: 12, case: 0 };
        }
    }
}

cycle_harness::property! {
    pub const LAST_PROPERTY = g83_peck_last in crate::PROPERTIES {
        rules: ["G83.FORMAT", "G83.PECK", "PRJ.MAXPASS"],
        states: "The G83 cycle's last peck (the rest of g83_peck_step's induction; stubs as there): one feed exactly to the bottom, advancing; the dwell only when P > 0; home to I; None.",
        body: |src, scope| body(src, &scope),
        /// The Kani harness of the last peck (unwind as `g83_peck_step`).
        kani: proof(LAST) { unwind: 3, stubs: [cycle_impl::g74::span => crate::peck_parts::stubs::span_spec, cycle_impl::g74::ceil_div => crate::peck_parts::stubs::ceil_div_spec, cycle_impl::g74::toward => crate::peck_parts::stubs::toward_spec], measured: "SUCCESSFUL (1572 checks, 22 unreachable: the other states'; 3/4 covers, 1 unreachable: the other states'), 188.4 s, 1.05 GB" },
        tests {
            fn g83_peck_last_random = random(0x5eed_0835, 4) on LAST, random(0x5eed_0836, 4) on Scope { max_pos: 40, max_len: 12, case: 2 };
        }
    }
}
