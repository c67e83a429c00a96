//! The g74 and g75 families: the peck cycles G74 (pecks along Z, columns stepped in X) and G75
//! (pecks along X, grooves stepped in Z) of M003, valid and invalid — one peck, Q larger than
//! the depth, a last peck of one increment, depths that are and are not a multiple of the peck,
//! columns whose last step is shorter, the single-column and single-groove forms, the retract
//! e from the first block, from parameter 5139 or from an earlier first block of the other code,
//! e larger than the peck, reliefs, both directions, inch and ISC grids, and the register's
//! alarms: no travel on the peck axis, a missing or zero peck or step, negative lengths, the
//! pass bound (a small `max_passes`), a missing feed, refused words, X with U, `nc201`.

use super::writer::{axis, tail};
use super::{unit, Case, Dice, LEAD_UNIT, N};
use cycle_vocab::text::fixed;
use cycle_vocab::Config;

/// Which peck cycle.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Peck {
    /// G74: pecks along Z by Q, columns in X by P (a radius).
    G74,
    /// G75: pecks along X by P (a radius), grooves in Z by Q.
    G75,
}

impl Peck {
    fn code(self) -> &'static str {
        match self {
            Peck::G74 => "74",
            Peck::G75 => "75",
        }
    }
    fn family(self) -> &'static str {
        match self {
            Peck::G74 => "g74",
            Peck::G75 => "g75",
        }
    }
}

/// A G74 program.
pub fn g74(dice: &mut Dice) -> Case {
    build(dice, Peck::G74)
}

/// A G75 program.
pub fn g75(dice: &mut Dice) -> Case {
    build(dice, Peck::G75)
}

/// The peck (or step) for a travel of `travel` increments: mostly a few pecks' worth; the
/// edges — exactly the travel, larger, a divisor, one increment, one increment short of a
/// divisor. At least 1.
fn step(d: &mut Dice, travel: i64) -> i64 {
    let t = travel.max(1);
    match d.weighted(&[55, 10, 8, 10, 5, 12]) {
        0 => (t / d.range(2, 12)).max(1),
        1 => t,
        2 => t + d.range(1, t),
        3 => t / d.range(1, 6).min(t),
        4 => (t / 40).max(1),
        _ => (t / d.range(2, 8)).max(2) - 1,
    }
}

