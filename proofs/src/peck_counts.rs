//! Harness `peck_counts` — G74.FORMAT, G74.PECK, G74.E, G74.COLUMN, G75.FORMAT, G75.PECK,
//! G75.COLUMN, PRJ.MAXPASS: the counts and bounds of one G74/G75 cycle of the production
//! expander (`cycle_impl::g74::cycle`, then `Cycle::next_event` until `None`).
//!
//! **Property.** For G74 and G75, every start point A and end point E, every peck, step, return
//! e and relief, every `max_passes`:
//!
//! - the cycle is refused exactly as the register's step 5 says, in its order (no travel on the
//!   peck axis: GEOMETRY on Z / X, rule G74.FORMAT / G75.FORMAT; no peck: MISSING WORD Q / P,
//!   G74.PECK / G75.PECK; step travel without a step: MISSING WORD P / Q, G74.COLUMN /
//!   G75.COLUMN), then when columns × pecks > `max_passes` (TOO MANY PASSES on Q / P,
//!   PRJ.MAXPASS) — before any event;
//! - otherwise there are exactly ⌈|travel| / step⌉ + 1 columns (1 without step travel), one pass
//!   header each, and in every column exactly ⌈depth / peck⌉ pecks (feeds), each along the peck
//!   axis only, each ending exactly one peck further toward E than the last (the first one peck
//!   from A), the last exactly at E, none past it;
//! - the tool ends at A and the cycle ends (`None`, twice).
//!
//! Expectations are computed here in `i128` from the register's text. **A TEST**, not a Kani
//! proof (Kani reached no verdict: see the end of the file). The scope written for Kani bounds
//! the counts the event loop follows — at most 3 pecks and 2 columns (`KANI`) over every
//! position and length in ±2^40 — and the random driver runs that scope; the drivers also run
//! the body with far larger counts.

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::g74::{cycle, PeckCode, Words};
use cycle_vocab::{AlarmCode, Event, MoveKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |coordinate| of A and E, and largest length.
    pub max_pos: i64,
    /// Largest pecks per column and columns the body follows through (larger cycles are only
    /// checked for their refusal and counts).
    pub max_pecks: u64,
    pub max_columns: u64,
}

/// What Kani checks (see the module documentation).
pub const KANI: Scope = Scope { max_pos: 1 << 40, max_pecks: 3, max_columns: 2 };

