use super::*;

#[test]
fn counts_cargo_test_results() {
    let out = "test result: ok. 12 passed; 0 failed; 1 ignored; 0 measured\nnoise\n\
                   test result: FAILED. 3 passed; 2 failed; 0 ignored\n";
    assert_eq!(test_counts(out), (15, 2));
}

#[test]
fn in_process_steps_pass_on_this_impl() {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let steps = [corpus_step(None), campaign_step(200, 1, None), replay_step(root, None)];
    for s in &steps {
        assert!(s.passed, "{}: {}\n{}", s.name, s.summary, s.details);
    }
    // The impl_invariants cases are replayed here too, in this process.
    let harness_cases =
        steps[2].summary.split(" and ").nth(1).and_then(|t| t.split(' ').next()).and_then(|n| n.parse::<usize>().ok());
    assert!(harness_cases.is_some_and(|n| n > 0), "{}", steps[2].summary);
    let text = report(&steps, Duration::from_secs(1));
    assert!(text.contains("gate PASSED: 3 of 3 steps passed"), "{text}");
}

#[test]
fn shards_of_the_in_process_steps_add_up_to_the_whole() {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    // The number before `programs`, `cases` or `committed` in a step's summary.
    let count = |s: &Step| -> usize {
        let words: Vec<&str> = s.summary.split_whitespace().collect();
        let at =
            words.windows(2).position(|w| ["programs", "programs,", "cases", "cases,", "committed"].contains(&w[1]));
        at.and_then(|i| words[i].parse().ok()).unwrap_or_else(|| panic!("no count in {}", s.summary))
    };
    let whole = [corpus_step(None), campaign_step(60, 1, None), replay_step(root, None)];
    let shards: Vec<[Step; 3]> = (1..=3)
        .map(|k| {
            let s = Some(Shard { index: k, count: 3 });
            [corpus_step(s), campaign_step(60, 1, s), replay_step(root, s)]
        })
        .collect();
    for (i, w) in whole.iter().enumerate() {
        assert!(w.passed, "{}", w.summary);
        assert!(shards.iter().all(|s| s[i].passed && s[i].summary.contains(", shard ")), "{}", shards[0][i].summary);
        assert_eq!(shards.iter().map(|s| count(&s[i])).sum::<usize>(), count(w), "{}", w.summary);
    }
}

#[test]
fn a_failed_step_fails_the_gate_and_shows_its_details() {
    let bad = Step {
        name: "x",
        passed: false,
        summary: "1 case".into(),
        details: "DIVERGE here".into(),
        time: Duration::ZERO,
    };
    let text = report(&[corpus_step(None), bad], Duration::ZERO);
    assert!(
        text.contains("FAIL x") && text.contains("--- x ---\nDIVERGE here") && text.contains("gate FAILED"),
        "{text}"
    );
}
