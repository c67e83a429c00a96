//! `diff_spec_impl`: see `cycle_oracle::fuzzing` (the body, shared with `cargo test`).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Err(report) = cycle_oracle::fuzzing::Target::DiffSpecImpl.run(data) {
        panic!("diff_spec_impl failed:\n{report}");
    }
});
