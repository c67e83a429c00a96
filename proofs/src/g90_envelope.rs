//! Harness `g90_envelope` — G90.FORMAT, G90.TAPER, G90.PATH, G94.FORMAT, G94.TAPER, G94.PATH
//! (PRJ.NOOP, the pass header of docs/INTERPRETATION.md, "G90 and G94").
//!
//! **Property.** For G90 and G94, every start point A and end point D (each coordinate in
//! ±2^60, beyond every reachable position: words are ≤ N < 2^30 and a block moves at most 2N),
//! every taper I (K) with |I| ≤ N, every feed and every index within the run, one cycle of the
//! production expander (`cycle_impl::g90::cycle`, then `Cycle::next_event` until `None`):
//!
//! - is refused exactly as the register's step 5 says, in its order: G90: W = 0 is GEOMETRY on
//!   Z (G90.FORMAT), then I ≠ 0, U ≠ 0 of different signs with 2·|I| > |U| is GEOMETRY on I
//!   (G90.TAPER); G94: U = 0 is GEOMETRY on X (G94.FORMAT), then K ≠ 0, W ≠ 0 of different signs
//!   with |K| > |W| is GEOMETRY on K (G94.TAPER) — on the block's line, before any event;
//! - otherwise emits exactly one pass header first (index, kind ROUGH, rule G90.PATH / G94.PATH,
//!   depth the infeed of ①: G90 |A.x − C.x| on diameter, G94 2·|A.z − C.z|), then exactly the
//!   register's path ① rapid to C (C.x = D.x + 2I, or C.z = D.z + K), ② feed to D, ③ feed back
//!   to A.x (G90) / A.z (G94), ④ rapid to A — each move to the current position left out
//!   (PRJ.NOOP) — with the modal feed on ② ③ and the rule tags (① the taper rule when I ≠ 0);
//! - so every point of the cycle lies in the box spanned by A, D and C, and the tool ends at A;
//! - then nothing more (`None`, and `None` again).
//!
//! Expectations are computed here in `i128` from the register's text, independently of the
//! module. No loop of the production code depends on a value: `next_event` skips at most four
//! moves. **Kani bounds.** Everything symbolic over the ranges above; the harness loop reads at
//! most 6 events (header, four moves, the end): `#[kani::unwind(7)]`.

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::g90::{cycle, CutCode, CutState};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{AlarmCode, Event, MoveKind, PassKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |coordinate| of A and D.
    pub max_pos: i64,
    /// Largest |I| (|K|).
    pub max_taper: i64,
    /// Largest feed, pass index and line number (drawn from 1).
    pub max_other: u32,
}

/// What Kani proves.
pub const KANI: Scope = Scope { max_pos: 1 << 60, max_taper: MAX_LENGTH, max_other: u32::MAX };

