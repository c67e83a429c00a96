//! Spindle speed (G50.SMAX, G96.SPEED, G96.SMAX, G96.RAPID, G84.FORMAT "S and G98/G99") and
//! G163 under `nc201`, against docs/INTERPRETATION.md, "Spindle speed: G50 S, G96, G97", "Table 30
//! and G163", and `003_…` lines 6–13.

use crate::expand;
use crate::tests::util::{alarm_of, alarm_with, run, run_with, Expect};
use cycle_vocab::readings::G96Rapid;
use cycle_vocab::{AlarmCode::*, Config, Dialect, MoveKind, Rule};

fn allow() -> Config {
    let mut c = Config::default();
    c.readings.g96_rapid = G96Rapid::Allow;
    c
}

/// The lead of the first thread move (G84's tap) of a clean run.
fn tap_lead(src: &str) -> i64 {
    run(src).moves().find(|m| m.kind == MoveKind::Thread).map(|m| m.feed).expect("a tap")
}

/// G96.SMAX (`003_…` line 11, "在恒线速度指令前必须限制最高转速"): G96 needs a maximum set by G50 S in an
/// **earlier** block; else `MISSING WORD S` at the G96 block.
#[test]
fn g96_needs_an_earlier_maximum() {
    assert_eq!(alarm_of("G0 X10\nG96 S200\n"), (MissingWord, Some('S'), Rule::G96Smax, 2));
    assert_eq!(alarm_of("G96\n"), (MissingWord, Some('S'), Rule::G96Smax, 1));
    // The same block's G50 S is no earlier block (its S is the maximum, not the surface speed).
    assert_eq!(alarm_of("G50 S1500 G96\n"), (MissingWord, Some('S'), Rule::G96Smax, 1));
    // G50 without S sets no maximum.
    assert_eq!(alarm_of("G50 X10\nG96 S200\n"), (MissingWord, Some('S'), Rule::G96Smax, 2));
    run("G50 S1500\nG96 S200\nG97 S800\nG96\n");
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(alarm_with("G96 S200\n", &fanuc), (MissingWord, Some('S'), Rule::G96Smax, 1));
}

/// G96.SMAX is check step 4, after the block's own missing words, before step 5 and any motion —
/// in a block of every kind (G00/G01, arcs, each cycle family).
#[test]
fn g96_smax_in_the_check_order() {
    let own_first: &[(&str, Expect)] = &[
        ("G96 G01 X10", (MissingWord, Some('F'), Rule::ComLead, 1)),
        ("G96 G02 X10 Z-5 F1", (MissingWord, Some('R'), Rule::ArcFormat, 1)),
        ("G96 G92 X10 Z-10", (MissingWord, Some('F'), Rule::ComLead, 1)),
        ("G96 G71 P10 F1", (MissingWord, Some('Q'), Rule::CntPq, 1)),
        ("G96 G76 X10 Z-10 F1 Q1", (MissingWord, Some('P'), Rule::G76Required, 1)),
        // A value (step 3) before it.
        ("G96 G01 X10 F0", (OutOfRange, Some('F'), Rule::ComRanges, 1)),
    ];
    for (block, expect) in own_first {
        assert_eq!(alarm_of(block), *expect, "{block}");
    }
    // Before the cycles' own checks (step 5): each of these would alarm there, or move.
    for block in [
        "G96 G00 X10",
        "G96 G01 X10 F1",
        "G96 G02 X10 Z-5 R20 F1",
        "G96 G32 Z-10 F1",
        "G96 G34 Z-10 F1 K0.1",
        "G96 G92 X10 Z-10 F1",
        "G96 G90 X10 Z-10 F1",
        "G96 G94 X10 Z-10 F1",
        "G96 G76 X10 Z-10 P1 Q0.1 F1",
        "G96 G78 X10 Z-10 P1 Q0.1 F1",
        "G96 G71 P10 Q20 F1",
        "G96 G72 P10 Q20 F1",
        "G96 G73 P10 Q20 F1",
        "G96 G70 P10 Q20 F1",
        "G96 G74 X0 Z-10 Q1 F1",
        "G96 G75 X0 Z0 P1 F1",
        "G96 G83 Z0 F1",
        "G96 M29 G84 Z0 F1",
        "G96 G50 X5",
        "G96 G74 R1",
    ] {
        let t = expand(format!("G0 X20 Z5\n{block}\n").as_bytes(), &Config::default());
        let a = t.alarm.unwrap_or_else(|| panic!("no alarm: {block}"));
        assert_eq!((a.code, a.word, a.rule, a.line), (MissingWord, Some(b'S'), Rule::G96Smax, 2), "{block}");
        assert_eq!(t.events.len(), 1, "{block}: nothing of the block is emitted");
    }
}

