//! G70, G71, G72 and the contour (docs/INTERPRETATION.md, "Contours, arcs and the stock-removal
//! cycles") on the whole expander: the seed's two examples move by move, the layers of random
//! monotone contours (lines and arcs, G71 and G72, outside and inside, both arc directions)
//! against a search of the whole contour per layer, the layer ends' roundings (ties), every
//! alarm of the register with its code, word, rule and line, the flow and modal state around the
//! cycles, contours of 1 000 and 1 001 blocks, 10 000 layers, and `fill` against the iterator.
extern crate std;

use crate::contour::Kind;
use crate::rough::{cut_on, Axis};
use crate::tests::{expand, gcode, moves, passes, xorshift};
use crate::Expander;
use cycle_vocab::{Alarm, AlarmCode, Config, Event, Move, MoveKind, Params, Pass, PassKind, Rule};
use std::format;
use std::string::String;
use std::vec::Vec;

pub const EXAMPLE_1: &str = "N010 G50 X150 Z100\nN020 G00 X41 Z0\nN030 G71 U2 R1\nN040 G71 P50 Q120 U0.5 W0.2 F100\n\
N050 G01 X0 Z0\nN060 G03 X11 W-5.5 R5.5\nN070 G01 W-10\nN080 X17 W-10\nN090 W-15\nN100 G02 X29 W-7.348 R7.5\n\
N110 G01 W-12.652\nN120 X41\nN130 G70 P50 Q120 F30\n";

pub const EXAMPLE_2: &str = "N010 G50 X150 Z100\nN020 G00 X41 Z1\nN030 G72 W1 R1\nN040 G72 P50 Q80 U0.1 W0.2 F100\n\
N050 G00 X41 Z-31\nN060 G01 X20 Z-20\nN070 Z-2\nN080 X14 Z1\nN090 G70 P50 Q80 F30\n";

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

fn with_max_passes(max: i64) -> Config {
    Config { params: Params { max_passes: Some(max), ..Params::default() }, ..Config::default() }
}

/// A length in mm with three decimals.
fn mm(v: i64) -> String {
    format!("{}{}.{:03}", if v < 0 { "-" } else { "" }, v.abs() / 1000, v.abs() % 1000)
}

/// The cut ② of every ROUGH pass: the second move after its header.
fn layer_cuts(events: &[Event]) -> Vec<(u32, (i64, i64))> {
    let mut out = Vec::new();
    for (i, e) in events.iter().enumerate() {
        if let Event::Pass(Pass { index, kind: PassKind::Rough, .. }) = e {
            let cut = events[i + 1..].iter().filter_map(|e| if let Event::Move(m) = e { Some(m) } else { None }).nth(1);
            out.push((*index, cut.map(|m| (m.x, m.z)).unwrap()));
        }
    }
    out
}

/// G71.EXAMPLE (the seed's example 1, corpus `g71_example.nc`): A = X41 Z0, Δd = 2, e = 1,
/// Q = the contour shifted by U0.5 W0.2, Q₀ = X0.5 Z0.2. The register lists layers at X37 … X1;
/// its own rule (a layer exists while its cut is positive, c·(z_k − A.z) > 0) ends them at X5:
/// at X1 the shifted ball N060 (centre X0.5 Z−5.3, radius 5.5) is at Z+0.194, behind A.z, so
/// layer 10 would cut backwards. Nine layers, then the semi-finish pass and the return; the G70
/// then finishes the contour at F30 and returns to X41 Z0.
#[test]
fn example_1_g71_then_g70() {
    let t = expand(EXAMPLE_1, Config::default());
    assert_eq!(t.alarm, None);
    let cuts = layer_cuts(&t.events);
    let want: [(i64, i64); 9] = [
        (37_000, -60_300),
        (33_000, -60_300),
        (29_000, -47_593),
        (25_000, -46_795),
        (21_000, -45_115),
        (17_000, -24_467),
        (13_000, -17_800),
        (9_000, -1_809),
        (5_000, -281),
    ];
    assert_eq!(cuts.iter().map(|c| c.1).collect::<Vec<_>>(), want);
    // Layer 10 at X1: the cut end on the shifted N060 arc lies behind A.z = 0.
    let z10 = cut_on(Axis::G71, Kind::Arc(false), (500, 200), (11_500, -5_300), (500, -5_300), 1_000);
    assert_eq!(z10, 194);
    // The whole trace (roughing feed F100 = 1 000 000 lead counts).
    let f = 1_000_000;
    let mut m = Vec::new();
    m.push(Move::rapid(41_000, 0, Rule::PrjModal));
    for (x, z) in want {
        m.push(Move::feed(x, 0, f, Rule::G71Layer));
        m.push(Move::feed(x, z, f, Rule::G71Layer));
        m.push(Move::feed(x + 2_000, z + 1_000, f, Rule::G71Retract));
        m.push(Move::rapid(x + 2_000, 0, Rule::G71Retract));
    }
    let semi = Rule::G71Lastpass;
    m.extend([
        Move::feed(500, 200, f, semi),
        Move::arc(false, 11_500, -5_300, 500, -5_300, f, semi),
        Move::feed(11_500, -15_300, f, semi),
        Move::feed(17_500, -25_300, f, semi),
        Move::feed(17_500, -40_300, f, semi),
        Move::arc(true, 29_500, -47_648, 32_500, -40_300, f, semi),
        Move::feed(29_500, -60_300, f, semi),
        Move::feed(41_500, -60_300, f, semi),
        Move::rapid(41_000, 0, Rule::G71Return),
    ]);
    let g70 = Rule::G70Path;
    let f30 = 300_000;
    m.extend([
        Move::feed(0, 0, f30, g70),
        Move::arc(false, 11_000, -5_500, 0, -5_500, f30, g70),
        Move::feed(11_000, -15_500, f30, g70),
        Move::feed(17_000, -25_500, f30, g70),
        Move::feed(17_000, -40_500, f30, g70),
        Move::arc(true, 29_000, -47_848, 32_000, -40_500, f30, g70),
        Move::feed(29_000, -60_500, f30, g70),
        Move::feed(41_000, -60_500, f30, g70),
        Move::rapid(41_000, 0, Rule::G70Return),
    ]);
    assert_eq!(moves(&t), m);
    let p = passes(&t);
    assert_eq!(p.len(), 11);
    for (k, pass) in p.iter().take(9).enumerate() {
        assert_eq!(*pass, Pass { index: k as u32 + 1, kind: PassKind::Rough, diameter_depth: 4_000 * (k as i64 + 1), rule: Rule::G71Layer });
    }
    assert_eq!(p[9], Pass { index: 10, kind: PassKind::Semi, diameter_depth: 40_500, rule: Rule::G71Lastpass });
    assert_eq!(p[10], Pass { index: 1, kind: PassKind::Finish, diameter_depth: 41_000, rule: Rule::G70Path });
    std::println!("{}", gcode(EXAMPLE_1, Config::default()));
}

