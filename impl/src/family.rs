//! TEMP stub (branch wp-families only): the production expander's family table in the shape
//! helper "implmod" writes, so that `tests/tests/families.rs` compiles and runs; replaced at the
//! merge by implmod's table.

use cycle_vocab::Dialect::{self, Fanuc, Gsk, Nc201};

/// A cycle family as the registry names it, the dialects and G codes that select it.
#[derive(Clone, Copy, Debug)]
pub struct FamilyCodes {
    pub name: &'static str,
    pub dialects: &'static [Dialect],
    pub codes: &'static [u16],
}

const GSK_FANUC: &[Dialect] = &[Gsk, Fanuc];

/// The cycle families.
pub const FAMILIES: &[FamilyCodes] = &[
    FamilyCodes { name: "g92", dialects: GSK_FANUC, codes: &[92] },
    FamilyCodes { name: "g76", dialects: &[Gsk], codes: &[76] },
    FamilyCodes { name: "g78", dialects: &[Gsk], codes: &[78] },
    FamilyCodes { name: "f76", dialects: &[Fanuc], codes: &[76] },
    FamilyCodes { name: "g162", dialects: &[Nc201], codes: &[162] },
    FamilyCodes { name: "g32", dialects: GSK_FANUC, codes: &[32, 33, 34] },
    FamilyCodes { name: "g90", dialects: GSK_FANUC, codes: &[90] },
    FamilyCodes { name: "g94", dialects: GSK_FANUC, codes: &[94] },
    FamilyCodes { name: "g71", dialects: GSK_FANUC, codes: &[71] },
    FamilyCodes { name: "g72", dialects: GSK_FANUC, codes: &[72] },
    FamilyCodes { name: "g70", dialects: GSK_FANUC, codes: &[70] },
    FamilyCodes { name: "g73", dialects: GSK_FANUC, codes: &[73] },
    FamilyCodes { name: "g74", dialects: GSK_FANUC, codes: &[74] },
    FamilyCodes { name: "g75", dialects: GSK_FANUC, codes: &[75] },
    FamilyCodes { name: "g83", dialects: GSK_FANUC, codes: &[83] },
    FamilyCodes { name: "g84", dialects: GSK_FANUC, codes: &[84] },
];
