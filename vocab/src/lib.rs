//! Shared vocabulary of the lathe canned-cycle reference.
//!
//! Both engines — the executable reference (`cycle-spec`) and the production expander
//! (`cycle-impl`) — speak these types: lengths on the least-increment grid ([`units`]), the
//! program lexer ([`lex`]), machine parameters and configuration ([`params`]), the trace of
//! moves ([`trace`]), alarms ([`alarm`]) and rule IDs ([`rule`]). The crate is `no_std` without
//! the `std` feature, so the production expander can use it without an allocator.
//!
//! Rule IDs and every interpretation are documented in `docs/RULES.md` and
//! `docs/INTERPRETATION.md`.
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]

pub mod alarm;
pub mod lex;
pub mod params;
pub mod rule;
pub mod trace;
pub mod units;

#[cfg(feature = "std")]
pub mod text;

/// The unit tests' random source (xorshift64).
#[cfg(test)]
fn xorshift(state: &mut u64) -> u64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    *state
}

pub use alarm::{Alarm, AlarmCode};
pub use lex::{letter_bit, letter_mask, Block, Blocks};
pub use params::{Config, Dialect, Params};
pub use rule::Rule;
pub use trace::{Event, Move, MoveKind, Pass, PassKind};
pub use units::{Grid, Increment, Number, Units};
