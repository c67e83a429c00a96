//! The front end's rules on the whole expander (docs/INTERPRETATION.md, "Program text",
//! "Values (check step 3)", "Program and modal state"): the byte-order mark (PRJ.LEX), values
//! beyond any machine word under the word's own range rule, and the F/I conflict only in thread
//! blocks (COM.LEAD).
extern crate std;

use crate::tests::{expand, moves};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, Rule};

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

/// PRJ.LEX: a UTF-8 byte-order mark as the first three bytes is skipped (the line count is
/// unchanged); anywhere else its first byte 0xEF is a BAD CHARACTER at its line.
#[test]
fn byte_order_mark() {
    let c = Config::default();
    let t = expand("\u{feff}G0 X1 Z2\n", c);
    assert_eq!((t.alarm, moves(&t)), (None, std::vec![Move::rapid(1_000, 2_000, Rule::PrjModal)]));
    // Only the mark is skipped: the line after it is still line 2.
    assert_eq!(expand("\u{feff}\nG0 X1 #\n", c).alarm, al(AlarmCode::BadCharacter, b'#', Rule::PrjLex, 2));
    assert_eq!(expand("\u{feff}(a)%\n", c).alarm, None);
    // Elsewhere: after a block (its move stands before the alarm), a second mark, a blank
    // before the mark.
    let t = expand("G0 X1\n\u{feff}G0 X2\n", c);
    assert_eq!((moves(&t).len(), t.alarm), (1, al(AlarmCode::BadCharacter, 0xEF, Rule::PrjLex, 2)));
    assert_eq!(expand("\u{feff}\u{feff}G0", c).alarm, al(AlarmCode::BadCharacter, 0xEF, Rule::PrjLex, 1));
    assert_eq!(expand(" \u{feff}G0", c).alarm, al(AlarmCode::BadCharacter, 0xEF, Rule::PrjLex, 1));
    // An incomplete mark is no mark; inside a comment any byte is ignored.
    let t = crate::expander::Expander::new(b"\xef\xbbG0 X1", c).next();
    assert_eq!(t, Some(Err(Alarm::new(AlarmCode::BadCharacter, Some(0xEF), Rule::PrjLex, 1))));
    assert_eq!(expand("G0 X1 (\u{feff}) Z1\n", c).alarm, None);
}

/// "Values (check step 3)": a value beyond any machine word (its count at the word's grid
/// exceeds 64 bits) is OUT OF RANGE under the rule that owns the word's range — the cycle rule
/// where the register names one, else COM.RANGES — as a value just outside the range is.
#[test]
fn overflow_names_the_words_range_rule() {
    let big = "999999999999999999"; // 18 digits: read, but beyond 64 bits at 1 or more places
    let g = Config::default();
    let gsk = |src: &str| expand(&std::format!("G0 X30 Z5\n{src}\n"), g).alarm;
    let out = |w: u8, rule: Rule| al(AlarmCode::OutOfRange, w, rule, 2);
    assert_eq!(gsk(&std::format!("G0 X{big}")), out(b'X', Rule::ComRanges));
    assert_eq!(gsk(&std::format!("G1 Z1 F{big}")), out(b'F', Rule::ComRanges));
    assert_eq!(gsk(&std::format!("G92 X1 Z1 F1 J{big}")), out(b'J', Rule::ComRanges));
    assert_eq!(gsk(&std::format!("G34 W-1 F2 K{big}")), out(b'K', Rule::G34));
    // Precision is checked before the range: 18 digits with more decimals than the grid.
    assert_eq!(gsk("G34 W-1 F2 K-9999999999999.99995"), al(AlarmCode::Precision, b'K', Rule::ComUnits, 2));
    // The same rule as a value just outside the range.
    assert_eq!(gsk("G34 W-1 F2 K10000"), out(b'K', Rule::G34));
    assert_eq!(gsk(&std::format!("G33 W-1 F2 P{big}")), out(b'P', Rule::G33));
    let n = |src: &str| expand(&std::format!("G0 X30 Z5\n{src}\n"), nc201()).alarm;
    let g162 = "G162 X24 Z-20 F1.5";
    assert_eq!(n(&std::format!("{g162} H{big}")), out(b'H', Rule::G162H));
    assert_eq!(n(&std::format!("{g162} H500 I-{big}")), out(b'I', Rule::G162I));
    assert_eq!(n(&std::format!("{g162} H500 J{big}")), out(b'J', Rule::G162J));
    assert_eq!(n(&std::format!("{g162} H500 B{big}")), out(b'B', Rule::G162B));
    assert_eq!(n(&std::format!("{g162} H500 A{big}")), out(b'A', Rule::G162A));
    assert_eq!(n(&std::format!("{g162} H500 A-{big}")), out(b'A', Rule::G162A));
    assert_eq!(n(&std::format!("{g162} H500 P{big} Q1")), out(b'P', Rule::ComRanges));
    assert_eq!(n(&std::format!("{g162} H500 W{big}")), out(b'W', Rule::ComRanges));
    // Alphabetical order still decides which word is named first.
    assert_eq!(n(&std::format!("G162 X24 Z-20 F1.5 J{big} H{big}")), out(b'H', Rule::G162H));
}

