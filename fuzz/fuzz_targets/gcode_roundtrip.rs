//! `gcode_roundtrip`: see `cycle_kernel::fuzzing` (the body, shared with `cargo test`).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Err(report) = cycle_kernel::fuzzing::Target::GcodeRoundtrip.run(data) {
        panic!("gcode_roundtrip failed:\n{report}");
    }
});
