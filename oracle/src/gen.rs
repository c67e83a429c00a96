//! proptest strategies: programs with the configuration they run under.
//!
//! Families:
//! - [`g92`]: G92 programs, valid and invalid — missing lead, out-of-range words, bad tapers,
//!   every J/K combination, multi-start, inch and ISC grids, modal repeats and new runs.
//! - [`multipass`]: G76 / G78 / FANUC G76 two-block programs over the whole legal input space,
//!   with the edge cases the rules turn on: Δd against Δdmin and k − d (ties included), taper,
//!   internal threads, inch, every infeed and depth mode, E lead-in, J/K, multi-start, the pass
//!   bound, and words just outside their ranges.
//! - [`g162()`]: G162 programs under `nc201` (M004), valid and invalid.
//! - [`thread_moves`]: G32 / G33 / G34 programs (M003), valid and invalid.
//! - [`garbage`]: random bytes, random word soup, and the corpus with a few bytes changed.
//!
//! Every structured case is built from a fixed-length vector of random *knobs* (`u32`s) by a
//! deterministic builder: the builder draws each decision from the next knob, and a knob of 0
//! always takes the ordinary choice. proptest shrinks knobs toward 0, so a failing case shrinks
//! toward the plainest program that still fails.
//!
//! Pass counts stay moderate: Δd is chosen relative to k − d so that a degressive schedule has
//! at most about 40 rough passes (a constant one fewer), starts are few, and a large pass count
//! is only reached through a small `max_passes` — so a case typically runs in well under a
//! millisecond.

mod g162;

use crate::corpus;
use cycle_vocab::text::fixed;
use cycle_vocab::{Config, Dialect, Grid, Increment, Units};
use proptest::prelude::*;
use std::fmt;

/// A generated case: program text and configuration.
#[derive(Clone, PartialEq, Eq)]
pub struct Case {
    /// The generator family (`g92`, `g76`, `g78`, `f76`, `bytes`, `soup`, `mutant`).
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

/// How many knobs a structured case draws from.
pub const KNOBS: usize = 256;

/// The knobs: `KNOBS` random `u32`s.
pub fn knobs() -> impl Strategy<Value = Vec<u32>> {
    proptest::collection::vec(any::<u32>(), KNOBS)
}

/// G92 programs.
pub fn g92() -> impl Strategy<Value = Case> {
    knobs().prop_map(|k| build_g92(&mut Dice::new(&k)))
}

/// G76, G78 and FANUC G76 programs.
pub fn multipass() -> impl Strategy<Value = Case> {
    knobs().prop_map(|k| build_multipass(&mut Dice::new(&k)))
}

/// G162 programs under `nc201`.
pub fn g162() -> impl Strategy<Value = Case> {
    knobs().prop_map(|k| g162::build_g162(&mut Dice::new(&k)))
}

/// G32, G33, G34 programs.
pub fn thread_moves() -> impl Strategy<Value = Case> {
    knobs().prop_map(|k| g162::build_thread_moves(&mut Dice::new(&k)))
}

/// Random bytes, word soup, corpus mutants.
pub fn garbage() -> impl Strategy<Value = Case> {
    let bytes = (proptest::collection::vec(any::<u8>(), 0..200), knobs()).prop_map(|(program, k)| {
        let config = config(&mut Dice::new(&k).fork(48), false);
        Case { family: "bytes", program, config }
    });
    let soup = knobs().prop_map(|k| build_soup(&mut Dice::new(&k)));
    let mutant = knobs().prop_map(|k| build_mutant(&mut Dice::new(&k)));
    prop_oneof![bytes, soup, mutant]
}

/// Any family.
pub fn any_case() -> impl Strategy<Value = Case> {
    prop_oneof![4 => g92(), 4 => multipass(), 2 => g162(), 1 => thread_moves(), 1 => garbage()]
}

/// A knob-built family, for drivers other than proptest (the fuzz targets draw the knobs from
/// the fuzzer's bytes, `crate::fuzzing`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Family {
    G92,
    /// G76, G78 or FANUC G76 (the first knob decides).
    Multipass,
    Soup,
    Mutant,
    /// G162 under `nc201`.
    G162,
    /// G32, G33, G34.
    ThreadMoves,
}

/// The case the knobs describe; knobs past the end of `knobs` are 0 (the ordinary choice).
pub fn build(family: Family, knobs: &[u32]) -> Case {
    let mut d = Dice::new(knobs);
    match family {
        Family::G92 => build_g92(&mut d),
        Family::Multipass => build_multipass(&mut d),
        Family::Soup => build_soup(&mut d),
        Family::Mutant => build_mutant(&mut d),
        Family::G162 => g162::build_g162(&mut d),
        Family::ThreadMoves => g162::build_thread_moves(&mut d),
    }
}

// ---------------------------------------------------------------------------------------------
// Decisions

/// Draws decisions from the knobs; past the last knob every draw is 0 (the ordinary choice).
pub struct Dice<'a> {
    knobs: &'a [u32],
    at: usize,
}

