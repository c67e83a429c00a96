//! `impl_invariants`: see `cycle_proofs::invariants` (the proof harness bodies, shared with Kani
//! and `cargo test`).
#![no_main]
libfuzzer_sys::fuzz_target!(|data: &[u8]| {
    if let Err(report) = cycle_proofs::invariants::fuzz(data) {
        panic!("impl_invariants failed:\n{report}");
    }
});
