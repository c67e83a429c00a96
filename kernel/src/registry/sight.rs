//! Which cycle a case runs, and what a hint needs of the block the reference alarmed on: both
//! read from the program in one pass of the reference's lexer ([`sight`]), which the judge makes
//! once per case and carries in its result (`crate::judge::Judged::sighting`), so counts and
//! hints never read the program again.

use super::{CycleRun, FAMILIES};
use cycle_spec::lex::{self, Block};
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, Config};
use num_traits::ToPrimitive;

/// What one read of a program shows, given how the reference's run of it ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sighting {
    /// The cycle it runs.
    pub cycle: CycleRun,
    /// The whole-number G codes of the block on the line of the reference's alarm (none without
    /// an alarm, or when no block that lexes is on that line): what [`crate::hint`] reads.
    pub alarm_codes: Vec<u64>,
}

/// Reads `program` once, knowing the reference's alarm (`None`: it ended cleanly or failed).
///
/// The cycle is the family of the first block — up to the alarm's line (inclusive: a block that
/// alarms runs its cycle) or the program's end (M02, M30, a lexing error) — whose G codes select
/// a family under the configuration's dialect; [`CycleRun::AlarmFirst`] when the reference
/// alarms before such a block, [`CycleRun::NoCycle`] when it ends without one.
///
/// The blocks are read with the reference's lexer (`cycle_spec::lex`); this is the one place
/// that reads them for the harness.
#[allow(clippy::disallowed_methods)] // the one read
pub fn sight(program: &[u8], config: &Config, alarm: Option<&Alarm>) -> Sighting {
    count();
    let alarm_line = alarm.map(|a| a.line);
    let (mut cycle, mut alarm_codes) = (None, Vec::new());
    for block in lex::blocks(program) {
        let Ok(block) = block else { break };
        if alarm_line.is_some_and(|line| block.line > line) {
            break;
        }
        if Some(block.line) == alarm_line {
            alarm_codes = block.g_codes().filter(|g| !g.point && !g.negative).filter_map(|g| g.mantissa().to_u64()).collect();
        }
        if cycle.is_none() {
            if let Some(f) = block.g_codes().find_map(|g| FAMILIES.iter().find(|f| f.selected_by(g, config.dialect))) {
                cycle = Some(CycleRun::Family(f));
            } else if ends(&block) {
                cycle = Some(unselected(alarm_line.is_some()));
            }
        }
        // Past a decided cycle, only the alarm's block is still wanted (a subprogram after M30
        // may hold it).
        if cycle.is_some() && !matches!(alarm_line, Some(line) if block.line < line) {
            break;
        }
    }
    Sighting { cycle: cycle.unwrap_or_else(|| unselected(alarm_line.is_some())), alarm_codes }
}

/// Whether `block` ends the program (M02, M30).
fn ends(block: &Block) -> bool {
    block.get(b'M').is_some_and(|m| !m.point && !m.negative && matches!(m.mantissa().to_u64(), Some(2 | 30)))
}

/// The row of a case no block of which selects a family.
fn unselected(alarmed: bool) -> CycleRun {
    if alarmed {
        CycleRun::AlarmFirst
    } else {
        CycleRun::NoCycle
    }
}

/// The cycle `program` runs, given the reference's trace (`None`: the reference failed) — for
/// the tests and the snapshot folders; a judged case has it in its sighting.
pub fn cycle_run(program: &[u8], config: &Config, reference: Option<&Trace>) -> CycleRun {
    sight(program, config, reference.and_then(|t| t.alarm.as_ref())).cycle
}

#[cfg(any(test, feature = "test-aids"))]
thread_local! {
    static SIGHTINGS: std::cell::Cell<usize> = const { std::cell::Cell::new(0) };
}

#[cfg(any(test, feature = "test-aids"))]
fn count() {
    SIGHTINGS.with(|n| n.set(n.get() + 1));
}

#[cfg(not(any(test, feature = "test-aids")))]
fn count() {}

/// How many programs this thread has read with [`sight`] (TEST AID: a judged case reads its
/// program once).
#[cfg(any(test, feature = "test-aids"))]
pub fn sightings() -> usize {
    SIGHTINGS.with(std::cell::Cell::get)
}
