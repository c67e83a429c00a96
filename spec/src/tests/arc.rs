//! Arcs G02/G03 (M003) against docs/INTERPRETATION.md, "Arcs": the seed's centres worked out by
//! hand, every quadrant by I/K and by R in both directions, ties, the word limits, the checks
//! and their order.

use crate::tests::util::{alarm_with as alarm_of};
use crate::arc::{centre_r, sweep_contains, turns, Point};
use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{AlarmCode, Config, Event, Move, MoveKind, Params, Rule};
use num_bigint::BigInt;
use num_traits::Signed;

fn run(src: &str) -> Trace {
    expand(src.as_bytes(), &Config::default())
}

/// The last move of a program that must run without an alarm.
fn last(src: &str) -> Move {
    let t = run(src);
    assert_eq!(t.alarm, None, "{src}: {}", t.to_gcode());
    *t.moves().last().expect("a move")
}

/// The exact centre of an R arc, scaled by 10^5 (truncated toward zero): the hand check of
/// ARC.R's formula, independent of the rounding.
fn exact_centre_e5(s: Point, e: Point, r: i64, cw: bool) -> (BigInt, BigInt) {
    let scale = BigInt::from(100_000);
    let (du, dv) = (BigInt::from(e.0 - s.0), BigInt::from(2 * (e.1 - s.1)));
    let c2 = &du * &du + &dv * &dv;
    let a = BigInt::from(16) * BigInt::from(r) * BigInt::from(r) - &c2;
    let (nu, nv) = if cw { (-dv, du) } else { (dv, -du) };
    let off = |n: &BigInt| {
        let root = BigInt::from((&a * &c2 * n * n * &scale * &scale).magnitude().sqrt());
        if n.is_negative() {
            -root
        } else {
            root
        }
    };
    let cu = (BigInt::from(s.0 + e.0) * &c2 * &scale + off(&nu)) / (&c2 * BigInt::from(2));
    let cz = (BigInt::from(2 * (s.1 + e.1)) * &c2 * &scale + off(&nv)) / (&c2 * BigInt::from(4));
    (cu, cz)
}

/// ARC.R, ARC.DIR: the seed's N100 `G02 X29 W-7.348 R7.5` from X17 Z−40.5. Chord in half
/// units (u = X, v = 2Z): du = 12 000, dv = −14 696, c² = 359 972 416; A = 16·7 500² − c² =
/// 540 027 584; the normal to the right (G02) is (−dv, du) = (14 696, 12 000), so the centre
/// lies toward +X and +Z. Exact: X31.99999997 Z−40.49953077 (the register's numbers), rounded
/// once: X32.000 Z−40.500. The end is 0.46 µm inside the circle: legal at the default 10.
#[test]
fn seed_n100_centre() {
    let (s, e) = ((17_000, -40_500), (29_000, -47_848));
    assert_eq!(exact_centre_e5(s, e, 7_500, true), (BigInt::from(3_199_999_997i64), BigInt::from(-4_049_953_076i64)));
    assert_eq!(centre_r(s, e, 7_500, true, 1), Ok((32_000, -40_500)));
    let m = last("G0 X17 Z-40.5\nG02 X29 W-7.348 R7.5 F100\n");
    assert_eq!(m, Move::arc(true, 29_000, -47_848, 32_000, -40_500, 1_000_000, Rule::ArcR));
    // Tolerance 0 refuses it: |E − C| = 7.49954 mm against 7.5.
    let strict = Config { params: Params { arc_tolerance: Some(0), ..Params::default() }, ..Config::default() };
    assert_eq!(alarm_of("G0 X17 Z-40.5\nG02 X29 W-7.348 R7.5 F100\n", &strict), (AlarmCode::Geometry, Some('X'), Rule::ArcTol, 2));
}

