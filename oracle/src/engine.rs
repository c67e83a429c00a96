//! The engines under comparison, behind one trait (in the style of wasmtime's fuzzing oracles:
//! each engine turns the same input into a comparable result, the oracle compares results).
//!
//! - [`SpecEngine`]: the executable reference, `cycle_spec::expand`.
//! - [`ImplEngine`]: the production expander, `cycle_impl::Expander`, a streaming iterator
//!   collected into a [`Trace`].
//!
//! A third engine — a vendor's expander run as a child process that reads the program and the
//! configuration and prints the JSON trace (`Trace::from_json`) — fits the same trait
//! (`CandidateEngine`); it is not built yet. Whatever goes wrong in such an engine (no output,
//! bad JSON, a crash) would have to become a trace that cannot conform, never a pass.

use cycle_vocab::text::Trace;
use cycle_vocab::Config;

/// An expander of programs into traces.
pub trait Engine {
    /// A short name for reports (`spec`, `impl`).
    fn name(&self) -> &str;
    /// The whole trace of `program` under `config`, ending at the first alarm.
    fn expand(&self, program: &[u8], config: &Config) -> Trace;
}

/// The executable reference spec (`cycle-spec`).
#[derive(Clone, Copy, Debug, Default)]
pub struct SpecEngine;

impl Engine for SpecEngine {
    fn name(&self) -> &str {
        "spec"
    }

    fn expand(&self, program: &[u8], config: &Config) -> Trace {
        cycle_spec::expand(program, config)
    }
}

/// The production expander (`cycle-impl`), collected from its stream of events.
///
/// The stream is read up to `event_limit` events, so that a production expander that never
/// ends cannot hang a campaign: a stream cut there (and not ended by an alarm) is a trace with
/// more events than any reference shorter than the limit, and so diverges from it. The spec
/// bounds every cycle by `max_passes` (PRJ.MAXPASS), far below the default limit for any
/// program of ordinary length.
#[derive(Clone, Copy, Debug)]
pub struct ImplEngine {
    pub event_limit: usize,
}

impl ImplEngine {
    /// The default bound on the events read from the stream.
    pub const DEFAULT_EVENT_LIMIT: usize = 4_000_000;
}

impl Default for ImplEngine {
    fn default() -> ImplEngine {
        ImplEngine { event_limit: ImplEngine::DEFAULT_EVENT_LIMIT }
    }
}

impl Engine for ImplEngine {
    fn name(&self) -> &str {
        "impl"
    }

    fn expand(&self, program: &[u8], config: &Config) -> Trace {
        let stream = cycle_impl::Expander::new(program, *config).take(self.event_limit);
        Trace::collect(config.grid, stream)
    }
}

/// An engine by its CLI name: `spec` or `impl`.
pub fn by_name(name: &str) -> Option<Box<dyn Engine>> {
    match name {
        "spec" => Some(Box::new(SpecEngine)),
        "impl" => Some(Box::new(ImplEngine::default())),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spec_engine_is_the_spec() {
        let p = b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n";
        let c = Config::default();
        assert_eq!(SpecEngine.expand(p, &c), cycle_spec::expand(p, &c));
        assert!(!SpecEngine.expand(p, &c).events.is_empty());
    }

    #[test]
    fn impl_engine_collects_the_stream_on_the_config_grid() {
        let c = Config { grid: cycle_vocab::Grid { units: cycle_vocab::Units::Inch, ..c_grid() }, ..Config::default() };
        let t = ImplEngine::default().expand(b"G0 X1 Z1\n", &c);
        assert_eq!(t.grid, c.grid);
        let direct = Trace::collect(c.grid, cycle_impl::Expander::new(b"G0 X1 Z1\n", c));
        assert_eq!(t, direct);
    }

    fn c_grid() -> cycle_vocab::Grid {
        cycle_vocab::Grid::METRIC_ISB
    }

    #[test]
    fn names() {
        assert_eq!(by_name("spec").unwrap().name(), "spec");
        assert_eq!(by_name("impl").unwrap().name(), "impl");
        assert!(by_name("other").is_none());
    }
}
