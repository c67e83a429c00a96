//! G71 — stock removal along Z (M003), under `gsk` and `fanuc`.
//!
//! `G71 U(Δd) R(e);` then `G71 P(ns) Q(nf) U(Δu) W(Δw) F S T;` (G71.FORMAT). A G71 block with P
//! or Q is the second block, else the first (G71.UW). The first block's values are kept for
//! later G71 cycles — apart from G72's — and a word it omits falls back to its parameter
//! (G71.PARAM). The second block reads its contour ahead and roughs it in layers along Z
//! ([`crate::stock_removal`]). One-shot (CYC.ONESHOT): the motion mode stays. The seed's
//! example 1 (G71.EXAMPLE, `corpus/g71_example.nc`) is expanded here.

use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::g70::{P, Q};
use crate::stock_removal::{second_block, Axes, First};
use crate::words::{Read, F, N, U, W};
use cycle_vocab::{Alarm, Dialect, Rule};

/// G71 as a family of the interpreter: its kept first block.
#[derive(Debug, Default)]
pub struct G71 {
    first: First,
}

/// G71.DEPTH, G71.RETRACT (M003): "Δd (radius length) 1 … N, else `OUT OF RANGE` on U, rule
/// G71.DEPTH; e (radius length) 0 … N, else `OUT OF RANGE` on R, rule G71.RETRACT"; "First block
/// words: U (Δd) and R (e) only".
const FIRST: Words = Words::of(&[
    (b'R', Read::RuledLength { lo: 0, hi: N, rule: Rule::G71Retract }),
    (b'U', Read::RuledLength { lo: 1, hi: N, rule: Rule::G71Depth }),
]);

/// G71.FORMAT, G71.ALLOW (M003): "second block: P Q U W F S T only"; Δu (diameter) and Δw
/// signed lengths, |v| ≤ N.
pub const SECOND: Words = Words::of(&[F, P, Q, U, W]);

impl Family for G71 {
    /// G71.UW (M003): "A G71 block with P or Q is the second block, else the first".
    fn words(&self, kind: Kind, _: Dialect) -> Words {
        if kind.pq {
            SECOND
        } else {
            FIRST
        }
    }
    /// G71.PARAM (M003, OPEN): "A first block replaces G71's kept values (G72 keeps its own); a
    /// word it omits falls back to its parameter".
    fn execute(&mut self, st: &mut State, b: &BlockIn, src: &mut Source) -> Result<(), Alarm> {
        if !b.kind.pq {
            self.first = First { depth: b.values.get(b'U'), retract: b.values.get(b'R') };
            return Ok(());
        }
        second_block(Axes::G71, self.first, st, b, src)
    }
}
