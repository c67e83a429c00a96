//! Evidence input from Kani: a parser of `cargo kani` output (per harness: its name, its
//! verdict, its verification time; the Kani and CBMC versions of the run) and the table of the
//! proof properties of `cycle-proofs` (per harness: its name, rule IDs, what it states, and
//! whether it is a Kani proof or a test run by the drivers only).
//!
//! Self-contained, `std` only. Not wired into the certify command here; the intended use is
//! `certify --kani-log FILE`: parse the log with [`parse_log`], then list each entry of
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

/// How a property of [`PROPERTIES`] is checked.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CheckedBy {
    /// A Kani proof harness (`cargo kani -p cycle-proofs --harness NAME`), also run by the
    /// bounded-exhaustive and random drivers under `cargo test`.
    Kani,
    /// A TEST: the harness body run by the bounded-exhaustive and random drivers under
    /// `cargo test` only (no Kani wrapper: Kani does not reach a verdict on it in useful time).
    Drivers,
}

/// One property of `cycle-proofs`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Property {
    /// The harness (`--harness` name; for a TEST, the body's module).
    pub harness: &'static str,
    /// The rule IDs it bears on.
    pub rules: &'static [&'static str],
    /// What it states, in one line.
    pub statement: &'static str,
    pub checked_by: CheckedBy,
}

