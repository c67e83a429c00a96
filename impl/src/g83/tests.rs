//! G83 and G84 (M003, read as FANUC lathe controls do; docs/INTERPRETATION.md, "G83 and G84")
//! on the whole expander: the seed's lines, the peck edges, the dwell and spindle events, the
//! lead under G98 and G99, M29 and G80, every alarm with its word and rule, the pass bound before
//! motion, and `fill` against the iterator.
extern crate std;

use crate::tests::assert_fill_agrees;
use crate::tests::{expand, moves, passes};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Dwell, Event, Move, Spindle, SpindleState, Rule};
use std::vec::Vec;

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

/// The events after the first `skip`.
fn events(src: &str, skip: usize) -> Vec<Event> {
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None, "{src}");
    t.events[skip..].to_vec()
}

/// G83.FORMAT: `G83Z-30R0.5Q2000F0.2` from Z0: R level Z0.5, pecks of 2 mm (Q in increments)
/// to Z−1.5, −3.5, …, −29.5 and −30, each but the last followed by a rapid to the R level and a
/// rapid down to the depth reached; no dwell; back to Z0.
#[test]
fn g83_seed_line() {
    let t = expand("G50 X60 Z40\nG00 X0 Z0 S800\nG83Z-30R0.5Q2000F0.2\n", Config::default());
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!((p.len(), p[0].index, p[0].diameter_depth, p[0].rule), (1, 1, 61_000, Rule::G83Peck));
    let m = moves(&t);
    let mut want = std::vec![Move::rapid(0, 500, Rule::G83Peck)];
    let ends: Vec<i64> = (1..=15).map(|k| 500 - 2_000 * k).chain([-30_000]).collect();
    for (k, z) in ends.iter().enumerate() {
        if k > 0 {
            want.push(Move::rapid(0, 500, Rule::G83Peck));
            want.push(Move::rapid(0, ends[k - 1], Rule::G83Peck));
        }
        want.push(Move::feed(0, *z, 2_000, Rule::G83Peck));
    }
    want.push(Move::rapid(0, 0, Rule::G83Peck));
    assert_eq!(m[1..], want[..]);
    assert!(!t.events.iter().any(|e| matches!(e, Event::Dwell(_))));
}

/// G83.PECK edges: without Q one feed, the dwell at the bottom; Q beyond the depth one peck; a
/// last peck of one increment; R omitted: the R level is the initial level; W incremental.
#[test]
fn g83_edges() {
    let r = Rule::G83Peck;
    let e = events("G00 X0 Z3\nG83 Z-10 R-1 P500 F0.1\n", 1);
    let pass = |d| Event::Pass(cycle_vocab::Pass { index: 1, kind: cycle_vocab::PassKind::Rough, diameter_depth: d, rule: r });
    assert_eq!(
        e,
        [
            pass(24_000),
            Event::Move(Move::rapid(0, 2_000, r)),
            Event::Move(Move::feed(0, -10_000, 1_000, r)),
            Event::Dwell(Dwell { ms: 500, rule: r }),
            Event::Move(Move::rapid(0, 3_000, r)),
        ]
    );
    let e = events("G00 X0 Z3\nG83 Z-4 R-1 Q9000 F0.1\n", 1);
    assert_eq!(e.len(), 4);
    let t = expand("G00 X0 Z3\nG83 W-8.001 Q1000 F0.1\n", Config::default());
    let m = moves(&t);
    // R omitted: the first peck feeds from the initial level; the last is one increment.
    assert_eq!(m[1], Move::feed(0, 2_000, 1_000, r));
    assert_eq!(m[m.len() - 2], Move::feed(0, -5_001, 1_000, r));
    assert_eq!(m.iter().filter(|m| m.feed != 0).count(), 9);
    // Q0 is one feed; an R level below the bottom drills toward +Z.
    let t = expand("G00 X10 Z0\nG83 Z5 R-2 Q0 F0.1\n", Config::default());
    assert_eq!(moves(&t)[1..], [Move::rapid(10_000, -2_000, r), Move::feed(10_000, 5_000, 1_000, r), Move::rapid(10_000, 0, r)]);
}

