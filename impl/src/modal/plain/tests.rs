//! The plain block's path against the general interpreter: each program is expanded as
//! written and with `T1` added to each plain block (T is a word every block accepts, without
//! a value rule, and with no nose-radius compensation in force does nothing — but it sends the
//! block through the general path). Events and alarms must be the same, through the iterator
//! and through `fill` in buffers of 1 to 5, 7 and 64 events.
extern crate std;

use crate::tests::{fanuc, inch};
use crate::Expander;
use cycle_vocab::readings::G96Rapid;
use cycle_vocab::{Alarm, AlarmCode, Config, Event, Move, Rule};
use std::string::String;
use std::vec::Vec;

/// The program with `T1` after every block that has no G code and only N U W X Z words (the
/// plain blocks; a `G` or any other letter leaves the block as written).
fn general(src: &str) -> String {
    let mut out = String::new();
    for line in src.lines() {
        let plain = !line.is_empty() && line.bytes().all(|c| b"NUWXZ0123456789.-+ ".contains(&c));
        out.push_str(line);
        if plain {
            out.push_str(" T1");
        }
        out.push('\n');
    }
    out
}

/// The stream through the iterator: the events, then the alarm if any.
fn iterate(src: &str, c: Config) -> (Vec<Event>, Option<Alarm>) {
    let mut events = Vec::new();
    for r in Expander::new(src.as_bytes(), c) {
        match r {
            Ok(e) => events.push(e),
            Err(a) => return (events, Some(a)),
        }
    }
    (events, None)
}

/// The stream through `fill` into buffers of `size` events.
fn filled(src: &str, c: Config, size: usize) -> (Vec<Event>, Option<Alarm>) {
    let mut ex = Expander::new(src.as_bytes(), c);
    let mut events = Vec::new();
    let mut buf = std::vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); size];
    loop {
        match ex.fill(&mut buf) {
            Ok(0) => return (events, None),
            Ok(n) => events.extend_from_slice(&buf[..n]),
            Err(a) => return (events, Some(a)),
        }
    }
}

/// `src` gives the same stream through the plain path as through the general one, and
/// through the iterator as through `fill`; returns it.
fn same(src: &str, c: Config) -> (Vec<Event>, Option<Alarm>) {
    let reference = iterate(&general(src), c);
    assert_eq!(iterate(src, c), reference, "iterator\n{src}");
    for size in [1, 2, 3, 4, 5, 7, 64] {
        assert_eq!(filled(src, c, size), reference, "fill by {size}\n{src}");
        assert_eq!(filled(&general(src), c, size), reference, "general, fill by {size}\n{src}");
    }
    reference
}

