use super::*;

#[test]
fn ids_round_trip_and_are_unique() {
    let mut seen = std::collections::HashSet::new();
    for &r in Rule::ALL {
        assert!(seen.insert(r.id()), "duplicate rule ID {}", r.id());
        assert_eq!(Rule::from_id(r.id()), Some(r));
    }
}

/// The code list and the catalogue in docs/RULES.md name the same rules.
#[test]
fn catalogue_matches_code() {
    let doc = include_str!("../../../docs/RULES.md");
    let mut in_doc = std::collections::BTreeSet::new();
    for line in doc.lines() {
        if let Some(rest) = line.strip_prefix("| ") {
            let id = rest.split(' ').next().unwrap_or("");
            if id.chars().next().is_some_and(|c| c.is_ascii_uppercase()) && id != "ID" {
                in_doc.insert(id.to_string());
            }
        }
    }
    let in_code: std::collections::BTreeSet<String> =
        Rule::ALL.iter().map(|r| r.id().to_string()).collect();
    let sources = ["M000", "M001", "M002", "M003", "M004", "PRJ"];
    in_doc.retain(|id| !sources.contains(&id.as_str()));
    assert_eq!(in_doc, in_code, "docs/RULES.md and Rule::ALL differ");
}
