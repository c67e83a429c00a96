//! The g90 and g94 families: G90 / G94 single cutting cycles (M003), valid and invalid — the
//! four taper sign cases with their equality edge and one increment past it, no travel on the
//! cycle's own axis, modal repeats that keep end point and taper, taper-only blocks, new runs
//! after another motion mode, a G76 in the middle of a run, F with I in one block, words the
//! cycles refuse, a missing feed, a value out of range or finer than the grid, X with U, a broken
//! number, a G code no dialect here has, inch and ISC grids, and the codes under `nc201`.

use super::writer::{axis, tail};
use super::{unit, Case, Dice, LEAD_UNIT, N};
use cycle_vocab::text::fixed;
use cycle_vocab::Config;

/// Which single cycle.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Cut {
    /// G90: cut along Z, taper I (radius) on X.
    G90,
    /// G94: cut along X, taper K on Z.
    G94,
}

impl Cut {
    fn code(self) -> &'static str {
        match self {
            Cut::G90 => "90",
            Cut::G94 => "94",
        }
    }
    fn taper_letter(self) -> char {
        match self {
            Cut::G90 => 'I',
            Cut::G94 => 'K',
        }
    }
    fn family(self) -> &'static str {
        match self {
            Cut::G90 => "g90",
            Cut::G94 => "g94",
        }
    }
}

/// A G90 program.
pub fn g90(dice: &mut Dice) -> Case {
    build(dice, Cut::G90)
}

/// A G94 program.
pub fn g94(dice: &mut Dice) -> Case {
    build(dice, Cut::G94)
}

/// The taper for a cycle with travel `u` (X, diameter) and `w` (Z) from the start: mostly
/// none; else on the free side any size, or on the limited side up to its limit — the limit
/// itself and one increment past it (G90.TAPER: 2|I| ≤ |U|; G94.TAPER: |k| ≤ |W| with k = C.z −
/// D.z, which under the letter of `g94.k` is −K, so a K of the travel's sign is the limited one).
fn taper(d: &mut Dice, cut: Cut, u: i64, w: i64, unit: i64) -> i64 {
    let travel = match cut {
        Cut::G90 => u,
        Cut::G94 => w,
    };
    // The largest magnitude of a taper on the limited side.
    let limit = match cut {
        Cut::G90 => travel.abs() / 2,
        Cut::G94 => travel.abs(),
    };
    let limited = match cut {
        Cut::G90 => -travel.signum(),
        Cut::G94 => travel.signum(),
    };
    // Both sides reach the limit and one past it for G94: under the reading g94.k =
    // start-minus-end (k = +K) the free side of the letter is the limited one.
    match d.weighted(&[50, 20, 16, 8, 3, 3, 4, 2]) {
        0 => 0,
        1 => -limited * d.range(1, 10 * unit),
        2 if limit > 0 => limited * d.range(1, limit),
        3 if limit > 0 => limited * limit,
        4 if limited != 0 => limited * (limit + 1),
        6 if limit > 0 && cut == Cut::G94 => -limited * limit,
        7 if limited != 0 && cut == Cut::G94 => -limited * (limit + 1),
        _ => d.range(-5 * unit, 5 * unit),
    }
}

