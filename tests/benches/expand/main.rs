//! Performance of the production expander (issues: performance, measured against the limit;
//! #32, every family, the worst step).
//!
//! The cases ([`cases`]): each registry family's bench case (`cycle_kernel::registry`) at 1, 100
//! and 9 900 passes (thread blocks for G32; contour elements for G70, capped at CNT.MAX), two
//! G76 extremes, and G71 per layer: contours of 10, 100 and 1 000 elements roughed in 10, 1 000
//! and 10 000 layers (`g71/<layers>_layers_<n>_elements`; the table adds the production
//! expander's time per layer to the case's name).
//!
//! Criterion's part times, per case, over the same trace: `baseline` (the case's events,
//! already computed, written one by one into a preallocated buffer — the memory-bound limit),
//! `impl` (`Expander::fill` into a buffer of the same size), `impl_iter` (the iterator, each
//! event pushed into a preallocated buffer) and `spec` (the executable reference).
//!
//! Then the tables ([`table`], [`latency`]): per case the ratios impl / baseline and impl / spec
//! (least of 15 interleaved rounds), the worst single `next()` and `fill` call and their means
//! (each call timed alone with the monotonic clock in a pass of its own), the time to the
//! cycle's first move, the production lexer's cost per block and the expander's against it;
//! the targets of issue #32 met or not; the first-move latency against the contour's length.
//! `cargo bench -p cycle-tests --bench expand -- no_such_bench` runs no criterion benchmark
//! (the filter matches none) and prints only the tables; `CYCLECHECK_BENCH_QUICK=1` takes 3
//! rounds of 0.5 ms instead of 15 of 2 ms and the registry cases only (for iterating, not for
//! figures); `CYCLECHECK_BENCH_CASES=g162/9900,g74` keeps the cases named so;
//! `CYCLECHECK_BENCH_ROUNDS=n` takes n rounds; `CYCLECHECK_BENCH_PROFILE=5` only runs the
//! production expander (`fill`) on each case kept, 5 s each, for `perf record`.

mod cases;
mod latency;
mod measure;
mod table;

use cases::{baseline_into, events, impl_into, iter_into, Case};
use criterion::{black_box, BenchmarkId, Criterion, Throughput};
use std::time::Duration;

fn bench(c: &mut Criterion, cases: &[Case]) {
    for case in cases {
        let events = events(case);
        let mut group = c.benchmark_group(&case.name);
        group.throughput(Throughput::Elements(events.len() as u64));
        group.sample_size(20).measurement_time(Duration::from_secs(2)).warm_up_time(Duration::from_millis(500));
        let mut buffer = events.clone();
        let mut pushed = Vec::with_capacity(events.len());
        group.bench_function(BenchmarkId::from_parameter("baseline"), |b| {
            b.iter(|| baseline_into(&mut buffer, black_box(&events)))
        });
        group.bench_function(BenchmarkId::from_parameter("impl"), |b| b.iter(|| impl_into(&mut buffer, black_box(case))));
        group.bench_function(BenchmarkId::from_parameter("impl_iter"), |b| {
            b.iter(|| iter_into(&mut pushed, black_box(case)))
        });
        group.bench_function(BenchmarkId::from_parameter("spec"), |b| {
            b.iter(|| cycle_spec::expand(black_box(case.program.as_bytes()), &case.config))
        });
        group.finish();
    }
}

/// The production expander alone on each case for `seconds` (a workload for a profiler).
fn profile(cases: &[Case], seconds: f64) {
    for case in cases {
        let mut buffer = events(case);
        let start = std::time::Instant::now();
        let mut runs = 0u64;
        while start.elapsed().as_secs_f64() < seconds {
            impl_into(&mut buffer, black_box(case));
            runs += 1;
        }
        println!("{}: {runs} expansions in {seconds} s", case.name);
    }
}

fn main() {
    let mode = measure::Mode::from_env();
    let quick = mode.quick();
    let cases = cases::cases(quick);
    if let Some(seconds) = std::env::var("CYCLECHECK_BENCH_PROFILE").ok().and_then(|s| s.parse().ok()) {
        return profile(&cases, seconds);
    }
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c, &cases);
    c.final_summary();
    let (clock_least, clock_median) = measure::clock_cost();
    table::table(&cases, mode);
    latency::latency(mode);
    println!(
        "\nThe monotonic clock (`Instant::now` and `elapsed`, back to back) costs {clock_least:.0} ns at least, \
         {clock_median:.0} ns in the median of 10 000 readings; {} rounds per figure{}.",
        mode.rounds,
        if quick { " (QUICK MODE: not for figures)" } else { "" }
    );
}
