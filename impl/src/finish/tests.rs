//! G70 alone (docs/INTERPRETATION.md, "G70"; CNT.FIND for G70) on the whole expander: the
//! contour before the G70 block run as ordinary moves, and its alarms.
extern crate std;

use crate::tests::{expand, moves, passes};
use cycle_vocab::{Alarm, AlarmCode, Config, Move, Pass, PassKind, Rule};
use std::format;
use std::string::String;

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

/// G70.*, CNT.FIND for G70: the contour before the G70 block (exactly one N(ns), N(nf) after it
/// within 1 000 blocks and before the G70 block), run as ordinary moves from the start point
/// with U/W, the feed rule, the return; a contour met without a cycle runs as ordinary blocks.
#[test]
fn g70_alone() {
    let src = "G0 X50 Z5\nN50 G1 X20 Z0 F0.1\nN60 Z-10 F0.2\nN65 F0.3\nN70 G2 X30 Z-15 R5\nN80 G0 X50\nG0 X50 Z5\nG70 P50 Q80 U0.4 W0.1 F0.05\nG1 Z6\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    // The contour first runs as ordinary blocks (CNT.FLOW).
    assert_eq!(m[1], Move::feed(20_000, 0, 1_000, Rule::PrjModal));
    assert_eq!(m[3], Move::arc(true, 30_000, -15_000, 30_000, -10_000, 3_000, Rule::ArcR));
    // G70: from X50 Z5, translated by U0.4 W0.1; the ns block's F0.1 applies from it on, the
    // next block's F0.2, the F0.3 of a block without motion to the arc; the G00 stays a rapid.
    let g = Rule::G70Path;
    assert_eq!(
        m[6..12],
        [
            Move::feed(20_400, 100, 1_000, g),
            Move::feed(20_400, -9_900, 2_000, g),
            Move::arc(true, 30_400, -14_900, 30_400, -9_900, 3_000, g),
            Move::rapid(50_400, -14_900, g),
            Move::rapid(50_000, 5_000, Rule::G70Return),
            // After G70: G00 is still the mode? No: the mode before G70 was G00 (the block before
            // it); `G1 Z6` feeds at G70's F0.05, the modal feed now.
            Move::feed(50_000, 6_000, 500, Rule::PrjModal),
        ]
    );
    let p = passes(&t);
    assert_eq!(p, [Pass { index: 1, kind: PassKind::Finish, diameter_depth: 29_600, rule: Rule::G70Path }]);
    // Without F in the G70 block the modal feed is the first feed (the contour's F is used
    // from its block on, not before).
    let t = expand("G0 X50 Z5\nN50 G1 X20 Z0 F0.1\nN60 G1 Z-10\nG0 X50 Z5\nG1 F0.07\nG70 P50 Q60\n", Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[m.len() - 3..], [Move::feed(20_000, 0, 1_000, g), Move::feed(20_000, -10_000, 1_000, g), Move::rapid(50_000, 5_000, Rule::G70Return)]);
    let t = expand("G0 X50 Z5\nG1 F0.05\nN50 G1 X20 Z0\nN60 G1 Z-10 F0.1\nG0 X50 Z5\nG1 F0.07\nG70 P50 Q60\n", Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[m.len() - 3..m.len() - 1], [Move::feed(20_000, 0, 700, g), Move::feed(20_000, -10_000, 1_000, g)]);
}

