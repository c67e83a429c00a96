//! Shared vocabulary of the lathe canned-cycle reference.
//!
//! Both engines — the executable reference (`cycle-spec`) and the production expander
//! (`cycle-impl`) — speak these types: the least-increment grid ([`units`]), machine parameters
//! and configuration ([`params`]), the trace of moves ([`trace`]), alarms ([`alarm`]) and rule
//! IDs ([`rule`]). Types only: each engine reads programs with its own lexer and number reader,
//! and keeps its own parameter defaults and ranges, so the differential campaigns check those
//! too. The crate is `no_std` without the `std` feature, so the production expander can use it
//! without an allocator.
//!
//! Rule IDs and every interpretation are documented in `docs/RULES.md` and
//! `docs/INTERPRETATION.md`.
#![cfg_attr(not(feature = "std"), no_std)]
#![forbid(unsafe_code)]

pub mod alarm;
pub mod operator;
pub mod params;
pub mod readings;
pub mod rule;
pub mod trace;
pub mod units;

#[cfg(feature = "std")]
pub mod text;

pub use alarm::{Alarm, AlarmCode};
pub use params::{Config, Dialect, Params};
pub use readings::Readings;
pub use rule::Rule;
pub use operator::{Action, Along, Script};
pub use trace::{Button, Dwell, Event, Move, MoveKind, Pass, PassKind, Press, Resume, Spindle, SpindleState, Stop, StopReason};
pub use units::{Grid, Increment, Units};
