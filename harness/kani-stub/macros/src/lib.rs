//! `#[kani::proof]`, `#[kani::unwind(n)]`, `#[kani::stub(..)]` and `#[kani::solver(..)]` as identity attributes.
//!
//! Under the stub (`--cfg kani --cfg kani_stub`) the harnesses only need to type-check, so each
//! attribute returns the item unchanged. Real Kani supplies its own macros.
use proc_macro::TokenStream;

/// Marks a proof harness; the stub leaves the function as it is, allowing it to be unused
/// (a harness is called by the verifier, never by the crate).
#[proc_macro_attribute]
pub fn proof(_attr: TokenStream, item: TokenStream) -> TokenStream {
    let mut out: TokenStream = "#[allow(dead_code)]".parse().expect("a valid attribute");
    out.extend(item);
    out
}

/// Sets the loop unwinding bound of a harness; the stub ignores it.
#[proc_macro_attribute]
pub fn unwind(_attr: TokenStream, item: TokenStream) -> TokenStream {
    item
}

/// Replaces a function by another under Kani (`#[kani::stub(original, replacement)]`); the stub
/// ignores it.
#[proc_macro_attribute]
pub fn stub(_attr: TokenStream, item: TokenStream) -> TokenStream {
    item
}

/// Selects the SAT solver of a harness (`#[kani::solver(kissat)]`); the stub ignores it.
#[proc_macro_attribute]
pub fn solver(_attr: TokenStream, item: TokenStream) -> TokenStream {
    item
}
