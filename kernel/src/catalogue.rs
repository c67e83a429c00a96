//! The rule catalogue (`docs/RULES.md`) as data: each rule's source manual, text and status, so
//! that a divergence report can quote the rule it concerns.
//!
//! The catalogue is read from the document itself (compiled in), so the text quoted is always
//! the text reviewed; `cycle_vocab::Rule` keeps the list of IDs in step with it.

use cycle_vocab::Rule;

const RULES_MD: &str = include_str!("../../docs/RULES.md");

/// One row of the catalogue.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Entry {
    pub rule: Rule,
    /// The source key (`M001`, `PRJ`, …).
    pub source: &'static str,
    /// The rule as the catalogue states it.
    pub text: &'static str,
    /// `impl`, `unsupported`, `later`, … as the catalogue says.
    pub status: &'static str,
}

/// The catalogue entry of `rule`, if the document has a row for it.
pub fn entry(rule: Rule) -> Option<Entry> {
    RULES_MD.lines().find_map(|line| {
        let cells = row(line)?;
        (cells.len() == 4 && cells[0] == rule.id()).then(|| Entry {
            rule,
            source: cells[1],
            text: cells[2],
            status: cells[3],
        })
    })
}

/// The cells of a Markdown table row (`| a | b |`), trimmed. Escaped pipes (`\|`) stay inside
/// their cell.
fn row(line: &str) -> Option<Vec<&str>> {
    let inner = line.trim().strip_prefix('|')?.strip_suffix('|')?;
    let mut cells = Vec::new();
    let mut start = 0;
    let bytes = inner.as_bytes();
    for (i, &b) in bytes.iter().enumerate() {
        if b == b'|' && (i == 0 || bytes[i - 1] != b'\\') {
            cells.push(inner[start..i].trim());
            start = i + 1;
        }
    }
    cells.push(inner[start..].trim());
    Some(cells)
}

#[cfg(test)]
mod tests;
