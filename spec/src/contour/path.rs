//! A contour run as moves: G70's finishing pass (G70.PATH) and the semi-finish pass of G71 and
//! G72 (G71.LASTPASS), each on its (translated) contour.

use super::{Contour, Mode};
use crate::emit::Out;
use cycle_vocab::{Alarm, Rule};

/// The feed of a contour run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Feed {
    /// G71.LASTPASS (M003): "all at the roughing feed"; the contour's F are ignored (CNT.FST).
    Roughing(i64),
    /// G70.FEED (M003): "The feed starts as the F in effect (G70's F, else the modal feed) and
    /// a contour block's F replaces it from that block on."
    Finishing(i64),
}

/// Runs contour `q` from the current position: one move to its first point (the ns block's
/// end) in the ns block's mode, then each later block that has axis words in its own mode —
/// G00 rapid, G01 feed, G02/G03 arcs about their (translated) centres. Every move is tagged
/// `rule`; `line` is the cycle block's (for an alarm on a coordinate beyond the trace's range).
pub fn run(out: &mut Out, q: &Contour, feed: Feed, rule: Rule, line: u32) -> Result<(), Alarm> {
    let (mut f, fixed) = match feed {
        Feed::Roughing(f) => (f, true),
        Feed::Finishing(f) => (f, false),
    };
    for (n, e) in q.elements.iter().enumerate() {
        if let (false, Some(written)) = (fixed, e.feed) {
            f = written;
        }
        // The ns block always leads to the first point: its translation moves it even when the
        // block itself has no axis words.
        if n > 0 && !e.moves {
            continue;
        }
        match (e.mode, e.centre) {
            (Mode::Rapid, _) => out.rapid(e.end.0, e.end.1, rule, line)?,
            (Mode::Arc { cw }, Some(centre)) => out.arc(cw, e.end, centre, f, rule, line)?,
            (Mode::Feed | Mode::Arc { .. }, _) => out.feed(e.end.0, e.end.1, f, rule, line)?,
        }
    }
    Ok(())
}
