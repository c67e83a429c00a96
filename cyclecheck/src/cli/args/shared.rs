//! The flags several subcommands share: the engine and the output format, the configuration
//! of a case ([`ConfigArgs`], with `--reading`), and a candidate with its limits
//! ([`CandidateArgs`]).

use clap::{Args, ValueEnum};
use cyclecheck::candidate::Limits;
use cycle_vocab::{Config, Dialect, Increment, Units};

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum EngineArg {
    Spec,
    Impl,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum FormatArg {
    Gcode,
    Json,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CorpusFormat {
    Text,
    Json,
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum DialectArg {
    Gsk,
    Fanuc,
    Nc201,
}

impl From<Dialect> for DialectArg {
    fn from(d: Dialect) -> DialectArg {
        match d {
            Dialect::Gsk => DialectArg::Gsk,
            Dialect::Fanuc => DialectArg::Fanuc,
            Dialect::Nc201 => DialectArg::Nc201,
        }
    }
}

impl From<DialectArg> for Dialect {
    fn from(d: DialectArg) -> Dialect {
        match d {
            DialectArg::Gsk => Dialect::Gsk,
            DialectArg::Fanuc => Dialect::Fanuc,
            DialectArg::Nc201 => Dialect::Nc201,
        }
    }
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnitsArg {
    Metric,
    Inch,
}

impl From<Units> for UnitsArg {
    fn from(u: Units) -> UnitsArg {
        match u {
            Units::Metric => UnitsArg::Metric,
            Units::Inch => UnitsArg::Inch,
        }
    }
}

#[derive(ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum IncrementArg {
    Isb,
    Isc,
}

impl From<Increment> for IncrementArg {
    fn from(i: Increment) -> IncrementArg {
        match i {
            Increment::Isb => IncrementArg::Isb,
            Increment::Isc => IncrementArg::Isc,
        }
    }
}

/// The configuration of `expand` and `diff`.
#[derive(Args, Debug)]
pub struct ConfigArgs {
    /// Input conventions (nc201: the Russian controller of G162, G90/G91, X radius or diameter).
    #[arg(long, value_enum, default_value_t = DialectArg::from(Config::default().dialect))]
    pub dialect: DialectArg,
    /// Units of the program and the trace (a G20/G21 must agree).
    #[arg(long, value_enum, default_value_t = UnitsArg::from(Config::default().grid.units))]
    pub units: UnitsArg,
    /// The least increment.
    #[arg(long, value_enum, default_value_t = IncrementArg::from(Config::default().grid.increment))]
    pub increment: IncrementArg,
    /// A machine parameter, N=V (repeatable): 19, 107, 18, 5130, 5131, 5140…5145, max_passes, x_radius.
    #[arg(long = "param", value_name = "N=V")]
    pub params: Vec<String>,
    /// Machine X (diameter) at program start, mm or inch.
    #[arg(long, value_name = "X", default_value = "0", allow_hyphen_values = true)]
    pub start_x: String,
    /// Machine Z at program start, mm or inch.
    #[arg(long, value_name = "Z", default_value = "0", allow_hyphen_values = true)]
    pub start_z: String,
    /// An operator action, in the order they happen (repeatable, at most 16; OP.SCRIPT):
    /// hold:E@F (feed hold at the fraction F — NUM/DEN or a decimal 0…1 — of move E of the
    /// uninterrupted trace, E its 0-based event index as `--format json` lists them), reset:E@F,
    /// start (cycle start at the next feed-hold stop), single:on@B / single:off@B (single block
    /// before event B). Parameter 18 (No.0018 bit 6) picks the G92 feed-hold behaviour.
    #[arg(long = "op", value_name = "ACTION")]
    pub ops: Vec<String>,
    #[arg(long = "reading", value_name = "NAME=VALUE", value_parser = reading, help = readings_help())]
    pub readings: Vec<String>,
}

/// One `--reading`, checked: an unknown name or value is refused, naming it and the legal ones.
pub(super) fn reading(text: &str) -> Result<String, String> {
    cycle_kernel::readings::Pins::parse(&[text]).map(|_| text.to_string())
}

/// The readings and their values, for `--help`.
fn reading_list() -> String {
    let list: Vec<String> =
        cycle_vocab::Readings::NAMES.iter().map(|n| format!("{n} = {}", cycle_vocab::Readings::values(n).unwrap_or(&[]).join(" | "))).collect();
    list.join("; ")
}

pub(super) fn readings_help() -> String {
    format!(
        "A declared reading, NAME=VALUE (repeatable; docs/INTERPRETATION.md, \"Declared readings\"): {}. The default is the manuals' letter, the first value",
        reading_list()
    )
}

pub(super) fn certify_readings_help() -> String {
    format!(
        "A declared reading, NAME=VALUE (repeatable): {}. The default is the manuals' letter, the first value. With --candidate: merged with the readings the candidate declares in its greeting, which it is certified against (a contradiction stops the run, exit 2); without: fixed in every case, the others drawn per case",
        reading_list()
    )
}

/// A candidate and its limits (docs/CANDIDATE.md).
#[derive(Args, Debug)]
pub struct CandidateArgs {
    /// An external expander speaking cyclecheck-candidate/1 to /4 (the versions it answers the greeting with; /2 for arcs and G70–G72, /3 for G73–G75, G83, G84, /4 for operator scripts), instead of the production expander; split like a shell command line (quotes, backslashes) and run without a shell.
    #[arg(long, value_name = "CMD")]
    pub candidate: Option<String>,
    /// Time allowed per case.
    #[arg(long, value_name = "MS", default_value_t = Limits::DEFAULT_TIMEOUT_MS, value_parser = clap::value_parser!(u64).range(1..))]
    pub timeout_ms: u64,
    /// The longest answer line per case.
    #[arg(long, value_name = "BYTES", default_value_t = Limits::DEFAULT_MAX_OUTPUT as u64, value_parser = clap::value_parser!(u64).range(1..))]
    pub max_output: u64,
}

impl CandidateArgs {
    pub fn limits(&self) -> Limits {
        Limits {
            timeout: std::time::Duration::from_millis(self.timeout_ms),
            max_output: usize::try_from(self.max_output).unwrap_or(usize::MAX),
        }
    }
}
