//! `diff_spec_impl`: see `cycle_oracle::fuzzing` (the body, shared with `cargo test`).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| cycle_oracle::fuzzing::fuzz(cycle_oracle::fuzzing::Target::DiffSpecImpl, data));