/// COM.LEAD: F with I is a CONFLICT on I only in a thread block — G92, G76/G78 (either
/// block), G32/G33/G34, written or modal. Elsewhere I is not allowed in G00/G01 (WORD NOT
/// ALLOWED, PRJ.WORD); under nc201 there is no pair conflict at all.
#[test]
fn f_with_i_conflicts_only_in_thread_blocks() {
    let c = Config::default();
    let a = |src: &str| expand(src, c).alarm;
    let conflict = |line: u32| al(AlarmCode::Conflict, b'I', Rule::ComLead, line);
    let not_allowed = |line: u32| al(AlarmCode::WordNotAllowed, b'I', Rule::PrjWord, line);
    assert_eq!(a("G01 F1 I1"), not_allowed(1));
    assert_eq!(a("G0 X1 F1 I1"), not_allowed(1));
    assert_eq!(a("G1 X1 F1\nF1 I1"), not_allowed(2)); // modal G01, no axis words
    assert_eq!(a("F1 I1"), not_allowed(1)); // G00 from the start
    // Thread blocks, written.
    assert_eq!(a("G92 X1 Z1 F1 I1"), conflict(1));
    assert_eq!(a("G76 P011060 F1 I1"), conflict(1)); // before F and I are refused there
    assert_eq!(a("G76 X1 Z-1 P1 Q1 F1 I1"), conflict(1));
    assert_eq!(a("G78 P010060 F1 I1"), conflict(1));
    assert_eq!(a("G78 X1 Z-1 P1 Q1 F1 I1"), conflict(1));
    for code in ["G32", "G33", "G34"] {
        assert_eq!(a(&std::format!("{code} Z-1 F1 I1")), conflict(1), "{code}");
        // Modal: a later block in the mode, with or without axis words.
        let k = if code == "G34" { " K0.1" } else { "" };
        assert_eq!(a(&std::format!("G0 X5\n{code} Z-1 F1{k}\nF1 I1")), conflict(3), "{code}");
    }
    assert_eq!(a("G0 X50 Z5\nG92 X40 Z-30 F2\nX39 F1 I1"), conflict(3));
    // G76 between G92 blocks is a thread block of its own; the G92 run goes on after it.
    assert_eq!(a("G0 X50 Z5\nG92 X40 Z-30 F2\nG76 P011060 F1 I1"), conflict(3));
    // X/U and Z/W come first, as before.
    assert_eq!(a("G0 Z1 W1 F1 I1"), al(AlarmCode::Conflict, b'W', Rule::ComAbsInc, 1));
    // nc201: I is G162's pitch change; in G01 it is not allowed.
    let n = |src: &str| expand(src, nc201()).alarm;
    assert_eq!(n("G1 X1 F1 I1"), not_allowed(1));
    assert_eq!(n("G0 X50 Z5\nG162 X44 Z-30 H600 F1 I1\n"), None);
}