impl<'a> Dice<'a> {
    pub fn new(knobs: &'a [u32]) -> Dice<'a> {
        Dice { knobs, at: 0 }
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
        Dice { knobs: &self.knobs[from..to], at: 0 }
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
            p.no19_pullout = Some((if d.chance(15) { d.range(0, 255) } else { d.range(0, 20) }) as i64);
        }
        if d.chance(5) {
            p.no107_pullout_speed = Some(d.range(1, 999_999) as i64);
        }
        if d.chance(10) {
            p.no18_bit6_hold = Some(1);
        }
        if d.chance(30) {
            p.p5130_chamfer = Some((if d.chance(15) { d.range(0, 99) } else { d.range(0, 20) }) as i64);
        }
        if d.chance(30) {
            p.p5131_chamfer_angle = Some(d.range(1, 89) as i64);
        }
        if d.chance(30) {
            p.p5140_min_cut = Some(d.range(0, u / 2) as i64);
        }
        if d.chance(30) {
            p.p5141_finish_allowance = Some(d.range(0, u / 5) as i64);
        }
        if d.chance(30) {
            p.p5142_finish_passes = Some(d.range(1, 4) as i64);
        }
        if d.chance(30) {
            p.p5143_tool_angle = Some((if fanuc { d.one_of(&[60, 55, 30, 29, 0, 80, 45]) } else { d.range(0, 99) as u32 }) as i64);
        }
        if d.chance(30) {
            p.p5144_infeed_mode = Some(d.range(0, 4) as i64);
        }
        if d.chance(30) {
            p.p5145_depth_mode = Some(d.range(0, 1) as i64);
        }
        if d.chance(20) {
            p.max_passes = Some(d.range(1, 60) as i64);
        }
    }
    if d.chance(10) {
        c.start_x = d.range(0, 100 * u);
        c.start_z = d.range(-10 * u, 30 * u);
    }
    c
}

// ---------------------------------------------------------------------------------------------
// Writing programs

/// Writes blocks of words in varied but legal spellings.
struct Writer {
    out: String,
    /// 0: the plain spelling everywhere.
    style: u32,
}

impl Writer {
    fn new(d: &mut Dice) -> Writer {
        let style = if d.chance(40) { d.range(1, u32::MAX as i64) as u32 } else { 0 };
        Writer { out: String::new(), style }
    }

    /// A cheap, deterministic variation source (0 when the style is plain).
    fn vary(&mut self, n: u32) -> u32 {
        if self.style == 0 || n == 0 {
            return 0;
        }
        self.style ^= self.style << 13;
        self.style ^= self.style >> 17;
        self.style ^= self.style << 5;
        self.style % n
    }

    /// A length of `count` increments with `decimals` places: `60`, `58.7`, `58.700`, `058.70`,
    /// `+58.7`, `.5`.
    fn length(&mut self, count: i64, decimals: u32) -> String {
        let full = fixed(count, decimals);
        let trimmed = {
            let t = full.trim_end_matches('0');
            t.to_string()
        };
        let integral = count % 10i64.pow(decimals) == 0;
        match self.vary(6) {
            0 if integral => trimmed.trim_end_matches('.').to_string(),
            0 | 3 => trimmed,
            1 => full,
            2 => format!("{full}0"),
            4 if count > 0 => format!("+{trimmed}"),
            5 if count.abs() < 10i64.pow(decimals) && count != 0 => trimmed.replacen("0.", ".", 1),
            _ => trimmed,
        }
    }

    /// G76 P(k), Q(Δd), Q(Δdmin): under fanuc mostly the micron form (an integer count).
    fn micron(&mut self, count: i64, decimals: u32, fanuc: bool) -> String {
        if fanuc && self.vary(4) != 1 {
            count.to_string()
        } else {
            let s = self.length(count, decimals);
            if fanuc && !s.contains('.') {
                format!("{s}.")
            } else {
                s
            }
        }
    }

    /// One block: its words (letter, value), in the given order or rotated, separated by spaces
    /// or not, sometimes lower case, ended by a newline or `;`.
    fn block(&mut self, words: &[(char, String)]) {
        if words.is_empty() {
            return;
        }
        let rotate = if self.vary(4) == 0 { 0 } else { self.vary(words.len() as u32) as usize };
        let sep = if self.vary(5) == 1 { "" } else { " " };
        let lower = self.vary(6) == 1;
        let mut first = true;
        for i in 0..words.len() {
            let (letter, value) = &words[(i + rotate) % words.len()];
            if !first {
                self.out.push_str(sep);
            }
            first = false;
            let l = if lower { letter.to_ascii_lowercase() } else { *letter };
            self.out.push(l);
            self.out.push_str(value);
        }
        match self.vary(8) {
            1 => self.out.push_str(";\n"),
            2 => self.out.push_str("; "),
            3 => self.out.push_str(" (note)\n"),
            _ => self.out.push('\n'),
        }
    }

    fn line(&mut self, text: &str) {
        self.out.push_str(text);
        self.out.push('\n');
    }
}

