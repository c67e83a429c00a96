//! A run's verdict in words — at which comparison level, with how many declared deviations —
//! and the declared deviations applied to a judged case.

use super::deviations::{self, Deviation};
use super::{CaseRecord, CaseResult, Run};
use crate::candidate::{CandidateEngine, Limits};
use cycle_kernel::conformance::Level;

/// `record` with its first divergence turned into a declared deviation when it matches one of
/// `list` ([`Deviation::matches`]); unchanged otherwise.
pub(super) fn deviate(list: &[Deviation], mut record: CaseRecord) -> CaseRecord {
    if let CaseResult::Diverge(d) = &record.result {
        if let Some(k) = deviations::find(list, d, record.cycle, record.config.dialect) {
            record.result = CaseResult::Deviate { divergence: d.clone(), declaration: k };
        }
    }
    record
}

/// Greets `command`'s candidate once, before a run: the level it declares, or why it could not
/// be greeted. `certify --level` refuses a run whose candidate declares less than it asks.
pub fn declared_level(command: &str, limits: Limits) -> Result<Level, String> {
    let engine = CandidateEngine::new(command, limits)?;
    engine.greet().map(|s| s.level).map_err(|f| f.to_string())
}

/// `the candidate declares comparison level motion, --level full asked`.
pub fn level_refusal(declared: Level, required: Level) -> String {
    format!(
        "the candidate declares comparison level {declared} in its greeting, --level {required} asked: {declared} compares {}",
        declared.describe()
    )
}

impl Run {
    /// Whether the candidate's level is at least the one `--level` asked for.
    pub fn level_ok(&self) -> bool {
        self.options.level.is_none_or(|required| self.level >= required)
    }

    /// Cases that deviate as declared.
    pub fn deviating(&self) -> usize {
        self.tally.deviate
    }

    /// The declarations (by index) no case matched.
    pub fn unused_deviations(&self) -> Vec<usize> {
        (0..self.options.deviations.len()).filter(|k| !self.tally.by_declaration.contains_key(k)).collect()
    }

    /// The verdict in words: `PASS` only for a full comparison without deviations; else
    /// `PASS at comparison level motion`, `PASS with 3 declared deviations`, `FAIL at comparison
    /// level motion`, and why the level fails when it does.
    pub fn verdict(&self) -> String {
        let mut v = if self.passed() { "PASS" } else { "FAIL" }.to_string();
        if self.level != Level::Full {
            v.push_str(&format!(" at comparison level {}", self.level));
        }
        if self.passed() && self.deviating() > 0 {
            let n = self.deviating();
            v.push_str(&format!(" with {n} declared deviation{}", if n == 1 { "" } else { "s" }));
        }
        if let (false, Some(required)) = (self.level_ok(), self.options.level) {
            v.push_str(&format!(" ({})", level_refusal(self.level, required)));
        }
        v
    }

    /// The summary's lines on the level and the declarations: what the level compares, each
    /// declaration with its count, the unused ones named.
    pub(super) fn level_and_deviation_lines(&self) -> String {
        let mut s = String::new();
        if self.level != Level::Full {
            s.push_str(&format!("comparison level {}: {}\n", self.level, self.level.describe()));
        }
        for (k, d) in self.options.deviations.iter().enumerate() {
            let n = self.tally.by_declaration.get(&k).copied().unwrap_or(0);
            let used = if n == 0 { "UNUSED: no case deviates so".to_string() } else { format!("{n} case(s) deviate as declared") };
            s.push_str(&format!("declared deviation {} {}: {used} — {}\n", k + 1, d.label(), d.reason));
        }
        s
    }
}

/// The page's paragraph on the comparison level and its table of declared deviations (each
/// with its count, the unused ones marked).
pub(super) fn html(run: &Run, out: &mut String) {
    use super::markdown::escape;
    use std::fmt::Write as _;
    let _ = writeln!(
        out,
        "<p><b>Comparison level: {}</b> — {}.{}</p>",
        run.level,
        escape(run.level.describe()),
        if run.level == Level::Full { "" } else { " A divergence's event index counts the moves only. This is not a full comparison." }
    );
    if run.options.deviations.is_empty() {
        return;
    }
    out.push_str("<p>Declared deviations (<code>--deviations</code>): a case whose <em>first</em> divergence matches one is reported as deviating as declared — never as conforming — and the rest of that case was not compared.</p>\n");
    out.push_str("<table><tr><th>#</th><th>declaration</th><th>reason</th><th>cases that deviate so</th></tr>\n");
    for (k, d) in run.options.deviations.iter().enumerate() {
        let n = run.tally.by_declaration.get(&k).copied().unwrap_or(0);
        let count = if n == 0 { r#"<span class="r-fail">0 — unused</span>"#.to_string() } else { n.to_string() };
        let _ = writeln!(out, "<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{count}</td></tr>", k + 1, escape(&d.label()), escape(&d.reason));
    }
    out.push_str("</table>\n");
    let unused = run.unused_deviations();
    if !unused.is_empty() {
        let list: Vec<String> = unused.iter().map(|k| (k + 1).to_string()).collect();
        let _ = writeln!(out, "<p class=\"r-fail\">Unused declarations (no case deviates so): {}.</p>", list.join(", "));
    }
}
