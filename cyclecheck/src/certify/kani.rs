//! Evidence input from Kani: a parser of `cargo kani` output (per harness: its name, its
//! verdict, its verification time; the Kani and CBMC versions of the run), and the proof
//! properties of `cycle-proofs` ([`PROPERTIES`], generated there from the harnesses: per
//! harness its name, rule IDs, what it states, and whether it is a Kani proof or a test run by
//! the drivers only).
//!
//! `certify --kani-log FILE` parses the log with [`parse_log`] and lists each entry of
//! [`PROPERTIES`] with the verdict of its harness ([`KaniLog::verdict_of`]) — a Kani proof
//! without a SUCCESSFUL verdict in the log is not evidence.

/// What Kani concluded about one harness.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// `VERIFICATION:- SUCCESSFUL`.
    Successful,
    /// `VERIFICATION:- FAILED` (any variant of it).
    Failed,
    /// The harness was started ("Checking harness …") but the log has no verdict for it: the run
    /// was stopped (time or memory limit), crashed, or the log was cut. The text is the last
    /// line of the log seen for the harness, as a hint.
    NoVerdict(String),
}

impl Verdict {
    /// `SUCCESSFUL`, `FAILED` or `no verdict`.
    pub fn label(&self) -> &'static str {
        match self {
            Verdict::Successful => "SUCCESSFUL",
            Verdict::Failed => "FAILED",
            Verdict::NoVerdict(_) => "no verdict",
        }
    }
}

/// One harness of a `cargo kani` log.
#[derive(Clone, Debug, PartialEq)]
pub struct HarnessResult {
    /// The name as Kani prints it, e.g. `g90_envelope::g90_envelope`.
    pub name: String,
    pub verdict: Verdict,
    /// `Verification Time: …s`, when the log has it.
    pub seconds: Option<f64>,
}

impl HarnessResult {
    /// The harness function's own name (the last path segment), as `--harness` takes it and as
    /// [`PROPERTIES`] lists it.
    pub fn short_name(&self) -> &str {
        self.name.rsplit("::").next().unwrap_or(&self.name)
    }
}

/// A parsed `cargo kani` log (one run, any number of harnesses, or several runs concatenated).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct KaniLog {
    /// From `Kani Rust Verifier X (…)`; the first one seen.
    pub kani_version: Option<String>,
    /// From `CBMC version X (…)` or `CBMC X (…)`; the first one seen.
    pub cbmc_version: Option<String>,
    /// In the order the log checks them; a harness checked twice appears twice.
    pub harnesses: Vec<HarnessResult>,
}

impl KaniLog {
    /// The last result for harness `name` (full name or short name).
    pub fn result_of(&self, name: &str) -> Option<&HarnessResult> {
        self.harnesses.iter().rev().find(|h| h.name == name || h.short_name() == name)
    }

    /// The verdict for harness `name`; `None` when the log does not check it at all.
    pub fn verdict_of(&self, name: &str) -> Option<&Verdict> {
        self.result_of(name).map(|h| &h.verdict)
    }
}

/// The first whitespace-separated word after `prefix` at the start of `line` (trimmed).
fn word_after<'a>(line: &'a str, prefix: &str) -> Option<&'a str> {
    line.strip_prefix(prefix)?.split_whitespace().next()
}

/// Parses `cargo kani` (or `kani`) output, regular or terse format.
pub fn parse_log(text: &str) -> KaniLog {
    let mut log = KaniLog::default();
    let mut current: Option<HarnessResult> = None;
    let mut last_line = String::new();
    let finish = |h: Option<HarnessResult>, last: &str, log: &mut KaniLog| {
        if let Some(mut h) = h {
            if h.verdict == Verdict::NoVerdict(String::new()) {
                h.verdict = Verdict::NoVerdict(last.to_string());
            }
            log.harnesses.push(h);
        }
    };
    for raw in text.lines() {
        let line = raw.trim();
        if line.is_empty() {
            continue;
        }
        if log.kani_version.is_none() {
            if let Some(v) = word_after(line, "Kani Rust Verifier ") {
                log.kani_version = Some(v.to_string());
            }
        }
        if log.cbmc_version.is_none() {
            if let Some(v) = word_after(line, "CBMC version ").or_else(|| word_after(line, "CBMC ")) {
                if v.chars().next().is_some_and(|c| c.is_ascii_digit()) {
                    log.cbmc_version = Some(v.to_string());
                }
            }
        }
        if let Some(rest) = line.strip_prefix("Checking harness ") {
            finish(current.take(), &last_line, &mut log);
            let name = rest.trim_end_matches("...").trim().to_string();
            current = Some(HarnessResult { name, verdict: Verdict::NoVerdict(String::new()), seconds: None });
        } else if let Some(rest) = line.strip_prefix("VERIFICATION:-") {
            if let Some(h) = current.as_mut() {
                let rest = rest.trim();
                h.verdict = if rest.starts_with("SUCCESSFUL") {
                    Verdict::Successful
                } else if rest.starts_with("FAILED") {
                    Verdict::Failed
                } else {
                    Verdict::NoVerdict(line.to_string())
                };
            }
        } else if let Some(rest) = line.strip_prefix("Verification Time:") {
            if let Some(h) = current.as_mut() {
                h.seconds = rest.trim().trim_end_matches('s').parse().ok();
            }
        }
        last_line = line.to_string();
    }
    finish(current.take(), &last_line, &mut log);
    log
}

/// The proof properties of `cycle-proofs`, as its harnesses state them (`property!`: name, rules,
/// statement, Kani proof or TEST, measured Kani result); proofs/README.md has the bounds, stubs
/// and measurements in full and is checked against this list by `cycle-proofs`' tests.
pub use cycle_proofs::{CheckedBy, Property, PROPERTIES};

/// The entry of [`PROPERTIES`] for harness `name`.
pub fn property(name: &str) -> Option<&'static Property> {
    PROPERTIES.iter().find(|p| p.harness == name)
}

#[cfg(test)]
mod tests;
