//! The block interpreter on the whole expander: the program words of the contour cycles
//! ([`program_words`]) and the spindle speed ([`speed`]).

mod program_words;
mod speed;

/// Every code of every family row maps to how its block is read (a row the interpreter did not
/// know would refuse its code as unsupported).
#[test]
fn every_family_code_has_a_kind() {
    let b = crate::lex::Block::new();
    for f in crate::family::FAMILIES {
        for &code in f.codes {
            for axis in [false, true] {
                assert!(super::kind::cycle_kind(f, u64::from(code), &b, axis).is_some(), "{} G{code}", f.name);
            }
        }
    }
}