/// G72.EXAMPLE (the seed's example 2, corpus `g72_example.nc`): A = X41 Z1, Δd = 1, e = 1,
/// Q₀ = X41.1 Z−30.8: layers at Z0, −1, …, −30, each a rapid infeed (the ns block is G00), a
/// cut along X to the shifted contour, the 45° retract (+2e on X, +e on Z) and the rapid back
/// to X41; the semi-finish pass (depth = the Z distance 31.8), the return, then G70.
#[test]
fn example_2_g72_then_g70() {
    let t = expand(EXAMPLE_2, Config::default());
    assert_eq!(t.alarm, None);
    let cuts = layer_cuts(&t.events);
    assert_eq!(cuts.len(), 31);
    for (i, (index, (x, z))) in cuts.iter().enumerate() {
        assert_eq!((*index, *z), (i as u32 + 1, -(i as i64) * 1_000));
        // The shifted contour: N080 (X14.1 Z1.2 back to X20.1 Z−1.8) above Z−1.8, N070 at X20.1
        // down to Z−19.8, N060 to X41.1 Z−30.8 below it.
        let zk = -(i as i64) * 1_000;
        let want = if zk > -1_800 {
            // x = 20.1 + (zk + 1.8)·(14.1 − 20.1)/3
            20_100 + ((zk + 1_800) * -6_000) / 3_000
        } else if zk >= -19_800 {
            20_100
        } else {
            let num = (zk + 19_800) as f64 * 21_000.0 / -11_000.0;
            20_100 + num.round() as i64
        };
        assert_eq!(*x, want, "layer {}", i + 1);
    }
    let m = moves(&t);
    // Layer 1: rapid infeed to Z0, cut to X16.5, retract to X18.5 Z1, rapid to X41.
    assert_eq!(
        m[1..5],
        [
            Move::rapid(41_000, 0, Rule::G72Layer),
            Move::feed(16_500, 0, 1_000_000, Rule::G72Layer),
            Move::feed(18_500, 1_000, 1_000_000, Rule::G72Retract),
            Move::rapid(41_000, 1_000, Rule::G72Retract),
        ]
    );
    let p = passes(&t);
    assert_eq!(p[0], Pass { index: 1, kind: PassKind::Rough, diameter_depth: 2_000, rule: Rule::G72Layer });
    assert_eq!(p[31], Pass { index: 32, kind: PassKind::Semi, diameter_depth: 63_600, rule: Rule::G72Lastpass });
    let semi = Rule::G72Lastpass;
    let f = 1_000_000;
    let g70 = Rule::G70Path;
    let f30 = 300_000;
    let tail: Vec<Move> = m[m.len() - 10..].to_vec();
    assert_eq!(
        tail,
        [
            Move::rapid(41_100, -30_800, semi),
            Move::feed(20_100, -19_800, f, semi),
            Move::feed(20_100, -1_800, f, semi),
            Move::feed(14_100, 1_200, f, semi),
            Move::rapid(41_000, 1_000, Rule::G72Return),
            Move::rapid(41_000, -31_000, g70),
            Move::feed(20_000, -20_000, f30, g70),
            Move::feed(20_000, -2_000, f30, g70),
            Move::feed(14_000, 1_000, f30, g70),
            Move::rapid(41_000, 1_000, Rule::G70Return),
        ]
    );
    assert_eq!(p[32], Pass { index: 1, kind: PassKind::Finish, diameter_depth: 0, rule: Rule::G70Path });
}

/// A contour element as the reference sees it: kind, end, centre (X diameter, Z).
type Piece = (Kind, (i64, i64), (i64, i64));

/// One random monotone contour for G71 or G72: the program and what the reference needs.
struct Case {
    program: String,
    axis: Axis,
    start: (i64, i64),
    /// Element ends and centres, untranslated (element 0 the ns block).
    elements: Vec<Piece>,
    depth: i64,
    shift: (i64, i64),
}

/// Frame helpers (a the layer axis, b the cut axis), as in `rough.rs`.
fn frame_point(axis: Axis, a: i64, b: i64) -> (i64, i64) {
    match axis {
        Axis::G71 => (a, b),
        Axis::G72 => (b, a),
    }
}

fn fa(axis: Axis, p: (i64, i64)) -> i64 {
    match axis {
        Axis::G71 => p.0,
        Axis::G72 => p.1,
    }
}

fn fb(axis: Axis, p: (i64, i64)) -> i64 {
    match axis {
        Axis::G71 => p.1,
        Axis::G72 => p.0,
    }
}

/// A random monotone contour: the ns block moves along a only; then lines (G00/G01) and
/// quarter-or-less arcs (I/K, both families of a quadrant: both directions occur) with
/// s·Δa ≤ 0 and c·Δb ≥ 0. Coordinates in half units for arcs: (u, v) = (X, 2Z).
fn random_case(state: &mut u64) -> Case {
    let mut r = |n: u64| xorshift(state) % n;
    let axis = if r(2) == 0 { Axis::G71 } else { Axis::G72 };
    let s = if r(2) == 0 { -1i64 } else { 1 };
    let c = if r(2) == 0 { -1i64 } else { 1 };
    let start = (r(60_000) as i64 + 20_000, r(40_000) as i64 - 20_000);
    let (a0, b0) = (fa(axis, start), fb(axis, start));
    let mut elements = Vec::new();
    let first_a = a0 + s * (r(40_000) as i64 + 2_000);
    let ns_rapid = r(2) == 0;
    let ns_end = frame_point(axis, first_a, b0);
    elements.push((if ns_rapid { Kind::Rapid } else { Kind::Feed }, ns_end, (0, 0)));
    let mut program = format!("G0 X{} Z{}\n", mm(start.0), mm(start.1));
    let depth = r(3_000) as i64 + 300;
    let retract = r(1_500) as i64;
    let shift = (r(2_000) as i64 - 1_000, r(2_000) as i64 - 1_000);
    let code = if axis == Axis::G71 { "G71" } else { "G72" };
    let dword = if axis == Axis::G71 { "U" } else { "W" };
    program += &format!("{code} {dword}{} R{}\n", mm(depth), mm(retract));
    let count = r(8) as usize + 1;
    program += &format!(
        "{code} P10 Q{} U{} W{} F0.2\n",
        10 + count,
        mm(shift.0),
        mm(shift.1)
    );
    program += &format!("N10 {} X{} Z{}\n", if ns_rapid { "G00" } else { "G01" }, mm(ns_end.0), mm(ns_end.1));
    // Half units per count along a and b.
    let (ha, hb) = match axis {
        Axis::G71 => (1i64, 2i64),
        Axis::G72 => (2, 1),
    };
    let mut p = ns_end;
    for i in 0..count {
        let n = 11 + i;
        let kind = r(3);
        if kind < 2 {
            // A line: at least one axis moves.
            let (da, db) = loop {
                let da = -s * (r(3) as i64) * (r(4_000) as i64);
                let db = c * (r(3) as i64) * (r(4_000) as i64);
                if da != 0 || db != 0 {
                    break (da, db);
                }
            };
            let e = frame_point(axis, fa(axis, p) + da, fb(axis, p) + db);
            let g = if kind == 0 { "G00" } else { "G01" };
            program += &format!("N{n} {g} X{} Z{}\n", mm(e.0), mm(e.1));
            elements.push((if kind == 0 { Kind::Rapid } else { Kind::Feed }, e, (0, 0)));
            p = e;
        } else {
            // An arc: radius ρ (even, half units), family 1 (centre along b from P) or 2 (centre
            // along a), end angle φ ≤ 90° (exactly 90° half the time).
            let rho = 2 * (r(3_000) as i64 + 200);
            let phi = if r(2) == 0 { core::f64::consts::FRAC_PI_2 } else { (15.0 + r(70) as f64).to_radians() };
            let (pa_h, pb_h) = (fa(axis, p) * ha, fb(axis, p) * hb);
            let (ca_h, cb_h, ea_h, eb_h);
            if r(2) == 0 {
                ca_h = pa_h;
                cb_h = pb_h + c * rho;
                ea_h = ca_h as f64 - (s * rho) as f64 * phi.sin();
                eb_h = cb_h as f64 - (c * rho) as f64 * phi.cos();
            } else {
                ca_h = pa_h - s * rho;
                cb_h = pb_h;
                ea_h = ca_h as f64 + (s * rho) as f64 * phi.cos();
                eb_h = cb_h as f64 + (c * rho) as f64 * phi.sin();
            }
            // Round the end to the grid: a and b counts.
            let ea = (ea_h / ha as f64).round() as i64;
            let eb = (eb_h / hb as f64).round() as i64;
            let e = frame_point(axis, ea, eb);
            let centre = frame_point(axis, ca_h / ha, cb_h / hb);
            // Direction in the (v right, u up) plane: the sign of (S − C) × (E − C).
            let half = |q: (i64, i64)| (2 * q.1, q.0); // (v, u)
            let (sc, ec) = ((half(p).0 - half(centre).0, half(p).1 - half(centre).1), (half(e).0 - half(centre).0, half(e).1 - half(centre).1));
            let cross = sc.0 as i128 * ec.1 as i128 - sc.1 as i128 * ec.0 as i128;
            let cw = cross < 0;
            let i_word = (centre.0 - p.0) / 2;
            let k_word = centre.1 - p.1;
            program += &format!(
                "N{n} {} X{} Z{} I{} K{}\n",
                if cw { "G02" } else { "G03" },
                mm(e.0),
                mm(e.1),
                mm(i_word),
                mm(k_word)
            );
            elements.push((Kind::Arc(cw), e, centre));
            p = e;
        }
    }
    Case { program, axis, start, elements, depth, shift }
}

