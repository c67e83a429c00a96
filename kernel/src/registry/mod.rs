//! The cycle families, in one table ([`FAMILIES`]). A family is a cycle as a run exercises it —
//! G92, G76 under gsk, G78, G76 under fanuc, G162 under nc201, the thread moves G32/G33/G34, the
//! single cutting cycles G90 and G94, the stock-removal cycles G71 and G72 and the finishing
//! cycle G70, the pattern repeating cycle G73, the peck cycles G74 and G75, peck drilling G83
//! and rigid tapping G84 —
//! and its row drives every consumer: the `--cycles` option and its help text, certify's
//! generated runs, which cycle a case runs ([`sight`], read once per judged case: the per-cycle
//! counts of `corpus`, `diff`, the gate and certify), the snapshot folders, the bench cases, the fuzz input's
//! generators, the matrix's rule groups ([`rule_group`]) and the differential tests. A
//! completeness test (`tests/tests/families.rs`) fails when a family is missing from one of them.
//!
//! Adding a family is: its spec module and a row in the spec's table (`cycle_spec::family`), its
//! impl module and a row in impl's table (`cycle_impl::family`), a row here, its generator module
//! in `gen/` (builder and bench case), its programs and snapshots, its rules in docs/RULES.md and
//! its name in the named test lists of `tests/tests/differential.rs` and `zero_alloc.rs`. The
//! families test fails until the three code tables agree and every consumer has it; the named
//! lists fail naming the family they lack.

use crate::gen::{self, Builder, Case};
use cycle_spec::lex::Number;
use cycle_vocab::{Dialect, Rule};
use num_traits::ToPrimitive;
use proptest::strategy::BoxedStrategy;
use std::cmp::Ordering;
use std::collections::BTreeMap;

mod group;
mod sight;
pub use group::{rule_group, RuleGroup};
pub use sight::{cycle_run, sight, Sighting};
#[cfg(any(test, feature = "test-aids"))]
pub use sight::sightings;

/// One family.
#[derive(Debug)]
pub struct Family {
    /// `g92`: its `--cycles` name, the prefix of its fuzz seeds' names and its snapshot folder
    /// (`tests/tests/snapshots/g92/`).
    pub name: &'static str,
    /// `G92`: how reports name it.
    pub display: &'static str,
    /// The dialects it runs under.
    pub dialects: &'static [Dialect],
    /// The G codes that select it under those dialects.
    pub codes: &'static [u64],
    /// Its generator's knob builder.
    pub build: Builder,
    /// Its catalogue rules: the IDs equal to one of these or starting with one and a dot.
    pub rule_prefixes: &'static [&'static str],
    /// Its bench case: a program of about `n` passes (or thread blocks), without an alarm
    /// (`tests/benches/expand/` runs it at each of [`BENCH_SIZES`]).
    pub bench: fn(usize) -> Case,
}

use Dialect::{Fanuc, Gsk, Nc201};