/// G84.PATH under G98: the lead F / S = 60 / 60 = 1 mm; thread in, M04, thread out, M03, back.
#[test]
fn g84_seed_line_g98() {
    let r = Rule::G84Path;
    let e = events("G50 X60 Z40\nG00 X0 Z0\nG98M29S60\nG84Z-21R2F60\nG80\n", 1);
    assert_eq!(
        e,
        [
            Event::Pass(cycle_vocab::Pass { index: 1, kind: cycle_vocab::PassKind::Rough, diameter_depth: 46_000, rule: r }),
            Event::Move(Move::rapid(0, 2_000, r)),
            Event::Move(Move::thread(0, -21_000, 10_000, 0, r)),
            Event::Spindle(Spindle { state: SpindleState::Reverse, rule: r }),
            Event::Move(Move::thread(0, 2_000, 10_000, 0, r)),
            Event::Spindle(Spindle { state: SpindleState::Forward, rule: r }),
            Event::Move(Move::rapid(0, 0, r)),
        ]
    );
    // The seed's one-block form: G80 in the G84 block does not disarm this block's M29 (`Rule::G80`).
    assert_eq!(events("G50 X60 Z40\nG00 X0 Z0\nG98M29S60G84Z-21R2F60G80\n", 1), e);
    // F / S rounded once, half up, on the lead grid: 100 / 3 mm per min → 33.3333 mm.
    let t = expand("G98 M29 S3 G84 Z-10 F100\n", Config::default());
    assert_eq!(moves(&t)[0].feed, 333_333);
    let t = expand("G98 M29 S3 G84 Z-10 F0.0002\n", Config::default());
    assert_eq!(moves(&t)[0].feed, 1);
}

/// G84.PATH under G99 (the default): the lead is F; the dwell P at the bottom; an R level below
/// the initial level.
#[test]
fn g84_g99() {
    let r = Rule::G84Path;
    let e = events("G00 X0 Z5\nG99 M29 S500 G84 Z-15 R-3 P200 F1.25\nG80\n", 2);
    assert_eq!(e[0], Event::Move(Move::rapid(0, 2_000, r)));
    assert_eq!(e[1], Event::Move(Move::thread(0, -15_000, 12_500, 0, r)));
    assert_eq!(e[2], Event::Dwell(Dwell { ms: 200, rule: r }));
    assert_eq!(e.last(), Some(&Event::Move(Move::rapid(0, 5_000, r))));
    // No S needed under G99; M29 stays armed across blocks until a G84 or G80.
    assert_eq!(alarm_of("M29\nG0 X0 Z5\nG84 Z-5 F1\n"), None);
    assert_eq!(alarm_of("G98\nG99\nM29\nG84 Z-5 F1\n"), None);
}

