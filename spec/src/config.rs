//! The configuration an expansion runs under, checked before the first block (COM.RANGES and the
//! parameter ranges of docs/INTERPRETATION.md, Parameters).
//!
//! A configuration built through the library API can hold any value; the CLI's `--param` already
//! refuses illegal ones. Checking here, once, means no cycle ever computes with an illegal
//! parameter and every coordinate derived from words (≤ N) and the start point (≤ N) fits in i64.

use crate::multipass::fanuc_angle;
use crate::words::N;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Rule};

/// The machine parameters with a value for each: the one set in the configuration, else the
/// machine's default ([`DEFAULTS`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Params {
    pub no19_pullout: i64,
    pub no107_pullout_speed: i64,
    pub no18_bit6_hold: i64,
    pub p5130_chamfer: i64,
    pub p5131_chamfer_angle: i64,
    pub p5140_min_cut: i64,
    pub p5141_finish_allowance: i64,
    pub p5142_finish_passes: i64,
    pub p5143_tool_angle: i64,
    pub p5144_infeed_mode: i64,
    pub p5145_depth_mode: i64,
    pub max_passes: i64,
    pub x_radius: i64,
    pub p5132_rough_depth: i64,
    pub p5133_rough_retract: i64,
    pub arc_tolerance: i64,
    pub nose_radius: i64,
    pub p5135_escape_x: i64,
    pub p5136_escape_z: i64,
    pub p5137_count: i64,
    pub p5139_peck_return: i64,
}

/// The defaults of docs/INTERPRETATION.md, "Parameters and defaults": No.19 one lead (G92.JK.1),
/// No.107 0 (G92.JK.8), No.0018 bit 6 0, 5130 one lead and 5131 45° (G76.PULLOUT), 5140 and 5141
/// 100 increments, 5142 one finishing pass, 5143 60° (G76.DEFAULTS), 5144 centre infeed (G78.MODE),
/// 5145 degressive (G78.DEPTHMODE), 10 000 cuts (PRJ.MAXPASS), X as diameters (NC201.XMODE),
/// 5132 a depth of cut of 1 000 and 5133 a retract of 500 increments (G71.PARAM), an arc end
/// within 10 increments of its circle (ARC.TOL), no nose radius (TNRC.RADIUS), G73's Δi, Δk 0 and
/// d 1 (G73.ESCAPE, G73.COUNT), no G74/G75 return (G74.E).
pub const DEFAULTS: Params = Params {
    no19_pullout: 10,
    no107_pullout_speed: 0,
    no18_bit6_hold: 0,
    p5130_chamfer: 10,
    p5131_chamfer_angle: 45,
    p5140_min_cut: 100,
    p5141_finish_allowance: 100,
    p5142_finish_passes: 1,
    p5143_tool_angle: 60,
    p5144_infeed_mode: 0,
    p5145_depth_mode: 1,
    max_passes: 10_000,
    x_radius: 0,
    p5132_rough_depth: 1_000,
    p5133_rough_retract: 500,
    arc_tolerance: 10,
    nose_radius: 0,
    p5135_escape_x: 0,
    p5136_escape_z: 0,
    p5137_count: 1,
    p5139_peck_return: 0,
};

/// The parameters of `config`: each set value, else its default.
pub fn params(config: &Config) -> Params {
    let set = &config.params;
    let d = DEFAULTS;
    Params {
        no19_pullout: set.no19_pullout.unwrap_or(d.no19_pullout),
        no107_pullout_speed: set.no107_pullout_speed.unwrap_or(d.no107_pullout_speed),
        no18_bit6_hold: set.no18_bit6_hold.unwrap_or(d.no18_bit6_hold),
        p5130_chamfer: set.p5130_chamfer.unwrap_or(d.p5130_chamfer),
        p5131_chamfer_angle: set.p5131_chamfer_angle.unwrap_or(d.p5131_chamfer_angle),
        p5140_min_cut: set.p5140_min_cut.unwrap_or(d.p5140_min_cut),
        p5141_finish_allowance: set.p5141_finish_allowance.unwrap_or(d.p5141_finish_allowance),
        p5142_finish_passes: set.p5142_finish_passes.unwrap_or(d.p5142_finish_passes),
        p5143_tool_angle: set.p5143_tool_angle.unwrap_or(d.p5143_tool_angle),
        p5144_infeed_mode: set.p5144_infeed_mode.unwrap_or(d.p5144_infeed_mode),
        p5145_depth_mode: set.p5145_depth_mode.unwrap_or(d.p5145_depth_mode),
        max_passes: set.max_passes.unwrap_or(d.max_passes),
        x_radius: set.x_radius.unwrap_or(d.x_radius),
        p5132_rough_depth: set.p5132_rough_depth.unwrap_or(d.p5132_rough_depth),
        p5133_rough_retract: set.p5133_rough_retract.unwrap_or(d.p5133_rough_retract),
        arc_tolerance: set.arc_tolerance.unwrap_or(d.arc_tolerance),
        nose_radius: set.nose_radius.unwrap_or(d.nose_radius),
        p5135_escape_x: set.p5135_escape_x.unwrap_or(d.p5135_escape_x),
        p5136_escape_z: set.p5136_escape_z.unwrap_or(d.p5136_escape_z),
        p5137_count: set.p5137_count.unwrap_or(d.p5137_count),
        p5139_peck_return: set.p5139_peck_return.unwrap_or(d.p5139_peck_return),
    }
}

