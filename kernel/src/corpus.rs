//! The built-in corpus: the manuals' example programs (`corpus/*.nc`) and one program per
//! feature (`tests/programs/*.nc`), compiled in, each with the configuration it runs under and
//! the rule IDs it illustrates.
//!
//! A program *illustrates* a rule when running it shows the rule at work, whether or not a move
//! carries the rule's tag: `g76_example` illustrates G76.DEFAULTS (its second block omits R: i
//! = 0), G76.FINISH.Z (its two finishing passes at the Z of the last rough one) and PRJ.NOOP (its
//! last G00 goes where the cycle ended: not emitted). The traceability matrix counts a rule
//! illustrated by a program that ran and conformed as exercised.
//!
//! Configurations follow the files' header comments: `f76_ex1_microns` runs under the `fanuc`
//! dialect (F76.MICRONS), the G162 programs under `nc201` (M004), the `*_inch` programs in inch
//! units (they write G20), a program whose header names `--reading NAME=VALUE` or `--param N=V`
//! under that declared reading or parameter (e.g. `g94_taper` under `g94.k=start-minus-end`), the
//! rest under the defaults (gsk, metric, ISB, start X0 Z0, the manuals' letter). The G78 example as printed has infeed mode 05,
//! outside 0…4: its expected result is that alarm (G78.MODE), and an engine that raises it
//! conforms.

use cycle_vocab::{AlarmCode, Config, Dialect, Grid, Increment, Params, Readings, Rule, Units};

/// An alarm a corpus program is expected to end in: code, word, rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ExpectedAlarm {
    pub code: AlarmCode,
    pub word: Option<u8>,
    pub rule: Rule,
}

/// One built-in program.
#[derive(Clone, Copy, Debug)]
pub struct Program {
    /// File stem, e.g. `g92_example`.
    pub name: &'static str,
    /// Path from the repository root.
    pub path: &'static str,
    /// The program text.
    pub text: &'static str,
    pub dialect: Dialect,
    pub units: Units,
    /// The increment system (ISB, or ISC where the header says `--increment isc`).
    pub increment: Increment,
    /// The rule IDs the program illustrates.
    pub rules: &'static [Rule],
    /// `Some` when the program is expected to end in this alarm.
    pub expect_alarm: Option<ExpectedAlarm>,
    /// Declared readings other than the letter, as `--reading NAME=VALUE` writes them.
    pub readings: &'static [(&'static str, &'static str)],
    /// Parameters set, as `--param N=V` writes them.
    pub params: &'static [(&'static str, i64)],
}

impl Program {
    /// The configuration the program runs under. The table's reading and parameter names are
    /// checked by this module's tests; an unknown one is left unset here.
    pub fn config(&self) -> Config {
        let mut readings = Readings::default();
        for (name, value) in self.readings {
            let _ = readings.set(name, value);
        }
        let mut params = Params::default();
        for (name, value) in self.params {
            let _ = params.set(name, *value);
        }
        Config {
            dialect: self.dialect,
            grid: Grid { units: self.units, increment: self.increment },
            params,
            readings,
            ..Config::default()
        }
    }
}

macro_rules! program {
    ($dir:literal, $name:literal, $dialect:ident, $units:ident $(/ $increment:ident)?, [$($rule:ident),* $(,)?] $(, alarm $code:ident $word:literal $arule:ident)? $(, reading $rname:literal = $rvalue:literal)* $(, param $pname:literal = $pvalue:literal)*) => {
        Program {
            name: $name,
            path: concat!($dir, "/", $name, ".nc"),
            text: include_str!(concat!("../../", $dir, "/", $name, ".nc")),
            dialect: Dialect::$dialect,
            units: Units::$units,
            increment: program!(@increment $($increment)?),
            rules: &[$(Rule::$rule),*],
            expect_alarm: program!(@alarm $($code $word $arule)?),
            readings: &[$(($rname, $rvalue)),*],
            params: &[$(($pname, $pvalue)),*],
        }
    };
    (@increment) => { Increment::Isb };
    (@increment $increment:ident) => { Increment::$increment };
    (@alarm) => { None };
    (@alarm $code:ident $word:literal $rule:ident) => {
        Some(ExpectedAlarm { code: AlarmCode::$code, word: Some($word), rule: Rule::$rule })
    };
}

