//! G71.LAYER on a line element: the cut of each layer after the first on the same element is
//! stepped from the layer before (`step::LineStep`, no division), not computed afresh. Both give
//! the same cut (`step`'s tests), so no trace tells them apart: `crate::probe` counts the fresh
//! computations.
use super::*;
use crate::probe;

/// A = X41 Z0, Δd = 1 (layers 2 mm apart on the diameter), Q = X5 Z0 → X21 Z−8 → X41 Z−36:
/// 17 layers (X39 … X7, G71.LAYER), 1 … 10 cut on the second line (X39 … X21: at X21 the
/// last point on or before the layer is X21 Z−8 itself), 11 … 17 on the first.
const TWO_LINES: &str = "G0 X41 Z0\nG71 U1 R0.5\nG71 P50 Q60 F0.2\nN50 G1 X5\nX21 Z-8\nN60 X41 Z-36\n";

/// The events of `program` and the fresh layer cuts counted while they were made, through
/// the iterator (`size` = None) or through `fill` with a buffer of `size`.
fn run(program: &str, size: Option<usize>) -> (Vec<Event>, usize) {
    let before = probe::cuts();
    let mut events = Vec::new();
    let mut expander = Expander::new(program.as_bytes(), Config::default());
    match size {
        None => events.extend(expander.map(Result::unwrap)),
        Some(size) => {
            let mut buffer = std::vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); size];
            while let n @ 1.. = expander.fill(&mut buffer).unwrap() {
                events.extend_from_slice(&buffer[..n]);
            }
        }
    }
    (events, probe::cuts() - before)
}

#[test]
fn a_line_element_steps_its_layers() {
    let (events, fresh) = run(TWO_LINES, None);
    let cuts = layer_cuts(&events);
    assert_eq!(cuts.len(), 17);
    // Layer 1 at X39 on the second line: Z = −8 + (39 − 21)·(−28/20) = −33.2; layer 10 at X21
    // ends at X21 Z−8; layer 11 at X19 on the first line: Z = (19 − 5)·(−8/16) = −7.
    assert_eq!((cuts[0], cuts[9], cuts[10]), ((1, (39_000, -33_200)), (10, (21_000, -8_000)), (11, (19_000, -7_000))));
    // One fresh cut per element the layers reach (two), through the iterator and through fill.
    assert_eq!(fresh, 2, "the iterator: fresh cuts");
    for size in [5, 6, 64, 4_096] {
        assert_eq!(run(TWO_LINES, Some(size)), (events.clone(), 2), "fill, buffer of {size}");
    }
    // An arc is computed afresh for every layer on it: the seed's example 1 (Q shifted by U0.5
    // W0.2) cuts layers 1–2 on the line N120, 3–5 on the arc N100, 6–7 on the line N080 and 8–9
    // on the ball N060: 9 layers, 7 fresh cuts.
    let (_, fresh) = run(EXAMPLE_1, None);
    assert_eq!(fresh, 7);
}
