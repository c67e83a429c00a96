//! Random legal G162 cycles, no-panic fuzzing of G162 and the thread moves, and every G162
//! program of the corpus expanding, on the whole expander.
extern crate std;

use super::programs::{depths, nc201, threads};
use crate::tests::{expand, gcode, grid_of_round, moves, xorshift};
use cycle_vocab::{AlarmCode, Config, Dialect, Event, Grid, Increment, MoveKind, Params, Rule, Units};
use std::format;
use std::string::String;

/// Random legal G162 cycles in every grid, external and internal, G90 and G91, radius or
/// diameter X: depths strictly increase and end exactly at P (never past it), full cuts first,
/// each split cut on its target; the last pass cuts at X0 − 2s·P; every pass returns to S; no
/// rapid inside a cycle; a shrinking lead's floor is |I| and no lead is ≤ 0.
#[test]
fn random_legal_g162_cycles() {
    let mut s = 0x6162_c7c1_e000_0001u64;
    let mut checked = 0;
    for round in 0..1_500u32 {
        let mut r = || xorshift(&mut s);
        let grid = grid_of_round(round);
        let x_radius = u32::from(round % 8 >= 4);
        let dec = grid.decimals();
        let len = |v: i64| cycle_vocab::text::fixed(v, dec);
        let lead = |v: i64| cycle_vocab::text::fixed(v, grid.lead_decimals());
        let p = 1 + (r() % 3_000) as i64;
        let q = 1 + (r() % 1_500) as i64;
        let external = r() % 2 == 0;
        let sign: i64 = if external { 1 } else { -1 };
        // x_radius: only even diameter counts are writable as radii.
        let even = |v: i64| if x_radius == 1 { v & !1 } else { v };
        let half = |v: i64| if x_radius == 1 { v / 2 } else { v };
        let x0 = even(20_000 + (r() % 40_000) as i64); // diameter
        let taper = even((r() % 4_000) as i64 - 2_000); // diameter
        let v = (r() % 2_000) as i64;
        let sx = x0 + sign * (2 * v + taper.abs() + 2 + 2 * (r() % 5_000) as i64);
        let sz = (r() % 10_000) as i64;
        let ze = sz - 5_000 - (r() % 50_000) as i64;
        let a = (r() % 1_781) as i64 - 890; // tenths of a degree
        let i = (r() % 4_000) as i64 - 2_000;
        let f = 1_000 + (r() % 30_000) as i64;
        let incremental = r() % 2 == 0;
        let (xw, zw) = if incremental { (x0 - sx, ze - sz) } else { (x0, ze) };
        let split = r() % 5 != 0;
        let pq = if split { format!(" P{} Q{}", len(p), len(q)) } else { String::new() };
        let src = format!(
            "G0 X{} Z{}\n{}G162 X{} Z{} H{} V{} W{} A{}{} F{} I{} J{}\n",
            len(half(sx)),
            len(sz),
            if incremental { "G91 " } else { "" },
            len(half(xw)),
            len(zw),
            lead(1 + (r() % 9_000_000) as i64),
            len(v),
            len(half(taper)),
            cycle_vocab::text::fixed(a, 1),
            pq,
            lead(f),
            lead(i),
            cycle_vocab::text::fixed(1 + (r() % 720_000) as i64, 3),
        );
        let cfg = Config { grid, params: Params { x_radius: Some(x_radius as i64), ..Params::default() }, ..nc201() };
        let t = expand(&src, cfg);
        if let Some(al) = t.alarm {
            // Only the growing-pitch bound may refuse these programs.
            assert_eq!((al.code, al.rule), (AlarmCode::Geometry, Rule::G162I), "{src}\n{al}");
            continue;
        }
        checked += 1;
        let d = depths(&t);
        if split {
            assert!(d.windows(2).all(|w| w[0] < w[1]), "{src} {d:?}");
            assert_eq!(d.last().copied(), Some(p), "{src}");
            let k = usize::try_from(p / q).unwrap();
            assert!(d.iter().take(k).enumerate().all(|(n, &x)| x == (n as i64 + 1) * q), "{src}");
            assert!(d.len() <= k + 4, "{src}");
        } else {
            assert_eq!(d, [0], "{src}");
        }
        let th = threads(&t);
        let last = th.last().unwrap();
        let depth = *d.last().unwrap();
        // G162.X: a single pass ends ② at X (its depth-0 line is X − Wd).
        let end_x = if split { x0 - 2 * sign * depth + taper } else { x0 };
        assert_eq!(last.x, end_x, "{src}");
        for m in &th {
            assert!(m.feed > 0, "{src}");
            // g162.lead = steps (the letter): every changing lead is stepped.
            assert_eq!(m.lead_steps, m.lead_change != 0, "{src}");
            assert!(m.lead_floor == 0 || (m.lead_change < 0 && m.lead_floor < m.feed), "{src}");
        }
        if i < 0 && f > -i {
            assert!(th.iter().all(|m| m.lead_floor == -i && m.lead_change == i), "{src}");
        }
        let ms = moves(&t);
        assert!(ms[1..].iter().all(|m| m.kind != MoveKind::Rapid), "{src}");
        // Every pass (5 moves at most) ends at S.
        let ends_at_s = t.events.windows(2).filter(|w| matches!(w[1], Event::Pass(_))).all(|w| match w[0] {
            Event::Move(m) => (m.x, m.z) == (sx, sz),
            _ => false,
        });
        assert!(ends_at_s, "{src}");
        assert_eq!(ms.last().map(|m| (m.x, m.z)), Some((sx, sz)), "{src}");
    }
    assert!(checked > 1_000, "{checked}");
}