/// Every family, in report order. NC201.* rules go with g162, the only family under `nc201`.
pub const FAMILIES: &[Family] = &[
    Family {
        name: "g92",
        display: "G92",
        dialects: &[Gsk, Fanuc],
        codes: &[92],
        build: gen::g92::build,
        rule_prefixes: &["G92"],
        bench: gen::g92::bench,
    },
    Family {
        name: "g76",
        display: "G76",
        dialects: &[Gsk],
        codes: &[76],
        build: gen::multipass::g76,
        rule_prefixes: &["G76"],
        bench: gen::multipass::g76_bench,
    },
    Family {
        name: "g78",
        display: "G78",
        dialects: &[Gsk],
        codes: &[78],
        build: gen::multipass::g78,
        rule_prefixes: &["G78"],
        bench: gen::multipass::g78_bench,
    },
    Family {
        name: "f76",
        display: "G76 fanuc",
        dialects: &[Fanuc],
        codes: &[76],
        build: gen::multipass::f76,
        rule_prefixes: &["F76"],
        bench: gen::multipass::f76_bench,
    },
    Family {
        name: "g162",
        display: "G162",
        dialects: &[Nc201],
        codes: &[162],
        build: gen::g162::build,
        rule_prefixes: &["G162", "NC201"],
        bench: gen::g162::bench,
    },
    Family {
        name: "g32",
        display: "G32/G33/G34",
        dialects: &[Gsk, Fanuc],
        codes: &[32, 33, 34],
        build: gen::thread_moves::build,
        rule_prefixes: &["G32", "G33", "G34"],
        bench: gen::thread_moves::bench,
    },
    Family {
        name: "g90",
        display: "G90",
        dialects: &[Gsk, Fanuc],
        codes: &[90],
        build: gen::single_cut::g90,
        rule_prefixes: &["G90"],
        bench: gen::single_cut::g90_bench,
    },
    Family {
        name: "g94",
        display: "G94",
        dialects: &[Gsk, Fanuc],
        codes: &[94],
        build: gen::single_cut::g94,
        rule_prefixes: &["G94"],
        bench: gen::single_cut::g94_bench,
    },
    // The contour (CNT.*) is read and checked alike by G71, G72 and G70; the matrix lists a rule
    // once, so its rules stand with g71, the first of the three. Arcs (ARC.*), G50 and the
    // nose-radius codes (TNRC.*) are program words any program may carry whatever cycle it runs
    // (an arc or a G50 is no cycle): they are common ([`COMMON_PREFIXES`]).
    Family {
        name: "g71",
        display: "G71",
        dialects: &[Gsk, Fanuc],
        codes: &[71],
        build: gen::contour::g71,
        rule_prefixes: &["G71", "CNT"],
        bench: gen::contour::g71_bench,
    },
    Family {
        name: "g72",
        display: "G72",
        dialects: &[Gsk, Fanuc],
        codes: &[72],
        build: gen::contour::g72,
        rule_prefixes: &["G72"],
        bench: gen::contour::g72_bench,
    },
    // G70 as the first cycle: a G70 finishing a contour written before it, without a roughing
    // cycle (a G70 after G71 or G72 runs in that cycle's family).
    Family {
        name: "g70",
        display: "G70",
        dialects: &[Gsk, Fanuc],
        codes: &[70],
        build: gen::contour::g70,
        rule_prefixes: &["G70"],
        bench: gen::contour::g70_bench,
    },
    Family {
        name: "g73",
        display: "G73",
        dialects: &[Gsk, Fanuc],
        codes: &[73],
        build: gen::contour::g73,
        rule_prefixes: &["G73"],
        bench: gen::contour::g73_bench,
    },
    Family {
        name: "g74",
        display: "G74",
        dialects: &[Gsk, Fanuc],
        codes: &[74],
        build: gen::peck::g74,
        rule_prefixes: &["G74"],
        bench: gen::peck::g74_bench,
    },
    Family {
        name: "g75",
        display: "G75",
        dialects: &[Gsk, Fanuc],
        codes: &[75],
        build: gen::peck::g75,
        rule_prefixes: &["G75"],
        bench: gen::peck::g75_bench,
    },
    Family {
        name: "g83",
        display: "G83",
        dialects: &[Gsk, Fanuc],
        codes: &[83],
        build: gen::drill::g83,
        rule_prefixes: &["G83"],
        bench: gen::drill::g83_bench,
    },
    // G80 cancels what G84's M29 armed: its rule stands with g84.
    Family {
        name: "g84",
        display: "G84",
        dialects: &[Gsk, Fanuc],
        codes: &[84],
        build: gen::drill::g84,
        rule_prefixes: &["G84", "G80"],
        bench: gen::drill::g84_bench,
    },
];

/// The sizes the bench runs each family's bench case at.
pub const BENCH_SIZES: [usize; 3] = [1, 100, 9_900];

/// The catalogue prefixes of the rules every family follows: the common rules, the project's,
/// and the program words of M003 any program may write whatever cycle it runs — arcs G02/G03
/// (ARC.*), G50 (G50.*) and the nose-radius codes G40/G41/G42 (TNRC.*).
pub const COMMON_PREFIXES: &[&str] = &["COM", "PRJ", "ARC", "G50", "TNRC"];

