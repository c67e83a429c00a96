//! The cycle families, in one table ([`FAMILIES`]). A family is a cycle as a run exercises it —
//! G92, G76 under gsk, G78, G76 under fanuc, G162 under nc201, the thread moves G32/G33/G34, the
//! single cutting cycles G90 and G94, the stock-removal cycles G71 and G72 and the finishing
//! cycle G70, the pattern repeating cycle G73, the peck cycles G74 and G75, peck drilling G83
//! and rigid tapping G84 —
//! and its row drives every consumer: the `--cycles` option and its help text, certify's
//! generated runs, which cycle a case runs ([`cycle_run`]: the per-cycle counts of `corpus`,
//! `diff`, the gate and certify), the snapshot folders, the bench cases, the fuzz input's
//! generators, the matrix's rule groups ([`rule_group`]) and the differential tests. A
//! completeness test (`tests/tests/families.rs`) fails when a family is missing from one of them.
//!
//! Adding a family is a row here and its generator module in `gen/` (builder and bench case).

use crate::gen::{self, Builder, Case};
use cycle_vocab::text::Trace;
use cycle_spec::lex::{self, Number};
use cycle_vocab::{Alarm, Config, Dialect, Rule};
use num_traits::ToPrimitive;
use proptest::strategy::BoxedStrategy;
use std::cmp::Ordering;
use std::collections::BTreeMap;

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
    /// (`tests/benches/expand.rs` runs it at each of [`BENCH_SIZES`]).
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

fn has_prefix(rule: Rule, prefixes: &[&str]) -> bool {
    let id = rule.id();
    prefixes.iter().any(|p| id.strip_prefix(p).is_some_and(|rest| rest.is_empty() || rest.starts_with('.')))
}

/// Which cycle a case runs ([`cycle_run`]): a family, or one of two named rows. Ordered as
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

/// Which cycle a case runs: the family of the first block — up to the line of the reference
/// trace's alarm (inclusive: a block that alarms runs its cycle) or the program's end (M02, M30,
/// a lexing error) — whose G codes select a family under the configuration's dialect;
/// [`CycleRun::AlarmFirst`] when the reference alarms before such a block,
/// [`CycleRun::NoCycle`] when it ends without one. Without a reference trace (the reference
/// failed) the program's end bounds the search.
///
/// The blocks are read with the reference's lexer (`cycle_spec::lex`); this is the one place
/// that reads them for it.
pub fn cycle_run(program: &[u8], config: &Config, reference: Option<&Trace>) -> CycleRun {
    cycle_run_until(program, config, reference.and_then(|t| t.alarm.as_ref()))
}

/// [`cycle_run`] knowing only the reference's alarm (`None`: it ended cleanly or failed).
pub fn cycle_run_until(program: &[u8], config: &Config, alarm: Option<&Alarm>) -> CycleRun {
    let alarm_line = alarm.map(|a| a.line);
    for block in lex::blocks(program) {
        let Ok(block) = block else { break };
        if alarm_line.is_some_and(|line| block.line > line) {
            break;
        }
        let family = block.g_codes().find_map(|g| FAMILIES.iter().find(|f| f.selected_by(g, config.dialect)));
        if let Some(f) = family {
            return CycleRun::Family(f);
        }
        let m = block.get(b'M');
        if m.is_some_and(|m| !m.point && !m.negative && matches!(m.mantissa().to_u64(), Some(2 | 30))) {
            break;
        }
    }
    if alarm_line.is_some() {
        CycleRun::AlarmFirst
    } else {
        CycleRun::NoCycle
    }
}

/// Where a catalogue rule stands in the traceability matrix. Ordered as the matrix lists them.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum RuleGroup {
    /// A family's own rules ([`Family::rule_prefixes`]).
    Family(&'static Family),
    /// Rules every family follows ([`COMMON_PREFIXES`]).
    Common,
    /// Rules of no family in the table: cycles still to come or not supported.
    Other,
}

impl RuleGroup {
    /// A name for keys: the family's name, `common`, `other`.
    pub fn name(self) -> &'static str {
        match self {
            RuleGroup::Family(f) => f.name,
            RuleGroup::Common => "common",
            RuleGroup::Other => "other",
        }
    }

    /// The group's heading.
    pub fn label(self) -> String {
        match self {
            RuleGroup::Family(f) => format!("{} ({})", f.display, f.name),
            RuleGroup::Common => format!("common to every family ({})", COMMON_PREFIXES.join(", ")),
            RuleGroup::Other => "no family yet (later or unsupported cycles)".to_string(),
        }
    }
}

