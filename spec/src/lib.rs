//! Executable reference spec of the lathe canned cycles: the thread cycles G92 (M002), G76
//! (M001, M003 FANUC-style), G78 (M000) and G162 (M004), the thread moves G32, G33, G34, the
//! single cutting cycles G90, G94, arcs G02/G03 and the contour cycles G70, G71, G72 (M003).
//!
//! A certification reference: clarity first, exact integer arithmetic, each rule a small
//! function whose doc comment names its rule ID (`docs/RULES.md`) and source manual key. Every
//! choice the manuals leave open is the one recorded in `docs/INTERPRETATION.md`.
//!
//! | module | rules |
//! |---|---|
//! | [`config`] | COM.RANGES of the start point, parameter ranges (line 0) |
//! | [`program`], [`step2`] | PRJ.MODAL, PRJ.WORD, PRJ.SUPPORTED, PRJ.DIALECT, COM.ABSINC, G163, check order |
//! | [`family`] | the one interface of the cycle families and their table |
//! | [`lex`] | PRJ.LEX, PRJ.WORD: the spec's own reader of program text |
//! | [`words`] | COM.UNITS, COM.RANGES, COM.LEAD, F76.MICRONS: exact values of words |
//! | [`exact`], [`tangent`] | the rounding rule: half up, once, on exact values |
//! | [`g92`] | G92.* |
//! | [`pullout`] | G92.PULLOUT, G76.PULLOUT, G78.PULLOUT geometry, COM.LONGAXIS |
//! | [`multipass`] | G76.*, G78.*, F76.*, PRJ.MAXPASS |
//! | [`g162`] | G162.* (M004, `nc201`), NC201.* in [`program`] |
//! | [`thread_moves`] | G32, G33, G34 (M003) |
//! | [`g90`], [`g94`], [`single_cut`] | G90.*, G94.* (M003): single cutting cycles and their runs |
//! | [`g50`], [`tnrc`] | G50.COORD, G50.SMAX; TNRC.* (M003): the program words of the contour cycles |
//! | [`spindle`] | G50.SMAX, G96.SPEED, G96.SMAX, G96.RAPID (M003): the spindle state |
//! | [`sub`] | SUB.CALL, SUB.FIND, SUB.RETURN, SUB.NEST, PRJ.MAXPASS: subprograms M98, M99 |
//! | [`arc`] | ARC.* (M003): G02/G03, their centres, the tolerance, the sweep |
//! | [`contour`] | CNT.* (M003): finding, checking and running the contour N(ns) … N(nf) |
//! | [`g70`] | G70.* (M003): finishing |
//! | [`g71`], [`g72`], [`stock_removal`] | G71.*, G72.* (M003): stock removal in layers |
//! | [`g73`] | G73.* (M003): pattern repeating, both formats |
//! | [`g74`], [`g75`], [`grooving`] | G74.*, G75.* (M003): peck drilling and grooving |
//! | [`g83`], [`g84`] | G83.*, G84.*, G80 (M003): peck drilling and rigid tapping |
//! | [`emit`] | PRJ.TRACE, PRJ.NOOP, COM.MULTISTART |
//! | [`operator`] | OP.*, G92.HOLD, G92.SINGLE, G92.RESET, G76.HOLD, G76.SINGLE, G162.NOSTOP |
#![forbid(unsafe_code)]

pub mod arc;
pub mod config;
pub mod contour;
pub mod emit;
pub mod exact;
pub mod family;
pub mod g162;
pub mod g50;
pub mod g70;
pub mod g71;
pub mod g72;
pub mod g73;
pub mod g74;
pub mod g75;
pub mod g83;
pub mod g84;
pub mod g90;
pub mod g94;
pub mod g92;
pub mod grooving;
pub mod lex;
pub mod multipass;
pub mod operator;
pub mod program;
pub mod pullout;
pub mod single_cut;
pub mod spindle;
pub mod step2;
pub mod stock_removal;
pub mod sub;
pub mod tangent;
pub mod thread_moves;
pub mod tnrc;
pub mod words;

use core::ops::ControlFlow;
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, Config, Event};

/// Expands a whole program into its trace. Stops at the first alarm, keeping the events emitted
/// before it. Never panics; resource use is bounded by the program length and `max_passes`
/// (PRJ.MAXPASS, checked before any motion of a cycle and before a subprogram call, whose runs
/// it bounds: SUB.NEST).
pub fn expand(program: &[u8], config: &Config) -> Trace {
    let mut events = Vec::new();
    let alarm = expand_into(program, config, &mut |e| {
        events.push(e);
        ControlFlow::Continue(())
    });
    Trace { grid: config.grid, events, alarm }
}

/// Expands a program event by event: each event of the trace goes to `sink` as it is
/// emitted, and the alarm that ends the trace, if any, is returned. Nothing is collected, so
/// memory does not grow with the trace. When `sink` answers `Break` it gets no further event
/// and the expansion stops after the block it is in (the result is then `None`, unless that
/// block itself ended in an alarm).
///
/// With an operator script in `config` (OP.SCRIPT) the events are those of the interrupted run:
/// the uninterrupted trace U is expanded whole first, then played under the script
/// ([`operator`]); a sink's `Break` then ends the run with `None`.
pub fn expand_into(program: &[u8], config: &Config, sink: &mut dyn FnMut(Event) -> ControlFlow<()>) -> Option<Alarm> {
    if let Err(a) = config::check(config) {
        return Some(a);
    }
    if !config.operator.is_empty() {
        // OP.SCRIPT: the interrupted run, played over U.
        return operator::play(program, config, sink);
    }
    let mut machine = program::Machine::new(config, sink);
    run_blocks(program, &mut machine)
}

/// Runs every block of `program` on `machine` — the main program and the subprograms it calls
/// ([`sub`]) — up to the program's end, its first alarm, or the block in which the sink stopped.
fn run_blocks(program: &[u8], machine: &mut program::Machine) -> Option<Alarm> {
    sub::run(program, machine)
}

#[cfg(test)]
mod tests;
