//! `third-party --check`: the deterministic content of the report — per candidate, each
//! campaign's heading and comparison level, its table rows per family (the counts), its verdict,
//! and its divergence groups by rule and count — compared between the committed file and this
//! run, for the candidates that ran here. Timings, minimized programs and messages are not
//! compared. A divergence group without a note fails the check too.

use super::report::{section, NO_NOTE};
use super::{CandidateReport, Outcome};
use std::collections::BTreeSet;

/// The deterministic lines of a candidate's section.
pub fn digest(section: &str) -> BTreeSet<String> {
    let mut lines = BTreeSet::new();
    let mut campaign = String::new();
    let mut in_counts = false;
    for line in section.lines() {
        if line.starts_with("### ") {
            campaign = line.trim_start_matches("### ").to_string();
        }
        if line.starts_with("| family |") {
            in_counts = true;
            continue;
        }
        if line.trim().is_empty() {
            in_counts = false;
        }
        let keep = line.starts_with("### Campaign")
            || line.starts_with("Comparison level:")
            || line.starts_with("**Verdict:")
            || line.starts_with("#### Divergence group")
            || (in_counts && line.starts_with("| ") && !line.starts_with("|---"));
        if keep {
            lines.insert(if line.starts_with("### Campaign") { line.to_string() } else { format!("{campaign} :: {line}") });
        }
    }
    lines
}

/// `Ok` when, for every candidate that ran, the committed section's digest equals this run's
/// and no divergence group lacks a note; else a diff-like message (`-` committed, `+` now).
pub fn compare(committed: &str, regenerated: &str, reports: &[CandidateReport]) -> Result<(), String> {
    let mut message = String::new();
    for r in reports.iter().filter(|r| matches!(r.outcome, Outcome::Ran(_))) {
        let name = &r.manifest.name;
        let now = section(regenerated, name).map(digest).unwrap_or_default();
        let Some(before) = section(committed, name) else {
            message.push_str(&format!("{name}: no section in the committed file\n"));
            continue;
        };
        let before = digest(before);
        if before != now {
            message.push_str(&format!("{name}:\n"));
            for l in before.difference(&now) {
                message.push_str(&format!("- {l}\n"));
            }
            for l in now.difference(&before) {
                message.push_str(&format!("+ {l}\n"));
            }
        }
        if section(regenerated, name).is_some_and(|s| s.contains(NO_NOTE)) {
            message.push_str(&format!("{name}: a divergence group has no note: add one sentence per rule under [notes] in {}\n", r.manifest.path.display()));
        }
    }
    if message.is_empty() {
        Ok(())
    } else {
        Err(message)
    }
}

#[cfg(test)]
mod tests;
