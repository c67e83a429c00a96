use super::*;

#[test]
fn every_lemma_file_is_compiled_in_and_names_its_rules() {
    let on_disk = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/../smt/lemmas")).unwrap().count();
    assert_eq!(LEMMAS.len(), on_disk);
    for (name, text) in LEMMAS {
        assert!(text.contains("(check-sat)"), "{name}");
        assert!(!header_rules(text).is_empty(), "{name} names no rule in its header");
    }
}

#[test]
fn nothing_unverified_is_called_a_proof() {
    let none = Proofs::default();
    let kani = kani::PROPERTIES.iter().find(|p| p.checked_by == CheckedBy::Kani).unwrap();
    assert!(none.kani_status(kani.harness, kani.checked_by).starts_with("not run here"));
    let failed = KaniLog {
        kani_version: Some("0.61.0".into()),
        cbmc_version: None,
        harnesses: vec![kani::HarnessResult { name: format!("m::{}", kani.harness), verdict: Verdict::Failed, seconds: Some(2.0) }],
    };
    let with = Proofs { kani: Some(failed), ..Proofs::default() };
    assert!(with.kani_status(kani.harness, kani.checked_by).ends_with("not a proof"));
    let test = kani::PROPERTIES.iter().find(|p| p.checked_by == CheckedBy::Drivers).unwrap();
    assert!(with.kani_status(test.harness, test.checked_by).starts_with("a TEST"));
}

/// With z3 on the PATH (CI installs it), every lemma is unsat; without it, each says why.
#[test]
fn lemmas_run_or_say_why_not() {
    for l in run_lemmas() {
        match z3_version() {
            Some(_) => assert!(l.proved(), "{}: {}", l.name, l.result),
            None => assert!(l.result.starts_with("not run"), "{}", l.result),
        }
    }
}
