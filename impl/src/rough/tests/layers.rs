//! G71.LAYER / G72.LAYER on random monotone contours (lines and arcs, G71 and G72, outside and
//! inside, both arc directions) against a search of the whole contour per layer, and the layer
//! ends' roundings (ties).
use super::*;
use crate::tests::xorshift;

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

/// Frame helpers (a the layer axis, b the cut axis), as in `rough::axis`.
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

/// G71.LAYER when layer 1 stands exactly on a point of Q that ends an arc: the cut ends where Q
/// leaves the layer — that point itself, X39 Z−0.001 (Q = the contour shifted by W5), one
/// increment beyond A.z, so the layer exists (c·(z₁ − A.z) > 0). The arc N55 (centre X39 Z0
/// before the shift, radius 5 from its start) ends 0.001 off its circle (within ARC.TOL's 0.010):
/// its circle meets X39 at Z0 after the shift, which is no cut; the layer's cut is the point, not
/// the circle's value there. Layer 2 (X37) meets the arc at Z+0.101, behind A.z: K = 1.
#[test]
fn a_layer_on_an_arcs_end_cuts_to_that_end() {
    let src = "G0 X41 Z0\nG71 U1 R0.5\nG71 P50 Q60 W5 F0.2\nN50 G1 X29\nN55 G2 X39 Z-5.001 I5 K0\nN60 G1 X41 Z-20\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(layer_cuts(&t.events), [(1, (39_000, -1))]);
}