/// Every alarm of the register's checks, with its word and rule.
#[test]
fn alarms() {
    use AlarmCode::*;
    // Words.
    assert_eq!(alarm_of("G83 X1 Z-5 F1\n"), al(WordNotAllowed, b'X', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G83 Z-5 K1 F1\n"), al(WordNotAllowed, b'K', Rule::PrjWord, 1));
    assert_eq!(alarm_of("M29 G84 Z-5 Q1 F1\n"), al(WordNotAllowed, b'Q', Rule::PrjWord, 1));
    assert_eq!(alarm_of("M29 G84 U1 Z-5 F1\n"), al(WordNotAllowed, b'U', Rule::PrjWord, 1));
    // Values: Q and P integers; R a length.
    assert_eq!(alarm_of("G83 Z-5 Q2. F1\n"), al(NotInteger, b'Q', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G83 Z-5 Q-1 F1\n"), al(OutOfRange, b'Q', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G83 Z-5 P1.5 F1\n"), al(NotInteger, b'P', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G83 Z-5 P100000000 F1\n"), al(OutOfRange, b'P', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G83 Z-5 R1000000 F1\n"), al(OutOfRange, b'R', Rule::ComRanges, 1));
    assert_eq!(alarm_of("G83 Z-5 W1 F1\n"), al(Conflict, b'W', Rule::ComAbsInc, 1));
    // (4) no feed; (5) the bottom at the R level.
    assert_eq!(alarm_of("G83 Z-5\n"), al(MissingWord, b'F', Rule::ComLead, 1));
    assert_eq!(alarm_of("G0 Z2\nG83 Z1 R-1 F1\n"), al(Geometry, b'Z', Rule::G83Format, 2));
    assert_eq!(alarm_of("G83 F1\n"), al(Geometry, b'Z', Rule::G83Format, 1));
    // G84: no feed; no M29 (never, or ended by G80 or by a G84 cycle); under G98 S; lead 0;
    // the bottom at the R level.
    assert_eq!(alarm_of("M29 G84 Z-5\n"), al(MissingWord, b'F', Rule::ComLead, 1));
    assert_eq!(alarm_of("G84 Z-5 F1\n"), al(Unsupported, b'G', Rule::G84Format, 1));
    assert_eq!(alarm_of("M29\nG80\nG84 Z-5 F1\n"), al(Unsupported, b'G', Rule::G84Format, 3));
    assert_eq!(alarm_of("M29\nG84 Z-5 F1\nG84 Z-5 F1\n"), al(Unsupported, b'G', Rule::G84Format, 3));
    assert_eq!(alarm_of("G98 M29 G84 Z-5 F60\n"), al(MissingWord, b'S', Rule::G84Format, 1));
    // S with a point is NOT INTEGER where it is written.
    assert_eq!(alarm_of("S60.5\nG98 M29 G84 Z-5 F60\n"), al(NotInteger, b'S', Rule::ComRanges, 1));
    assert_eq!(alarm_of("S0\nG98 M29 G84 Z-5 F60\n"), al(OutOfRange, b'S', Rule::G84Format, 2));
    assert_eq!(alarm_of("G98 M29 S100000 G84 Z-5 F60\n"), al(OutOfRange, b'S', Rule::G84Format, 1));
    assert_eq!(alarm_of("G98 M29 S99999 G84 Z-5 F0.0001\n"), al(OutOfRange, b'F', Rule::G84Format, 1));
    assert_eq!(alarm_of("G0 Z2\nM29 G84 Z0 R-2 F1\n"), al(Geometry, b'Z', Rule::G84Format, 2));
    // nc201: the codes, G80 included, do not exist.
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    for src in ["G83 Z-5 F1\n", "G84 Z-5 F1\n", "G80\n"] {
        assert_eq!(expand(src, nc201).alarm, al(UnsupportedCode, b'G', Rule::PrjDialect, 1), "{src}");
    }
    // Two cycle codes in a block; G80 is no motion code.
    assert_eq!(alarm_of("G83 G84 Z-5 F1\n"), al(Conflict, b'G', Rule::PrjWord, 1));
    assert_eq!(alarm_of("G80 G0 X1\n"), None);
}

/// PRJ.MAXPASS: the pecks in closed form, before any motion.
#[test]
fn pass_bound_before_motion() {
    let t = expand("G83 Z-999999.999 Q1 F1\n", Config::default());
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass, 1));
    assert!(t.events.is_empty());
    let t = expand("G83 Z-10.001 Q1 F1\n", Config::default());
    assert_eq!(t.alarm, al(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass, 1));
    let t = expand("G83 Z-10 Q1 F1\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(moves(&t).iter().filter(|m| m.feed != 0).count(), 10_000);
}

/// CYC.ONESHOT: the motion mode is as before; the modal feed is the cycle's F.
#[test]
fn one_shot() {
    let t = expand("G1 X0 Z2 F0.3\nG83 Z-5 F0.1\nZ3\n", Config::default());
    assert_eq!(moves(&t).last(), Some(&Move::feed(0, 3_000, 1_000, Rule::PrjModal)));
    let t = expand("G0 X0 Z2\nM29 G84 Z-5 F1\nZ3\n", Config::default());
    assert_eq!(moves(&t).last(), Some(&Move::rapid(0, 3_000, Rule::PrjModal)));
}

#[test]
fn fill_equals_the_iterator() {
    let sizes: Vec<usize> = (1..=40).chain([64, 1_000]).collect();
    for src in [
        "G00 X0 Z0 S800\nG83Z-30R0.5Q2000F0.2\nG0 X10\n",
        "G00 X0 Z3\nG83 Z-10 R-1 P500 F0.1\nG83 Z-4 R-1 Q9000 F0.1\nG83 Z-5.001 Q1000 F0.1\nG00 X50 Z50\n",
        "G00 X0 Z0\nG98M29S60\nG84Z-21R2F60\nG80\nG00 X60 Z40\n",
        "G00 X0 Z5\nG99 M29 S500 G84 Z-15 R-3 P200 F1.25\nG80\nG84 Z1 F1\n",
    ] {
        assert_fill_agrees(src, Config::default(), &sizes);
    }
}

/// G83's and G84's own `fill` against their `next_event` (the stream would hide a `fill` that
/// writes nothing): G83 with pecks and a dwell, without Q; G84 with and without a dwell.
#[test]
fn cycle_fill_on_its_own() {
    use crate::g83::{cycle, Cycle, Words};
    use crate::tests::assert_cycle_fill;
    let sizes: Vec<usize> = (1..=12).chain([64]).collect();
    let a = (0, 3_000);
    let w = Words { r: -1_000, bottom: -10_000, q: 2_000, dwell: 500, feed: 1_000 };
    for w in [w, Words { q: 0, dwell: 0, ..w }] {
        assert_cycle_fill(&cycle(a, &w, 10_000, 2).unwrap(), a, Cycle::next_event, Cycle::fill, &sizes);
    }
    for w in [w, Words { dwell: 0, ..w }] {
        let tap = crate::g84::cycle(a, &w, None, 2).unwrap();
        assert_cycle_fill(&tap, a, crate::g84::Cycle::next_event, crate::g84::Cycle::fill, &sizes);
    }
}

/// G83's bulk path (`batch::Bulk`, what `fill` writes in place): at a peck before the last,
/// `in_bulk` holds and `write_bulk` writes the peck, the rapid up to the R level and the rapid
/// down while three events fit; at the last peck it no longer holds.
#[test]
fn bulk_writes_the_pecks_before_the_last() {
    use crate::batch::Bulk;
    use crate::g83::{cycle, Words};
    // From Z0: R level Z0.5, pecks of 2 mm to Z−1.5 and −3.5 (the last).
    let w = Words { r: 500, bottom: -3_500, q: 2_000, dwell: 0, feed: 1_000 };
    let mut c = cycle((0, 0), &w, 10_000, 1).unwrap();
    let mut pos = (0, 0);
    assert!(!c.in_bulk());
    assert!(matches!(c.next_event(&mut pos), Some(Event::Pass(_))));
    assert!(!c.in_bulk());
    assert_eq!(c.next_event(&mut pos), Some(Event::Move(Move::rapid(0, 500, Rule::G83Peck))));
    assert!(c.in_bulk());
    let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
    let mut out = [filler; 2];
    assert_eq!(c.write_bulk(&mut pos, &mut out), 0, "three events do not fit in two");
    let mut out = [filler; 4];
    assert_eq!(c.write_bulk(&mut pos, &mut out), 3);
    let r = Rule::G83Peck;
    assert_eq!(out[..3], [Move::feed(0, -1_500, 1_000, r), Move::rapid(0, 500, r), Move::rapid(0, -1_500, r)].map(Event::Move));
    assert!(!c.in_bulk());
    assert_eq!(c.next_event(&mut pos), Some(Event::Move(Move::feed(0, -3_500, 1_000, r))));
}
