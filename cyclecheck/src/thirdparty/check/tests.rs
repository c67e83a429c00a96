use super::*;

#[test]
fn digests_keep_counts_verdicts_and_groups_not_timings() {
    let doc = "<!-- candidate: x -->\n## x\n\n### Campaign 1: cycles g92\n\nComparison level: **motion** — m.\n\n| family | cases |\n|---|---:|\n| G92 | 35 |\n\n**Verdict: FAIL**\n\nTiming (never compared): 1.0 s\n\n#### Divergence group G92.PULLOUT: 6 case(s) (field mismatch, field z)\n\nNote: n\n\n| reason | cases |\n| r | 1 |\n<!-- end candidate: x -->";
    let d = digest(doc);
    assert!(d.contains("Campaign 1: cycles g92 :: | G92 | 35 |"), "{d:?}");
    assert!(d.iter().any(|l| l.ends_with("**Verdict: FAIL**")));
    assert!(d.iter().any(|l| l.contains("Divergence group G92.PULLOUT: 6 case(s)")));
    assert!(!d.iter().any(|l| l.contains("Timing") || l.contains("| r |")), "{d:?}");
    assert_eq!(d, digest(&doc.replace("1.0 s", "9.9 s")));
    assert_ne!(d, digest(&doc.replace("| 35 |", "| 36 |")));
}
