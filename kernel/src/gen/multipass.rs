//! The multipass families g76 (G76 under gsk), g78 and f76 (G76 under fanuc): two-block
//! programs over the whole legal input space, one builder for the three ([`build`]).

use super::writer::{axis, lead, lead_text, tail, Writer};
use super::{config, unit, Case, Dice};
use cycle_vocab::{Config, Dialect};

/// Which of the three cycles a program threads with.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cycle {
    /// G76 under gsk.
    G76,
    G78,
    /// G76 under fanuc.
    F76,
}

/// A G76 program under gsk.
pub fn g76(dice: &mut Dice) -> Case {
    build(Cycle::G76, dice)
}

/// A G78 program.
pub fn g78(dice: &mut Dice) -> Case {
    build(Cycle::G78, dice)
}

/// A G76 program under fanuc.
pub fn f76(dice: &mut Dice) -> Case {
    build(Cycle::F76, dice)
}

/// A program of any of the three, the first knob choosing (the fuzz input's multipass bytes).
pub fn any(dice: &mut Dice) -> Case {
    let cycle = [Cycle::G76, Cycle::G78, Cycle::F76][dice.weighted(&[50, 35, 15])];
    build(cycle, dice)
}

/// A program of `cycle`.
pub fn build(cycle: Cycle, dice: &mut Dice) -> Case {
    let fanuc = cycle == Cycle::F76;
    let code = if cycle == Cycle::G78 { "78" } else { "76" };
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
        let mid = if cycle == Cycle::G78 {
            if d.chance(4) { d.range(5, 99) } else { d.range(0, 4) }
        } else {
            d.range(0, 20)
        };
        let a = if fanuc && !d.chance(5) {
            d.one_of(&[60, 55, 40, 30, 29, 0, 80])
        } else {
            match d.weighted(&[50, 30, 20]) {
                0 => d.one_of(&[60, 55, 40, 30, 29, 0, 80]),
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
            let v = if cycle == Cycle::G78 {
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
    let mut gave_jk = false;
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
            gave_jk = true;
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

    // Sometimes a second thread with the kept first block, or a G00 back. Its block omits J and
    // K, which G78 keeps (modal, M000): more often after a G78 block that gave them.
    let d = &mut dice.fork(8);
    if d.chance(if cycle == Cycle::G78 && gave_jk { 50 } else { 25 }) {
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
    let family = match cycle {
        Cycle::G76 => "g76",
        Cycle::G78 => "g78",
        Cycle::F76 => "f76",
    };
    Case { family, program: w.finish(), config }
}

/// The g76 bench case: Δdmin = 0 and Δd = 10 increments, about (T/10)² = `n` rough passes for
/// T = k − d.
pub fn g76_bench(n: usize) -> Case {
    let t = (10.0 * (n as f64).sqrt()).round() as i64; // radius increments
    let k = t + 100; // d = 0.1 mm
    let p = format!("G0 X40 Z5\nG76 P011060 Q0 R0.1\nG76 X27.4 Z-20 P{}.{:03} Q0.01 F2\n", k / 1000, k % 1000);
    Case { family: "g76", program: p.into_bytes(), config: Config::default() }
}

/// The g78 bench case: constant depth (mode 3, depth mode 0), Δd = 1 increment: `n` rough
/// passes.
pub fn g78_bench(n: usize) -> Case {
    let k = n as i64 + 50;
    let p = format!("G0 X60 Z5\nG78 P010360 Q0 R0.05 D0\nG78 X27.4 Z-20 P{}.{:03} Q0.001 F2\n", k / 1000, k % 1000);
    Case { family: "g78", program: p.into_bytes(), config: Config::default() }
}

/// The f76 bench case: the g76 case under fanuc, Q and P in microns (F76.MICRONS).
pub fn f76_bench(n: usize) -> Case {
    let t = (10.0 * (n as f64).sqrt()).round() as i64;
    let p = format!("G0 X40 Z5\nG76 P011060 Q0 R0.1\nG76 X27.4 Z-20 P{} Q10 F2\n", t + 100);
    Case { family: "f76", program: p.into_bytes(), config: Config { dialect: Dialect::Fanuc, ..Config::default() } }
}
