//! Where a catalogue rule stands in the traceability matrix: with a family, common to all, or
//! with none yet.

use super::{has_prefix, Family, COMMON_PREFIXES, FAMILIES};
use cycle_vocab::Rule;

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
