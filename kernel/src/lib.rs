//! The kernel of the lathe canned-cycle reference's harness: the engines behind one trait
//! ([`engine`]), the conformance relation and trace diff ([`conformance`]), the rule catalogue as
//! data ([`catalogue`]), the cycle families ([`registry`]), the built-in corpus of the manuals'
//! programs ([`corpus`]), proptest generators of programs and configurations ([`gen`]), and
//! differential campaigns ([`campaign`]) judged case by case in lockstep ([`judge`]). The `cyclecheck` application
//! (`cyclecheck/`: the CLI, certify, the candidate protocol) runs over these; nothing here
//! spawns a process.
//!
//! ```
//! use cycle_kernel::engine::{Engine, SpecEngine};
//! use cycle_vocab::Config;
//! let trace = SpecEngine.expand(b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n", &Config::default());
//! assert!(trace.to_gcode().contains("G32 X58.700 Z-27.000 F3.0000"));
//! assert_eq!(cycle_kernel::conformance::check(&trace, &trace.clone()), Ok(()));
//! ```
#![forbid(unsafe_code)]

pub mod campaign;
pub mod catalogue;
pub mod conformance;
pub mod corpus;
pub mod engine;
pub mod fuzzing;
pub mod gen;
pub mod hint;
pub mod judge;
pub mod operator;
pub mod readings;
pub mod readback;
pub mod registry;
pub mod spec_alone;

pub use conformance::{check, Divergence, DivergenceKind};
pub use engine::{Engine, ImplEngine, SpecEngine};
