//! proptest strategies: programs with the configuration they run under, one generator per
//! cycle family of the registry ([`crate::registry`]) and one of garbage.
//!
//! Generators (a module each):
//! - [`g92`]: G92 programs, valid and invalid — missing lead, out-of-range words, bad tapers,
//!   every J/K combination, multi-start, inch and ISC grids, modal repeats and new runs.
//! - [`multipass`]: G76 / G78 / FANUC G76 two-block programs (three families, one builder) over
//!   the whole legal input space, with the edge cases the rules turn on: Δd against Δdmin and
//!   k − d (ties included), taper, internal threads, inch, every infeed and depth mode, E
//!   lead-in, J/K, multi-start, the pass bound, and words just outside their ranges.
//! - [`g162`]: G162 programs under `nc201` (M004), valid and invalid.
//! - [`thread_moves`]: G32 / G33 / G34 programs (M003), valid and invalid.
//! - [`single_cut`]: G90 / G94 single cutting cycles (M003), valid and invalid.
//! - [`contour`]: G71 / G72 stock removal over random monotone contours of lines and arcs, then
//!   G70, and G70 alone (M003), with the register's contour, arc, G50 and nose-radius alarms at
//!   a controlled rate; G73 pattern repeating over the same contours, both formats.
//! - [`peck`]: G74 / G75 peck cycles (M003), valid and invalid.
//! - [`drill`]: G83 peck drilling and G84 rigid tapping (M003, read as FANUC lathe controls
//!   do), valid and invalid.
//! - [`garbage`]: random bytes, random word soup, and the corpus with a few bytes changed.
//! - [`program`]: the program-structure wrappers every built case may get — a subprogram
//!   (M98/M99) running part of it, a spindle-mode prelude (G50 S, G96, G97).
//!
//! Every structured case is built from a fixed-length vector of random *knobs* (`u32`s) by a
//! deterministic builder ([`Builder`]): the builder draws each decision from the next knob, and
//! a knob of 0 always takes the ordinary choice. proptest shrinks knobs toward 0, so a failing
//! case shrinks toward the plainest program that still fails. The [`SPELLING_KNOBS`] knobs from
//! [`SPELLING_AT`] choose the program's spelling ([`writer::Spelling`]), which no builder draws
//! otherwise; the [`program::STRUCTURE_KNOBS`] after them its structure ([`program::wrap`]). Each case's
//! declared readings are drawn beside the knobs ([`drawn`]).
//!
//! Pass counts stay moderate: Δd is chosen relative to k − d so that a degressive schedule has
//! at most about 40 rough passes (a constant one fewer), starts are few, and a large pass count
//! is only reached through a small `max_passes` — so a case typically runs in well under a
//! millisecond.

pub mod contour;
pub mod drill;
pub mod g162;
pub mod g92;
pub mod garbage;
pub mod multipass;
pub mod operator;
pub mod peck;
pub mod program;
pub mod single_cut;
pub mod thread_moves;
pub mod writer;

use crate::registry::FAMILIES;
use cycle_vocab::{Config, Dialect, Grid, Increment, Units};
use proptest::prelude::*;
use std::fmt;

/// A generated case: program text and configuration.
#[derive(Clone, PartialEq, Eq)]
pub struct Case {
    /// The generator: a registry family's name (`g92`, `g76`, …, `g71`, `g72`, `g70`), a
    /// garbage generator's (`bytes`, `soup`, `mutant`) or `operator` (a thread case with an
    /// operator script).
    pub family: &'static str,
    pub program: Vec<u8>,
    pub config: Config,
}

impl Case {
    /// The program as text (lossy for non-UTF-8 bytes).
    pub fn text(&self) -> String {
        String::from_utf8_lossy(&self.program).into_owned()
    }
}

impl fmt::Debug for Case {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(f, "Case {} under {:?}", self.family, self.config)?;
        match std::str::from_utf8(&self.program) {
            Ok(text) => write!(f, "program:\n{text}"),
            Err(_) => write!(f, "program (bytes): {:?}", self.program),
        }
    }
}

/// The 32-byte ChaCha seed of a campaign from a `u64` (`CYCLECHECK_SEED`, `--seed`): the same
/// expansion everywhere, so one number names one run.
pub fn seed_bytes(seed: u64) -> [u8; 32] {
    let mut bytes = [0u8; 32];
    for (i, chunk) in bytes.chunks_mut(8).enumerate() {
        chunk.copy_from_slice(&(seed.rotate_left(16 * i as u32) ^ i as u64).to_le_bytes());
    }
    bytes
}

/// How many knobs a structured case draws from: the builder's, then the spelling's
/// ([`SPELLING_AT`]), then the structure's ([`STRUCTURE_AT`]).
pub const KNOBS: usize = STRUCTURE_AT + program::STRUCTURE_KNOBS;

