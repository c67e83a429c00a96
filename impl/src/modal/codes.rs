//! Check step (2) of a block: its G and M codes (PRJ.SUPPORTED, PRJ.DIALECT, COM.UNITS,
//! PRJ.WORD, NC201.ABSINC), the family a cycle code selects (`family::lookup`), and the
//! nose-radius rules (TNRC.*).

use super::{Comp, Machine};
use crate::family::{self, FamilyCodes, Lookup};
use crate::lex::Block;
use crate::words::At;
use cycle_vocab::{Alarm, AlarmCode, Dialect, Rule, Units};

/// What step (2) found in a block's G and M codes.
#[derive(Clone, Copy, Debug)]
pub(super) struct Codes {
    /// The block's motion/cycle code, if any.
    pub(super) motion: Option<u64>,
    /// The family that code selects ([`family::FAMILIES`]), if any.
    pub(super) family: Option<&'static FamilyCodes>,
    /// M02 or M30: nothing after this block is read.
    pub(super) end: bool,
    /// NC201.ABSINC: G90 (`Some(false)`) or G91 (`Some(true)`) under nc201.
    pub(super) absinc: Option<bool>,
    /// G80 was written (it ends an M29 not followed by G84).
    pub(super) g80: bool,
    /// G96 was written (G96.SMAX).
    pub(super) g96: bool,
    /// M98 (`Some(true)`) or M99 (`Some(false)`): SUB.CALL, SUB.RETURN.
    pub(super) sub: Option<bool>,
}

