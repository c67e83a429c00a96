//! G73 — pattern repeating (M003), under `gsk` and `fanuc`.
//!
//! Format (a): `G73 U(Δi) W(Δk) R(d);` then `G73 P(ns) Q(nf) U(Δu) W(Δw) F S T;`. Format (b), one
//! block: `G73 P Q I(Δi) K(Δk) U(Δu) W(Δw) D(d) F S T` (G73.FORMAT, G73.UW). The contour
//! N(ns) … N(nf) follows the P/Q block (CNT.FIND as for G71) and is run d times, translated
//! toward the allowances (G73.DEPTH, G73.PATH); any contour, arcs included (G73.USE). One-shot
//! (CYC.ONESHOT); the program resumes after N(nf) (CNT.FLOW). The seed's example 3
//! (G73.EXAMPLE, `corpus/g73_example.nc`) is expanded here.

use crate::contour::block::{read, Reader};
use crate::contour::path::{run, Feed};
use crate::contour::{self, Contour, Point};
use crate::emit::Out;
use crate::exact::round_div;
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::g70::{P, Q};
use crate::words::{alarm, Read, F, N, U, W};
use cycle_vocab::readings::G73C;
use cycle_vocab::{Alarm, AlarmCode, Dialect, PassKind, Rule};

/// G73 as a family of the interpreter: the values its last first block gave.
#[derive(Debug, Default)]
pub struct G73 {
    kept: Kept,
}

/// "Kept values. A first block replaces G73's kept Δi, Δk, d (format (b)'s I, K, D do not change
/// them); a word it omits falls back to its parameter: Δi ← 5135, Δk ← 5136 (default 0 each),
/// d ← 5137 (default 1)." `None`: the parameter.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct Kept {
    di: Option<i64>,
    dk: Option<i64>,
    d: Option<i64>,
}

/// G73.ESCAPE (OPEN): "Δi (a radius), Δk, Δu (diameter), Δw: signed lengths, |v| ≤ N".
const SIGNED: Read = Read::Length { lo: -N, hi: N };

/// G73.COUNT (OPEN): "d … an integer (a decimal point is `NOT INTEGER`), d ≥ 1 (else `OUT OF
/// RANGE`, rule G73.COUNT)", and at most N like every word's value (the register's
/// clarification: beyond N is `OUT OF RANGE`, G73.COUNT, at the block that writes it); the pass
/// bound of the cycle (PRJ.MAXPASS) comes later, with the cycle.
const COUNT: Read = Read::Integer { lo: 1, hi: crate::words::N, rule: Rule::G73Count };

/// G73.FORMAT: format (a)'s first block, "words U (Δi), W (Δk), R (d) only".
const FIRST: Words = Words::of(&[(b'R', COUNT), (b'U', SIGNED), (b'W', SIGNED)]);
/// G73.FORMAT: format (a)'s second block, "words P Q U (Δu) W (Δw) F S T (R is `WORD NOT
/// ALLOWED`)".
const SECOND: Words = Words::of(&[F, P, Q, U, W]);
/// G73.FORMAT: format (b), "words P Q I (Δi) K (Δk) U (Δu) W (Δw) D (d) F S T".
const FORMAT_B: Words = Words::of(&[(b'D', COUNT), F, (b'I', SIGNED), (b'K', SIGNED), P, Q, U, W]);

/// G73.FORMAT (M003, OPEN): "A G73 block without P and Q is format (a)'s first block … with P
/// or Q and none of I, K, D is format (a)'s second block … with P or Q and any of I, K, D is
/// format (b)".
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Format {
    First,
    Second,
    B,
}

fn format(kind: Kind) -> Format {
    if !kind.pq {
        Format::First
    } else if kind.has(b'I') || kind.has(b'K') || kind.has(b'D') {
        Format::B
    } else {
        Format::Second
    }
}

impl Family for G73 {
    fn words(&self, kind: Kind, _: Dialect) -> Words {
        match format(kind) {
            Format::First => FIRST,
            Format::Second => SECOND,
            Format::B => FORMAT_B,
        }
    }
    fn execute(&mut self, st: &mut State, b: &BlockIn, src: &mut Source) -> Result<(), Alarm> {
        let v = b.values;
        match format(b.kind) {
            Format::First => {
                self.kept = Kept { di: v.get(b'U'), dk: v.get(b'W'), d: v.get(b'R') };
                Ok(())
            }
            f => cycle(self.kept, f == Format::B, st, b, src),
        }
    }
}

/// One G73 cycle as checked: A, the contour, the escapes, the count, the allowances, the feed.
#[derive(Clone, Debug)]
struct Cycle {
    a: Point,
    contour: Contour,
    di: i64,
    dk: i64,
    d: i64,
    du: i64,
    dw: i64,
    feed: i64,
    /// The declared reading `g73.c`: whether roughing first retreats to C.
    c: G73C,
    line: u32,
}

