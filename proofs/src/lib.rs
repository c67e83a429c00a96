//! Proof harnesses for the production expander (`cycle-impl`).
//!
//! Each harness is one generic body over a [`source::Source`], used three ways: a Kani proof
//! (`#[kani::proof]`, symbolic values, run by vendors with `cargo kani`), a bounded-exhaustive
//! test and a random test (both under `cargo test`, so CI executes every body). See
//! `proofs/README.md` for the properties, bounds and commands.
#![forbid(unsafe_code)]

pub use cycle_harness::{check, cover};

pub mod program;
pub mod source;
pub mod model;
pub mod schedule;
pub mod schedule_parts;

pub mod depth_bounds;
pub mod depth_step_monotone;
pub mod depth_step_clamp;
pub mod depth_step;
pub mod schedule_step;
pub mod schedule_count;
pub mod schedule_new_shape;
pub mod g71_layers;
pub mod fixed_point;
pub mod mutation;
pub mod expander_envelope;
pub mod g92_pullout;
pub mod g162_split;
pub mod g162_pitch;
pub mod g90_envelope;
pub mod peck_counts;
pub mod g92_pullout_geometry;
pub mod hold_retract;
#[cfg(not(kani))]
pub mod schedule_spec;

pub mod invariants;
pub mod trace_depths;
