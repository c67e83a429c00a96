extern crate std;

use super::*;

#[test]
fn a_code_selects_at_most_one_family_per_dialect() {
    for d in [Gsk, Fanuc, Nc201] {
        for code in 0..=200u64 {
            let n = FAMILIES.iter().filter(|f| f.has(code) && f.dialects.contains(&d)).count();
            assert!(n <= 1, "G{code} under {d:?} selects {n} families");
        }
    }
}

#[test]
fn lookup_finds_the_family_of_each_dialect() {
    assert!(matches!(lookup(76, Gsk), Lookup::Selects(f) if f.name == "g76"));
    assert!(matches!(lookup(76, Fanuc), Lookup::Selects(f) if f.name == "f76"));
    assert!(matches!(lookup(33, Fanuc), Lookup::Selects(f) if f.name == "g32"));
    assert!(matches!(lookup(162, Nc201), Lookup::Selects(f) if f.name == "g162"));
    assert!(matches!(lookup(78, Fanuc), Lookup::OtherDialect));
    assert!(matches!(lookup(162, Gsk), Lookup::OtherDialect));
    assert!(matches!(lookup(92, Nc201), Lookup::OtherDialect));
    assert!(matches!(lookup(1, Gsk), Lookup::None));
    assert!(matches!(lookup(91, Gsk), Lookup::None));
}

/// Every code of every row is read by the block interpreter under each of its dialects: its
/// block may end in a missing-word or range alarm, never in an unsupported-code one; and under
/// a dialect outside the row it is refused by PRJ.DIALECT (G90 under nc201 aside).
#[test]
fn the_interpreter_reads_every_row() {
    use crate::expander::Expander;
    use cycle_vocab::{AlarmCode, Config, Rule};
    use std::format;
    for f in FAMILIES {
        for &code in f.codes {
            let program = format!("G{code} X10.\n");
            for d in [Gsk, Fanuc, Nc201] {
                if d == Nc201 && code == 90 {
                    continue; // NC201.ABSINC: G90 is the absolute mode there, no cycle.
                }
                let config = Config { dialect: d, ..Config::default() };
                let alarm = Expander::new(program.as_bytes(), config).find_map(Result::err);
                let unsupported = alarm.filter(|a| a.code == AlarmCode::UnsupportedCode && a.word == Some(b'G'));
                let other_family = FAMILIES.iter().any(|g| g.has(u64::from(code)) && g.dialects.contains(&d));
                if f.dialects.contains(&d) || other_family {
                    assert_eq!(unsupported, None, "G{code} ({}) under {d:?}", f.name);
                } else {
                    assert_eq!(unsupported.map(|a| a.rule), Some(Rule::PrjDialect), "G{code} under {d:?}");
                }
            }
        }
    }
}
