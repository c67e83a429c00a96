//! Executable reference spec of the lathe thread-cycle rules (in progress).
use cycle_vocab::text::Trace;
use cycle_vocab::Config;

/// Expands a whole program into its trace.
pub fn expand(program: &[u8], config: &Config) -> Trace {
    let _ = program;
    Trace { grid: config.grid, events: Vec::new(), alarm: None }
}