/// Every built-in program: the manuals' examples first, then the feature programs.
pub const PROGRAMS: &[Program] = &[
    // The manuals' examples (corpus/).
    program!("corpus", "g92_example", Gsk, Metric, [G92Example, G92Format, G92Modal, G92Path, G92Pullout, ComAxes, PrjTrace]),
    program!("corpus", "g76_example", Gsk, Metric, [G76Example, G76Format, G76Depth1, G76DepthMin, G76DepthLast, G76Finish, G76FinishZ, G76Defaults, G76Pullout, G76Path, PrjNoop]),
    program!("corpus", "g78_example", Gsk, Metric, [G78Example, G78Format, G78Mode], alarm OutOfRange b'P' G78Mode),
    program!("corpus", "f76_ex1", Gsk, Metric, [F76Ex1, F76Format, G76Depth1, G76DepthLast, G76Finish, G76Pullout]),
    program!("corpus", "f76_ex1_microns", Fanuc, Metric, [F76Ex1, F76Microns, PrjDialect, F76Format]),
    program!("corpus", "f76_ex2", Gsk, Metric, [F76Ex2, F76Format, G76Depth1, G76DepthMin, G76DepthLast, G76Finish]),
    program!("corpus", "g162_cone", Nc201, Metric, [G162Format, G162F, G162W, G162Pq, G162Path, Nc201XMode]),
    program!("corpus", "g90_example", Gsk, Metric, [G90Example, G90Format, G90Modal, G90Path, G90Taper]),
    program!("corpus", "g94_example", Gsk, Metric, [G94Example, G94Format, G94Modal, G94Path]),
    program!("corpus", "g71_example", Gsk, Metric, [G71Example, G71Format, G71Layer, G71Retract, G71Lastpass, G71Return, ArcR, G50Coord, G70Path, G70Return]),
    program!("corpus", "g72_example", Gsk, Metric, [G72Example, G72Format, G72Layer, G72Retract, G72Lastpass, G72Return, G70Path]),
    program!("corpus", "g73_example", Gsk, Metric, [G73Example, G73Format, G73Uw, G73Escape, G73Count, G73Depth, G73Path, ArcR, G70Path]),
    program!("corpus", "g74_example", Gsk, Metric, [G74Example, G74Format, G74E, G74Peck, G74Column]),
    program!("corpus", "g75_example", Gsk, Metric, [G75Example, G75Format, G75Peck, G75Column]),
    program!("corpus", "g83_example", Gsk, Metric, [G83Format, G83Peck]),
    program!("corpus", "g84_example", Gsk, Metric, [G84Format, G84Path, G80]),
    // One program per feature (tests/programs/).
    program!("tests/programs", "g92_taper", Gsk, Metric, [G92Taper, G92Pullout, G92Modal, ComLongAxis]),
    program!("tests/programs", "g92_internal", Gsk, Metric, [ComSide, G92Jk1, G92Pullout, G92Modal]),
    program!("tests/programs", "g92_inch", Gsk, Inch, [ComUnits, ComLead, G92Format]),
    program!("tests/programs", "g92_multistart", Gsk, Metric, [ComMultiStart, G92Format, G92Modal]),
    program!("tests/programs", "g92_modal_pullout", Gsk, Metric, [G92Modal, G92Jk1, G92Jk3, G92Pullout, G92Taper, ComSide]),
    program!("tests/programs", "g92_5131", Gsk, Metric, [G92Jk1, G92Pullout], param "5131" = 30),
    program!("tests/programs", "g92_step3", Gsk, Metric, [G92Path, G92Pullout, G92Modal], alarm Geometry b'J' G92Path),
    program!("tests/programs", "g76_taper", Gsk, Metric, [G76Format, G76Pullout, G76InfeedX, ComPoints]),
    program!("tests/programs", "g76_internal", Gsk, Metric, [ComSide, G76InfeedX, G76InfeedZ]),
    program!("tests/programs", "g76_inch", Gsk, Inch, [ComUnits, ComLead]),
    program!("tests/programs", "g76_multistart", Gsk, Metric, [ComMultiStart, G76MultiStart, G76LeadIn]),
    program!("tests/programs", "g76_mode0", Gsk, Metric, [G76Mode, G76InfeedZ]),
    program!("tests/programs", "g76_mode1", Gsk, Metric, [G76Mode, G76InfeedZ]),
    program!("tests/programs", "g76_mode2", Gsk, Metric, [G76Mode, G76InfeedZ]),
    program!("tests/programs", "g78_mode0", Gsk, Metric, [G78Mode, G78DepthMode]),
    program!("tests/programs", "g78_mode1", Gsk, Metric, [G78Mode, G78DepthMode]),
    program!("tests/programs", "g78_mode2", Gsk, Metric, [G78Mode, G78DepthMode]),
    program!("tests/programs", "g78_mode3", Gsk, Metric, [G78Mode, G78DepthMode]),
    program!("tests/programs", "g78_mode4", Gsk, Metric, [G78Mode, G78DepthMode]),
    program!("tests/programs", "g78_constant", Gsk, Metric, [G78DepthMode, G76DepthLast]),
    program!("tests/programs", "g78_jk_modal", Gsk, Metric, [G78Pullout, G78Format]),
    program!("tests/programs", "g78_zref", Gsk, Metric, [G78Mode, G76InfeedZ, G76FinishZ], reading "thread.zref" = "groove"),
    program!("tests/programs", "f76_angle40", Fanuc, Metric, [F76Format, G76InfeedZ]),
    program!("tests/programs", "g162_straight", Nc201, Metric, [G162Pq, G162Split, G162V, G162Path, G162Retract]),
    program!("tests/programs", "g162_taper", Nc201, Metric, [G162W, G162A, G162F, G162V, G162Split]),
    program!("tests/programs", "g162_multistart", Nc201, Metric, [G162B, G162Pq]),
    program!("tests/programs", "g162_variable", Nc201, Metric, [G162I, G162J, G162Split]),
    program!("tests/programs", "g162_internal_g91", Nc201, Metric, [Nc201AbsInc, G162A, G162X, G162F, G162Retract]),
    program!("tests/programs", "g162_single_taper", Nc201, Metric, [G162X, G162W, G162Path]),
    program!("tests/programs", "g162_steps", Nc201, Metric, [G162I, G162J, G162Split]),
    program!("tests/programs", "g162_continuous", Nc201, Metric, [G162I, G162J], reading "g162.lead" = "continuous"),
    program!("tests/programs", "g32_g33_g34", Gsk, Metric, [G32, G33, G34, PrjModal]),
    program!("tests/programs", "g90_taper_signs", Gsk, Metric, [G90Taper, G90Path, G90Modal]),
    program!("tests/programs", "g90_modal_runs", Gsk, Metric, [G90Modal, G94Modal, G90Path]),
    program!("tests/programs", "g90_inch", Gsk, Inch, [ComUnits, G90Format, G90Path]),
    program!("tests/programs", "g94_taper", Gsk, Metric, [G94Taper, G94Path, G94Modal], reading "g94.k" = "start-minus-end"),
    program!("tests/programs", "g94_k_letter", Gsk, Metric, [G94Taper, G94Path, G94Modal]),
    program!("tests/programs", "g71_bore", Gsk, Metric, [G71Layer, G71Allow, G71Monotone, G71Lastpass]),
    program!("tests/programs", "g70_arcs_ik", Gsk, Metric, [ArcIk, ArcDir, G70Path, G70Feed, CntFlow]),
    program!("tests/programs", "g71_vertex_on_layer", Gsk, Metric, [G71Layer, G71Lastpass]),
    program!("tests/programs", "g71_deep_cut", Gsk, Metric, [G71Layer, G71Lastpass, G71Return]),
    program!("tests/programs", "g70_after_g71", Gsk, Metric, [G70Uw, G70Path, G70Return, CntFind, CntFlow]),
    program!("tests/programs", "g72_inch", Gsk, Inch, [ComUnits, G72Layer, G72Retract, ArcR]),
    program!("tests/programs", "g71_isc", Gsk, Metric / Isc, [ComUnits, G71Layer, ArcR, G71Allow]),
    program!("tests/programs", "g73_d1", Gsk, Metric, [G73Count, G73Depth, G73Path, ArcR]),
    program!("tests/programs", "g73_both_formats", Gsk, Metric, [G73Format, G73Uw, G73Escape, G73Count, G73Path, ArcIk]),
    program!("tests/programs", "g73_point_c", Gsk, Metric, [G73Path, G73Escape, G73Depth]),
    program!("tests/programs", "g73_skip_c", Gsk, Metric, [G73Path, G73Depth], reading "g73.c" = "skip"),
    program!("tests/programs", "g74_one_peck", Gsk, Metric, [G74Peck, G74E]),
    program!("tests/programs", "g74_last_increment", Gsk, Metric, [G74Peck, G74E]),
    program!("tests/programs", "g74_columns", Gsk, Metric, [G74Column, G74Relief, G74Peck]),
    program!("tests/programs", "g75_single_groove", Gsk, Metric, [G75Format, G75Peck]),
    program!("tests/programs", "g75_relief", Gsk, Metric, [G75Column, G75Relief, G75Peck]),
    program!("tests/programs", "g75_relief_against_step", Gsk, Metric, [G75Relief, G75Column], reading "g75.relief" = "against-step"),
    program!("tests/programs", "g83_edges", Gsk, Metric, [G83Peck, G83Format]),
    program!("tests/programs", "g84_g99", Gsk, Metric, [G84Path, G84Format, G80]),
    program!("tests/programs", "g84_g97", Gsk, Metric, [G84Format, G84Path, G50Smax, G96Speed]),
    program!("tests/programs", "g84_g50_s", Gsk, Metric, [G84Format, G50Smax], alarm MissingWord b'S' G84Format),
    program!("tests/programs", "g96_spindle", Gsk, Metric, [G96Smax, G96Speed, G96Rapid, G50Smax, G71Layer]),
    program!("tests/programs", "g96_rapid", Gsk, Metric, [G96Rapid, G96Smax], alarm Unsupported b'G' G96Rapid),
    program!("tests/programs", "sub_call", Gsk, Metric, [SubCall, SubFind, SubReturn, G92Modal]),
    program!("tests/programs", "sub_repeat", Gsk, Metric, [SubCall, SubReturn, G90Path]),
    program!("tests/programs", "sub_nested", Gsk, Metric, [SubNest, SubCall, SubReturn]),
];

/// The program named `name` (file stem).
pub fn find(name: &str) -> Option<&'static Program> {
    PROGRAMS.iter().find(|p| p.name == name)
}

/// The corpus as campaign cases: name, program bytes, configuration.
pub fn cases() -> impl Iterator<Item = (String, Vec<u8>, Config)> {
    PROGRAMS.iter().map(|p| (p.name.to_string(), p.text.as_bytes().to_vec(), p.config()))
}

#[cfg(test)]
mod tests;
