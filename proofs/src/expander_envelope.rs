//! TEST `expander_never_panics` (driver-only: not a Kani proof) — COM.POINTS, COM.RANGES, PRJ.MAXPASS (and G76.PATH,
//! G92.PATH, PRJ.TRACE): the production expander on small symbolic programs.
//!
//! **Programs.** One cycle, written as text from drawn values into a fixed 256-byte buffer
//! ([`Program`], no allocation): `G92 U W [R] F [J] [K] [L]`, or an optional first block
//! `G76 P(m)(r)(a) [Q] [R] [D] [L] [E]` / `G78 P(m)(mode)(a) …` followed by
//! `G76|G78 U W [R] P Q F [J] [K]`. The machine starts at a drawn point A (configuration, any
//! legal X and Z) on a drawn grid (metric/inch, ISB/ISC) with a drawn `max_passes`. U is
//! derived from the drawn taper i, thread height k and a clearance c ≥ 0 so that most drawn
//! cycles are legal — A outside B (COM.POINTS) — but nothing is assumed: any alarm is an
//! acceptable outcome, only a panic or a broken property below is not.
//!
//! **Properties.**
//!
//! - No panic, no arithmetic overflow (Kani checks overflow; the test profile has overflow
//!   checks on) for any drawn program.
//! - The iterator ends: at most 7·`max_passes` events (per pass one header and at most six
//!   moves per start — approach, lead-in, cut, pull-out, retract X, retract Z — and
//!   passes × starts ≤ `max_passes`), then at most one alarm, then `None` (PRJ.TRACE,
//!   PRJ.MAXPASS).
//! - `TOO MANY PASSES` comes before any motion of the cycle (PRJ.MAXPASS); without an alarm,
//!   pass headers × starts ≤ `max_passes`.
//! - Every move — thread moves in particular, so every synchronized segment, whose start is the
//!   previous move's end — lies in the envelope computed here from the words alone (COM.POINTS,
//!   radius values doubled on X): on X (oriented by the side s) between the thread's deepest
//!   line min(s·C.x, s·D.x) and max(s·A.x, s·C.x + 2k + 2E, s·D.x + 2k + 2J*), where J* bounds
//!   the resolved pull-out (the larger of |J|, |K| and the No.19 / chamfer amount); on Z
//!   within the hull of A.z, D.z (and D.z − sign(W)·J* when X is the long axis), widened on
//!   both sides by 2·t*, t* = ⌊T·a/84⌋ + 1 ≥ round(T·tan(a/2)) for a ≤ 99° (tan is convex:
//!   tan(a/2) ≤ a·tan(49.5°)/99 < a/84), T = k − d (thread.zref: under `groove` the left
//!   flank reaches 2·t(T) on the infeed side; under `start`, the letter, it goes t(δ) ≤ t(T)
//!   the other way).
//! - Thread moves carry the programmed lead and a start angle below 360°.
//! - The tool ends where it started (G76.PATH, G92.PATH: every pass returns to A).
//!
//! **Not a Kani proof.** Kani 0.61.0 / CBMC 6.4.0 ran out of memory in symbolic execution (issue #25): the symbolic program text makes the lexer's loops (comment, digit runs, blanks) unroll to the bound. No entry below the lexer reaches the G92/G76/G78 state machines (`modal` and `emit` are private), so this stays a TEST; `g90_envelope` is the Kani envelope proof below the lexer for G90/G94. The body runs under `cargo test` (bounded-exhaustive and random
//! drivers); its Kani harness (the scope named `KANI` below) is a proof harness only with the
//! feature `kani-attempts`.
//!
//! **Kani bounds of the attempt** ([`KANI`]): lengths ≤ 9 increments, leads ≤ 9 counts, `max_passes` ≤ 3,
//! L ≤ 2, m ≤ 2; the program is at most [`KANI_PROGRAM`] = 110 bytes (checked by the body in
//! every driver). Loops: the lexer's byte loops ≤ 111, our event loop ≤ 7·3 + 2 = 23, digit loops
//! ≤ 20, the switch-pass search ≤ 33, the root's walk ≤ 4 (`isqrt` is loop-free), the
//! configuration check 15.
//! So `#[kani::unwind(112)]`.

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::Expander;
use cycle_impl::MAX_LENGTH;
use cycle_vocab::{AlarmCode, Config, Event, Grid, Increment, MoveKind, Params, Units};
use write::Written;