/// ARC.R, ARC.DIR: N060 `G03 X11 W-5.5 R5.5` from X0 Z0 is a ball end centred on the axis:
/// chord (11 000, −11 000), left normal (dv, −du) = (−11 000, −11 000), offset √A/(2c) = ½ of
/// it: centre X0 Z−5.5 exactly.
#[test]
fn seed_ball_end() {
    assert_eq!(exact_centre_e5((0, 0), (11_000, -5_500), 5_500, false), (BigInt::from(0), BigInt::from(-550_000_000)));
    let m = last("G03 X11 W-5.5 R5.5 F100\n");
    assert_eq!((m.kind, m.cx, m.cz, m.rule), (MoveKind::ArcCcw, 0, -5_500, Rule::ArcR));
}

/// ARC.IK, ARC.R, ARC.DIR in all four quadrants, both directions: the circle of radius 5 about
/// X20 Z−10 (X as a diameter: the points X20 Z−5 (+Z), X30 Z−10 (+X), X20 Z−15 (−Z), X10 Z−10
/// (−X)). G03 runs +Z → +X → −Z → −X (counter-clockwise with +Z right and +X up); G02 the
/// reverse. I is the radius distance to the centre, K the Z distance; R5 gives the same centre.
#[test]
fn four_quadrants_both_directions() {
    let ring = [(20_000i64, -5_000i64, "X20 Z-5"), (30_000, -10_000, "X30 Z-10"), (20_000, -15_000, "X20 Z-15"), (10_000, -10_000, "X10 Z-10")];
    for q in 0..4 {
        for cw in [false, true] {
            let (from, to) = if cw { (ring[(q + 1) % 4], ring[q]) } else { (ring[q], ring[(q + 1) % 4]) };
            let (i, k) = ((20_000 - from.0) as f64 / 2_000.0, (-10_000 - from.1) as f64 / 1_000.0);
            let g = if cw { "G02" } else { "G03" };
            let ik = format!("G0 {}\n{g} {} I{i} K{k} F1\n", from.2, to.2);
            let r = format!("G0 {}\n{g} {} R5 F1\n", from.2, to.2);
            let kind = if cw { MoveKind::ArcCw } else { MoveKind::ArcCcw };
            let by_ik = last(&ik);
            let by_r = last(&r);
            assert_eq!((by_ik.kind, by_ik.x, by_ik.z, by_ik.cx, by_ik.cz, by_ik.rule), (kind, to.0, to.1, 20_000, -10_000, Rule::ArcIk), "{ik}");
            assert_eq!(Move { rule: Rule::ArcIk, ..by_r }, by_ik, "{r}");
            assert_eq!(by_r.rule, Rule::ArcR);
        }
    }
}

/// ARC.R: the other side of the chord with the other direction, the half circle (c = 2R)
/// about the chord's midpoint, and the larger circle on the named side.
#[test]
fn r_sides_and_half_circle() {
    // G02 from X0 Z0 to X0 Z−10 (travel −Z): right of the travel is +X. G03: −X.
    assert_eq!(centre_r((0, 0), (0, -10_000), 5_000, true, 1), Ok((0, -5_000)));
    assert_eq!(centre_r((0, 0), (0, -10_000), 13_000, true, 1), Ok((24_000, -5_000))); // 12 radius → X24
    assert_eq!(centre_r((0, 0), (0, -10_000), 13_000, false, 1), Ok((-24_000, -5_000)));
    // c > 2R: GEOMETRY on R; one increment less than the half circle.
    assert_eq!(centre_r((0, 0), (0, -10_000), 4_999, true, 7), Err(crate::words::alarm(AlarmCode::Geometry, b'R', Rule::ArcR, 7)));
}