/// The layers by a search of the whole contour for every layer (the register's words, with
/// the crossing itself from `cut_on`): (a_k, b_k) for k = 1, 2, … until one fails; and whether
/// the layers ended because a cut was not positive (not at Q₀), and how many ended on an arc.
fn reference_layers(case: &Case, limit: usize) -> (Vec<(i64, i64)>, bool, usize) {
    let axis = case.axis;
    let shifted: Vec<(i64, i64)> = case.elements.iter().map(|e| (e.1 .0 + case.shift.0, e.1 .1 + case.shift.1)).collect();
    let a_start = fa(axis, case.start);
    let s = (fa(axis, case.elements[0].1) - a_start).signum();
    let c = (fb(axis, case.elements.last().unwrap().1) - fb(axis, case.elements[0].1)).signum();
    let pa = if axis == Axis::G71 { 2 } else { 1 };
    let q0 = shifted[0];
    let mut out = Vec::new();
    let mut on_arcs = 0;
    for k in 1..=limit as i64 {
        let ak = a_start + s * k * case.depth * pa;
        if s * (ak - fa(axis, q0)) >= 0 {
            return (out, false, on_arcs);
        }
        let j = (0..shifted.len()).rev().find(|&j| s * (fa(axis, shifted[j]) - ak) >= 0).unwrap();
        let bk = if j + 1 == shifted.len() {
            fb(axis, shifted[j])
        } else {
            let e = &case.elements[j + 1];
            let centre = (e.2 .0 + case.shift.0, e.2 .1 + case.shift.1);
            on_arcs += usize::from(matches!(e.0, Kind::Arc(_)));
            cut_on(axis, e.0, shifted[j], shifted[j + 1], centre, ak)
        };
        if c * (bk - fb(axis, case.start)) <= 0 {
            return (out, true, on_arcs);
        }
        out.push(frame_point(axis, ak, bk));
    }
    (out, false, on_arcs)
}

/// G71.LAYER / G72.LAYER, the sweep and the count: on 3 000 random monotone contours, the
/// expander's layers (the cursor moving once along the contour, the count by one pass over the
/// elements) equal a search of the whole contour per layer, layer for layer; the semi-finish
/// pass follows the shifted contour element by element; `fill` gives the iterator's stream.
#[test]
fn layers_match_a_search_per_layer() {
    let mut state = 0x0071_0072_5eed_u64;
    let (mut compared, mut layers_total, mut ended_by_cut, mut arc_layers) = (0, 0, 0, 0);
    for _ in 0..3_000 {
        let case = random_case(&mut state);
        let t = expand(&case.program, Config::default());
        match t.alarm {
            None => {}
            // A rounded arc end may make the contour turn by an increment: refused, skipped.
            Some(a) if a.rule == Rule::G71Monotone || a.rule == Rule::G72Monotone => continue,
            Some(a) => panic!("{a:?}\n{}", case.program),
        }
        let (want, by_cut, on_arcs) = reference_layers(&case, 20_000);
        ended_by_cut += usize::from(by_cut);
        arc_layers += on_arcs;
        let got: Vec<(i64, i64)> = layer_cuts(&t.events).iter().map(|c| c.1).collect();
        assert_eq!(got, want, "\n{}", case.program);
        // Every layer's path: infeed, cut, retract, back.
        let semi: Vec<Move> = {
            let m = moves(&t);
            let i = m.iter().rposition(|m| m.rule == Rule::G71Return || m.rule == Rule::G72Return).unwrap();
            m[i - (case.elements.len() - 1)..i].to_vec()
        };
        for (m, e) in semi.iter().zip(&case.elements[1..]) {
            assert_eq!((m.x, m.z), (e.1 .0 + case.shift.0, e.1 .1 + case.shift.1));
            if let Kind::Arc(cw) = e.0 {
                assert_eq!((m.kind, m.cx, m.cz), (if cw { MoveKind::ArcCw } else { MoveKind::ArcCcw }, e.2 .0 + case.shift.0, e.2 .1 + case.shift.1));
            }
        }
        assert_fill_agrees(&case.program, Config::default(), &[1, 2, 3, 5, 7, 64]);
        compared += 1;
        layers_total += want.len();
    }
    assert!(compared > 2_000, "{compared}");
    assert!(layers_total > 20_000, "{layers_total}");
    // Both ends of the layers occur often: the contour's start reached, and a cut behind A.
    assert!(ended_by_cut > 300, "{ended_by_cut}");
    assert!(arc_layers > 2_000, "{arc_layers}");
}