mod write;

/// The ranges a run draws from, and which optional parts of a program it may write.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest |A.x|, |A.z| (the configured start point), increments.
    pub max_start: i64,
    /// Largest length word (i, k, c, W, Δd, Δdmin, d, E, J, K), increments.
    pub max_len: i64,
    /// Largest lead, lead counts (also capped by the unit's legal range).
    pub max_lead: i64,
    /// Largest `max_passes` parameter.
    pub max_passes: u32,
    /// Largest L.
    pub max_starts: u32,
    /// Largest m (finishing passes).
    pub max_finish: u32,
    /// The grid is drawn from the first `grids` (1…4) of [`GRIDS`].
    pub grids: u32,
    /// Whether a G76/G78 first block (with each of its optional words) may be written.
    pub first_block: bool,
    /// Whether the optional words J, K, L (G92) and an explicit R0 may be written.
    pub optional_words: bool,
    /// The longest program the scope can build (checked).
    pub max_program: usize,
}

/// The longest program of the Kani scope.
pub const KANI_PROGRAM: usize = 110;

/// What Kani proves.
pub const KANI: Scope = Scope {
    max_start: MAX_LENGTH,
    max_len: 9,
    max_lead: 9,
    max_passes: 3,
    max_starts: 2,
    max_finish: 2,
    grids: 4,
    first_block: true,
    optional_words: true,
    max_program: KANI_PROGRAM,
};

/// The full legal ranges (lengths to N/8 so that U = −2i − s(2k + c) stays legal), up to 200
/// passes: what the random driver samples.
pub const WIDE: Scope = Scope {
    max_start: MAX_LENGTH,
    max_len: MAX_LENGTH / 8,
    max_lead: 99_990_000,
    max_passes: 200,
    max_starts: 5,
    max_finish: 3,
    grids: 4,
    first_block: true,
    optional_words: true,
    max_program: crate::program::CAPACITY,
};

/// The grids, by index.
pub const GRIDS: [Grid; 4] = [
    Grid { units: Units::Metric, increment: Increment::Isb },
    Grid { units: Units::Metric, increment: Increment::Isc },
    Grid { units: Units::Inch, increment: Increment::Isb },
    Grid { units: Units::Inch, increment: Increment::Isc },
];

/// The largest legal F in lead counts (COM.RANGES): 9999 mm or 9.99 in.
pub const fn max_f(units: Units) -> i64 {
    match units {
        Units::Metric => 99_990_000,
        Units::Inch => 999_000,
    }
}

/// `n` rounded up after dividing by `d` > 0 (n ≥ 0).
const fn ceil_div(n: i64, d: i64) -> i64 {
    (n + d - 1) / d
}

