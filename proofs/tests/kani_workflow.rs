//! `.github/workflows/kani.yml` against [`PROPERTIES`]: one job per Kani proof, none for a TEST,
//! and `-Z stubbing` exactly for the harnesses that stub a function.

use cycle_proofs::{CheckedBy, PROPERTIES};

const WORKFLOW: &str = include_str!("../../.github/workflows/kani.yml");

/// The matrix entries: (harness, flags).
fn jobs() -> Vec<(String, String)> {
    let mut jobs = Vec::new();
    let mut lines = WORKFLOW.lines().map(str::trim);
    while let Some(line) = lines.next() {
        let Some(name) = line.strip_prefix("- harness: ") else { continue };
        let flags = lines
            .by_ref()
            .take_while(|l| !l.starts_with("- harness:") && !l.is_empty())
            .find_map(|l| l.strip_prefix("flags: "))
            .unwrap_or_else(|| panic!("{name}: no flags line"));
        jobs.push((name.to_string(), flags.trim_matches('\'').to_string()));
    }
    jobs
}

#[test]
fn one_job_per_kani_proof_with_its_flags() {
    let jobs = jobs();
    let mut names: Vec<&str> = jobs.iter().map(|(n, _)| n.as_str()).collect();
    names.sort_unstable();
    let mut proofs: Vec<&str> = PROPERTIES.iter().filter(|p| p.checked_by == CheckedBy::Kani).map(|p| p.harness).collect();
    proofs.sort_unstable();
    assert_eq!(names, proofs, "kani.yml's jobs vs the Kani proofs of PROPERTIES");
    for (name, flags) in &jobs {
        let p = PROPERTIES.iter().find(|p| p.harness == name).unwrap();
        assert_eq!(flags.contains("-Z stubbing"), !p.stubs.is_empty(), "{name}: -Z stubbing exactly when it stubs");
        assert!(!flags.contains("kani-attempts"), "{name}: a proof needs no kani-attempts");
    }
}