/// The group of `rule`.
pub fn rule_group(rule: Rule) -> RuleGroup {
    match FAMILIES.iter().find(|f| f.owns(rule)) {
        Some(f) => RuleGroup::Family(f),
        None if has_prefix(rule, COMMON_PREFIXES) => RuleGroup::Common,
        None => RuleGroup::Other,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The cycle run's name, with a reference trace that alarms on `alarm_line`.
    fn run(program: &[u8], dialect: Dialect, alarm_line: Option<u32>) -> &'static str {
        let alarm = alarm_line.map(|line| cycle_vocab::Alarm::new(cycle_vocab::AlarmCode::Geometry, None, Rule::PrjWord, line));
        let reference = Trace { grid: cycle_vocab::Grid::METRIC_ISB, events: Vec::new(), alarm };
        cycle_run(program, &Config { dialect, ..Config::default() }, Some(&reference)).name()
    }

    #[test]
    fn the_first_selecting_block_names_the_family() {
        assert_eq!(run(b"G0 X1\nG92 X1 Z-1 F1", Gsk, None), "g92");
        assert_eq!(run(b"G76 P1", Fanuc, None), "f76");
        assert_eq!(run(b"G76 P1", Gsk, None), "g76");
        assert_eq!(run(b"G0 X1\ng033 Z-1 F1\nG92 X1", Gsk, None), "g32");
        assert_eq!(run(b"G162 G91 X1", Nc201, None), "g162");
        // A contour written before G70 (arcs, G50: no family) runs G70; G71 before G70 runs G71.
        assert_eq!(run(b"G50 X10 Z0\nN1 G0 X5 F1\nN2 G2 X9 Z-2 R2\nG70 P1 Q2", Gsk, None), "g70");
        assert_eq!(run(b"G71 P1 Q2 F1\nN1 G0 X5\nN2 G1 Z-2\nG70 P1 Q2", Fanuc, None), "g71");
        assert_eq!(run(b"G72 W1", Nc201, Some(1)), "alarm_before_cycle");
        // G92.1 and G-92 select nothing; G78 selects nothing under fanuc.
        assert_eq!(run(b"G92.1\nG-92\nG0 X1", Gsk, None), "no_cycle");
        assert_eq!(run(b"G78 P1", Fanuc, Some(1)), "alarm_before_cycle");
    }

    #[test]
    fn the_alarm_and_the_end_bound_the_search() {
        assert_eq!(run(b"G0 X1 Q5\nG92 X1 Z-1 F1", Gsk, Some(1)), "alarm_before_cycle");
        assert_eq!(run(b"G0 X1\nG92 X1 Z-1\n", Gsk, Some(2)), "g92");
        assert_eq!(run(b"G0 X1 #G92", Gsk, Some(1)), "alarm_before_cycle");
        assert_eq!(run(b"G0 X1\nM30\nG92 X1 Z-1 F1", Gsk, None), "no_cycle");
        assert_eq!(run(b"", Gsk, None), "no_cycle");
    }

    #[test]
    fn rules_group_by_family() {
        assert_eq!(rule_group(Rule::G92Jk3), RuleGroup::Family(find("g92").unwrap()));
        assert_eq!(rule_group(Rule::G76DepthMin), RuleGroup::Family(find("g76").unwrap()));
        assert_eq!(rule_group(Rule::F76Microns), RuleGroup::Family(find("f76").unwrap()));
        assert_eq!(rule_group(Rule::Nc201XMode), RuleGroup::Family(find("g162").unwrap()));
        assert_eq!(rule_group(Rule::G33), RuleGroup::Family(find("g32").unwrap()));
        assert_eq!(rule_group(Rule::ComLead), RuleGroup::Common);
        assert_eq!(rule_group(Rule::G163), RuleGroup::Other);
        // The contour's rules stand with g71; arcs, G50 and the nose-radius codes are common.
        assert_eq!(rule_group(Rule::CntFind), RuleGroup::Family(find("g71").unwrap()));
        assert_eq!(rule_group(Rule::G72Layer), RuleGroup::Family(find("g72").unwrap()));
        assert_eq!(rule_group(Rule::G70Uw), RuleGroup::Family(find("g70").unwrap()));
        for rule in [Rule::ArcTol, Rule::G50Coord, Rule::TnrcSwitch] {
            assert_eq!(rule_group(rule), RuleGroup::Common, "{rule}");
        }
    }

    #[test]
    fn rows_are_distinct_and_ordered() {
        for (i, f) in FAMILIES.iter().enumerate() {
            assert_eq!(f.index(), i);
            assert_eq!(find(f.name), Some(f));
            assert!(FAMILIES[..i].iter().all(|g| g.name != f.name && g.display != f.display), "{} twice", f.name);
        }
        assert!(CycleRun::Family(&FAMILIES[0]) < CycleRun::Family(&FAMILIES[1]));
        assert!(CycleRun::Family(&FAMILIES[5]) < CycleRun::NoCycle && CycleRun::NoCycle < CycleRun::AlarmFirst);
    }
}
