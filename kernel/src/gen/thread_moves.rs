//! The g32 family: G32 / G33 / G34 thread-move programs (M003), valid and invalid. They chain
//! blocks with modal repeats, G33 start angles and G34 lead changes that keep or lose a legal
//! lead.

use super::writer::{axis, lead, lead_text, tail, Writer};
use super::{config, unit, Case, Dice, LEAD_UNIT};
use cycle_vocab::{Config, Dialect};

/// G32 / G33 / G34 programs under `gsk` or `fanuc` (and sometimes `nc201`, where they are
/// refused).
pub fn build(dice: &mut Dice) -> Case {
    let fanuc = dice.fork(1).chance(30);
    let mut config = config(&mut dice.fork(48), fanuc);
    if dice.fork(1).chance(3) {
        config.dialect = Dialect::Nc201;
    }
    let grid = config.grid;
    let dec = grid.decimals();
    let lead_dec = grid.lead_decimals();
    let u = unit(grid);
    let mut w = Writer::new(&mut dice.fork(2));
    let d = &mut dice.fork(6);
    let (mut x, mut z) = (d.range(2 * u, 80 * u), d.range(-5 * u, 20 * u));
    let start = [('G', "0".to_string()), ('X', w.length(x, dec)), ('Z', w.length(z, dec))];
    w.block(&start);
    let mut first = true;
    let mut modal = 3; // G00: a repeat block then is a rapid
    let blocks = 1 + dice.fork(1).below(5) as usize;
    for _ in 0..blocks {
        let d = &mut dice.fork(24);
        // G32, G33, G34, or a modal repeat of the current mode (a stray word now and then).
        let written = d.weighted(&[35, 25, 30, 10]);
        let code = if written == 3 { modal } else { written };
        modal = code;
        let mut words: Vec<(char, String)> = Vec::new();
        match written {
            0 => words.push(('G', "32".into())),
            1 => words.push(('G', "33".into())),
            2 => words.push(('G', "34".into())),
            _ => {}
        }
        // The end point: mostly along Z, sometimes a taper or a face move, sometimes nowhere.
        let (nx, nz) = match d.weighted(&[55, 25, 10, 10]) {
            0 => (x, z - d.range(1, 40 * u)),
            1 => (x + d.range(-4 * u, 4 * u), z - d.range(1, 40 * u)),
            2 => (x - d.range(1, 10 * u), z),
            _ => (x, z),
        };
        words.push(axis(&mut w, d, 'X', 'U', nx, x, dec));
        words.push(axis(&mut w, d, 'Z', 'W', nz, z, dec));
        if first || d.chance(30) {
            let l = lead(d, grid);
            if !(first && d.chance(5)) {
                words.push(lead_text(&mut w, &l, grid));
            }
        }
        if (code == 1 && d.chance(70)) || d.chance(2) {
            let p = if d.chance(95) { d.range(0, 359_999) } else { d.one_of(&[360_000, -1]) };
            words.push(('P', p.to_string()));
        }
        if (code == 2 && d.chance(95)) || d.chance(2) {
            // Mostly small against the lead; sometimes large enough to lose the lead.
            let k = match d.weighted(&[85, 10, 5]) {
                0 => d.range(-LEAD_UNIT / 100, LEAD_UNIT / 100),
                1 => -d.range(LEAD_UNIT / 10, 2 * LEAD_UNIT),
                _ => d.range(LEAD_UNIT, 10_000 * LEAD_UNIT),
            };
            words.push(('K', w.length(k, lead_dec)));
        }
        w.block(&words);
        x = nx;
        z = nz;
        first = false;
    }
    tail(&mut w, &mut dice.fork(1));
    Case { family: "g32", program: w.finish(), config }
}

/// The bench case: `n` G32 blocks, each a thread of 1 mm along Z.
pub fn bench(n: usize) -> Case {
    let mut p = String::from("G0 X30 Z5\nG32 Z4 F2\n");
    for i in 1..n {
        p.push_str(&format!("Z{}\n", 4 - i as i64));
    }
    Case { family: "g32", program: p.into_bytes(), config: Config::default() }
}

#[cfg(test)]
mod tests;
