//! Program flow and spindle speed in the block interpreter (docs/INTERPRETATION.md, "Spindle
//! speed: G50 S, G96, G97" and "Subprograms: M98, M99"): the M98/M99 block's words and P
//! (SUB.CALL, SUB.RETURN; the call itself is [`crate::sub::Calls`]), the S word's value
//! (G50.SMAX, COM.RANGES), G96.SMAX, G96.RAPID, and the rpm G84 taps with (G84.FORMAT).

use super::Machine;
use crate::lex::{letter_bit, letter_mask, Block};
use crate::number::Number;
use crate::sub::{Call, Flow};
use crate::words::{integer_in, At};
use cycle_vocab::readings::G96Rapid;
use cycle_vocab::{Alarm, AlarmCode, Rule};

/// SUB.CALL: P's largest value (repeats 9999, program 9999).
const MAX_CALL: i64 = 99_999_999;

impl Machine {
    /// SUB.CALL, SUB.RETURN — an M98 (`call`) or M99 block after step 2's codes and conflicts:
    /// (2) words allowed, alphabetically (M98: N, M, P; M99: N, M; G or any other word is
    /// `WORD NOT ALLOWED`); (3) P an integer 1 … 99 999 999 whose last four digits n ≠ 0 (`NOT
    /// INTEGER`, COM.RANGES; `OUT OF RANGE`, SUB.CALL); (4) no P: `MISSING WORD P`. P's digits
    /// before the last four are the repeats (none or 0: once). Step 5 is the call's.
    pub(super) fn sub_block(&self, b: &Block, call: bool) -> Result<Flow, Alarm> {
        let line = b.line;
        let (allowed, rule) = if call {
            (const { letter_mask(b"MNP") }, Rule::SubCall)
        } else {
            (const { letter_mask(b"MN") }, Rule::SubReturn)
        };
        let g = if b.has_g() { letter_bit(b'G') } else { 0 };
        let refused = (b.mask() | g) & !allowed;
        if refused != 0 {
            let l = b'A' + refused.trailing_zeros() as u8; // the first alphabetically
            return Err(Alarm::new(AlarmCode::WordNotAllowed, Some(l), rule, line));
        }
        if !call {
            return Ok(Flow::Return);
        }
        let at = At { letter: b'P', line };
        let p = b.get(b'P').ok_or(at.alarm(AlarmCode::MissingWord, Rule::SubCall))?;
        let p = integer_in(p, 1, MAX_CALL, Rule::SubCall, at)?;
        let program = p % 10_000;
        if program == 0 {
            return Err(at.alarm(AlarmCode::OutOfRange, Rule::SubCall));
        }
        // 1 ≤ p ≤ 99 999 999: both parts fit, the repeats below 10 000.
        let repeats = u32::try_from(p / 10_000).unwrap_or(1).max(1);
        Ok(Flow::Call(Call { program: program.unsigned_abs(), repeats, line }))
    }

    /// (3) An S word under gsk and fanuc: an integer (`NOT INTEGER`, COM.RANGES, wherever
    /// written); in a G50 block the maximum spindle speed, 1 … 99 999 (`OUT OF RANGE`,
    /// G50.SMAX). A surface speed or an rpm has no range here (G84 checks the rpm it taps with).
    pub(super) fn speed_word(&self, g50: bool, n: Number, at: At) -> Result<(), Alarm> {
        if g50 {
            integer_in(n, 1, 99_999, Rule::G50Smax, at)?;
        } else {
            integer_in(n, -i64::MAX, i64::MAX, Rule::ComRanges, at)?;
        }
        Ok(())
    }

    /// G96.SMAX, at the end of check step 4 (after the block's own missing words, before its
    /// step 5 and any motion): a block that writes G96 with no maximum set by a G50 S in an
    /// earlier block is `MISSING WORD S`. Each block handler calls it where its step 5 begins;
    /// the interpreter calls it again after the handler (for blocks without a step 5).
    pub(super) fn speed_limit(&self, line: u32) -> Result<(), Alarm> {
        if self.smax_due {
            return Err(Alarm::new(AlarmCode::MissingWord, Some(b'S'), Rule::G96Smax, line));
        }
        Ok(())
    }

    /// G96.RAPID (declared reading `g96.rapid`): under `refuse` (the letter) a block that moves
    /// at rapid — G00 written or modal, with axis words — while G96 is in force (the G96 block
    /// itself included) is `UNSUPPORTED` on G, before it moves. Rapids of cycles are not G00
    /// blocks and never come here.
    pub(super) fn rapid_under_g96(&self, line: u32) -> Result<(), Alarm> {
        if self.surface && self.config.readings.g96_rapid == G96Rapid::Refuse {
            return Err(Alarm::new(AlarmCode::Unsupported, Some(b'G'), Rule::G96Rapid, line));
        }
        Ok(())
    }

    /// G84.FORMAT under G98: the rpm the lead is derived from — under G96 `UNSUPPORTED` on G (the
    /// speed follows X; no tapping lead is given for it), else the rpm in force (the last S
    /// written under G97, never a G50 S nor a G96 S: none is `MISSING WORD S`), an integer
    /// 1 … 99 999 (`OUT OF RANGE` on S), all on the G84 block's line.
    pub(super) fn tapping_rpm(&self, line: u32) -> Result<i64, Alarm> {
        if self.surface {
            return Err(Alarm::new(AlarmCode::Unsupported, Some(b'G'), Rule::G84Format, line));
        }
        let at = At { letter: b'S', line };
        let s = self.spindle.ok_or(at.alarm(AlarmCode::MissingWord, Rule::G84Format))?;
        integer_in(s, 1, 99_999, Rule::G84Format, at)
    }
}