/// A single-cycle program of `cut`.
fn build(dice: &mut Dice, cut: Cut) -> Case {
    let (config, mut w) = super::cycle_start(dice);
    let grid = config.grid;
    let (dec, lead_dec) = (grid.decimals(), grid.lead_decimals());
    let u = unit(grid);
    let d = &mut dice.fork(8);

    // The start point A: outside the part (external) mostly, inside (internal) sometimes.
    let internal = d.chance(20);
    let (ax, az) = (if internal { d.range(2 * u, 20 * u) } else { d.range(20 * u, 120 * u) }, d.range(0, 10 * u));
    let (x, z) = (w.length(ax, dec), w.length(az, dec));
    w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);

    // The feed: written in the first cycle block (mostly), before it, or nowhere.
    let feed = d.range(LEAD_UNIT / 50, LEAD_UNIT);
    let feed_where = d.weighted(&[85, 10, 5]);
    if feed_where == 1 {
        let f = w.length(feed, lead_dec);
        w.block(&[('F', f)]);
    }

    let blocks = 1 + dice.fork(1).below(5) as usize;
    let (mut end_x, mut end_z) = (ax, az);
    for i in 0..blocks {
        let d = &mut dice.fork(24);
        let mut words: Vec<(char, String)> = Vec::new();
        // The first block writes the code; later ones mostly repeat modally, sometimes write it
        // again, start a new run after a G01 move, or put a G76 pair in between.
        let kind = if i == 0 { 0 } else { d.weighted(&[55, 15, 10, if internal { 0 } else { 8 }, 7, 5]) };
        match kind {
            2 => {
                // A new run: another motion mode first (it moves back to A).
                let (x, z) = (w.length(ax, dec), w.length(az, dec));
                let f = w.length(feed, lead_dec);
                w.block(&[('G', "1".into()), ('X', x), ('Z', z), ('F', f)]);
                words.push(('G', cut.code().into()));
            }
            3 => {
                // A G76 between the blocks of a run does not end it.
                w.line("G76 P010060 Q0 R0");
                let (x, z) = (w.length(ax - 2 * u, dec), w.length(az - 5 * u, dec));
                let (k, dd) = (w.length(u / 5, dec), w.length(u / 10, dec));
                let f = w.length(LEAD_UNIT, lead_dec);
                w.block(&[('G', "76".into()), ('X', x), ('Z', z), ('P', k), ('Q', dd), ('F', f)]);
                words.push(('G', cut.code().into()));
            }
            4 => {
                // Only the taper (or the feed): the kept values change, nothing is cut.
                let t = taper(d, cut, end_x - ax, end_z - az, u);
                let t = w.length(t, dec);
                words.push((cut.taper_letter(), t));
                w.block(&words);
                continue;
            }
            1 => words.push(('G', cut.code().into())),
            _ if i == 0 => words.push(('G', cut.code().into())),
            _ => {}
        }
        // The end point: along the cycle's axis mostly; sometimes no travel on an axis.
        let (nx, nz) = match (cut, d.weighted(&[96, 2, 2])) {
            (_, 2) => (ax, az),
            (Cut::G90, 1) => (ax - d.range(1, 10 * u), az),
            (Cut::G94, 1) => (ax, az - d.range(1, 10 * u)),
            (Cut::G90, _) => (if internal { ax + d.range(1, 10 * u) } else { ax - d.range(1, 15 * u) }, az - d.range(1, 40 * u)),
            (Cut::G94, _) => (if internal { ax + d.range(1, 20 * u) } else { ax - d.range(1, 40 * u) }, az - d.range(1, 8 * u)),
        };
        let repeat = i > 0 && kind == 0;
        if !repeat || nx != end_x || d.chance(30) {
            words.push(axis(&mut w, d, 'X', 'U', nx, ax, dec));
        }
        if !repeat || nz != end_z || d.chance(30) {
            words.push(axis(&mut w, d, 'Z', 'W', nz, az, dec));
        }
        if !repeat || d.chance(20) {
            let t = taper(d, cut, nx - ax, nz - az, u);
            if t != 0 || d.chance(20) {
                let t = w.length(t, dec);
                words.push((cut.taper_letter(), t));
            }
        }
        if i == 0 && feed_where == 0 {
            let f = w.length(feed, lead_dec);
            words.push(('F', f));
        }
        // Now and then a defect: a word the cycle refuses, a value out of range or finer than
        // the grid, X with U, a broken number, a code no dialect here has.
        if d.chance(6) {
            let defect = match d.weighted(&[3, 1, 1, 1, 1, 1]) {
                0 => d.one_of(&[('R', "1".to_string()), ('J', "1".to_string()), ('L', "2".to_string())]),
                1 => ('X', w.length(N + 1, dec)),
                2 => ('X', format!("{}1", fixed(nx, dec))),
                3 => ('U', w.length(nx - ax, dec)),
                4 => ('X', "-".to_string()),
                _ => ('G', "91".to_string()),
            };
            if defect.0 == 'X' {
                words.retain(|(l, _)| *l != 'X' && *l != 'U');
            }
            words.push(defect);
        }
        w.block(&words);
        (end_x, end_z) = (nx, nz);
    }
    tail(&mut w, &mut dice.fork(1));
    Case { family: cut.family(), program: w.finish(), config }
}

/// The bench case of `cut`: `n` cycles of one modal run from X100 Z2, each 0.005 deeper — G90
/// down in X (cut to Z−20), G94 down in Z (faced to X50).
fn bench(cut: Cut, n: usize) -> Case {
    let mut p = String::from("G0 X100 Z2\n");
    for i in 0..n {
        let depth = 5 * (i as i64 + 1);
        match (cut, i) {
            (Cut::G90, 0) => p.push_str(&format!("G90 X{} Z-20 F0.2\n", fixed(100_000 - depth, 3))),
            (Cut::G94, 0) => p.push_str(&format!("G94 X50 Z{} F0.2\n", fixed(2_000 - depth, 3))),
            (Cut::G90, _) => p.push_str(&format!("X{}\n", fixed(100_000 - depth, 3))),
            (Cut::G94, _) => p.push_str(&format!("Z{}\n", fixed(2_000 - depth, 3))),
        }
    }
    Case { family: cut.family(), program: p.into_bytes(), config: Config::default() }
}

/// The g90 bench case.
pub fn g90_bench(n: usize) -> Case {
    bench(Cut::G90, n)
}

/// The g94 bench case.
pub fn g94_bench(n: usize) -> Case {
    bench(Cut::G94, n)
}

#[cfg(test)]
mod tests;
