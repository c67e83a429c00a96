use super::*;

#[test]
fn every_rule_has_an_entry() {
    for &r in Rule::ALL {
        let e = entry(r).unwrap_or_else(|| panic!("no catalogue row for {r}"));
        assert!(!e.text.is_empty() && !e.source.is_empty() && !e.status.is_empty(), "{e:?}");
    }
}

#[test]
fn quotes_the_row() {
    let e = entry(Rule::G76DepthMin).unwrap();
    assert_eq!(e.source, "M001");
    assert!(e.text.starts_with("When (√n − √(n−1))·Δd < Δdmin"), "{}", e.text);
    assert_eq!(e.status, "impl");
    // An escaped pipe stays in its cell.
    let l = entry(Rule::ComLongAxis).unwrap();
    assert!(l.text.contains(r"\|ΔZ\|"), "{}", l.text);
}
