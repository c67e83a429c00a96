//! `diff_spec_impl`: see `cycle_kernel::fuzzing` (the body, shared with `cargo test`).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Err(report) = cycle_kernel::fuzzing::Target::DiffSpecImpl.run(data) {
        panic!("diff_spec_impl failed:\n{report}");
    }
});
