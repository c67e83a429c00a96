//! The production expander allocates nothing (issue: performance; impl is `no_std` without an
//! allocator, and this checks it at run time too): a counting global allocator counts the
//! allocations made on this test's thread while whole programs are expanded. Every registry
//! family has its own test (#32): its bench cases and cases of its generator.

use cycle_kernel::gen::{self, KNOBS};
use cycle_kernel::registry::{self, CycleRun, FAMILIES};
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
        cycle_kernel::corpus::PROGRAMS.iter().map(|p| (p.text, p.config())).collect();
    programs.extend([
        (include_str!("../programs/g92_inch.nc"), inch_isc),
        ("G0 X40 Z5\nG76 P011060 Q0 R0.1\nG76 X27.4 Z-20 P1.09 Q0.01 F2\n", metric), // 9 801 rough passes
        ("G0 X40 Z5\nG76 X30 Z-20 F2\n", metric),                                 // alarm: missing P
        ("\u{1}\u{2}garbage(", metric),
        ("G0 X30 Z5\nG162 X24 Z-20 H500 P10.001 Q0.001 V1 A29.5 F1.5 B90 I-0.1 J180\n", nc201), // 10 001 passes: alarm
        ("G0 X30 Z5\nG162 X24 Z-20 H500 P9.999 Q0.001 V1 A29.5 F1.5 B90 I-0.1 J180\n", nc201), // 9 999 passes
        ("G0 X30 Z5\nG34 X30 Z-20 F2 K-0.05\nG34 W-1 F2 K-5\n", metric), // ends in the G34 bound alarm
        ("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nX39\nX38\nG94 X20 Z-1 K-1\nZ-2\nG90 X40 Z2\n", metric), // the last: GEOMETRY on Z (W = 0)
        // G73 (both formats), G74, G75, G83, G84 (#21), near their bounds and ending in alarms.
        ("G0 X50 Z10\nG73 U18 W5 R10\nG73 P50 Q100 U0.5 W0.5 F100\nN50 G01 X0 Z1\nN60 G03 X12 W-6 R6\nN70 G01 W-10\nN80 X20 W-15\nN90 W-13\nN100 G02 X34 W-7 R7\nG70 P50 Q100 F30\n", metric),
        ("G0 X50 Z5\nG73 P1 Q2 I1 K1 D5000 F1\nN1 G0 X10\nN2 G1 Z-10\nG73 P1 Q2 I1 K1 D10001 F1\nN1 G0 X10\nN2 G1 Z-10\n", metric), // 5 000 passes, then the bound
        ("G0 X0 Z2\nG74 R1\nG74 Z-12 Q5 F30\nG74 Z-10 Q0.001 F1\nG00 X20 Z1\nG74 R0.5\nG74 X40 Z-5 P3 Q2 R0.2 F0.05\nG74 Z-999999.999 Q0.001\n", metric), // 10 000 pecks; bound
        ("G0 X42 Z22\nG75 R1\nG75 X30 Z10 P3 Q2.9 F30\nG75 X40 Z-20 P2 Q3 R0.3\nG75 X30 Z10 P0 Q1\n", metric), // the last: MISSING WORD P
        ("G0 X0 Z3\nG83 Z-30 R0.5 Q2000 P500 F0.2\nG83 Z-10 Q1 F1\nG83 Z-10.001 Q1 F1\n", metric), // 10 000 pecks; bound
        ("G0 X0 Z5\nG98 M29 S60 G84 Z-21 R2 P200 F60 G80\nG99 M29 G84 Z-15 R-3 F1.25\nG84 Z-5 F1\n", metric), // the last: no M29
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

/// Subprograms (M98/M99: the call stack is fixed, the area is searched in place) and the spindle
/// rules (G50 S, G96, G97, G84's rpm) allocate nothing either, alarms included.
#[test]
fn subprograms_and_spindle_speed_allocate_nothing() {
    let metric = Config::default();
    let programs = [
        // O1000 four times, each calling O2000 (nesting 2), then M30 in the main program.
        "G50 S2000\nG0 X40 Z5\nM98 P41000\nG0 X60\nM30\nO1000\nG1 U-1 F0.2\nM98 P2000\nM99\nO2000\nG90 X30 Z-10 F0.3\nM99\n",
        // G97 S60 taps at F / 60 under G98; G96 with its maximum; a rapid after G97.
        "G50 X60 Z40 S1500\nG00 X0 Z0\nG97 S60\nG98 M29\nG84 Z-21 R2 F60\nG96 S200\nG1 X10 F1\nG97\nG0 X60\n",
        // Alarms: recursion (NESTING), no M99, G96 without a maximum.
        "M98 P1\nM30\nO1\nG0 U1\nM98 P1\nM99\n",
        "M98 P3\nM30\nO3\nG0 X1\n",
        "G96 S200\n",
    ];
    for program in programs {
        let (events, alarmed, allocations) = expand_counting(program.as_bytes(), metric);
        assert_eq!(allocations, 0, "the production expander allocated on:\n{program}");
        assert_eq!(fill_counting(program.as_bytes(), metric), (events, alarmed, 0), "{program}");
    }
}

/// Generated cases per family.
const DRAWN: u64 = 48;

/// The knobs of drawn case `seed`: a fixed xorshift stream, the same cases every run.
fn knobs(seed: u64) -> Vec<u32> {
    let mut x = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
    (0..KNOBS)
        .map(|_| {
            x ^= x << 13;
            x ^= x >> 7;
            x ^= x << 17;
            (x >> 32) as u32
        })
        .collect()
}

/// The family `name` allocates nothing: its bench cases at 1 and 100 passes (each runs the
/// family's cycle to its end without an alarm) and [`DRAWN`] cases of its generator under
/// readings drawn with them (alarms included), through the iterator and through `fill`; at
/// least a quarter of the drawn cases must select the family.
fn family_allocates_nothing(name: &str) {
    let family = registry::find(name).unwrap_or_else(|| panic!("no registry family {name}"));
    let selects = |case: &gen::Case| registry::cycle_run(&case.program, &case.config, None) == CycleRun::Family(family);
    for n in [1, 100] {
        let case = (family.bench)(n);
        assert!(selects(&case), "{name}'s bench case does not run {name}:\n{}", case.text());
        let (events, alarmed, allocations) = expand_counting(&case.program, case.config);
        assert!(events > 0 && !alarmed, "{name}'s bench case at {n}: {events} events, alarm {alarmed}");
        assert_eq!(allocations, 0, "the production expander allocated on {name}'s bench case:\n{}", case.text());
        assert_eq!(fill_counting(&case.program, case.config), (events, false, 0), "fill on {name}'s bench case at {n}");
    }
    let mut selecting = 0;
    for seed in 0..DRAWN {
        let mut case = gen::build(family.build, &knobs(seed));
        case.config.readings = cycle_kernel::readings::from_bits(seed as u8);
        selecting += u64::from(selects(&case));
        let (events, alarmed, allocations) = expand_counting(&case.program, case.config);
        assert_eq!(allocations, 0, "the production expander allocated on {case:?}");
        assert_eq!(fill_counting(&case.program, case.config), (events, alarmed, 0), "fill on {case:?}");
    }
    assert!(selecting * 4 >= DRAWN, "only {selecting} of {DRAWN} drawn {name} cases select {name}");
}

/// One test per registry family.
macro_rules! families {
    ($($name:ident),* $(,)?) => {
        $(#[test]
        fn $name() {
            family_allocates_nothing(stringify!($name));
        })*

        /// The tests above name every registry family (a new family without its test fails).
        #[test]
        fn every_family_has_its_test() {
            let tested = [$(stringify!($name)),*];
            let registered: Vec<&str> = FAMILIES.iter().map(|f| f.name).collect();
            assert_eq!(tested.as_slice(), registered.as_slice());
        }
    };
}

mod family {
    use super::*;
    families!(g92, g76, g78, f76, g162, g32, g90, g94, g71, g72, g70, g73, g74, g75, g83, g84);
}
