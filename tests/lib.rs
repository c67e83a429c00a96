//! End-to-end tests live in `tests/*.rs`. This library holds one piece of glue: the committed
//! cases of the `impl_invariants` fuzz target ([`invariants`]), whose file format is the
//! oracle's (`cycle_oracle::fuzzing::decoded`) and whose harness bodies are the proofs'
//! (`cycle_proofs::invariants`) — the oracle does not link the proofs. `tests/fuzz_replay.rs`
//! replays them; the `fuzz-invariants` tool (`fuzz_invariants.rs`) serves `cyclecheck fuzz`.

pub mod invariants;