/// A lead word: F (lead counts) or I (threads per inch, in 0.0001).
#[derive(Clone, Copy, Debug)]
enum Lead {
    F(i64),
    I(i64),
}

fn lead_word(w: &mut Writer, lead: Lead, grid: Grid) -> (char, String) {
    match lead {
        Lead::F(c) => ('F', w.length(c, grid.lead_decimals())),
        Lead::I(i4) => ('I', w.length(i4, 4)),
    }
}

/// A lead: mostly a legal F; sometimes I, sometimes just outside the range or finer than the
/// lead grid.
fn lead(d: &mut Dice, grid: Grid) -> Result<Lead, String> {
    Ok(match d.weighted(&[80, 12, 2, 2, 2, 2]) {
        0 => Lead::F(d.range(LEAD_UNIT / 4, 6 * LEAD_UNIT)),
        1 => Lead::I(d.range(4, 80) * 10_000 + if d.chance(20) { d.range(1, 9999) } else { 0 }),
        2 => Lead::F(d.one_of(&[1, max_lead(grid)])),
        3 => return Err(d.one_of(&["0", "-1", "99999", "-0.5"]).to_string()),
        4 => return Err(format!("{}1", fixed(d.range(1, 3 * LEAD_UNIT), grid.lead_decimals()))),
        _ => Lead::I(d.one_of(&[0, 1, 254 * 10_000, 254 * 10_000 + 1, 100 * 10_000 + 1])),
    })
}

/// A written lead word, or a broken one (as text).
fn lead_text(w: &mut Writer, l: &Result<Lead, String>, grid: Grid) -> (char, String) {
    match l {
        Ok(lead) => lead_word(w, *lead, grid),
        Err(text) => ('F', text.clone()),
    }
}

/// An axis word: absolute or incremental.
fn axis(w: &mut Writer, d: &mut Dice, abs: char, inc: char, target: i64, current: i64, dec: u32) -> (char, String) {
    if d.chance(20) {
        (inc, w.length(target - current, dec))
    } else {
        (abs, w.length(target, dec))
    }
}

/// The program end: mostly `M30`, sometimes followed by text that must not be read, sometimes
/// nothing.
fn tail(w: &mut Writer, d: &mut Dice) {
    match d.weighted(&[70, 15, 10, 5]) {
        0 => w.line("M30"),
        1 => {}
        2 => w.line("M30\nG92 X#junk after the end"),
        _ => w.line("M02\n%"),
    }
}

// ---------------------------------------------------------------------------------------------
// G92

