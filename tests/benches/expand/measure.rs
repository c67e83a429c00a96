//! Timing: the least of interleaved rounds for throughput, and the worst step — each `next()`
//! and each `fill` call timed alone with the monotonic clock in a pass of its own.

use super::cases::Case;
use criterion::black_box;
use cycle_impl::Expander;
use cycle_vocab::{Event, Move, Rule};
use std::time::Instant;

/// The events each timed `fill` call may write (a controller's batch; the worst-step column).
pub const FILL_CHUNK: usize = 64;

/// How the run measures: rounds per figure and the least duration of one timed repetition.
#[derive(Clone, Copy)]
pub struct Mode {
    pub rounds: usize,
    pub min_ns: f64,
}

impl Mode {
    /// 15 rounds of at least 2 ms each; `CYCLECHECK_BENCH_QUICK` set: 3 rounds of 0.5 ms;
    /// `CYCLECHECK_BENCH_ROUNDS=n`: n rounds (more on a loaded machine).
    pub fn from_env() -> Mode {
        let mut mode = if std::env::var_os("CYCLECHECK_BENCH_QUICK").is_some() {
            Mode { rounds: 3, min_ns: 5e5 }
        } else {
            Mode { rounds: 15, min_ns: 2e6 }
        };
        if let Some(n) = std::env::var("CYCLECHECK_BENCH_ROUNDS").ok().and_then(|n| n.parse().ok()) {
            mode.rounds = n;
        }
        mode
    }

    /// Whether the run is the quick one.
    pub fn quick(self) -> bool {
        self.min_ns < 2e6
    }
}

/// How many calls of `f` last at least `min_ns`.
fn reps_for(min_ns: f64, f: &mut dyn FnMut()) -> u32 {
    let mut reps = 1u32;
    loop {
        if time_ns(reps, f) * f64::from(reps) >= min_ns || reps >= 1 << 20 {
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

/// The measurements `fs` taken in turn, round after round, each the least time of one call (ns)
/// over the rounds: on a shared VM whose speed drifts, the least time is the undisturbed one.
pub fn least_of_rounds(mode: Mode, fs: &mut [&mut dyn FnMut()]) -> Vec<f64> {
    let reps: Vec<u32> = fs.iter_mut().map(|f| reps_for(mode.min_ns, &mut **f)).collect();
    let mut least = vec![f64::INFINITY; fs.len()];
    for _ in 0..mode.rounds {
        for ((f, &r), l) in fs.iter_mut().zip(&reps).zip(&mut least) {
            *l = l.min(time_ns(r, &mut **f));
        }
    }
    least
}

/// The steps of an expansion: the longest (ns), where it was (the step's index, from 0), and the
/// mean (ns); both include the clock's own cost ([`clock_cost`]).
#[derive(Clone, Copy)]
pub struct Steps {
    pub max: f64,
    pub at: usize,
    pub mean: f64,
}

/// Each step's least duration over the rounds, kept in `least` (the expansion is the same every
/// round, step for step): a step that a preemption or the VM disturbs in one round is measured
/// undisturbed in another, and a step that is long every round stays long.
struct StepMin<'a> {
    least: &'a mut Vec<u64>,
    round: usize,
    step: usize,
}

impl<'a> StepMin<'a> {
    fn new(least: &'a mut Vec<u64>) -> StepMin<'a> {
        least.clear();
        StepMin { least, round: 0, step: 0 }
    }

    fn start_round(&mut self) {
        self.round += 1;
        self.step = 0;
    }

    fn record(&mut self, t: Instant) {
        let d = t.elapsed().as_nanos() as u64;
        match self.least.get_mut(self.step) {
            Some(l) => *l = (*l).min(d),
            None => {
                assert_eq!(self.round, 1, "the expansion took more steps in a later round");
                self.least.push(d);
            }
        }
        self.step += 1;
    }

    fn steps(&self) -> Steps {
        let (at, max) = self.least.iter().copied().enumerate().max_by_key(|&(_, d)| d).unwrap_or((0, 0));
        let mean = self.least.iter().sum::<u64>() as f64 / self.least.len().max(1) as f64;
        Steps { max: max as f64, at, mean }
    }
}

/// The worst step of the iterator: every `next()` of a whole expansion timed alone with the
/// monotonic clock (the call returning `None` included), over `rounds` expansions; each step's
/// least time ([`StepMin`]), then the longest of them and their mean.
pub fn worst_next(case: &Case, rounds: usize, scratch: &mut Vec<u64>) -> Steps {
    let mut steps = StepMin::new(scratch);
    for _ in 0..rounds {
        steps.start_round();
        let mut expander = Expander::new(case.program.as_bytes(), case.config);
        loop {
            let t = Instant::now();
            let item = expander.next();
            steps.record(t);
            if black_box(item).is_none() {
                break;
            }
        }
    }
    steps.steps()
}

/// The worst step of the batch API: every `fill` call into a buffer of [`FILL_CHUNK`] events
/// timed alone (the last, returning 0, included), as [`worst_next`].
pub fn worst_fill(case: &Case, rounds: usize, scratch: &mut Vec<u64>) -> Steps {
    let mut buffer = [Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); FILL_CHUNK];
    let mut steps = StepMin::new(scratch);
    for _ in 0..rounds {
        steps.start_round();
        let mut expander = Expander::new(case.program.as_bytes(), case.config);
        loop {
            let t = Instant::now();
            let written = expander.fill(&mut buffer);
            steps.record(t);
            black_box(&buffer);
            match written {
                Ok(0) => break,
                Ok(_) => {}
                Err(a) => panic!("bench case {} alarms: {a:?}", case.name),
            }
        }
    }
    steps.steps()
}

/// The clock's own cost: the least and the median of 10 000 back-to-back readings (ns), which
/// every timed step includes.
pub fn clock_cost() -> (f64, f64) {
    let mut d: Vec<u64> = (0..10_000)
        .map(|_| {
            let t = Instant::now();
            t.elapsed().as_nanos() as u64
        })
        .collect();
    d.sort_unstable();
    (d[0] as f64, d[d.len() / 2] as f64)
}
