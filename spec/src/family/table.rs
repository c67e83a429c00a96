//! The spec's family table: the one place the spec states which G codes select which family
//! under which dialects (PRJ.SUPPORTED, PRJ.DIALECT). The interpreter's dispatch is derived from
//! it ([`select`], [`rows`]); `tests/tests/families.rs` compares it with the registry's rows and
//! with the production expander's table.

use super::Family;
use cycle_vocab::Dialect::{self, Fanuc, Gsk, Nc201};

/// One row: a cycle family as the registry names it, the dialects and G codes that select it,
/// and its handler.
#[derive(Clone, Copy, Debug)]
pub struct Row {
    /// The registry's name of the family (`g92`, `f76`, …).
    pub name: &'static str,
    /// The dialects under which its codes select it. A code that a row has, under a dialect no
    /// row with that code has, is `UNSUPPORTED CODE`, rule PRJ.DIALECT.
    pub dialects: &'static [Dialect],
    /// Its G codes.
    pub codes: &'static [u32],
    /// A fresh handler, one per row and per program run. G76 under `gsk` and under `fanuc` are
    /// two rows with a handler each: one program has one dialect, so they never share a run.
    pub handler: fn() -> Box<dyn Family>,
}

/// A fresh handler of type `F`.
fn new<F: Family + Default + 'static>() -> Box<dyn Family> {
    Box::<F>::default()
}

/// `gsk` and `fanuc`: the codes of M001, M002, M003.
const GSK_FANUC: &[Dialect] = &[Gsk, Fanuc];

/// The cycle families, in the registry's order: each G code under each dialect selects at most
/// one row.
pub const FAMILIES: &[Row] = &[
    Row { name: "g92", dialects: GSK_FANUC, codes: &[92], handler: new::<crate::g92::G92> },
    // G76 (M001) and G78 (M000): `gsk`; G76 FANUC-style (M003): `fanuc`. G78 is a GSK code.
    Row { name: "g76", dialects: &[Gsk], codes: &[76], handler: new::<crate::multipass::unit::Multipass> },
    Row { name: "g78", dialects: &[Gsk], codes: &[78], handler: new::<crate::multipass::unit::Multipass> },
    Row { name: "f76", dialects: &[Fanuc], codes: &[76], handler: new::<crate::multipass::unit::Multipass> },
    Row { name: "g162", dialects: &[Nc201], codes: &[162], handler: new::<crate::g162::unit::G162> },
    Row { name: "g32", dialects: GSK_FANUC, codes: &[32, 33, 34], handler: new::<crate::thread_moves::ThreadMoves> },
    Row { name: "g90", dialects: GSK_FANUC, codes: &[90], handler: new::<crate::g90::G90> },
    Row { name: "g94", dialects: GSK_FANUC, codes: &[94], handler: new::<crate::g94::G94> },
    Row { name: "g71", dialects: GSK_FANUC, codes: &[71], handler: new::<crate::g71::G71> },
    Row { name: "g72", dialects: GSK_FANUC, codes: &[72], handler: new::<crate::g72::G72> },
    Row { name: "g70", dialects: GSK_FANUC, codes: &[70], handler: new::<crate::g70::G70> },
    Row { name: "g73", dialects: GSK_FANUC, codes: &[73], handler: new::<crate::g73::G73> },
    Row { name: "g74", dialects: GSK_FANUC, codes: &[74], handler: new::<crate::g74::G74> },
    Row { name: "g75", dialects: GSK_FANUC, codes: &[75], handler: new::<crate::g75::G75> },
    Row { name: "g83", dialects: GSK_FANUC, codes: &[83], handler: new::<crate::g83::G83> },
    Row { name: "g84", dialects: GSK_FANUC, codes: &[84], handler: new::<crate::g84::G84> },
];

/// The codes with a handler that are no cycle: G50 (G50.COORD, G50.SMAX), a program word any
/// program may carry, whatever cycle it runs (the registry has no family for it).
pub const NO_CYCLE: &[Row] = &[Row { name: "g50", dialects: GSK_FANUC, codes: &[50], handler: new::<crate::g50::G50> }];

/// Every row with a handler: [`FAMILIES`], then [`NO_CYCLE`]. The interpreter keeps one handler
/// per row, by its index here.
pub fn rows() -> impl Iterator<Item = &'static Row> {
    FAMILIES.iter().chain(NO_CYCLE)
}

/// What a G code selects in the table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Selection {
    /// The row at this index of [`rows`].
    Row(usize),
    /// Rows have the code, but under other dialects only (PRJ.DIALECT).
    OtherDialect,
    /// No row has the code: the interpreter's own codes, or an unsupported one (PRJ.SUPPORTED).
    None,
}

/// PRJ.SUPPORTED, PRJ.DIALECT: the row G code `g` selects under `dialect`.
pub fn select(g: u64, dialect: Dialect) -> Selection {
    let mut found = Selection::None;
    for (index, row) in rows().enumerate() {
        if row.codes.iter().any(|&c| u64::from(c) == g) {
            if row.dialects.contains(&dialect) {
                return Selection::Row(index);
            }
            found = Selection::OtherDialect;
        }
    }
    found
}
