//! Machine parameters by number, with their defaults (docs/INTERPRETATION.md, Parameters), and
//! the configuration an expansion runs under.

use crate::units::{Grid, Increment, Units};

/// Input conventions (PRJ.DIALECT).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum Dialect {
    /// GSK: values without a decimal point are mm (inch).
    Gsk,
    /// FANUC: G76 P(k), Q(Δd), Q(Δdmin) without a decimal point are least increments (F76.MICRONS).
    Fanuc,
    /// The Russian controller of M004: G90/G91 (NC201.ABSINC), X and W radius or diameter by
    /// the parameter `x_radius` (NC201.XMODE), G162.
    Nc201,
}

/// Machine parameters. Lengths are counts of the least increment.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Params {
    /// No.19: G92 pull-out amount in tenths of the lead, 0…255 (G92.JK.1, G92.JK.2).
    pub no19_pullout: u32,
    /// No.107: G92 short-axis pull-out speed; only 0 (angle from J:K) is supported (G92.JK.8).
    pub no107_pullout_speed: u32,
    /// No.0018 bit 6: feed-hold behaviour (G92.HOLD; not modelled, recorded only).
    pub no18_bit6_hold: u32,
    /// 5130: chamfer (pull-out) width in tenths of the lead, 0…99.
    pub p5130_chamfer: u32,
    /// 5131: chamfer angle in degrees, 1…89.
    pub p5131_chamfer_angle: u32,
    /// 5140: minimum cut Δdmin, increments.
    pub p5140_min_cut: i64,
    /// 5141: finishing allowance d, increments.
    pub p5141_finish_allowance: i64,
    /// 5142: finishing passes m, 1…99.
    pub p5142_finish_passes: u32,
    /// 5143: tool angle a in degrees, 0…99.
    pub p5143_tool_angle: u32,
    /// 5144: G78 infeed mode, 0…4.
    pub p5144_infeed_mode: u32,
    /// 5145: G78 depth mode, 0…1.
    pub p5145_depth_mode: u32,
    /// PRJ.MAXPASS: the most thread cuts (passes × starts) one cycle may make, 1…1 000 000.
    pub max_passes: u32,
    /// NC201.XMODE: under `nc201`, X and W words are 0 = diameters, 1 = radii (0…1).
    #[cfg_attr(feature = "std", serde(default))]
    pub x_radius: u32,
}

impl Default for Params {
    fn default() -> Params {
        Params {
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
        }
    }
}

/// The largest length any word or parameter may hold, in increments (COM.RANGES).
pub const MAX_LENGTH: i64 = 999_999_999;

impl Params {
    /// Sets the parameter named `name` (`"19"`, `"107"`, `"18"`, `"5130"`…`"5145"`,
    /// `"max_passes"`, `"x_radius"`), checking its range. The error says what is legal.
    pub fn set(&mut self, name: &str, value: i64) -> Result<(), &'static str> {
        fn within(v: i64, lo: i64, hi: i64, err: &'static str) -> Result<i64, &'static str> {
            if (lo..=hi).contains(&v) { Ok(v) } else { Err(err) }
        }
        let small = |v, lo, hi, err| within(v, lo, hi, err).map(|v| v as u32);
        match name {
            "19" => self.no19_pullout = small(value, 0, 255, "No.19 takes 0…255")?,
            "107" => self.no107_pullout_speed = small(value, 0, 999_999, "No.107 takes 0…999999")?,
            "18" => self.no18_bit6_hold = small(value, 0, 1, "No.0018 bit 6 takes 0 or 1")?,
            "5130" => self.p5130_chamfer = small(value, 0, 99, "5130 takes 0…99")?,
            "5131" => self.p5131_chamfer_angle = small(value, 1, 89, "5131 takes 1…89")?,
            "5140" => self.p5140_min_cut = within(value, 0, MAX_LENGTH, "5140 takes 0…999999999")?,
            "5141" => self.p5141_finish_allowance = within(value, 0, MAX_LENGTH, "5141 takes 0…999999999")?,
            "5142" => self.p5142_finish_passes = small(value, 1, 99, "5142 takes 1…99")?,
            "5143" => self.p5143_tool_angle = small(value, 0, 99, "5143 takes 0…99")?,
            "5144" => self.p5144_infeed_mode = small(value, 0, 4, "5144 takes 0…4")?,
            "5145" => self.p5145_depth_mode = small(value, 0, 1, "5145 takes 0 or 1")?,
            "max_passes" => self.max_passes = small(value, 1, 1_000_000, "max_passes takes 1…1000000")?,
            "x_radius" => self.x_radius = small(value, 0, 1, "x_radius takes 0 (X diameter) or 1 (X radius)")?,
            _ => return Err("unknown parameter (19, 107, 18, 5130, 5131, 5140…5145, max_passes, x_radius)"),
        }
        Ok(())
    }
}

/// Everything an expansion depends on besides the program text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Config {
    pub dialect: Dialect,
    pub grid: Grid,
    pub params: Params,
    /// Machine position when the program starts: X (diameter) and Z, in increments.
    pub start_x: i64,
    pub start_z: i64,
}

impl Default for Config {
    fn default() -> Config {
        Config {
            dialect: Dialect::Gsk,
            grid: Grid { units: Units::Metric, increment: Increment::Isb },
            params: Params::default(),
            start_x: 0,
            start_z: 0,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn set_checks_ranges() {
        let mut p = Params::default();
        assert!(p.set("5140", 50).is_ok());
        assert_eq!(p.p5140_min_cut, 50);
        assert!(p.set("5144", 5).is_err());
        assert!(p.set("5131", 0).is_err());
        assert!(p.set("max_passes", 0).is_err());
        assert!(p.set("9999", 1).is_err());
        assert!(p.set("x_radius", 2).is_err());
        assert!(p.set("x_radius", 1).is_ok());
        assert_eq!(p.x_radius, 1);
    }
}
