//! Performance of the production expander (issue: performance, measured against the limit).
//!
//! The cases: each registry family's bench case (`cycle_kernel::registry`) at 1, 100 and 9 900
//! passes (thread blocks for G32), two G76 extremes, and G71 per layer: contours of 10, 100 and
//! 1 000 elements roughed in 10, 1 000 and 10 000 layers (`g71/<layers>_layers_<n>_elements`;
//! the table adds the production expander's time per layer to the case's name).
//!
//! For each case, four measurements over the same trace, all reported as events per second
//! (criterion throughput in elements = events):
//! - `baseline`: writes the case's events, already computed, one by one into a preallocated
//!   buffer — the memory-bound limit of producing that many events of that size;
//! - `impl`: the production expander writing the program's events into a buffer of the same
//!   size with `Expander::fill` (its batch API);
//! - `impl_iter`: the production expander as a streaming iterator, each event pushed into a
//!   preallocated buffer;
//! - `spec`: the executable reference expanding the program (owned trace).
//!
//! After criterion's own output, a table prints each case's figures as ratios (impl / baseline,
//! impl / spec), the time per event and the time to the cycle's first move (latency), the five
//! measurements of a case taken in turn over 15 rounds, each the least time (see [`table`]). The README's table is
//! copied from that output. `cargo bench -p cycle-tests --bench expand -- no_such_bench` runs no
//! criterion benchmark (the filter matches none) and prints only the table.

use criterion::{black_box, BenchmarkId, Criterion, Throughput};
use cycle_impl::Expander;
use cycle_kernel::registry::{BENCH_SIZES, FAMILIES};
use cycle_vocab::{Config, Event, MoveKind};
use std::time::{Duration, Instant};

/// One benchmark case: a program, its configuration, and the figures measured for it.
struct Case {
    name: String,
    program: String,
    config: Config,
    /// The layers of a per-layer case (the table reports the time per layer).
    layers: Option<usize>,
}

/// G76 with a minimum cut that is never reached (Δd = 0.2, Δdmin = 0.001: the switch of
/// G76.DEPTH.MIN would come after pass 10 000): the root grows by more than one increment per
/// pass (Δd/(2√n): ~1–3.5 from pass ~800 on, more before), so every pass checks several
/// candidates for it and the first ~800 take a square root — the costliest pass change of a
/// single-start cycle.
fn g76_min_cut_unreached() -> Case {
    let p = "G0 X80 Z5\nG76 P011060 Q0.001 R0.1\nG76 X27.4 Z-20 P20.0 Q0.2 F2\n";
    Case { name: "g76/9900_min_cut_unreached".into(), program: p.into(), config: Config::default(), layers: None }
}

/// The hardest legal inputs: the largest lengths of the grid, multi-start, a Δd = Δdmin tie,
/// a steep taper, 99 spring passes, seven starts: 9 086 thread cuts, near the bound.
fn extreme() -> Case {
    let p = "G0 X999999.999 Z999999.999\nG76 P996060 Q0.5 R0.5 L7\n\
             G76 X-999999.999 Z-999999.999 R-1000 P600 Q0.5 F9999\n";
    Case { name: "g76/extreme_ranges".into(), program: p.into(), config: Config::default(), layers: None }
}

/// Each registry family's bench case at each size (`g92/100`, `g76/9900`, …), then the extremes,
/// then G71 per layer.
fn cases() -> Vec<Case> {
    let mut v = Vec::new();
    for family in FAMILIES {
        for n in BENCH_SIZES {
            let case = (family.bench)(n);
            v.push(Case { name: format!("{}/{n}", family.name), program: case.text(), config: case.config, layers: None });
        }
    }
    v.push(g76_min_cut_unreached());
    v.push(extreme());
    for elements in [10, 100, 1_000] {
        for layers in [10, 1_000, 10_000] {
            let case = cycle_kernel::gen::contour::layers_bench(false, layers, elements);
            let name = format!("g71/{layers}_layers_{elements}_elements");
            v.push(Case { name, program: case.text(), config: case.config, layers: Some(layers) });
        }
    }
    v
}

/// The case's trace from the production expander: its events, checked to end without alarm.
fn events(case: &Case) -> Vec<Event> {
    let mut out = Vec::new();
    for item in Expander::new(case.program.as_bytes(), case.config) {
        match item {
            Ok(e) => out.push(e),
            Err(a) => panic!("bench case {} alarms: {a:?}", case.name),
        }
    }
    out
}

/// The production expander's batch API: the events written straight into `buffer`.
fn impl_into(buffer: &mut [Event], case: &Case) {
    let mut expander = Expander::new(case.program.as_bytes(), case.config);
    let mut n = 0;
    while let Some(rest) = buffer.get_mut(n..).filter(|r| !r.is_empty()) {
        match expander.fill(rest) {
            Ok(0) => break,
            Ok(k) => n += k,
            Err(a) => panic!("bench case {} alarms: {a:?}", case.name),
        }
    }
    black_box(&buffer);
}

