//! The summary table: per case, throughput ratios (least of interleaved rounds), the worst
//! step, the first-move latency and the cost per block against the production lexer's; then
//! the targets of issue #32, met or not, from the same figures.

use super::cases::{baseline_into, events, first_cycle_move, impl_into, iter_into, lex_all, Case};
use super::measure::{least_of_rounds, worst_fill, worst_next, Mode, FILL_CHUNK};
use criterion::black_box;
use cycle_kernel::registry::FAMILIES;

/// The figures of one registry case that the targets read.
struct Row {
    family: &'static str,
    size: usize,
    impl_spec: f64,
    impl_baseline: f64,
    impl_lex: f64,
}

/// Families emitting several moves per block: impl / baseline ≥ 0.5 at ~9 900 passes.
const SEVERAL_MOVES: [&str; 11] = ["g76", "g78", "f76", "g162", "g71", "g72", "g73", "g74", "g75", "g83", "g84"];
/// Families reading one block per pass or move: per block within 2× of the lexer.
const ONE_BLOCK: [&str; 5] = ["g92", "g90", "g94", "g32", "g70"];

/// Prints the table of `cases` and the targets.
pub fn table(cases: &[Case], mode: Mode) {
    println!("\n## cyclecheck expander figures (this run)\n");
    println!(
        "| case | events | blocks | impl Mev/s | baseline Mev/s | spec Mev/s | impl/baseline | impl/spec | ns/event | iter ns/event \
         | next mean ns | next max ns (@step) | fill mean ns | fill max ns (@call) | first move ns | lex ns/block | impl ns/block | impl/lex |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    let mut rows = Vec::new();
    let mut durations = Vec::new();
    for case in cases {
        let events = events(case);
        assert!(first_cycle_move(case).is_some(), "bench case {}: no cycle move", case.name);
        let n = events.len() as f64;
        let program = case.program.as_bytes();
        let blocks = lex_all(program) as f64;
        let (mut copied, mut filled) = (events.clone(), events.clone());
        let mut pushed = Vec::with_capacity(events.len());
        let mut base = || baseline_into(&mut copied, black_box(&events));
        let mut imp = || impl_into(&mut filled, black_box(case));
        let mut iter = || iter_into(&mut pushed, black_box(case));
        let mut spec = || {
            black_box(cycle_spec::expand(black_box(program), &case.config));
        };
        let mut first = || {
            black_box(first_cycle_move(black_box(case)));
        };
        let mut lex = || {
            black_box(lex_all(black_box(program)));
        };
        let least = least_of_rounds(mode, &mut [&mut base, &mut imp, &mut iter, &mut spec, &mut first, &mut lex]);
        assert_eq!(filled, events, "bench case {}: fill wrote other events", case.name);
        let [base, imp, iter, spec, first, lex] = [0, 1, 2, 3, 4, 5].map(|i| least[i]);
        let next = worst_next(case, mode.rounds, &mut durations);
        let fill = worst_fill(case, mode.rounds, &mut durations);
        let rate = |ns: f64| n / ns * 1e3; // events per ns → M events per s
        let name = match case.layers {
            Some(layers) => format!("{} ({:.1} ns/layer)", case.name, imp / layers as f64),
            None => case.name.clone(),
        };
        let per_block = imp / blocks;
        let lex_block = lex / blocks;
        // Per block only where blocks drive the trace (a block per 20 events or more).
        let block_cols = if blocks * 20.0 >= n {
            format!("{per_block:.1} | {:.2}", per_block / lex_block)
        } else {
            "— | —".to_string()
        };
        println!(
            "| {name} | {} | {blocks} | {:.1} | {:.1} | {:.2} | {:.2} | {:.2} | {:.1} | {:.1} | {:.0} | {:.0} (@{}) | {:.0} | {:.0} (@{}) | {:.0} | {:.1} | {block_cols} |",
            events.len(),
            rate(imp),
            rate(base),
            rate(spec),
            base / imp,
            spec / imp,
            imp / n,
            iter / n,
            next.mean,
            next.max,
            next.at,
            fill.mean,
            fill.max,
            fill.at,
            first,
            lex_block,
        );
        if let Some(size) = case.size {
            rows.push(Row { family: case.family, size, impl_spec: spec / imp, impl_baseline: base / imp, impl_lex: per_block / lex_block });
        }
    }
    println!(
        "\n(`fill` calls write up to {FILL_CHUNK} events each; a step is the least of its times over the rounds, the \
         clock's own cost included — see the last line; @ is the step's index from 0.)"
    );
    targets(&rows);
}

/// Issue #32's targets, family by family, from the registry rows of this run.
fn targets(rows: &[Row]) {
    println!("\n## Targets of issue #32 (this run)\n");
    println!("| family | impl/spec @100 | impl/spec @9900 | ≥ 3 | impl/baseline @9900 | ≥ 0.5 | impl/lex per block @9900 | ≤ 2 |");
    println!("|---|---:|---:|---|---:|---|---:|---|");
    let (mut met, mut missed) = (0, 0);
    for family in FAMILIES {
        let at = |size| rows.iter().find(|r| r.family == family.name && r.size == size);
        let (Some(small), Some(large)) = (at(100), at(9_900)) else {
            if std::env::var_os("CYCLECHECK_BENCH_CASES").is_some() {
                continue; // a filtered run: the family's cases were left out on purpose
            }
            println!("| {} | missing | missing | NO CASE | | | | |", family.name);
            missed += 1;
            continue;
        };
        let mut verdict = |ok: bool| {
            if ok {
                met += 1;
                "met"
            } else {
                missed += 1;
                "**not met**"
            }
        };
        let spec_ok = verdict(small.impl_spec >= 3.0 && large.impl_spec >= 3.0);
        let base = if SEVERAL_MOVES.contains(&family.name) {
            (format!("{:.2}", large.impl_baseline), verdict(large.impl_baseline >= 0.5))
        } else {
            (format!("({:.2})", large.impl_baseline), "—")
        };
        let lex = if ONE_BLOCK.contains(&family.name) {
            (format!("{:.2}", large.impl_lex), verdict(large.impl_lex <= 2.0))
        } else {
            (format!("({:.2})", large.impl_lex), "—")
        };
        println!(
            "| {} | {:.2} | {:.2} | {spec_ok} | {} | {} | {} | {} |",
            family.name, small.impl_spec, large.impl_spec, base.0, base.1, lex.0, lex.1
        );
    }
    println!("\n{met} targets met, {missed} not met (a figure in parentheses has no target).");
}
