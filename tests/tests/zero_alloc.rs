//! The production expander allocates nothing (issue: performance; impl is `no_std` without an
//! allocator, and this checks it at run time too): a counting global allocator counts the
//! allocations made on this test's thread while whole programs are expanded.

use cycle_vocab::{Config, Dialect, Event, Grid, Increment, Move, Rule, Units};
use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

struct Counting;

thread_local! {
    static COUNTING: Cell<bool> = const { Cell::new(false) };
    static COUNT: Cell<u64> = const { Cell::new(0) };
}

unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        if COUNTING.with(|c| c.get()) {
            COUNT.with(|n| n.set(n.get() + 1));
        }
        System.alloc(layout)
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        System.dealloc(ptr, layout)
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        if COUNTING.with(|c| c.get()) {
            COUNT.with(|n| n.set(n.get() + 1));
        }
        System.realloc(ptr, layout, new_size)
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// Expands `program` with the production expander's iterator and returns (events, alarm?,
/// allocations).
fn expand_counting(program: &[u8], config: Config) -> (u64, bool, u64) {
    let mut events = 0;
    let mut alarmed = false;
    COUNT.with(|n| n.set(0));
    COUNTING.with(|c| c.set(true));
    for item in cycle_impl::Expander::new(program, config) {
        match item {
            Ok(_) => events += 1,
            Err(_) => alarmed = true,
        }
    }
    COUNTING.with(|c| c.set(false));
    (events, alarmed, COUNT.with(|n| n.get()))
}

/// The same with `Expander::fill` into a buffer of 100 events allocated before counting starts.
fn fill_counting(program: &[u8], config: Config) -> (u64, bool, u64) {
    let mut buffer = vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); 100];
    let mut events = 0;
    let mut alarmed = false;
    COUNT.with(|n| n.set(0));
    COUNTING.with(|c| c.set(true));
    let mut expander = cycle_impl::Expander::new(program, config);
    loop {
        match expander.fill(&mut buffer) {
            Ok(0) => break,
            Ok(n) => events += n as u64,
            Err(_) => alarmed = true,
        }
    }
    COUNTING.with(|c| c.set(false));
    (events, alarmed, COUNT.with(|n| n.get()))
}

#[test]
fn counting_allocator_sees_allocations() {
    // The counter itself must be able to fail: a Vec on this thread is counted.
    COUNT.with(|n| n.set(0));
    COUNTING.with(|c| c.set(true));
    let v: Vec<u64> = std::hint::black_box(Vec::with_capacity(8));
    COUNTING.with(|c| c.set(false));
    drop(v);
    assert_eq!(COUNT.with(|n| n.get()), 1);
}

#[test]
fn expanding_any_cycle_allocates_nothing() {
    let metric = Config::default();
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    let inch_isc = Config { grid: Grid { units: Units::Inch, increment: Increment::Isc }, ..Config::default() };
    // Every built-in program (every family: the manuals' examples and the feature programs),
    // then near-bound cycles and alarms.
    let mut programs: Vec<(&str, Config)> =
        cycle_oracle::corpus::PROGRAMS.iter().map(|p| (p.text, p.config())).collect();
    programs.extend([
        (include_str!("../programs/g92_inch.nc"), inch_isc),
        ("G0 X40 Z5\nG76 P011060 Q0 R0.1\nG76 X27.4 Z-20 P1.09 Q0.01 F2\n", metric), // 9 801 rough passes
        ("G0 X40 Z5\nG76 X30 Z-20 F2\n", metric),                                 // alarm: missing P
        ("\u{1}\u{2}garbage(", metric),
        ("G0 X30 Z5\nG162 X24 Z-20 H500 P10.001 Q0.001 V1 A29.5 F1.5 B90 I-0.1 J180\n", nc201), // 10 001 passes: alarm
        ("G0 X30 Z5\nG162 X24 Z-20 H500 P9.999 Q0.001 V1 A29.5 F1.5 B90 I-0.1 J180\n", nc201), // 9 999 passes
        ("G0 X30 Z5\nG34 X30 Z-20 F2 K-0.05\nG34 W-1 F2 K-5\n", metric), // ends in the G34 bound alarm
        ("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nX39\nX38\nG94 X20 Z-1 K-1\nZ-2\nG90 X40 Z2\n", metric), // the last: GEOMETRY on Z (W = 0)
    ]);
    let mut total_events = 0;
    for (program, config) in &programs {
        let (events, alarmed, allocations) = expand_counting(program.as_bytes(), *config);
        assert_eq!(allocations, 0, "the production expander allocated on:\n{program}");
        let filled = fill_counting(program.as_bytes(), *config);
        assert_eq!(filled, (events, alarmed, 0), "Expander::fill: (events, alarm, allocations) on:\n{program}");
        total_events += events;
    }
    assert!(total_events > 10_000, "the programs must exercise the expander ({total_events} events)");
}