/// The production expander's iterator, each event pushed into a preallocated buffer.
fn iter_into(buffer: &mut Vec<Event>, case: &Case) {
    buffer.clear();
    for e in Expander::new(case.program.as_bytes(), case.config).flatten() {
        buffer.push(e);
    }
    black_box(&buffer);
}

/// The latency: the production expander from the start of the program to the cycle's first
/// move (the first move after a pass header, or the first thread move of thread blocks, which
/// have no pass headers) — every block read and checked, the cycle's checks and its pass-count
/// bound done. The rapid of the program's first block comes before the cycle and does not count.
fn first_cycle_move(case: &Case) -> Option<Event> {
    let mut in_cycle = false;
    for item in Expander::new(case.program.as_bytes(), case.config) {
        match item {
            Ok(Event::Pass(_)) => in_cycle = true,
            Ok(e @ Event::Move(m)) if in_cycle || m.kind == MoveKind::Thread => return Some(e),
            Ok(Event::Move(_) | Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_)) => {}
            Err(_) => return None,
        }
    }
    None
}

/// The memory-bound limit: the same events, already computed, written one by one into the same
/// buffer. The compiler may turn this loop into a block copy — that is the limit.
fn baseline_into(buffer: &mut [Event], events: &[Event]) {
    for (slot, e) in buffer.iter_mut().zip(events) {
        *slot = *e;
    }
    black_box(&buffer);
}

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

/// How many calls of `f` last at least 2 ms.
fn reps_for(f: &mut dyn FnMut()) -> u32 {
    let mut reps = 1u32;
    loop {
        if time_ns(reps, f) * f64::from(reps) >= 2e6 || reps >= 1 << 20 {
            return reps;
        }
        reps *= 2;
    }
}

/// The time of one call of `f`, in ns, over `reps` calls.
fn time_ns(reps: u32, f: &mut dyn FnMut()) -> f64 {
    let t = Instant::now();
    for _ in 0..reps {
        f();
    }
    t.elapsed().as_nanos() as f64 / f64::from(reps)
}

fn least(v: &[f64]) -> f64 {
    v.iter().copied().fold(f64::INFINITY, f64::min)
}

/// Rounds per figure of the summary table.
const ROUNDS: usize = 15;

/// The summary table: figures measured in this run. The five measurements of a case are taken
/// in turn, round after round, and each figure is the least time over the rounds: on a shared
/// VM whose speed drifts, through spells that slow computing more than copying, the least time
/// is the one undisturbed; ratios are those of the least times.
fn table(cases: &[Case]) {
    println!("\n## cyclecheck expander figures (this run)\n");
    println!(
        "| case | events | impl Mev/s | impl_iter Mev/s | baseline Mev/s | spec Mev/s | impl/baseline | impl/spec | impl_iter/baseline | ns/event | first move ns |"
    );
    println!("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|");
    for case in cases {
        let events = events(case);
        assert!(first_cycle_move(case).is_some(), "bench case {}: no cycle move", case.name);
        let n = events.len() as f64;
        let (mut copied, mut filled) = (events.clone(), events.clone());
        let mut pushed = Vec::with_capacity(events.len());
        let mut base = || baseline_into(&mut copied, black_box(&events));
        let mut imp = || impl_into(&mut filled, black_box(case));
        let mut iter = || iter_into(&mut pushed, black_box(case));
        let mut spec = || {
            black_box(cycle_spec::expand(black_box(case.program.as_bytes()), &case.config));
        };
        let mut first = || {
            black_box(first_cycle_move(black_box(case)));
        };
        let mut measures: [&mut dyn FnMut(); 5] = [&mut base, &mut imp, &mut iter, &mut spec, &mut first];
        let reps: Vec<u32> = measures.iter_mut().map(|f| reps_for(&mut **f)).collect();
        let mut ns = vec![Vec::new(); 5];
        for _ in 0..ROUNDS {
            for ((f, &r), times) in measures.iter_mut().zip(&reps).zip(&mut ns) {
                times.push(time_ns(r, &mut **f));
            }
        }
        assert_eq!(filled, events, "bench case {}: fill wrote other events", case.name);
        let [base, imp, iter, spec, first] = [0, 1, 2, 3, 4].map(|i| least(&ns[i]));
        let rate = |ns: f64| n / ns * 1e3; // events per ns → M events per s
        let name = match case.layers {
            Some(layers) => format!("{} ({:.1} ns/layer)", case.name, imp / layers as f64),
            None => case.name.clone(),
        };
        println!(
            "| {} | {} | {:.1} | {:.1} | {:.1} | {:.2} | {:.2} | {:.2} | {:.2} | {:.1} | {:.0} |",
            name,
            events.len(),
            rate(imp),
            rate(iter),
            rate(base),
            rate(spec),
            base / imp,
            spec / imp,
            base / iter,
            imp / n,
            first
        );
    }
}

fn main() {
    let cases = cases();
    let mut c = Criterion::default().configure_from_args();
    bench(&mut c, &cases);
    c.final_summary();
    table(&cases);
}
