//! The program words of the stock-removal cycles (M003): sequence numbers, G50, G96/G98 and the
//! nose-radius codes, checked against docs/INTERPRETATION.md, "Program words".

use crate::tests::util::{alarm_with as alarm_of};
use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{AlarmCode, Config, Dialect, MoveKind, Params, Rule};

fn run(src: &str) -> Trace {
    expand(src.as_bytes(), &Config::default())
}

fn moves(t: &Trace) -> Vec<(MoveKind, i64, i64)> {
    assert_eq!(t.alarm, None, "{}", t.to_gcode());
    t.moves().map(|m| (m.kind, m.x, m.z)).collect()
}

/// G50.COORD: the seed's `N010 G50 X150 Z100` declares the position without an event; the
/// next move starts there; an omitted axis keeps its coordinate; N takes any number.
#[test]
fn g50_sets_the_position_without_an_event() {
    let t = run("N010 G50 X150 Z100\nN020 G00 X41 Z0\n");
    assert_eq!(moves(&t), vec![(MoveKind::Rapid, 41_000, 0)]);
    let t = run("G0 X10 Z10\nG50 X100\nG0 Z5\nN-5.25 G0 X1\n");
    assert_eq!(moves(&t), vec![(MoveKind::Rapid, 10_000, 10_000), (MoveKind::Rapid, 100_000, 5_000), (MoveKind::Rapid, 1_000, 5_000)]);
    // G50 S (spindle limit) alone moves nothing and changes nothing.
    assert_eq!(moves(&run("G50 S1500\nG0 X1\n")), vec![(MoveKind::Rapid, 1_000, 0)]);
}

/// G50 is one-shot: the motion mode stays (a G01 mode repeats after it) and a G90 run goes on.
#[test]
fn g50_is_one_shot() {
    let t = run("G1 X1 F1\nG50 X0 Z0\nZ-1\n");
    assert_eq!(moves(&t), vec![(MoveKind::Feed, 1_000, 0), (MoveKind::Feed, 0, -1_000)]);
    let a = run("G0 X50 Z2\nG90 X40 Z-40 F0.3\nG50 X50 Z2\nX35\n");
    let b = run("G0 X50 Z2\nG90 X40 Z-40 F0.3\nX35\n");
    assert_eq!(a, b);
}

/// G50.COORD words: X Z (S), absolute only; U, W, any other word refused (PRJ.WORD); |v| ≤ N;
/// G50 with a motion code is two motion/cycle codes.
#[test]
fn g50_words() {
    let c = Config::default();
    assert_eq!(alarm_of("G50 U1", &c), (AlarmCode::WordNotAllowed, Some('U'), Rule::PrjWord, 1));
    assert_eq!(alarm_of("G50 X1 W1", &c), (AlarmCode::WordNotAllowed, Some('W'), Rule::PrjWord, 1));
    assert_eq!(alarm_of("G50 F1", &c), (AlarmCode::WordNotAllowed, Some('F'), Rule::PrjWord, 1));
    assert_eq!(alarm_of("G50 X1000000", &c), (AlarmCode::OutOfRange, Some('X'), Rule::ComRanges, 1));
    assert_eq!(alarm_of("G0 G50 X1", &c), (AlarmCode::Conflict, Some('G'), Rule::PrjWord, 1));
    assert_eq!(run("G50 X999999.999 Z-999999.999 S3000 T1 M3 N1 O1").alarm, None);
}

/// G50.SMAX: G96, G97, G98, G99 are no-motion codes; the feed is kept as written. (G96.SMAX:
/// the maximum, G50 S, comes first.)
#[test]
fn spindle_and_feed_modes_change_no_geometry() {
    let t = run("G50 S2000\nG96 S200\nG98 G1 X1 F100\nG99 G97 S500\nG1 Z-1\n");
    assert_eq!(moves(&t), vec![(MoveKind::Feed, 1_000, 0), (MoveKind::Feed, 1_000, -1_000)]);
    assert!(t.moves().all(|m| m.feed == 1_000_000));
}

/// PRJ.DIALECT: under `nc201` the new codes are `UNSUPPORTED CODE`; G40 stays legal there.
#[test]
fn new_codes_under_nc201() {
    let nc = Config { dialect: Dialect::Nc201, ..Config::default() };
    for g in ["G02 X1 Z1 R1 F1", "G3 X1 Z1 R1 F1", "G41", "G42", "G50 X1", "G96 S1", "G98"] {
        assert_eq!(alarm_of(g, &nc), (AlarmCode::UnsupportedCode, Some('G'), Rule::PrjDialect, 1), "{g}");
    }
    assert_eq!(expand(b"G40 G0 X1\n", &nc).alarm, None);
}

/// TNRC.*: the register's checks, in its order, each on its line; paths are unchanged
/// (TNRC.CODES: G41, G42, G40 are modal no-motion codes that change no path at radius 0;
/// TNRC.TIP: no tip codes, no offset geometry).
#[test]
fn nose_radius_codes() {
    let c = Config::default();
    let with = moves(&run("G41 G1 X10 Z-5 F0.2\nZ-10\nG40 X20\n"));
    let without = moves(&run("G1 X10 Z-5 F0.2\nZ-10\nX20\n"));
    assert_eq!(with, without);
    // TNRC.NOARC: a compensation code in a block that writes G02/G03.
    assert_eq!(alarm_of("G1 F1\nG41 G02 X1 Z-1 R1", &c), (AlarmCode::Conflict, Some('G'), Rule::TnrcNoarc, 2));
    assert_eq!(alarm_of("G40 G3 X1 Z-1 R1 F1", &c), (AlarmCode::Conflict, Some('G'), Rule::TnrcNoarc, 1));
    // NOARC is checked after the two-motion-codes conflict; an arc mode only modal is no arc written.
    assert_eq!(alarm_of("G40 G1 G2 X1", &c), (AlarmCode::Conflict, Some('G'), Rule::PrjWord, 1));
    assert_eq!(run("G02 F1\nG41\nG40").alarm, None);
    // TNRC.SWITCH: a side change without G40, and a tool call with compensation on.
    assert_eq!(alarm_of("G41\nG42", &c), (AlarmCode::WordNotAllowed, Some('G'), Rule::TnrcSwitch, 2));
    assert_eq!(alarm_of("G42\nG41 X1", &c), (AlarmCode::WordNotAllowed, Some('G'), Rule::TnrcSwitch, 2));
    assert_eq!(run("G41\nG41\nG40\nG42\nG40 T0202\n").alarm, None);
    assert_eq!(alarm_of("G42\nT0101", &c), (AlarmCode::WordNotAllowed, Some('T'), Rule::TnrcSwitch, 2));
    assert_eq!(alarm_of("G41 T0101", &c), (AlarmCode::WordNotAllowed, Some('T'), Rule::TnrcSwitch, 1));
    // SWITCH is checked before the pair conflicts (X with U).
    assert_eq!(alarm_of("G41\nG42 X1 U1", &c), (AlarmCode::WordNotAllowed, Some('G'), Rule::TnrcSwitch, 2));
    // TNRC.RADIUS: only a radius of 0 is modelled; G40 is legal with any radius.
    let r = Config { params: Params { nose_radius: Some(400), ..Params::default() }, ..Config::default() };
    assert_eq!(alarm_of("G0 X1\nG42 X2", &r), (AlarmCode::Unsupported, Some('G'), Rule::TnrcRadius, 2));
    assert_eq!(expand(b"G40 G0 X1\n", &r).alarm, None);
}
