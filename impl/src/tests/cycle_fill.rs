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