fn build_g92(dice: &mut Dice) -> Case {
    let mut config = config(&mut dice.fork(48), false);
    let grid = config.grid;
    let dec = grid.decimals();
    let u = unit(grid);
    let mut w = Writer::new(&mut dice.fork(2));
    let d = &mut dice.fork(12);

    // The start point A, by G00 (mostly) or by the configuration.
    let mut ax = d.range(4 * u, 120 * u);
    let az = d.range(0, 20 * u);
    if !d.chance(15) {
        if d.chance(10) {
            w.line("O0012");
            w.line("M3 S300 T0101");
        }
        let (x, z) = (w.length(ax, dec), w.length(az, dec));
        let g = if d.chance(50) { "G0" } else { "G00" };
        w.block(&[('G', g[1..].to_string()), ('X', x), ('Z', z)]);
    } else {
        config.start_x = ax;
        config.start_z = az;
    }

    // The lead, in the first G92 block (mostly), in a block of its own before, or missing.
    let d = &mut dice.fork(10);
    let lead = lead(d, grid);
    let lead_where = d.weighted(&[88, 8, 4]); // 0 in the G92 block, 1 before, 2 missing
    if lead_where == 1 {
        let lw = lead_text(&mut w, &lead, grid);
        w.block(&[lw]);
    }

    let cycles = 1 + d.below(4) as usize;
    let mut end_x = ax;
    let mut end_z = az;
    for n in 0..cycles {
        let d = &mut dice.fork(32);
        let mut words: Vec<(char, String)> = Vec::new();
        let kind = if n == 0 { 0 } else { d.weighted(&[55, 12, 10, 8, 8, 7]) };
        match kind {
            // A new cycle of the run (or the first): X (deeper), maybe Z, R, J, K, L.
            0..=2 => {
                if n == 0 || kind == 1 {
                    words.push(('G', "92".to_string()));
                }
                let side = if n == 0 { d.weighted(&[78, 19, 3]) } else { d.weighted(&[80, 18, 2]) }; // external, internal, on the start X
                let depth = if n == 0 { d.range(1, 10 * u) } else { d.range(1, u) };
                let base = if n == 0 { ax } else { end_x };
                end_x = match side {
                    0 => base - 2 * depth,
                    1 => base + 2 * depth,
                    _ => ax,
                };
                if n == 0 || kind == 2 {
                    let len = match d.weighted(&[88, 5, 5, 2]) {
                        0 => d.range(u, 100 * u),
                        1 => 0,                      // W = 0: a face thread (GEOMETRY on Z)
                        2 => -d.range(u, 30 * u),    // toward +Z
                        _ => d.range(1, 3),          // a very short thread
                    };
                    end_z = az - len;
                }
                words.push(axis(&mut w, d, 'X', 'U', end_x, ax, dec));
                if n == 0 || kind == 2 || d.chance(15) {
                    words.push(axis(&mut w, d, 'Z', 'W', end_z, az, dec));
                }
                // Taper R: same sign as U, opposite within 2|R| ≤ |U| (and the tie), opposite
                // beyond it, or steep (X the long axis).
                let u_dia = end_x - ax;
                let travel = (end_z - az).abs();
                let r = match d.weighted(&[76, 8, 8, 2, 2, 4]) {
                    0 => None,
                    1 => Some(u_dia.signum() * d.range(1, 3 * u)),
                    2 => Some(-u_dia.signum() * d.range(0, u_dia.abs() / 2)),
                    3 => Some(-u_dia.signum() * (u_dia.abs() / 2)),
                    4 => Some(-u_dia.signum() * (u_dia.abs() / 2 + d.range(1, u))),
                    _ => Some(d.one_of(&[1, -1]) * (travel + d.range(0, 2 * u))),
                };
                if let Some(r) = r {
                    words.push(('R', w.length(r, dec)));
                }
                if n == 0 && lead_where == 0 {
                    words.push(lead_text(&mut w, &lead, grid));
                }
                jk_words(&mut w, d, travel.max(1), dec, &mut words);
                l_word(&mut w, d, &mut words);
            }
            // A block without axis words: only modal values change.
            3 => {
                match d.below(4) {
                    0 => words.push(lead_word(&mut w, Lead::F(d.range(LEAD_UNIT / 4, 6 * LEAD_UNIT)), grid)),
                    1 => words.push(('J', w.length(d.range(0, u), dec))),
                    2 => words.push(('K', w.length(d.range(0, u), dec))),
                    _ => words.push(('R', w.length(d.range(-u, u), dec))),
                }
            }
            // A G00 back to the start (ends the run), then a new run with G92.
            4 => {
                let (x, z) = (w.length(ax, dec), w.length(az, dec));
                w.block(&[('G', "0".to_string()), ('X', x), ('Z', z)]);
                if d.chance(30) {
                    ax += 2 * u;
                    let x = w.length(ax, dec);
                    w.block(&[('X', x)]);
                }
                end_x = ax - 2 * d.range(1, 5 * u);
                words.push(('G', "92".to_string()));
                words.push(('X', w.length(end_x, dec)));
                if !d.chance(5) { // omitted: W = 0, a face thread
                    words.push(('Z', w.length(end_z, dec)));
                }
            }
            // Something else between cycles: a G76/G78 first block (one-shot), a dwell-free M
            // code, or a G01 move.
            _ => match d.below(3) {
                0 => w.block(&[('G', "76".to_string()), ('P', "010060".to_string())]),
                1 => w.block(&[('M', d.range(0, 120).to_string())]),
                _ => {
                    let f = w.length(d.range(1, 3 * LEAD_UNIT), grid.lead_decimals());
                    let z = w.length(az, dec);
                    w.block(&[('G', "1".to_string()), ('Z', z), ('F', f)]);
                }
            },
        }
        // Rarely, a word outside its G92 range or not allowed.
        if d.chance(3) {
            let beyond = fixed(N + 1, dec);
            words.push(d.one_of(&[
                ('Z', beyond),
                ('L', "0".to_string()),
                ('L', "2.".to_string()),
                ('J', "100000.".to_string()),
                ('Q', "1".to_string()),
                ('X', format!("{}1", fixed(ax, dec))),
                ('U', "1".to_string()),
            ]));
        }
        w.block(&words);
    }
    tail(&mut w, &mut dice.fork(2));
    Case { family: "g92", program: w.out.into_bytes(), config }
}

/// G92 J and K: each absent, positive, 0, negative (taken as positive), past the long-axis
/// travel, or at the edge of the J/K range.
fn jk_words(w: &mut Writer, d: &mut Dice, travel: i64, dec: u32, words: &mut Vec<(char, String)>) {
    for letter in ['J', 'K'] {
        let v = match d.weighted(&[50, 25, 8, 7, 3, 3]) {
            0 => continue,
            1 => d.range(1, (travel / 2).max(1)),
            2 => 0,
            3 => -d.range(1, (travel / 2).max(1)),
            4 => travel + d.range(0, 2),
            _ => d.one_of(&[99_999_999, -99_999_999, 100_000_000]),
        };
        words.push((letter, w.length(v, dec)));
    }
}

/// G92 L: mostly absent, sometimes 1…4 starts, rarely at or past its range.
fn l_word(w: &mut Writer, d: &mut Dice, words: &mut Vec<(char, String)>) {
    let _ = w;
    match d.weighted(&[80, 17, 3]) {
        0 => {}
        1 => words.push(('L', d.range(1, 4).to_string())),
        _ => words.push(('L', d.one_of(&["99", "100", "0", "2.", "-1"]).to_string())),
    }
}

