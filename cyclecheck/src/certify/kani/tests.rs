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
    let more = format!(
        "{text}Checking harness depth_bounds::depth_bounds...\nVERIFICATION:- SUCCESSFUL\nVerification Time: 3s\n"
    );
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
            assert!(
                r.chars().all(|c| c.is_ascii_uppercase() || c.is_ascii_digit() || c == '.'),
                "{}: rule {r}",
                p.harness
            );
        }
    }
    for name in [
        "g90_envelope",
        "g92_pullout_geometry",
        "hold_retract",
        "schedule_step",
        "schedule_count",
        "schedule_new_shape",
    ] {
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
