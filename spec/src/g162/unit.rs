//! G162 (M004) as a family of the interpreter, under `nc201`: a one-shot code; its words
//! (G162.FORMAT) and missing words in the register's order.

use super::{expand, G162Block};
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::words::{alarm, Read, F, N, X};
use cycle_vocab::{Alarm, AlarmCode, Dialect, Rule};

/// G162 has no memory of its own (H is not modal; F is the shared modal feed).
#[derive(Debug, Default)]
pub struct G162;

/// G162.FORMAT (M004): `G162 X Z H [P Q] [V] [W] [A] [F] [B] [I] [J]`, each word read as the
/// register's table says (X and W by `x_radius`).
const WORDS: Words = Words::of(&[
    (b'A', Read::Tenths),
    (b'B', Read::Millidegrees { lo: 0, hi: 360_000, rule: Rule::G162B }),
    F,
    (b'H', Read::Feed { hi: N, rule: Rule::G162H }),
    (b'I', Read::SignedLead { rule: Rule::G162I }),
    (b'J', Read::Millidegrees { lo: 1, hi: N, rule: Rule::G162J }),
    (b'P', Read::Length { lo: 1, hi: N }),
    (b'Q', Read::Length { lo: 1, hi: N }),
    (b'V', Read::Length { lo: 0, hi: N }),
    (b'W', Read::XLength),
    X,
    (b'Z', Read::Length { lo: -N, hi: N }),
]);

impl Family for G162 {
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }

    /// G162 (M004): F sets the modal feed; without F the modal feed is the lead (G162.F).
    /// Missing words in the register's order: F, H, P/Q (a pair), X, Z.
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        let (v, line) = (b.values, b.line);
        let missing = |word: u8, rule: Rule| Err(alarm(AlarmCode::MissingWord, word, rule, line));
        st.take_feed(v);
        let Some(lead) = st.feed else { return missing(b'F', Rule::G162F) };
        let Some(h) = v.get(b'H') else { return missing(b'H', Rule::G162H) };
        let depth = match (v.get(b'P'), v.get(b'Q')) {
            (Some(p), Some(q)) => Some((p, q)),
            (None, Some(_)) => return missing(b'P', Rule::G162Pq),
            (Some(_), None) => return missing(b'Q', Rule::G162Pq),
            (None, None) => None,
        };
        let (x, z) = st.end_point(v);
        let Some(x0) = x else { return missing(b'X', Rule::G162Format) };
        let Some(ze) = z else { return missing(b'Z', Rule::G162Format) };
        let cycle = G162Block {
            s: st.position(),
            x0,
            ze,
            h,
            depth,
            v: v.get(b'V').unwrap_or(0),
            wd: v.get(b'W').unwrap_or(0) as i128,
            a_tenths: v.get(b'A').unwrap_or(0),
            lead,
            b: v.get(b'B').unwrap_or(0),
            i: v.get(b'I').unwrap_or(0),
            j: v.get(b'J').unwrap_or(360_000),
            line,
        };
        expand(&cycle, st.config, &mut st.out)
    }
}
