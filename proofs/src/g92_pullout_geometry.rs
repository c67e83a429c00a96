//! Harness `g92_pullout_geometry` — G92.JK.1–G92.JK.7, G92.PULLOUT, COM.LONGAXIS (and the
//! No.19 amount of G92.JK.1): the pull-out below the lexer (`cycle_impl::pullout`).
//!
//! **Property.** Three parts (one branch of the body each; Kani explores all of them):
//!
//! 0. `g92_amounts(J, K, c, 45)`, J and K each absent, 0 or any legal positive value (G92.JK.7:
//!    the words' absolute values), c the No.19 amount (0…N), the chamfer angle 5131 at its
//!    default 45° (No.5131 for G92: JK.1's J = round(c·tan 5131°), exact at 45°; other angles
//!    are impl's unit tests, `pullout::tests`, `thread_points_tests`): the register's table —
//!    (none, none) → (c, c) JK.1; (none, K) → (c, K), K = 0 read as JK.5 → (c, c) JK.2; (0, any) → no pull-out
//!    JK.4/JK.6; (J, none) → (J, J) JK.3; (J, 0) → (J, J) JK.5; (J, K) → (J, K); a resolved
//!    amount of 0 → no pull-out.
//! 1. `offsets(amounts, W, R, s)` for any resolved J, K (1…N) with K below the long-axis travel
//!    (the caller's G92.PULLOUT check), any Z travel W ≠ 0 and radius taper R (|W|, |R| ≤ 2N),
//!    side s = ±1: the long axis is Z exactly when |W| > |R| (COM.LONGAXIS); Z long: the
//!    pull-out starts K before the end on Z (toward A: −sign(W)·K) and ends at the end Z with
//!    X = end + s·J (radius, so 2·s·J on diameter); X long: it starts at X = end + sign(R)·K
//!    (2·sign(R)·K on diameter), ends at the end X with Z = end − sign(W)·J; the start's
//!    interpolated coordinate (round(R·K/|W|), or round(|W|·K/|R|)) has the sign of R (of
//!    −sign(W)) or is 0.
//! 2. `tenths_of_lead(No.19, lead, grid)` for No.19 0…255, any legal lead, both increment
//!    systems: round(No.19 · lead / 10) on the length grid, half up, checked by its exact
//!    bracket (no division), decided in `u128` ([`is_div_round_u64`]: num < 2^35, den ≤ 100,
//!    so nothing is lost against the 256-bit [`crate::model::is_div_round`]). Each grid is
//!    its own path, so the divisor is a constant on each.
//!
//! **Left to the drivers** (`g92_pullout_total`, a TEST, and impl's unit tests): the size of the
//! interpolated coordinate (|round(R·K/|W|)| ≤ |R|, its exact rounding) — a quotient of products
//! of 30-bit words, beyond a SAT solver's reach (see `depth_step_clamp`) — and the whole G92
//! trace built from these parts.
//!
//! **Kani bounds.** Everything symbolic over the ranges above; no stub. Neither the production
//! functions nor the checks loop (the 256-bit helpers, whose limb loops made the last query
//! too hard for the SAT solver, are no longer used here). `#[kani::unwind(5)]`,
//! `#[kani::solver(kissat)]`; the measured verdict is in proofs/README.md.

use crate::model::is_div_round_u64;
use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::pullout::{g92_amounts, offsets, tenths_of_lead, z_long, Amounts};
use cycle_impl::MAX_LENGTH;
use cycle_vocab::Grid;

/// The ranges a run draws from.
#[derive(Clone, Copy, Debug)]
pub struct Scope {
    /// Largest J, K, c; W and R up to twice this.
    pub max_len: i64,
    /// Largest lead, lead counts.
    pub max_lead: i64,
}

/// What Kani proves: the legal ranges (the metric lead range, the larger one).
pub const KANI: Scope = Scope { max_len: MAX_LENGTH, max_lead: 99_990_000 };

/// An optional word: absent, 0, or 1…max.
fn word<S: Source>(src: &mut S, max: i64) -> Option<i64> {
    match src.choose(3) {
        0 => None,
        1 => Some(0),
        _ => Some(src.bounded_i64(1, max)),
    }
}

