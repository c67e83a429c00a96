//! TEST `g92_pullout_total` (driver-only: not a Kani proof) — G92.JK.1, G92.JK.2, G92.JK.3, G92.JK.4, G92.JK.5, G92.JK.6,
//! G92.JK.7 (with G92.PULLOUT, G92.TAPER, COM.LONGAXIS).
//!
//! **Property.** The G92 pull-out is a total function of J and K. For every combination of
//! J ∈ {absent, 0, positive, negative} and K ∈ {absent, 0, positive, negative}, any No.19
//! (0…255), lead, grid, start point, straight or tapered thread with Z or X as the long axis,
//! the production expander's trace of `G92 U W R F [J] [K]` has exactly the pull-out that the
//! register's table gives (docs/INTERPRETATION.md, "G92.JK.* as one function"), computed here
//! independently:
//!
//! | J \ K | absent | 0 | K ≠ 0 |
//! |---|---|---|---|
//! | absent | (c, c) JK.1 | (c, c) JK.2 read as JK.5 | (c, \|K\|) JK.2 |
//! | 0 | none JK.4 | none JK.4 | none JK.6 |
//! | J ≠ 0 | (\|J\|, \|J\|) JK.3 | (\|J\|, \|J\|) JK.5 | (\|J\|, \|K\|) |
//!
//! with c = round(No.19 × lead / 10) on the length grid and |·| by G92.JK.7; a resolved amount
//! of 0 means no pull-out. "Exactly" means: the thread moves of the trace are C → D when there
//! is no pull-out, else C → pull-out start → pull-out end with the G92.PULLOUT geometry
//! (Z long: start K before D.z on the thread line, end at D.z and D.x + s·J; X long: start at
//! D.x + sign(R)·K, end at D.x and D.z − sign(W)·J), the pull-out move naming G92.PULLOUT; a
//! K not below the long-axis travel is `GEOMETRY` on K (G92.PULLOUT) and an illegal taper
//! `GEOMETRY` on R (G92.TAPER), and an X where step ③ starts (the pull-out's end, else D.x)
//! beyond A.x `GEOMETRY` on J (on X when D.x itself is beyond; G92.PATH, step ③ opposite to ①,
//! the last check), before any motion. The pass header and the return to A are checked too.
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 ran out of memory in symbolic execution (issue #25): the symbolic program text unrolls the lexer's loops. Its parts below the lexer (the J/K table, the pull-out geometry, the No.19 amount) are the Kani harness `g92_pullout_geometry`. The body runs under `cargo test` (bounded-exhaustive and random
//! drivers); its Kani harness (the scope named `KANI` below) is a proof harness only with the
//! feature `kani-attempts`.
//!
//! **Kani bounds of the attempt** ([`KANI`]): lengths ≤ 9 increments, lead ≤ 99 counts; No.19, grid, start
//! point and the J/K cases fully symbolic. The program is ≤ 57 bytes; the event loop ≤ 8.
//! `#[kani::unwind(60)]` covers the lexer's byte loops (≤ 58) and everything else (digit loops
//! ≤ 20, the configuration check 15; no square roots on this path).

use crate::model::div_round_half_up;
use crate::program::Program;
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::Expander;
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{AlarmCode, Config, Event, MoveKind, Params, PassKind, Rule};

use crate::expander_envelope::{max_f, GRIDS};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    pub max_start: i64,
    /// Largest length word (W, R, thread depth, J, K), increments.
    pub max_len: i64,
    /// Largest lead, lead counts.
    pub max_lead: i64,
    pub max_program: usize,
}

/// What Kani proves.
pub const KANI: Scope = Scope { max_start: MAX_LENGTH, max_len: 9, max_lead: 99, max_program: 57 };

/// A J or K word as written: absent, or a signed value.
fn jk_word<S: Source>(src: &mut S, len: i64) -> Option<i64> {
    match src.choose(4) {
        0 => None,
        1 => Some(0),
        2 => Some(src.bounded_i64(1, len)),
        _ => Some(-src.bounded_i64(1, len)),
    }
}

/// The register's table (G92.JK.1–7): the resolved (J, K), `None` for no pull-out.
pub fn table(j: Option<i64>, k: Option<i64>, c: i64) -> Option<(i64, i64)> {
    let (j, k) = (j.map(i64::abs), k.map(i64::abs)); // G92.JK.7
    let (rj, rk) = match (j, k) {
        (None, None) => (c, c),                // JK.1
        (None, Some(0)) => (c, c),             // JK.2, K = 0 read as JK.5
        (None, Some(k)) => (c, k),             // JK.2
        (Some(0), _) => return None,           // JK.4, JK.6
        (Some(j), None) => (j, j),             // JK.3
        (Some(j), Some(0)) => (j, j),          // JK.5
        (Some(j), Some(k)) => (j, k),
    };
    (rj != 0 && rk != 0).then_some((rj, rk))
}