/// The cut ends' rounding (one quotient on a line, one square root on an arc), against a float
/// computation away from rounding boundaries, and the ties: on a line a quotient of exactly
/// ½, on a G71 arc an odd square radicand (Z = c_z ± √M/2), rounded half away from zero.
#[test]
fn cut_ends_round_once_half_away_from_zero() {
    // Line ties: from (X0, Z1) to (X4, Z0) at X2: Z = 0.5 increment → 1; toward −Z: −0.5 → −1.
    assert_eq!(cut_on(Axis::G71, Kind::Feed, (0, 1), (4, 0), (0, 0), 2), 1);
    assert_eq!(cut_on(Axis::G71, Kind::Feed, (0, -1), (4, 0), (0, 0), 2), -1);
    assert_eq!(cut_on(Axis::G71, Kind::Feed, (0, -3), (4, -2), (0, 0), 2), -3); // −2.5
    assert_eq!(cut_on(Axis::G71, Kind::Feed, (0, 2), (4, 3), (0, 0), 2), 3); // 2.5
    // G72 on X: from (X1, Z0) to (X0, Z2) at Z1: X = 0.5 → 1.
    assert_eq!(cut_on(Axis::G72, Kind::Feed, (1, 0), (0, 2), (0, 0), 1), 1);
    assert_eq!(cut_on(Axis::G72, Kind::Feed, (-1, 0), (0, 2), (0, 0), 1), -1);
    // G71 arc ties: centre X0 Z0, start on the circle at X0 Z5 (r = 10 half units); at X6
    // (d = 6): M = 100 − 36 = 64, √M = 8: Z = ±4 exactly. At X8: M = 36, Z = ±3.
    assert_eq!(cut_on(Axis::G71, Kind::Arc(true), (0, 5), (10, 0), (0, 0), 6), 4);
    // Radius 13 half units is no grid point on v; take r² = 6² + (2·4)² = 100 again but at
    // X = 0 ± ... an odd square: centre X0 Z0, start X3 Z−2 (r² = 9 + 16 = 25), at X0:
    // M = 25, √M = 5: Z = −2.5 → −3 (away from zero); mirrored at +2.5 → 3.
    assert_eq!(cut_on(Axis::G71, Kind::Arc(false), (3, -2), (0, -3), (0, 0), 0), -3);
    assert_eq!(cut_on(Axis::G71, Kind::Arc(true), (3, 2), (0, 3), (0, 0), 0), 3);
    // The same with the centre at Z1: Z = 1 − 2.5 = −1.5 → −2; 1 + 2.5 = 3.5 → 4.
    assert_eq!(cut_on(Axis::G71, Kind::Arc(false), (3, -1), (0, -2), (0, 1), 0), -2);
    assert_eq!(cut_on(Axis::G71, Kind::Arc(true), (3, 3), (0, 4), (0, 1), 0), 4);
    // Random arcs and lines against floats.
    let mut state = 0x0000_c0de_0c07_u64;
    let mut checked = 0;
    for _ in 0..100_000 {
        let mut r = |n: u64| (xorshift(&mut state) % n) as i64;
        let axis = if r(2) == 0 { Axis::G71 } else { Axis::G72 };
        let (cx, cz) = (r(200_000) - 100_000, r(200_000) - 100_000);
        let rho = r(50_000) + 10; // radius, increments
        let t0 = r(6283) as f64 / 1000.0;
        // A start on the grid near the circle; the circle is then the one through it.
        let s = (cx + (2.0 * rho as f64 * t0.sin()).round() as i64, cz + (rho as f64 * t0.cos()).round() as i64);
        let (su, sv) = ((s.0 - cx) as f64, 2.0 * (s.1 - cz) as f64);
        let rr = (su * su + sv * sv).sqrt();
        // A layer through the circle along a.
        let (ha, hb) = if axis == Axis::G71 { (1.0, 2.0) } else { (2.0, 1.0) };
        let ca = if axis == Axis::G71 { cx } else { cz };
        let cb = if axis == Axis::G71 { cz } else { cx };
        let span = (rr / ha) as i64;
        if span < 2 {
            continue;
        }
        let ak = ca + r(2 * span as u64) - span;
        let sb = if axis == Axis::G71 { s.1 } else { s.0 };
        let plus = sb >= cb;
        let d = (ak - ca) as f64 * ha;
        let exact = cb as f64 + if plus { 1.0 } else { -1.0 } * (rr * rr - d * d).max(0.0).sqrt() / hb;
        if (exact.abs().fract() - 0.5).abs() < 1e-6 {
            continue;
        }
        let want = exact.abs().round() as i64 * if exact < 0.0 { -1 } else { 1 };
        assert_eq!(cut_on(axis, Kind::Arc(true), s, s, (cx, cz), ak), want, "{axis:?} c {cx},{cz} s {s:?} ak {ak}");
        checked += 1;
    }
    assert!(checked > 90_000);
}

/// G71.FORMAT, G71.DEPTH, G71.RETRACT, G72.DEPTH, G70.FORMAT, CNT.PQ: the words and values of
/// the cycle blocks, and the missing words in their order.
#[test]
fn cycle_block_words() {
    let a = |src: &str| alarm_of(&format!("G0 X41 Z0\n{src}"));
    let oor = |w: u8, rule: Rule| al(AlarmCode::OutOfRange, w, rule, 2);
    let wna = |w: u8| al(AlarmCode::WordNotAllowed, w, Rule::PrjWord, 2);
    // First blocks.
    assert_eq!(a("G71 U0 R1"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U-1"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U1000000"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U999999999999999999"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U1 R-0.001"), oor(b'R', Rule::G71Retract));
    assert_eq!(a("G71 U1 R1000000"), oor(b'R', Rule::G71Retract));
    assert_eq!(a("G71 U1.0001"), al(AlarmCode::Precision, b'U', Rule::ComUnits, 2));
    assert_eq!(a("G71 U1 R0"), None);
    assert_eq!(a("G71 U1 F1"), wna(b'F'));
    assert_eq!(a("G71 W1"), wna(b'W'));
    assert_eq!(a("G72 W0"), oor(b'W', Rule::G72Depth));
    assert_eq!(a("G72 W1 R-1"), oor(b'R', Rule::G72Depth));
    assert_eq!(a("G72 U1"), wna(b'U'));
    assert_eq!(a("G72 W1 R1 S100 T0101 M8 N5"), None);
    // Second blocks: allowed P Q U W F (and S T …); values; missing F, P, Q.
    assert_eq!(a("G71 P1 Q2 F1 X1"), wna(b'X'));
    assert_eq!(a("G71 P1 Q2 F1 R1"), wna(b'R'));
    assert_eq!(a("G72 Q2 F1 I1"), wna(b'I'));
    assert_eq!(a("G70 P1 Q2 R1"), wna(b'R'));
    for code in ["G70", "G71", "G72"] {
        assert_eq!(a(&format!("{code} P1.0 Q2 F1")), al(AlarmCode::NotInteger, b'P', Rule::ComRanges, 2), "{code}");
        assert_eq!(a(&format!("{code} P0 Q2 F1")), oor(b'P', Rule::CntPq), "{code}");
        assert_eq!(a(&format!("{code} P1 Q100000 F1")), oor(b'Q', Rule::CntPq), "{code}");
        assert_eq!(a(&format!("{code} P1 Q-2 F1")), oor(b'Q', Rule::CntPq), "{code}");
        assert_eq!(a(&format!("{code} P1 Q2 U1000000 F1")), oor(b'U', Rule::ComRanges), "{code}");
        assert_eq!(a(&format!("{code} P1 Q2 W-1000000 F1")), oor(b'W', Rule::ComRanges), "{code}");
        assert_eq!(a(&format!("{code} P1 Q2")), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2), "{code}");
        assert_eq!(a(&format!("{code} Q2 F1")), al(AlarmCode::MissingWord, b'P', Rule::CntPq, 2), "{code}");
        assert_eq!(a(&format!("{code} P1 F1")), al(AlarmCode::MissingWord, b'Q', Rule::CntPq, 2), "{code}");
        assert_eq!(a(&format!("{code} P1")), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2), "{code}");
        // With a modal feed F may be omitted (then P, Q are looked for).
        assert_eq!(alarm_of(&format!("G1 X41 Z0 F1\n{code} P1 Q2")), al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, 2), "{code}");
    }
}

/// A G71 cycle from X41 Z0 (Δd 2, e 1, F0.2) around the contour `body` (its blocks N50 …),
/// the cycle block on line 3: `G71 P50 Q<nf>`.
fn g71(nf: u32, body: &str) -> String {
    format!("G0 X41 Z0\nG71 U2 R1\nG71 P50 Q{nf} F0.2\n{body}")
}

