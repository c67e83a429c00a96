//! The g83 and g84 families: peck drilling G83 and rigid tapping G84 as the register reads them
//! (M003, FANUC lathe conventions) — the R level on either side of the initial level or at it
//! (R omitted), Q in the least increment (one peck, Q larger than the depth, a last peck of one
//! increment, no Q: one feed), dwells, W instead of Z, tapping under G99 (lead F) and G98 (lead
//! F / S, ties of the rounding included), M29 in the block or before it, G80 after; and the
//! register's alarms: the bottom at the R level, Q or P with a decimal point, Q or P out of
//! range, no M29 (or a G80 between M29 and G84), no S or S out of range, no feed, refused words
//! (X, U, C, K, I), the pass bound, `nc201`. The rpm of G84 is a bare S or G97 S, sometimes
//! after `G50 S` (the spindle maximum, G50.SMAX), sometimes missing behind only a `G50 S` or a
//! G96 S (G96.SPEED: a surface speed, no rpm).

use super::writer::tail;
use super::{unit, Case, Dice, LEAD_UNIT};
use cycle_vocab::text::fixed;
use cycle_vocab::Config;

/// A G83 program.
pub fn g83(dice: &mut Dice) -> Case {
    build(dice, false)
}

/// A G84 program.
pub fn g84(dice: &mut Dice) -> Case {
    build(dice, true)
}

