//! Nothing in the thread manuals is left unaccounted for (issue #22, item 5): every parameter
//! and address of `docs/THREAD-WORDS.md` names catalogue rules that exist, or the register
//! section that decides it, and every parameter is spoken of in the register.

use cycle_vocab::Rule;

const LIST: &str = include_str!("../../docs/THREAD-WORDS.md");
const REGISTER: &str = include_str!("../../docs/INTERPRETATION.md");

/// The table's rows: (manual, kind, item, rules column).
fn rows() -> Vec<[&'static str; 4]> {
    LIST.lines()
        .filter(|l| l.starts_with("| M00"))
        .map(|l| {
            let cells: Vec<&str> = l.trim_matches('|').split('|').map(str::trim).collect();
            assert_eq!(cells.len(), 5, "a row has five cells: {l}");
            [cells[0], cells[1], cells[2], cells[4]]
        })
        .collect()
}

#[test]
fn every_item_has_a_rule_or_a_register_entry() {
    let rows = rows();
    assert!(rows.len() >= 30, "the list has {} rows", rows.len());
    for [manual, kind, item, rules] in rows {
        let named: Vec<&str> = rules.split_whitespace().filter(|w| w.chars().next().is_some_and(|c| c.is_ascii_uppercase()) && w.contains('.') || ["G32", "G33", "G34"].contains(w)).collect();
        let in_register = rules.contains("register");
        assert!(!named.is_empty() || in_register, "{manual} {kind} {item}: no rule and no register entry");
        for id in named {
            assert!(Rule::from_id(id).is_some(), "{manual} {kind} {item}: {id} is not a catalogue rule");
        }
        if kind == "parameter" {
            let number = item.trim_start_matches("No.");
            assert!(REGISTER.contains(item) || REGISTER.contains(&format!("No.{number}")), "{manual} {item}: the register never speaks of it");
        }
    }
}

/// Every parameter number the thread manuals name is in the list (the seeds' own list, in the
/// project's words: M000/M001's parameter table, M002's notes).
#[test]
fn the_list_names_every_parameter_of_the_manuals() {
    let items: Vec<&str> = rows().iter().filter(|r| r[1] == "parameter").map(|r| r[2]).collect();
    for p in ["No.19", "No.107", "No.0018 bit 6", "5129", "5130", "5131", "5140", "5141", "5142", "5143", "5144", "5145"] {
        assert!(items.contains(&p), "{p} missing from docs/THREAD-WORDS.md");
    }
}