/// How many knobs choose the spelling ([`writer::Spelling`]): no builder reaches them.
pub const SPELLING_KNOBS: usize = 16;

/// The first spelling knob: the builders draw from the knobs before it.
pub const SPELLING_AT: usize = 240;

/// The first of the [`program::STRUCTURE_KNOBS`] knobs, after the spelling knobs: they choose
/// the program-structure wrappers ([`program::wrap`]). Knobs past the end of a short knob list
/// are 0, so a fuzz input written before they existed builds the program it built then.
pub const STRUCTURE_AT: usize = SPELLING_AT + SPELLING_KNOBS;

/// The knobs: `KNOBS` random `u32`s.
pub fn knobs() -> impl Strategy<Value = Vec<u32>> {
    proptest::collection::vec(any::<u32>(), KNOBS)
}

/// A knob builder: the case its dice describe.
pub type Builder = fn(&mut Dice) -> Case;

/// The knobs `knobs[from..from + n]`, as many of them as there are.
fn window(knobs: &[u32], from: usize, n: usize) -> &[u32] {
    knobs.get(from..).map_or(&[][..], |k| &k[..k.len().min(n)])
}

/// The case the knobs describe; knobs past the end of `knobs` are 0 (the ordinary choice). The
/// builder's program, then the program-structure wrappers ([`program::wrap`]) from their knobs.
pub fn build(builder: Builder, knobs: &[u32]) -> Case {
    let case = builder(&mut Dice::new(knobs));
    program::wrap(case, &mut Dice::new(window(knobs, STRUCTURE_AT, program::STRUCTURE_KNOBS)))
}

/// The cases of one builder, each under readings drawn for it ([`drawn`]).
pub fn strategy(builder: Builder) -> BoxedStrategy<Case> {
    drawn(knobs().prop_map(move |k| build(builder, &k)))
}

/// `cases`, each under declared readings drawn for it (`crate::readings::from_bits`): each
/// reading its letter half the time, so both engines run under every value. The draw shrinks
/// toward the letter. A candidate run overrides them with the run's readings.
pub fn drawn(cases: impl Strategy<Value = Case> + 'static) -> BoxedStrategy<Case> {
    (cases, any::<u8>())
        .prop_map(|(mut case, bits)| {
            case.config.readings = crate::readings::from_bits(bits);
            case
        })
        .boxed()
}

/// Any case: each registry family's generator, and garbage, alike often.
pub fn any_case() -> impl Strategy<Value = Case> {
    let mut all: Vec<BoxedStrategy<Case>> = FAMILIES.iter().map(|f| f.strategy()).collect();
    all.push(garbage::strategy());
    proptest::strategy::Union::new(all)
}

// ---------------------------------------------------------------------------------------------
// Decisions

/// Draws decisions from the knobs; past the last knob every draw is 0 (the ordinary choice).
pub struct Dice<'a> {
    knobs: &'a [u32],
    at: usize,
    /// The last [`SPELLING_KNOBS`] knobs of the case, kept by every fork ([`Dice::spelling`]).
    spelling: &'a [u32],
}

impl<'a> Dice<'a> {
    pub fn new(knobs: &'a [u32]) -> Dice<'a> {
        Dice { knobs, at: 0, spelling: window(knobs, SPELLING_AT, SPELLING_KNOBS) }
    }

    /// Dice over the case's spelling knobs (the same from every fork).
    pub fn spelling(&self) -> Dice<'a> {
        Dice { knobs: self.spelling, at: 0, spelling: &[] }
    }

    fn next(&mut self) -> u32 {
        let v = self.knobs.get(self.at).copied().unwrap_or(0);
        self.at += 1;
        v
    }

    /// 0…n−1 (0 when n = 0).
    pub fn below(&mut self, n: u64) -> u64 {
        let v = self.next() as u64;
        if n == 0 {
            0
        } else {
            v % n
        }
    }

    /// lo…hi inclusive (lo when hi < lo); the knob 0 gives lo.
    pub fn range(&mut self, lo: i64, hi: i64) -> i64 {
        if hi <= lo {
            return lo;
        }
        let span = (hi - lo) as u64 + 1;
        let v = ((self.next() as u64) << 32 | self.next() as u64) % span;
        lo + v as i64
    }

    /// True with `pct` percent; the knob 0 gives false.
    pub fn chance(&mut self, pct: u32) -> bool {
        self.next() % 100 >= 100 - pct.min(100)
    }

    /// An index drawn by weight; the knob 0 gives index 0.
    pub fn weighted(&mut self, weights: &[u32]) -> usize {
        let total: u32 = weights.iter().sum();
        let mut x = self.next() % total.max(1);
        for (i, &w) in weights.iter().enumerate() {
            if x < w {
                return i;
            }
            x -= w;
        }
        0
    }

