//! Machine parameters by number and the configuration an expansion runs under.
//!
//! The configuration carries what was *set*: a parameter left `None` takes the machine's
//! default. Each engine keeps its own table of defaults and legal ranges (`spec/src/config.rs`,
//! `impl/src/config.rs`; docs/INTERPRETATION.md, "Parameters and defaults"), so a misread
//! default or range in one of them shows as a divergence instead of being shared by both.

use crate::operator::Script;
use crate::readings::Readings;
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

macro_rules! params {
    ($($field:ident => $name:literal: $doc:literal),* $(,)?) => {
        /// Machine parameters as configured: `None` where not set (the machine's default
        /// applies). Lengths are counts of the least increment.
        #[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
        #[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
        pub struct Params {
            $(
                #[doc = $doc]
                #[cfg_attr(feature = "std", serde(default, skip_serializing_if = "Option::is_none"))]
                pub $field: Option<i64>,
            )*
        }

        impl Params {
            /// The parameters' names as `--param` and the register write them, in order.
            pub const NAMES: &'static [&'static str] = &[$($name),*];

            /// Sets the parameter named `name` (one of [`Params::NAMES`]). Whether the value is
            /// legal is for the engines to say (an `OUT OF RANGE` alarm on line 0).
            pub fn set(&mut self, name: &str, value: i64) -> Result<(), UnknownParam> {
                match name {
                    $($name => self.$field = Some(value),)*
                    _ => return Err(UnknownParam),
                }
                Ok(())
            }

            /// The value set for the parameter named `name`, if any.
            pub fn get(&self, name: &str) -> Option<i64> {
                match name {
                    $($name => self.$field,)*
                    _ => None,
                }
            }
        }
    };
}

params! {
    no19_pullout => "19": "No.19: G92 pull-out amount in tenths of the lead (G92.JK.1, G92.JK.2).",
    no107_pullout_speed => "107": "No.107: G92 short-axis pull-out speed (G92.JK.8).",
    no18_bit6_hold => "18": "No.0018 bit 6: feed-hold behaviour (G92.HOLD).",
    p5130_chamfer => "5130": "5130: chamfer (pull-out) width in tenths of the lead.",
    p5131_chamfer_angle => "5131": "5131: chamfer angle in degrees.",
    p5140_min_cut => "5140": "5140: minimum cut Δdmin, increments.",
    p5141_finish_allowance => "5141": "5141: finishing allowance d, increments.",
    p5142_finish_passes => "5142": "5142: finishing passes m.",
    p5143_tool_angle => "5143": "5143: tool angle a in degrees.",
    p5144_infeed_mode => "5144": "5144: G78 infeed mode.",
    p5145_depth_mode => "5145": "5145: G78 depth mode.",
    max_passes => "max_passes": "PRJ.MAXPASS: the most thread cuts (passes × starts) one cycle may make.",
    x_radius => "x_radius": "NC201.XMODE: under `nc201`, X and W words are 0 = diameters, 1 = radii.",
    p5132_rough_depth => "5132": "5132: G71/G72 depth of cut Δd not yet given, increments (G71.PARAM).",
    p5133_rough_retract => "5133": "5133: G71/G72 retract e not yet given, increments (G71.PARAM).",
    arc_tolerance => "arc_tolerance": "ARC.TOL: how far an arc's end may lie off its circle, increments (radius).",
    nose_radius => "nose_radius": "TNRC.RADIUS: the tool nose radius, increments; only 0 is modelled.",
    p5135_escape_x => "5135": "5135: G73 Δi not yet given, increments, radius (G73.ESCAPE).",
    p5136_escape_z => "5136": "5136: G73 Δk not yet given, increments (G73.ESCAPE).",
    p5137_count => "5137": "5137: G73 d not yet given (G73.COUNT).",
    p5139_peck_return => "5139": "5139: G74/G75 return e not yet given, increments (G74.E).",
}

/// A `--param` name that is not one of [`Params::NAMES`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct UnknownParam;

/// Everything an expansion depends on besides the program text.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Config {
    pub dialect: Dialect,
    pub grid: Grid,
    /// Parameters set; the rest take the machine's defaults.
    #[cfg_attr(feature = "std", serde(default))]
    pub params: Params,
    /// Machine position when the program starts: X (diameter) and Z, in increments.
    pub start_x: i64,
    pub start_z: i64,
    /// Operator events while the program runs (OP.SCRIPT); empty: uninterrupted.
    #[cfg_attr(feature = "std", serde(default, skip_serializing_if = "Script::is_empty"))]
    pub operator: Script,
    /// The declared readings (docs/INTERPRETATION.md, "Declared readings"); default: the letter.
    #[cfg_attr(feature = "std", serde(default, skip_serializing_if = "Readings::is_letter"))]
    pub readings: Readings,
}

impl Default for Config {
    fn default() -> Config {
        Config {
            dialect: Dialect::Gsk,
            grid: Grid { units: Units::Metric, increment: Increment::Isb },
            params: Params::default(),
            start_x: 0,
            start_z: 0,
            operator: Script::EMPTY,
            readings: Readings::default(),
        }
    }
}

#[cfg(test)]
mod tests;