/// Draws an optional length word when `allowed`: absent, or a value in `lo..=hi`.
fn optional<S: Source>(src: &mut S, allowed: bool, lo: i64, hi: i64) -> Option<i64> {
    if allowed && src.bool() { Some(src.bounded_i64(lo, hi)) } else { None }
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    let code = src.choose(3); // 0: G92, 1: G76, 2: G78
    let grid = GRIDS[src.choose(scope.grids.clamp(1, 4)) as usize];
    let start_x = src.bounded_i64(-scope.max_start, scope.max_start);
    let start_z = src.bounded_i64(-scope.max_start, scope.max_start);
    let max_passes = src.bounded_u32(1, scope.max_passes);
    let len = scope.max_len;
    // G76.DEFAULTS: Δdmin (5140) and d (5141) within the scope's lengths.
    let p5140_min_cut = src.bounded_i64(0, len);
    let p5141_finish_allowance = src.bounded_i64(0, len);
    let params = Params {
        max_passes: Some(i64::from(max_passes)),
        p5140_min_cut: Some(p5140_min_cut),
        p5141_finish_allowance: Some(p5141_finish_allowance),
        ..Params::default()
    };
    let config = Config { grid, params, start_x, start_z, ..Config::default() };

    let s: i64 = if src.bool() { 1 } else { -1 };
    let taper = src.bounded_i64(-len, len); // G92 R / G76 R(i), radius
    let w_mag = src.bounded_i64(1, len);
    let w = if src.bool() { w_mag } else { -w_mag };
    let lead = src.bounded_i64(1, scope.max_lead.min(max_f(grid.units)));

    let Written { prog, u, k, e_len, d_allow, angle, starts, pull_bound } =
        write::write(src, scope, code, grid, s, taper, w, lead, p5141_finish_allowance);
    src.note_program(prog.bytes());
    check!(src, !prog.overflowed() && prog.len() <= scope.max_program, "the program fits the scope's buffer bound");

    // The points (X diameter): A, D = A + (U, W), C.x = D.x + 2i.
    let (ax, az) = (start_x, start_z);
    let (dx, dz) = (ax + u, az + w);
    let cx = dx + 2 * taper;
    let x_long = w.abs() <= taper.abs();
    let target = (k - d_allow).max(0);
    let t_star = target * angle / 84 + 1;
    let x_lo = (s * cx).min(s * dx);
    let x_hi = (s * ax).max(s * cx + 2 * k + 2 * e_len).max(s * dx + 2 * k + 2 * pull_bound);
    let pull_z = if x_long { dz - w.signum() * pull_bound } else { dz };
    let shift = if code == 0 { 0 } else { 2 * t_star };
    let z_lo = az.min(dz).min(pull_z) - shift;
    let z_hi = az.max(dz).max(pull_z) + shift;

    // Run: at most 7·max_passes events, one alarm, then None.
    let bound = 7 * max_passes as usize;
    let mut it = Expander::new(prog.bytes(), config);
    let (mut events, mut headers, mut moves, mut threads) = (0usize, 0u64, 0usize, 0usize);
    let mut pos = (ax, az);
    let mut alarm = None;
    let mut ended = false;
    for _ in 0..bound + 2 {
        match it.next() {
            None => {
                ended = true;
                break;
            }
            Some(Err(a)) => {
                alarm = Some(a);
                check!(src, it.next().is_none(), "PRJ.TRACE: the alarm ends the trace");
                ended = true;
                break;
            }
            Some(Ok(Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_))) => {
                check!(src, false, "PRJ.TRACE: no dwell or spindle event in these cycles");
            }
            Some(Ok(Event::Pass(_))) => {
                headers += 1;
                events += 1;
            }
            Some(Ok(Event::Move(m))) => {
                events += 1;
                moves += 1;
                check!(src, (m.x, m.z) != pos, "PRJ.NOOP: no move to the current position");
                pos = (m.x, m.z);
                check!(src, x_lo <= s * m.x && s * m.x <= x_hi, "COM.POINTS: every move's X lies between the thread and the start point (plus lead-in, pull-out)");
                check!(src, z_lo <= m.z && m.z <= z_hi, "COM.POINTS: every move's Z lies between the start and the thread end (plus flank shift, pull-out)");
                if m.kind == MoveKind::Thread {
                    threads += 1;
                    check!(src, m.feed == lead && m.angle < 360_000, "COM.LEAD: thread moves carry the lead and an angle below 360°");
                }
            }
        }
        check!(src, events <= bound, "PRJ.MAXPASS: at most 7·max_passes events");
    }
    check!(src, ended, "the expansion ends within 7·max_passes events and one alarm");
    match alarm {
        Some(a) => {
            if a.code == AlarmCode::TooManyPasses {
                check!(src, moves == 0, "PRJ.MAXPASS: too many passes is refused before any motion");
            }
            cover!(src, a.code == AlarmCode::TooManyPasses, "TOO MANY PASSES");
            cover!(src, a.code == AlarmCode::Geometry, "a GEOMETRY alarm");
        }
        None => {
            check!(src, headers >= 1 && threads >= 1, "a legal cycle cuts");
            check!(src, headers * u64::from(starts) <= u64::from(max_passes), "PRJ.MAXPASS: passes × starts within max_passes");
            check!(src, pos == (ax, az), "G76.PATH / G92.PATH: the tool returns to the start point");
            cover!(src, code == 0, "a G92 cycle");
            cover!(src, code == 1, "a G76 cycle");
            cover!(src, code == 2, "a G78 cycle");
            cover!(src, headers >= 3, "three or more passes");
            cover!(src, x_long, "X as the long axis");
            if scope.first_block {
                cover!(src, e_len > 0 && code != 0, "a lead-in");
            }
        }
    }
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = expander_never_panics in crate::PROPERTIES {
        rules: ["COM.POINTS", "COM.RANGES", "PRJ.MAXPASS", "G76.PATH", "G92.PATH", "PRJ.TRACE"],
        states: "Small G92/G76/G78 programs: no panic, bounded events, TOO MANY PASSES before any motion, every move inside the envelope computed from the words, back at A.",
        body: |src, scope| body(src, &scope),
        /// The Kani attempt (a TEST: out of memory; a harness only with `kani-attempts`).
        kani: test(KANI) { unwind: 112, why: "out of memory in symbolic execution (the lexer's loops over symbolic text)" },
        tests {
            /// Geometry: every side, taper, height, clearance, W, Δd, Δdmin (5140), d (5141) ≤ 2
            /// increments, leads 1…2, max_passes 1…4, every grid; no optional words.
            fn expander_never_panics_exhaustive_geometry = exhaustive(3, 3_000_000) on Scope { max_start: 0, max_len: 2, max_lead: 2, max_passes: 4, max_starts: 1, max_finish: 1, grids: 4, first_block: false, optional_words: false, max_program: KANI_PROGRAM };
            /// Pull-out and start words: J, K (absent, smallest, largest, and negative for G92), L, R0,
            /// with each length at its smallest and largest value in 1…2.
            fn expander_never_panics_exhaustive_words = exhaustive(1, 3_000_000) on Scope { max_start: 0, max_len: 2, max_lead: 2, max_passes: 4, max_starts: 2, max_finish: 1, grids: 1, first_block: false, optional_words: true, max_program: KANI_PROGRAM };
            /// First blocks: m, r or mode, a, Δdmin, d, D, L, E in every combination of presence and
            /// extreme value, on a pinned thread.
            fn expander_never_panics_exhaustive_first_block = exhaustive(1, 3_000_000) on Scope { max_start: 0, max_len: 1, max_lead: 1, max_passes: 3, max_starts: 2, max_finish: 2, grids: 1, first_block: true, optional_words: false, max_program: KANI_PROGRAM };
            /// The Kani scope itself, sampled: its programs fit the 110 bytes its unwind bound assumes
            /// (the body checks the length), and every property holds.
            fn expander_never_panics_random_kani_scope = random(0x5eed_0006, 4) on KANI;
            /// Full legal lengths and leads, up to 200 passes, 5 starts, 3 finishing passes.
            fn expander_never_panics_random = random(0x5eed_0004, 4) on WIDE;
            /// Small lengths (1…60 increments) where cycles are legal and have many passes.
            fn expander_never_panics_random_small = random(0x5eed_0005, 4) on Scope { max_start: 2000, max_len: 60, max_lead: 3000, max_passes: 60, max_program: 160, ..WIDE };
        }
    }
}

#[cfg(test)]
mod tests;