impl Machine {
    /// (2) PRJ.SUPPORTED, PRJ.DIALECT, COM.UNITS, PRJ.WORD, NC201.ABSINC, TNRC.*: the G codes in
    /// the order written, then M, then two motion/cycle codes, G90 with G91 (nc201), then the
    /// nose-radius rules — TNRC.NOARC, TNRC.SWITCH (G, then T), TNRC.RADIUS — which update the
    /// compensation in force.
    pub(super) fn codes(&mut self, b: &Block, in_subprogram: bool) -> Result<Codes, Alarm> {
        let line = b.line;
        let g_alarm = |code: AlarmCode, rule: Rule| Alarm::new(code, Some(b'G'), rule, line);
        let dialect = self.config.dialect;
        let nc201 = dialect == Dialect::Nc201;
        let mut motion = None;
        let mut family = None;
        let mut motions = 0u32;
        let mut absinc = None;
        let mut absincs = 0u32;
        let mut tnrc = false;
        let mut g80 = false;
        let mut g96 = false;
        for g in b.g_codes() {
            if g.point || g.negative {
                return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjSupported));
            }
            match g.mantissa {
                0 | 1 => {}
                2 | 3 | 50 if !nc201 => {}
                // G80 (`Rule::G80`, no motion): ends an armed M29.
                80 if !nc201 => {
                    g80 = true;
                    continue;
                }
                40..=42 | 96 | 98 if !nc201 => {
                    tnrc |= matches!(g.mantissa, 40..=42);
                    // G98: feed per minute (G84.FORMAT's lead).
                    self.per_minute |= g.mantissa == 98;
                    // G96.SPEED: constant surface speed from this block on.
                    if g.mantissa == 96 {
                        self.surface = true;
                        g96 = true;
                    }
                    continue;
                }
                // G163 (M004's tapping / die cycle): named, its motion not given.
                163 if nc201 => return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::G163)),
                // M003's program words are not defined for the M004 controller (PRJ.DIALECT).
                2 | 3 | 41 | 42 | 50 | 80 | 96 | 98 if nc201 => {
                    return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjDialect))
                }
                // Under nc201 G90 is the absolute mode, no cycle (NC201.ABSINC).
                90 | 91 if nc201 => {
                    absincs += 1;
                    absinc = Some(g.mantissa == 91);
                    continue;
                }
                20 if self.config.grid.units != Units::Inch => {
                    return Err(g_alarm(AlarmCode::Unsupported, Rule::ComUnits))
                }
                21 if self.config.grid.units != Units::Metric => {
                    return Err(g_alarm(AlarmCode::Unsupported, Rule::ComUnits))
                }
                99 => {
                    self.per_minute = false;
                    continue;
                }
                97 => {
                    self.surface = false;
                    continue;
                }
                18 | 20 | 21 | 40 => continue,
                // A cycle code: the family it selects under this dialect (family::FAMILIES), a
                // cycle code of another dialect (PRJ.DIALECT), or no code at all.
                code => match family::lookup(code, dialect) {
                    Lookup::Selects(f) => family = Some(f),
                    Lookup::OtherDialect => return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjDialect)),
                    Lookup::None => return Err(g_alarm(AlarmCode::UnsupportedCode, Rule::PrjSupported)),
                },
            }
            motions += 1;
            motion = Some(g.mantissa);
        }
        let mut end = false;
        let mut sub = None;
        if let Some(m) = b.get(b'M') {
            let at = At { letter: b'M', line };
            if m.point {
                return Err(at.alarm(AlarmCode::NotInteger, Rule::ComRanges));
            }
            if m.negative || m.mantissa > 99 {
                return Err(at.alarm(AlarmCode::UnsupportedCode, Rule::PrjSupported));
            }
            end = m.mantissa == 2 || m.mantissa == 30;
            sub = match m.mantissa {
                98 => Some(true),
                // SUB.RETURN: M99 in the main program (FANUC restarts it endlessly).
                99 if !in_subprogram => return Err(at.alarm(AlarmCode::Unsupported, Rule::SubReturn)),
                99 => Some(false),
                _ => None,
            };
        }
        if motions > 1 {
            return Err(g_alarm(AlarmCode::Conflict, Rule::PrjWord));
        }
        // NC201.ABSINC: G90 with G91, or either twice.
        if absincs > 1 {
            return Err(g_alarm(AlarmCode::Conflict, Rule::Nc201AbsInc));
        }
        if tnrc || b.has(b'T') {
            self.compensation(b, motion)?;
        }
        Ok(Codes { motion, family, end, absinc, g80, g96, sub })
    }

    /// TNRC.NOARC, TNRC.SWITCH, TNRC.RADIUS (check step 2, after the two-motion-codes conflict):
    /// G40/G41/G42 with G02/G03; G41 while G42 is in force or G42 while G41 is (the codes taken in
    /// the order written); a T word after which G41 or G42 is still in force; G41/G42 with a
    /// nose radius. The compensation in force is updated. TNRC.TIP: no tip codes, no offset
    /// geometry — `comp` feeds these checks only, no move reads it.
    fn compensation(&mut self, b: &Block, motion: Option<u64>) -> Result<(), Alarm> {
        let g_alarm = |code: AlarmCode, rule: Rule| Alarm::new(code, Some(b'G'), rule, b.line);
        let codes = || b.g_codes().iter().map(|g| g.mantissa).filter(|m| matches!(m, 40..=42));
        if matches!(motion, Some(2 | 3)) && codes().next().is_some() {
            return Err(g_alarm(AlarmCode::Conflict, Rule::TnrcNoarc));
        }
        let mut comp = self.comp;
        let mut side = false;
        for code in codes() {
            comp = match (code, comp) {
                (41, Comp::Right) | (42, Comp::Left) => {
                    return Err(g_alarm(AlarmCode::WordNotAllowed, Rule::TnrcSwitch))
                }
                (41, _) => Comp::Left,
                (42, _) => Comp::Right,
                _ => Comp::Off,
            };
            side |= code != 40;
        }
        if b.has(b'T') && comp != Comp::Off {
            return Err(Alarm::new(AlarmCode::WordNotAllowed, Some(b'T'), Rule::TnrcSwitch, b.line));
        }
        if side && self.params.nose_radius != 0 {
            return Err(g_alarm(AlarmCode::Unsupported, Rule::TnrcRadius));
        }
        self.comp = comp;
        Ok(())
    }
}
