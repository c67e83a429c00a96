//! Harness `trace_depths`: the depth properties of `depth_step_monotone` and `depth_bounds`,
//! checked on the production expander's *trace* rather than on its schedule API: a G76/G78
//! program is written from drawn values, expanded by `cycle_impl::Expander` alone, and its pass
//! headers and moves are checked against the values the program was written from.
//!
//! Properties, for a trace that ends without an alarm:
//! - rough depths never decrease, and strictly increase when Δdmin ≥ 1 increment or the
//!   schedule is constant (G76.DEPTH.1, G76.DEPTH.MIN, G78.DEPTHMODE);
//! - every cut but the last rough one is ≥ Δdmin (degressive) or exactly Δd (constant);
//! - the last rough depth is k − d (G76.DEPTH.LAST); m finishing passes follow at depth k, the
//!   first FINISH, the rest SPRING (G76.FINISH);
//! - passes × starts ≤ `max_passes`, the impl's default (PRJ.MAXPASS);
//! - thread moves carry the programmed lead (COM.LEAD), and the tool ends at A (G76.PATH).
//!
//! The drawn programs are legal by construction (the shape of `tests/properties.rs`: A outside
//! the crest by a clearance, d < k, K within the Z travel), so an alarm is only acceptable as
//! TOO MANY PASSES, raised before any motion of the cycle (PRJ.MAXPASS).
//!
//! No Kani wrapper (whole G76/G78 expansions of up to thousands of passes): it runs under the
//! `impl_invariants` fuzz target ([`crate::invariants`]) and the replay of its seeds and
//! regressions.

use crate::expander_envelope::{max_f, GRIDS};
use crate::program::Program;
use crate::source::{Outcome, Source};
use cycle_impl::config::DEFAULTS;
use cycle_impl::{Expander, MAX_LENGTH};
use cycle_vocab::{AlarmCode, Config, Event, Move, MoveKind, PassKind};