/// Cases per cycle run on one line: `G92 7, G76 8, …, alarm before a cycle 2`.
pub fn counts_line(counts: &BTreeMap<CycleRun, usize>) -> String {
    counts.iter().map(|(c, n)| format!("{} {n}", c.label())).collect::<Vec<_>>().join(", ")
}

/// The family named `name`.
pub fn find(name: &str) -> Option<&'static Family> {
    FAMILIES.iter().find(|f| f.name == name)
}

/// The families' names, comma-separated: `g92, g76, …` (help texts).
pub fn names() -> String {
    FAMILIES.iter().map(|f| f.name).collect::<Vec<_>>().join(", ")
}

impl Family {
    /// Its position in [`FAMILIES`].
    pub fn index(&self) -> usize {
        FAMILIES.iter().position(|f| f.name == self.name).unwrap_or(FAMILIES.len())
    }

    /// Its generator's cases.
    pub fn strategy(&self) -> BoxedStrategy<Case> {
        gen::strategy(self.build)
    }

    /// Whether G word `g` selects it under `dialect`.
    pub fn selected_by(&self, g: &Number, dialect: Dialect) -> bool {
        let code = g.mantissa().to_u64();
        !g.point && !g.negative && code.is_some_and(|c| self.codes.contains(&c)) && self.dialects.contains(&dialect)
    }

    /// Whether `rule` is one of its rules.
    pub fn owns(&self, rule: Rule) -> bool {
        has_prefix(rule, self.rule_prefixes)
    }
}

impl PartialEq for Family {
    fn eq(&self, other: &Family) -> bool {
        self.name == other.name
    }
}

impl Eq for Family {}

impl PartialOrd for Family {
    fn partial_cmp(&self, other: &Family) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

/// Families order as the table lists them.
impl Ord for Family {
    fn cmp(&self, other: &Family) -> Ordering {
        self.index().cmp(&other.index())
    }
}

pub(crate) fn has_prefix(rule: Rule, prefixes: &[&str]) -> bool {
    let id = rule.id();
    prefixes.iter().any(|p| id.strip_prefix(p).is_some_and(|rest| rest.is_empty() || rest.starts_with('.')))
}

/// Which cycle a case runs ([`sight`]): a family, or one of two named rows. Ordered as
/// reports list them: the families in table order, then the two rows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum CycleRun {
    Family(&'static Family),
    /// No block selects a family and the reference ends without an alarm.
    NoCycle,
    /// The reference alarms before any block that selects a family.
    AlarmFirst,
}

impl CycleRun {
    /// How reports name it: `G92`, `no cycle`, `alarm before a cycle`.
    pub fn label(self) -> &'static str {
        match self {
            CycleRun::Family(f) => f.display,
            CycleRun::NoCycle => "no cycle",
            CycleRun::AlarmFirst => "alarm before a cycle",
        }
    }

    /// A name for files and keys: the family's name, `no_cycle`, `alarm_before_cycle`.
    pub fn name(self) -> &'static str {
        match self {
            CycleRun::Family(f) => f.name,
            CycleRun::NoCycle => "no_cycle",
            CycleRun::AlarmFirst => "alarm_before_cycle",
        }
    }

    /// What the row counts, for a reader of the report.
    pub fn describe(self) -> String {
        match self {
            CycleRun::Family(f) => {
                let codes: Vec<String> = f.codes.iter().map(|c| format!("G{c}")).collect();
                let dialects: Vec<String> = f.dialects.iter().map(|d| format!("{d:?}").to_lowercase()).collect();
                format!("the first cycle block is {} under {}", codes.join(", "), dialects.join(" or "))
            }
            CycleRun::NoCycle => {
                "no block selects a family and the reference ends without an alarm: rapids and feeds only, or nothing"
                    .to_string()
            }
            CycleRun::AlarmFirst => concat!(
                "the reference alarms before any cycle block runs: a configuration it refuses, garbage, a lexing ",
                "error (in the cycle's own block too), a block before the cycle it refuses, a cycle code of another dialect"
            )
            .to_string(),
        }
    }
}

#[cfg(test)]
mod tests;
