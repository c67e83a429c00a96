//! proofs/README.md against [`PROPERTIES`]: its table of Kani proofs lists exactly the
//! properties checked by Kani, its table of TESTs exactly the others, each row with the rules,
//! unwind bound, solver and measured result (or reason) its harness states.

use cycle_proofs::{CheckedBy, Property, PROPERTIES};
use std::collections::BTreeMap;

const README: &str = include_str!("../README.md");

/// The rows of the first table after the heading that starts with `heading`, by harness name
/// (the first cell, in backquotes), each as its cells.
fn table(heading: &str) -> BTreeMap<String, Vec<String>> {
    let at = README.find(&format!("\n{heading}")).unwrap_or_else(|| panic!("README has no heading {heading:?}"));
    let mut rows = BTreeMap::new();
    let lines = README[at..].lines().skip_while(|l| !l.starts_with('|'));
    for line in lines.take_while(|l| l.starts_with('|')).skip(2) {
        // `\|` inside a cell is an escaped bar, not a separator.
        let cells: Vec<String> = line.trim().trim_matches('|').replace("\\|", "\u{1}").split(" | ").map(|c| c.trim().replace('\u{1}', "\\|")).collect();
        let name = cells[0].strip_prefix('`').and_then(|c| c.strip_suffix('`')).unwrap_or_else(|| panic!("first cell not a `name`: {line}"));
        assert!(rows.insert(name.to_string(), cells.clone()).is_none(), "{name} listed twice");
    }
    rows
}

fn names(kind: CheckedBy) -> Vec<&'static str> {
    let mut v: Vec<_> = PROPERTIES.iter().filter(|p| p.checked_by == kind).map(|p| p.harness).collect();
    v.sort_unstable();
    v
}

fn property(name: &str) -> &'static Property {
    PROPERTIES.iter().find(|p| p.harness == name).unwrap()
}

#[test]
fn kani_proofs_table_is_the_property_list() {
    let rows = table("## Kani proofs");
    assert_eq!(rows.keys().map(String::as_str).collect::<Vec<_>>(), names(CheckedBy::Kani), "README's Kani proofs vs PROPERTIES");
    for (name, cells) in &rows {
        let p = property(name);
        assert_eq!(cells.len(), 11, "{name}: harness | rules | proves | bounds | stubs | unwind | solver | verdict | Kani time | wall | peak memory");
        assert_eq!(cells[1], p.rules.join(", "), "{name}: rules");
        assert_eq!(cells[5], p.unwind.map_or("none (no loop)".to_string(), |u| u.to_string()), "{name}: unwind");
        let solver = match p.solver {
            None => "CaDiCaL",
            Some("kissat") => "Kissat",
            Some(other) => panic!("{name}: solver {other} not described in the README"),
        };
        assert!(cells[6].starts_with(solver), "{name}: solver {} vs {solver}", cells[6]);
        assert_eq!(format!("{}, {}, {}", cells[7], cells[8], cells[10]), p.kani, "{name}: verdict, Kani time, peak memory");
        assert_eq!(cells[4] == "none", p.stubs.is_empty(), "{name}: stubs");
    }
}

#[test]
fn tests_table_is_the_property_list() {
    let rows = table("## TESTs");
    assert_eq!(rows.keys().map(String::as_str).collect::<Vec<_>>(), names(CheckedBy::Drivers), "README's TESTs vs PROPERTIES");
    for (name, cells) in &rows {
        let p = property(name);
        assert_eq!(cells.len(), 4, "{name}: TEST | rules | why not Kani | what covers it instead");
        assert_eq!(cells[1], p.rules.join(", "), "{name}: rules");
        assert_eq!(cells[2], p.kani, "{name}: why not Kani");
    }
}

#[test]
fn every_property_has_tests_and_names_are_unique() {
    let mut seen = std::collections::BTreeSet::new();
    for p in PROPERTIES {
        assert!(seen.insert(p.harness), "{} listed twice", p.harness);
        assert!(!p.tests.is_empty() && !p.rules.is_empty() && !p.kani.is_empty(), "{}", p.harness);
        assert!(!p.statement.contains('\n'), "{}: one line", p.harness);
    }
}