const PROGRAMS: &[&str] = &[
    // G32: moves along Z, by W, by U, a move to where it stands (PRJ.NOOP), an N-only block.
    "G0 X30 Z5\nG32 Z4 F2\nZ3\nW-1\nU-0.5 W-1\nZ1\nN7\nN8 X29 Z0\n",
    // X with U, Z with W (COM.ABSINC conflicts, on U and W).
    "G0 X30 Z5\nG32 Z4 F2\nZ3\nX30 U1\n",
    "G0 X30 Z5\nG32 Z4 F2\nZ3 W1\n",
    "G0 X30 Z5\nG32 Z4 F2\nX1 U2 Z3 W1\n",
    // Values: out of range, beyond the grid, the first alphabetically wins.
    "G0 X30 Z5\nG32 Z4 F2\nZ1000000\n",
    "G0 X30 Z5\nG32 Z4 F2\nZ3.0001\n",
    "G0 X30 Z5\nG32 Z4 F2\nX1000000 W0.0001\n",
    "G0 X30 Z5\nG32 Z4 F2\nU1000000 X1.00001\n",
    // G33 repeats (no P: start angle 0), G34 repeats (K missing).
    "G0 X30 Z5\nG33 Z4 F2 P90000\nZ3\n",
    "G0 X30 Z5\nG34 Z4 F2 K0.01\nZ3\n",
    // G00, G01 (a feed, then none: MISSING WORD F), the modal rapid.
    "G0 X30 Z5\nX20\nW-1\nG1 Z2 F0.2\nZ1\nU-1 W-1\n",
    "G1\nZ1\n",
    "X10 Z2\nZ1\n",
    // G90 / G94 / G92 runs continued by plain blocks, one with a conflict.
    "G0 X100 Z2\nG90 X95 Z-20 F0.2\nX90\nU-5\nZ-25\nW-1\nX80 U1\n",
    "G0 X100 Z2\nG94 X50 Z1 F0.2\nZ0\nW-1\nX40\nZ-1 W-1\n",
    "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX58\nU-0.5\nW-1\nN5\n",
    "G0 X65 Z5\nG92 X58.7 Z-28 F3\nX58 U-1\n",
    // G92 of two starts (L2): its plain passes are run from `Run`, not written whole.
    "G0 X65 Z5\nG92 X58.7 Z-28 F3 L2\nX58\nX57.5\n",
    // A plain block after G01 under G96 (a feed: allowed), then the rapid that is not.
    "G0 X30 Z5\nG50 S2000\nG96 S100\nG1 Z4 F0.2\nZ3\nG0 X40\nZ5\n",
    "G0 X30 Z5\nG50 S2000\nG96 S100 G1 Z4 F0.2\nG0\nZ3\n",
    // A block of N alone in a G90, a G92 and a G32 run: no axis word, so no pass and no move.
    "G0 X100 Z2\nG90 X95 Z-20 F0.2\nN5\nX90\n",
    "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nN6\nX58\n",
    "G0 X30 Z5\nG32 Z4 F2\nN7\nZ3\n",
    // G92 passes moved by W, then by Z with X, then by U, with no alarm on the way.
    "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX58\nW-20\nX57.5 Z-25\nU-1\n",
];

#[test]
fn plain_blocks_read_as_the_general_path() {
    let refuse = {
        let mut c = Config::default();
        c.readings.g96_rapid = G96Rapid::Refuse;
        c
    };
    let allow = {
        let mut c = Config::default();
        c.readings.g96_rapid = G96Rapid::Allow;
        c
    };
    for src in PROGRAMS {
        for c in [Config::default(), fanuc(), inch(), refuse, allow] {
            same(src, c);
        }
    }
}

/// What the comparison above rests on: the plain blocks do give moves and alarms (a check
/// that the programs are not all refused early).
#[test]
fn plain_blocks_give_moves_and_alarms() {
    let (events, alarm) = same(PROGRAMS[0], Config::default());
    assert_eq!(alarm, None);
    assert_eq!(events.len(), 6, "{events:?}");
    assert_eq!(events[2], Event::Move(Move::thread(30_000, 3_000, 20_000, 0, Rule::G32)));
    let conflict = same(PROGRAMS[1], Config::default()).1;
    assert_eq!(conflict, Some(Alarm::new(AlarmCode::Conflict, Some(b'U'), Rule::ComAbsInc, 4)));
    let range = same(PROGRAMS[4], Config::default()).1;
    assert_eq!(range, Some(Alarm::new(AlarmCode::OutOfRange, Some(b'Z'), Rule::ComRanges, 3)));
    let k = same(PROGRAMS[9], Config::default()).1;
    assert_eq!(k, Some(Alarm::new(AlarmCode::MissingWord, Some(b'K'), Rule::G34, 3)));
    let f = same(PROGRAMS[11], Config::default()).1;
    assert_eq!(f, Some(Alarm::new(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 2)));
    // The L2 G92 run: three passes, each cut at two start angles (0 and 180°).
    let (starts, alarm) = same(PROGRAMS[17], Config::default());
    assert_eq!(alarm, None);
    assert_eq!(starts.iter().filter(|e| matches!(e, Event::Pass(_))).count(), 3, "{starts:?}");
    let second = |e: &Event| matches!(e, Event::Move(m) if m.angle == 180_000);
    assert_eq!(starts.iter().filter(|e| second(e)).count(), 3 * 2, "{starts:?}");
}