/// A drilling (`tap`: tapping) program.
fn build(dice: &mut Dice, tap: bool) -> Case {
    let (mut config, mut w) = super::cycle_start(dice);
    let grid = config.grid;
    let (dec, lead_dec) = (grid.decimals(), grid.lead_decimals());
    let u = unit(grid);
    let d = &mut dice.fork(40);

    // The initial level: X on the axis mostly, Z above the face.
    let (ax, az) = (if d.chance(80) { 0 } else { d.range(0, 20 * u) }, d.range(0, 10 * u));
    let (x, z) = (w.length(ax, dec), w.length(az, dec));
    w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);

    // R: omitted (the initial level), toward the part, away from it.
    let r = match d.weighted(&[20, 50, 30]) {
        0 => None,
        1 => Some(-d.range(0, az.max(1))),
        _ => Some(d.range(1, 3 * u)),
    };
    let r_level = az + r.unwrap_or(0);
    // The bottom: below the R level mostly; sometimes at it (GEOMETRY) or above it.
    let depth = match d.weighted(&[90, 4, 6]) {
        0 => d.range(1, 40 * u),
        1 => 0,
        _ => -d.range(1, 5 * u),
    };
    let bottom = r_level - depth;

    let mut words: Vec<(char, String)> = Vec::new();
    let mut before: Vec<(char, String)> = Vec::new();
    let feed;
    if tap {
        // The mode, S, M29: in the block or in blocks before it; the lead F (G99) or F = lead·S (G98).
        let g98 = d.chance(40);
        let s = match d.weighted(&[92, 3, 3, 2]) {
            0 => Some(d.range(50, 2_000)),
            1 => None,
            2 => Some(0),
            _ => Some(100_000),
        };
        let lead = d.range(LEAD_UNIT / 5, 3 * LEAD_UNIT);
        feed = if g98 { lead * s.unwrap_or(1).clamp(1, 2_000) + d.range(-1, 1) } else { lead };
        // The rpm: a bare S (G97 is in force), or G97 S; sometimes after a `G50 S` (the maximum,
        // not a speed); sometimes only `G50 S` or `G96 S` and no rpm (`MISSING WORD S`).
        let spindle = d.weighted(&[60, 25, 10, 3, 2]);
        let max = s.unwrap_or(1).clamp(1, 99_999) + d.range(0, 3_000);
        if spindle >= 2 {
            w.block(&[('G', "50".into()), ('S', max.to_string())]);
        }
        if spindle == 4 {
            w.block(&[('G', "96".into()), ('S', d.range(20, 300).to_string())]);
        }
        let speed: Vec<(char, String)> = match (spindle, s) {
            (3 | 4, _) => Vec::new(),
            (1, Some(s)) => vec![('G', "97".into()), ('S', s.to_string())],
            (_, s) => s.map(|s| ('S', s.to_string())).into_iter().collect(),
        };
        let modes: Vec<(char, String)> = [Some(('G', if g98 { "98" } else { "99" }.to_string())).filter(|_| g98 || d.chance(30))]
            .into_iter()
            .flatten()
            .chain(speed)
            .chain(Some(('M', "29".to_string())).filter(|_| !d.chance(4)))
            .collect();
        if d.chance(50) || spindle == 1 {
            before = modes;
        } else {
            words = modes;
        }
        if !before.is_empty() && d.chance(3) {
            before.push(('G', "80".into()));
        }
    } else {
        feed = d.range(LEAD_UNIT / 100, LEAD_UNIT / 2);
    }
    if !before.is_empty() {
        w.block(&before);
    }
    words.push(('G', if tap { "84" } else { "83" }.to_string()));
    if d.chance(15) {
        words.push(('W', w.length(bottom - az, dec)));
    } else {
        words.push(('Z', w.length(bottom, dec)));
    }
    if let Some(r) = r {
        words.push(('R', w.length(r, dec)));
    }
    if !tap {
        // Q: the peck in increments (an integer word).
        let q = match d.weighted(&[60, 10, 10, 8, 6, 3, 3]) {
            0 => Some((depth.abs() / d.range(1, 15)).max(1).to_string()),
            1 => None,
            2 => Some((depth.abs() + d.range(0, u)).to_string()),
            3 => Some(((depth.abs() - 1) / d.range(1, 5)).max(1).to_string()),
            4 => Some("0".to_string()),
            5 => Some(format!("{}.", d.range(1, 5))),
            _ => Some((depth.abs() / 200).max(1).to_string()),
        };
        words.extend(q.map(|q| ('Q', q)));
    }
    match d.weighted(&[70, 25, 3, 2]) {
        0 => {}
        1 => words.push(('P', d.range(0, 5_000).to_string())),
        2 => words.push(('P', "1.5".into())),
        _ => words.push(('P', "100000000".into())),
    }
    match d.weighted(&[90, 6, 4]) {
        0 => words.push(('F', w.length(feed, lead_dec))),
        1 => {
            let f = w.length(feed, lead_dec);
            w.block(&[('F', f)]);
        }
        _ => {}
    }
    if d.chance(10) {
        // A defect: a refused word, an axis twice, a broken number, finer than the grid, out of
        // range, a negative Q, a code no dialect here has, a zero feed.
        let defect = match d.below(9) {
            0 => d.one_of(&[('X', "1".to_string()), ('U', "1".to_string()), ('C', "1".to_string()), ('K', "1".to_string()), ('I', "1".to_string())]),
            1 => ('W', w.length(bottom - az, dec)),
            2 => ('Z', "-".to_string()),
            3 => ('Z', format!("{}1", fixed(bottom, dec))),
            4 => ('R', w.length(super::N + 1, dec)),
            5 => ('Q', "-5".to_string()),
            6 => ('G', "91".to_string()),
            7 => ('F', "0".to_string()),
            _ => ('S', "1.5".to_string()),
        };
        if matches!(defect.0, 'Z' | 'R' | 'Q' | 'F') {
            words.retain(|(l, _)| *l != defect.0);
        }
        words.push(defect);
    }
    if d.chance(3) {
        config.params.max_passes = Some(d.range(1, 3));
    }
    w.block(&words);
    if d.chance(40) {
        w.line("G80");
    }
    let (x, z) = (w.length(ax + 20 * u, dec), w.length(az + 10 * u, dec));
    w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);
    tail(&mut w, &mut dice.fork(1));
    Case { family: if tap { "g84" } else { "g83" }, program: w.finish(), config }
}

/// The g83 bench case: one G83 of about `n` pecks of 0.01 mm.
pub fn g83_bench(n: usize) -> Case {
    let p = format!("G0 X0 Z1\nG83 Z{} R-0.5 Q10 F0.05\n", fixed(500 - 10 * n as i64, 3));
    let mut config = Config::default();
    config.params.max_passes = Some(n as i64 + 1);
    Case { family: "g83", program: p.into_bytes(), config }
}

/// The g84 bench case: `n` taps (one pass each), each block its own cycle.
pub fn g84_bench(n: usize) -> Case {
    let mut p = String::from("G0 X0 Z5\nS500\n");
    for _ in 0..n {
        p.push_str("M29\nG84 Z-10 R-3 F1\n");
    }
    Case { family: "g84", program: p.into_bytes(), config: Config::default() }
}

#[cfg(test)]
mod tests;
