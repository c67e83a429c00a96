//! The machine parameters: the expander's own defaults, and the configuration check before the
//! first block (docs/INTERPRETATION.md, "Parameters and defaults" and "The configuration is
//! checked before the first block"): each bad value is `OUT OF RANGE` on line 0.

use crate::words::MAX_LENGTH;
use cycle_vocab::{Action, Alarm, AlarmCode, Config, Dialect, Rule, Script};

/// FANUC tool angles (F76.FORMAT, PRJ.DIALECT: `003_…` line 5 lists 40 too).
pub const FANUC_ANGLES: [u32; 7] = [80, 60, 55, 40, 30, 29, 0];

/// The machine parameters in force: each value set in the configuration, else the default.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Params {
    pub no19_pullout: u32,
    pub no107_pullout_speed: u32,
    pub no18_bit6_hold: u32,
    pub p5130_chamfer: u32,
    pub p5131_chamfer_angle: u32,
    pub p5140_min_cut: i64,
    pub p5141_finish_allowance: i64,
    pub p5142_finish_passes: u32,
    pub p5143_tool_angle: u32,
    pub p5144_infeed_mode: u32,
    pub p5145_depth_mode: u32,
    pub max_passes: u32,
    pub x_radius: u32,
    pub p5132_rough_depth: i64,
    pub p5133_rough_retract: i64,
    pub arc_tolerance: i64,
    pub nose_radius: i64,
    pub p5135_escape_x: i64,
    pub p5136_escape_z: i64,
    pub p5137_count: u32,
    pub p5139_peck_return: i64,
}

/// The defaults this controller ships with.
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

fn out(word: Option<u8>, rule: Rule) -> Alarm {
    Alarm::new(AlarmCode::OutOfRange, word, rule, 0)
}

/// One parameter: the value set, else `default`, within `lo..=hi` (else `OUT OF RANGE` under
/// `rule`).
fn small(set: Option<i64>, default: u32, lo: u32, hi: u32, rule: Rule) -> Result<u32, Alarm> {
    match set {
        None => Ok(default),
        Some(v) => u32::try_from(v).ok().filter(|v| (lo..=hi).contains(v)).ok_or(out(None, rule)),
    }
}

/// A length parameter: the value set, else `default`, within 0…N.
fn length(set: Option<i64>, default: i64, rule: Rule) -> Result<i64, Alarm> {
    length_from(set, default, 0, rule)
}

/// A length parameter: the value set, else `default`, within `lo`…N.
fn length_from(set: Option<i64>, default: i64, lo: i64, rule: Rule) -> Result<i64, Alarm> {
    let v = set.unwrap_or(default);
    if (lo..=MAX_LENGTH).contains(&v) {
        Ok(v)
    } else {
        Err(out(None, rule))
    }
}