/// G92 passes of X alone (a modal run's usual block, read by its own short path in
/// `Machine::plain_g92`), with N too: the same stream as the general path, and the alarms of
/// the X word and of the cycle's checks on the block's line.
#[test]
fn g92_passes_of_x_alone() {
    let alarm = |code: AlarmCode, word: u8, rule: Rule, line: u32| Some(Alarm::new(code, Some(word), rule, line));
    let cases: &[(&str, usize, Option<Alarm>)] = &[
        // Two passes (a header and five moves each), then X out of range (COM.RANGES).
        (
            "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nN6 X58\nX57.5\nX1000000\n",
            1 + 3 * 6,
            alarm(AlarmCode::OutOfRange, b'X', Rule::ComRanges, 5),
        ),
        // X finer than the grid (COM.UNITS).
        ("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX58.0001\n", 1 + 6, alarm(AlarmCode::Precision, b'X', Rule::ComUnits, 3)),
        // X on A.x, R = 0: C.x = A.x (COM.SIDE). No pull-out: four moves a pass.
        ("G0 X65 Z5\nG92 X58.7 Z-28 F3\nX58\nX65\n", 1 + 2 * 6, alarm(AlarmCode::Geometry, b'X', Rule::ComSide, 4)),
        // X above A.x (s = −1): the pull-out of J3 ends past A.x (G92.PATH, on J).
        ("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX70\n", 1 + 6, alarm(AlarmCode::Geometry, b'J', Rule::G92Path, 3)),
        // With J1: a pass on each side of A.x; X63's pull-out ends on A.x (63 + 2·1), so its
        // rapid back in X is no move (PRJ.NOOP).
        ("G0 X65 Z5\nG92 X58.7 Z-28 F3 J1 K1\nX68\nX63\n", 1 + 3 * 6 - 1, None),
        // A taper's R kept from the G92 block.
        ("G0 X65 Z5\nG92 X58.7 Z-28 R-1 F3 J3 K1\nX58\nX57\n", 1 + 3 * 6, None),
    ];
    for (src, events, expected) in cases {
        for c in [Config::default(), fanuc(), inch()] {
            same(src, c);
        }
        let (got, a) = same(src, Config::default());
        assert_eq!((got.len(), a), (*events, *expected), "{src}\n{got:?}");
    }
    // The short path is the one `fill`'s G92 loop takes: by each pass of X alone (N aside), by
    // no other block.
    let shorts = |src: &str| {
        let before = crate::probe::shorts();
        filled(src, Config::default(), 64);
        crate::probe::shorts() - before
    };
    let run = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nN6 X58\nX57.5\nZ-27\nX57 Z-28\nN9\nX56.5\n";
    assert_eq!(shorts(run), 3, "N6 X58, X57.5, X56.5");
    assert_eq!(shorts(&general(run)), 0);
}

/// Which blocks take the plain path: none with a G code or another word, none under an arc
/// mode or nc201; the others read as their mode's move or cycle.
#[test]
fn which_blocks_are_plain() {
    use super::super::{Machine, Mode};
    use crate::g90::CutCode;
    use crate::lex::{Block, Blocks};
    use crate::thread_move::ThreadCode;
    use cycle_vocab::Dialect;
    let block = |src: &str| {
        let mut b = Block::new();
        assert!(Blocks::new(src.as_bytes()).read(&mut b).unwrap());
        b
    };
    let mut m = Machine::new(Config::default());
    for (mode, moves) in [
        (Mode::Rapid, true),
        (Mode::Feed, true),
        (Mode::Thread(ThreadCode::G34), true),
        (Mode::G92, false),
        (Mode::Cut(CutCode::G94), false),
    ] {
        m.mode = mode;
        for src in ["Z3", "N1 U-1 W2", "X1 U1", "N5"] {
            assert_eq!(m.plain(&block(src)).map(|p| p.is_move()), Some(moves), "{src} under {mode:?}");
        }
        for src in ["G0 Z3", "Z3 F1", "Z3 T1", "Z3 S10", "M3", "Z3 I1", "X1 R1"] {
            assert_eq!(m.plain(&block(src)), None, "{src} under {mode:?}");
        }
    }
    m.mode = Mode::Arc(true);
    assert_eq!(m.plain(&block("Z3")), None);
    let mut nc = Machine::new(Config { dialect: Dialect::Nc201, ..Config::default() });
    nc.mode = Mode::Rapid;
    assert_eq!(nc.plain(&block("Z3")), None);
}
