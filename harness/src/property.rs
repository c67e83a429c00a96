//! One body per property: [`property!`](crate::property) turns a harness body and its domains
//! into the `cargo test` drivers, the Kani harness and the [`Property`] entry that lists it.

use crate::report::Report;
use crate::source::Outcome;
use crate::{Exhaustive, Random};

/// How a property is checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheckedBy {
    /// A Kani proof harness (`cargo kani -p cycle-proofs --harness NAME`) with a measured
    /// SUCCESSFUL verdict, also run by the bounded-exhaustive and random drivers under `cargo test`.
    Kani,
    /// A TEST: the body run by the drivers under `cargo test` only (Kani reached no verdict on
    /// its harness in the time and memory measured, or it is not a Kani target).
    Drivers,
}

/// One property, as [`property!`](crate::property) states it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Property {
    /// The harness: the Kani `--harness` name, for a TEST the name its Kani attempt would have.
    pub harness: &'static str,
    /// The rule IDs it bears on.
    pub rules: &'static [&'static str],
    /// What it states, in one line.
    pub statement: &'static str,
    pub checked_by: CheckedBy,
    /// Kani as measured: a proof's verdict, Kani time and peak memory; a TEST's reason.
    pub kani: &'static str,
    /// The harness's `#[kani::unwind]` (`None`: no loop to bound).
    pub unwind: Option<u32>,
    /// The harness's `#[kani::solver]` (`None`: Kani's default, CaDiCaL).
    pub solver: Option<&'static str>,
    /// The functions the harness stubs (`#[kani::stub]`; run with `-Z stubbing`).
    pub stubs: &'static [&'static str],
    /// The `cargo test` functions that run the body.
    pub tests: &'static [&'static str],
}

/// Fails the calling test unless `registry` lists `harness` (each property is in the crate's list).
#[track_caller]
pub fn assert_listed(registry: &[Property], harness: &str) {
    assert!(
        registry.iter().any(|p| p.harness == harness),
        "property {harness} is not in the crate's list of properties"
    );
}

/// The runs a generated test can make: each asserts its verdict (panicking with its message)
/// and returns the report for printing.
pub mod drive {
    use super::*;

    /// The bounded-exhaustive driver ([`crate::exhaustive`]): `width` values at each end of a
    /// draw's range, at most `budget` cases.
    #[track_caller]
    pub fn exhaustive(
        width: u64,
        budget: u64,
        body: impl FnMut(&mut Exhaustive) -> Outcome,
    ) -> Report {
        crate::exhaustive(width, budget, body).assert_ok()
    }

    /// The random driver ([`crate::random`]) from `seed`, on [`crate::random_cases`]`(divisor)`
    /// cases.
    #[track_caller]
    pub fn random(seed: u64, divisor: u64, body: impl FnMut(&mut Random) -> Outcome) -> Report {
        crate::random(seed, crate::random_cases(divisor), body).assert_ok()
    }
}