fn sign(v: i64) -> i64 {
    v.signum()
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, scope: &Scope) -> Outcome {
    match src.choose(3) {
        0 => {
            let j = word(src, scope.max_len);
            let k = word(src, scope.max_len);
            let c = src.bounded_i64(0, scope.max_len);
            let want = match (j, k) {
                (None, None) | (None, Some(0)) => (c, c),
                (None, Some(k)) => (c, k),
                (Some(0), _) => (0, 0),
                (Some(j), None) | (Some(j), Some(0)) => (j, j),
                (Some(j), Some(k)) => (j, k),
            };
            let want = if want.0 > 0 && want.1 > 0 { Some(Amounts { j: want.0, k: want.1 }) } else { None };
            check!(src, g92_amounts(j, k, c, 45) == want, "G92.JK.1–G92.JK.6: the register's table of J, K and No.19");
            cover!(src, want.is_none(), "no pull-out");
            cover!(src, want.is_some_and(|a| a.j != a.k), "J and K differ");
        }
        1 => {
            let a = Amounts { j: src.bounded_i64(1, scope.max_len), k: src.bounded_i64(1, scope.max_len) };
            let w = src.bounded_i64(-2 * scope.max_len, 2 * scope.max_len);
            let r = src.bounded_i64(-2 * scope.max_len, 2 * scope.max_len);
            let s = if src.bool() { 1 } else { -1 };
            src.assume(w != 0)?;
            let zl = w.unsigned_abs() > r.unsigned_abs();
            check!(src, z_long(w, r) == zl, "COM.LONGAXIS: Z is the long axis exactly when |W| > |R|");
            // G92.PULLOUT: K below the long-axis travel (the caller refuses the rest).
            let travel = if zl { w.unsigned_abs() } else { r.unsigned_abs() };
            src.assume(a.k.unsigned_abs() < travel)?;
            let o = offsets(a, w, r, s);
            if zl {
                check!(src, o.start.1 == -sign(w) * a.k, "G92.PULLOUT (Z long): the pull-out starts K before the end, toward A");
                check!(src, o.end == (2 * s * a.j, 0), "G92.PULLOUT (Z long): it ends at the end Z, s·J out on X");
                check!(src, o.start.0 == 0 || sign(o.start.0) == sign(r), "G92.PULLOUT (Z long): the start X follows the taper's sign");
                check!(src, o.start.0 % 2 == 0, "the start X is a radius on diameter");
            } else {
                check!(src, o.start.0 == 2 * sign(r) * a.k, "G92.PULLOUT (X long): the pull-out starts K before the end X");
                check!(src, o.end == (0, -sign(w) * a.j), "G92.PULLOUT (X long): it ends at the end X, J toward A on Z");
                check!(src, o.start.1 == 0 || sign(o.start.1) == -sign(w), "G92.PULLOUT (X long): the start Z lies toward A");
            }
            cover!(src, zl && r != 0, "Z long, tapered");
            cover!(src, !zl, "X long");
        }
        _ => {
            let tenths = src.bounded_u32(0, 255);
            let lead = src.bounded_i64(1, scope.max_lead);
            // One call per increment system, each with its grid a constant: under Kani the
            // divisor (10 or 100) is then a constant on each path, not a symbolic choice.
            if src.bool() {
                tenths_case(src, tenths, lead, Grid::METRIC_ISB)?;
            } else {
                tenths_case(src, tenths, lead, Grid { increment: cycle_vocab::Increment::Isc, ..Grid::METRIC_ISB })?;
            }
        }
    }
    Ok(())
}

/// Part 2 on one grid: `tenths_of_lead` against the exact bracket of No.19 × lead / 10.
fn tenths_case<S: Source>(src: &mut S, tenths: u32, lead: i64, grid: Grid) -> Outcome {
    let c = tenths_of_lead(tenths, lead, grid);
    // 64-bit operands: No.19 ≤ 255 and lead < 2^27 give num < 2^35; den is 10 or 100.
    let den = 10 * grid.lead_counts_per_increment().unsigned_abs();
    check!(
        src,
        c >= 0 && is_div_round_u64(c as u64, u64::from(tenths) * lead as u64, den),
        "G92.JK.1: No.19 × lead / 10 on the length grid, rounded once half up"
    );
    cover!(src, c > 0, "a pull-out amount");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = g92_pullout_geometry in crate::PROPERTIES {
        rules: ["G92.JK.1", "G92.JK.2", "G92.JK.3", "G92.JK.4", "G92.JK.5", "G92.JK.6", "G92.JK.7", "G92.PULLOUT", "COM.LONGAXIS"],
        states: "Below the lexer: the register's J/K/No.19 table, the pull-out geometry (long axis at |W| > |R|, start K before the end toward A, end s·J out on X or J toward A on Z, the interpolated coordinate's sign), No.19 × lead / 10 rounded once half up.",
        body: |src, scope| body(src, &scope),
        /// Kani: the pull-out parts over the legal ranges. Kissat: with CaDiCaL (Kani's default) the
        /// last query reached no verdict in 5–15 min (README). Unwind 5 as measured; no loop is left
        /// (part 2's bracket is decided in `u128`, [`is_div_round_u64`]), so it bounds nothing.
        kani: proof(KANI) { unwind: 5, solver: kissat, measured: "SUCCESSFUL (300 checks, 2 unreachable; 5/5 covers), 360.2 s, 0.32 GB" },
        tests {
            /// Words ≤ 6, W and R in ±12, leads ≤ 40: every combination.
            fn g92_pullout_geometry_exhaustive_small = exhaustive(32, 2_000_000) on Scope { max_len: 6, max_lead: 40 };
            fn g92_pullout_geometry_exhaustive_edges = exhaustive(3, 2_000_000) on KANI;
            fn g92_pullout_geometry_random = random(0x5eed_0092, 2) on KANI;
        }
    }
}
