//! The g92 family: G92 programs, valid and invalid — missing lead, out-of-range words, bad
//! tapers, every J/K combination, multi-start, inch and ISC grids, modal repeats and new runs.

use super::writer::{axis, lead, lead_text, lead_word, tail, Lead, Writer};
use super::{config, unit, Case, Dice, LEAD_UNIT, N};
use cycle_vocab::text::fixed;
use cycle_vocab::Config;

/// A G92 program.
pub fn build(dice: &mut Dice) -> Case {
    let mut config = config(&mut dice.fork(48), false);
    let grid = config.grid;
    let dec = grid.decimals();
    let u = unit(grid);
    let mut w = Writer::new(&mut dice.fork(2));
    let d = &mut dice.fork(12);

    // G92.PATH step ③: a pull-out may not end beyond the start X. `room` (radius) is more than
    // the default pull-out (No.19 tenths of a lead, a lead below 7 units); most first cycles cut
    // at least that deep, and the start X leaves that room above the axis.
    let room = config.params.no19_pullout.unwrap_or(10).clamp(0, 255) * 7 * u / 10;

    // The start point A, by G00 (mostly) or by the configuration.
    let mut ax = d.range(4 * u, 120 * u) + 2 * room;
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
                let depth = if n == 0 { d.range(1, 10 * u) + if d.chance(15) { 0 } else { room } } else { d.range(1, u) };
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
                jk_words(&mut w, d, travel.max(1), (end_x - ax).abs() / 2, dec, &mut words);
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
                end_x = ax - 2 * (d.range(1, 5 * u) + room); // room for the pull-out (step ③)
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
    Case { family: "g92", program: w.finish(), config }
}

/// G92 J and K: each absent, positive, 0, negative (taken as positive), past the long-axis
/// travel, or at the edge of the J/K range. A J written with a size stays within `depth`, the
/// cycle's X infeed (radius), so that step ③ mostly has a legal start (G92.PATH).
fn jk_words(w: &mut Writer, d: &mut Dice, travel: i64, depth: i64, dec: u32, words: &mut Vec<(char, String)>) {
    for letter in ['J', 'K'] {
        let most = if letter == 'J' { (travel / 2).min(depth) } else { travel / 2 };
        let v = match d.weighted(&[50, 25, 8, 7, 3, 3]) {
            0 => continue,
            1 => d.range(1, most.max(1)),
            2 => 0,
            3 => -d.range(1, most.max(1)),
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


/// The bench case: the manual's first cycle and `n − 1` modal repeats (one pass each,
/// G92.MODAL).
pub fn bench(n: usize) -> Case {
    let mut p = String::from("G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n");
    for i in 1..n {
        let x = 58_700 - (i % 500) as i64; // increments, 0.001 mm
        p.push_str(&format!("X{}.{:03}\n", x / 1000, x % 1000));
    }
    Case { family: "g92", program: p.into_bytes(), config: Config::default() }
}

#[cfg(test)]
mod tests;
