//! G84 — rigid tapping along Z (M003), under `gsk` and `fanuc`, "read as FANUC lathe controls
//! (code system A) do" (docs/INTERPRETATION.md, "G83 and G84").
//!
//! `M29 S…; G84 Z(W) R P F`: from the initial level a rapid to the R level, a synchronized move
//! to the bottom, a dwell, the spindle reversed, the synchronized move back, the spindle forward
//! again, a rapid to the initial level (G84.PATH). Rigid tapping only (M29, G84.FORMAT). The
//! lead is F under G99, F / S under G98 (S the rpm in force under G97). One-shot (CYC.ONESHOT). The seed's line
//! `G98M29S60G84Z-21R2F60G80` is `corpus/g84_example.nc`.

use crate::exact::round_div;
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::g83::{Levels, P, R};
use crate::words::{alarm, F, W, Z};
use cycle_vocab::{Alarm, AlarmCode, Dialect, PassKind, Rule, SpindleState};

/// G84 as a family of the interpreter; its state (M29, G98/G99, S) is the machine's
/// ([`crate::family::Tapping`]).
#[derive(Debug, Default)]
pub struct G84;

/// "Words. … G84: Z (W) R P F. X, U, C, K, and anything else: `WORD NOT ALLOWED`."
const WORDS: Words = Words::of(&[F, P, R, W, Z]);

impl Family for G84 {
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }

    /// Step 4: "No feed → `MISSING WORD F`". Step 5 in the register's order: M29 (G84.FORMAT),
    /// the lead (under G98 the spindle speed S), "c = 0 (the bottom at the R level) is
    /// `GEOMETRY` on Z". Then G84.PATH; "The rigid-tapping mode ends after the cycle."
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        let (v, line) = (b.values, b.line);
        st.take_feed(v);
        let Some(feed) = st.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        st.missing_words_checked()?;
        if !st.tapping.rigid {
            return Err(alarm(AlarmCode::Unsupported, b'G', Rule::G84Format, line));
        }
        let lead = lead(st, feed, line)?;
        let lv = Levels::of(st, v);
        if lv.c() == 0 {
            return Err(alarm(AlarmCode::Geometry, b'Z', Rule::G84Format, line));
        }
        tap(&lv, lead, v.get(b'P').unwrap_or(0), st, line)?;
        st.tapping.rigid = false;
        Ok(())
    }
}

/// G84.FORMAT (M003, OPEN): "under G99 (feed per revolution, the default mode) the lead is F;
/// under G98 (feed per minute) it is F / S exactly (F = lead × speed, the seed), rounded once to
/// the lead grid"; S is "the rpm in force" — the last S written under G97, never a G50 S nor a
/// G96 S; under G96 `UNSUPPORTED` on G ([`crate::spindle::Spindle::tapping_rpm`]). A decimal point
/// in S was `NOT INTEGER` where it was written. A lead that rounds to 0 (F < S/2 lead counts) is
/// no lead: `OUT OF RANGE` on F, rule G84.FORMAT.
fn lead(st: &State, feed: i64, line: u32) -> Result<i64, Alarm> {
    if !st.tapping.per_minute {
        return Ok(feed);
    }
    let s = st.spindle.tapping_rpm(line)?;
    let lead = round_div(i128::from(feed), i128::from(s));
    match i64::try_from(lead) {
        Ok(l) if l > 0 => Ok(l),
        _ => Err(alarm(AlarmCode::OutOfRange, b'F', Rule::G84Format, line)),
    }
}

/// G84.PATH (M003, OPEN): "rapid to the R level; one synchronized thread move (the lead, angle
/// 0) to the bottom; the dwell (if P > 0); a spindle event REVERSE; one synchronized thread move
/// back to the R level at the same lead; a spindle event FORWARD; a rapid to the initial level.
/// One pass header (index 1, ROUGH, diameter_depth = 2·|E.z − R level|, rule G84.PATH)", first.
fn tap(lv: &Levels, lead: i64, ms: i64, st: &mut State, line: u32) -> Result<(), Alarm> {
    let (out, rule) = (&mut st.out, Rule::G84Path);
    out.pass(1, PassKind::Rough, 2 * lv.depth(), rule, line)?;
    out.rapid(lv.x, lv.r, rule, line)?;
    out.thread(lv.x, lv.bottom, lead, 0, rule, line)?;
    if ms > 0 {
        out.dwell(u32::try_from(ms).unwrap_or(u32::MAX), rule);
    }
    out.spindle(SpindleState::Reverse, rule);
    out.thread(lv.x, lv.r, lead, 0, rule, line)?;
    out.spindle(SpindleState::Forward, rule);
    out.rapid(lv.x, lv.initial, rule, line)
}
