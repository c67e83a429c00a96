//! Spindle speed (docs/INTERPRETATION.md, "Spindle speed: G50 S, G96, G97"; the G83/G84
//! clarification "S and G98/G99") and G163 ("Table 30 and G163") on the whole expander: the S
//! word's values, G96.SMAX in the check order, G96.RAPID under both readings, the rpm G84 taps
//! with, and G163 under each dialect.
extern crate std;

use crate::tests::{expand, moves};
use cycle_vocab::readings::G96Rapid;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, MoveKind, Readings, Rule};

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

fn allow() -> Config {
    Config { readings: Readings { g96_rapid: G96Rapid::Allow, ..Readings::default() }, ..Config::default() }
}

/// G50.SMAX: G50 S is the maximum, an integer 1 … 99 999; every S is an integer.
#[test]
fn s_values() {
    assert_eq!(alarm_of("G50 S1\nG50 S99999\nG50 X1 Z1 S1500\n"), None);
    assert_eq!(alarm_of("G50 S0"), al(AlarmCode::OutOfRange, b'S', Rule::G50Smax, 1));
    assert_eq!(alarm_of("G50 S100000"), al(AlarmCode::OutOfRange, b'S', Rule::G50Smax, 1));
    assert_eq!(alarm_of("G50 S-5"), al(AlarmCode::OutOfRange, b'S', Rule::G50Smax, 1));
    assert_eq!(alarm_of("G50 S1500."), al(AlarmCode::NotInteger, b'S', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G0 X1 S12.5"), al(AlarmCode::NotInteger, b'S', Rule::ComRanges, 1));
    // Under G97 and G96 an S has no range of its own.
    assert_eq!(alarm_of("S0\nG50 S10\nG96 S999999\n"), None);
    // Values alphabetically: S before X.
    assert_eq!(alarm_of("G50 S0 X1000000"), al(AlarmCode::OutOfRange, b'S', Rule::G50Smax, 1));
    // Under nc201 the section does not apply: S takes any number (PRJ.LEX).
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(expand("G0 X1 S12.5
G97 S-3.5
", nc201).alarm, None);
    // Under fanuc as under gsk.
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(expand("G0 X1 S12.5", fanuc).alarm, al(AlarmCode::NotInteger, b'S', Rule::ComRanges, 1));
}

/// G96.SMAX: a block that writes G96 needs a G50 S of an earlier block — at the end of check
/// step 4: after the block's own missing words, before its step 5 and any motion.
#[test]
fn g96_needs_an_earlier_maximum() {
    let smax = |line| al(AlarmCode::MissingWord, b'S', Rule::G96Smax, line);
    assert_eq!(alarm_of("G96 S200"), smax(1));
    assert_eq!(alarm_of("G0 X1\nG96"), smax(2));
    assert_eq!(alarm_of("G50 S1500\nG96 S200\nG97\nG96\n"), None);
    // The maximum must come from an earlier block: in the G96 block it is too late.
    assert_eq!(alarm_of("G50 G96 S1500"), smax(1));
    // One S per block.
    assert_eq!(alarm_of("G50 S1500 G96 S200"), al(AlarmCode::DuplicateWord, b'S', Rule::PrjWord, 1));
    // A G97 S, or an S under G96, is no maximum.
    assert_eq!(alarm_of("G97 S1500\nG96 S200"), smax(2));
    // After the block's own missing words …
    assert_eq!(alarm_of("G96 S100 G1 X10"), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 1));
    assert_eq!(alarm_of("G96 G71 P10 F1"), al(AlarmCode::MissingWord, b'Q', Rule::CntPq, 1));
    assert_eq!(alarm_of("G96 G73 P1 Q2 I1 K1 F1"), al(AlarmCode::MissingWord, b'D', Rule::G73Format, 1));
    assert_eq!(alarm_of("G96 G76 X1 Z-5 F1 P1"), al(AlarmCode::MissingWord, b'Q', Rule::G76Required, 1));
    // … before the block's step 5: no search for a contour, no cycle check, no motion.
    assert_eq!(alarm_of("G96 G71 P10 Q20 F1"), smax(1));
    assert_eq!(alarm_of("G0 X50 Z5\nG96 G70 P10 Q20 F1"), smax(2));
    assert_eq!(alarm_of("G96 G83 F1"), smax(1));
    assert_eq!(alarm_of("G96 G84 Z-5 F1"), smax(1));
    assert_eq!(alarm_of("G96 G74 X0 Z-5 P1 Q1 F1"), smax(1));
    assert_eq!(alarm_of("G96 G90 X0 Z0 F1"), smax(1));
    assert_eq!(alarm_of("G96 G92 X0 Z0 F1"), smax(1));
    assert_eq!(alarm_of("G96 G34 Z-5 F1 K0"), smax(1));
    assert_eq!(alarm_of("G96 G2 X0 Z0 R5 F1"), smax(1));
    let t = expand("G0 X10\nG96 G1 X20 F1", Config::default());
    assert_eq!((t.alarm, moves(&t).len()), (smax(2), 1));
    // The first blocks of G71/G73/G74 and G50 have no step 5: the alarm all the same.
    assert_eq!(alarm_of("G96 G71 U1 R1"), smax(1));
    assert_eq!(alarm_of("G96 G50 X1"), smax(1));
}

/// G96.RAPID (declared reading `g96.rapid`): under `refuse` (the letter) a G00 block with axis
/// words while G96 is in force — the G96 block itself included — is UNSUPPORTED on G; under
/// `allow` it runs. Cycles' rapids are not G00 blocks.
#[test]
fn rapids_under_g96() {
    let refused = |line| al(AlarmCode::Unsupported, b'G', Rule::G96Rapid, line);
    let head = "G50 S2000\nG0 X40 Z2\n";
    let a = |body: &str| alarm_of(&std::format!("{head}{body}"));
    assert_eq!(a("G96 S200\nG0 X10\n"), refused(4));
    assert_eq!(a("G96 S200 G0 X10\n"), refused(3));
    // Modal G00 with axis words.
    assert_eq!(a("G96 S200\nZ5\n"), refused(4));
    // No axis words: no rapid.
    assert_eq!(a("G96 S200\nG0\nG1 X10 F1\n"), None);
    // G97 ends it, also in the G00 block itself.
    assert_eq!(a("G96 S200\nG97 G0 X10\nG96\nG1 X20 F1\n"), None);
    // The cycles' rapids (G90, G71) and G01 are not refused.
    assert_eq!(a("G96 S200\nG90 X30 Z-10 F0.3\nG1 X40 F1\n"), None);
    // Before the block moves; the block's other checks first (here G96.SMAX).
    let t = expand(&std::format!("{head}G96 S200\nG1 X30 F1\nG0 X50\n"), Config::default());
    assert_eq!((t.alarm, moves(&t).len()), (refused(5), 2));
    assert_eq!(alarm_of("G96 G0 X10"), al(AlarmCode::MissingWord, b'S', Rule::G96Smax, 1));
    // `allow`: the rapid runs.
    let t = expand(&std::format!("{head}G96 S200\nG0 X10\n"), allow());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t).last(), Some(&Move::rapid(10_000, 2_000, Rule::PrjModal)));
}

/// G96.SPEED, G84.FORMAT: G84 under G98 taps with the rpm in force — the last S written under
/// G97, never a G50 S (the maximum) nor a G96 S (a surface speed); under G96 it is UNSUPPORTED
/// on G.
#[test]
fn g84_rpm() {
    let missing = |line| al(AlarmCode::MissingWord, b'S', Rule::G84Format, line);
    // The seed's G84 after a G50 S1500: no rpm.
    assert_eq!(alarm_of("G50 X60 Z40 S1500\nG00 X0 Z0\nG98 M29\nG84 Z-21 R2 F60\n"), missing(4));
    // G97 S60: the lead F / 60 = 1 mm.
    let t = expand("G50 X60 Z40 S1500\nG00 X0 Z0\nG97 S60\nG98 M29\nG84 Z-21 R2 F60\n", Config::default());
    assert_eq!(t.alarm, None);
    let taps: std::vec::Vec<Move> = moves(&t).into_iter().filter(|m| m.kind == MoveKind::Thread).collect();
    assert_eq!(taps.len(), 2);
    assert!(taps.iter().all(|m| m.feed == 10_000));
    // A G96 S does not replace the rpm; G97 without S brings the last rpm back.
    let t = expand("G50 S1500\nG97 S60\nG96 S200\nG97\nG98 M29 G84 Z-5 F30\n", Config::default());
    assert_eq!(t.alarm, None);
    assert!(moves(&t).iter().filter(|m| m.kind == MoveKind::Thread).all(|m| m.feed == 5_000));
    assert_eq!(alarm_of("G50 S1500\nG96 S200\nG97\nG98 M29 G84 Z-5 F30\n"), missing(4));
    // An S in the G84 block itself, under G97, is the rpm.
    assert_eq!(alarm_of("G98 M29 G84 Z-5 F30 S30\n"), None);
    // Under G96 with G98: UNSUPPORTED on G; with G99 the spindle mode does not matter.
    let g96 = "G50 S1500\nG97 S60\nG96 S200\n";
    assert_eq!(
        alarm_of(&std::format!("{g96}G98 M29\nG84 Z-5 F60\n")),
        al(AlarmCode::Unsupported, b'G', Rule::G84Format, 5)
    );
    assert_eq!(alarm_of(&std::format!("{g96}G99 M29\nG84 Z-5 F1\n")), None);
    // M29 first (the same alarm), then the speed, then its range.
    assert_eq!(alarm_of("S0\nG98 M29 G84 Z-5 F60\n"), al(AlarmCode::OutOfRange, b'S', Rule::G84Format, 2));
}

/// G163: under nc201 UNSUPPORTED CODE with its own rule; elsewhere an unknown code.
#[test]
fn g163() {
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    let t = expand("G0 X1\nG163 Z-5 F1 X10 M5 I1\n", nc201);
    assert_eq!(t.alarm, al(AlarmCode::UnsupportedCode, b'G', Rule::G163, 2));
    assert_eq!(moves(&t).len(), 1);
    assert_eq!(alarm_of("G163 Z-5 F1"), al(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, 1));
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(expand("G163", fanuc).alarm, al(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, 1));
    // G163.0 and the like stay PRJ.SUPPORTED (a decimal part).
    assert_eq!(expand("G163.5", nc201).alarm, al(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, 1));
}