/// G73.FORMAT (M003): "Missing words: no feed → `MISSING WORD F` (COM.LEAD); then P, Q
/// (CNT.PQ); in format (b) then I, K, D, each `MISSING WORD`, rule G73.FORMAT. U, W default to
/// 0." Then "Cycle checks (step 5), in order: the contour (CNT.FIND as for G71 …; CNT.MAX; each
/// contour block's checks; CNT.FIRST); the pass bound" — "d greater than `max_passes` is `TOO
/// MANY PASSES` on that word (PRJ.MAXPASS)", R in format (a), D in format (b). G73.USE: "No
/// monotonicity: G73 takes any contour" — unlike G71/G72 no monotone or type check is made.
fn cycle(kept: Kept, format_b: bool, st: &mut State, b: &BlockIn, src: &mut Source) -> Result<(), Alarm> {
    let (v, line) = (b.values, b.line);
    st.take_feed(v);
    let Some(feed) = st.feed else {
        return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
    };
    let (Some(ns), Some(nf)) = (v.get(b'P'), v.get(b'Q')) else {
        let word = if v.get(b'P').is_none() { b'P' } else { b'Q' };
        return Err(alarm(AlarmCode::MissingWord, word, Rule::CntPq, line));
    };
    let params = st.params();
    let (di, dk, d, count_word) = if format_b {
        let word = |w: u8| v.get(w).ok_or(alarm(AlarmCode::MissingWord, w, Rule::G73Format, line));
        (word(b'I')?, word(b'K')?, word(b'D')?, b'D')
    } else {
        let di = kept.di.unwrap_or(params.p5135_escape_x);
        let dk = kept.dk.unwrap_or(params.p5136_escape_z);
        (di, dk, kept.d.unwrap_or(params.p5137_count), b'R')
    };
    st.missing_words_checked()?;
    let a = st.position();
    let blocks = contour::ahead(src, ns, nf, line)?;
    let contour = read(&blocks, a, &Reader { config: st.config, side: st.side })?;
    contour::first(&contour)?;
    if d > params.max_passes {
        return Err(alarm(AlarmCode::TooManyPasses, count_word, Rule::PrjMaxPass, line));
    }
    let du = v.get(b'U').unwrap_or(0);
    let dw = v.get(b'W').unwrap_or(0);
    let c = st.config.readings.g73_c;
    emit(&Cycle { a, contour, di, dk, d, du, dw, feed, c, line }, &mut st.out)
}

/// G73.DEPTH (M003, OPEN): pass n's escape left, "round(Δi·(d − n)/d)" (radius counts) and
/// "round(Δk·(d − n)/d)" — "each radius or Z offset the exact quotient rounded once (half away
/// from zero)".
fn escape(total: i64, d: i64, n: i64) -> i128 {
    round_div(i128::from(total) * i128::from(d - n), i128::from(d))
}

/// G73.DEPTH (M003, OPEN): "Pass n = 1 … d uses the contour translated by T_n = (2·round(Δi·(d −
/// n)/d) + Δu, round(Δk·(d − n)/d) + Δw) (diameter count, Z count)".
fn offset(cy: &Cycle, n: i64) -> (i128, i128) {
    (2 * escape(cy.di, cy.d, n) + i128::from(cy.du), escape(cy.dk, cy.d, n) + i128::from(cy.dw))
}

/// G73 point C (declared reading `g73.c`; `003_…` line 123: "粗加工时刀具从A点后退至C点，后退距离分别
/// 为Δi+Δu/2，Δk+Δw"): C = (A.x + 2·Δi + Δu, A.z + Δk + Δw), diameter count, every word with its
/// sign.
fn point_c(cy: &Cycle) -> Point {
    (cy.a.0 + 2 * i128::from(cy.di) + i128::from(cy.du), cy.a.1 + i128::from(cy.dk) + i128::from(cy.dw))
}

/// G73.PATH (M003, OPEN): under `g73.c=visit` (the letter) one rapid A → C before pass 1's
/// header (not emitted when C = A, PRJ.NOOP); `skip`: none. Then for each pass: "Pass header (index n, kind ROUGH, diameter_depth = |2·round(Δi·(d −
/// n)/d)|, rule G73.DEPTH); one rapid from the current position to A + T_n (G73.PATH); then
/// the contour translated by T_n, block by block in each block's own mode …; arcs about
/// translated centres …. After pass d, one rapid to A (G73.PATH)."
fn emit(cy: &Cycle, out: &mut Out) -> Result<(), Alarm> {
    let (a, line) = (cy.a, cy.line);
    if cy.c == G73C::Visit {
        let c = point_c(cy);
        out.rapid(c.0, c.1, Rule::G73Path, line)?;
    }
    for n in 1..=cy.d {
        let (tx, tz) = offset(cy, n);
        let depth = (2 * escape(cy.di, cy.d, n)).abs();
        out.pass(u32::try_from(n).unwrap_or(u32::MAX), PassKind::Rough, depth, Rule::G73Depth, line)?;
        out.rapid(a.0 + tx, a.1 + tz, Rule::G73Path, line)?;
        // |T_n| ≤ 3N: the offsets fit the contour's i64 translation.
        let (tx, tz) = (i64::try_from(tx).unwrap_or(i64::MAX), i64::try_from(tz).unwrap_or(i64::MAX));
        run(out, &cy.contour.translated(tx, tz), Feed::Roughing(cy.feed), Rule::G73Path, line)?;
    }
    out.rapid(a.0, a.1, Rule::G73Path, line)
}

#[cfg(test)]
mod tests;
