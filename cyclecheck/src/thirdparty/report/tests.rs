use super::*;

fn manifest(name: &str) -> Manifest {
    Manifest {
        path: format!("candidates/{name}/candidate.toml").into(),
        name: name.to_string(),
        expander: format!("{name} 1.0"),
        command: format!("candidates/{name}/run"),
        setup: "true".to_string(),
        deviations: None,
        ci: false,
        timeout_ms: None,
        max_failures: None,
        campaigns: Vec::new(),
        notes: Default::default(),
        findings: Vec::new(),
    }
}

/// A candidate not run keeps its previous section verbatim; one never run says so; one not
/// installed here (without a previous section) says that.
#[test]
fn sections_not_run_are_kept_from_the_previous_document() {
    let all = [manifest("a"), manifest("b"), manifest("c")];
    let previous = "intro\n<!-- candidate: a -->\n## a\n\n| G92 | 7 |\n<!-- end candidate: a -->\n";
    let missing = CandidateReport { manifest: manifest("c"), declarations: Vec::new(), outcome: Outcome::NotInstalled("spawn failed".into()) };
    let doc = document(&all, &[missing], Some(previous));
    assert_eq!(section(&doc, "a"), section(previous, "a"));
    assert!(section(&doc, "b").unwrap().contains("Not run yet."));
    assert!(section(&doc, "c").unwrap().contains("**Not installed here** (spawn failed)"));
    assert!(doc.starts_with("# Third-party expanders against the reference") && doc.contains("| a | a 1.0 | `candidates/a/run` |"));
    assert_eq!(section("no markers", "a"), None);
}
