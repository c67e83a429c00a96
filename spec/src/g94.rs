//! G94 — single face cutting cycle (M003), under `gsk` and `fanuc` (under `nc201` it is
//! `UNSUPPORTED CODE`, PRJ.DIALECT).
//!
//! One cycle from the start point A: ① rapid Z to the cut start C, ② feed to the end point D
//! (a taper when K ≠ 0), ③ feed Z back to A.z, ④ rapid X back to A.x (G94.PATH). The run
//! (G94.MODAL) is read by [`crate::single_cut`]. The seed's fragment (G94.EXAMPLE) is
//! `corpus/g94_example.nc`, read as docs/INTERPRETATION.md, "G90 and G94", says.

use crate::emit::Out;
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::single_cut::{taper_ok, Cut, Run};
use crate::words::{alarm, Read, F, N, U, W, X, Z};
use cycle_vocab::readings::G94K;
use cycle_vocab::{Alarm, AlarmCode, Dialect, PassKind, Rule};

/// G94 as a family of the interpreter: a motion mode with its run.
#[derive(Debug, Default)]
pub struct G94 {
    run: Run,
}

/// G94.FORMAT (M003): `G94 X(U) Z(W) [K] F`; K a signed length, |K| ≤ N (COM.RANGES). R, I
/// and every other word are not allowed.
const WORDS: Words = Words::of(&[F, (b'K', Read::Length { lo: -N, hi: N }), U, W, X, Z]);

impl Family for G94 {
    fn modal(&self) -> bool {
        true
    }
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        match self.run.block(st, b, b'K')? {
            Some(cut) => expand(&cut, st.config.readings.g94_k, &mut st.out),
            None => Ok(()),
        }
    }
}

/// G94.TAPER (declared reading `g94.k`): the Z of the cut start. The letter, `end-minus-start`
/// (`003_…` line 142: K is "端面切削始点至终点位移在Z方向的…增量值", the Z increment from the cut's
/// start to its end): K = D.z − C.z, so C.z = D.z − K. `start-minus-end` (FANUC, ADTECH):
/// C.z = D.z + K.
pub fn cut_start_z(d_z: i128, k: i128, reading: G94K) -> i128 {
    match reading {
        G94K::EndMinusStart => d_z - k,
        G94K::StartMinusEnd => d_z + k,
    }
}

/// Checks one cycle in the register's order — U = 0 (`GEOMETRY` on X, G94.FORMAT), then the
/// taper on k = C.z − D.z under the reading in force (|k| ≤ |W| when they differ in sign, else
/// `GEOMETRY` on K, G94.TAPER) — and emits it: the pass header (index in the run, Z depth
/// |A.z − C.z|, so 2·|A.z − C.z| on diameter), then G94.PATH.
pub fn expand(c: &Cut, reading: G94K, out: &mut Out) -> Result<(), Alarm> {
    let ((ax, az), (dx, dz), k, line) = (c.a, c.d, c.taper, c.line);
    if dx == ax {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::G94Format, line));
    }
    let cz = cut_start_z(dz, k, reading);
    if !taper_ok(cz - dz, dz - az) {
        return Err(alarm(AlarmCode::Geometry, b'K', Rule::G94Taper, line));
    }
    let approach = if k != 0 { Rule::G94Taper } else { Rule::G94Path };
    out.pass(c.index, PassKind::Rough, 2 * (az - cz).abs(), Rule::G94Path, line)?;
    out.rapid(ax, cz, approach, line)?; // ①
    out.feed(dx, dz, c.feed, Rule::G94Path, line)?; // ②
    out.feed(dx, az, c.feed, Rule::G94Path, line)?; // ③
    out.rapid(ax, az, Rule::G94Path, line) // ④
}

#[cfg(test)]
mod tests;