/// COM.RANGES, G92.JK.1, G92.JK.8, G92.HOLD, G76.PULLOUT, G76.DEFAULTS, G78.MODE,
/// G78.DEPTHMODE, PRJ.MAXPASS, F76.FORMAT, NC201.XMODE, G71.PARAM, ARC.TOL, TNRC.RADIUS,
/// G73.ESCAPE, G73.COUNT, G74.E: the
/// configuration, in the register's order; the parameters in force when it is legal.
pub fn check(c: &Config) -> Result<Params, Alarm> {
    let p = &c.params;
    let d = DEFAULTS;
    if c.start_x.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
        return Err(out(Some(b'X'), Rule::ComRanges));
    }
    if c.start_z.unsigned_abs() > MAX_LENGTH.unsigned_abs() {
        return Err(out(Some(b'Z'), Rule::ComRanges));
    }
    let params = Params {
        no19_pullout: small(p.no19_pullout, d.no19_pullout, 0, 255, Rule::G92Jk1)?,
        no107_pullout_speed: small(p.no107_pullout_speed, d.no107_pullout_speed, 0, 999_999, Rule::G92Jk8)?,
        no18_bit6_hold: small(p.no18_bit6_hold, d.no18_bit6_hold, 0, 1, Rule::G92Hold)?,
        p5130_chamfer: small(p.p5130_chamfer, d.p5130_chamfer, 0, 99, Rule::G76Pullout)?,
        p5131_chamfer_angle: small(p.p5131_chamfer_angle, d.p5131_chamfer_angle, 1, 89, Rule::G76Pullout)?,
        p5140_min_cut: length(p.p5140_min_cut, d.p5140_min_cut, Rule::G76Defaults)?,
        p5141_finish_allowance: length(p.p5141_finish_allowance, d.p5141_finish_allowance, Rule::G76Defaults)?,
        p5142_finish_passes: small(p.p5142_finish_passes, d.p5142_finish_passes, 1, 99, Rule::G76Defaults)?,
        p5143_tool_angle: small(p.p5143_tool_angle, d.p5143_tool_angle, 0, 99, Rule::G76Defaults)?,
        p5144_infeed_mode: small(p.p5144_infeed_mode, d.p5144_infeed_mode, 0, 4, Rule::G78Mode)?,
        p5145_depth_mode: small(p.p5145_depth_mode, d.p5145_depth_mode, 0, 1, Rule::G78DepthMode)?,
        max_passes: small(p.max_passes, d.max_passes, 1, 1_000_000, Rule::PrjMaxPass)?,
        x_radius: d.x_radius,
        p5132_rough_depth: d.p5132_rough_depth,
        p5133_rough_retract: d.p5133_rough_retract,
        arc_tolerance: d.arc_tolerance,
        nose_radius: d.nose_radius,
        p5135_escape_x: d.p5135_escape_x,
        p5136_escape_z: d.p5136_escape_z,
        p5137_count: d.p5137_count,
        p5139_peck_return: d.p5139_peck_return,
    };
    if c.dialect == Dialect::Fanuc && !FANUC_ANGLES.contains(&params.p5143_tool_angle) {
        return Err(out(None, Rule::F76Format));
    }
    // Checked under every dialect, read only under nc201.
    let x_radius = small(p.x_radius, d.x_radius, 0, 1, Rule::Nc201XMode)?;
    let p5132_rough_depth = length_from(p.p5132_rough_depth, d.p5132_rough_depth, 1, Rule::G71Param)?;
    let p5133_rough_retract = length(p.p5133_rough_retract, d.p5133_rough_retract, Rule::G71Param)?;
    let arc_tolerance = length(p.arc_tolerance, d.arc_tolerance, Rule::ArcTol)?;
    let nose_radius = length(p.nose_radius, d.nose_radius, Rule::TnrcRadius)?;
    let signed = |set: Option<i64>, default: i64| {
        let v = set.unwrap_or(default);
        if v.unsigned_abs() <= MAX_LENGTH.unsigned_abs() { Ok(v) } else { Err(out(None, Rule::G73Escape)) }
    };
    let p5135_escape_x = signed(p.p5135_escape_x, d.p5135_escape_x)?;
    let p5136_escape_z = signed(p.p5136_escape_z, d.p5136_escape_z)?;
    let p5137_count = small(p.p5137_count, d.p5137_count, 1, 1_000_000, Rule::G73Count)?;
    let p5139_peck_return = length(p.p5139_peck_return, d.p5139_peck_return, Rule::G74E)?;
    Ok(Params {
        x_radius,
        p5132_rough_depth,
        p5133_rough_retract,
        arc_tolerance,
        nose_radius,
        p5135_escape_x,
        p5136_escape_z,
        p5137_count,
        p5139_peck_return,
        ..params
    })
}

/// OP.SCRIPT: checked with the configuration, after its other checks: 1 ≤ den ≤ 1 000 000
/// and num ≤ den for every Hold and Reset, else `OUT OF RANGE` on line 0, no word. The
/// script's length is bounded by its type (`SCRIPT_MAX`).
pub fn check_script(script: &Script) -> Result<(), Alarm> {
    for a in script.actions() {
        if let Action::Hold(p) | Action::Reset(p) = a {
            if !p.is_legal() {
                return Err(Alarm::new(AlarmCode::OutOfRange, None, Rule::OpScript, 0));
            }
        }
    }
    Ok(())
}
