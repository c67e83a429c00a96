//! G72 — stock removal along X (M003), under `gsk` and `fanuc`.
//!
//! `G72 W(Δd) R(e);` then `G72 P(ns) Q(nf) U(Δu) W(Δw) F S T;` (G72.FORMAT): "As G71 with X and
//! Z exchanged" — layers at Z_k, cuts along X ([`crate::stock_removal`]). Its first block's
//! values are kept apart from G71's, with the same parameters 5132, 5133 (G72.DEPTH). The seed's
//! example 2 (G72.EXAMPLE, `corpus/g72_example.nc`) is expanded here.

use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::g71::SECOND;
use crate::stock_removal::{second_block, Axes, First};
use crate::words::{Read, N};
use cycle_vocab::{Alarm, Dialect, Rule};

/// G72 as a family of the interpreter: its kept first block.
#[derive(Debug, Default)]
pub struct G72 {
    first: First,
}

/// G72.DEPTH (M003): "First block words W (Δd, a Z length 1 … N, `OUT OF RANGE` on W, rule
/// G72.DEPTH) and R (e, 0 … N, rule G72.DEPTH)".
const FIRST: Words = Words::of(&[
    (b'R', Read::RuledLength { lo: 0, hi: N, rule: Rule::G72Depth }),
    (b'W', Read::RuledLength { lo: 1, hi: N, rule: Rule::G72Depth }),
]);

impl Family for G72 {
    /// G72.FORMAT (M003), as G71.UW: a block with P or Q is the second block ("P Q U W F S T as
    /// G71's"), else the first.
    fn words(&self, kind: Kind, _: Dialect) -> Words {
        if kind.pq {
            SECOND
        } else {
            FIRST
        }
    }
    /// G72.DEPTH (M003): a first block replaces G72's kept Δd and e.
    fn execute(&mut self, st: &mut State, b: &BlockIn, src: &mut Source) -> Result<(), Alarm> {
        if !b.kind.pq {
            self.first = First { depth: b.values.get(b'W'), retract: b.values.get(b'R') };
            return Ok(());
        }
        second_block(Axes::G72, self.first, st, b, src)
    }
}
