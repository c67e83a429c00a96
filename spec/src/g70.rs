//! G70 — finishing along the contour (M003), under `gsk` and `fanuc`.
//!
//! `G70 P(ns) Q(nf) [U W] [F]`: the tool runs the contour N(ns) … N(nf), which stands before the
//! G70 block (CNT.FIND), translated by (U, W), as ordinary moves from the G70 start point S, then
//! returns to S at rapid (docs/INTERPRETATION.md, "G70 (finishing)"). One-shot: the motion mode
//! stays; the modal feed afterwards is G70's F if written (CYC.ONESHOT, CNT.MODAL). The program
//! goes on after the G70 block (CNT.FLOW).

use crate::contour::block::{read, Reader};
use crate::contour::path::{run, Feed};
use crate::contour::{self, Contour, Point};
use crate::emit::Out;
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::words::{alarm, Read, F, U, W};
use cycle_vocab::{Alarm, AlarmCode, Dialect, PassKind, Rule};

/// G70 as a family of the interpreter: a one-shot code.
#[derive(Debug, Default)]
pub struct G70;

/// CNT.PQ (M003): "P(ns) and Q(nf) … are integers (`NOT INTEGER`, COM.RANGES) in 1 … 99 999
/// (`OUT OF RANGE`, rule CNT.PQ)".
pub const P: (u8, Read) = (b'P', Read::Integer { lo: 1, hi: 99_999, rule: Rule::CntPq });
pub const Q: (u8, Read) = (b'Q', Read::Integer { lo: 1, hi: 99_999, rule: Rule::CntPq });

/// G70.FORMAT, G70.UW (M003, OPEN): "Words P Q U W F S T"; U (a diameter) and W signed
/// lengths, |v| ≤ N, default 0.
const WORDS: Words = Words::of(&[F, P, Q, U, W]);

impl Family for G70 {
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }

    /// G70.FORMAT (M003): missing words — "no feed (neither F nor a modal feed) → `MISSING WORD
    /// F` (COM.LEAD), then P, Q (CNT.PQ)"; then the cycle checks, "find the contour (CNT.FIND
    /// for G70, CNT.MAX); each contour block's checks; CNT.FIRST. No monotonicity"; then the
    /// pass.
    fn execute(&mut self, st: &mut State, b: &BlockIn, src: &mut Source) -> Result<(), Alarm> {
        let (v, line) = (b.values, b.line);
        st.take_feed(v);
        let Some(feed) = st.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        let Some(ns) = v.get(b'P') else {
            return Err(alarm(AlarmCode::MissingWord, b'P', Rule::CntPq, line));
        };
        let Some(nf) = v.get(b'Q') else {
            return Err(alarm(AlarmCode::MissingWord, b'Q', Rule::CntPq, line));
        };
        st.missing_words_checked()?;
        let s = st.position();
        let blocks = contour::behind(src, ns, nf, line)?;
        let c = read(&blocks, s, &Reader { config: st.config, side: st.side })?;
        contour::first(&c)?;
        let p = c.translated(v.get(b'U').unwrap_or(0), v.get(b'W').unwrap_or(0));
        finish(&mut st.out, s, &p, feed, line)
    }
}

/// G70.PATH, G70.FEED, G70.RETURN (M003): "Pass header index 1, kind FINISH, diameter_depth =
/// |S.x − P₀.x| (P₀ = the ns block's end translated), rule G70.PATH; then each contour block,
/// translated by (U, W), as an ordinary move in its mode from the current position"; "One rapid
/// back to S, rule G70.RETURN".
pub fn finish(out: &mut Out, s: Point, p: &Contour, feed: i64, line: u32) -> Result<(), Alarm> {
    out.pass(1, PassKind::Finish, (s.0 - p.ns().end.0).abs(), Rule::G70Path, line)?;
    run(out, p, Feed::Finishing(feed), Rule::G70Path, line)?;
    out.rapid(s.0, s.1, Rule::G70Return, line)
}
