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
mod tests {
    use super::*;

    const TWO: &str = "\
Kani Rust Verifier 0.61.0 (cargo plugin)
   Compiling cycle-proofs v0.1.0 (/w/proofs)
    Finished `dev` profile [unoptimized + debuginfo] target(s) in 6.56s
Checking harness g90_envelope::g90_envelope...
CBMC 6.4.0 (27a27caba2-dirty)
CBMC version 6.4.0 (27a27caba2-dirty) 64-bit x86_64 linux
Reading GOTO program from file /w/target/kani/x.out
481657 variables, 1180863 clauses
SUMMARY:
 ** 0 of 438 failed
 ** 7 of 7 cover properties satisfied

VERIFICATION:- SUCCESSFUL
Verification Time: 87.682434s

Checking harness depth_step_clamp::depth_step_clamp...
CBMC 6.4.0 (27a27caba2-dirty)
Check 3: depth_step_clamp::body.assertion.1
\t - Status: FAILURE
\t - Description: \"G76.DEPTH.LAST: every rough depth lies in 1…k − d\"
VERIFICATION:- FAILED
Verification Time: 12.5s

Summary:
Verification failed for - depth_step_clamp::depth_step_clamp
Complete - 1 successfully verified harnesses, 1 failures, 2 total.
";

    #[test]
    fn parses_verdicts_times_and_versions() {
        let log = parse_log(TWO);
        assert_eq!(log.kani_version.as_deref(), Some("0.61.0"));
        assert_eq!(log.cbmc_version.as_deref(), Some("6.4.0"));
        assert_eq!(log.harnesses.len(), 2);
        let g90 = &log.harnesses[0];
        assert_eq!((g90.name.as_str(), g90.short_name()), ("g90_envelope::g90_envelope", "g90_envelope"));
        assert_eq!(g90.verdict, Verdict::Successful);
        assert_eq!(g90.seconds, Some(87.682434));
        assert_eq!(log.verdict_of("depth_step_clamp"), Some(&Verdict::Failed));
        assert_eq!(log.result_of("depth_step_clamp::depth_step_clamp").and_then(|h| h.seconds), Some(12.5));
        assert_eq!(log.verdict_of("g162_split_exact"), None);
    }

    /// A run stopped by a time or memory limit: the harness was started, no verdict follows.
    #[test]
    fn a_harness_without_a_verdict() {
        let text = "Kani Rust Verifier 0.61.0 (cargo plugin)\nChecking harness depth_bounds::depth_bounds...\n\
                    CBMC version 6.4.0 (x) 64-bit\n1570135 variables, 8299612 clauses\n";
        let log = parse_log(text);
        let h = log.result_of("depth_bounds").unwrap();
        assert_eq!(h.verdict, Verdict::NoVerdict("1570135 variables, 8299612 clauses".into()));
        assert_eq!(h.verdict.label(), "no verdict");
        assert_eq!(h.seconds, None);
        // Then a later run of the same harness decides it: the last result counts.
        let more = format!("{text}Checking harness depth_bounds::depth_bounds...\nVERIFICATION:- SUCCESSFUL\nVerification Time: 3s\n");
        assert_eq!(parse_log(&more).verdict_of("depth_bounds"), Some(&Verdict::Successful));
        assert_eq!(parse_log(&more).harnesses.len(), 2);
    }

    /// Terse output, and failure variants.
    #[test]
    fn terse_and_failure_variants() {
        let text = "Kani Rust Verifier 0.61.0 (standalone)\nChecking harness a::b...\n\
                    VERIFICATION:- FAILED (encountered failures other than panics, which were unexpected)\n\
                    Checking harness c::d...\nVERIFICATION:- UNDETERMINED\n";
        let log = parse_log(text);
        assert_eq!(log.verdict_of("b"), Some(&Verdict::Failed));
        assert_eq!(log.verdict_of("d"), Some(&Verdict::NoVerdict("VERIFICATION:- UNDETERMINED".into())));
        assert_eq!(log.cbmc_version, None);
        assert_eq!(parse_log("").harnesses, vec![]);
    }

    /// An excerpt of the measured g92_pullout_geometry log (Kissat, an external solver), with
    /// the `/usr/bin/time -v` lines that follow it in the evidence file.
    #[test]
    fn kissat_log_with_time_lines() {
        let text = "Kani Rust Verifier 0.61.0 (cargo plugin)\n\
                    Checking harness g92_pullout_geometry::g92_pullout_geometry...\n\
                    CBMC version 6.4.0 (27a27caba2-dirty) 64-bit x86_64 linux\n\
                    Solving with External SAT solver\nresult:SATISFIABLE\n\
                    SUMMARY:\n ** 0 of 200 failed (2 unreachable)\n ** 5 of 5 cover properties satisfied\n\n\
                    VERIFICATION:- SUCCESSFUL\nVerification Time: 214.57138s\n\n\
                    Complete - 1 successfully verified harnesses, 0 failures, 1 total.\n\
                    \tElapsed (wall clock) time (h:mm:ss or m:ss): 3:37.04\n\tMaximum resident set size (kbytes): 309388\n";
        let log = parse_log(text);
        assert_eq!(log.verdict_of("g92_pullout_geometry"), Some(&Verdict::Successful));
        assert_eq!(log.result_of("g92_pullout_geometry").and_then(|h| h.seconds), Some(214.57138));
        assert_eq!(property("g92_pullout_geometry").map(|p| p.checked_by), Some(CheckedBy::Kani));
        for name in ["depth_step", "g162_split_tail", "g71_layers"] {
            assert_eq!(property(name).map(|p| p.checked_by), Some(CheckedBy::Drivers), "{name}");
        }
    }

    #[test]
    fn property_table_is_well_formed() {
        let mut names: Vec<&str> = PROPERTIES.iter().map(|p| p.harness).collect();
        names.sort_unstable();
        let before = names.len();
        names.dedup();
        assert_eq!(before, names.len(), "one entry per harness");
        for p in PROPERTIES {
            assert!(!p.rules.is_empty() && !p.statement.is_empty(), "{}", p.harness);
            assert!(!p.statement.contains('\n'), "{}: one line", p.harness);
            for r in p.rules {
                assert!(r.chars().all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '.'), "{}: rule {r}", p.harness);
            }
        }
        for name in ["g90_envelope", "g92_pullout_geometry", "hold_retract", "schedule_step", "schedule_count", "schedule_new_shape"] {
            assert_eq!(property(name).map(|p| p.checked_by), Some(CheckedBy::Kani), "{name}");
        }
        assert!(property("nope").is_none());
        // Every rule a property names is in the catalogue.
        for p in PROPERTIES {
            for r in p.rules {
                assert!(cycle_vocab::Rule::from_id(r).is_some(), "{}: unknown rule {r}", p.harness);
            }
        }
    }
}
