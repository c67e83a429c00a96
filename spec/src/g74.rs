//! G74 — face peck drilling / face grooving (M003), under `gsk` and `fanuc`.
//!
//! `G74 R(e);` then `G74 X(U) Z(W) P(Δi) Q(Δk) R(Δd) F;` (G74.FORMAT). Pecks along Z, columns
//! stepped in X; the path is written once for G74 and G75 in [`crate::grooving`]. One-shot
//! (CYC.ONESHOT): the motion mode stays; the modal feed afterwards is the F of the cycle block.
//! The seed's example 4 (G74.EXAMPLE, `corpus/g74_example.nc`) is expanded here.

use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::grooving::{second_block, words, Axes};
use cycle_vocab::{Alarm, Dialect};

/// G74 as a family of the interpreter: its kept return e.
#[derive(Debug, Default)]
pub struct G74 {
    /// G74.FORMAT (OPEN): "The first block's e is kept per code (G74's and G75's apart) until
    /// another first block; without one, parameter 5139 (default 0)". `None`: 5139.
    e: Option<i64>,
}

/// G74.FORMAT (M003, OPEN): "A block with any of X U Z W P Q is the second block".
pub fn second(kind: Kind) -> bool {
    kind.axes || kind.has(b'P') || kind.has(b'Q')
}

impl Family for G74 {
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
        second_block(Axes::G74, self.e, st, b)
    }
}
