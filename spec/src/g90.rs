//! G90 — single OD/ID cutting cycle (M003), under `gsk` and `fanuc` (under `nc201` G90 is the
//! absolute mode, NC201.ABSINC).
//!
//! One cycle from the start point A: ① rapid X to the cut start C, ② feed to the end point D
//! (a taper when I ≠ 0), ③ feed X back to A.x, ④ rapid Z back to A.z (G90.PATH). The run
//! (G90.MODAL) is read by [`crate::single_cut`]. The seed's fragments (G90.EXAMPLE) are
//! `corpus/g90_example.nc`, read as docs/INTERPRETATION.md, "G90 and G94", says.

use crate::emit::Out;
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::single_cut::{taper_ok, Cut, Run};
use crate::words::{alarm, Read, F, N, U, W, X, Z};
use cycle_vocab::{Alarm, AlarmCode, Dialect, PassKind, Rule};

/// G90 as a family of the interpreter: a motion mode with its run.
#[derive(Debug, Default)]
pub struct G90 {
    run: Run,
}

/// G90.FORMAT (M003): `G90 X(U) Z(W) [I] F`; I a signed radius length, |I| ≤ N (COM.RANGES).
/// R and every other word are not allowed; I is no lead, so F with I is legal.
const WORDS: Words = Words::of(&[F, (b'I', Read::Length { lo: -N, hi: N }), U, W, X, Z]);

impl Family for G90 {
    fn modal(&self) -> bool {
        true
    }
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        match self.run.block(st, b, b'I')? {
            Some(cut) => expand(&cut, &mut st.out),
            None => Ok(()),
        }
    }
}

/// G90.TAPER (M003): the X of the cut start, C.x = D.x + 2I (I = start radius − end radius,
/// X a diameter).
pub fn cut_start_x(d_x: i128, i: i128) -> i128 {
    d_x + 2 * i
}

/// Checks one cycle in the register's order — W = 0 (`GEOMETRY` on Z, G90.FORMAT), then the
/// taper (2·|I| ≤ |U| when they differ in sign, else `GEOMETRY` on I, G90.TAPER) — and emits
/// it: the pass header (index in the run, depth |A.x − C.x| on diameter), then G90.PATH.
pub fn expand(c: &Cut, out: &mut Out) -> Result<(), Alarm> {
    let ((ax, az), (dx, dz), i, line) = (c.a, c.d, c.taper, c.line);
    if dz == az {
        return Err(alarm(AlarmCode::Geometry, b'Z', Rule::G90Format, line));
    }
    if !taper_ok(2 * i, dx - ax) {
        return Err(alarm(AlarmCode::Geometry, b'I', Rule::G90Taper, line));
    }
    let cx = cut_start_x(dx, i);
    let approach = if i != 0 { Rule::G90Taper } else { Rule::G90Path };
    out.pass(c.index, PassKind::Rough, (ax - cx).abs(), Rule::G90Path, line)?;
    out.rapid(cx, az, approach, line)?; // ①
    out.feed(dx, dz, c.feed, Rule::G90Path, line)?; // ②
    out.feed(ax, dz, c.feed, Rule::G90Path, line)?; // ③
    out.rapid(ax, az, Rule::G90Path, line) // ④
}

#[cfg(test)]
mod tests;