/// CNT.FIND, CNT.MAX, CNT.RANGE for G71/G72: the contour right after the P/Q block, N(nf)
/// before the end, at most 1 000 blocks; a lexing alarm inside is that alarm; the find comes
/// before the blocks' own checks.
#[test]
fn contour_find_and_bound() {
    let nf = |line| al(AlarmCode::BlockNotFound, b'Q', Rule::CntFind, line);
    let np = |line| al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, line);
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN60 Z-10\n")), None);
    // The block after the P/Q block is not N50, or there is none.
    assert_eq!(alarm_of(&g71(60, "N49 G1 X20\nN50 X10\nN60 Z-10\n")), np(3));
    assert_eq!(alarm_of(&g71(60, "G1 X20\nN50 X10\nN60 Z-10\n")), np(3));
    assert_eq!(alarm_of(&g71(60, "")), np(3));
    assert_eq!(alarm_of(&g71(60, "(only a comment)\n\n")), np(3));
    // Blank and comment lines are no blocks: N50 is still the next block.
    assert_eq!(alarm_of(&g71(60, "\n(c)\nN50 G1 X20\n;\nN60 Z-10\n")), None);
    // N(nf) missing before the end; N(nf) = N(ns) is a one-block contour (c = 0 then).
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN61 Z-10\n")), nf(3));
    assert_eq!(alarm_of(&g71(50, "N50 G1 X20\n")), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 3));
    // N50.0 and N050 are N50; N(nf) is the first one at or after N(ns).
    assert_eq!(alarm_of(&g71(60, "N050 G1 X20\nN60.0 Z-10\nN60 X50\n")), None);
    // A lexing alarm while the contour is read, on its line — before a missing N(nf).
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 Z-5 #\nN59 X30\n")), al(AlarmCode::BadCharacter, b'#', Rule::PrjLex, 5));
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 Z-5 (open\n")), al(AlarmCode::UnclosedComment, b'(', Rule::PrjLex, 5));
    // The find before the blocks' checks: a bad block and no N(nf) is BLOCK NOT FOUND.
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 G04 Z-5\nN59 X30\n")), nf(3));
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 G04 Z-5\nN60 X30\n")), al(AlarmCode::WordNotAllowed, b'G', Rule::CntWords, 5));
    // CNT.MAX: 1 000 blocks are a contour; a 1 001st without N(nf) is CONTOUR TOO LONG, even
    // when it is N(nf) itself or the program would end without N(nf) after it.
    let body = |blocks: usize, last: &str| {
        let mut s = String::from("N50 G1 X20\n");
        for i in 1..blocks - 1 {
            s += &format!("W-0.01 (block {})\n", i + 1);
        }
        s + last
    };
    let t = expand(&g71(60, &body(1_000, "N60 X50\n")), Config::default());
    assert_eq!(t.alarm, None);
    // Every one of the 998 W-0.01 steps is an element of the semi-finish pass.
    assert_eq!(moves(&t).iter().filter(|m| m.rule == Rule::G71Lastpass).count(), 1 + 998 + 1);
    let long = |line| al(AlarmCode::ContourTooLong, b'Q', Rule::CntMax, line);
    assert_eq!(alarm_of(&g71(60, &body(1_001, "N60 X50\n"))), long(3));
    assert_eq!(alarm_of(&g71(60, &body(1_001, "X50\n"))), long(3));
    assert_eq!(alarm_of(&g71(60, &body(1_000, "X50\n"))), nf(3));
    assert_eq!(alarm_of(&g71(60, &body(1_002, "N60 X50\n"))), long(3));
}

/// CNT.WORDS, CNT.NOSUB and every block check inside a contour, on the block's own line:
/// G codes other than G00–G03, M codes, other letters; conflicts; values; arcs; no MISSING
/// WORD F; T while compensating. The first block's alarm in program order is the one named.
#[test]
fn contour_block_checks() {
    let a = |block: &str| alarm_of(&g71(60, &format!("N50 G1 X20\n{block}\nN60 X50\n")));
    let wna = |w: u8, rule: Rule| al(AlarmCode::WordNotAllowed, w, rule, 5);
    for g in ["G04", "G70", "G50 X1", "G90", "G41", "G40", "G20", "G21", "G1.5", "G5", "G32", "G96", "G0 G99"] {
        assert_eq!(a(&format!("{g} Z-5")), wna(b'G', Rule::CntWords), "{g}");
    }
    assert_eq!(a("M98 P100"), wna(b'M', Rule::CntNosub));
    assert_eq!(a("M99"), wna(b'M', Rule::CntNosub));
    assert_eq!(a("M98.0"), wna(b'M', Rule::CntNosub));
    assert_eq!(a("M3 Z-5"), wna(b'M', Rule::CntWords));
    assert_eq!(a("M30"), wna(b'M', Rule::CntWords));
    assert_eq!(a("M1.5"), wna(b'M', Rule::CntWords));
    // M before the two-motion-codes conflict; G before M.
    assert_eq!(a("G0 G1 M3"), wna(b'M', Rule::CntWords));
    assert_eq!(a("G4 M98"), wna(b'G', Rule::CntWords));
    for l in ["O1", "P1", "Q1", "J1", "L1", "D1", "E1", "H1", "A1", "B1", "V1"] {
        assert_eq!(a(&format!("Z-5 {l}")), wna(l.as_bytes()[0], Rule::CntWords), "{l}");
    }
    // Arc words in a G00/G01 block are PRJ.WORD, as in any block; alphabetical order decides.
    assert_eq!(a("Z-5 R1"), wna(b'R', Rule::PrjWord));
    assert_eq!(a("Z-5 I1 O1"), wna(b'I', Rule::PrjWord));
    assert_eq!(a("Z-5 K1 J1"), wna(b'J', Rule::CntWords));
    // Conflicts.
    assert_eq!(a("G0 G1 Z-5"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 5));
    assert_eq!(a("G1 G1 Z-5"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 5));
    assert_eq!(a("X1 U1"), al(AlarmCode::Conflict, b'U', Rule::ComAbsInc, 5));
    assert_eq!(a("Z1 W1 O1"), al(AlarmCode::Conflict, b'W', Rule::ComAbsInc, 5));
    assert_eq!(a("G2 X30 W-5 R5 I1"), al(AlarmCode::Conflict, b'R', Rule::ArcFormat, 5));
    // Values.
    assert_eq!(a("Z-5 F0"), al(AlarmCode::OutOfRange, b'F', Rule::ComRanges, 5));
    assert_eq!(a("Z-1000000"), al(AlarmCode::OutOfRange, b'Z', Rule::ComRanges, 5));
    assert_eq!(a("Z-5.0001"), al(AlarmCode::Precision, b'Z', Rule::ComUnits, 5));
    assert_eq!(a("G2 X30 W-5 R0"), al(AlarmCode::OutOfRange, b'R', Rule::ArcR, 5));
    // Arcs: missing R, then the geometry, each on its line; no feed is needed.
    assert_eq!(a("G2 X30 W-5"), al(AlarmCode::MissingWord, b'R', Rule::ArcFormat, 5));
    assert_eq!(a("G2 X20 W0 R5"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 5));
    assert_eq!(a("G2 X30 W-5 I0 K0"), al(AlarmCode::Geometry, b'I', Rule::ArcIk, 5));
    assert_eq!(a("G2 X30 W-50 R5"), al(AlarmCode::Geometry, b'R', Rule::ArcR, 5));
    assert_eq!(a("G3 X30 W-5 K-6"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 5));
    // No MISSING WORD F in a contour (the cycle block's F is the feed).
    assert_eq!(alarm_of("G0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\nN60 G2 X30 W-5 R5\n"), None);
    // T while G41/G42 is in force (TNRC.SWITCH, the contour block's line).
    let comp = |body: &str| alarm_of(&format!("G42\nG0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\n{body}\nN60 X50\n"));
    assert_eq!(comp("Z-5 T0202"), al(AlarmCode::WordNotAllowed, b'T', Rule::TnrcSwitch, 6));
    assert_eq!(comp("Z-5 S500"), None);
    // The first alarm in program order.
    assert_eq!(
        alarm_of(&g71(60, "N50 G1 X20\nZ-5 O1\nG4 Z-6\nN60 X50\n")),
        al(AlarmCode::WordNotAllowed, b'O', Rule::CntWords, 5)
    );
    // Blocks without axis words move nothing; their F waits for the next move (G70).
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nF0.5 S300 T0101\nN60 X50 Z-5\n")), None);
}