// ---------------------------------------------------------------------------------------------
// G76 / G78 / FANUC G76

fn build_multipass(dice: &mut Dice) -> Case {
    let which = dice.weighted(&[50, 35, 15]); // G76 gsk, G78, G76 fanuc
    let fanuc = which == 2;
    let code = if which == 1 { "78" } else { "76" };
    let mut config = config(&mut dice.fork(48), fanuc);
    let grid = config.grid;
    let dec = grid.decimals();
    let u = unit(grid);
    let mut w = Writer::new(&mut dice.fork(2));
    let d = &mut dice.fork(40);

    // Thread geometry (radius values k, i, d; X on diameter).
    let k = match d.weighted(&[80, 10, 10]) {
        0 => d.range(u / 10, 3 * u),
        1 => d.range(1, 20),
        _ => d.range(3 * u, 10 * u),
    }
    .max(1);
    let finish = match d.weighted(&[65, 20, 5, 4, 3, 3]) {
        0 => Some(d.range(0, k / 4)),
        1 => None, // 5141
        2 => Some(0),
        3 => Some(k - 1),
        4 => Some(k),                   // d = k: no rough pass (G76.DEPTH.LAST alarm)
        _ => Some(k + d.range(1, u)),   // d > k
    };
    let d_eff = finish.unwrap_or(cycle_spec::config::params(&config).p5141_finish_allowance);
    let t = (k - d_eff).max(1);
    // Δd relative to T = k − d: at most about 40 degressive passes, with exact ties.
    let dd = match d.weighted(&[70, 6, 6, 6, 4, 4, 4]) {
        0 => {
            let n = d.range(1, 40) as f64;
            ((t as f64 / n.sqrt()).ceil() as i64).max(1)
        }
        1 => t,                      // one rough pass, exactly at T
        2 => (t / 2).max(1),         // √4·Δd = T when T is even
        3 => (t / 3).max(1),         // √9·Δd
        4 => k + d.range(1, u),      // Δd beyond k
        5 if t <= 12 => 1,           // one increment (T² passes, T small)
        // Δd ≥ T/√40: at most 40 degressive (and 7 constant) rough passes.
        _ => d.range(1, u.max(2)).max(((t as f64) / 40f64.sqrt()).ceil() as i64),
    };
    let dmin = match d.weighted(&[40, 20, 10, 10, 8, 6, 6]) {
        0 => Some(d.range(0, dd)),
        1 => None,                   // 5140
        2 => Some(0),                // no minimum
        3 => Some(dd),               // Δdmin = Δd: minimum cuts from pass 2 on
        4 => Some((dd * 41 + 50) / 100), // ≈ (√2 − 1)·Δd: the switch decided near a tie
        5 => Some(dd + d.range(1, u)),   // Δdmin > Δd
        _ => Some(d.range(1, 3)),
    };

    // The infeed side and the points: C.x = D.x + 2i, B.x = C.x + 2sk, A beyond B.
    let side: i64 = if d.chance(25) { -1 } else { 1 }; // +1 external, −1 internal
    let i = match d.weighted(&[70, 12, 8, 5, 5]) {
        0 => 0,
        1 => -side * d.range(1, 3 * u),  // taper widening toward the end
        2 => side * d.range(1, 2 * u),
        3 => d.one_of(&[1, -1]) * d.range(20 * u, 60 * u), // steep: X the long axis
        _ => d.one_of(&[1, -1]),
    };
    let dx = d.range(10 * u, 100 * u);
    let cx = dx + 2 * i;
    let bx = cx + 2 * side * k;
    let ax = match d.weighted(&[91, 3, 3, 3]) {
        0 => bx + 2 * side * d.range(1, 2 * u),
        1 => bx,                                 // A on B: legal, no clearance
        2 => bx - 2 * side * d.range(1, k),      // A between B and C (COM.POINTS)
        _ => cx,                                 // A on the thread's start X (COM.SIDE)
    };
    let az = d.range(-5 * u, 20 * u);
    let len = match d.weighted(&[89, 4, 5, 2]) {
        0 => d.range(2 * u, 80 * u),
        1 => 0,                            // W = 0 (GEOMETRY on Z)
        2 => -d.range(2 * u, 30 * u),      // toward +Z
        _ => d.range(1, 5),                // very short: K against the travel
    };
    let dz = az - len;
    let travel = len.abs().max(1);

    // Start point.
    let d = &mut dice.fork(2);
    if !d.chance(10) {
        let (x, z) = (w.length(ax, dec), w.length(az, dec));
        w.block(&[('G', "00".to_string()), ('X', x), ('Z', z)]);
    } else {
        config.start_x = ax;
        config.start_z = az;
    }

    // First block: P(m)(r)(a) or P(m)(mode)(a), Q(Δdmin), R(d), D, L, E.
    let d = &mut dice.fork(40);
    let mut first: Vec<(char, String)> = vec![('G', code.to_string())];
    if !d.chance(10) {
        let m = match d.weighted(&[88, 3, 4, 5]) {
            0 => d.range(1, 3),
            1 => 0, // m = 0 (G76.FINISH alarm)
            2 => 99,
            _ => d.range(4, 9),
        };
        let mid = if which == 1 {
            if d.chance(4) { d.range(5, 99) } else { d.range(0, 4) }
        } else {
            d.range(0, 20)
        };
        let a = if fanuc && !d.chance(5) {
            d.one_of(&[60, 55, 30, 29, 0, 80])
        } else {
            match d.weighted(&[50, 30, 20]) {
                0 => d.one_of(&[60, 55, 30, 29, 0, 80]),
                1 => d.range(0, 99),
                _ => d.one_of(&[45, 1, 89, 99]),
            }
        };
        let p = m * 10_000 + mid * 100 + a;
        let text = match d.weighted(&[94, 2, 2, 2]) {
            0 => format!("{p:06}"),
            1 => p.to_string(),                 // leading zeros implied
            2 => format!("{p}."),               // NOT INTEGER
            _ => "1000000".to_string(),         // past six digits
        };
        first.push(('P', text));
    }
    if let Some(q) = dmin {
        first.push(('Q', w.micron(q, dec, fanuc)));
    }
    if let Some(r) = finish {
        first.push(('R', w.length(r, dec)));
    }
    // GSK-only words; under fanuc they are refused (F76.FORMAT), so only rarely.
    let gsk_words = !fanuc || d.chance(4);
    if gsk_words {
        if d.chance(35) {
            let v = if which == 1 {
                if d.chance(10) { 2 } else { d.range(0, 1) }
            } else if d.chance(10) {
                3
            } else {
                d.range(0, 2)
            };
            first.push(('D', v.to_string()));
        }
        if d.chance(15) {
            let l = match d.weighted(&[80, 12, 8]) {
                0 => d.range(1, 3),
                1 => d.range(4, 12),
                _ => match d.below(3) {
                    // 999 starts only under a pass bound it exceeds (999 × 2 cuts at least).
                    0 => {
                        config.params.max_passes = Some(d.range(1, 1997));
                        999
                    }
                    1 => 1000,
                    _ => 0,
                },
            };
            first.push(('L', l.to_string()));
        }
        if d.chance(15) {
            let e = if d.chance(20) { 0 } else { d.range(1, u) };
            first.push(('E', w.length(e, dec)));
        }
    }
    if d.chance(3) {
        first.push(d.one_of(&[('F', "2".to_string()), ('Q', "-1".to_string()), ('R', "-0.1".to_string()), ('X', "1".to_string())]));
    }
    if !d.chance(8) {
        w.block(&first);
    }

    // Second block: X(U) Z(W) R(i) P(k) Q(Δd) J K F(I).
    let d = &mut dice.fork(32);
    let mut second: Vec<(char, String)> = vec![('G', code.to_string())];
    second.push(axis(&mut w, d, 'X', 'U', dx, ax, dec));
    if len != 0 || d.chance(50) {
        second.push(axis(&mut w, d, 'Z', 'W', dz, az, dec));
    }
    if i != 0 || (fanuc && d.chance(50)) {
        second.push(('R', w.length(i, dec)));
    }
    if !d.chance(2) {
        second.push(('P', w.micron(k, dec, fanuc)));
    }
    if !d.chance(2) {
        second.push(('Q', w.micron(dd, dec, fanuc)));
    }
    if gsk_words {
        for letter in ['J', 'K'] {
            let v = match d.weighted(&[55, 25, 8, 4, 3]) {
                0 => continue,
                1 => d.range(1, (travel / 3).max(1)),
                2 => 0,
                3 => travel + d.range(0, 2), // K past the travel
                _ => -d.range(1, u),          // unsigned: negative is OUT OF RANGE
            };
            second.push((letter, w.length(v, dec)));
        }
    }
    let lead = lead(d, grid);
    let lead_where = d.weighted(&[91, 6, 3]); // in the second block, before, missing
    match lead_where {
        0 => second.push(lead_text(&mut w, &lead, grid)),
        1 => {
            let lw = lead_text(&mut w, &lead, grid);
            w.block(&[lw]);
        }
        _ => {}
    }
    w.block(&second);

    // Sometimes a second thread with the kept first block, or a G00 back.
    let d = &mut dice.fork(8);
    if d.chance(25) {
        let (x, z) = (w.length(ax, dec), w.length(az, dec));
        w.block(&[('G', "0".to_string()), ('X', x), ('Z', z)]);
        if !d.chance(40) {
            let x2 = dx - 2 * side * d.range(0, (k / 2).max(1));
            let mut again = vec![('G', code.to_string()), ('X', w.length(x2, dec))];
            again.push(('P', w.micron(k, dec, fanuc)));
            again.push(('Q', w.micron(dd, dec, fanuc)));
            if len != 0 {
                again.push(('Z', w.length(dz, dec)));
            }
            w.block(&again);
        }
    }
    tail(&mut w, &mut dice.fork(2));
    let family = match which {
        0 => "g76",
        1 => "g78",
        _ => "f76",
    };
    Case { family, program: w.out.into_bytes(), config }
}

