use super::*;
use cycle_vocab::{AlarmCode, Rule};

fn origin() -> Origin {
    Origin { target: "diff_spec_impl".into(), found_by: "a test".into(), date: None }
}

#[test]
fn a_program_case_reads_back_as_written() {
    let alarm = Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3);
    let expect = Expect { conform: Some(true), reference_ends: Some(Ending::Alarm(alarm)), ..Expect::default() };
    let case = ProgramCase { config: Some(Config::default()), expect, origin: origin(), built: None };
    let text = to_json(&case).unwrap();
    assert!(text.contains("\n  \"expect\": {\"conform\":true,\"reference_ends\":{\"alarm\":{\"code\":\"MISSING_WORD\""), "{text}");
    assert_eq!(parse::<ProgramCase>("x", text.as_bytes()), Ok(case));
    assert!(parse::<ProgramCase>("x", b"{\"expect\": {\"conformm\": true}}").unwrap_err().contains("conformm"));
}

#[test]
fn directories_pair_programs_with_their_json() {
    let dir = std::env::temp_dir().join(format!("cyclecheck-decoded-{}", std::process::id()));
    let case = ProgramCase { config: None, expect: Expect::default(), origin: origin(), built: None };
    write_dir(&dir, &program_files("a", b"G0 X1\n", &case).unwrap()).unwrap();
    assert_eq!(load_programs(&dir).unwrap(), vec![("a".to_string(), b"G0 X1\n".to_vec(), case.clone())]);
    std::fs::write(dir.join("b.nc"), "G0").unwrap();
    assert!(load_programs(&dir).unwrap_err().contains("no b.json beside it"));
    write_dir(&dir, &[]).unwrap();
    assert_eq!(read_dir(&dir).unwrap(), vec![]);
    let _ = std::fs::remove_dir(&dir);
}

#[test]
fn a_harness_case_keeps_wide_draws() {
    let case = HarnessCase {
        harness: "g92_pullout_total".into(),
        draws: vec![0, -705_032_702, i128::from(u64::MAX)],
        expect: HarnessExpect::Holds,
        program: Some("G92 U1\n".into()),
        origin: origin(),
    };
    let text = to_json(&case).unwrap();
    assert!(text.contains("\"draws\": [0,-705032702,18446744073709551615]"), "{text}");
    assert_eq!(parse::<HarnessCase>("x", text.as_bytes()), Ok(case));
}
