//! The first-move latency as a function of the contour's length: G70, G71, G72 and G73 over
//! contours of 10, 100 and 1 000 blocks, each the least of interleaved rounds, with a fitted
//! cost per element and how linear it is.

use super::cases::{contour_case, events, first_cycle_move, Case};
use super::measure::{least_of_rounds, worst_next, Mode};
use criterion::black_box;

/// The contour lengths (blocks; CNT.MAX is 1 000).
const ELEMENTS: [usize; 3] = [10, 100, 1_000];

/// Prints the latency table.
pub fn latency(mode: Mode) {
    println!("\n## First-move latency against the contour's length (this run)\n");
    println!(
        "| family | 10 elements ns | 100 elements ns | 1 000 elements ns | ns/element (100→1 000) | ns/element (10→100) \
         | slope ratio | 1 000 / 100 | longest next() at 1 000, ns (@step) |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut durations = Vec::new();
    for family in ["g70", "g71", "g72", "g73"] {
        let cases: Vec<Case> = ELEMENTS.iter().map(|&n| contour_case(family, n)).collect();
        for case in &cases {
            events(case); // panics on an alarm
            assert!(first_cycle_move(case).is_some(), "latency case {}: no cycle move", case.name);
        }
        let first = |i: usize| {
            let case = &cases[i];
            move || {
                black_box(first_cycle_move(black_box(case)));
            }
        };
        let (mut f0, mut f1, mut f2) = (first(0), first(1), first(2));
        let l = least_of_rounds(mode, &mut [&mut f0, &mut f1, &mut f2]);
        let slope_large = (l[2] - l[1]) / (ELEMENTS[2] - ELEMENTS[1]) as f64;
        let slope_small = (l[1] - l[0]) / (ELEMENTS[1] - ELEMENTS[0]) as f64;
        let worst = worst_next(&cases[2], mode.rounds, &mut durations);
        println!(
            "| {family} | {:.0} | {:.0} | {:.0} | {slope_large:.1} | {slope_small:.1} | {:.2} | {:.2} | {:.0} (@{}) |",
            l[0],
            l[1],
            l[2],
            slope_large / slope_small,
            l[2] / l[1],
            worst.max,
            worst.at
        );
    }
    println!(
        "\n(G71/G72 rough 10 layers, G73 runs 10 passes; slope ratio 1.00 = linear; the longest `next()` is the \
         1 000-element case's, as the main table measures it.)"
    );
}
