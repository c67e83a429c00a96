//! G75 — OD grooving (M003), under `gsk` and `fanuc`.
//!
//! `G75 R(e);` then `G75 X(U) Z(W) P(Δi) Q(Δk) R(Δd) F;` (G75.FORMAT): "As G74 with X↔Z" — pecks
//! along X (Δi, a radius), grooves stepped in Z (Δk), relief in Z; written once with G74 in
//! [`crate::grooving`]. One-shot (CYC.ONESHOT). The seed's example 5 (G75.EXAMPLE,
//! `corpus/g75_example.nc`) is expanded here.

use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::g74::second;
use crate::grooving::{second_block, words, Axes};
use cycle_vocab::{Alarm, Dialect};

/// G75 as a family of the interpreter: its kept return e.
#[derive(Debug, Default)]
pub struct G75 {
    /// G74.FORMAT (OPEN): "The first block's e is kept per code (G74's and G75's apart) until
    /// another first block; without one, parameter 5139 (default 0)". `None`: 5139.
    e: Option<i64>,
}

impl Family for G75 {
    fn words(&self, kind: Kind, _: Dialect) -> Words {
        words(second(kind))
    }
    /// The first block replaces the kept e (a first block without R falls back to 5139); the
    /// second block runs the cycle.
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        if !second(b.kind) {
            self.e = b.values.get(b'R');
            return Ok(());
        }
        second_block(Axes::G75, self.e, st, b)
    }
}
