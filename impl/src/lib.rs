//! Production expander (in progress).
#![no_std]
use cycle_vocab::{Alarm, Config, Event};

/// Streaming expansion of a program.
pub struct Expander<'a> {
    program: &'a [u8],
    config: Config,
}

impl<'a> Expander<'a> {
    pub fn new(program: &'a [u8], config: Config) -> Expander<'a> {
        Expander { program, config }
    }
}

impl Iterator for Expander<'_> {
    type Item = Result<Event, Alarm>;
    fn next(&mut self) -> Option<Self::Item> {
        let _ = (self.program, self.config);
        None
    }
}
