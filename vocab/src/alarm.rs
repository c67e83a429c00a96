//! Alarms: what the controller says instead of moving. Every alarm names a code, the offending
//! word (address letter, or the bad character for a lexical error), the rule, and the line.

use crate::rule::Rule;
use core::fmt;

/// Alarm codes, numbered by family: 1xxx program text, 2xxx word values, 3xxx cycle geometry
/// and resources.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "SCREAMING_SNAKE_CASE"))]
pub enum AlarmCode {
    /// A byte that is no part of a program (PRJ.LEX).
    BadCharacter,
    /// An address letter without a well-formed number (PRJ.LEX).
    BadNumber,
    /// A `(` comment not closed on its line (PRJ.LEX).
    UnclosedComment,
    /// The same address twice in one block (PRJ.WORD).
    DuplicateWord,
    /// A word the block's code does not take (PRJ.WORD).
    WordNotAllowed,
    /// Words that exclude each other: X and U, two motion codes, F and I (PRJ.WORD).
    Conflict,
    /// A G or M code outside the supported set (PRJ.SUPPORTED).
    UnsupportedCode,
    /// A word the cycle requires is missing.
    MissingWord,
    /// A value outside its legal range (COM.RANGES).
    OutOfRange,
    /// More decimal places than the least increment (COM.UNITS).
    Precision,
    /// A decimal point in a word that takes an integer.
    NotInteger,
    /// The points of the cycle do not form a legal thread.
    Geometry,
    /// The cycle would exceed the pass bound (PRJ.MAXPASS).
    TooManyPasses,
    /// A documented feature this reference does not model.
    Unsupported,
    /// A sequence number a cycle's P or Q names is not where the cycle needs it (CNT.FIND), or
    /// the subprogram an M98 names is not in the program text (SUB.FIND).
    BlockNotFound,
    /// A cycle's contour has more blocks than the documented bound (CNT.MAX).
    ContourTooLong,
    /// An operator action that cannot happen where the script puts it: on a block the project
    /// does not model operator events for (OP.SCOPE), at an event that is not a move (OP.AT),
    /// or never reached (OP.REACH).
    Operator,
    /// A subprogram call nested deeper than the documented bound (SUB.NEST).
    Nesting,
}

impl AlarmCode {
    /// The number shown to the machinist.
    pub const fn number(self) -> u16 {
        match self {
            AlarmCode::BadCharacter => 1001,
            AlarmCode::BadNumber => 1002,
            AlarmCode::UnclosedComment => 1003,
            AlarmCode::DuplicateWord => 1004,
            AlarmCode::WordNotAllowed => 1005,
            AlarmCode::Conflict => 1006,
            AlarmCode::UnsupportedCode => 1007,
            AlarmCode::MissingWord => 2001,
            AlarmCode::OutOfRange => 2002,
            AlarmCode::Precision => 2003,
            AlarmCode::NotInteger => 2004,
            AlarmCode::BlockNotFound => 2005,
            AlarmCode::Geometry => 3001,
            AlarmCode::TooManyPasses => 3002,
            AlarmCode::Unsupported => 3003,
            AlarmCode::ContourTooLong => 3004,
            AlarmCode::Operator => 3005,
            AlarmCode::Nesting => 3006,
        }
    }

    /// A short text a machinist understands.
    pub const fn text(self) -> &'static str {
        match self {
            AlarmCode::BadCharacter => "character not allowed in a program",
            AlarmCode::BadNumber => "address without a valid number",
            AlarmCode::UnclosedComment => "comment not closed on its line",
            AlarmCode::DuplicateWord => "address given twice in one block",
            AlarmCode::WordNotAllowed => "address not allowed in this block",
            AlarmCode::Conflict => "addresses that exclude each other",
            AlarmCode::UnsupportedCode => "G or M code not supported",
            AlarmCode::MissingWord => "required address missing",
            AlarmCode::OutOfRange => "value out of range",
            AlarmCode::Precision => "more decimals than the least increment",
            AlarmCode::NotInteger => "decimal point in an integer value",
            AlarmCode::Geometry => "cycle points do not form a legal path",
            AlarmCode::TooManyPasses => "cycle exceeds the maximum pass count",
            AlarmCode::Unsupported => "function not supported",
            AlarmCode::BlockNotFound => "sequence number not found where the cycle needs it",
            AlarmCode::ContourTooLong => "contour longer than the supported number of blocks",
            AlarmCode::Operator => "operator event not applicable here",
            AlarmCode::Nesting => "subprogram calls nested too deep",
        }
    }
}

/// An alarm raised while reading or expanding a program; it ends the expansion.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Alarm {
    pub code: AlarmCode,
    /// The offending address letter (upper case), or the offending byte of a lexical error.
    pub word: Option<u8>,
    pub rule: Rule,
    /// 1-based source line of the block (or of the offending byte).
    pub line: u32,
}

impl Alarm {
    pub const fn new(code: AlarmCode, word: Option<u8>, rule: Rule, line: u32) -> Alarm {
        Alarm { code, word, rule, line }
    }
}

/// Writes a byte as the machinist would read it: the letter itself, or `0xNN`.
pub(crate) fn fmt_word(byte: u8, f: &mut fmt::Formatter<'_>) -> fmt::Result {
    if byte.is_ascii_graphic() {
        write!(f, "{}", byte as char)
    } else {
        write!(f, "0x{byte:02X}")
    }
}

impl fmt::Display for Alarm {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "ALARM {} line {}: {}", self.code.number(), self.line, self.code.text())?;
        if let Some(w) = self.word {
            f.write_str(" (")?;
            fmt_word(w, f)?;
            f.write_str(")")?;
        }
        write!(f, " [rule {}]", self.rule)
    }
}

#[cfg(feature = "std")]
mod json {
    use super::*;
    use serde::{Deserialize, Deserializer, Serialize, Serializer};

    /// The JSON form: `{"code": "MISSING_WORD", "number": 2001, "word": "P", "rule": "G76.REQUIRED", "line": 3}`.
    #[derive(Serialize, Deserialize)]
    struct AlarmJson {
        code: AlarmCode,
        #[serde(default)]
        number: u16,
        word: Option<String>,
        rule: Rule,
        line: u32,
    }

    impl Serialize for Alarm {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            let word = self.word.map(|b| {
                if b.is_ascii_graphic() { (b as char).to_string() } else { format!("0x{b:02X}") }
            });
            AlarmJson { code: self.code, number: self.code.number(), word, rule: self.rule, line: self.line }
                .serialize(s)
        }
    }

    impl<'de> Deserialize<'de> for Alarm {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            let j = AlarmJson::deserialize(d)?;
            let word = match j.word.as_deref() {
                None => None,
                Some(w) if w.len() == 1 => Some(w.as_bytes()[0]),
                Some(w) => match w.strip_prefix("0x").map(|h| u8::from_str_radix(h, 16)) {
                    Some(Ok(b)) => Some(b),
                    _ => return Err(serde::de::Error::custom(format!("bad alarm word {w:?}"))),
                },
            };
            Ok(Alarm { code: j.code, word, rule: j.rule, line: j.line })
        }
    }
}

#[cfg(test)]
mod tests;
