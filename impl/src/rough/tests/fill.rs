//! G71/G72's own `fill` against its `next_event` (`tests::assert_cycle_fill`), and that it
//! builds its layers in place: `crate::probe` counts the `next_event` calls (the stream falls
//! back to `next_event` when a cycle's `fill` writes nothing, so no trace tells the two apart).
use super::*;
use crate::contour::{Contour, Element};
use crate::probe;
use crate::rough::{Phase, Roughing, Words};
use crate::tests::assert_cycle_fill;

/// A = X41 Z0 (G71) or its mirror X0 Z41 (G72, the frame exchanged), Δd = 1 mm, e = 0.5 mm,
/// Q = (a, b) = (5, 0) → (21, −8) → (41, −36) with a on the layer axis: the layers, the
/// semi-finish pass over three elements, the return. Element 2 is a feed (G01), the ns block
/// a rapid (the infeeds are rapids).
fn case(axis: Axis) -> (Roughing, Contour, (i64, i64)) {
    let p = |a: i64, b: i64| match axis {
        Axis::G71 => (a, b),
        Axis::G72 => (b, a),
    };
    let mut contour = Contour::new();
    for (i, (kind, (a, b))) in [(Kind::Rapid, (5_000, 0)), (Kind::Feed, (21_000, -8_000)), (Kind::Feed, (41_000, -36_000))].into_iter().enumerate() {
        let (x, z) = p(a, b);
        assert!(contour.push(Element { x, z, kind, line: i as u32 + 4, ..Element::ZERO }));
    }
    let w = Words { depth: 1_000, retract: 500, allowance: (0, 0), feed: 2_000 };
    let start = p(41_000, 0);
    (Roughing::new(axis, start, &w, &contour, 10_000, 3).unwrap(), contour, start)
}

#[test]
fn cycle_fill_on_its_own() {
    let sizes: Vec<usize> = (1..=16).chain([64, 4_096]).collect();
    for axis in [Axis::G71, Axis::G72] {
        let (cycle, contour, a) = case(axis);
        // G71 layers 2 mm apart on the diameter X39 … X7, G72 1 mm apart Z40 … Z6.
        assert_eq!(cycle.layer_count(), if axis == Axis::G71 { 17 } else { 35 });
        let next = |c: &mut Roughing, pos: &mut (i64, i64)| c.next_event(pos, &contour);
        let fill = |c: &mut Roughing, pos: &mut (i64, i64), out: &mut [Event]| c.fill(pos, out, &contour);
        assert_cycle_fill(&cycle, a, next, fill, &sizes);
    }
}

/// `fill` writes every layer that begins with five slots free in place; `next_event` serves
/// only the rest: the tail of a layer begun in an earlier call (at most four events), a layer
/// that no longer fits (at most four), and the semi-finish pass and the return. With room for
/// the whole cycle: six calls — the SEMI header, the move to Q₀, its two elements after the ns
/// block, the return, the end.
#[test]
fn fill_builds_the_layers_in_place() {
    for axis in [Axis::G71, Axis::G72] {
        let (cycle, contour, a) = case(axis);
        let (mut c, mut pos, before) = (cycle, a, probe::calls());
        let mut events = 0;
        while c.next_event(&mut pos, &contour).is_some() {
            events += 1;
        }
        assert_eq!(probe::calls() - before, events + 1, "the iterator counts each call");
        let mut buffer = std::vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); 4_096];
        let (mut c, mut pos, before) = (cycle, a, probe::calls());
        assert_eq!(c.fill(&mut pos, &mut buffer, &contour), (events, true));
        assert_eq!(probe::calls() - before, 6, "{axis:?}: next_event ran for a layer's event");
        for size in 5..=16 {
            let (mut c, mut pos) = (cycle, a);
            let mut buffer = std::vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); size];
            while c.phase == Phase::Layer {
                let before = probe::calls();
                c.fill(&mut pos, &mut buffer, &contour);
                let calls = probe::calls() - before;
                // A call that reached the semi-finish pass takes its events from `next_event`.
                assert!(calls <= 8 || c.phase != Phase::Layer, "{axis:?}, buffer of {size}: {calls} next_event calls in one fill among the layers");
            }
        }
    }
}
