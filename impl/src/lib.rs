//! Production expander of the lathe thread cycles G92, G76, G78 and FANUC-style G76
//! (in progress: the depth schedule and the fixed-point helpers are in place).
#![no_std]
#![forbid(unsafe_code)]

pub mod fixed;
pub mod schedule;

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