/// One expected move: (x, z, rapid?, rule).
type Step = (i64, i64, bool, Rule);

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let g94 = src.bool();
    let a = (src.bounded_i64(-scope.max_pos, scope.max_pos), src.bounded_i64(-scope.max_pos, scope.max_pos));
    let d = (src.bounded_i64(-scope.max_pos, scope.max_pos), src.bounded_i64(-scope.max_pos, scope.max_pos));
    let taper = src.bounded_i64(-scope.max_taper, scope.max_taper);
    let feed = src.bounded_i64(1, MAX_LENGTH.min(i64::from(scope.max_other)));
    let index = src.bounded_u32(1, scope.max_other);
    let line = src.bounded_u32(1, scope.max_other);
    let code = if g94 { CutCode::G94 } else { CutCode::G90 };
    let st = CutState { end: d, taper, index };

    // The register, in i128.
    let (u, w, t) = (i128::from(d.0) - i128::from(a.0), i128::from(d.1) - i128::from(a.1), i128::from(taper));
    let (format, path, taper_rule) =
        if g94 { (Rule::G94Format, Rule::G94Path, Rule::G94Taper) } else { (Rule::G90Format, Rule::G90Path, Rule::G90Taper) };
    // (travel that must not be 0, the taper on the travel's scale, the travel it is limited by)
    let (no_travel, scaled, limit) = if g94 { (u == 0, t, w) } else { (w == 0, 2 * t, u) };
    let taper_bad = scaled != 0 && limit != 0 && (scaled < 0) != (limit < 0) && scaled.abs() > limit.abs();
    let expected_alarm = if no_travel {
        Some((if g94 { b'X' } else { b'Z' }, format))
    } else if taper_bad {
        Some((if g94 { b'K' } else { b'I' }, taper_rule))
    } else {
        None
    };

    let result = cycle(code, &st, a, feed, line);
    let mut cy = match (result, expected_alarm) {
        (Err(al), Some((word, rule))) => {
            check!(
                src,
                al.code == AlarmCode::Geometry && al.word == Some(word) && al.rule == rule && al.line == line,
                "G90.FORMAT/G90.TAPER, G94.FORMAT/G94.TAPER: the register's GEOMETRY alarm, in its order"
            );
            cover!(src, rule == format, "refused: no travel");
            cover!(src, rule == taper_rule, "refused: the taper");
            return Ok(());
        }
        (Ok(cy), None) => cy,
        _ => {
            check!(src, false, "G90/G94 step 5: refused exactly when the register refuses");
            return Ok(());
        }
    };

    // C, the cut start, and the path ①–④.
    let c: (i128, i128) =
        if g94 { (i128::from(a.0), i128::from(d.1) + t) } else { (i128::from(d.0) + 2 * t, i128::from(a.1)) };
    let (ai, di) = ((i128::from(a.0), i128::from(a.1)), (i128::from(d.0), i128::from(d.1)));
    let back = if g94 { (di.0, ai.1) } else { (ai.0, di.1) };
    let depth = if g94 { 2 * (ai.1 - c.1).abs() } else { (ai.0 - c.0).abs() };
    let first_rule = if taper != 0 { taper_rule } else { path };
    let steps: [(i128, i128, bool, Rule); 4] =
        [(c.0, c.1, true, first_rule), (di.0, di.1, false, path), (back.0, back.1, false, path), (ai.0, ai.1, true, path)];

    let mut pos = a;
    let header = cy.next_event(&mut pos);
    check!(
        src,
        matches!(header, Some(Event::Pass(p)) if p.index == index && p.kind == PassKind::Rough && p.rule == path
            && i128::from(p.diameter_depth) == depth),
        "G90/G94 pass header: one ROUGH pass, its index, the path rule, the infeed of ① as its depth"
    );
    check!(src, pos == a, "the header does not move the tool");

    // The box spanned by A, D and C.
    let lo = (ai.0.min(di.0).min(c.0), ai.1.min(di.1).min(c.1));
    let hi = (ai.0.max(di.0).max(c.0), ai.1.max(di.1).max(c.1));
    let mut at: (i128, i128) = ai;
    let mut k = 0usize;
    let mut moves = 0u32;
    // The expected moves, in order, each left out when it goes nowhere (PRJ.NOOP).
    while k < 4 {
        let (x, z, rapid, rule) = steps[k];
        k += 1;
        if (x, z) == at {
            continue;
        }
        at = (x, z);
        let e = cy.next_event(&mut pos);
        let want: Option<Step> = Some((x as i64, z as i64, rapid, rule));
        let got: Option<Step> = match e {
            Some(Event::Move(m)) => {
                let feed_ok = if rapid { m.kind == MoveKind::Rapid } else { m.kind == MoveKind::Feed && m.feed == feed };
                check!(src, feed_ok, "G90.PATH/G94.PATH: ① ④ rapid, ② ③ at the modal feed");
                Some((m.x, m.z, m.kind == MoveKind::Rapid, m.rule))
            }
            _ => None,
        };
        check!(src, got == want, "G90.PATH/G94.PATH: the register's moves ①–④ in order, none to the current position");
        check!(
            src,
            lo.0 <= i128::from(pos.0) && i128::from(pos.0) <= hi.0 && lo.1 <= i128::from(pos.1) && i128::from(pos.1) <= hi.1,
            "every point of the cycle lies in the box spanned by A, D and C"
        );
        moves += 1;
    }
    check!(src, cy.next_event(&mut pos).is_none(), "nothing after ④");
    check!(src, cy.next_event(&mut pos).is_none(), "nothing after the end");
    check!(src, pos == a, "the cycle returns to A");

    cover!(src, moves == 4, "all four moves");
    cover!(src, moves < 4, "a move left out (PRJ.NOOP)");
    cover!(src, taper != 0 && limit != 0 && (scaled < 0) != (limit < 0), "a taper against the travel, accepted");
    cover!(src, g94, "G94");
    cover!(src, !g94, "G90");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = g90_envelope in crate::PROPERTIES {
        rules: ["G90.FORMAT", "G90.TAPER", "G90.PATH", "G94.FORMAT", "G94.TAPER", "G94.PATH", "PRJ.NOOP"],
        states: "One G90/G94 cycle: refused exactly by the register's step 5 in its order, else one ROUGH pass header (index, depth = the infeed of ①) then exactly the moves ①–④ (none to the current position), every point in the box of A, D and C, back at A.",
        body: |src, scope| body(src, &scope),
        /// Kani: one G90/G94 cycle over the ranges of [`KANI`]. Unwind 7: the harness reads at most
        /// six events; `next_event` skips at most four moves.
        kani: proof(KANI) { unwind: 7, measured: "SUCCESSFUL (465 checks, 1 unreachable; 7/7 covers), 200.4 s, 1.28 GB" },
        tests {
            /// Coordinates in ±3, tapers in ±3: every combination (both codes), so every
            /// coincidence of A, C and D (the left-out moves) and every taper sign.
            fn g90_envelope_exhaustive_small = exhaustive(4, 2_000_000) on Scope { max_pos: 3, max_taper: 3, max_other: 1 };
            /// The edges of the ranges.
            fn g90_envelope_exhaustive_edges = exhaustive(2, 1_000_000) on KANI;
            fn g90_envelope_random = random(0x5eed_0090, 2) on KANI, random(0x5eed_0091, 2) on Scope { max_pos: 40, max_taper: 25, max_other: 1000 };
        }
    }
}