// ---------------------------------------------------------------------------------------------
// Garbage

/// Random word soup: letters (either case, any address), numbers of every shape, separators,
/// comments (closed or not), `%`, and the cycle codes, in random order.
fn build_soup(d: &mut Dice) -> Case {
    let fanuc = d.chance(20);
    let config = config(&mut d.fork(48), fanuc);
    let mut out = String::new();
    let tokens = d.range(1, 40);
    for _ in 0..tokens {
        match d.weighted(&[30, 20, 10, 8, 8, 4, 4, 4, 4, 4, 4]) {
            0 => {
                let letter = (b'A' + d.below(26) as u8) as char;
                out.push(if d.chance(20) { letter.to_ascii_lowercase() } else { letter });
                out.push_str(&soup_number(d));
            }
            1 => out.push_str(d.one_of(&["G92", "G76", "G78", "G0", "G00", "G1", "G20", "G21", "G18", "G97", "G92.1", "G-1"])),
            2 => out.push_str(d.one_of(&[" ", "\t", "  "])),
            3 => out.push_str(d.one_of(&["\n", ";", ";\n", "\r\n"])),
            4 => out.push_str(d.one_of(&["X", "Z", "U", "W", "P", "Q", "R", "F", "I", "J", "K", "L", "D", "E"])),
            5 => out.push_str(d.one_of(&["(comment)", "(open", "()", "(a(b)"])),
            6 => out.push_str(d.one_of(&["%", "%\n", "O1", "N10"])),
            7 => out.push_str(d.one_of(&["M30", "M02", "M3", "M100", "M1.5", "M-1"])),
            8 => out.push_str(&soup_number(d)),
            9 => out.push(d.one_of(&['#', '/', '=', '[', '*', '$', '.', '-', '+'])),
            _ => out.push_str(d.one_of(&["G76 P020545 Q0.15 R0.5\n", "G76 X60 Z-60 P3 Q1.8 F3\n", "G0 X65 Z5\n", "G92 X58.7 Z-28 F3\n"])),
        }
    }
    Case { family: "soup", program: out.into_bytes(), config }
}