/// G50.SMAX: G50 S is the maximum, an integer 1 … 99 999; every S is an integer (`NOT INTEGER`,
/// COM.RANGES), checked in its alphabetical place among the block's values.
#[test]
fn s_values() {
    let cases: &[(&str, Expect)] = &[
        ("G50 S0", (OutOfRange, Some('S'), Rule::G50Smax, 1)),
        ("G50 S100000", (OutOfRange, Some('S'), Rule::G50Smax, 1)),
        ("G50 S-1500", (OutOfRange, Some('S'), Rule::G50Smax, 1)),
        ("G50 S1500.", (NotInteger, Some('S'), Rule::ComRanges, 1)),
        ("S1.5", (NotInteger, Some('S'), Rule::ComRanges, 1)),
        ("G97 S800.0", (NotInteger, Some('S'), Rule::ComRanges, 1)),
        ("G50 S2000\nG96 S1.5", (NotInteger, Some('S'), Rule::ComRanges, 2)),
        // Alphabetical: F before S, S before X.
        ("G1 F0 S1.5", (OutOfRange, Some('F'), Rule::ComRanges, 1)),
        ("G50 S0 X1.0001", (OutOfRange, Some('S'), Rule::G50Smax, 1)),
    ];
    for (src, expect) in cases {
        assert_eq!(alarm_of(src), *expect, "{src}");
    }
    run("G50 S1\nG50 S99999 X0\nS0\nS-5\nM3 S999999999999999999\n");
    // Under `nc201` the section does not apply: S takes any number there.
    let nc = Config { dialect: Dialect::Nc201, ..Config::default() };
    run_with("S1.5 G0 X1\n", &nc);
}

/// G96.RAPID, the letter (`003_…` lines 12–13): a program block that moves at rapid while G96 is in
/// force — G00 written or modal, the G96 block itself included — is `UNSUPPORTED` on G.
#[test]
fn rapid_under_g96_is_refused() {
    let max = "G50 S2000\n";
    let cases: &[(&str, Expect)] = &[
        ("G96 S200\nG0 X10", (Unsupported, Some('G'), Rule::G96Rapid, 3)),
        ("G96 S200 G0 X10", (Unsupported, Some('G'), Rule::G96Rapid, 2)),
        ("G0 X5\nG96 S200\nZ-1", (Unsupported, Some('G'), Rule::G96Rapid, 4)),
        ("G96 S200\nG97\nG96\nG0 U1", (Unsupported, Some('G'), Rule::G96Rapid, 5)),
    ];
    for (src, expect) in cases {
        let src = format!("{max}{src}\n");
        assert_eq!(alarm_of(&src), *expect, "{src}");
        assert_eq!(expand(src.as_bytes(), &allow()).alarm, None, "{src} under g96.rapid=allow");
    }
    // Before it moves.
    assert_eq!(expand(b"G50 S2000\nG96 S200 G0 X10\n", &Config::default()).moves().count(), 0);
    // A G00 block without axis words moves nothing; G97 in the block ends G96 there.
    run(&format!("{max}G96 S200 G0\nG97 G0 X10\n"));
    // Rapids a cycle makes, and a contour's G00 run by a cycle, are no G00 blocks of the program.
    let t = run(&format!("{max}G96 S200\nG1 X50 Z2 F1\nG90 X40 Z-40 F0.3\nG92 X44 Z-20 F2\n"));
    assert!(t.moves().any(|m| m.kind == MoveKind::Rapid));
    run(&format!("{max}G1 X41 Z1 F1\nG96 S180\nG71 U2 R1\nG71 P10 Q30 F0.2\nN10 G0 X0\nN20 G1 Z-10\nN30 X40\nG97\n"));
}

