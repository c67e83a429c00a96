//! Harness `peck_toward` — G74.PECK, G74.E, G74.RELIEF, G75.PECK, G75.RELIEF, G83.PECK: the
//! lemma on `cycle_impl::g74::toward` (dir·len, saturating) that `g74_peck_step` and
//! `g83_peck_step` use in place of its multiplier.
//!
//! **Property.** For every direction dir ∈ {−1, 0, 1} and every len (all of `i64`),
//! `toward(dir, len)` is [`spec`]: len, 0, or −len (saturating: −i64::MIN is i64::MAX) —
//! exactly what the peck harnesses' stub returns, without a multiplier. The cycles call `toward`
//! only with a direction: c and σ are signs (`signum`), the relief direction is σ or 1 (the
//! stub asserts it).

use crate::source::{Outcome, Source};
use crate::{check, cover};
use cycle_impl::g74::toward;

/// dir·len for dir ∈ {−1, 0, 1}, without a multiplier (the stub of `toward`).
pub fn spec(dir: i64, len: i64) -> i64 {
    if dir < 0 {
        len.saturating_neg()
    } else if dir == 0 {
        0
    } else {
        len
    }
}

/// The harness body (see the module documentation).
pub fn body<S: Source>(src: &mut S, _scope: &()) -> Outcome {
    let dir = src.bounded_i64(-1, 1);
    let len = src.bounded_i64(i64::MIN, i64::MAX);
    check!(src, toward(dir, len) == spec(dir, len), "toward(dir, len) = dir·len (saturating) for a direction");
    cover!(src, dir == -1 && len == i64::MIN, "the saturating end");
    Ok(())
}

cycle_harness::property! {
    pub const PROPERTY = peck_toward in crate::PROPERTIES {
        rules: ["G74.PECK", "G74.E", "G74.RELIEF", "G75.PECK", "G75.RELIEF", "G83.PECK"],
        states: "The lemma behind the peck harnesses' stub of `toward`: for a direction dir ∈ {−1, 0, 1} and every i64 len, toward(dir, len) is len, 0 or −len (saturating).",
        body: |src, scope| body(src, &scope),
        /// The Kani harness (no loop).
        kani: proof(()) { measured: "SUCCESSFUL (5 checks; 1/1 covers), 0.7 s, 0.90 GB" },
        tests {
            /// Every direction with each len's 200 smallest and largest values.
            fn peck_toward_exhaustive = exhaustive(200, 2_000_000) on ();
            fn peck_toward_random = random(0x5eed_0743, 4) on ();
        }
    }
}