fn ceil_div(a: i128, b: i128) -> i128 {
    (a + b - 1) / b
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let g75 = src.bool();
    let m = scope.max_pos;
    let a = (src.bounded_i64(-m, m), src.bounded_i64(-m, m));
    let end = (src.bounded_i64(-m, m), src.bounded_i64(-m, m));
    let (di, dk) = (src.bounded_i64(0, m), src.bounded_i64(0, m));
    let (e, relief) = (src.bounded_i64(0, m), src.bounded_i64(0, m));
    let max_passes = src.bounded_u32(1, u32::MAX);
    let line = 7;
    let code = if g75 { PeckCode::G75 } else { PeckCode::G74 };
    // g75.relief changes the relief's direction, never whether it moves: both readings (taken
    // from the parity of e, no extra draw for the exhaustive driver's budget).
    let w = Words { end, di, dk, relief, e, feed: 1, relief_minus_z: e % 2 == 0 };

    // The register, in i128, in the frame (peck axis p, step axis s): G74 p = Z, s = X (steps
    // 2Δi, pecks Δk); G75 p = X, s = Z (pecks 2Δi, steps Δk).
    let (ai, ei) = ((i128::from(a.0), i128::from(a.1)), (i128::from(end.0), i128::from(end.1)));
    let (ap, as_, ep, es) = if g75 { (ai.0, ai.1, ei.0, ei.1) } else { (ai.1, ai.0, ei.1, ei.0) };
    let (peck, step) = if g75 { (2 * i128::from(di), i128::from(dk)) } else { (i128::from(dk), 2 * i128::from(di)) };
    let (format, peck_rule, column_rule) =
        if g75 { (Rule::G75Format, Rule::G75Peck, Rule::G75Column) } else { (Rule::G74Format, Rule::G74Peck, Rule::G74Column) };
    let (peck_word, step_word, p_axis) = if g75 { (b'P', b'Q', b'X') } else { (b'Q', b'P', b'Z') };
    let (depth, travel) = ((ep - ap).abs(), (es - as_).abs());
    let expected = if depth == 0 {
        Err((AlarmCode::Geometry, p_axis, format))
    } else if peck == 0 {
        Err((AlarmCode::MissingWord, peck_word, peck_rule))
    } else if travel != 0 && step == 0 {
        Err((AlarmCode::MissingWord, step_word, column_rule))
    } else {
        let pecks = ceil_div(depth, peck);
        let columns = if travel == 0 { 1 } else { ceil_div(travel, step) + 1 };
        if pecks * columns > i128::from(max_passes) {
            Err((AlarmCode::TooManyPasses, peck_word, Rule::PrjMaxPass))
        } else {
            Ok((pecks, columns))
        }
    };

    let (mut cy, pecks, columns) = match (cycle(code, a, &w, max_passes, line), expected) {
        (Err(al), Err((c, word, rule))) => {
            check!(src, al.code == c && al.word == Some(word) && al.rule == rule && al.line == line, "G74/G75 step 5: the register's alarm, in its order");
            cover!(src, c == AlarmCode::TooManyPasses, "refused: the pass bound");
            return Ok(());
        }
        (Ok(cy), Ok((pecks, columns))) => {
            if pecks as u128 > u128::from(scope.max_pecks) || columns as u128 > u128::from(scope.max_columns) {
                return Ok(());
            }
            (cy, pecks, columns)
        }
        _ => {
            check!(src, false, "G74/G75 step 5: refused exactly when the register refuses");
            return Ok(());
        }
    };
    // Follow the events: headers, and the pecks of each column.
    let c = (ep - ap).signum();
    let mut pos = a;
    let (mut headers, mut in_column, mut last_end) = (0i128, 0i128, ap);
    // Each column: header, to column, pecks and returns, relief, back; then home and the end.
    let most = columns * (2 * pecks + 4) + 2;
    let mut n = 0i128;
    while n < most {
        n += 1;
        let Some(ev) = cy.next_event(&mut pos) else { break };
        match ev {
            Event::Pass(_) => {
                check!(src, headers == 0 || in_column == pecks, "G74.PECK/G75.PECK: every column has ⌈depth / peck⌉ pecks");
                headers += 1;
                in_column = 0;
                last_end = ap;
            }
            Event::Move(mv) if mv.kind == MoveKind::Feed => {
                let (p, _) = if g75 { (i128::from(mv.x), i128::from(mv.z)) } else { (i128::from(mv.z), i128::from(mv.x)) };
                in_column += 1;
                let want = if in_column == pecks { ep } else { last_end + c * peck };
                check!(src, p == want, "G74.PECK/G75.PECK: each peck one peck further toward E, the last exactly at E");
                check!(src, c * (ep - p) >= 0 && c * (p - ap) > 0, "no peck passes E or stays at A");
                last_end = p;
            }
            Event::Move(_) => {}
            _ => check!(src, false, "G74/G75 neither dwell nor switch the spindle"),
        }
    }
    check!(src, in_column == pecks, "the last column has ⌈depth / peck⌉ pecks");
    check!(src, headers == columns, "G74.COLUMN/G75.COLUMN: ⌈travel / step⌉ + 1 columns, one header each");
    check!(src, cy.next_event(&mut pos).is_none(), "the cycle ends");
    check!(src, cy.next_event(&mut pos).is_none(), "and stays ended");
    check!(src, pos == a, "the cycle returns to A");
    cover!(src, columns > 1, "several columns");
    cover!(src, pecks > 1, "several pecks");
    cover!(src, g75, "G75");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = peck_counts in crate::PROPERTIES {
        rules: ["G74.FORMAT", "G74.PECK", "G74.E", "G74.COLUMN", "G75.FORMAT", "G75.PECK", "G75.COLUMN", "PRJ.MAXPASS"],
        states: "One G74/G75 cycle below the lexer: refused exactly in the register's order (no travel on the peck axis, no peck, a step travel without a step, then columns × pecks > max_passes) before any event; else ⌈travel/step⌉ + 1 columns with one header each, ⌈depth/peck⌉ pecks per column, each one peck further toward E, the last exactly at E, none past it; back at A.",
        body: |src, scope| body(src, &scope),
        /// The Kani harness that was run: still in symbolic execution after 720 s, so a TEST, a proof
        /// harness only with `kani-attempts`. Unwind 24: the event loop runs at most 2·(2·3 + 4) + 2 = 22
        /// times; `next_event` skips at most six phases per event.
        kani: test(KANI) { unwind: 24, why: "no verdict: Kani 0.61.0 / CBMC 6.4.0 (CaDiCaL), scope `KANI` (≤ 3 pecks × 2 columns, positions and lengths ±2^40), unwind 24 — still in symbolic execution at the 720 s timeout; a narrower trial (KANI edited to ≤ 2 pecks × 1 column, unwind 11; CaDiCaL 1.5.3): symbolic execution 550 s (2.7 M steps, 12 888 VCCs left), then CBMC out of memory converting to SAT (23.6 GB, killed by the kernel at 10 min 35 s wall, load 4–6) — the unwind bound also unrolls `next_event`'s inner loop in every call, and the per-peck functions (`nth`, `ceil_div`) are private to impl, so no lemma over them can be stated from this crate" },
        tests {
            /// Positions in ±2 and lengths in 0…2: every combination of both codes (600 000 cases) —
            /// every refusal, ties of the last peck and the last column, e and relief of every size
            /// against the peck, `max_passes` at its edges.
            fn peck_counts_exhaustive_small = exhaustive(3, 1_000_000) on Scope { max_pos: 2, max_pecks: 100, max_columns: 100 };
            fn peck_counts_random = random(0x5eed_0074, 2) on KANI, random(0x5eed_0075, 2) on Scope { max_pos: 2_000, max_pecks: 400, max_columns: 400 };
        }
    }
}
