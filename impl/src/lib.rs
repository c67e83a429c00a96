//! Production expander of the lathe thread cycles G92, G76, G78, FANUC-style G76 and G162
//! (`nc201`), of the thread moves G32, G33, G34, of the single cutting cycles G90, G94, of arcs
//! G02/G03, of the contour cycles G70, G71, G72 and of the canned cycles G73, G74, G75, G83, G84
//! (M003).
//!
//! `no_std`, no heap, no floating point, no `unsafe`, no panics: [`Expander`] is a streaming
//! iterator over the trace events of a program (PRJ.TRACE), computed on the integer grid with
//! exact fixed-point arithmetic ([`fixed`]); [`Expander::fill`] writes the same stream into a
//! caller's buffer, a whole start of a cycle at a time. The rules and every interpretation are those of
//! `docs/RULES.md` and `docs/INTERPRETATION.md`; each rule-implementing function cites its ID.
//!
//! **Modules**, in layers: a module imports only from its own layer or an earlier one, never
//! from this crate root, and no import circle runs between modules:
//! 1. Foundations: [`fixed`] (exact integer helpers, the tangent table), [`number`] (numbers as
//!    written, scaled exactly), [`lex`] (the program lexer), `words` (word values and ranges),
//!    [`config`] (parameters, the configuration and script checks), [`family`] (the cycle
//!    families' G codes), `batch` (the batch path's units written in place).
//! 2. Geometry and plans: [`schedule`] (rough-pass depths), [`pullout`], [`arc`] (G02/G03),
//!    [`contour`] (the contour buffer), `passes` (a G76/G78 pass and the pass plan), `emit` (a
//!    move as an event, PRJ.NOOP; the per-pass move state machine of G92/G76/G78).
//! 3. The generators, one per cycle: `g92`, `multipass` (G76/G78), [`g162`], `thread_move`
//!    (G32/G33/G34), [`g90`] (G90/G94), [`rough`] (G71/G72), `finish` (G70), `g73`, [`g74`]
//!    (G74/G75), `g83`, `g84`.
//! 4. `run` (the enum of everything that runs) and `sub` (subprograms M98/M99: the call stack,
//!    the area and its search).
//! 5. `modal`: the block interpreter and the check order, one block in, what it runs out; it
//!    finds a cycle code's family in [`family::FAMILIES`].
//! 6. `stream`: the uninterrupted expansion (blocks in, events out).
//! 7. `operator`: operator events (feed hold, cycle start, single block, reset — OP.SCRIPT)
//!    between the stream and the caller.
//! 8. `expander`: [`Expander`], the stream through the operator layer.
//!
//! **Memory.** An [`Expander`] holds the block being read (~0.5 KB), the machine state, what
//! runs, the subprogram call stack (`sub`: 4 frames, 248 bytes; SUB.NEST), and the contour
//! buffer of the contour cycles: [`contour::MAX_BLOCKS`] (CNT.MAX, 1 000) elements of 48 bytes,
//! 48 000 bytes, initialised on the first contour cycle (a program without one writes none of
//! it; G73 shares it). Nothing else grows with the program:
//! the canned cycles keep O(1) state (their pass, column, peck) and count their passes in closed
//! form before any motion. The operator layer (`operator`, OP.SCRIPT) holds its script
//! (16 actions), the events of one cut (`emit::START_EVENTS` = 7, for the repeat after a
//! G92.HOLD/G76.HOLD retract), one event of look-ahead and an output queue of 8 events:
//! 2 344 bytes, fixed.
//!
//! **Magnitudes.** Every word and parameter is at most N = 999 999 999 < 2^30 increments
//! (COM.RANGES) and the start point too, so a block moves the machine by at most N from where it
//! stands (an absolute word puts it within N of 0; a cycle returns to its start after excursions
//! below 2^52): after B blocks every position is below (B + 1)·N, under 2^61 for any program of
//! fewer than 2^31 blocks (over 20 GB of text; B counts the blocks run — a subprogram's once per
//! run, at most `max_passes` runs, PRJ.MAXPASS). The arithmetic is written, and its bounds proved
//! in each module, for positions below 2^62; beyond, it saturates (never wraps, never panics).
#![no_std]
#![forbid(unsafe_code)]
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::indexing_slicing,
        clippy::panic,
        clippy::unreachable,
        clippy::float_arithmetic
    )
)]

pub mod arc;
pub mod config;
pub mod contour;
mod batch;
mod emit;
mod expander;
pub mod family;
mod finish;
pub mod fixed;
/// Public (hidden) only so that the proof harness `g73_passes` (`cycle-proofs`) can drive one G73
/// cycle below the lexer; not part of the API.
#[doc(hidden)]
pub mod g73;
/// G74/G75 peck cycles (public for the proof harness `peck_counts`).
pub mod g74;
/// G83 peck drilling: public (hidden) only for the proof harness `g83_peck_step` (`cycle-proofs`).
#[doc(hidden)]
pub mod g83;
mod g84;
pub mod g162;
/// Public (hidden) only so that the proof harnesses (`cycle-proofs`) can drive one G90/G94 cycle
/// below the lexer; not part of the API.
#[doc(hidden)]
#[allow(clippy::new_without_default)]
pub mod g90;
mod g92;
pub mod lex;
mod modal;
mod multipass;
pub mod number;
mod operator;
mod passes;
#[cfg(test)]
mod probe;
/// Public (hidden) only so that the proof harnesses (`cycle-proofs`) can check the G92 pull-out
/// amounts and geometry below the lexer; not part of the API.
#[doc(hidden)]
pub mod pullout;
/// Public (hidden) only so that the proof harnesses (`cycle-proofs`) can drive one G71/G72 cycle's
/// layer schedule below the lexer (`g71_layers`); not part of the API.
#[doc(hidden)]
pub mod rough;
mod run;
pub mod schedule;
mod stream;
mod sub;
mod thread_move;
mod words;

pub use expander::Expander;
/// The feed-hold retract as a pure function (G92.HOLD, G76.HOLD), for the proofs.
pub use operator::geometry as hold_geometry;
/// N: the largest length of any word or parameter, increments (COM.RANGES).
pub use words::MAX_LENGTH;

#[cfg(test)]
mod tests;