/// A peck-cycle program of `peck`.
fn build(dice: &mut Dice, peck: Peck) -> Case {
    let (mut config, mut w) = super::cycle_start(dice);
    let grid = config.grid;
    let (dec, lead_dec) = (grid.decimals(), grid.lead_decimals());
    let u = unit(grid);
    let d = &mut dice.fork(40);

    // The start point A: G74 above the face, G75 outside the diameter.
    let (ax, az) = match peck {
        Peck::G74 => (d.range(0, 60 * u), d.range(0, 5 * u)),
        Peck::G75 => (d.range(20 * u, 100 * u), d.range(-40 * u, 30 * u)),
    };
    let (x, z) = (w.length(ax, dec), w.length(az, dec));
    w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);

    // The travel along the peck axis (pecks toward the part, sometimes away) and the step axis.
    let deep = d.range(1, 30 * u) * if d.chance(8) { -1 } else { 1 };
    let (pecks_along_x, steps) = (peck == Peck::G75, d.chance(45));
    let across = if steps { d.range(1, 20 * u) * if d.chance(30) { -1 } else { 1 } } else { 0 };
    // End point E and the peck / step lengths (radius for X).
    let (ex, ez) = match peck {
        Peck::G74 => (ax + 2 * across, az - deep),
        Peck::G75 => (ax - 2 * deep, az - across),
    };
    let peck_len = step(d, deep.abs());
    let step_len = if steps { step(d, across.abs()) } else { 0 };
    let (p, q) = if pecks_along_x { (peck_len, step_len) } else { (step_len, peck_len) };

    // The retract e: a first block, parameter 5139, the other code's first block (kept apart).
    let mut e = Some(d.range(0, u));
    match d.weighted(&[70, 10, 10, 5, 5]) {
        1 => e = None,
        2 => {
            config.params.p5139_peck_return = Some(d.range(0, u));
            e = None;
        }
        3 => e = Some(peck_len + d.range(0, u)),
        4 => {
            let other = if peck == Peck::G74 { "75" } else { "74" };
            let r = w.length(d.range(0, u), dec);
            w.block(&[('G', other.into()), ('R', r)]);
        }
        _ => {}
    }
    if let Some(e) = e {
        let r = w.length(e, dec);
        w.block(&[('G', peck.code().into()), ('R', r)]);
    }

    // The second block.
    let mut words = vec![('G', peck.code().to_string())];
    let x_written = ex != ax || d.chance(20);
    let z_written = ez != az || d.chance(20);
    if x_written {
        words.push(axis(&mut w, d, 'X', 'U', ex, ax, dec));
    }
    if z_written {
        words.push(axis(&mut w, d, 'Z', 'W', ez, az, dec));
    }
    if p != 0 || d.chance(20) {
        words.push(('P', w.length(p, dec)));
    }
    if q != 0 || d.chance(20) {
        words.push(('Q', w.length(q, dec)));
    }
    if steps && d.chance(40) {
        words.push(('R', w.length(d.range(0, u / 2), dec)));
    }
    let feed = d.range(LEAD_UNIT / 100, LEAD_UNIT / 2);
    match d.weighted(&[85, 10, 5]) {
        0 => words.push(('F', w.length(feed, lead_dec))),
        1 => {
            let f = w.length(feed, lead_dec);
            w.block(&[('F', f)]);
        }
        _ => {}
    }
    if d.chance(10) {
        words.push(('S', "250".into()));
    }

    // Now and then a defect: no travel on the peck axis, no peck, a negative length, a refused
    // word, out of range, X with U, a few passes allowed.
    if d.chance(8) {
        let (peck_axis, peck_word) = if pecks_along_x { ('X', 'P') } else { ('Z', 'Q') };
        let step_word = if pecks_along_x { 'Q' } else { 'P' };
        match d.below(12) {
            8 if steps => words.retain(|(l, _)| *l != step_word),
            9 => words.push(('X', format!("{}1", fixed(ex, dec)))),
            10 => words.push(('Z', "-".into())),
            11 => words.push(('G', "91".into())),
            0 => words.retain(|(l, _)| *l != peck_axis && *l != if peck_axis == 'X' { 'U' } else { 'W' }),
            1 => words.retain(|(l, _)| *l != peck_word),
            2 => words.push((peck_word, "0".into())),
            3 => words.push(('R', w.length(-d.range(1, u), dec))),
            4 => words.push(d.one_of(&[('I', "1".to_string()), ('K', "1".to_string()), ('J', "1".to_string()), ('L', "2".to_string())])),
            5 => words.push(('X', w.length(N + 1, dec))),
            6 => words.push(('U', w.length(ex - ax, dec))),
            _ => config.params.max_passes = Some(d.range(1, 4)),
        }
    }
    w.block(&words);
    let (x, z) = (w.length(ax + 10 * u, dec), w.length(az + 10 * u, dec));
    w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);
    tail(&mut w, &mut dice.fork(1));
    Case { family: peck.family(), program: w.finish(), config }
}

/// The bench case of `peck`: one cycle of about `n` pecks (0.01 mm each, e = 0.005) in one
/// column (G74) or one groove (G75).
fn bench(peck: Peck, n: usize) -> Case {
    let depth = 10 * n as i64;
    let p = match peck {
        Peck::G74 => format!("G0 X0 Z1\nG74 R0.005\nG74 Z{} Q0.01 F0.05\n", fixed(1_000 - depth, 3)),
        Peck::G75 => format!("G0 X{} Z-5\nG75 R0.005\nG75 X50 P0.01 F0.05\n", fixed(50_000 + 2 * depth, 3)),
    };
    let mut config = Config::default();
    config.params.max_passes = Some(n as i64 + 1);
    Case { family: peck.family(), program: p.into_bytes(), config }
}

/// The g74 bench case.
pub fn g74_bench(n: usize) -> Case {
    bench(Peck::G74, n)
}

/// The g75 bench case.
pub fn g75_bench(n: usize) -> Case {
    bench(Peck::G75, n)
}

#[cfg(test)]
mod tests;