/// The proof properties of `cycle-proofs` (proofs/README.md has the bounds, stubs, measured
/// times and what is left to the drivers).
pub const PROPERTIES: &[Property] = &[
    Property {
        harness: "depth_step_clamp",
        rules: &["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        statement: "Every step of the production depth schedule (first, or next of any pass): numbered n + 1, depth in 1…k − d, last exactly at k − d and named G76.DEPTH.LAST, a minimum-cut step adds exactly Δdmin, a constant step is n·Δd, nothing after the last or past pass 2^32 − 1; the pass count is at most the limit and does not depend on it.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "g90_envelope",
        rules: &["G90.FORMAT", "G90.TAPER", "G90.PATH", "G94.FORMAT", "G94.TAPER", "G94.PATH", "PRJ.NOOP"],
        statement: "One G90/G94 cycle: refused exactly by the register's step 5 in its order, else one ROUGH pass header (index, depth = the infeed of ①) then exactly the moves ①–④ (none to the current position), every point in the box of A, D and C, back at A.",
        checked_by: CheckedBy::Kani,
    },
    Property {
        harness: "g92_pullout_geometry",
        rules: &["G92.JK.1", "G92.JK.2", "G92.JK.3", "G92.JK.4", "G92.JK.5", "G92.JK.6", "G92.JK.7", "G92.PULLOUT", "COM.LONGAXIS"],
        statement: "Below the lexer: the register's J/K/No.19 table, the pull-out geometry (long axis at |W| > |R|, start K before the end toward A, end s·J out on X or J toward A on Z, the interpolated coordinate's sign), No.19 × lead / 10 rounded once half up.",
        checked_by: CheckedBy::Kani,
    },
    Property {
        harness: "hold_retract",
        rules: &["G92.HOLD", "G76.HOLD"],
        statement: "The feed-hold retract of a thread cut (No.0018 bit 6 = 0) over ±2^40, from any point of the held move: a move in the pull-out manner exactly when the cut has a pull-out, by the programmed pull-out's displacement (or on to its end from the pull-out), the way the pull-out goes on the short axis, never past the thread's end on the long axis; then a rapid on the short axis only to A's coordinate, then A.",
        checked_by: CheckedBy::Kani,
    },
    Property {
        harness: "schedule_step",
        rules: &["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE"],
        statement: "The induction step of the production depth schedule on a symbolic schedule (from_parts; root_depth and constant_depth stubbed by two depths whose assumptions are z3 lemmas 01-05, 07, 09, 11, checked by the drivers): the next pass of an admissible pass is pass n + 1, depth in 1…k − d, last exactly at k − d and named G76.DEPTH.LAST, never shallower, strictly deeper with Δdmin ≥ 1, in constant mode and at the last, every cut but the last ≥ Δdmin (exactly Δdmin from the switch pass, Δd in constant mode), admissible again; pass 1 is min(Δd, k − d).",
        checked_by: CheckedBy::Kani,
    },
    Property {
        harness: "schedule_count",
        rules: &["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        statement: "The closed-form pass count agrees with stepping on a symbolic schedule (the count's root and quotient stubbed by b and Q whose assumptions are z3 lemmas 05, 08, 11, checked by the drivers): the pass after an exact pass is last exactly when it is numbered by the count, earlier passes are numbered below it, and a limit gives the count or none.",
        checked_by: CheckedBy::Kani,
    },
    Property {
        harness: "schedule_new_shape",
        rules: &["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE"],
        statement: "Schedule::new of legal words (its reach quotient real, switch_pass stubbed: NEVER without a minimum, else ≥ 1, lemma 07) has the shape from_parts accepts (reach in 1…2^33, switch ≥ 1, NEVER without a minimum or in constant mode) and from_parts rebuilds it exactly.",
        checked_by: CheckedBy::Kani,
    },
    Property {
        harness: "depth_step",
        rules: &["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE"],
        statement: "One step of the production depth schedule (first, or next of any pass) over the full legal ranges, with root and switch_pass stubbed by their specifications (z3 lemmas 01, 02, 07; impl's unit tests): numbered n + 1, depth in 1…k − d, last exactly at k − d and named G76.DEPTH.LAST, a minimum cut adds exactly Δdmin, a constant step adds Δd (depth n·Δd), a G76.DEPTH.1 depth is the root of n·Δd², nothing after the last or past pass 2^32 − 1.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "g162_split_tail",
        rules: &["G162.PQ", "G162.SPLIT", "PRJ.MAXPASS"],
        statement: "The G162 split over the full legal ranges with P formed as kQ + D (norm stubbed by k and D): pass 1, full pass n + 1 after n < k at (n + 1)·Q, the split targets kQ + e·D/8 rounded once half up (a target not deeper dropped), last exactly at P, the cuts summing to D, the pass count against the limit.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "peck_counts",
        rules: &["G74.FORMAT", "G74.PECK", "G74.E", "G74.COLUMN", "G75.FORMAT", "G75.PECK", "G75.COLUMN", "PRJ.MAXPASS"],
        statement: "One G74/G75 cycle below the lexer: refused exactly in the register's order (no travel on the peck axis, no peck, a step travel without a step, then columns × pecks > max_passes) before any event; else ⌈travel/step⌉ + 1 columns with one header each, ⌈depth/peck⌉ pecks per column, each one peck further toward E, the last exactly at E, none past it; back at A.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "g71_layers",
        rules: &["G71.LAYER", "G72.LAYER", "PRJ.MAXPASS"],
        statement: "The G71/G72 layer schedule below the contour geometry: TOO MANY PASSES before motion exactly when layer max_passes exists; layers strictly monotone toward the contour, each depth step exactly Δd, every layer before Q₀, the count the closed form ⌈D/step⌉ − 1 (0 when the cut is not positive); the run's headers, infeeds and cuts.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "depth_step_monotone",
        rules: &["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE"],
        statement: "Every reachable pass n of the production schedule is the register's closed form (round(√n·Δd) before the switch pass, + Δdmin from it, n·Δd in constant mode, clamped at k − d), and each step is monotone.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "depth_bounds",
        rules: &["G76.DEPTH.LAST", "G76.DEPTH.MIN", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        statement: "The first K + 1 passes of every schedule: numbered 1, 2, …, depths in 1…k − d and never decreasing, every cut but the last ≥ Δdmin (= Δd in constant mode), the closed-form pass count equal to the iterated one.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "schedule_spec",
        rules: &["G76.DEPTH.1", "G76.DEPTH.MIN", "G76.DEPTH.LAST", "G78.DEPTHMODE", "PRJ.MAXPASS"],
        statement: "The same depth-schedule properties over the spec's (BigInt) schedule: closed form, monotone steps, cuts ≥ Δdmin, last exactly at k − d, the count.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "no_overflow_isqrt_tan",
        rules: &["COM.RANGES", "COM.UNITS", "G76.INFEED.Z", "G76.PULLOUT", "COM.MULTISTART"],
        statement: "The fixed-point helpers meet their specifications with no panic: isqrt and sqrt_round brackets, half-up quotients, the exact 256-bit product, δ·tan rounded over the table's enclosure, the start angle.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "expander_never_panics",
        rules: &["COM.POINTS", "COM.RANGES", "PRJ.MAXPASS", "G76.PATH", "G92.PATH", "PRJ.TRACE"],
        statement: "Small G92/G76/G78 programs: no panic, bounded events, TOO MANY PASSES before any motion, every move inside the envelope computed from the words, back at A.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "g92_pullout_total",
        rules: &["G92.JK.1", "G92.JK.2", "G92.JK.3", "G92.JK.4", "G92.JK.5", "G92.JK.6", "G92.JK.7", "G92.PULLOUT", "G92.TAPER", "COM.LONGAXIS"],
        statement: "A whole G92 expansion: the thread moves are C → D or C → pull-out start → pull-out end with the register's J/K table and geometry; K ≥ travel and an illegal taper refused before any motion.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "g162_split_exact",
        rules: &["G162.PQ", "G162.SPLIT", "PRJ.MAXPASS"],
        statement: "The G162 depth split is the register's: k = ⌊P/Q⌋ full passes, the remainder split at D/2, 3D/4, 7D/8, D each rounded once half up (a target not deeper dropped), last exactly at P, the pass count.",
        checked_by: CheckedBy::Drivers,
    },
    Property {
        harness: "g162_variable_pitch",
        rules: &["G162.I", "G162.J", "G162.F", "G162.PQ", "G162.SPLIT", "G162.PATH", "G162.H", "PRJ.TRACE"],
        statement: "A whole G162 expansion under nc201: GEOMETRY on I exactly when the end lead leaves the F range, else the register's variable lead (the shrinking pitch never reaches ≤ 0) and depths strictly increasing to exactly P.",
        checked_by: CheckedBy::Drivers,
    },
];

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
    }
}