impl Params {
    /// Every parameter as set, for a request that must name them all (the candidate protocol).
    pub fn as_set(&self) -> cycle_vocab::Params {
        cycle_vocab::Params {
            no19_pullout: Some(self.no19_pullout),
            no107_pullout_speed: Some(self.no107_pullout_speed),
            no18_bit6_hold: Some(self.no18_bit6_hold),
            p5130_chamfer: Some(self.p5130_chamfer),
            p5131_chamfer_angle: Some(self.p5131_chamfer_angle),
            p5140_min_cut: Some(self.p5140_min_cut),
            p5141_finish_allowance: Some(self.p5141_finish_allowance),
            p5142_finish_passes: Some(self.p5142_finish_passes),
            p5143_tool_angle: Some(self.p5143_tool_angle),
            p5144_infeed_mode: Some(self.p5144_infeed_mode),
            p5145_depth_mode: Some(self.p5145_depth_mode),
            max_passes: Some(self.max_passes),
            x_radius: Some(self.x_radius),
            p5132_rough_depth: Some(self.p5132_rough_depth),
            p5133_rough_retract: Some(self.p5133_rough_retract),
            arc_tolerance: Some(self.arc_tolerance),
            nose_radius: Some(self.nose_radius),
            p5135_escape_x: Some(self.p5135_escape_x),
            p5136_escape_z: Some(self.p5136_escape_z),
            p5137_count: Some(self.p5137_count),
            p5139_peck_return: Some(self.p5139_peck_return),
        }
    }
}

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
/// `fanuc` 5143 ∈ {80, 60, 55, 40, 30, 29, 0} (F76.FORMAT), `x_radius` ≤ 1 (NC201.XMODE, every
/// dialect), 5132 in 1…N and 5133 in 0…N (G71.PARAM), `arc_tolerance` in 0…N (ARC.TOL),
/// `nose_radius` in 0…N (TNRC.RADIUS), 5135 and 5136 in −N…N (G73.ESCAPE), 5137 in 1…1 000 000
/// (G73.COUNT), 5139 in 0…N (G74.E), then the operator script (OP.SCRIPT). An illegal value is `OUT OF RANGE` on line 0 (the configuration). No.107 is legal in
/// any value up to 999 999; a value other than 0 is refused when a G92 cycle runs (G92.JK.8).
pub fn check(config: &Config) -> Result<(), Alarm> {
    let p = params(config);
    within(config.start_x, -N, N, Some(b'X'), Rule::ComRanges)?;
    within(config.start_z, -N, N, Some(b'Z'), Rule::ComRanges)?;
    within(p.no19_pullout, 0, 255, None, Rule::G92Jk1)?;
    within(p.no107_pullout_speed, 0, 999_999, None, Rule::G92Jk8)?;
    within(p.no18_bit6_hold, 0, 1, None, Rule::G92Hold)?;
    within(p.p5130_chamfer, 0, 99, None, Rule::G76Pullout)?;
    within(p.p5131_chamfer_angle, 1, 89, None, Rule::G76Pullout)?;
    within(p.p5140_min_cut, 0, N, None, Rule::G76Defaults)?;
    within(p.p5141_finish_allowance, 0, N, None, Rule::G76Defaults)?;
    within(p.p5142_finish_passes, 1, 99, None, Rule::G76Defaults)?;
    within(p.p5143_tool_angle, 0, 99, None, Rule::G76Defaults)?;
    within(p.p5144_infeed_mode, 0, 4, None, Rule::G78Mode)?;
    within(p.p5145_depth_mode, 0, 1, None, Rule::G78DepthMode)?;
    within(p.max_passes, 1, 1_000_000, None, Rule::PrjMaxPass)?;
    if config.dialect == Dialect::Fanuc && !fanuc_angle(p.p5143_tool_angle as u32) {
        return Err(Alarm::new(AlarmCode::OutOfRange, None, Rule::F76Format, 0));
    }
    within(p.x_radius, 0, 1, None, Rule::Nc201XMode)?;
    within(p.p5132_rough_depth, 1, N, None, Rule::G71Param)?;
    within(p.p5133_rough_retract, 0, N, None, Rule::G71Param)?;
    within(p.arc_tolerance, 0, N, None, Rule::ArcTol)?;
    within(p.nose_radius, 0, N, None, Rule::TnrcRadius)?;
    within(p.p5135_escape_x, -N, N, None, Rule::G73Escape)?;
    within(p.p5136_escape_z, -N, N, None, Rule::G73Escape)?;
    within(p.p5137_count, 1, 1_000_000, None, Rule::G73Count)?;
    within(p.p5139_peck_return, 0, N, None, Rule::G74E)?;
    crate::operator::point::check_script(&config.operator)
}