/// The harness body: draws, writes, expands, checks (see the module documentation).
pub fn body<S: Source>(src: &mut S) -> Outcome {
    let grid = GRIDS[src.choose(4) as usize];
    let dec = grid.decimals();
    let g78 = src.bool();
    let m = src.bounded_u32(1, 99);
    let angle = src.bounded_u32(0, 99);
    let mode = if g78 { src.every_u32(0, 4) } else { src.every_u32(0, 2) };
    let degressive = !g78 || src.bool();
    let k = src.bounded_i64(1, MAX_LENGTH / 8);
    let d = src.bounded_i64(0, k - 1);
    let dd = src.bounded_i64(1, MAX_LENGTH / 8);
    let dmin = src.bounded_i64(0, dd);
    let w = src.bounded_i64(1, MAX_LENGTH / 8);
    let taper = src.bounded_i64(-3, 3) * (w / 8).max(1);
    let internal = src.bool();
    let clearance = src.bounded_i64(1, 1_000_000);
    let end_x = src.bounded_i64(1, MAX_LENGTH / 4) + 2 * k + 2 * taper.abs() + 2;
    let jk = if src.bool() { Some((src.bounded_i64(1, 2_000_000), src.bounded_i64(1, 2_000_000).min(w))) } else { None };
    let lead = src.bounded_i64(1, max_f(grid.units));
    let starts = src.bounded_u32(1, 4);
    let e = src.bounded_i64(0, 5_000);

    // A: outside the crest by the clearance (external), or inside it (internal).
    let crest_x = end_x + 2 * taper + if internal { -2 * k } else { 2 * k };
    let ax = if internal { crest_x - 2 * clearance } else { crest_x + 2 * clearance };
    let az = 5 * 10i64.pow(dec);
    src.assume(ax.abs() <= MAX_LENGTH && end_x <= MAX_LENGTH)?; // COM.RANGES on the words

    let code = if g78 { 78 } else { 76 };
    let middle = if g78 { mode } else { 0 };
    let d_word = if g78 { u32::from(degressive) } else { mode };
    let mut prog = Program::new();
    prog.text(b"G00 ");
    prog.len_word(b'X', ax, dec);
    prog.byte(b' ');
    prog.len_word(b'Z', az, dec);
    prog.end_block();
    prog.int_word(b'G', code);
    prog.byte(b' ');
    prog.six_digits(b'P', m, middle, angle);
    for (letter, v) in [(b'Q', dmin), (b'R', d)] {
        prog.byte(b' ');
        prog.len_word(letter, v, dec);
    }
    prog.byte(b' ');
    prog.int_word(b'D', i64::from(d_word));
    prog.byte(b' ');
    prog.int_word(b'L', i64::from(starts));
    prog.byte(b' ');
    prog.len_word(b'E', e, dec);
    prog.end_block();
    prog.int_word(b'G', code);
    for (letter, v) in [(b'X', end_x), (b'W', -w - 1), (b'R', taper), (b'P', k), (b'Q', dd)] {
        prog.byte(b' ');
        prog.len_word(letter, v, dec);
    }
    prog.byte(b' ');
    prog.len_word(b'F', lead, grid.lead_decimals());
    match jk {
        Some((j, kk)) => {
            prog.byte(b' ');
            prog.len_word(b'J', j, dec);
            prog.byte(b' ');
            prog.len_word(b'K', kk, dec);
        }
        None => prog.text(b" J0"),
    }
    prog.end_block();
    src.note_program(prog.bytes());
    src.verdict(!prog.overflowed(), "the program fits the writer's buffer")?;

    let config = Config { grid, ..Config::default() };
    let mut events = Vec::new();
    let mut alarm = None;
    for item in Expander::new(prog.bytes(), config).take(4_000_000) {
        match item {
            Ok(e) => events.push(e),
            Err(a) => {
                alarm = Some(a);
                break;
            }
        }
    }
    let moves = || events.iter().filter_map(|e| if let Event::Move(m) = e { Some(m) } else { None });
    if let Some(a) = alarm {
        src.verdict(a.code == AlarmCode::TooManyPasses, "a legal cycle is refused only for its pass count")?;
        src.verdict(events.len() <= 1, "PRJ.MAXPASS: refused before any motion of the cycle")?;
        return Ok(());
    }
    let passes: Vec<_> = events.iter().filter_map(|e| if let Event::Pass(p) = e { Some(*p) } else { None }).collect();
    let max_passes = DEFAULTS.max_passes as usize;
    src.verdict(passes.len() * starts as usize <= max_passes, "PRJ.MAXPASS: passes × starts within max_passes")?;
    let rough: Vec<i64> = passes.iter().filter(|p| p.kind == PassKind::Rough).map(|p| p.diameter_depth / 2).collect();
    let finish: Vec<_> = passes.iter().filter(|p| p.kind != PassKind::Rough).collect();
    src.verdict(rough.last() == Some(&(k - d)), "G76.DEPTH.LAST: the last rough depth is k − d")?;
    src.verdict(finish.len() == m as usize, "G76.FINISH: m finishing passes")?;
    src.verdict(finish.iter().all(|p| p.diameter_depth == 2 * k), "G76.FINISH: finishing passes at depth k")?;
    src.verdict(finish[0].kind == PassKind::Finish, "G76.FINISH: the first finishing pass is FINISH")?;
    src.verdict(finish[1..].iter().all(|p| p.kind == PassKind::Spring), "G76.FINISH: the others are SPRING")?;
    for (i, pair) in rough.windows(2).enumerate() {
        let cut = pair[1] - pair[0];
        let last = i + 2 == rough.len();
        src.verdict(cut >= 0, "G76.DEPTH.1: rough depths never decrease")?;
        if !degressive || dmin >= 1 {
            src.verdict(cut > 0, "G76.DEPTH.MIN: rough depths strictly increase when Δdmin ≥ 1")?;
        }
        if !last && degressive {
            src.verdict(cut >= dmin, "G76.DEPTH.MIN: every cut but the last is ≥ Δdmin")?;
        }
        if !last && !degressive {
            src.verdict(cut == dd, "G78.DEPTHMODE: constant cuts of Δd")?;
        }
    }
    src.verdict(moves().filter(|m: &&Move| m.kind == MoveKind::Thread).all(|m| m.feed == lead), "COM.LEAD: thread moves carry the lead")?;
    src.verdict(moves().next_back().map(|m| (m.x, m.z)) == Some((ax, az)), "G76.PATH: the cycle ends at A")?;
    Ok(())
}
