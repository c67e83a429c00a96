use super::*;

#[test]
fn dates_are_civil() {
    assert_eq!(civil_date(0), "1970-01-01");
    assert_eq!(civil_date(11_016), "2000-02-29");
    assert_eq!(civil_date(20_415), "2025-11-23");
    assert_eq!(civil_date(-1), "1969-12-31");
}

#[test]
fn regressions_are_written_decoded() {
    if crate::spec_alone::skip("a parse_blocks regression's replay (the two lexers side by side)") {
        return;
    }
    let root = std::env::temp_dir().join(format!("cyclecheck-committed-{}", std::process::id()));
    let input = root.join("crash-1");
    std::fs::create_dir_all(&root).unwrap();
    std::fs::write(&input, "G0 X1 Z1\nG92 X#\n").unwrap();
    let report = write_regression(&root, Target::ParseBlocks, &input, "crash-1", "a test").unwrap();
    assert!(report.starts_with("passes in this build"), "{report}");
    let cases = decoded::load_programs(&regressions_dir(&root, Target::ParseBlocks)).unwrap();
    assert_eq!(cases.len(), 1);
    let (name, program, case) = &cases[0];
    assert_eq!((name.as_str(), program.as_slice(), case.origin.date.as_deref()), ("crash-1", &b"G0 X1 Z1\nG92 X#\n"[..], Some(today().as_str())));
    let _ = std::fs::remove_dir_all(&root);
}