/// ARC.R ties: an odd chord parallel to an axis puts the exact centre on half an increment, and
/// it is rounded half away from zero. From X0 to X0.001 (du = 1, dv = 0) with R0.001: centre
/// u = ½ → X1 (increments), v = √15 / 1 … z = √15/4 = 0.968 → Z1. Mirrored below the axis:
/// u = −½ → X−1. Along Z from Z0 to Z−0.001 (dv = −2): z = −½ → Z−1.
#[test]
fn r_centre_ties_half_away_from_zero() {
    assert_eq!(centre_r((0, 0), (1, 0), 1, true, 1), Ok((1, 1)));
    assert_eq!(centre_r((-1, 0), (0, 0), 1, true, 1), Ok((-1, 1)));
    // G02 travelling −Z (dv = −2, c = 2, A = 16·1 − 4 = 12): the right side is +X, u offset
    // √A/(2c)·c = √3 = 1.732 → X2; z = (0 − 1)/2 = −½ → Z−1. G03 from Z1 to Z0: X−2, z = ½ → Z1.
    assert_eq!(centre_r((0, 0), (0, -1), 1, true, 1), Ok((2, -1)));
    assert_eq!(centre_r((0, 1), (0, 0), 1, false, 1), Ok((-2, 1)));
    assert_eq!(last("G0 X-0.001\nG02 X0 R0.001 F1\n").cx, -1);
}

/// ARC.R at the word limits: R = N with a short chord and with a chord of N increments (radius)
/// is decided exactly (products beyond i128) and lands on the named side.
#[test]
fn r_at_the_word_limits() {
    // Chord (10 000, −20 000) half units, G02 normal (20 000, 10 000): exact centre
    // X1 788 859 380.183 Z447 208 595.046 (increments; 50-digit decimals by hand).
    let m = last("G02 X10 Z-10 R999999.999 F1\n");
    assert_eq!((m.cx, m.cz), (1_788_859_380, 447_208_595));
    let m = last("G0 X-999999.999\nG03 X999999.999 R999999.999 F1\n");
    // Chord 2N (half units) along +u, G03: centre to the left of +X travel = −Z. Offset
    // √(R_h² − N²) = N·√3 half units → Z = −N·√3/2 = −866 025 402.918 → −866 025 403.
    assert_eq!((m.cx, m.cz), (0, -866_025_403));
    let c = Config::default();
    assert_eq!(alarm_of("G02 X1 R0 F1", &c), (AlarmCode::OutOfRange, Some('R'), Rule::ArcR, 1));
    assert_eq!(alarm_of("G02 X1 R-5 F1", &c), (AlarmCode::OutOfRange, Some('R'), Rule::ArcR, 1));
    assert_eq!(alarm_of("G02 X1 R1000000 F1", &c), (AlarmCode::OutOfRange, Some('R'), Rule::ComRanges, 1));
    assert_eq!(alarm_of("G02 X1 R0.0005 F1", &c), (AlarmCode::Precision, Some('R'), Rule::ComUnits, 1));
    assert_eq!(alarm_of("G02 X1 I1000000 F1", &c), (AlarmCode::OutOfRange, Some('I'), Rule::ComRanges, 1));
    assert_eq!(alarm_of("G02 X1 R0.001 F1", &c), (AlarmCode::Geometry, Some('R'), Rule::ArcR, 1));
}

