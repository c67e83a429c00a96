//! The plumbing of the proof harness bodies (`cycle-proofs`), shared by the proofs, the
//! `impl_invariants` fuzz target and the replay of its regressions.
//!
//! One body, many uses: a harness body is a generic function over a [`Source`] of values that
//! states its properties with [`check!`] and [`cover!`]. Kani makes each draw symbolic
//! (`KaniSource`, under `cfg(kani)`); under `cargo test` the [`exhaustive`] driver enumerates
//! every combination of draws within a small scope and the [`random`] driver samples the full
//! ranges; under libFuzzer the [`FuzzSource`] reads each draw from the fuzzer's bytes; a
//! committed regression's draws are replayed by the [`ReplaySource`].
//!
//! [`property!`] states a property once — its body, rules, Kani harness and driver tests — and
//! gives the [`Property`] entry a crate lists. Nothing here depends on the engines.
#![forbid(unsafe_code)]

mod bytes;
mod exhaustive;
#[cfg(kani)]
mod kani;
mod property;
mod random;
mod replay;
mod report;
mod source;

pub use bytes::FuzzSource;
pub use exhaustive::{exhaustive, Exhaustive};
#[cfg(kani)]
pub use kani::KaniSource;
pub use property::{assert_listed, drive, CheckedBy, Property};
pub use random::{random, random_cases, Random, DEFAULT_RANDOM_CASES};
pub use replay::ReplaySource;
pub use report::{Failure, Report};
pub use source::{Outcome, Source, Stop};

/// Checks a property: `check!(src, cond, "message")`. Under Kani this is
/// `kani::assert(cond, "message")`; under the other sources a false `cond` returns
/// `Err(Stop::Failed("message"))` from the enclosing body.
#[macro_export]
macro_rules! check {
    ($src:expr, $cond:expr, $msg:literal) => {{
        let ok: bool = $cond;
        #[cfg(kani)]
        kani::assert(ok, $msg);
        $crate::Source::verdict($src, ok, $msg)?;
    }};
}

/// A cover property: `cover!(src, cond, "message")`. Kani reports whether `cond` can hold; the
/// exhaustive driver fails a harness whose cover condition never held (a vacuous harness).
#[macro_export]
macro_rules! cover {
    ($src:expr, $cond:expr, $msg:literal) => {{
        let c: bool = $cond;
        #[cfg(kani)]
        kani::cover!(c, $msg);
        $crate::Source::cover($src, c, $msg);
    }};
}
