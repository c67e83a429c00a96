//! Each cycle's own `fill` and batch path on its own, against its `next_event` (issue #33's
//! mutation runs): the stream takes a cycle's events one at a time when its `fill` writes none,
//! and `batch::fill` falls back to `next_event`, so a `fill` or a batch unit that writes nothing
//! cannot be seen in an expander trace; these tests see it.
extern crate std;

use crate::batch::Batch;
use crate::tests::assert_cycle_fill;
use cycle_vocab::{Event, Move, Rule};
use std::vec::Vec;

fn sizes() -> Vec<usize> {
    (1..=12).chain([64]).collect()
}

/// A cycle's batch unit (`batch::Batch`): a fresh cycle is neither begun nor finished;
/// `write_unit` writes exactly `next_event`'s events of the unit and leaves it finished (not
/// begun, no next unit); one `next_event` begins it.
fn assert_unit<const N: usize, C: Batch<N> + Clone>(cycle: &C, at: (i64, i64)) {
    let (mut c, mut pos, mut want) = (cycle.clone(), at, Vec::new());
    while let Some(e) = c.next_event(&mut pos) {
        want.push(e);
    }
    assert!(!cycle.begun());
    let mut once = cycle.clone();
    assert!(once.next_event(&mut at.clone()).is_some());
    assert!(once.begun());
    let mut c = cycle.clone();
    assert!(c.ready());
    let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
    let mut slots = [filler; N];
    let mut pos = at;
    let n = c.write_unit(&mut pos, &mut slots);
    assert_eq!(slots[..n], want[..]);
    assert!(!c.begun());
    assert!(!c.ready());
}

/// G73 from A = X50 Z10 over a contour with a rapid, feeds and an arc; with and without C.
#[test]
fn g73() {
    use crate::g73::{Cycle, Words};
    let (contour, a, w) = crate::tests::g73_case();
    for w in [w, Words { visit_c: false, ..w }] {
        let c = Cycle::new(a, &w, &contour, 10_000, 3).unwrap();
        let next = |c: &mut Cycle, p: &mut (i64, i64)| c.next_event(p, &contour);
        let fill = |c: &mut Cycle, p: &mut (i64, i64), out: &mut [Event]| c.fill(p, out, &contour);
        assert_cycle_fill(&c, a, next, fill, &sizes());
    }
}

/// G90 and G94, straight and tapered; their batch unit.
#[test]
fn g90_g94() {
    use crate::g90::{cycle, CutCode, CutState, Cycle};
    let a = (50_000, 2_000);
    for (code, end, taper) in [
        (CutCode::G90, (40_000, -20_000), 0),
        (CutCode::G90, (40_000, -20_000), -2_000),
        (CutCode::G94, (20_000, -5_000), 0),
        (CutCode::G94, (20_000, -5_000), -1_000),
    ] {
        let st = CutState { end, taper, index: 1 };
        let c = cycle(code, &st, a, 1_000, 2).unwrap();
        assert_cycle_fill(&c, a, Cycle::next_event, Cycle::fill, &sizes());
        assert_unit(&c, a);
    }
}

/// G84's batch unit (the whole tap), with and without a dwell.
#[test]
fn g84_unit() {
    use crate::g83::Words;
    let a = (0, 3_000);
    let w = Words { r: -1_000, bottom: -10_000, q: 0, dwell: 500, feed: 1_000 };
    for w in [w, Words { dwell: 0, ..w }] {
        assert_unit(&crate::g84::cycle(a, &w, None, 2).unwrap(), a);
    }
}

/// A cycle's batch units one after another: before each, no unit is begun and `ready` makes
/// the next one current; each `write_unit` leaves its unit finished; together they are exactly
/// `next_event`'s events, and then `ready` says done. Returns the number of units. (Bounded:
/// a `ready` that never says done fails here, not by a hang.)
fn assert_units<const N: usize, C: Batch<N> + Clone>(cycle: &C, at: (i64, i64)) -> usize {
    let (mut c, mut pos, mut want) = (cycle.clone(), at, Vec::new());
    while let Some(e) = c.next_event(&mut pos) {
        want.push(e);
    }
    let want_end = pos;
    let (mut c, mut pos, mut got, mut units) = (cycle.clone(), at, Vec::new(), 0);
    let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
    while c.ready() {
        assert!(units < want.len(), "more units than events");
        assert!(!c.begun());
        let mut slots = [filler; N];
        let n = c.write_unit(&mut pos, &mut slots);
        assert!(n > 0, "unit {units} wrote nothing");
        got.extend_from_slice(&slots[..n]);
        assert!(!c.begun(), "unit {units} left begun");
        units += 1;
    }
    assert_eq!((got, pos), (want, want_end));
    units
}

/// G162 (M004, G162.PATH): a unit is a pass, its header and five moves. P2.5 Q1 (two full
/// passes and four split passes, the manual's example) with a taper, a leg and an infeed
/// angle; a single pass. Its own `fill` against `next_event`; a fresh cycle is not begun, one
/// `next_event` (the header) begins the pass, the pass's five moves finish it.
#[test]
fn g162() {
    use crate::g162::{cycle, Cycle, SplitParams, Words};
    use cycle_vocab::Config;
    let start = (30_000, 5_000);
    let w = Words {
        x: 24_000,
        z: -20_000,
        incremental: false,
        h: 500,
        split: Some(SplitParams { depth: 2_500, allowance: 1_000 }),
        v: 1_000,
        taper: -2_000,
        a: 300,
        lead: 15_000,
        b: 0,
        i: 0,
        j: 360_000,
    };
    for (w, passes) in [(w, 6), (Words { split: None, ..w }, 1)] {
        let c = cycle(&Config::default(), &crate::config::DEFAULTS, &w, start, 2).unwrap();
        assert_cycle_fill(&c, start, Cycle::next_event, Cycle::fill, &sizes());
        assert_eq!(assert_units(&c, start), passes);
        assert!(!c.begun());
        let (mut once, mut pos) = (c, start);
        assert!(matches!(once.next_event(&mut pos), Some(Event::Pass(_))));
        assert!(once.begun());
        for _ in 0..5 {
            assert!(matches!(once.next_event(&mut pos), Some(Event::Move(_))));
        }
        assert!(!once.begun());
    }
    // The multi-pass cycle's units are a pass each: after one, the next is its header.
    let c = cycle(&Config::default(), &crate::config::DEFAULTS, &w, start, 2).unwrap();
    assert_unit_then_next(&c, start);
}

/// After one unit written, `ready` makes the next pass current and `next_event` gives its
/// header — the unit did not begin the next pass nor leave the current one half done.
fn assert_unit_then_next(c: &crate::g162::Cycle, at: (i64, i64)) {
    let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
    let (mut c, mut pos, mut slots) = (*c, at, [filler; 6]);
    assert!(c.ready());
    assert_eq!(c.write_unit(&mut pos, &mut slots), 6);
    assert!(matches!(slots[0], Event::Pass(p) if p.index == 1));
    assert!(c.ready());
    assert!(matches!(c.next_event(&mut pos), Some(Event::Pass(p)) if p.index == 2));
}
