//! The `cyclecheck` application over the kernel (`cycle_kernel`: engines, judge, conformance,
//! registry, generators, corpus, fuzz bodies): the certification run and its evidence bundle and
//! page ([`certify`]), the candidate protocol's client and `serve` ([`candidate`]), third-party
//! expanders ([`thirdparty`]), the merge gate ([`gate`]), fuzz campaigns ([`nightly`]), the
//! harness's rates ([`bench_harness`]) and the clean-up of child processes ([`reaper`]). The
//! `cyclecheck` binary (`src/main.rs`, `src/cli/`) is a thin CLI over these.
#![forbid(unsafe_code)]

pub mod bench_harness;
pub mod candidate;
pub mod certify;
pub mod gate;
pub mod nightly;
pub mod reaper;
pub mod thirdparty;