/// CNT.FIND for G70 and its alarms: none or two N(ns) before the G70 block, N(nf) missing or
/// after it, a contour over 1 000 blocks; the contour's checks; CNT.FIRST; the G70 block's line.
#[test]
fn g70_alarms() {
    let head = "G0 X50 Z5\n";
    let a = |body: &str, g70: &str| alarm_of(&format!("{head}{body}{g70}\n"));
    let np = |line| al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, line);
    let nq = |line| al(AlarmCode::BlockNotFound, b'Q', Rule::CntFind, line);
    assert_eq!(a("N50 G1 X20 F1\nN60 Z-10\n", "G70 P50 Q60"), None);
    assert_eq!(a("N50 G1 X20 F1\nN60 Z-10\n", "G70 P51 Q60"), np(4));
    assert_eq!(a("N50 G1 X20 F1\nN50 Z-5\nN60 Z-10\n", "G70 P50 Q60"), np(5));
    // A second N(ns) after N(nf) still makes N(ns) ambiguous.
    assert_eq!(a("N50 G1 X20 F1\nN60 Z-10\nN50 X30\n", "G70 P50 Q60"), np(5));
    // N(ns) after the G70 block does not count; nor does N(nf).
    assert_eq!(a("", "G70 P50 Q60 F1\nN50 G1 X20 F1\nN60 Z-10"), np(2));
    assert_eq!(a("N50 G1 X20 F1\n", "G70 P50 Q60\nN60 Z-10"), nq(3));
    // N(nf) before N(ns) is not "at or after" it.
    assert_eq!(a("N60 G1 X30 F1\nN50 G1 X20\n", "G70 P50 Q60"), nq(4));
    // The G70 block's own N is not "before" it.
    assert_eq!(a("N50 G1 X20 F1\n", "N60 G70 P50 Q60"), nq(3));
    // N(nf) = N(ns): a one-block contour.
    assert_eq!(a("N50 G1 X20 F1\n", "G70 P50 Q50"), None);
    // 1 000 blocks, 1 001.
    let body = |blocks: usize| {
        let mut s = String::from("N50 G1 X20 F1\n");
        for _ in 1..blocks - 1 {
            s += "W-0.01\n";
        }
        s + "N60 X50\n"
    };
    assert_eq!(a(&body(1_000), "G70 P50 Q60"), None);
    assert_eq!(a(&body(1_001), "G70 P50 Q60"), al(AlarmCode::ContourTooLong, b'Q', Rule::CntMax, 1_003));
    // Too long before not found: N(nf) missing after more than 1 000 blocks.
    let mut long = String::from("N50 G1 X20 F1\n");
    for _ in 0..1_000 {
        long += "W-0.01\n";
    }
    assert_eq!(a(&long, "G70 P50 Q60"), al(AlarmCode::ContourTooLong, b'Q', Rule::CntMax, 1_003));
    // Exactly 1 000 blocks from N(ns) to the G70 block, none N(nf): not too long, not found.
    long.truncate(long.len() - "W-0.01\n".len());
    assert_eq!(a(&long, "G70 P50 Q60"), nq(1_002));
    // The contour's checks (on its lines) and CNT.FIRST (on the ns block's line). A contour
    // met in program order runs as ordinary blocks first, so only what is legal there and
    // refused in a contour reaches the G70: an M code, an O word, a G04…
    assert_eq!(a("N50 G1 X20 F1\nZ-5 M8\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'M', Rule::CntWords, 3));
    assert_eq!(a("N50 G1 X20 F1\nO5\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'O', Rule::CntWords, 3));
    assert_eq!(a("N50 G1 X20 F1\nG97 S100\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntWords, 3));
    assert_eq!(a("N50 X20 F1\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::MissingWord, b'G', Rule::CntFirst, 2));
    assert_eq!(a("N50 G3 X60 Z0 R5 F1\nN60 G1 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntFirst, 2));
    // No monotonicity for G70.
    assert_eq!(a("N50 G1 X20 F1\nZ-10\nX10\nZ0\nN60 X50\n", "G70 P50 Q60"), None);
    // Missing feed, P, Q as for G71.
    assert_eq!(alarm_of("N50 G0 X20\nN60 Z-10\nG70 P50 Q60"), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 3));
}

/// G70's own `fill` (the stream takes a cycle's events one at a time when its `fill` writes
/// none, so no expander trace shows a `fill` that writes nothing or leaves the contour to
/// `next_event`; issue #33): against `next_event` through buffers of 1 … 12 and 64 events, every
/// call with room writes or says done; and only the header, the return and the end come from
/// `next_event` — three calls for the whole cycle, whatever the buffer — the contour's elements
/// (a rapid, feeds with their own F, an arc; G70.FEED) being built in place. The iterator alone is
/// called once per event and once more for the end (the counter's control).
#[test]
fn fill_builds_the_contour_in_place() {
    use crate::contour::{Contour, Element, Kind};
    use crate::finish::Cycle;
    use crate::probe;
    use crate::tests::assert_cycle_fill;
    use cycle_vocab::Event;
    let mut contour = Contour::new();
    let e = Element::ZERO;
    for el in [
        Element { x: 20_000, z: 0, kind: Kind::Feed, feed: 1_000, ..e },
        Element { x: 20_000, z: -10_000, kind: Kind::Feed, feed: 2_000, ..e },
        Element { x: 30_000, z: -15_000, cx: 30_000, cz: -10_000, kind: Kind::Arc(true), ..e },
        Element { x: 50_000, z: -15_000, kind: Kind::Rapid, ..e },
    ] {
        assert!(contour.push(el));
    }
    let start = (50_000, 5_000);
    let cycle = Cycle::new(start, (400, 100), 500, &contour);
    let sizes: std::vec::Vec<usize> = (1..=12).chain([64]).collect();
    let next = |c: &mut Cycle, p: &mut (i64, i64)| c.next_event(p, &contour);
    let fill = |c: &mut Cycle, p: &mut (i64, i64), out: &mut [Event]| c.fill(p, out, &contour);
    assert_cycle_fill(&cycle, start, next, fill, &sizes);
    let (mut c, mut pos, before) = (cycle, start, probe::calls());
    let mut events = 0;
    while c.next_event(&mut pos, &contour).is_some() {
        events += 1;
    }
    // The header, four elements, the return.
    assert_eq!((events, probe::calls() - before), (6, 7));
    for &size in &sizes {
        let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
        let mut buffer = std::vec![filler; size];
        let (mut c, mut pos, mut got, before) = (cycle, start, 0, probe::calls());
        loop {
            let (n, done) = c.fill(&mut pos, &mut buffer, &contour);
            got += n;
            if done {
                break;
            }
        }
        assert_eq!((got, probe::calls() - before), (events, 3), "buffer of {size}");
    }
}
