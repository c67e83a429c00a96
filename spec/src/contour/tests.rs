use super::*;
use crate::lex::blocks;

fn block(text: &str) -> Block {
    blocks(text.as_bytes()).next().and_then(Result::ok).expect("a block")
}

#[test]
fn sequence_numbers_by_exact_value() {
    for n in ["N50", "N050", "N50.0", "N 50.000", "n50."] {
        assert!(is_sequence(&block(&format!("{n} X1")), 50), "{n}");
    }
    for n in ["N5", "N500", "N50.1", "N-50", "N0.5"] {
        assert!(!is_sequence(&block(&format!("{n} X1")), 50), "{n}");
    }
    assert!(!is_sequence(&block("X1"), 50));
}
