//! Proof harnesses for the production expander (`cycle-impl`).
//!
//! Each property is one generic body over a [`source::Source`], stated once with
//! [`cycle_harness::property!`]: its bounded-exhaustive and random tests (under `cargo test`, so
//! CI executes every body), its Kani harness (`cfg(kani)`; a proof where Kani reached a measured
//! verdict) and its entry in [`PROPERTIES`]. See `proofs/README.md` for the properties, bounds
//! and commands.
#![forbid(unsafe_code)]

pub use cycle_harness::{check, cover, CheckedBy, Property};

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
pub mod g71_layer_step;
pub mod g73_passes;
pub mod fixed_point;
pub mod mutation;
pub mod expander_envelope;
pub mod g92_pullout;
pub mod g162_split;
pub mod g162_split_target;
pub mod g162_split_step;
pub mod g162_pitch;
pub mod g90_envelope;
pub mod peck_counts;
pub mod g92_pullout_geometry;
pub mod hold_retract;
pub mod peck_parts;
pub mod g74_peck_step;
pub mod g83_peck_step;
pub mod peck_toward;
#[cfg(not(kani))]
pub mod schedule_spec;

pub mod invariants;
pub mod trace_depths;

/// Every property of this crate, in the order the certify page lists them. Each module's
/// `property!` states its entry; this list is the only place they are gathered (each property's
/// tests fail when it is missing here).
pub const PROPERTIES: &[Property] = &[
    depth_step_clamp::PROPERTY,
    g90_envelope::PROPERTY,
    g92_pullout_geometry::PROPERTY,
    hold_retract::PROPERTY,
    schedule_step::PROPERTY,
    schedule_count::PROPERTY,
    schedule_new_shape::PROPERTY,
    depth_step::PROPERTY,
    g162_split::TAIL,
    g162_split_target::PROPERTY,
    peck_counts::PROPERTY,
    g71_layers::PROPERTY,
    depth_step_monotone::PROPERTY,
    depth_bounds::PROPERTY,
    #[cfg(not(kani))]
    schedule_spec::PROPERTY,
    fixed_point::PROPERTY,
    expander_envelope::PROPERTY,
    g92_pullout::PROPERTY,
    g162_split::EXACT,
    g162_pitch::PROPERTY,
    g71_layer_step::PROPERTY,
    g73_passes::PROPERTY,
    g74_peck_step::PROPERTY,
    g83_peck_step::PROPERTY,
    peck_toward::PROPERTY,
    g74_peck_step::START_PROPERTY,
    g74_peck_step::LAST_PROPERTY,
    g74_peck_step::COLUMN_PROPERTY,
    g83_peck_step::START_PROPERTY,
    g83_peck_step::LAST_PROPERTY,
    g162_split_step::START_PROPERTY,
    g162_split_step::PROPERTY,
    g162_split_step::LAST_PROPERTY,
];
