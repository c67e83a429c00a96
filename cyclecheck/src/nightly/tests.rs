use super::*;

#[test]
fn text_summary_lists_targets_and_findings() {
    let plan = Plan { budget: 5, targets: vec![Target::DiffSpecImpl], out: "o".into(), features: None, root: ".".into(), fork: 2, rss_limit_mb: 2048 };
    let s = TargetSummary {
        target: "diff_spec_impl",
        seconds: 5.0,
        fuzz_exit: Some(77),
        stats: Stats { executions: 10, execs_per_sec: 2, coverage_edges: 3, features: 4, new_units: 0, peak_rss_mb: Some(612), fork: 2, jobs: 5, ooms: 1, ..Stats::default() },
        sampled_peak_rss_mb: Some(700),
        corpus_files: (9, 7),
        corpus_bytes: (90, 70),
        findings: vec![Finding { artifact: "a/crash-1".into(), minimized: None, regression: "r/crash-1".into(), report: "DIVERGE".into() }],
        errors: vec![],
    };
    let t = summary_text(&plan, &[s]);
    assert!(t.contains("diff_spec_impl") && t.contains("9 →      7") && t.contains("FINDING a/crash-1"), "{t}");
    assert!(t.contains("-fork=2, RSS limit 2048 MB") && t.contains("       1     612\n") && t.contains("5 jobs; oom/timeout/crash 1/0/0"), "{t}");
}
