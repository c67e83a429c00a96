use super::*;

#[test]
fn names_round_trip() {
    for t in Target::ALL {
        assert_eq!(Target::by_name(t.name()), Some(t));
    }
    assert_eq!(Target::by_name("nope"), None);
}

#[test]
fn every_target_passes_on_empty_and_small_inputs() {
    assert!(Target::ImplInvariants.run(b"").unwrap_err().contains("cycle_proofs::invariants"));
    // parse_blocks and diff_spec_impl compare the two lexers, the two engines.
    let differential = crate::spec_alone::skip("the parse_blocks and diff_spec_impl targets");
    for t in Target::PROGRAMS {
        if differential && matches!(t, Target::ParseBlocks | Target::DiffSpecImpl) {
            continue;
        }
        for data in [&b""[..], b"G0 X65 Z5\nG92 X58.7 Z-28 F3\n", &[0xff; 64], &[7; 300]] {
            t.run(data).unwrap_or_else(|e| panic!("{}: {e}", t.name()));
        }
    }
}

#[test]
fn parse_blocks_rejects_with_an_alarm_on_a_line() {
    if crate::spec_alone::skip("parse_blocks (the two lexers side by side)") {
        return;
    }
    assert_eq!(parse_blocks(b"G0 X1 Z1\nG92 X#\n"), Ok(()));
}

/// A report names the divergence and the program.
#[test]
fn a_divergence_report_names_program_and_config() {
    let e = verdict_ok(
        Verdict::Panic { engine: "impl".to_string(), message: "boom".to_string() },
        b"G0 X1",
        &Config::default(),
    )
    .unwrap_err();
    assert!(e.contains("PANIC in the impl engine: boom") && e.contains("program:\nG0 X1"), "{e}");
}
