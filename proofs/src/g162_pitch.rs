//! TEST `g162_variable_pitch` (driver-only: not a Kani proof) — G162.I, G162.J, G162.F (with G162.PQ, G162.SPLIT, G162.PATH,
//! PRJ.TRACE).
//!
//! **Property.** For a G162 block `G162 X Z H [P Q] F I [J]` under `nc201` with any F (1…Fmax),
//! any pitch change I (−Fmax…Fmax), any J (absent or 0.001…999 999.999°), any grid, external
//! or internal, any start point, the production expander's trace
//!
//! - either is `GEOMETRY` on I (G162.I) before any motion — exactly when I > 0 and the lead
//!   would pass the F maximum within the thread (s = Z travel in lead counts), decided here in
//!   integers by the declared reading g162.lead (both drawn): `continuous`, the lead at the end
//!   L² = F² + 720 000·I·s/J: J·F² + 720 000·I·s > J·Fmax²; `steps` (the letter), the first
//!   step above Fmax, k* = ⌊(Fmax − F)/I⌋ + 1, starts before the end:
//!   (2·k*·F + I·k*·(k* − 1))·J < 720 000·s;
//! - or its thread moves all have lead F ≥ 1 and the register's variable lead: I = 0, or I < 0
//!   with F ≤ |I|: the constant form (change, angle, floor all 0); I < 0 with F > |I|: change I
//!   over J (360 000 when omitted) and floor |I| ≥ 1 < F — so the shrinking lead starts above
//!   its floor and stops there: **it never reaches ≤ 0**; I > 0: change I over J, no floor, the
//!   end lead within the F range (above); `lead_steps` exactly when the lead changes under
//!   `steps`;
//! - and the pass headers' depths strictly increase, never pass P, end exactly at P (0 for a
//!   single pass); each thread cuts at X0 − 2s·depth to Ze; the tool ends at the start point.
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 ran out of memory in symbolic execution (issue #25): the symbolic program text unrolls the lexer's loops. The body runs under `cargo test` (bounded-exhaustive and random
//! drivers); its Kani harness (the scope named `KANI` below) is a proof harness only with the
//! feature `kani-attempts`.
//!
//! **Kani bounds of the attempt** ([`KANI`]): lengths (thread gap, Z travel, P, Q) ≤ 9 increments, H ≤ 99
//! counts; F, I, J, the grid, the side and the start point (within ±(N − 100)) symbolic over
//! their full ranges. At most 13 passes (P/Q ≤ 9, plus four split passes), so ≤ 1 + 13·6 events:
//! the event loop runs ≤ 80 times. The program is ≤ 110 bytes (checked): `#[kani::unwind(112)]`
//! covers the lexer's byte loops, the event loop, digit loops ≤ 20 and the configuration check.

use crate::expander_envelope::{max_f, GRIDS};
use crate::g162_split::model;
use crate::program::Program;
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::Expander;
use cycle_impl::MAX_LENGTH;
use cycle_vocab::readings::G162Lead;
use cycle_vocab::{AlarmCode, Config, Dialect, Event, MoveKind, Rule};

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |start X|, |start Z|.
    pub max_start: i64,
    /// Largest gap to the thread, P and Q, increments (≤ 9 keeps ≤ 13 passes).
    pub max_len: i64,
    /// Largest Z travel, increments.
    pub max_travel: i64,
    /// Largest F and |I| (capped at Fmax), lead counts.
    pub max_lead: i64,
    pub max_program: usize,
}

/// What Kani proves.
pub const KANI: Scope =
    Scope { max_start: MAX_LENGTH - 100, max_len: 9, max_travel: 9, max_lead: i64::MAX, max_program: 110 };

