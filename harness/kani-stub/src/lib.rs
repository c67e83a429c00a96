//! A stand-in for the subset of the `kani` crate the proof harnesses use.
//!
//! It exists so that `RUSTFLAGS="--cfg kani --cfg kani_stub" cargo check -p cycle-proofs`
//! type-checks the harnesses as Kani would compile them, on a machine without Kani. It is not a
//! verifier: `any` returns a default value and `assert` panics. Under real Kani (`cfg(kani)`
//! without `kani_stub`) cargo-kani injects the real crate and this one is not built.
//!
//! The signatures follow the real crate: `any::<T: Arbitrary>()`, `any_where(f)`,
//! `assume(bool)`, `assert(bool, &'static str)`, `cover!(cond, "msg")`, `#[kani::proof]`,
//! `#[kani::unwind(n)]`, `#[kani::stub(original, replacement)]`, `#[kani::solver(s)]`.

pub use kani_stub_macros::{proof, solver, stub, unwind};

/// Types that have a symbolic (here: a default concrete) value.
pub trait Arbitrary: Sized {
    fn any() -> Self;
}

macro_rules! arbitrary_default {
    ($($t:ty),*) => { $(impl Arbitrary for $t { fn any() -> Self { <$t>::default() } })* };
}

arbitrary_default!(bool, u8, u16, u32, u64, u128, usize, i8, i16, i32, i64, i128, isize, char);

impl<T: Arbitrary, const N: usize> Arbitrary for [T; N] {
    fn any() -> Self {
        core::array::from_fn(|_| T::any())
    }
}

impl<T: Arbitrary> Arbitrary for Option<T> {
    fn any() -> Self {
        None
    }
}

/// A value of `T` (Kani: any value; the stub: a fixed one).
pub fn any<T: Arbitrary>() -> T {
    T::any()
}

/// A value of `T` satisfying `f` (Kani: any such value; the stub: the fixed one, which must
/// satisfy `f`).
pub fn any_where<T: Arbitrary, F: FnOnce(&T) -> bool>(f: F) -> T {
    let v = T::any();
    assume(f(&v));
    v
}

/// Restricts the paths considered to those where `cond` holds (the stub: panics otherwise, since
/// a concrete run cannot discard its path).
#[track_caller]
pub fn assume(cond: bool) {
    assert!(cond, "kani stub: assumption violated on the concrete path");
}

/// A verification condition.
#[track_caller]
pub fn assert(cond: bool, msg: &'static str) {
    assert!(cond, "{msg}");
}

/// A cover property: Kani reports whether `cond` is satisfiable. The stub does nothing.
pub fn cover(_cond: bool, _msg: &'static str) {}

/// `kani::cover!(cond)` / `kani::cover!(cond, "msg")`, as the real crate spells it.
#[macro_export]
macro_rules! cover {
    () => {
        $crate::cover(true, "cover location")
    };
    ($cond:expr $(,)?) => {
        $crate::cover($cond, concat!("cover condition: ", stringify!($cond)))
    };
    ($cond:expr, $msg:literal) => {
        $crate::cover($cond, $msg)
    };
}

#[cfg(test)]
mod tests;
