//! The g162 family: G162 programs (M004, `--dialect nc201`).
//!
//! They cover the register's input space: external and internal threads, G90 and G91,
//! X as diameter or radius (`x_radius`), single and multi-pass (P/Q ties, Q > P, remainders of a
//! few increments), the run-out leg V, taper W, half-degree infeed angles of both signs, B, a
//! variable pitch I over J (growing, shrinking, already below |I|, F = |I| exactly), F omitted (modal feed), and
//! words just outside their ranges, missing words and every cycle check. Pass counts stay small
//! (≤ about 40), so a case runs in microseconds.

use super::writer::{lead, lead_text, tail, Lead, Writer};
use super::{config, unit, Case, Dice, LEAD_UNIT};
use cycle_vocab::text::fixed;
use cycle_vocab::{Config, Dialect};

/// A G162 program under `nc201`.
pub fn build(dice: &mut Dice) -> Case {
    let mut config = config(&mut dice.fork(48), false);
    config.dialect = Dialect::Nc201;
    let grid = config.grid;
    let dec = grid.decimals();
    let lead_dec = grid.lead_decimals();
    let u = unit(grid);
    let d = &mut dice.fork(4);
    let radius = d.chance(25);
    if radius {
        config.params.x_radius = Some(1);
    }
    let mut w = Writer::new(&mut dice.fork(2));
    // An X value as written: a diameter count, or half of it in radius mode.
    let x_text = |w: &mut Writer, diameter: i64| w.length(if radius { diameter / 2 } else { diameter }, dec);

    // The start point S: always an even diameter, so that radius mode can write it.
    let d = &mut dice.fork(8);
    let sx = 2 * d.range(2 * u, 60 * u);
    let sz = d.range(-10 * u, 20 * u);
    let (x, z) = (x_text(&mut w, sx), w.length(sz, dec));
    w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);

    // A modal feed for F omitted: sometimes a G01 feed before (read as mm/rev).
    let d = &mut dice.fork(4);
    if d.chance(15) {
        let f = d.range(LEAD_UNIT / 4, 4 * LEAD_UNIT);
        let f = w.length(f, lead_dec);
        w.block(&[('G', "1".into()), ('F', f)]);
    }

    let blocks = 1 + usize::from(dice.fork(1).chance(15));
    for _ in 0..blocks {
        let d = &mut dice.fork(64);
        let mut words: Vec<(char, String)> = vec![('G', "162".into())];
        let incremental = d.chance(20);
        if incremental {
            words.push(('G', "91".into()));
        } else if d.chance(10) {
            words.push(('G', "90".into()));
        }
        // Side, depth, X0 (even diameters), thread length and direction.
        let external = !d.chance(20);
        let multi = !d.chance(20);
        let p = d.range(1, 3 * u);
        let q = match d.weighted(&[50, 15, 15, 10, 10]) {
            0 => d.range((p / 10).max(1), p),
            1 => p,                                   // one pass, D = 0
            2 => d.range(p + 1, 2 * p + 1),           // Q > P: the split alone
            3 => (p - d.range(1, 3)).max(1),          // a remainder of a few increments
            _ => (p / d.range(2, 8)).max(1),          // exact multiples or near
        };
        let v = if d.chance(40) { d.range(0, 3 * u) } else { 0 };
        let wd = if d.chance(30) { 2 * d.range(-4 * u, 4 * u) } else { 0 };
        let room = 2 * (p + v) + wd.abs() + 2 * d.range(0, 4 * u); // S stays outside the path
        let x0 = if external { sx - room - 2 * d.range(1, u) } else { sx + room + 2 * d.range(1, u) };
        let len = d.range(u / 2 + v, 60 * u);
        let ze = if d.chance(80) { sz - len } else { sz + len };
        let x_word = if incremental { x0 - sx } else { x0 };
        let z_word = if incremental { ze - sz } else { ze };
        words.push(('X', x_text(&mut w, x_word)));
        words.push(('Z', w.length(z_word, dec)));
        // H, mostly legal.
        match d.weighted(&[92, 4, 4]) {
            0 => words.push(('H', w.length(d.range(LEAD_UNIT, 1_000 * LEAD_UNIT), lead_dec))),
            1 => words.push(('H', d.one_of(&["0", "-5", "100000"]).into())),
            _ => {}
        }
        // P and Q as a pair, neither, or one of them.
        match (multi, d.weighted(&[94, 3, 3])) {
            (true, 0) => {
                words.push(('P', w.length(p, dec)));
                words.push(('Q', w.length(q, dec)));
            }
            (true, 1) => words.push(('P', w.length(p, dec))),
            (true, _) => words.push(('Q', w.length(q, dec))),
            (false, _) => {}
        }
        if v > 0 || d.chance(10) {
            words.push(('V', w.length(v, dec)));
        }
        if wd != 0 {
            words.push(('W', x_text(&mut w, wd)));
        }
        if d.chance(35) {
            let half = d.range(-90, 90);
            let text = match d.weighted(&[90, 5, 5]) {
                0 => fixed(half * 5, 1),
                1 => format!("{}.3", half / 2),
                _ => d.one_of(&["89.5", "-90", "180"]).to_string(),
            };
            words.push(('A', text));
        }
        // F: written (mostly), or omitted (modal feed, or MISSING WORD F).
        let mut f_counts = None;
        if !d.chance(15) {
            let f = lead(d, grid).map(|l| match l {
                Lead::I(_) => Lead::F(LEAD_UNIT + d.range(0, LEAD_UNIT)),
                other => other,
            });
            if let Ok(Lead::F(c)) = f {
                f_counts = Some(c);
            }
            words.push(lead_text(&mut w, &f, grid));
        }
        if d.chance(25) {
            let b = match d.weighted(&[90, 5, 5]) {
                0 => fixed(d.range(0, 360_000), 3),
                1 => "360".into(),
                _ => d.one_of(&["-1", "360.001", "0.0001"]).into(),
            };
            words.push(('B', b));
        }
        if d.chance(25) {
            let i = match d.weighted(&[45, 45, 5, 5, 5]) {
                0 => d.range(1, LEAD_UNIT / 2),
                1 => -d.range(1, 2 * LEAD_UNIT),
                2 => d.range(LEAD_UNIT, 2_000 * LEAD_UNIT),
                3 => 100_000 * LEAD_UNIT,
                // The tie |I| = F: a shrinking lead that starts at its floor never changes.
                _ => -f_counts.unwrap_or(LEAD_UNIT),
            };
            words.push(('I', w.length(i, lead_dec)));
            if d.chance(50) {
                let j = if d.chance(95) { d.range(1_000, 720_000) } else { 0 };
                words.push(('J', fixed(j, 3)));
            }
        }
        // A few stray words and codes that the register refuses.
        match d.weighted(&[94, 2, 2, 2]) {
            0 => {}
            1 => words.push(('U', "1".into())),
            2 => words.push(('G', d.one_of(&["91", "0", "92"]).into())),
            _ => words.push(('K', "1".into())),
        }
        w.block(&words);
    }
    tail(&mut w, &mut dice.fork(1));
    Case { family: "g162", program: w.finish(), config }
}

/// The bench case: a straight thread of depth P = `n` increments cut Q = 1 at a time — `n`
/// passes (G162.PQ, G162.SPLIT).
pub fn bench(n: usize) -> Case {
    let p = format!("G0 X60 Z5\nG162 X30 Z-20 H400 P{}.{:03} Q0.001 F2\n", n / 1000, n % 1000);
    Case { family: "g162", program: p.into_bytes(), config: Config { dialect: Dialect::Nc201, ..Config::default() } }
}

#[cfg(test)]
mod tests;