/// The most events a trace of the scope has: a rapid-free cycle of ≤ 13 passes × (header + 5).
const EVENT_BOUND: usize = 80;

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let grid = GRIDS[src.choose(4) as usize];
    let dec = grid.decimals();
    let fmax = max_f(grid.units);
    let sx = src.bounded_i64(-scope.max_start, scope.max_start);
    let sz = src.bounded_i64(-scope.max_start, scope.max_start);
    let s: i64 = if src.bool() { 1 } else { -1 };
    let gap = src.bounded_i64(1, scope.max_len);
    let x0 = sx - 2 * s * gap;
    let dz: i64 = if src.bool() { 1 } else { -1 };
    let travel = src.bounded_i64(1, scope.max_travel);
    let ze = sz + dz * travel;
    let h = src.bounded_i64(1, 99);
    let split =
        if src.bool() { Some((src.bounded_i64(1, scope.max_len), src.bounded_i64(1, scope.max_len))) } else { None };
    let max_lead = scope.max_lead.min(fmax);
    let f = src.bounded_i64(1, max_lead);
    // I: 0, a magnitude below F, or one at or above F (together: every I), either sign.
    let i_sign = if src.bool() { 1 } else { -1 };
    let i = match src.choose(3) {
        0 => 0,
        1 => {
            src.assume(f >= 2)?;
            i_sign * src.bounded_i64(1, f - 1)
        }
        _ => i_sign * src.bounded_i64(f, max_lead),
    };
    let j = if src.bool() { Some(src.bounded_i64(1, 999_999_999)) } else { None };
    let stepped = src.bool();

    let mut prog = Program::new();
    prog.text(b"G162");
    prog.len_word(b'X', x0, dec);
    prog.len_word(b'Z', ze, dec);
    prog.len_word(b'H', h, grid.lead_decimals());
    if let Some((p, q)) = split {
        prog.len_word(b'P', p, dec);
        prog.len_word(b'Q', q, dec);
    }
    prog.len_word(b'F', f, grid.lead_decimals());
    prog.len_word(b'I', i, grid.lead_decimals());
    if let Some(j) = j {
        prog.len_word(b'J', j, 3);
    }
    prog.end_block();
    src.note_program(prog.bytes());
    check!(src, !prog.overflowed() && prog.len() <= scope.max_program, "the program fits the scope's buffer bound");
    let mut config = Config { dialect: Dialect::Nc201, grid, start_x: sx, start_z: sz, ..Config::default() };
    config.readings.g162_lead = if stepped { G162Lead::Steps } else { G162Lead::Continuous };

    // Expected, from the words alone.
    let jj = j.unwrap_or(360_000);
    let s_lead = i128::from(travel) * i128::from(grid.lead_counts_per_increment());
    let too_fast = i > 0
        && if stepped {
            let (f, ii) = (i128::from(f), i128::from(i));
            let k = (i128::from(fmax) - f) / ii + 1;
            (2 * k * f + ii * k * (k - 1)) * i128::from(jj) < 720_000 * s_lead
        } else {
            i128::from(jj) * i128::from(f) * i128::from(f) + 720_000 * i128::from(i) * s_lead
                > i128::from(jj) * i128::from(fmax) * i128::from(fmax)
        };
    let constant = i == 0 || (i < 0 && f <= -i);
    let depths_model = split.map(|(p, q)| model::split(p, q));
    let final_depth = split.map_or(0, |(p, _)| p);

    let mut it = Expander::new(prog.bytes(), config);
    let mut first_event = true;
    let mut ended = false;
    let mut previous_depth: Option<i64> = None;
    let mut depth = 0i64;
    let mut passes = 0usize;
    let mut threads = 0usize;
    let mut pos = (sx, sz);
    for _ in 0..EVENT_BOUND + 1 {
        match it.next() {
            None => {
                ended = true;
                break;
            }
            Some(Err(a)) => {
                check!(src, too_fast, "only the growing-pitch bound may refuse these programs");
                check!(
                    src,
                    a.code == AlarmCode::Geometry && a.word == Some(b'I') && a.rule == Rule::G162I,
                    "G162.I: a growing pitch past the F range is GEOMETRY on I"
                );
                check!(src, first_event, "the alarm comes before any motion");
                check!(src, it.next().is_none(), "the alarm ends the trace");
                ended = true;
                break;
            }
            Some(Ok(Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_))) => {
                check!(src, false, "PRJ.TRACE: no dwell or spindle event in these cycles");
            }
            Some(Ok(Event::Pass(p))) => {
                check!(src, p.diameter_depth % 2 == 0, "pass depths are radius counts");
                depth = p.diameter_depth / 2;
                let increasing = previous_depth.is_none_or(|d| depth > d);
                check!(src, increasing && depth <= final_depth, "depths strictly increase and never pass P");
                if let Some(m) = &depths_model {
                    let k = m.k as usize;
                    let want = if passes < k {
                        Some((passes as i64 + 1) * split.map_or(0, |sp| sp.1))
                    } else {
                        m.tail.get(passes - k).map(|t| t.0)
                    };
                    check!(src, want == Some(depth), "G162.PQ / G162.SPLIT: the depths are the register's split");
                }
                previous_depth = Some(depth);
                passes += 1;
            }
            Some(Ok(Event::Move(m))) => {
                if m.kind == MoveKind::Thread {
                    check!(src, !too_fast, "a refused pitch emits no thread");
                    check!(
                        src,
                        (m.x, m.z) == (x0 - 2 * s * depth, ze),
                        "G162.PATH ②: the thread cuts at X0 − 2s·depth to Ze"
                    );
                    check!(src, m.feed == f && m.feed >= 1, "G162.F: the thread starts at the lead F");
                    check!(src, m.lead_steps == (stepped && !constant), "g162.lead: steps exactly when stepped and changing");
                    if constant {
                        check!(
                            src,
                            m.lead_change == 0 && m.lead_change_angle == 0 && m.lead_floor == 0,
                            "G162.I: I = 0, or F ≤ |I| shrinking, is a constant lead"
                        );
                    } else if i < 0 {
                        check!(
                            src,
                            m.lead_change == i && i64::from(m.lead_change_angle) == jj,
                            "G162.I, G162.J: the change I over J"
                        );
                        check!(
                            src,
                            m.lead_floor == -i && m.lead_floor >= 1 && m.lead_floor < m.feed,
                            "G162.I: a shrinking pitch starts above its floor |I| ≥ 1 and stops there: never ≤ 0"
                        );
                    } else {
                        check!(
                            src,
                            m.lead_change == i && i64::from(m.lead_change_angle) == jj && m.lead_floor == 0,
                            "G162.I, G162.J: a growing pitch, change I over J, no floor"
                        );
                    }
                    threads += 1;
                } else {
                    check!(src, m.kind == MoveKind::Feed && m.feed == h, "G162.H: every other move is a feed at H");
                }
                pos = (m.x, m.z);
            }
        }
        first_event = false;
    }
    check!(src, ended, "the trace ends within the event bound");
    if !too_fast {
        let want = depths_model.map_or(1, |m| m.k as usize + m.count);
        check!(src, passes == want && threads == want, "one pass header and one thread per pass");
        check!(src, depth == final_depth, "the last pass is at P (0 for a single pass)");
        check!(src, pos == (sx, sz), "G162.PATH ⑤: back at the start point");
    }

    cover!(src, too_fast, "growing pitch refused");
    cover!(src, too_fast && stepped, "growing stepped pitch refused");
    cover!(src, i > 0 && !too_fast && stepped, "growing stepped pitch");
    cover!(src, i > 0 && !too_fast, "growing pitch");
    cover!(src, i < 0 && !constant, "shrinking pitch with a floor");
    cover!(src, i < 0 && constant, "shrinking pitch already at its floor");
    cover!(src, split.is_none(), "single pass");
    cover!(src, depths_model.is_some_and(|m| m.count >= 1), "split passes");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = g162_variable_pitch in crate::PROPERTIES {
        rules: ["G162.I", "G162.J", "G162.F", "G162.PQ", "G162.SPLIT", "G162.PATH", "G162.H", "PRJ.TRACE"],
        states: "A whole G162 expansion under nc201: GEOMETRY on I exactly when the end lead leaves the F range, else the register's variable lead (the shrinking pitch never reaches ≤ 0) and depths strictly increasing to exactly P.",
        body: |src, scope| body(src, &scope),
        /// The Kani attempt (a TEST: out of memory; a harness only with `kani-attempts`).
        kani: test(KANI) { unwind: 112, why: "out of memory in symbolic execution (lexer loops)" },
        tests {
            /// Every choice (grid, side, direction, split or not, J or not) with the edges of every
            /// range: F and |I| at 1 and Fmax, J at 0.001° and 999 999.999°, lengths 1 and 3.
            fn g162_variable_pitch_exhaustive = exhaustive(1, 3_000_000) on Scope { max_start: 50, max_len: 3, max_travel: 3, max_lead: i64::MAX, max_program: 110 };
            fn g162_variable_pitch_random_kani_scope = random(0x5eed_0163, 8) on KANI;
            /// Longer threads (up to 200 mm at ISB) so that moderate growth is accepted and refused.
            fn g162_variable_pitch_random_long = random(0x5eed_0164, 8) on Scope { max_start: 1_000_000, max_len: 9, max_travel: 200_000, max_lead: 50_000, max_program: 110 };
        }
    }
}
