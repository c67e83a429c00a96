//! The cycle families and the G codes that select each (PRJ.SUPPORTED, PRJ.DIALECT): the one
//! place the production expander writes its cycle codes. A family is named as in the harness's
//! registry (`g92`, `g76`, `f76`, …); the block interpreter (`modal`) finds a block's family
//! here ([`lookup`]) and maps its name to how the block is read.
//!
//! G00–G03, G50 and the modal codes (G18, G20/G21, G40–G42, G80, G90/G91 under nc201, G96–G99)
//! are program words, no family: `modal` reads them.

use cycle_vocab::Dialect;
use Dialect::{Fanuc, Gsk, Nc201};

/// One family: its name, the dialects it runs under, the G codes that select it there.
#[derive(Debug)]
pub struct FamilyCodes {
    pub name: &'static str,
    pub dialects: &'static [Dialect],
    pub codes: &'static [u16],
}

/// Every family, in the registry's order. The `g32` family's codes are in the order of
/// `thread_move::ThreadCode::ALL` (G32, G33, G34).
pub const FAMILIES: &[FamilyCodes] = &[
    FamilyCodes { name: "g92", dialects: &[Gsk, Fanuc], codes: &[92] },
    FamilyCodes { name: "g76", dialects: &[Gsk], codes: &[76] },
    FamilyCodes { name: "g78", dialects: &[Gsk], codes: &[78] },
    FamilyCodes { name: "f76", dialects: &[Fanuc], codes: &[76] },
    FamilyCodes { name: "g162", dialects: &[Nc201], codes: &[162] },
    FamilyCodes { name: "g32", dialects: &[Gsk, Fanuc], codes: &[32, 33, 34] },
    FamilyCodes { name: "g90", dialects: &[Gsk, Fanuc], codes: &[90] },
    FamilyCodes { name: "g94", dialects: &[Gsk, Fanuc], codes: &[94] },
    FamilyCodes { name: "g71", dialects: &[Gsk, Fanuc], codes: &[71] },
    FamilyCodes { name: "g72", dialects: &[Gsk, Fanuc], codes: &[72] },
    FamilyCodes { name: "g70", dialects: &[Gsk, Fanuc], codes: &[70] },
    FamilyCodes { name: "g73", dialects: &[Gsk, Fanuc], codes: &[73] },
    FamilyCodes { name: "g74", dialects: &[Gsk, Fanuc], codes: &[74] },
    FamilyCodes { name: "g75", dialects: &[Gsk, Fanuc], codes: &[75] },
    FamilyCodes { name: "g83", dialects: &[Gsk, Fanuc], codes: &[83] },
    FamilyCodes { name: "g84", dialects: &[Gsk, Fanuc], codes: &[84] },
];

/// What G code `code` is to the families under a dialect.
#[derive(Clone, Copy, Debug)]
pub enum Lookup {
    /// It selects this family.
    Selects(&'static FamilyCodes),
    /// It selects a family under another dialect only (PRJ.DIALECT).
    OtherDialect,
    /// No family's code.
    None,
}

impl FamilyCodes {
    /// Whether G code `code` is one of this family's.
    pub fn has(&self, code: u64) -> bool {
        self.codes.iter().any(|&c| u64::from(c) == code)
    }

    /// The position of `code` in [`FamilyCodes::codes`].
    pub fn position(&self, code: u64) -> Option<usize> {
        self.codes.iter().position(|&c| u64::from(c) == code)
    }
}

/// The family G code `code` selects under `dialect` (a scan of [`FAMILIES`]: 16 rows, no
/// allocation; on the per-block path only for blocks with a cycle code).
pub fn lookup(code: u64, dialect: Dialect) -> Lookup {
    let mut found = Lookup::None;
    for f in FAMILIES {
        if f.has(code) {
            if f.dialects.contains(&dialect) {
                return Lookup::Selects(f);
            }
            found = Lookup::OtherDialect;
        }
    }
    found
}

#[cfg(test)]
mod tests;