/// `v / d` rounded half away from zero (d > 0).
fn div_round_signed(v: i64, d: i64) -> i64 {
    let m = div_round_half_up(u128::from(v.unsigned_abs()), u128::from(d.unsigned_abs())) as i64;
    if v < 0 { -m } else { m }
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let grid = GRIDS[src.choose(4) as usize];
    let dec = grid.decimals();
    let no19 = src.bounded_u32(0, 255);
    let lead = src.bounded_i64(1, scope.max_lead.min(max_f(grid.units)));
    let ax = src.bounded_i64(-scope.max_start, scope.max_start);
    let az = src.bounded_i64(-scope.max_start, scope.max_start);
    let len = scope.max_len;

    // Long axis and taper: Z long (|R| < |W|) or X long (R ≠ 0, |W| ≤ |R|).
    let z_long = src.bool();
    let (w_mag, r) = if z_long {
        let w_mag = src.bounded_i64(1, len);
        (w_mag, src.bounded_i64(-(w_mag - 1), w_mag - 1))
    } else {
        let r_mag = src.bounded_i64(1, len);
        let r = if src.bool() { r_mag } else { -r_mag };
        (src.bounded_i64(1, r_mag), r)
    };
    let w = if src.bool() { w_mag } else { -w_mag };
    // Side and infeed: A.x = C.x + s·2·depth, C.x = D.x + 2R.
    let s: i64 = if src.bool() { 1 } else { -1 };
    let depth = src.bounded_i64(1, len);
    let u = -2 * r - 2 * s * depth;
    let j = jk_word(src, len);
    let k = jk_word(src, len);

    let mut prog = Program::new();
    prog.text(b"G92");
    prog.len_word(b'U', u, dec);
    prog.len_word(b'W', w, dec);
    prog.len_word(b'R', r, dec);
    prog.len_word(b'F', lead, grid.lead_decimals());
    if let Some(j) = j {
        prog.len_word(b'J', j, dec);
    }
    if let Some(k) = k {
        prog.len_word(b'K', k, dec);
    }
    prog.end_block();
    src.note_program(prog.bytes());
    check!(src, !prog.overflowed() && prog.len() <= scope.max_program, "the program fits the scope's buffer bound");

    let params = Params { no19_pullout: Some(i64::from(no19)), ..Params::default() };
    let config = Config { grid, params, start_x: ax, start_z: az, ..Config::default() };

    // Expected, from the words alone.
    let (dx, dz) = (ax + u, az + w);
    let cx = dx + 2 * r;
    let c = div_round_half_up(u128::from(no19) * lead as u128, 10 * grid.lead_counts_per_increment() as u128) as i64;
    let amounts = table(j, k, c);
    // G92.TAPER: R ≠ 0, U ≠ 0 of different signs need 2|R| ≤ |U|.
    let taper_bad = r != 0 && u != 0 && (r < 0) != (u < 0) && 2 * r.abs() > u.abs();
    let travel = if z_long { w_mag } else { r.abs() };
    let k_bad = amounts.is_some_and(|(_, rk)| rk >= travel);
    let sz = w.signum();
    // G92.PATH step ③ (DEPARTS): X₃ = the pull-out's end X (Z long) or D.x must not lie beyond A.x.
    let x3 = match amounts {
        Some((rj, _)) if z_long => dx + 2 * s * rj,
        _ => dx,
    };
    let step3_bad = s * (ax - x3) < 0;
    let step3_word = if s * (ax - dx) < 0 { b'X' } else { b'J' };
    let expected_threads: [Option<(i64, i64)>; 2] = match amounts {
        None => [Some((dx, dz)), None],
        Some((rj, rk)) if z_long => {
            let start = (dx + 2 * div_round_signed(r * rk, w_mag), dz - sz * rk);
            [Some(start), Some((dx + 2 * s * rj, dz))]
        }
        Some((rj, rk)) => {
            let start = (dx + 2 * r.signum() * rk, dz - sz * div_round_signed(w_mag * rk, r.abs()));
            [Some(start), Some((dx, dz - sz * rj))]
        }
    };

    // The trace: a header and at most five moves, or an alarm.
    let mut it = Expander::new(prog.bytes(), config);
    let mut threads = 0usize;
    let mut pos = (ax, az);
    let mut first_event = true;
    let mut ended = false;
    for _ in 0..8 {
        match it.next() {
            None => {
                ended = true;
                break;
            }
            Some(Err(a)) => {
                if taper_bad {
                    check!(src, a.code == AlarmCode::Geometry && a.word == Some(b'R') && a.rule == Rule::G92Taper, "G92.TAPER: an illegal taper is GEOMETRY on R");
                } else if k_bad {
                    check!(src, a.code == AlarmCode::Geometry && a.word == Some(b'K') && a.rule == Rule::G92Pullout, "G92.PULLOUT: K not below the long-axis travel is GEOMETRY on K");
                } else {
                    check!(src, step3_bad, "only the expected alarms occur");
                    check!(src, a.code == AlarmCode::Geometry && a.word == Some(step3_word) && a.rule == Rule::G92Path, "G92.PATH: step ③ starting beyond A.x is GEOMETRY on J (X)");
                }
                check!(src, first_event, "the alarm comes before any motion");
                check!(src, it.next().is_none(), "the alarm ends the trace");
                cover!(src, k_bad && !taper_bad, "K beyond the travel");
                cover!(src, step3_bad && !k_bad && !taper_bad, "step ③ from beyond A.x");
                ended = true;
                break;
            }
            Some(Ok(Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_))) => {
                check!(src, false, "PRJ.TRACE: no dwell or spindle event in these cycles");
            }
            Some(Ok(Event::Pass(p))) => {
                check!(src, first_event && p.index == 1 && p.kind == PassKind::Rough && p.diameter_depth == 2 * depth, "G92 pass header: index 1, ROUGH, depth |A.x − C.x|");
            }
            Some(Ok(Event::Move(m))) => {
                if m.kind == MoveKind::Thread {
                    let want = expected_threads.get(threads).copied().flatten();
                    check!(src, want == Some((m.x, m.z)), "G92.JK.1–7, G92.PULLOUT: the thread moves are C → D, or C → pull-out start → pull-out end with the table's J and K");
                    let rule = if threads == 1 { Rule::G92Pullout } else { Rule::G92Path };
                    check!(src, m.rule == rule && m.feed == lead, "the cut names G92.PATH, the pull-out G92.PULLOUT, both with the lead");
                    threads += 1;
                } else {
                    check!(src, m.kind == MoveKind::Rapid, "G92.PATH: only rapids besides the thread");
                    if threads == 0 {
                        check!(src, (m.x, m.z) == (cx, az), "G92.PATH ①: rapid X to the cutting start");
                    }
                }
                pos = (m.x, m.z);
            }
        }
        first_event = false;
    }
    check!(src, ended, "the G92 trace ends within eight events");
    if !(taper_bad || k_bad || step3_bad) {
        let want = if amounts.is_some() { 2 } else { 1 };
        check!(src, threads == want, "a pull-out is two thread moves, no pull-out one");
        check!(src, pos == (ax, az), "G92.PATH ④: back at the start point");
    }

    cover!(src, j.is_none() && k.is_none() && amounts.is_some() && !k_bad, "JK.1 pull-out by No.19");
    cover!(src, j.is_none() && k.is_some_and(|k| k != 0) && amounts.is_some() && !k_bad, "JK.2");
    cover!(src, j.is_some_and(|j| j != 0) && k.is_none() && !k_bad, "JK.3");
    cover!(src, j == Some(0), "JK.4 / JK.6");
    cover!(src, j.is_some_and(|j| j != 0) && k == Some(0) && !k_bad, "JK.5");
    cover!(src, j.is_some_and(|j| j < 0) && k.is_some_and(|k| k < 0) && !k_bad && !taper_bad, "JK.7 negatives");
    cover!(src, amounts.is_none() && !taper_bad, "no pull-out");
    cover!(src, !z_long && amounts.is_some() && !k_bad && !taper_bad, "X-long pull-out");
    cover!(src, taper_bad, "illegal taper");
    cover!(src, amounts.is_some() && !(taper_bad || k_bad || step3_bad), "a pull-out run to its end");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = g92_pullout_total in crate::PROPERTIES {
        rules: ["G92.JK.1", "G92.JK.2", "G92.JK.3", "G92.JK.4", "G92.JK.5", "G92.JK.6", "G92.JK.7", "G92.PULLOUT", "G92.TAPER", "COM.LONGAXIS"],
        states: "A whole G92 expansion: the thread moves are C → D or C → pull-out start → pull-out end with the register's J/K table and geometry; K ≥ travel and an illegal taper refused before any motion.",
        body: |src, scope| body(src, &scope),
        /// The Kani attempt (a TEST: out of memory; a harness only with `kani-attempts`).
        kani: test(KANI) { unwind: 60, why: "out of memory in symbolic execution (lexer loops)" },
        tests {
            /// Every J/K case, every grid, every long-axis/side/sign combination; lengths ≤ 3, No.19 and
            /// the lead at their extremes (0, 1, 2, 253…255; 1…3).
            fn g92_pullout_total_exhaustive = exhaustive(3, 3_000_000) on Scope { max_start: 0, max_len: 3, max_lead: 3, max_program: 57 };
            /// The Kani scope, sampled.
            fn g92_pullout_total_random_kani_scope = random(0x5eed_0007, 4) on KANI;
            /// Legal J, K (≤ 99 999 999) and lengths, leads to 9999 mm.
            fn g92_pullout_total_random = random(0x5eed_0008, 4) on Scope { max_start: MAX_LENGTH, max_len: 99_999_999, max_lead: 99_990_000, max_program: 128 };
        }
    }
}

#[cfg(test)]
mod tests;