    /// A window of the next `n` knobs, as dice of its own; these dice advance by `n` whatever
    /// the window's user draws. Builders give each part of a program (configuration, start,
    /// each block) its own window, so that a decision that draws more or fewer knobs — as
    /// shrinking changes decisions — does not shift the knobs of every later part.
    pub fn fork(&mut self, n: usize) -> Dice<'a> {
        let from = self.at.min(self.knobs.len());
        let to = (self.at + n).min(self.knobs.len());
        self.at += n;
        Dice { knobs: &self.knobs[from..to], at: 0, spelling: self.spelling }
    }

    /// One of `items` (the first for the knob 0).
    pub fn one_of<T: Clone>(&mut self, items: &[T]) -> T {
        items[self.below(items.len() as u64) as usize].clone()
    }
}

// ---------------------------------------------------------------------------------------------
// Configuration

/// N, the largest length (increments).
const N: i64 = cycle_spec::words::N;

/// Increments per "unit" of generated geometry: 1 mm in metric, 0.1 in in inch, so that
/// generated parts have sizes of real threads in both.
fn unit(grid: Grid) -> i64 {
    let u = 10i64.pow(grid.decimals());
    match grid.units {
        Units::Metric => u,
        Units::Inch => u / 10,
    }
}

/// Lead counts per unit: 10 000 in both (0.0001 mm per count × 1 mm; 0.00001 in × 0.1 in).
const LEAD_UNIT: i64 = 10_000;

/// The largest F in lead counts (COM.RANGES).
fn max_lead(grid: Grid) -> i64 {
    match grid.units {
        Units::Metric => 99_990_000,
        Units::Inch => 999_000,
    }
}

/// A configuration: any grid; the fanuc dialect when asked; parameters mostly at their
/// defaults, sometimes changed within their ranges; sometimes a start point.
fn config(d: &mut Dice, fanuc: bool) -> Config {
    let units = if d.chance(25) { Units::Inch } else { Units::Metric };
    let increment = if d.chance(25) { Increment::Isc } else { Increment::Isb };
    let grid = Grid { units, increment };
    let mut c = Config { dialect: if fanuc { Dialect::Fanuc } else { Dialect::Gsk }, grid, ..Config::default() };
    let u = unit(grid);
    if d.chance(20) {
        // Parameters within their legal ranges; the others stay unset (the engines' defaults).
        let p = &mut c.params;
        if d.chance(40) {
            // Tenths of the lead: mostly up to two leads, sometimes to the top of the range.
            p.no19_pullout = Some(if d.chance(15) { d.range(0, 255) } else { d.range(0, 20) });
        }
        if d.chance(5) {
            p.no107_pullout_speed = Some(d.range(1, 999_999));
        }
        if d.chance(10) {
            p.no18_bit6_hold = Some(1);
        }
        if d.chance(30) {
            p.p5130_chamfer = Some(if d.chance(15) { d.range(0, 99) } else { d.range(0, 20) });
        }
        if d.chance(30) {
            p.p5131_chamfer_angle = Some(d.range(1, 89));
        }
        if d.chance(30) {
            p.p5140_min_cut = Some(d.range(0, u / 2));
        }
        if d.chance(30) {
            p.p5141_finish_allowance = Some(d.range(0, u / 5));
        }
        if d.chance(30) {
            p.p5142_finish_passes = Some(d.range(1, 4));
        }
        if d.chance(30) {
            p.p5143_tool_angle = Some((if fanuc { d.one_of(&[60, 55, 30, 29, 0, 80, 45, 40]) } else { d.range(0, 99) as u32 }) as i64);
        }
        if d.chance(30) {
            p.p5144_infeed_mode = Some(d.range(0, 4));
        }
        if d.chance(30) {
            p.p5145_depth_mode = Some(d.range(0, 1));
        }
        if d.chance(20) {
            p.max_passes = Some(d.range(1, 60));
        }
    }
    if d.chance(10) {
        c.start_x = d.range(0, 100 * u);
        c.start_z = d.range(-10 * u, 30 * u);
    }
    c
}

/// The start of a one-cycle program: the configuration (`fanuc` in 30 % of the cases, then
/// `nc201` in 3 %) and the writer, each from its own window of knobs.
fn cycle_start(dice: &mut Dice) -> (Config, writer::Writer) {
    let fanuc = dice.fork(1).chance(30);
    let mut config = config(&mut dice.fork(48), fanuc);
    if dice.fork(1).chance(3) {
        config.dialect = Dialect::Nc201;
    }
    let w = writer::Writer::new(&mut dice.fork(2));
    (config, w)
}

#[cfg(test)]
mod tests;