/// ARC.FORMAT and the check order: conflicts (R with I or K, after X/U and Z/W), words, values,
/// missing words (F, then R), then step 5 (E = S, the centre, the tolerance).
#[test]
fn arc_alarms_in_order() {
    let c = Config::default();
    assert_eq!(alarm_of("G02 X1 Z1 R1 I1 F1", &c), (AlarmCode::Conflict, Some('R'), Rule::ArcFormat, 1));
    assert_eq!(alarm_of("G03 X1 R1 K1", &c), (AlarmCode::Conflict, Some('R'), Rule::ArcFormat, 1));
    assert_eq!(alarm_of("G02 X1 U1 R1 I1", &c), (AlarmCode::Conflict, Some('U'), Rule::ComAbsInc, 1));
    assert_eq!(alarm_of("G02 X1 P1 R1", &c), (AlarmCode::WordNotAllowed, Some('P'), Rule::PrjWord, 1));
    assert_eq!(alarm_of("G02 X1 R1", &c), (AlarmCode::MissingWord, Some('F'), Rule::ComLead, 1));
    assert_eq!(alarm_of("G02 X1 F1", &c), (AlarmCode::MissingWord, Some('R'), Rule::ArcFormat, 1));
    // R with I in a G01 block is no arc conflict: I is not allowed there (alphabetical first).
    assert_eq!(alarm_of("G01 X1 R1 I1 F1", &c), (AlarmCode::WordNotAllowed, Some('I'), Rule::PrjWord, 1));
    // F with I is legal in an arc (no thread block).
    assert_eq!(run("G02 X5 Z-2.5 I2.5 F0.2").alarm, None);
    // Step 5: E = S before the centre (I0 K0 would also fail), centre, tolerance.
    assert_eq!(alarm_of("G02 X0 Z0 I0 K0 F1", &c), (AlarmCode::Geometry, Some('X'), Rule::ArcTol, 1));
    assert_eq!(alarm_of("G02 X5 I0 K0 F1", &c), (AlarmCode::Geometry, Some('I'), Rule::ArcIk, 1));
    assert_eq!(alarm_of("G02 W-1 I10 F1", &c), (AlarmCode::Geometry, Some('X'), Rule::ArcTol, 1));
    // An end on the ray through the start (here 2 µm beyond it) closes the circle: ARC.TOL.
    assert_eq!(alarm_of("G0 X10\nG03 X10.004 I-5 F1", &c), (AlarmCode::Geometry, Some('X'), Rule::ArcTol, 2));
    // Without axis words an arc block moves nothing and sets the feed; the mode is modal.
    let t = run("G02 F2\nX5 Z-2.5 I2.5\nG0 X0 Z0\nG03 I0 K-1\n");
    assert_eq!(t.alarm, None);
    assert_eq!(t.moves().next().map(|m| (m.kind, m.feed, m.rule)), Some((MoveKind::ArcCw, 20_000, Rule::ArcIk)));
}

/// ARC.TOL: the tolerance, radius increments, decided exactly. Centre X0 Z0 given by I/K from
/// X20 Z0 (radius 10): an end at radius 10.010 passes at the default 10, 10.011 does not, and
/// 9.990 / 9.989 likewise.
#[test]
fn tolerance_exact() {
    let arc = |end: &str| run(&format!("G0 X20\nG03 {end} I-10 F1\n")).alarm.map(|a| (a.code, a.rule));
    assert_eq!(arc("X0 Z10.01"), None);
    assert_eq!(arc("X0 Z10.011"), Some((AlarmCode::Geometry, Rule::ArcTol)));
    assert_eq!(arc("X0 Z9.99"), None);
    assert_eq!(arc("X0 Z9.989"), Some((AlarmCode::Geometry, Rule::ArcTol)));
    // X as a radius: X20.02 (diameter) is 10.010 from the axis.
    assert_eq!(arc("X-20.02 Z0"), None);
    assert_eq!(arc("X-20.022 Z0"), Some((AlarmCode::Geometry, Rule::ArcTol)));
}

/// G71.MONOTONE's sweep test: the quadrant points strictly inside an arc's sweep.
#[test]
fn quadrant_points_inside_the_sweep() {
    let c = (20_000, -10_000);
    let (pz, px, mz, mx) = ((20_000, -5_000), (30_000, -10_000), (20_000, -15_000), (10_000, -10_000));
    // A quarter from +Z to +X (G03) has no quadrant point strictly inside; G02 the other way
    // round (three quarters) has −Z and −X inside.
    assert_eq!(turns(pz, px, c, false), (false, false));
    assert_eq!(turns(pz, px, c, true), (true, true));
    // Half circles: +Z → −Z counter-clockwise passes +X; clockwise −X.
    assert_eq!(turns(pz, mz, c, false), (true, false));
    assert_eq!(turns(pz, mz, c, true), (true, false));
    assert_eq!(turns(px, mx, c, false), (false, true));
    // A small arc around +X crosses the extreme X only.
    assert_eq!(turns((29_000, -11_000), (29_000, -9_000), c, true), (true, false));
    assert_eq!(turns((29_000, -11_000), (29_000, -9_000), c, false), (true, true));
}

