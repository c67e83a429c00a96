//! Harness `schedule_new_shape` — G76.DEPTH.LAST, G76.DEPTH.MIN, G78.DEPTHMODE: the schedule
//! `Schedule::new` prepares from legal words has the shape `Schedule::from_parts` accepts, and
//! `from_parts` rebuilds it exactly — the structural half of what `schedule_step` and
//! `schedule_count` assume of their symbolic schedule.
//!
//! **Property.** For legal Δd (1…N), Δdmin (0…N), T (1…N), either mode: `from_parts(new(p).parts())`
//! is `Some(new(p))` (Δd, T ≥ 1, reach in 1…2^33, the switch pass ≥ 1 and NEVER without a
//! minimum or in constant mode; Δd² formed again the same), the words kept as drawn.
//!
//! **Left to z3 and the drivers.** That reach and the switch pass are *the* passes of
//! G76.DEPTH.LAST and G76.DEPTH.MIN (lemmas 05, 07, 11; `schedule_parts`'s drivers check them
//! on every case).

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::schedule::{Schedule, ScheduleParams, NEVER};
use cycle_impl::MAX_LENGTH;

/// The legal words, 1…N (Δdmin from 0): what Kani proves and the drivers sample.
pub const FULL: i64 = MAX_LENGTH;

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, max_len: i64) -> Outcome {
    let first_cut = src.bounded_i64(1, max_len);
    let min_cut = src.bounded_i64(0, max_len);
    let target = src.bounded_i64(1, max_len);
    let constant = src.bool();
    let sch = Schedule::new(&ScheduleParams { first_cut, min_cut, target, constant });
    let p = sch.parts();
    check!(src, Schedule::from_parts(p) == Some(sch), "new's schedule has from_parts' shape and is rebuilt exactly");
    let words = (p.dd as i64, p.dmin as i64, p.target as i64);
    check!(src, words == (first_cut, min_cut, target), "legal words are kept as drawn");
    cover!(src, p.switch != NEVER, "a switch pass");
    cover!(src, p.reach > 1, "more than one pass before the clamp");
    Ok(())
}

/// The Kani stub (TRUSTED specification, see the Kani harness `schedule_new_shape`).
#[cfg(kani)]
pub mod stubs {
    /// `switch_pass(Δd, Δdmin)`: NEVER without a minimum (its first line), else s ≥ 1 (lemma 07).
    pub fn switch_pass_spec(_dd: u64, dmin: u64) -> u64 {
        if dmin == 0 {
            return u64::MAX;
        }
        let s: u64 = kani::any();
        kani::assume(s >= 1);
        s
    }
}

cycle_harness::property! {
    pub const PROPERTY = schedule_new_shape in crate::PROPERTIES {
        rules: ["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE"],
        states: "Schedule::new of legal words (its reach quotient real, switch_pass stubbed: NEVER without a minimum, else ≥ 1, lemma 07) has the shape from_parts accepts (reach in 1…2^33, switch ≥ 1, NEVER without a minimum or in constant mode) and from_parts rebuilds it exactly.",
        body: |src, max_len| body(src, max_len),
        /// Kani: the legal words, `switch_pass` stubbed (NEVER without a minimum — its first line —,
        /// else any s ≥ 1: lemma 07's s is ⌊a²/c²⌋ + 2 ≥ 2 or 1, the search's at least 1), the reach
        /// quotient T(T − 1)/Δd² + 1 real. Kissat: with CaDiCaL the fifth query was still open after
        /// 600 s (proofs/README.md); Kissat decides it in about 590 s. No loop: unwind 3 bounds nothing.
        kani: proof(FULL) { unwind: 3, solver: kissat, stubs: [cycle_impl::schedule::switch_pass => stubs::switch_pass_spec], measured: "SUCCESSFUL (270 checks; 2/2 covers), 350.0 s, 0.26 GB" },
        tests {
            /// Δd, Δdmin, T their 12 smallest and largest legal values, both modes.
            fn schedule_new_shape_exhaustive = exhaustive(12, 2_000_000) on FULL;
            /// The legal words at random.
            fn schedule_new_shape_random = random(0x5eed_0035, 4) on FULL;
        }
    }
}