/// G84.FORMAT, "S and G98/G99": under G98 the lead is F / (the rpm in force, the last S under
/// G97) — never a G50 S (the seed's G50 S1500) nor a G96 S; under G96 with G98 `UNSUPPORTED` on
/// G; under G99 the lead is F whatever the spindle mode.
#[test]
fn g84_takes_the_rpm_in_force() {
    let no_rpm = "G50 X60 Z40 S1500\nG00 X0 Z0\nG98 M29\nG84 Z-21 R2 F60\n";
    assert_eq!(alarm_of(no_rpm), (MissingWord, Some('S'), Rule::G84Format, 4));
    // `G97 S60`: F60 / 60 rpm = 1 mm (10 000 lead counts).
    assert_eq!(tap_lead("G50 X60 Z40 S1500\nG97 S60\nG00 X0 Z0\nG98 M29\nG84 Z-21 R2 F60\n"), 10_000);
    // A later G50 S does not change the rpm; G97 without S keeps the last rpm under G97; a G96 S
    // is no rpm.
    assert_eq!(tap_lead("G97 S60\nG50 S30\nG98 M29\nG84 Z-1 F60\n"), 10_000);
    assert_eq!(tap_lead("G97 S120\nG50 S3000\nG96 S60\nG1 X1 F1\nG97\nG98 M29\nG84 Z-1 F60\n"), 5_000);
    assert_eq!(alarm_of("G50 S3000\nG96 S60\nG97\nG98 M29\nG84 Z-1 F60\n"), (MissingWord, Some('S'), Rule::G84Format, 5));
    // Under G96 with G98: refused, after the M29 check (both UNSUPPORTED on G, G84.FORMAT).
    let css = "G50 S2000\nG97 S60\nG96 S100\nG98 M29\nG84 Z-21 R2 F60\n";
    assert_eq!(alarm_of(css), (Unsupported, Some('G'), Rule::G84Format, 5));
    assert_eq!(alarm_of("G50 S2000\nG96 S100\nG98\nG84 Z-21 R2 F60\n"), (Unsupported, Some('G'), Rule::G84Format, 4));
    // Under G99 the spindle mode does not matter: the lead is F.
    assert_eq!(tap_lead("G50 S2000\nG96 S100\nG99 M29\nG84 Z-5 F1.25\n"), 12_500);
    // The rpm's range is G84's, on the G84 line.
    assert_eq!(alarm_of("S-60\nG98 M29\nG84 Z-1 F60\n"), (OutOfRange, Some('S'), Rule::G84Format, 3));
}

/// G163 (M004, `004_…` lines 79–89): under `nc201` `UNSUPPORTED CODE` on G, rule G163 (the seed
/// gives no table or motion); elsewhere an unknown code (PRJ.SUPPORTED).
#[test]
fn g163() {
    let nc = Config { dialect: Dialect::Nc201, ..Config::default() };
    assert_eq!(alarm_with("G163 Z-10 F1 X20 M5 I1\n", &nc), (UnsupportedCode, Some('G'), Rule::G163, 1));
    assert_eq!(alarm_with("G0 X1\nG163\n", &nc), (UnsupportedCode, Some('G'), Rule::G163, 2));
    assert_eq!(alarm_of("G163 Z-10 F1\n"), (UnsupportedCode, Some('G'), Rule::PrjSupported, 1));
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(alarm_with("G163\n", &fanuc), (UnsupportedCode, Some('G'), Rule::PrjSupported, 1));
}

/// G96.SPEED, G50.SMAX: what an S word means in the block's state after its G codes — the
/// maximum with G50, the surface speed under G96, else the rpm; G96 / G97 modal, in the order
/// written; G97 without S keeps the last rpm.
#[test]
fn what_s_means() {
    use crate::spindle::Spindle;
    let mut sp = Spindle::default();
    let mut apply = |text: &str, s: Option<i64>| {
        let b = crate::lex::blocks(text.as_bytes()).next().and_then(Result::ok).expect("a block");
        sp.take(&b, s);
        sp.clone()
    };
    let start = Spindle::default();
    assert!(!start.constant_surface && start.rpm.is_none() && start.surface.is_none() && start.max.is_none());
    assert_eq!(apply("S500", Some(500)).rpm, Some(500));
    let after = apply("G50 S1500", Some(1_500));
    assert_eq!((after.max, after.rpm), (Some(1_500), Some(500)));
    let after = apply("G96 S180", Some(180));
    assert_eq!((after.constant_surface, after.surface, after.rpm), (true, Some(180), Some(500)));
    let after = apply("G97", None);
    assert_eq!((after.constant_surface, after.rpm), (false, Some(500)));
    let after = apply("G96 G97 S800", Some(800));
    assert_eq!((after.constant_surface, after.rpm, after.surface), (false, Some(800), Some(180)));
    let after = apply("G97 G96 S90", Some(90));
    assert_eq!((after.constant_surface, after.surface, after.rpm), (true, Some(90), Some(800)));
    // G50 while G96 is in force: its S is the maximum, not a surface speed.
    let after = apply("G50 X0 S2000", Some(2_000));
    assert_eq!((after.max, after.surface), (Some(2_000), Some(90)));
}
