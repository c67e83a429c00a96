//! End-to-end tests live in `tests/*.rs` and the benchmarks in `benches/`; this library target
//! is empty (cargo needs one target besides tests and benches).
