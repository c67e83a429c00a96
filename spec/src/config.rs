//! The configuration an expansion runs under, checked before the first block (COM.RANGES and the
//! parameter ranges of docs/INTERPRETATION.md, Parameters).
//!
//! A configuration built through the library API can hold any value; the CLI's `--param` already
//! refuses illegal ones. Checking here, once, means no cycle ever computes with an illegal
//! parameter and every coordinate derived from words (≤ N) and the start point (≤ N) fits in i64.

use crate::multipass::fanuc_angle;
use crate::words::N;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Rule};

/// One parameter's legal range and the rule that uses it.
fn within(v: i64, lo: i64, hi: i64, word: Option<u8>, rule: Rule) -> Result<(), Alarm> {
    if (lo..=hi).contains(&v) {
        Ok(())
    } else {
        Err(Alarm::new(AlarmCode::OutOfRange, word, rule, 0))
    }
}

/// Checks, in this order: the start point (|X|, |Z| ≤ N: COM.RANGES, word X / Z), No.19
/// (G92.JK.1), No.0018 bit 6 (G92.HOLD), 5130 and 5131 (G76.PULLOUT), 5140, 5141, 5142, 5143
/// (G76.DEFAULTS), 5144 (G78.MODE), 5145 (G78.DEPTHMODE), `max_passes` (PRJ.MAXPASS), under
/// `fanuc` 5143 ∈ {80, 60, 55, 30, 29, 0} (F76.FORMAT), and `x_radius` ≤ 1 (NC201.XMODE, every
/// dialect). An illegal value is `OUT OF RANGE` on line 0 (the configuration). No.107 is legal in
/// any value up to 999 999; a value other than 0 is refused when a G92 cycle runs (G92.JK.8).
pub fn check(config: &Config) -> Result<(), Alarm> {
    let p = &config.params;
    within(config.start_x, -N, N, Some(b'X'), Rule::ComRanges)?;
    within(config.start_z, -N, N, Some(b'Z'), Rule::ComRanges)?;
    within(p.no19_pullout as i64, 0, 255, None, Rule::G92Jk1)?;
    within(p.no107_pullout_speed as i64, 0, 999_999, None, Rule::G92Jk8)?;
    within(p.no18_bit6_hold as i64, 0, 1, None, Rule::G92Hold)?;
    within(p.p5130_chamfer as i64, 0, 99, None, Rule::G76Pullout)?;
    within(p.p5131_chamfer_angle as i64, 1, 89, None, Rule::G76Pullout)?;
    within(p.p5140_min_cut, 0, N, None, Rule::G76Defaults)?;
    within(p.p5141_finish_allowance, 0, N, None, Rule::G76Defaults)?;
    within(p.p5142_finish_passes as i64, 1, 99, None, Rule::G76Defaults)?;
    within(p.p5143_tool_angle as i64, 0, 99, None, Rule::G76Defaults)?;
    within(p.p5144_infeed_mode as i64, 0, 4, None, Rule::G78Mode)?;
    within(p.p5145_depth_mode as i64, 0, 1, None, Rule::G78DepthMode)?;
    within(p.max_passes as i64, 1, 1_000_000, None, Rule::PrjMaxPass)?;
    if config.dialect == Dialect::Fanuc && !fanuc_angle(p.p5143_tool_angle) {
        return Err(Alarm::new(AlarmCode::OutOfRange, None, Rule::F76Format, 0));
    }
    within(p.x_radius as i64, 0, 1, None, Rule::Nc201XMode)?;
    Ok(())
}