/// An arc is one event; the trace prints its centre as I, K.
#[test]
fn arc_event_in_the_trace() {
    let t = run("G0 X17 Z-40.5\nG02 X29 W-7.348 R7.5 F100\n");
    assert!(t.to_gcode().contains("G02 X29.000 Z-47.848 I32.000 K-40.500 F100.0000"), "{}", t.to_gcode());
    assert_eq!(t.events.iter().filter(|e| matches!(e, Event::Move(_))).count(), 2);
}

/// ARC.TOL: only an end on the ray from the centre through S closes the circle; an end on the
/// opposite ray is a half circle, legal within the tolerance. From X10 Z0 about X5 Z0 (I−2.5),
/// the end X0.01 Z0 lies 2.495 from the centre and S 2.5: 0.005 ≤ 0.01. Along Z, from X10 Z0
/// about Z−5 (K−5), the end Z−9.995 lies 4.995 from it and S 5.
#[test]
fn half_circle_to_the_opposite_ray_within_the_tolerance() {
    let m = last("G0 X10 Z0\nG2 X0.01 I-2.5 F0.1\n");
    assert_eq!((m.kind, m.x, m.z, m.cx, m.cz, m.rule), (MoveKind::ArcCw, 10, 0, 5_000, 0, Rule::ArcIk));
    let m = last("G0 X10 Z0\nG3 Z-9.995 K-5 F0.1\n");
    assert_eq!((m.kind, m.x, m.z, m.cx, m.cz, m.rule), (MoveKind::ArcCcw, 10_000, -9_995, 10_000, -5_000, Rule::ArcIk));
}

/// `sweep_contains`, as its doc comment states: a sweep whose end lies on its start's ray is the
/// full circle — every direction but that ray lies strictly inside. No program gets here (ARC.TOL
/// refuses such an arc before its sweep is asked for), so it is checked directly.
#[test]
fn full_circle_sweep_contains_all_but_its_start_ray() {
    let v = |u: i32, w: i32| (BigInt::from(u), BigInt::from(w));
    let (a, b) = (v(1, 0), v(2, 0));
    for cw in [false, true] {
        for q in [v(0, 1), v(-1, 0), v(0, -1), v(1, 1)] {
            assert!(sweep_contains(&a, &b, cw, &q), "{q:?} cw {cw}");
        }
        assert!(!sweep_contains(&a, &b, cw, &v(3, 0)));
    }
}

/// `sweep_contains` past half a turn: counter-clockwise from a = (9 000, −2 000) to b = (9 000,
/// 2 000) (half units, u up, v right) leaves out only the closed remainder from b back to a, which
/// holds +u. (Through `turns`, its one caller, a sweep this long always has one of each pair of
/// opposite directions inside, so the pairs alone cannot show which ones.)
#[test]
fn long_sweep_leaves_out_only_its_remainder() {
    let v = |u: i32, w: i32| (BigInt::from(u), BigInt::from(w));
    let (a, b) = (v(9_000, -2_000), v(9_000, 2_000));
    for q in [v(0, 1), v(0, -1), v(-1, 0)] {
        assert!(sweep_contains(&a, &b, false, &q), "{q:?}");
        assert!(!sweep_contains(&a, &b, true, &q), "{q:?} clockwise");
    }
    assert!(!sweep_contains(&a, &b, false, &v(1, 0)));
    assert!(sweep_contains(&a, &b, true, &v(1, 0)));
    // The ends' own rays are never strictly inside.
    assert!(!sweep_contains(&a, &b, false, &a) && !sweep_contains(&a, &b, false, &b));
}