/// A number in any shape the lexer may meet: signs, leading dots, long digit strings, a point
/// alone, nothing.
fn soup_number(d: &mut Dice) -> String {
    match d.weighted(&[40, 15, 10, 10, 8, 7, 5, 5]) {
        0 => d.range(0, 100).to_string(),
        1 => format!("{}.{}", d.range(0, 100), d.range(0, 9999)),
        2 => format!("-{}", d.range(0, 1_000_000)),
        3 => format!(".{}", d.range(0, 999)),
        4 => "9".repeat(d.range(9, 22) as usize),
        5 => d.one_of(&["", ".", "-", "+", "-.", "1.2.3", "0.0000000001"]).to_string(),
        6 => format!("+{}", d.range(0, 99)),
        _ => format!("{}.", d.range(0, 999_999_999)),
    }
}

/// A corpus program with a few bytes replaced, inserted or deleted, under its configuration or
/// a random one.
fn build_mutant(d: &mut Dice) -> Case {
    let p = corpus::PROGRAMS[d.below(corpus::PROGRAMS.len() as u64) as usize];
    let mut bytes = p.text.as_bytes().to_vec();
    let edits = d.range(1, 4);
    for _ in 0..edits {
        if bytes.is_empty() {
            break;
        }
        let at = d.below(bytes.len() as u64) as usize;
        let byte = match d.weighted(&[40, 30, 30]) {
            0 => b"0123456789.-+ ;\nXZUWPQRFIJKLDEGM"[d.below(32) as usize],
            1 => d.below(256) as u8,
            _ => b'0' + d.below(10) as u8,
        };
        match d.below(3) {
            0 => bytes[at] = byte,
            1 => bytes.insert(at, byte),
            _ => {
                bytes.remove(at);
            }
        }
    }
    let config = if !d.chance(30) {
        p.config()
    } else {
        let fanuc = d.chance(20);
        config(&mut d.fork(48), fanuc)
    };
    Case { family: "mutant", program: bytes, config }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::{Engine, SpecEngine};
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{Config as PtConfig, RngAlgorithm, TestRng, TestRunner};

    fn sample(strategy: impl Strategy<Value = Case>, n: usize) -> Vec<Case> {
        let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[7; 32]);
        let mut runner = TestRunner::new_with_rng(PtConfig::default(), rng);
        (0..n).map(|_| strategy.new_tree(&mut runner).unwrap().current()).collect()
    }

    /// The plain program (every knob 0) of each family expands without an alarm.
    #[test]
    fn zero_knobs_give_plain_valid_programs() {
        let zero = vec![0u32; KNOBS];
        for case in [build_g92(&mut Dice::new(&zero)), build_multipass(&mut Dice::new(&zero))] {
            let t = SpecEngine.expand(&case.program, &case.config);
            assert_eq!(t.alarm, None, "{case:?}");
            assert!(t.moves().any(|m| m.kind == cycle_vocab::MoveKind::Thread), "{case:?}");
        }
    }

    /// The structured families mostly reach the cycle (not just alarms): at least 40 % of the
    /// cases end without an alarm, and together they reach many different alarms.
    #[test]
    fn structured_families_reach_the_cycles_and_many_alarms() {
        for (name, cases) in [("g92", sample(g92(), 400)), ("multipass", sample(multipass(), 400))] {
            let mut clean = 0;
            let mut alarms = std::collections::BTreeSet::new();
            for c in &cases {
                let t = SpecEngine.expand(&c.program, &c.config);
                match t.alarm {
                    None => clean += 1,
                    Some(a) => {
                        alarms.insert((a.code.number(), a.rule));
                    }
                }
            }
            assert!(clean * 5 >= cases.len() * 2, "{name}: only {clean} of {} clean", cases.len());
            assert!(alarms.len() >= 10, "{name}: only these alarms: {alarms:?}");
        }
    }

    /// Every mode, both sides, inch and ISC, fanuc and G78 occur.
    #[test]
    fn multipass_covers_the_input_space() {
        let cases = sample(multipass(), 600);
        let fam: std::collections::BTreeSet<_> = cases.iter().map(|c| c.family).collect();
        assert_eq!(fam.into_iter().collect::<Vec<_>>(), vec!["f76", "g76", "g78"]);
        assert!(cases.iter().any(|c| c.config.grid.units == Units::Inch));
        assert!(cases.iter().any(|c| c.config.grid.increment == Increment::Isc));
        let text: String = cases.iter().map(Case::text).collect();
        for needle in [" D0", " D1", " D2", " E", " J", " K", " L", "I"] {
            assert!(text.contains(needle), "no {needle:?}");
        }
    }

    /// Pass counts stay moderate: the reference trace of a generated case is short.
    #[test]
    fn cases_are_small() {
        let mut longest = 0;
        for c in sample(any_case(), 600) {
            let t = SpecEngine.expand(&c.program, &c.config);
            longest = longest.max(t.events.len());
        }
        assert!(longest < 20_000, "a case with {longest} events");
    }

    #[test]
    fn garbage_never_panics_the_spec() {
        for c in sample(garbage(), 500) {
            let _ = SpecEngine.expand(&c.program, &c.config);
        }
    }

    #[test]
    fn dice_zero_is_ordinary() {
        let zero = [0u32; 4];
        let mut d = Dice::new(&zero);
        assert!(!d.chance(99));
        assert_eq!(d.weighted(&[5, 5]), 0);
        assert_eq!(d.range(3, 9), 3);
        let mut w = Writer { out: String::new(), style: 0 };
        assert_eq!(w.length(60_000, 3), "60");
        assert_eq!(w.length(58_700, 3), "58.7");
        assert_eq!(w.length(-28_000, 3), "-28");
        assert_eq!(w.micron(2_400, 3, true), "2400");
        assert_eq!(w.micron(2_400, 3, false), "2.4");
    }
}
/// Generator statistics, for tuning the weights: `cargo test -p cycle-oracle --lib
/// family_statistics -- --ignored --nocapture` prints, per family, the time per case, the
/// event counts and how the reference trace ends; `SHOW=G92.TAPER` also prints three cases of
/// each ending that contains the text.
#[cfg(test)]
mod stats {
    use super::*;
    use crate::engine::{Engine, SpecEngine};
    use proptest::strategy::ValueTree;
    use proptest::test_runner::{Config as PtConfig, RngAlgorithm, TestRng, TestRunner};

