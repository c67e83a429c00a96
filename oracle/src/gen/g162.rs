//! Generators for G162 (M004, `--dialect nc201`) and the thread moves G32/G33/G34 (M003).
//!
//! G162 programs cover the register's input space: external and internal threads, G90 and G91,
//! X as diameter or radius (`x_radius`), single and multi-pass (P/Q ties, Q > P, remainders of a
//! few increments), the run-out leg V, taper W, half-degree infeed angles of both signs, B, a
//! variable pitch I over J (growing, shrinking, already below |I|, F = |I| exactly), F omitted (modal feed), and
//! words just outside their ranges, missing words and every cycle check. Thread-move programs
//! chain G32/G33/G34 blocks with modal repeats, G33 start angles and G34 lead changes that keep
//! or lose a legal lead. Pass counts stay small (≤ about 40), so a case runs in microseconds.

use super::{config, lead, lead_text, tail, unit, Case, Dice, Writer, LEAD_UNIT};
use cycle_vocab::text::fixed;
use cycle_vocab::Dialect;

/// A G162 program under `nc201`.
pub(super) fn build_g162(dice: &mut Dice) -> Case {
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
                super::Lead::I(_) => super::Lead::F(LEAD_UNIT + d.range(0, LEAD_UNIT)),
                other => other,
            });
            if let Ok(super::Lead::F(c)) = f {
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
    Case { family: "g162", program: w.out.into_bytes(), config }
}

/// G32 / G33 / G34 programs under `gsk` or `fanuc` (and sometimes `nc201`, where they are
/// refused).
pub(super) fn build_thread_moves(dice: &mut Dice) -> Case {
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
        words.push(super::axis(&mut w, d, 'X', 'U', nx, x, dec));
        words.push(super::axis(&mut w, d, 'Z', 'W', nz, z, dec));
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
    Case { family: "thread", program: w.out.into_bytes(), config }
}

#[cfg(test)]
mod tests {
    use super::super::{build, Family, KNOBS};
    use crate::engine::{Engine, SpecEngine};
    use cycle_vocab::Rule;
    use std::collections::BTreeMap;

    /// How the spec ends `n` cases of a family: "ok" or the alarm's rule.
    fn outcomes(family: Family, n: u32) -> BTreeMap<String, u32> {
        let mut seen = BTreeMap::new();
        let mut s = 0x2545_f491_4f6c_dd1du64;
        for _ in 0..n {
            let knobs: Vec<u32> = (0..KNOBS)
                .map(|_| {
                    s ^= s << 13;
                    s ^= s >> 7;
                    s ^= s << 17;
                    s as u32
                })
                .collect();
            let case = build(family, &knobs);
            let t = SpecEngine.expand(&case.program, &case.config);
            let key = t.alarm.map_or("ok".to_string(), |a| a.rule.id().to_string());
            *seen.entry(key).or_default() += 1;
        }
        seen
    }

    /// The generators mostly build legal programs and reach every check of the register.
    #[test]
    fn families_reach_the_rules() {
        let g162 = outcomes(Family::G162, 3_000);
        assert!(g162["ok"] > 1_500, "{g162:?}");
        for rule in [
            Rule::G162A, Rule::G162B, Rule::G162H, Rule::G162I, Rule::G162J, Rule::G162Pq, Rule::G162F,
            Rule::PrjMaxPass, Rule::PrjWord, Rule::PrjDialect, Rule::Nc201AbsInc,
        ] {
            assert!(g162.contains_key(rule.id()), "G162 family never reaches {rule}: {g162:?}");
        }
        let threads = outcomes(Family::ThreadMoves, 3_000);
        assert!(threads["ok"] > 1_500, "{threads:?}");
        for rule in [Rule::G33, Rule::G34, Rule::ComLead, Rule::PrjDialect] {
            assert!(threads.contains_key(rule.id()), "thread family never reaches {rule}: {threads:?}");
        }
    }
}