/// No input panics under nc201, and G32/G33/G34 under gsk/fanuc: word soups over the new codes'
/// alphabets, random bytes, extreme values and configurations. Each call of `next` returns.
#[test]
fn no_panic_on_random_g162_and_thread_moves() {
    let mut s = 0xdead_beef_6162_0034u64;
    let alphabet = b"GGGXZWHPQVAFBIJKUM0123456789162.-   ;\n";
    let extremes = [0i64, 1, -1, 999_999_999, -999_999_999, i64::MAX, i64::MIN];
    for round in 0..20_000u32 {
        let r = xorshift(&mut s);
        let cfg = Config {
            dialect: [Dialect::Nc201, Dialect::Nc201, Dialect::Gsk, Dialect::Fanuc][(r % 4) as usize],
            grid: Grid {
                units: if r & 4 == 0 { Units::Metric } else { Units::Inch },
                increment: if r & 8 == 0 { Increment::Isb } else { Increment::Isc },
            },
            params: Params {
                x_radius: Some(((r >> 8) as u32 % 3) as i64),
                max_passes: Some([1, 7, 10_000, 0][(r >> 12) as usize % 4]),
                ..Params::default()
            },
            start_x: if r & 16 == 0 { 0 } else { extremes[(r >> 16) as usize % extremes.len()] },
            start_z: if r & 32 == 0 { 0 } else { extremes[(r >> 24) as usize % extremes.len()] },
            operator: cycle_vocab::Script::EMPTY,
            readings: cycle_vocab::Readings::default(),
        };
        let mut buf = [0u8; 96];
        if round % 3 == 0 {
            // A G162 / G34 block with random extreme words.
            let vals = ["0", "1", "-1", "999999.999", "-999999.999", "0.001", "89", "360", "0.0001", "9999"];
            let mut pick = || vals[(xorshift(&mut s) % vals.len() as u64) as usize];
            let text = if round % 2 == 0 {
                format!(
                    "G0 X{} Z{}\nG91 G162 X{} Z{} H{} P{} Q{} V{} W{} A{} F{} B{} I{} J{}",
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick()
                )
            } else {
                format!(
                    "G0 X{} Z{}\nG34 X{} Z{} F{} K{}\nG33 W{} P{}",
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick(),
                    pick()
                )
            };
            let n = text.len().min(buf.len());
            buf[..n].copy_from_slice(&text.as_bytes()[..n]);
        } else {
            let soup = round % 3 == 1;
            for b in buf.iter_mut() {
                let v = xorshift(&mut s);
                *b = if soup { alphabet[(v % alphabet.len() as u64) as usize] } else { (v >> 40) as u8 };
            }
        }
        let mut n = 0;
        for _ in crate::expander::Expander::new(&buf, cfg) {
            n += 1;
            if n > 200_000 {
                break;
            }
        }
    }
}

/// The traces of the G162 test programs, for review with `--nocapture`.
#[test]
fn g162_programs_expand() {
    for (name, src) in [
        ("straight", include_str!("../../../../tests/programs/g162_straight.nc")),
        ("taper", include_str!("../../../../tests/programs/g162_taper.nc")),
        ("multistart", include_str!("../../../../tests/programs/g162_multistart.nc")),
        ("variable", include_str!("../../../../tests/programs/g162_variable.nc")),
        ("internal_g91", include_str!("../../../../tests/programs/g162_internal_g91.nc")),
        ("cone", include_str!("../../../../corpus/g162_cone.nc")),
    ] {
        let t = expand(src, nc201());
        assert_eq!(t.alarm, None, "{name}");
        std::println!("== {name}\n{}", gcode(src, nc201()));
    }
}