    #[test]
    #[ignore]
    fn family_statistics() {
        let show = std::env::var("SHOW").ok();
        for (name, s) in [("g92", g92().boxed()), ("multipass", multipass().boxed()), ("garbage", garbage().boxed())] {
            let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[7; 32]);
            let mut runner = TestRunner::new_with_rng(PtConfig::default(), rng);
            let mut endings = std::collections::BTreeMap::new();
            let (n, t0) = (2000, std::time::Instant::now());
            let (mut events, mut longest) = (0, 0);
            for _ in 0..n {
                let c = s.new_tree(&mut runner).unwrap().current();
                let t = SpecEngine.expand(&c.program, &c.config);
                events += t.events.len();
                longest = longest.max(t.events.len());
                let k = t.alarm.map_or_else(|| "clean".to_string(), |a| crate::conformance::alarm_short(&a));
                let seen = endings.entry(k.clone()).or_insert(0);
                if show.as_deref().is_some_and(|s| k.contains(s)) && *seen < 3 {
                    println!("{}\n{}", c.text(), t.to_gcode());
                }
                *seen += 1;
            }
            println!("{name}: {:?} per case, mean {} events, longest {longest}", t0.elapsed() / n, events / n as usize);
            for (k, v) in endings {
                println!("  {v:5} {k}");
            }
        }
    }
}