/// States a property once: its body, its rules, how Kani checks it, and the tests that drive it.
///
/// ```text
/// property! {
///     /// What the property is (the const's doc).
///     pub const PROPERTY = harness_name in crate::PROPERTIES {
///         rules: ["RULE.ID", ...],
///         states: "one line",
///         body: |src, scope| body(src, &scope),
///         /// The Kani harness's doc.
///         kani: proof(KANI_SCOPE) { unwind: 7, solver: kissat, stubs: [a::f => b::f_spec], measured: "..." },
///         tests {
///             /// A test's doc.
///             fn harness_name_exhaustive = exhaustive(width, budget) on SMALL_SCOPE;
///             fn harness_name_random = random(seed, divisor) on KANI_SCOPE, random(seed2, divisor) on OTHER;
///         }
///     }
/// }
/// ```
///
/// `body` is an expression of the source `src` and the domain `scope` (any names). It emits:
/// - `PROPERTY: Property`, the entry the crate lists in its registry (`crate::PROPERTIES` above);
/// - one `#[test]` per `fn` line, running the body under each listed driver
///   ([`drive::exhaustive`], [`drive::random`]) on its domain, after checking that the registry
///   lists the property;
/// - under `cfg(kani)`, the harness `harness_name()`: the body once on `KaniSource`
///   (`kani::any` + `kani::assume` for every draw) over the Kani domain. `kani: proof(..)` (a
///   measured SUCCESSFUL verdict, `measured: "…"`) makes it `#[kani::proof]` with the given
///   `unwind`, `solver` and `stub`s; `kani: test(..)` (`why: "…"` it is not a proof) makes it a
///   proof harness only with the calling crate's feature `kani-attempts`, so a plain
///   `cargo kani` runs the proofs alone; `kani: none { why: "…" }` emits no harness.
#[macro_export]
macro_rules! property {
    (
        $(#[$doc:meta])*
        $vis:vis const $konst:ident = $name:ident in $registry:path {
            rules: [$($rule:literal),* $(,)?],
            states: $statement:literal,
            body: |$src:ident, $scope:ident| $body:expr,
            $(#[$kdoc:meta])*
            kani: $kind:ident $(($kscope:expr))? {
                $(unwind: $unwind:literal,)?
                $(solver: $solver:ident,)?
                $(stubs: [$($from:path => $to:path),* $(,)?],)?
                $(measured: $measured:literal)? $(why: $why:literal)? $(,)?
            },
            tests {
                $( $(#[$tdoc:meta])* fn $test:ident = $( $driver:ident ($($arg:expr),* $(,)?) on $dscope:expr ),+ ; )+
            } $(,)?
        }
    ) => {
        $(#[$doc])*
        $vis const $konst: $crate::Property = $crate::Property {
            harness: stringify!($name),
            rules: &[$($rule),*],
            statement: $statement,
            checked_by: $crate::__property!(@checked $kind),
            kani: $crate::__property!(@text $kind $(measured $measured)? $(why $why)?),
            unwind: $crate::__property!(@some $($unwind)?),
            solver: $crate::__property!(@some $(stringify!($solver))?),
            stubs: &[$($(stringify!($from)),*)?],
            tests: &[$(stringify!($test)),+],
        };

        $crate::__property! {
            @kani $kind, $name, ($($kscope)?), |$src, $scope| $body,
            [kani::proof $(, kani::unwind($unwind))? $(, kani::solver($solver))? $($(, kani::stub($from, $to))*)?]
            $(#[$kdoc])*
        }

        $(
            $(#[$tdoc])*
            #[cfg(test)]
            #[test]
            fn $test() {
                $crate::assert_listed(&$registry, stringify!($name));
                $({
                    let $scope = $dscope;
                    let report = $crate::drive::$driver($($arg),*, |$src| $body);
                    println!("{report}");
                })+
            }
        )+
    };
}

/// The parts of [`property!`] that depend on the kind of Kani check (not for direct use).
#[doc(hidden)]
#[macro_export]
macro_rules! __property {
    (@checked proof) => { $crate::CheckedBy::Kani };
    (@checked test) => { $crate::CheckedBy::Drivers };
    (@checked none) => { $crate::CheckedBy::Drivers };
    (@text proof measured $text:literal) => { $text };
    (@text test why $text:literal) => { $text };
    (@text none why $text:literal) => { $text };
    (@text $($other:tt)*) => {
        compile_error!("property!: `kani: proof(..)` takes `measured: \"…\"`, `kani: test(..)` and `kani: none` take `why: \"…\"`")
    };
    (@some) => { None };
    (@some $e:expr) => { Some($e) };
    (@kani proof, $name:ident, ($kscope:expr), |$src:ident, $scope:ident| $body:expr, [$($attr:tt)*] $(#[$kdoc:meta])*) => {
        $(#[$kdoc])*
        #[cfg(kani)]
        #[cfg_attr(kani, $($attr)*)]
        fn $name() {
            let $scope = $kscope;
            let $src = &mut $crate::KaniSource;
            let _ = $body;
        }
    };
    (@kani test, $name:ident, ($kscope:expr), |$src:ident, $scope:ident| $body:expr, [$($attr:tt)*] $(#[$kdoc:meta])*) => {
        $(#[$kdoc])*
        #[cfg(kani)]
        #[cfg_attr(feature = "kani-attempts", $($attr)*)]
        #[allow(dead_code)]
        fn $name() {
            let $scope = $kscope;
            let $src = &mut $crate::KaniSource;
            let _ = $body;
        }
    };
    (@kani none, $name:ident, (), |$src:ident, $scope:ident| $body:expr, [$($attr:tt)*] $(#[$kdoc:meta])*) => {};
}

#[cfg(test)]
mod tests;
