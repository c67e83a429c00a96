//! Comparison levels: how much of a trace the relation compares. A candidate that emits less
//! than a whole trace — a third-party expander that knows moves but no pass headers — declares
//! a level in its greeting (`docs/CANDIDATE.md`); the relation then compares what that level
//! names, and every report names the level. In-process engines are compared at [`Level::Full`].

use cycle_vocab::Event;
use std::fmt;

/// What the relation compares, strongest first. Ordered weakest first (`Full` is the greatest),
/// so `declared < required` reads "declares less than asked".
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Level {
    /// Only whether the trace ends in an alarm, and the moves as [`Level::Motion`].
    MotionAlarmPresence,
    /// Only the moves (rapid, feed, thread, arcs; every field of each), and the alarm's code.
    Motion,
    /// Every event, field by field, and the alarm's code, word, line and rule.
    #[default]
    Full,
}

impl Level {
    /// Every level, strongest first.
    pub const ALL: [Level; 3] = [Level::Full, Level::Motion, Level::MotionAlarmPresence];

    /// Its name in the greeting, on the command line and in reports: `full`, `motion`,
    /// `motion-alarm-presence`.
    pub const fn name(self) -> &'static str {
        match self {
            Level::Full => "full",
            Level::Motion => "motion",
            Level::MotionAlarmPresence => "motion-alarm-presence",
        }
    }

    /// The level named `name`.
    pub fn parse(name: &str) -> Result<Level, String> {
        Level::ALL.into_iter().find(|l| l.name() == name).ok_or_else(|| {
            let names: Vec<&str> = Level::ALL.iter().map(|l| l.name()).collect();
            format!("unknown comparison level {name:?} (one of {})", names.join(", "))
        })
    }

    /// Whether the relation at this level compares `e`: every event at `full`, moves only below.
    pub fn compares(self, e: &Event) -> bool {
        self == Level::Full || matches!(e, Event::Move(_))
    }

    /// What the level compares, in one sentence for reports.
    pub const fn describe(self) -> &'static str {
        match self {
            Level::Full => "every event and the alarm, field by field",
            Level::Motion => {
                "the moves only (rapid, feed, thread, arcs, every field); pass headers, dwell, spindle and operator events dropped from both traces; the alarm by its code"
            }
            Level::MotionAlarmPresence => {
                "the moves only (rapid, feed, thread, arcs, every field); pass headers, dwell, spindle and operator events dropped from both traces; only whether the trace ends in an alarm"
            }
        }
    }
}

impl fmt::Display for Level {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

#[cfg(test)]
mod tests;
