//! Spindle speed: G50 S, G96, G97 (M003: G50.SMAX, G96.SPEED, G96.SMAX, G96.RAPID), under `gsk`
//! and `fanuc` (docs/INTERPRETATION.md, "Spindle speed: G50 S, G96, G97").
//!
//! The trace carries no spindle speed: these rules decide alarms and G84's lead under G98. The
//! program starts in G97 with no spindle speed, no surface speed and no maximum. G96 and G97 are
//! modal and take effect in the block that writes them; an S word means, in the block's state
//! after its G codes, the maximum (with G50 in the block), else the surface speed (G96), else
//! the spindle speed in rpm (G97).

use crate::lex::{Block, Number};
use crate::program::code_value;
use crate::words::{alarm, in_range, whole};
use cycle_vocab::readings::G96Rapid;
use cycle_vocab::{Alarm, AlarmCode, Rule};
use num_traits::ToPrimitive;

/// G50.SMAX: the maximum spindle speed, rpm: 1 … 99 999.
pub const MAX_RPM: i64 = 99_999;

/// The spindle state between blocks. Contour blocks never change it (CNT.MODAL).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Spindle {
    /// G96.SPEED: constant surface speed (G96) in force; `false` is G97, the start.
    pub constant_surface: bool,
    /// The last S written under G97: the spindle speed in rpm, as written (G84 checks its
    /// range). "G97 without S keeps the last rpm set under G97."
    pub rpm: Option<i64>,
    /// G96.SPEED: the last S written under G96, the surface speed (m/min, ft/min). Nothing
    /// reads it: the trace has no speed, and G84 under G96 and G98 is refused.
    pub surface: Option<i64>,
    /// G50.SMAX: the maximum set by the last G50 S, rpm.
    pub max: Option<i64>,
}

/// Whether the block writes G50 (its S is then the maximum).
pub fn writes_g50(b: &Block) -> bool {
    b.g_codes().any(|g| code_value(g) == Some(50))
}

/// Whether the block writes G96.
pub fn writes_g96(b: &Block) -> bool {
    b.g_codes().any(|g| code_value(g) == Some(96))
}

/// Check step 3, the S word (G50.SMAX, COM.RANGES): "S values are integers (`NOT INTEGER` with a
/// point, COM.RANGES); G50 S 1 … 99 999, else `OUT OF RANGE` on S, rule G50.SMAX". Another S
/// takes any integer (at most 18 digits, PRJ.LEX, so it fits an `i64`); G84 checks its rpm.
pub fn s_value(n: &Number, g50: bool, line: u32) -> Result<i64, Alarm> {
    let v = whole(n, b'S', line)?;
    if g50 {
        return in_range(&v, 1, MAX_RPM, b'S', Rule::G50Smax, line);
    }
    v.to_i64().ok_or(alarm(AlarmCode::OutOfRange, b'S', Rule::ComRanges, line))
}

impl Spindle {
    /// G96.SMAX (M003, `003_…` line 11: "在恒线速度指令前必须限制最高转速", before constant surface
    /// speed the maximum must be limited): a block that writes G96 with no maximum set by a G50
    /// S in an **earlier** block is `MISSING WORD S`, rule G96.SMAX. Decided before the block's
    /// own S is taken ([`Spindle::take`]); raised at the end of check step 4.
    pub fn smax_missing(&self, b: &Block) -> Option<Alarm> {
        (writes_g96(b) && self.max.is_none()).then(|| alarm(AlarmCode::MissingWord, b'S', Rule::G96Smax, b.line))
    }

    /// G96.SPEED, G50.SMAX (M003, `003_…` lines 9–10: "G50 s1500 … 达到1500转的时候就不在往上提速"):
    /// the block's G96 / G97 in the order written, then its S (`s`, already read) by what it
    /// means in that state: the maximum with G50 in the block, else the surface speed under G96,
    /// else the rpm.
    pub fn take(&mut self, b: &Block, s: Option<i64>) {
        for g in b.g_codes() {
            match code_value(g) {
                Some(96) => self.constant_surface = true,
                Some(97) => self.constant_surface = false,
                _ => {}
            }
        }
        let Some(s) = s else { return };
        if writes_g50(b) {
            self.max = Some(s);
        } else if self.constant_surface {
            self.surface = Some(s);
        } else {
            self.rpm = Some(s);
        }
    }

    /// G96.RAPID (declared reading `g96.rapid`; `003_…` lines 12–13: "在G96程序段开始及之下、G97程序段之前,
    /// 一般不能出现G00程序段"): under `refuse` (the letter) a program block that moves at rapid
    /// (G00 written or modal, with axis words) while G96 is in force, the G96 block itself
    /// included, is `UNSUPPORTED` on G, rule G96.RAPID, before it moves; `allow` runs it.
    pub fn rapid(&self, reading: G96Rapid, line: u32) -> Result<(), Alarm> {
        match reading {
            G96Rapid::Refuse if self.constant_surface => Err(alarm(AlarmCode::Unsupported, b'G', Rule::G96Rapid, line)),
            G96Rapid::Refuse | G96Rapid::Allow => Ok(()),
        }
    }

    /// G84.FORMAT (M003, "S and G98/G99"): the speed rigid tapping under G98 divides F by — "the
    /// last S written under G97 … never a G50 S (the maximum) nor an S under G96 (a surface
    /// speed)". Under G96 `UNSUPPORTED` on G (the seeds give no tapping lead for a speed that
    /// follows X); none `MISSING WORD S`; outside 1 … 99 999 `OUT OF RANGE` on S; all G84.FORMAT.
    pub fn tapping_rpm(&self, line: u32) -> Result<i64, Alarm> {
        if self.constant_surface {
            return Err(alarm(AlarmCode::Unsupported, b'G', Rule::G84Format, line));
        }
        let Some(rpm) = self.rpm else {
            return Err(alarm(AlarmCode::MissingWord, b'S', Rule::G84Format, line));
        };
        if (1..=MAX_RPM).contains(&rpm) {
            Ok(rpm)
        } else {
            Err(alarm(AlarmCode::OutOfRange, b'S', Rule::G84Format, line))
        }
    }
}
