//! The program words of the contour cycles (M003; docs/INTERPRETATION.md, "Contours, arcs and
//! the stock-removal cycles", "Program words") on the whole expander: sequence numbers, G50,
//! G96/G98, the nose-radius codes and their alarms, and the new codes under nc201.
extern crate std;

use crate::lex::Blocks;
use crate::tests::{expand, moves};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Move, Params, Rule};

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

/// "Sequence numbers": a block is N(p) when its N word's exact value equals p.
#[test]
fn sequence_numbers() {
    let is = |src: &str, p: u64| {
        let mut b = crate::lex::Block::new();
        Blocks::new(src.as_bytes()).read(&mut b).unwrap();
        b.is_sequence(p)
    };
    for src in ["N50", "N050", "N50.0", "N+50", "N 50.000", "n50 G0", "N0000000050.00000000"] {
        assert!(is(src, 50), "{src}");
    }
    for src in ["N-50", "N50.5", "N5", "N500", "G0 X1", "N.50", "N49.99999999999999"] {
        assert!(!is(src, 50), "{src}");
    }
    assert!(is("N99999", 99_999));
    assert!(is("N1.", 1));
    // A value 10^decimals · p beyond 64 bits is never p.
    assert!(!is("N0.000000000000000001", 1));
}

/// G50.COORD: X and Z make the current position, no event; an omitted axis stays; the next
/// move is in the new coordinates. U, W and other words are not allowed; S is.
#[test]
fn g50_sets_the_position() {
    let c = Config::default();
    let t = expand("G50 X150 Z100\nG0 W-10\nG50 Z0\nG1 U-2 F1\nG50 S1500\n", c);
    assert_eq!(t.alarm, None);
    assert_eq!(
        moves(&t),
        [Move::rapid(150_000, 90_000, Rule::PrjModal), Move::feed(148_000, 0, 10_000, Rule::PrjModal)]
    );
    // The motion mode goes on after G50 (G01 here).
    let t = expand("G1 X1 F1\nG50 X0 Z0\nZ-5\n", c);
    assert_eq!(moves(&t)[1], Move::feed(0, -5_000, 10_000, Rule::PrjModal));
    // A G90 run goes on after G50.
    let t = expand("G0 X50 Z2\nG90 X40 Z-10 F1\nG50 X60 Z10\nX30\n", c);
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t).len(), 1 + 4 + 4);
    assert_eq!(alarm_of("G50 U1"), al(AlarmCode::WordNotAllowed, b'U', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G50 W1"), al(AlarmCode::WordNotAllowed, b'W', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G50 X1 F1"), al(AlarmCode::WordNotAllowed, b'F', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G50 X1 U1"), al(AlarmCode::Conflict, b'U', Rule::ComAbsInc, 1));
    assert_eq!(alarm_of("G50 X1000000"), al(AlarmCode::OutOfRange, b'X', Rule::ComRanges, 1));
    // G50 is one-shot: with a motion code in the block it is a CONFLICT on G.
    assert_eq!(alarm_of("G0 G50 X1"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 1));
    assert_eq!(alarm_of("N010 G50 X150 Z100 S2000 T0101 M3 O1"), None);
}

/// G50.SMAX: G96, G97, G98, G99 change no geometry; the feed is kept as written.
#[test]
fn spindle_and_feed_modes() {
    let t = expand("G50 S2000\nG96 S200\nG98 G1 X1 F100\nG99 G97 Z-1\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(
        moves(&t),
        [Move::feed(1_000, 0, 1_000_000, Rule::PrjModal), Move::feed(1_000, -1_000, 1_000_000, Rule::PrjModal)]
    );
}

/// TNRC.*: G41/G42/G40 change no path (TNRC.TIP: no tip codes, no offset geometry — the moves
/// are those of the program without them); the alarms in the register's order.
#[test]
fn nose_radius_codes() {
    let c = Config::default();
    let t = expand("G42 G0 X10 Z1\nG1 Z-5 F1\nG40 X20\nT0202\n", c);
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t).len(), 3);
    assert_eq!(moves(&t), moves(&expand("G0 X10 Z1\nG1 Z-5 F1\nX20\nT0202\n", c)));
    // G41 while G41 is in force changes nothing; G40 then G42 is legal.
    assert_eq!(alarm_of("G41\nG41 X1\nG40\nG42\nG40 T0101"), None);
    // TNRC.SWITCH: G41 ↔ G42 without G40, also within one block; a T while compensating.
    assert_eq!(alarm_of("G41\nG42"), al(AlarmCode::WordNotAllowed, b'G', Rule::TnrcSwitch, 2));
    assert_eq!(alarm_of("G42\nX1\nG41 X2"), al(AlarmCode::WordNotAllowed, b'G', Rule::TnrcSwitch, 3));
    assert_eq!(alarm_of("G41 G42"), al(AlarmCode::WordNotAllowed, b'G', Rule::TnrcSwitch, 1));
    assert_eq!(alarm_of("G41 G40 G42"), None);
    assert_eq!(alarm_of("G41\nT0202"), al(AlarmCode::WordNotAllowed, b'T', Rule::TnrcSwitch, 2));
    assert_eq!(alarm_of("G42 T0202"), al(AlarmCode::WordNotAllowed, b'T', Rule::TnrcSwitch, 1));
    assert_eq!(alarm_of("G41\nG40 T0202"), None);
    // The T check is made in every block kind (before the X/U conflict).
    assert_eq!(alarm_of("G41\nG0 X1 U1 T1"), al(AlarmCode::WordNotAllowed, b'T', Rule::TnrcSwitch, 2));
    // TNRC.RADIUS: G41/G42 with a nose radius; G40 stays legal.
    let r = Config { params: Params { nose_radius: Some(400), ..Params::default() }, ..c };
    assert_eq!(expand("G41", r).alarm, al(AlarmCode::Unsupported, b'G', Rule::TnrcRadius, 1));
    assert_eq!(expand("G0 X1\nG42 X2", r).alarm, al(AlarmCode::Unsupported, b'G', Rule::TnrcRadius, 2));
    assert_eq!(expand("G40 X1 T1", r).alarm, None);
    // Switch and T come before the radius (the register's order).
    assert_eq!(expand("G41 T1", r).alarm, al(AlarmCode::WordNotAllowed, b'T', Rule::TnrcSwitch, 1));
}

