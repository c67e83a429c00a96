//! Unit tests of `invariants`.

use super::*;

#[test]
fn seeds_reach_every_harness_encode_and_replay_to_themselves() {
    let seeds = seeds();
    assert_eq!(seeds.len(), 5 * HARNESSES.len());
    for (name, d) in &seeds {
        assert!(name.starts_with(d.harness), "{name} runs {}", d.harness);
        report(d.harness, &d.draws, d.outcome, d.program.as_deref()).unwrap_or_else(|e| panic!("seed {name}: {e}"));
        let bytes = encode(d.harness, &d.draws).unwrap();
        assert_eq!(&decode(&bytes), d, "seed {name}");
        assert_eq!(replay(d.harness, &d.draws), Ok((d.outcome, d.program.clone())), "seed {name}");
    }
    // The random seeds are not all plain: most draw something other than the low ends.
    let random_with_programs = seeds.iter().filter(|(n, d)| n.contains("random") && d.program.is_some()).count();
    assert!(random_with_programs >= 8, "{random_with_programs}");
}

#[test]
fn unknown_harnesses_and_misfit_draws_are_refused() {
    assert_eq!(run("nope", &mut ReplaySource::new(vec![])), None);
    assert_eq!(encode("nope", &[]), None);
    assert!(replay("nope", &[]).unwrap_err().contains("no harness \"nope\""));
    // g92_pullout_total draws the grid first, from 0..=3.
    assert!(replay("g92_pullout_total", &[9]).unwrap_err().contains("draw 0 is 9, outside 0..=3"));
}

#[test]
fn a_failing_case_reports_harness_draws_and_program() {
    let e = report("trace_depths", &[1, 2], Err(Stop::Failed("boom")), Some(b"G0 X1")).unwrap_err();
    assert_eq!(e, "harness trace_depths: boom\ndraws: [1, 2]\nprogram:\nG0 X1");
    assert_eq!(report("trace_depths", &[], Err(Stop::Rejected), None), Ok(()));
}
