//! How a block's words are read ([`Kind`]): from the family its cycle code selects
//! ([`crate::family::FAMILIES`], mapped by name in [`cycle_kind`]), its motion code or the modal
//! mode; and the words each kind accepts (PRJ.WORD, PRJ.DIALECT).

use crate::family::FamilyCodes;
use crate::g74::PeckCode;
use crate::g90::CutCode;
use crate::lex::{letter_mask, Block};
use crate::multipass::Code;
use crate::rough::Axis;
use crate::thread_move::ThreadCode;
use cycle_vocab::Dialect;

/// How the block's words are read (its code, or the modal mode).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Kind {
    Rapid,
    Feed,
    G92,
    First(Code),
    Second(Code),
    Thread(ThreadCode),
    G162,
    Cut(CutCode),
    /// G50 (G50.COORD): set the current position.
    G50,
    /// G02 (`true`) / G03 (ARC.FORMAT).
    Arc(bool),
    /// G70 (G70.FORMAT).
    G70,
    /// G71/G72 without P and Q (Δd, e), and with them (G71.UW).
    RoughFirst(Axis),
    RoughSecond(Axis),
    /// G74/G75 without X U Z W P Q (e), and with any of them (G74.FORMAT, G75.FORMAT).
    PeckFirst(PeckCode),
    PeckSecond(PeckCode),
    /// G73 without P and Q (Δi, Δk, d); with P or Q: format (a)'s second block (`false`) or
    /// format (b) (`true`, with I, K or D) (G73.FORMAT).
    PatternFirst,
    PatternSecond(bool),
    /// G83 (G83.FORMAT), G84 (G84.FORMAT).
    G83,
    G84,
}

/// How a block whose G code `code` selects family `f` is read, by the family's name (the one
/// map from [`crate::family::FAMILIES`] to the interpreter); `None` for a family it does not know.
pub(super) fn cycle_kind(f: &FamilyCodes, code: u64, b: &Block, axis: bool) -> Option<Kind> {
    // G71.UW, G73.FORMAT: a block with P or Q is the second block.
    let pq = || b.has(b'P') || b.has(b'Q');
    // G74.FORMAT, G75.FORMAT: any of X U Z W P Q makes the second block.
    let peck_second = || b.mask() & const { letter_mask(b"PQUWXZ") } != 0;
    Some(match f.name {
        "g92" => Kind::G92,
        "g76" | "f76" if axis => Kind::Second(Code::G76),
        "g76" | "f76" => Kind::First(Code::G76),
        "g78" if axis => Kind::Second(Code::G78),
        "g78" => Kind::First(Code::G78),
        "g32" => Kind::Thread(*ThreadCode::ALL.get(f.position(code)?)?),
        "g162" => Kind::G162,
        "g90" => Kind::Cut(CutCode::G90),
        "g94" => Kind::Cut(CutCode::G94),
        "g70" => Kind::G70,
        "g71" if pq() => Kind::RoughSecond(Axis::G71),
        "g71" => Kind::RoughFirst(Axis::G71),
        "g72" if pq() => Kind::RoughSecond(Axis::G72),
        "g72" => Kind::RoughFirst(Axis::G72),
        // G73.FORMAT: I, K or D in the second block makes format (b).
        "g73" if pq() => Kind::PatternSecond(b.has(b'I') || b.has(b'K') || b.has(b'D')),
        "g73" => Kind::PatternFirst,
        "g74" if peck_second() => Kind::PeckSecond(PeckCode::G74),
        "g74" => Kind::PeckFirst(PeckCode::G74),
        "g75" if peck_second() => Kind::PeckSecond(PeckCode::G75),
        "g75" => Kind::PeckFirst(PeckCode::G75),
        "g83" => Kind::G83,
        "g84" => Kind::G84,
        _ => return None,
    })
}

/// Words every block accepts (no motion effect).
pub(super) const COMMON: u32 = letter_mask(b"MNOST");

/// PRJ.WORD, PRJ.DIALECT: the words a block of `kind` accepts besides G and [`COMMON`].
pub(super) fn allowed(kind: Kind, dialect: Dialect) -> u32 {
    match (kind, dialect) {
        // NC201.ABSINC: U and W are no incremental addresses under nc201.
        (Kind::Rapid | Kind::Feed, Dialect::Nc201) => const { letter_mask(b"FXZ") },
        (Kind::Rapid | Kind::Feed, _) => const { letter_mask(b"FUWXZ") },
        (Kind::Thread(ThreadCode::G32), _) => const { letter_mask(b"FIUWXZ") },
        (Kind::Thread(ThreadCode::G33), _) => const { letter_mask(b"FIPUWXZ") },
        (Kind::Thread(ThreadCode::G34), _) => const { letter_mask(b"FIKUWXZ") },
        (Kind::G162, _) => const { letter_mask(b"ABFHIJPQVWXZ") },
        (Kind::Cut(CutCode::G90), _) => const { letter_mask(b"FIUWXZ") },
        (Kind::Cut(CutCode::G94), _) => const { letter_mask(b"FKUWXZ") },
        (Kind::G92, _) => const { letter_mask(b"FIJKLRUWXZ") },
        (Kind::First(_), Dialect::Fanuc) => const { letter_mask(b"PQR") },
        (Kind::First(_), Dialect::Gsk | Dialect::Nc201) => const { letter_mask(b"DELPQR") },
        (Kind::Second(_), Dialect::Fanuc) => const { letter_mask(b"FIPQRUWXZ") },
        (Kind::Second(_), Dialect::Gsk | Dialect::Nc201) => const { letter_mask(b"FIJKPQRUWXZ") },
        // G50.COORD: X and Z, absolute only (S is common).
        (Kind::G50, _) => const { letter_mask(b"XZ") },
        (Kind::Arc(_), _) => const { letter_mask(b"FIKRUWXZ") },
        // G70.FORMAT, G71.FORMAT, G72.FORMAT.
        (Kind::G70 | Kind::RoughSecond(_), _) => const { letter_mask(b"FPQUW") },
        (Kind::RoughFirst(Axis::G71), _) => const { letter_mask(b"RU") },
        (Kind::RoughFirst(Axis::G72), _) => const { letter_mask(b"RW") },
        // G74.FORMAT, G75.FORMAT, G73.FORMAT, G83/G84 words.
        (Kind::PeckFirst(_), _) => const { letter_mask(b"R") },
        (Kind::PeckSecond(_), _) => const { letter_mask(b"FPQRUWXZ") },
        (Kind::PatternFirst, _) => const { letter_mask(b"RUW") },
        (Kind::PatternSecond(false), _) => const { letter_mask(b"FPQUW") },
        (Kind::PatternSecond(true), _) => const { letter_mask(b"DFIKPQUW") },
        (Kind::G83, _) => const { letter_mask(b"FPQRWZ") },
        (Kind::G84, _) => const { letter_mask(b"FPRWZ") },
    }
}
