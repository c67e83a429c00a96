//! The bench's cases and the bodies it times: the production expander (batch and iterator), the
//! baseline copy, the production lexer alone, and the first cycle move.

use criterion::black_box;
use cycle_impl::lex::{Block, Blocks};
use cycle_impl::Expander;
use cycle_kernel::registry::{BENCH_SIZES, FAMILIES};
use cycle_vocab::{Config, Event, MoveKind};

/// One benchmark case: a program and its configuration.
pub struct Case {
    pub name: String,
    pub program: String,
    pub config: Config,
    /// The registry family's name (`g92`, …), for the targets of issue #32.
    pub family: &'static str,
    /// The size it was built at (passes, thread blocks or contour elements), if a registry size.
    pub size: Option<usize>,
    /// The layers of a per-layer case (the table reports the time per layer).
    pub layers: Option<usize>,
}

impl Case {
    fn new(name: String, family: &'static str, case: cycle_kernel::gen::Case) -> Case {
        Case { name, program: case.text(), config: case.config, family, size: None, layers: None }
    }
}

/// G76 with a minimum cut that is never reached (Δd = 0.2, Δdmin = 0.001: the switch of
/// G76.DEPTH.MIN would come after pass 10 000): the root grows by more than one increment per
/// pass, so every pass checks several candidates for it and the first ~800 take a square root —
/// the costliest pass change of a single-start cycle.
fn g76_min_cut_unreached() -> Case {
    let p = "G0 X80 Z5\nG76 P011060 Q0.001 R0.1\nG76 X27.4 Z-20 P20.0 Q0.2 F2\n";
    Case { name: "g76/9900_min_cut_unreached".into(), program: p.into(), config: Config::default(), family: "g76", size: None, layers: None }
}

/// The hardest legal inputs: the largest lengths of the grid, multi-start, a Δd = Δdmin tie,
/// a steep taper, 99 spring passes, seven starts: 9 086 thread cuts, near the bound.
fn extreme() -> Case {
    let p = "G0 X999999.999 Z999999.999\nG76 P996060 Q0.5 R0.5 L7\n\
             G76 X-999999.999 Z-999999.999 R-1000 P600 Q0.5 F9999\n";
    Case { name: "g76/extreme_ranges".into(), program: p.into(), config: Config::default(), family: "g76", size: None, layers: None }
}

/// Each registry family's bench case at each size (`g92/100`, `g76/9900`, …; G70's contour is
/// capped at CNT.MAX, so `g70/9900` is 999 elements), then the extremes, then G71 per layer.
/// `quick`: the registry sizes only. `CYCLECHECK_BENCH_CASES` set: the cases whose name starts
/// with one of its comma-separated prefixes (to profile one case: `g162/9900`).
pub fn cases(quick: bool) -> Vec<Case> {
    let mut v = all_cases(quick);
    if let Ok(only) = std::env::var("CYCLECHECK_BENCH_CASES") {
        v.retain(|c| only.split(',').any(|p| c.name.starts_with(p)));
    }
    v
}

fn all_cases(quick: bool) -> Vec<Case> {
    let mut v = Vec::new();
    for family in FAMILIES {
        for n in BENCH_SIZES {
            let mut case = Case::new(format!("{}/{n}", family.name), family.name, (family.bench)(n));
            case.size = Some(n);
            v.push(case);
        }
    }
    if quick {
        return v;
    }
    v.push(g76_min_cut_unreached());
    v.push(extreme());
    for elements in [10, 100, 1_000] {
        for layers in [10, 1_000, 10_000] {
            let bench = cycle_kernel::gen::contour::layers_bench(false, layers, elements);
            let mut case = Case::new(format!("g71/{layers}_layers_{elements}_elements"), "g71", bench);
            case.layers = Some(layers);
            v.push(case);
        }
    }
    v
}

/// A contour of `elements` blocks N1…N`elements` (a rapid to X10, then feeds out along a taper),
/// as G70 and G73 read it.
fn contour(elements: usize, x0: i64) -> String {
    let mut p = format!("N1 G00 X{}\n", fixed(x0));
    for i in 1..elements as i64 {
        p.push_str(&format!("N{} G01 X{} Z-{}\n", i + 1, fixed(x0 + 40 * i), fixed(30 * i)));
    }
    p
}

/// `v` thousandths as a decimal word value.
fn fixed(v: i64) -> String {
    format!("{}.{:03}", v / 1000, v % 1000)
}

/// The first-move latency cases: G70, G71, G72, G73 over a contour of `elements` blocks (G71/G72
/// rough 10 layers, G73 runs 10 passes).
pub fn contour_case(family: &'static str, elements: usize) -> Case {
    let program = match family {
        "g71" | "g72" => return Case::new(format!("{family}/{elements}"), family, cycle_kernel::gen::contour::layers_bench(family == "g72", 10, elements)),
        "g70" => format!("G00 X100 Z2\nG01 F0.2\n{}G00 X100 Z2\nG70 P1 Q{elements}\n", contour(elements, 10_000)),
        _ => format!("G00 X100 Z2\nG73 U10 W0 R10\nG73 P1 Q{elements} U0.2 W0.1 F0.2\n{}", contour(elements, 20_000)),
    };
    Case { name: format!("{family}/{elements}"), program, config: Config::default(), family, size: None, layers: None }
}

/// The case's trace from the production expander: its events, checked to end without alarm.
pub fn events(case: &Case) -> Vec<Event> {
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
pub fn impl_into(buffer: &mut [Event], case: &Case) {
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
pub fn iter_into(buffer: &mut Vec<Event>, case: &Case) {
    buffer.clear();
    for e in Expander::new(case.program.as_bytes(), case.config).flatten() {
        buffer.push(e);
    }
    black_box(&buffer);
}

/// The memory-bound limit: the same events, already computed, written one by one into the same
/// buffer. The compiler may turn this loop into a block copy — that is the limit.
pub fn baseline_into(buffer: &mut [Event], events: &[Event]) {
    for (slot, e) in buffer.iter_mut().zip(events) {
        *slot = *e;
    }
    black_box(&buffer);
}

/// The production lexer alone (`cycle_impl::lex::Blocks::read`, each block built in one
/// `Block` as the expander does): the blocks of `program` read, nothing else; their count.
pub fn lex_all(program: &[u8]) -> u64 {
    let mut blocks = Blocks::new(program);
    let mut block = Block::new();
    let mut n = 0;
    while let Ok(true) = blocks.read(black_box(&mut block)) {
        n += 1;
    }
    black_box(&block);
    n
}

/// The latency: the production expander from the start of the program to the cycle's first
/// move (the first move after a pass header, or the first thread move of thread blocks, which
/// have no pass headers) — every block read and checked, the cycle's checks and its pass-count
/// bound done. The rapid of the program's first block comes before the cycle and does not count.
pub fn first_cycle_move(case: &Case) -> Option<Event> {
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