/// CNT.FIRST, G71.TYPE2, G71.FIRST, G71.MONOTONE (and G72's): the cycle checks after the
/// contour's own, in the register's order. Lines (docs/INTERPRETATION.md, G71 "Alarm lines"):
/// CNT.FIRST, TYPE2 and FIRST on the ns block's, c = 0 on the cycle block's, the monotonicity of
/// an element on the element's.
#[test]
fn cycle_checks() {
    let a = |body: &str| alarm_of(&g71(60, body));
    // CNT.FIRST: the ns block writes no motion code, or an arc.
    assert_eq!(a("N50 X20\nN60 Z-10\n"), al(AlarmCode::MissingWord, b'G', Rule::CntFirst, 4));
    assert_eq!(a("N50 G2 X20 Z0 R5\nN60 G1 Z-10\n"), al(AlarmCode::Geometry, b'R', Rule::ArcR, 4));
    assert_eq!(a("N50 G2 X31 Z0 R5\nN60 G1 Z-10\n"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntFirst, 4));
    assert_eq!(a("N50 G3 X31 R5\nN60 G1 Z-10\n"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntFirst, 4));
    // An ns block without motion code is checked as G00/G01: an arc word in it is PRJ.WORD.
    assert_eq!(a("N50 X20 R5\nN60 G1 Z-10\n"), al(AlarmCode::WordNotAllowed, b'R', Rule::PrjWord, 4));
    // G71.TYPE2 (the ns block moves Z) before G71.FIRST; by motion, not by words.
    assert_eq!(a("N50 G1 X20 Z-1\nN60 Z-10\n"), al(AlarmCode::Unsupported, b'Z', Rule::G71Type2, 4));
    assert_eq!(a("N50 G1 X41 W-1\nN60 Z-10\n"), al(AlarmCode::Unsupported, b'Z', Rule::G71Type2, 4));
    assert_eq!(a("N50 G1 X20 Z0\nN60 Z-10\n"), None);
    assert_eq!(a("N50 G1 X41\nN60 Z-10\n"), al(AlarmCode::Geometry, b'X', Rule::G71First, 4));
    assert_eq!(a("N50 G1 Z0\nN60 Z-10\n"), al(AlarmCode::Geometry, b'X', Rule::G71First, 4));
    // G71.MONOTONE: c = 0 (the contour ends at A′'s Z), then element by element, X before Z.
    assert_eq!(a("N50 G1 X20\nN60 X30\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 3));
    assert_eq!(a("N50 G1 X20\nN55 Z-10\nN60 Z0\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 3));
    assert_eq!(a("N50 G1 X20\nZ-10\nX18\nN60 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    assert_eq!(a("N50 G1 X20\nZ-10\nZ-5\nN60 Z-20\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 6));
    assert_eq!(a("N50 G1 X20\nZ-10\nX18 Z-5\nN60 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    // Equal X or equal Z pieces are legal; a rapid is an element like any.
    assert_eq!(a("N50 G1 X20\nZ-10\nX30\nG0 X35 Z-12\nN60 G1 Z-20\n"), None);
    // Arcs: a quadrant point strictly inside the sweep. From X20 Z-10: G02 to X30 Z-15 about
    // X30 Z-10 (I5) is a quarter (legal); G03 the long way round turns in X first.
    assert_eq!(a("N50 G1 X20\nZ-10\nG2 X30 Z-15 I5\nN60 G1 Z-20\n"), None);
    assert_eq!(a("N50 G1 X20\nZ-10\nG3 X30 Z-15 I5\nN60 G1 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    // A half circle through an extreme Z (its ends monotone: X20 → X40 at one Z): Z turns.
    assert_eq!(a("N50 G1 X20\nZ-10\nG2 X40 Z-10 R5\nN60 G1 Z-20\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 6));
    // An arc whose ends go the wrong way fails on its ends (X).
    assert_eq!(a("N50 G1 X20\nZ-10\nG2 X10 Z-15 I-5\nN60 G1 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    // G72: TYPE2 on X, FIRST on Z, c = 0 on X; Z (the layer axis) before X.
    let b = |body: &str| alarm_of(&format!("G0 X41 Z1\nG72 W1 R1\nG72 P50 Q60 F0.2\n{body}"));
    assert_eq!(b("N50 G0 X40 Z-20\nN60 G1 X10\n"), al(AlarmCode::Unsupported, b'X', Rule::G72Type2, 4));
    assert_eq!(b("N50 G0 X41 Z1\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'Z', Rule::G72First, 4));
    assert_eq!(b("N50 G0 Z-20\nN60 G1 Z-10\n"), al(AlarmCode::Geometry, b'X', Rule::G72Monotone, 3));
    assert_eq!(b("N50 G0 Z-20\nX30 Z-21\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'Z', Rule::G72Monotone, 5));
    assert_eq!(b("N50 G0 Z-20\nX50 Z-21\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'Z', Rule::G72Monotone, 5));
    assert_eq!(b("N50 G0 Z-20\nX50 Z-19\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'X', Rule::G72Monotone, 5));
    assert_eq!(b("N50 G0 Z-20\nX30 Z-19\nN60 G1 X10\n"), None);
}

/// PRJ.MAXPASS: K layers + the semi-finish pass against `max_passes`, before any motion of the
/// cycle — `TOO MANY PASSES` on U (G71) or W (G72), the cycle block's line. 10 000 layers run
/// within max_passes = 10 001, and one more is refused.
#[test]
fn pass_bound() {
    // A = X41 Z0, Δd = 0.001: layer k at X41 − 0.002k; Q₀ = X20.998: layers while
    // 0.002k < 20.002, k ≤ 10 000.
    let src = "G0 X41 Z0\nG71 U0.001 R0.001\nG71 P50 Q60 F0.2\nN50 G1 X20.998\nN60 Z-10\n";
    let t = expand(src, with_max_passes(10_001));
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(p.len(), 10_001);
    assert_eq!(p[9_999], Pass { index: 10_000, kind: PassKind::Rough, diameter_depth: 20_000, rule: Rule::G71Layer });
    assert_eq!(p[10_000].kind, PassKind::Semi);
    let cuts = layer_cuts(&t.events);
    assert_eq!(cuts[9_999].1, (21_000, -10_000));
    let refused = expand(src, with_max_passes(10_000));
    assert_eq!(refused.alarm, al(AlarmCode::TooManyPasses, b'U', Rule::PrjMaxPass, 3));
    // Before any motion of the cycle: only the G0 rapid stands in the trace.
    assert_eq!(refused.events.len(), 1);
    // The default bound (10 000) refuses it as well; G72 names W.
    assert_eq!(alarm_of(src), al(AlarmCode::TooManyPasses, b'U', Rule::PrjMaxPass, 3));
    let g72 = "G0 X41 Z1\nG72 W0.001 R0\nG72 P50 Q60 F0.2\nN50 G0 Z-20\nN60 G1 X10\n";
    // Layers at Z1 − 0.001k while above Q₀.z = −20: k ≤ 20 999, then the semi-finish pass.
    let t = expand(g72, with_max_passes(21_000));
    assert_eq!((t.alarm, passes(&t).len()), (None, 21_000));
    assert_eq!(expand(g72, with_max_passes(20_999)).alarm, al(AlarmCode::TooManyPasses, b'W', Rule::PrjMaxPass, 3));
    // The cut-positive end counts: Δw moves the contour behind A.z, so the deep layers (the
    // contour's start) do not cut and are no layers; the bound sees only the layers that cut.
    let behind = "G0 X41 Z0\nG71 U0.5 R0\nG71 P50 Q60 W5 F0.2\nN50 G1 X1\nN60 X40 Z-39\n";
    let t = expand(behind, Config::default());
    assert_eq!(t.alarm, None);
    // Q from X1 Z5 to X40 Z-34 (a line): the cut at X_k is behind Z0 while X_k < 6.
    let cuts = layer_cuts(&t.events);
    assert!(cuts.iter().all(|c| c.1 .1 < 0));
    assert_eq!(cuts.last().unwrap().1 .0, 7_000);
    assert_eq!(expand(behind, with_max_passes(cuts.len() as i64)).alarm, al(AlarmCode::TooManyPasses, b'U', Rule::PrjMaxPass, 3));
    assert_eq!(expand(behind, with_max_passes(cuts.len() as i64 + 1)).alarm, None);
}

/// G70.*, CNT.FIND for G70: the contour before the G70 block (exactly one N(ns), N(nf) after it
/// within 1 000 blocks and before the G70 block), run as ordinary moves from the start point
/// with U/W, the feed rule, the return; a contour met without a cycle runs as ordinary blocks.
#[test]
fn g70_alone() {
    let src = "G0 X50 Z5\nN50 G1 X20 Z0 F0.1\nN60 Z-10 F0.2\nN65 F0.3\nN70 G2 X30 Z-15 R5\nN80 G0 X50\nG0 X50 Z5\nG70 P50 Q80 U0.4 W0.1 F0.05\nG1 Z6\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    // The contour first runs as ordinary blocks (CNT.FLOW).
    assert_eq!(m[1], Move::feed(20_000, 0, 1_000, Rule::PrjModal));
    assert_eq!(m[3], Move::arc(true, 30_000, -15_000, 30_000, -10_000, 3_000, Rule::ArcR));
    // G70: from X50 Z5, translated by U0.4 W0.1; the ns block's F0.1 applies from it on, the
    // next block's F0.2, the F0.3 of a block without motion to the arc; the G00 stays a rapid.
    let g = Rule::G70Path;
    assert_eq!(
        m[6..12],
        [
            Move::feed(20_400, 100, 1_000, g),
            Move::feed(20_400, -9_900, 2_000, g),
            Move::arc(true, 30_400, -14_900, 30_400, -9_900, 3_000, g),
            Move::rapid(50_400, -14_900, g),
            Move::rapid(50_000, 5_000, Rule::G70Return),
            // After G70: G00 is still the mode? No: the mode before G70 was G00 (the block before
            // it); `G1 Z6` feeds at G70's F0.05, the modal feed now.
            Move::feed(50_000, 6_000, 500, Rule::PrjModal),
        ]
    );
    let p = passes(&t);
    assert_eq!(p, [Pass { index: 1, kind: PassKind::Finish, diameter_depth: 29_600, rule: Rule::G70Path }]);
    // Without F in the G70 block the modal feed is the first feed (the contour's F is used
    // from its block on, not before).
    let t = expand("G0 X50 Z5\nN50 G1 X20 Z0 F0.1\nN60 G1 Z-10\nG0 X50 Z5\nG1 F0.07\nG70 P50 Q60\n", Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[m.len() - 3..], [Move::feed(20_000, 0, 1_000, g), Move::feed(20_000, -10_000, 1_000, g), Move::rapid(50_000, 5_000, Rule::G70Return)]);
    let t = expand("G0 X50 Z5\nG1 F0.05\nN50 G1 X20 Z0\nN60 G1 Z-10 F0.1\nG0 X50 Z5\nG1 F0.07\nG70 P50 Q60\n", Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[m.len() - 3..m.len() - 1], [Move::feed(20_000, 0, 700, g), Move::feed(20_000, -10_000, 1_000, g)]);
}

/// CNT.FIND for G70 and its alarms: none or two N(ns) before the G70 block, N(nf) missing or
/// after it, a contour over 1 000 blocks; the contour's checks; CNT.FIRST; the G70 block's line.
#[test]
fn g70_alarms() {
    let head = "G0 X50 Z5\n";
    let a = |body: &str, g70: &str| alarm_of(&format!("{head}{body}{g70}\n"));
    let np = |line| al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, line);
    let nq = |line| al(AlarmCode::BlockNotFound, b'Q', Rule::CntFind, line);
    assert_eq!(a("N50 G1 X20 F1\nN60 Z-10\n", "G70 P50 Q60"), None);
    assert_eq!(a("N50 G1 X20 F1\nN60 Z-10\n", "G70 P51 Q60"), np(4));
    assert_eq!(a("N50 G1 X20 F1\nN50 Z-5\nN60 Z-10\n", "G70 P50 Q60"), np(5));
    // A second N(ns) after N(nf) still makes N(ns) ambiguous.
    assert_eq!(a("N50 G1 X20 F1\nN60 Z-10\nN50 X30\n", "G70 P50 Q60"), np(5));
    // N(ns) after the G70 block does not count; nor does N(nf).
    assert_eq!(a("", "G70 P50 Q60 F1\nN50 G1 X20 F1\nN60 Z-10"), np(2));
    assert_eq!(a("N50 G1 X20 F1\n", "G70 P50 Q60\nN60 Z-10"), nq(3));
    // N(nf) before N(ns) is not "at or after" it.
    assert_eq!(a("N60 G1 X30 F1\nN50 G1 X20\n", "G70 P50 Q60"), nq(4));
    // The G70 block's own N is not "before" it.
    assert_eq!(a("N50 G1 X20 F1\n", "N60 G70 P50 Q60"), nq(3));
    // N(nf) = N(ns): a one-block contour.
    assert_eq!(a("N50 G1 X20 F1\n", "G70 P50 Q50"), None);
    // 1 000 blocks, 1 001.
    let body = |blocks: usize| {
        let mut s = String::from("N50 G1 X20 F1\n");
        for _ in 1..blocks - 1 {
            s += "W-0.01\n";
        }
        s + "N60 X50\n"
    };
    assert_eq!(a(&body(1_000), "G70 P50 Q60"), None);
    assert_eq!(a(&body(1_001), "G70 P50 Q60"), al(AlarmCode::ContourTooLong, b'Q', Rule::CntMax, 1_003));
    // Too long before not found: N(nf) missing after more than 1 000 blocks.
    let mut long = String::from("N50 G1 X20 F1\n");
    for _ in 0..1_000 {
        long += "W-0.01\n";
    }
    assert_eq!(a(&long, "G70 P50 Q60"), al(AlarmCode::ContourTooLong, b'Q', Rule::CntMax, 1_003));
    // The contour's checks (on its lines) and CNT.FIRST (on the ns block's line). A contour
    // met in program order runs as ordinary blocks first, so only what is legal there and
    // refused in a contour reaches the G70: an M code, an O word, a G04…
    assert_eq!(a("N50 G1 X20 F1\nZ-5 M8\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'M', Rule::CntWords, 3));
    assert_eq!(a("N50 G1 X20 F1\nO5\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'O', Rule::CntWords, 3));
    assert_eq!(a("N50 G1 X20 F1\nG97 S100\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntWords, 3));
    assert_eq!(a("N50 X20 F1\nN60 Z-10\n", "G70 P50 Q60"), al(AlarmCode::MissingWord, b'G', Rule::CntFirst, 2));
    assert_eq!(a("N50 G3 X60 Z0 R5 F1\nN60 G1 Z-10\n", "G70 P50 Q60"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntFirst, 2));
    // No monotonicity for G70.
    assert_eq!(a("N50 G1 X20 F1\nZ-10\nX10\nZ0\nN60 X50\n", "G70 P50 Q60"), None);
    // Missing feed, P, Q as for G71.
    assert_eq!(alarm_of("N50 G0 X20\nN60 Z-10\nG70 P50 Q60"), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 3));
}

/// CNT.FLOW, CYC.ONESHOT, CNT.MODAL: after G71/G72 the program resumes after N(nf); the motion
/// mode is what it was before (a G90 run goes on); the modal feed is the cycle block's F; the
/// machine ends at A. The contour blocks' F, S, T do not change the machine's state.
#[test]
fn flow_and_modal_state() {
    // G01 before; after the cycle `Z-1` is a G01 move at the G71's F0.3 (not the contour's F9).
    let src = "G1 X41 Z0 F0.1\nG71 U2 R1\nG71 P50 Q60 F0.3\nN50 G1 X20 F9\nN60 Z-10 F8\nZ-1\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(*m.last().unwrap(), Move::feed(41_000, -1_000, 3_000, Rule::PrjModal));
    assert_eq!(m[m.len() - 2], Move::rapid(41_000, 0, Rule::G71Return));
    // The roughing feed is the cycle's, never the contour's.
    assert!(m.iter().filter(|m| m.kind == MoveKind::Feed && m.rule != Rule::PrjModal).all(|m| m.feed == 3_000));
    // The contour is not run again after G71: nothing between the return and `Z-1`.
    assert_eq!(m.iter().filter(|m| m.rule == Rule::PrjModal).count(), 2);
    // A G90 run goes on after G71: `X35` after the contour is another G90 cycle.
    let src = "G0 X50 Z2\nG90 X40 Z-10 F0.2\nG71 P50 Q60 F0.3\nN50 G1 X30\nN60 Z-10\nX35\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(p.last().unwrap(), &Pass { index: 2, kind: PassKind::Rough, diameter_depth: 15_000, rule: Rule::G90Path });
    // G71 uses the parameters when no first block was given (5132 = 1 mm, 5133 = 0.5 mm) and
    // keeps a first block's values apart from G72's.
    let t = expand("G0 X41 Z0\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", Config::default());
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1 .0).collect::<Vec<_>>(), [39_000, 37_000]);
    let t = expand("G0 X41 Z0\nG72 W3\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", Config::default());
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1 .0).collect::<Vec<_>>(), [39_000, 37_000]);
    let cfg = Config { params: Params { p5132_rough_depth: Some(1_500), p5133_rough_retract: Some(0), ..Params::default() }, ..Config::default() };
    let t = expand("G0 X41 Z0\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", cfg);
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1 .0).collect::<Vec<_>>(), [38_000]);
    // e = 0: no retract move; the rapid back follows the cut.
    let m = moves(&t);
    assert_eq!(m[2..4], [Move::feed(38_000, -10_000, 3_000, Rule::G71Layer), Move::rapid(38_000, 0, Rule::G71Retract)]);
    // A first block's omitted word falls back to its parameter.
    let t = expand("G0 X41 Z0\nG71 U1.5 R2\nG71 R0.25\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", Config::default());
    let m = moves(&t);
    assert_eq!(m[3], Move::feed(39_500, -9_750, 3_000, Rule::G71Retract));
    // Inside (s = +1): from X10 outward to X30, cutting toward −Z.
    let t = expand("G0 X10 Z2\nG71 U1 R0.5\nG71 P50 Q60 U-0.2 F0.3\nN50 G0 X30 Z2\nN60 G1 Z-20\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1).collect::<Vec<_>>(), [(12_000, -20_000), (14_000, -20_000), (16_000, -20_000), (18_000, -20_000), (20_000, -20_000), (22_000, -20_000), (24_000, -20_000), (26_000, -20_000), (28_000, -20_000)]);
    let m = moves(&t);
    // Rapid infeeds (ns G00), retract inward (−X) at 45°.
    assert_eq!(m[0..4], [Move::rapid(10_000, 2_000, Rule::PrjModal), Move::rapid(12_000, 2_000, Rule::G71Layer), Move::feed(12_000, -20_000, 3_000, Rule::G71Layer), Move::feed(11_000, -19_500, 3_000, Rule::G71Retract)]);
}

/// Both ways of taking the stream: `fill` equals the iterator for every buffer size, on the
/// seed's examples, the bound cases and alarms inside contours.
pub(crate) fn assert_fill_agrees(program: &str, config: Config, sizes: &[usize]) {
    let mut want = Vec::new();
    let mut want_alarm = None;
    for item in Expander::new(program.as_bytes(), config) {
        match item {
            Ok(e) => want.push(e),
            Err(a) => want_alarm = Some(a),
        }
    }
    for &size in sizes {
        let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
        let mut buffer = std::vec![filler; size];
        let mut expander = Expander::new(program.as_bytes(), config);
        let mut got = Vec::new();
        let alarm = loop {
            match expander.fill(&mut buffer) {
                Err(a) => break Some(a),
                Ok(0) => break None,
                Ok(n) => got.extend_from_slice(&buffer[..n]),
            }
        };
        assert_eq!(got, want, "buffer of {size}\n{program}");
        assert_eq!(alarm, want_alarm, "buffer of {size}\n{program}");
    }
}

#[test]
fn fill_equals_the_iterator() {
    // Every buffer size from 1 to one more than the whole stream.
    for program in [EXAMPLE_1, EXAMPLE_2] {
        let events = Expander::new(program.as_bytes(), Config::default()).count();
        let sizes: Vec<usize> = (1..=events + 1).collect();
        assert_fill_agrees(program, Config::default(), &sizes);
    }
    let sizes: Vec<usize> = (1..=40).chain([64, 100, 1_000, 4_096]).collect();
    for program in [
        EXAMPLE_1,
        EXAMPLE_2,
        "G0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\nN55 Z-5 M8\nN60 X50\n",
        "G0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\nZ-10\nX18\nN60 Z-20\n",
        "G0 X10 Z2\nG71 U1 R0.5\nG71 P50 Q60 U-0.2 F0.3\nN50 G0 X30 Z2\nN60 G1 Z-20\nG1 X5\n",
        "G0 X50 Z5\nN50 G1 X20 Z0 F0.1\nN60 Z-10 F0.2\nN70 G2 X30 Z-15 R5\nN80 G0 X50\nG0 X50 Z5\nG70 P50 Q80 U0.4 W0.1\nG1 Z6\n",
        "G0 X41 Z0\nG71 U1 R0\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\nG70 P50 Q60\nG0 X#",
    ] {
        assert_fill_agrees(program, Config::default(), &sizes);
    }
    let src = "G0 X41 Z0\nG71 U0.001 R0.001\nG71 P50 Q60 F0.2\nN50 G1 X20.998\nN60 Z-10\n";
    assert_fill_agrees(src, with_max_passes(10_001), &[1, 5, 7, 64, 4_096]);
}