/// PRJ.DIALECT: under nc201 the codes of M003's contour cycles are UNSUPPORTED CODE; G40 stays.
#[test]
fn new_codes_under_nc201() {
    for g in ["G02", "G03", "G41", "G42", "G50", "G70", "G71", "G72", "G96", "G98"] {
        assert_eq!(
            expand(&std::format!("G0 X1\n{g}\n"), nc201()).alarm,
            al(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, 2),
            "{g}"
        );
    }
    assert_eq!(expand("G40 G0 X1", nc201()).alarm, None);
    // Under fanuc they are supported as under gsk.
    let f = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(expand("G50 X1 Z1 S2000\nG96 S100\nG98\nG41\nG40\n", f).alarm, None);
}

/// "The configuration is checked before the first block": 5132 outside 1…N, 5133 outside 0…N
/// (G71.PARAM), arc_tolerance outside 0…N (ARC.TOL), nose_radius outside 0…N (TNRC.RADIUS),
/// each OUT OF RANGE on line 0 without a word, in that order.
#[test]
fn contour_parameters_are_checked() {
    let with = |p: Params| expand("G0 X1", Config { params: p, ..Config::default() }).alarm;
    let out = |rule: Rule| Some(Alarm::new(AlarmCode::OutOfRange, None, rule, 0));
    let d = Params::default();
    assert_eq!(with(Params { p5132_rough_depth: Some(0), ..d }), out(Rule::G71Param));
    assert_eq!(with(Params { p5132_rough_depth: Some(1_000_000_000), ..d }), out(Rule::G71Param));
    assert_eq!(with(Params { p5133_rough_retract: Some(-1), ..d }), out(Rule::G71Param));
    assert_eq!(with(Params { p5133_rough_retract: Some(0), ..d }), None);
    assert_eq!(with(Params { arc_tolerance: Some(-1), ..d }), out(Rule::ArcTol));
    assert_eq!(with(Params { arc_tolerance: Some(1_000_000_000), ..d }), out(Rule::ArcTol));
    assert_eq!(with(Params { nose_radius: Some(-1), ..d }), out(Rule::TnrcRadius));
    assert_eq!(
        with(Params { p5133_rough_retract: Some(-1), arc_tolerance: Some(-1), nose_radius: Some(-1), ..d }),
        out(Rule::G71Param)
    );
    assert_eq!(with(Params { arc_tolerance: Some(-1), nose_radius: Some(-1), ..d }), out(Rule::ArcTol));
}
