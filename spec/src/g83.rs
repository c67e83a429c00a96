//! G83 — peck drilling along Z (M003), under `gsk` and `fanuc`, "read as FANUC lathe controls
//! (code system A) do" (docs/INTERPRETATION.md, "G83 and G84").
//!
//! `G83 Z(W) R Q P F`: from the initial level I (the Z when the block is read) a rapid to the R
//! level I + R, then pecks of Q toward the bottom, each followed (but the last) by a rapid back
//! to the R level and a rapid down to the depth reached; a dwell of P ms at the bottom; a rapid
//! to the initial level (G83.PECK). Drilling at the current X only. One-shot (CYC.ONESHOT). The
//! seed's line `G83Z-30R0.5Q2000F0.2` is `corpus/g83_example.nc`.

use crate::emit::Out;
use crate::family::{BlockIn, Family, Kind, Source, State, Values, Words};
use crate::grooving::stops;
use crate::words::{alarm, Read, F, N, W, Z};
use cycle_vocab::{Alarm, AlarmCode, Dialect, PassKind, Rule};

/// G83 as a family of the interpreter: a one-shot code without memory.
#[derive(Debug, Default)]
pub struct G83;

/// "R (OPEN). … Length, |R| ≤ N."
pub const R: (u8, Read) = (b'R', Read::Length { lo: -N, hi: N });

/// "P (OPEN). The dwell at the bottom in ms, an integer 0 … 99 999 999 (`NOT INTEGER` with a
/// point); omitted 0 (no dwell event)."
pub const P: (u8, Read) = (b'P', Read::Integer { lo: 0, hi: 99_999_999, rule: Rule::ComRanges });

/// "Q (OPEN units). The peck depth, an integer in the least increment …, 1 … N; a decimal point
/// is `NOT INTEGER` (COM.RANGES). G83 without Q (or Q0) drills in one feed to the bottom" — so
/// Q0 is legal and means no pecking: 0 … N.
const Q: (u8, Read) = (b'Q', Read::Integer { lo: 0, hi: N, rule: Rule::ComRanges });

/// "Words. G83: Z (W) R Q P F (and G N O M S T) … X, U, C, K, and anything else: `WORD NOT
/// ALLOWED`."
const WORDS: Words = Words::of(&[F, P, Q, R, W, Z]);

impl Family for G83 {
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }

    /// Step 4: no feed → `MISSING WORD F` (COM.LEAD). Step 5 (G83.FORMAT): "c = 0 (the bottom at
    /// the R level) is `GEOMETRY` on Z, rule G83.FORMAT; then the pass bound": "Pecks >
    /// `max_passes`: `TOO MANY PASSES` on Q". Then the path.
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        let (v, line) = (b.values, b.line);
        st.take_feed(v);
        let Some(feed) = st.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        st.missing_words_checked()?;
        let lv = Levels::of(st, v);
        if lv.c() == 0 {
            return Err(alarm(AlarmCode::Geometry, b'Z', Rule::G83Format, line));
        }
        let q = i128::from(v.get(b'Q').unwrap_or(0));
        let peck = if q == 0 { lv.depth() } else { q };
        if (lv.depth() + peck - 1) / peck > i128::from(st.params().max_passes) {
            return Err(alarm(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass, line));
        }
        let ms = v.get(b'P').unwrap_or(0);
        drill(&lv, peck, feed, ms, &mut st.out, line)
    }
}

/// The levels of a drilling cycle (G83, G84), increments: the X drilled at, "The initial level
/// I = the Z when the block is read", "R level = I + R; R omitted is 0", "the bottom E.z from Z
/// (absolute) or W (incremental)" — an omitted Z (W) leaves the bottom at I, as an omitted
/// axis is the current one everywhere.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Levels {
    pub x: i128,
    pub initial: i128,
    pub r: i128,
    pub bottom: i128,
}

impl Levels {
    pub fn of(st: &State, v: &Values) -> Levels {
        let (x, initial) = st.position();
        let bottom = st.end_point(v).1.unwrap_or(initial);
        Levels { x, initial, r: initial + i128::from(v.get(b'R').unwrap_or(0)), bottom }
    }
    /// "c = the sign of E.z − (I + R)".
    pub fn c(&self) -> i128 {
        (self.bottom - self.r).signum()
    }
    /// |E.z − R level|, the drilled depth.
    pub fn depth(&self) -> i128 {
        (self.bottom - self.r).abs()
    }
}

/// G83.PECK (M003, OPEN path): "One pass header (index 1, ROUGH, diameter_depth = 2·|E.z − R
/// level|, rule G83.PECK)"; "rapid to the R level (Z only); then pecks: peck k feeds from the R
/// level (k = 1) or from the previous peck's depth (k > 1, after a rapid from the R level back
/// down to it) to R + c·k·Q, the last exactly to E.z; after every peck but the last a rapid back
/// to the R level; at the bottom the dwell (if P > 0); then a rapid to the initial level". Every
/// event is tagged G83.PECK.
fn drill(lv: &Levels, peck: i128, feed: i64, ms: i64, out: &mut Out, line: u32) -> Result<(), Alarm> {
    let rule = Rule::G83Peck;
    out.pass(1, PassKind::Rough, 2 * lv.depth(), rule, line)?;
    out.rapid(lv.x, lv.r, rule, line)?;
    let mut reached = None;
    for depth in stops(lv.r, lv.bottom, peck) {
        if let Some(previous) = reached {
            out.rapid(lv.x, previous, rule, line)?;
        }
        out.feed(lv.x, depth, feed, rule, line)?;
        if depth != lv.bottom {
            out.rapid(lv.x, lv.r, rule, line)?;
        }
        reached = Some(depth);
    }
    if ms > 0 {
        out.dwell(u32::try_from(ms).unwrap_or(u32::MAX), rule);
    }
    out.rapid(lv.x, lv.initial, rule, line)
}
