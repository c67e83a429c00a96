use super::*;

/// The traceability promise: every catalogue rule has a row, and every implemented rule
/// points at code (spec, production or shared) and at least one test, proof or fuzz target —
/// mentions in module documentation count for neither. A manual's example (status `impl
/// (snapshot…)`) is implemented by the rules it shows, not by code of its own: it needs the
/// check only.
/// A rule that fails here needs a citation where it is implemented or checked — not a
/// weaker test.
#[test]
fn every_rule_is_traced() {
    let rows = rows(None);
    let ids: Vec<&str> = rows.iter().map(|r| r.id).collect();
    for &rule in Rule::ALL {
        assert!(ids.contains(&rule.id()), "{rule} has no row");
    }
    let mut missing = Vec::new();
    // A check in a module's documentation is no check.
    for r in rows.iter().filter(|r| r.implemented) {
        if !r.has_code() && !r.status.contains("(snapshot") {
            missing.push(format!("{}: no spec, impl or shared code", r.id));
        }
        if !r.has_check() {
            missing.push(format!("{}: no test, proof or fuzz target", r.id));
        }
    }
    assert!(missing.is_empty(), "untraced rules:\n{}", missing.join("\n"));
}

/// The scan found what it should: the spec's G92 table, a test, and only catalogue IDs.
#[test]
fn citations_are_found_where_they_are() {
    let jk3 = citations(Rule::G92Jk3);
    assert!(jk3.iter().any(|c| c.kind == Kind::Spec && c.file == "spec/src/g92.rs" && c.item == "fn resolve_jk"), "{jk3:#?}");
    assert!(jk3.iter().any(|c| c.kind == Kind::Test), "{jk3:#?}");
    let example = citations(Rule::G92Example);
    assert!(example.iter().any(|c| c.item == "corpus program g92_example" && c.kind == Kind::Test), "{example:#?}");
    for c in CITATIONS {
        assert!(Rule::from_id(c.rule).is_some(), "{c:?}");
        assert!(c.line > 0 && !c.item.is_empty(), "{c:?}");
    }
    assert!(SCANNED.contains(&"spec/src") && SCANNED.contains(&"impl/src"), "{SCANNED:?}");
}

/// Rows come by group, families first in registry order, and each family has rules.
#[test]
fn rows_are_grouped_by_family() {
    let rows = rows(None);
    assert!(rows.windows(2).all(|w| w[0].group <= w[1].group));
    for f in registry::FAMILIES {
        assert!(rows.iter().any(|r| r.group == RuleGroup::Family(f)), "no rule of {}", f.name);
    }
    assert_eq!(rows[0].id, "G92.FORMAT");
    assert!(rows.iter().any(|r| r.group == RuleGroup::Common && r.id == "PRJ.LEX"));
}

#[test]
fn later_rules_are_not_implemented() {
    let g34 = rows(None).into_iter().find(|r| r.id == "G34").unwrap();
    if !g34.implemented {
        assert_eq!(g34.outcome, Outcome::NotImplemented);
    }
}
