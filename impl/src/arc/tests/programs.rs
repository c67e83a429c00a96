//! Arcs G02/G03 (ARC.*; docs/INTERPRETATION.md, "Arcs (G02, G03)") on the whole expander and
//! on the geometry functions: the seed's two arcs, quarter and half circles in all four
//! quadrants in both directions by R and by I/K, ties of the rounded R-centre, random R-centres
//! against a float reference away from rounding boundaries, the tolerance at its boundary, the
//! sweep tests, and every alarm with its word, rule and line.
extern crate std;

use crate::arc::{centre_r, turns, within_tolerance};
use crate::tests::{expand, moves, xorshift};
use cycle_vocab::{Alarm, AlarmCode, Config, Move, MoveKind, Params, Rule};
use std::format;

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

/// The one arc move of `G0 X<sx> Z<sz>` then `block` (values in mm).
fn arc_of(start: &str, block: &str) -> Move {
    let t = expand(&format!("G0 {start}\n{block}\n"), Config::default());
    assert_eq!(t.alarm, None, "{start} {block}");
    *moves(&t).last().unwrap()
}

/// ARC.DIR, ARC.R: the seed's N060 (a ball end centred on the axis) and N100 (a fillet
/// tangent to the Ø17 cylinder: the exact centre X31.99999997 Z−40.49953077 rounds to X32 Z−40.5);
/// the N100 end lies 0.46 µm off the circle, legal at the default tolerance.
#[test]
fn seed_arcs() {
    assert_eq!(arc_of("X0 Z0", "G03 X11 W-5.5 R5.5 F0.1"), Move::arc(false, 11_000, -5_500, 0, -5_500, 1_000, Rule::ArcR));
    assert_eq!(
        arc_of("X17 Z-40.5", "G02 X29 W-7.348 R7.5 F0.1"),
        Move::arc(true, 29_000, -47_848, 32_000, -40_500, 1_000, Rule::ArcR)
    );
    // With a tolerance of 0 the N100 end is off its circle.
    let strict = Config { params: Params { arc_tolerance: Some(0), ..Params::default() }, ..Config::default() };
    assert_eq!(
        expand("G0 X17 Z-40.5\nG02 X29 W-7.348 R7.5 F0.1", strict).alarm,
        al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2)
    );
    assert_eq!(expand("G0 X0 Z0\nG03 X11 W-5.5 R5.5 F0.1", strict).alarm, None);
}

/// Quarter and half circles in all four quadrants, both directions, by R and by I/K: the same
/// centre and the same move. Centre (cx, cz) = (40, -20) mm, radius 5 mm; the point at angle θ
/// (from +Z toward +X) is (cx + 2·5·sin θ, cz + 5·cos θ).
#[test]
fn quadrants_and_directions() {
    let (cx, cz, r) = (40_000i64, -20_000i64, 5_000i64);
    let at = |q: i64| -> (i64, i64) {
        match q.rem_euclid(4) {
            0 => (cx, cz + r),
            1 => (cx + 2 * r, cz),
            2 => (cx, cz - r),
            _ => (cx - 2 * r, cz),
        }
    };
    let mm = |v: i64| format!("{}{}.{:03}", if v < 0 { "-" } else { "" }, v.abs() / 1000, v.abs() % 1000);
    for q in 0..4 {
        for (cw, span) in [(false, 1), (true, 1), (false, 2), (true, 2)] {
            // G03 runs counter-clockwise: from angle q to q + span; G02 from q + span back to q.
            let (s, e) = if cw { (at(q + span), at(q)) } else { (at(q), at(q + span)) };
            let g = if cw { "G02" } else { "G03" };
            let start = format!("X{} Z{}", mm(s.0), mm(s.1));
            let end = format!("X{} Z{}", mm(e.0), mm(e.1));
            let by_r = arc_of(&start, &format!("{g} {end} R5 F0.2"));
            assert_eq!((by_r.x, by_r.z, by_r.cx, by_r.cz), (e.0, e.1, cx, cz), "{g} q{q} span {span} by R");
            assert_eq!(by_r.kind, if cw { MoveKind::ArcCw } else { MoveKind::ArcCcw });
            assert_eq!(by_r.rule, Rule::ArcR);
            let (i, k) = ((cx - s.0) / 2, cz - s.1);
            let by_ik = arc_of(&start, &format!("{g} {end} I{} K{} F0.2", mm(i), mm(k)));
            assert_eq!((by_ik.x, by_ik.z, by_ik.cx, by_ik.cz, by_ik.rule), (e.0, e.1, cx, cz, Rule::ArcIk), "{g} q{q} by IK");
            // The other direction with R puts the centre on the other side of the chord (a
            // quarter) or, for a half circle, at the same midpoint.
            let other = if cw { "G03" } else { "G02" };
            let mirrored = arc_of(&start, &format!("{other} {end} R5 F0.2"));
            if span == 2 {
                assert_eq!((mirrored.cx, mirrored.cz), (cx, cz));
            } else {
                assert_eq!((mirrored.cx, mirrored.cz), (s.0 + e.0 - cx, s.1 + e.1 - cz), "{other} q{q}");
            }
        }
    }
}

/// The exact centre as a float, for the cross-check away from rounding boundaries.
fn centre_float(s: (i64, i64), e: (i64, i64), r: i64, cw: bool) -> Option<(f64, f64)> {
    let (su, sv, eu, ev) = (s.0 as f64, 2.0 * s.1 as f64, e.0 as f64, 2.0 * e.1 as f64);
    let (du, dv) = (eu - su, ev - sv);
    let c2 = du * du + dv * dv;
    let rh = 2.0 * r as f64;
    if c2 > 4.0 * rh * rh {
        return None;
    }
    let t = ((4.0 * rh * rh - c2) / (4.0 * c2)).sqrt();
    let (av, au) = if cw { (du, -dv) } else { (-du, dv) };
    Some(((su + eu) / 2.0 + t * au, ((sv + ev) / 2.0 + t * av) / 2.0))
}

/// ARC.R: random chords and radii (small and up to nine digits) against the float centre
/// wherever the float is far from a rounding boundary; the chord bound exactly at c = 2R.
#[test]
fn r_centres_match_the_exact_value() {
    let mut state = 0x0000_acce_17e5_u64;
    let mut checked = 0;
    for round in 0..200_000u32 {
        let scale: i64 = if round % 2 == 0 { 100 } else { 1_000_000 };
        let mut n = || (xorshift(&mut state) % (2 * scale as u64 + 1)) as i64 - scale;
        let s = (n(), n());
        let e = (n(), n());
        if s == e {
            continue;
        }
        let r = (xorshift(&mut state) % (scale as u64 * 2)) as i64 + 1;
        let cw = round % 3 == 0;
        let got = centre_r(s, e, r, cw);
        let want = centre_float(s, e, r, cw);
        match (got, want) {
            (None, None) => {}
            (Some(c), Some((x, z))) => {
                let near = |v: f64| (v.abs().fract() - 0.5).abs() < 1e-6 * (1.0 + v.abs());
                if !near(x) && !near(z) {
                    let rd = |v: f64| v.abs().round() as i64 * if v < 0.0 { -1 } else { 1 };
                    assert_eq!(c, (rd(x), rd(z)), "s {s:?} e {e:?} r {r} cw {cw}");
                    checked += 1;
                }
            }
            (g, w) => {
                // Only at the chord bound itself may the float disagree.
                let c2 = ((e.0 - s.0) as i128).pow(2) + (2 * (e.1 - s.1) as i128).pow(2);
                assert_eq!(c2, 16 * (r as i128).pow(2), "s {s:?} e {e:?} r {r}: {g:?} vs {w:?}");
            }
        }
    }
    assert!(checked > 50_000, "{checked}");
    // Nine-digit words: the largest radius and a chord just within 2R.
    let n = 999_999_999i64;
    assert_eq!(centre_r((0, 0), (0, -2 * n), n, true), Some((0, -n)));
    assert_eq!(centre_r((0, 0), (0, -2 * n), n - 1, true), None);
    assert_eq!(centre_r((-n, n), (n, -n), n, false), None);
}

/// ARC.R: every small case whose exact centre is rational, against the rational centre
/// rounded by hand — and none of them is a tie. *The R-centre never ties:* with C the exact
/// centre in half units, |C − S|² = |C − E|² = (2r)². A Z tie needs cv odd (C.z a half count):
/// then cv − sv is odd and (cu − su)² = 4r² − odd² ≡ 3 (mod 4), an integer that is no square of
/// a rational. An X tie needs cu = m + ½: then (2(cv − sv))² = 16r² − (2m + 1)² ≡ 7 (mod 8),
/// again no square. So the rounding of the R-centre never meets an exact half.
#[test]
fn r_centres_rational_and_never_tied() {
    let (mut rational, mut ties) = (0, 0);
    for r in 1i64..=12 {
        for du in -24i64..=24 {
            for dz in -12i64..=12 {
                for (sx, sz) in [(0i64, 0i64), (-7, 3), (5, -9)] {
                    let (s, e) = ((sx, sz), (sx + du, sz + dz));
                    let dv = 2 * dz;
                    let c2 = (du * du + dv * dv) as i128;
                    let rh = 2 * r as i128;
                    if c2 == 0 || c2 > 4 * rh * rh {
                        continue;
                    }
                    // t² = (4R_h² − c²) / (4c²) rational square: t = p / q.
                    let Some((p, q)) = rational_sqrt(4 * rh * rh - c2, 4 * c2) else { continue };
                    for cw in [true, false] {
                        let (av, au) = if cw { (du as i128, -dv as i128) } else { (-du as i128, dv as i128) };
                        // x = (su + eu)/2 + (p/q)·au ; z = ((sv + ev)/2 + (p/q)·av) / 2
                        let (su, sv, eu, ev) = (sx as i128, 2 * sz as i128, (sx + du) as i128, 2 * (sz + dz) as i128);
                        let (xn, xd) = ((su + eu) * q + 2 * p * au, 2 * q);
                        let (zn, zd) = ((sv + ev) * q + 2 * p * av, 4 * q);
                        let got = centre_r(s, e, r, cw).unwrap();
                        assert_eq!(got, (round_rational(xn, xd) as i64, round_rational(zn, zd) as i64), "s {s:?} e {e:?} r {r} cw {cw}");
                        rational += 1;
                        let is_tie = |n: i128, d: i128| (2 * n).rem_euclid(2 * d) == d;
                        ties += usize::from(is_tie(xn, xd) || is_tie(zn, zd));
                    }
                }
            }
        }
    }
    assert!(rational > 500, "{rational}");
    assert_eq!(ties, 0);
}

/// √(n/d) as a reduced fraction when it is rational.
fn rational_sqrt(n: i128, d: i128) -> Option<(i128, i128)> {
    let g = gcd(n, d);
    let (n, d) = (n / g, d / g);
    let (rn, rd) = (isqrt_i(n), isqrt_i(d));
    (rn * rn == n && rd * rd == d).then_some((rn, rd))
}

fn isqrt_i(n: i128) -> i128 {
    crate::fixed::isqrt(n as u128) as i128
}

fn gcd(a: i128, b: i128) -> i128 {
    if b == 0 {
        a.abs()
    } else {
        gcd(b, a % b)
    }
}

/// n / d (d > 0) rounded half away from zero.
fn round_rational(n: i128, d: i128) -> i128 {
    let r = (2 * n.abs() + d) / (2 * d);
    if n < 0 {
        -r
    } else {
        r
    }
}

/// ARC.TOL: | |E − C| − |S − C| | ≤ tolerance, exactly at the boundary and one past it, on
/// both sides of the circle; the default 10 µm and 0.
#[test]
fn tolerance_boundary() {
    // S = X0 Z0, centre X0 Z-0.01 (K-0.01): radius 10 µm. E on the X axis of the centre.
    let c = (0, -10);
    assert!(within_tolerance((0, 0), (40, -10), c, 10)); // |E−C| = 20 µm: 10 off
    assert!(!within_tolerance((0, 0), (42, -10), c, 10)); // 11 off
    assert!(within_tolerance((0, 0), (20, -10), c, 0)); // on the circle
    assert!(!within_tolerance((0, 0), (22, -10), c, 0));
    assert!(!within_tolerance((0, 0), (18, -10), c, 0));
    // Inside the circle: |E − C| = 0 is 10 off.
    assert!(within_tolerance((0, 0), (0, -10), c, 10));
    assert!(!within_tolerance((0, 0), (0, -10), c, 9));
    // Far points are screened before any square is formed.
    assert!(!within_tolerance((0, 0), (i64::MAX, i64::MIN), c, 999_999_999));
    // On the whole expander: the rule, word and line; the default tolerance.
    assert_eq!(alarm_of("G0 X0 Z0\nG02 X0.04 Z-0.01 K-0.01 F1"), None);
    assert_eq!(alarm_of("G0 X0 Z0\nG02 X0.042 Z-0.01 K-0.01 F1"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2));
}

/// G71.MONOTONE's sweep test: which quadrant points lie strictly inside an arc's sweep.
#[test]
fn sweeps() {
    // Centre X0 Z0, radius 10 mm (u, v: 20 000 half units): points by angle from +Z.
    let c = (0, 0);
    let p = |deg: i64| -> (i64, i64) {
        let (s, co): (i64, i64) = match deg.rem_euclid(360) {
            0 => (0, 1),
            90 => (1, 0),
            180 => (0, -1),
            270 => (-1, 0),
            45 => (7_071, 7_071),
            135 => (7_071, -7_071),
            225 => (-7_071, -7_071),
            _ => (-7_071, 7_071),
        };
        if s.abs() == 1 || co.abs() == 1 {
            (2 * 10_000 * s, 10_000 * co)
        } else {
            (2 * s, co)
        }
    };
    // G03 (counter-clockwise) 0° → 90°: a quarter, nothing strictly inside.
    assert_eq!(turns(p(0), p(90), c, false), (false, false));
    // G03 0° → 135° passes 90° (extreme X).
    assert_eq!(turns(p(0), p(135), c, false), (true, false));
    // G03 45° → 225° passes 90° and 180° (extreme Z at 180°).
    assert_eq!(turns(p(45), p(225), c, false), (true, true));
    // G02 (clockwise) 90° → 0°: a quarter; 90° → 315° passes 0° (extreme Z).
    assert_eq!(turns(p(90), p(0), c, true), (false, false));
    assert_eq!(turns(p(90), p(315), c, true), (false, true));
    // The long way round: G02 from 0° to 90° is 270°, through 270° and 180°.
    assert_eq!(turns(p(0), p(90), c, true), (true, true));
    // A half turn from 0° to 180°: G03 passes 90° (X), G02 passes 270° (X).
    assert_eq!(turns(p(0), p(180), c, false), (true, false));
    assert_eq!(turns(p(0), p(180), c, true), (true, false));
    // E on the start's ray (a full circle) turns both ways.
    assert_eq!(turns(p(45), (p(45).0 * 2, p(45).1 * 2), c, false), (true, true));
}

/// Every arc alarm with its code, word, rule and line, in the check order.
#[test]
fn arc_alarms() {
    let a = |src: &str| alarm_of(&format!("G0 X10 Z0\n{src}"));
    // (2) conflicts: R with I or K (after X/U and Z/W); F with I is none.
    assert_eq!(a("G02 X20 Z-5 R5 I1 F1"), al(AlarmCode::Conflict, b'R', Rule::ArcFormat, 2));
    assert_eq!(a("G03 X20 Z-5 K1 R5 F1"), al(AlarmCode::Conflict, b'R', Rule::ArcFormat, 2));
    assert_eq!(a("G02 X20 U1 R5 I1 F1"), al(AlarmCode::Conflict, b'U', Rule::ComAbsInc, 2));
    assert_eq!(a("G02 X20 Z-5 I5 F1"), None);
    // TNRC.NOARC before the pair conflicts; the two-motion-codes conflict before it.
    assert_eq!(a("G41 G02 X20 Z-5 R5 F1"), al(AlarmCode::Conflict, b'G', Rule::TnrcNoarc, 2));
    assert_eq!(a("G3 G40 X20 Z-5 R5 I1 F1"), al(AlarmCode::Conflict, b'G', Rule::TnrcNoarc, 2));
    assert_eq!(a("G41 G02 G01 X1"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 2));
    // Words allowed: X U Z W R I K F; P is not.
    assert_eq!(a("G02 X20 Z-5 R5 F1 P1"), al(AlarmCode::WordNotAllowed, b'P', Rule::PrjWord, 2));
    // (3) values, alphabetically: R ≤ 0 names ARC.R; I, K COM.RANGES.
    assert_eq!(a("G02 X20 Z-5 R0 F1"), al(AlarmCode::OutOfRange, b'R', Rule::ArcR, 2));
    assert_eq!(a("G02 X20 Z-5 R-5 F1"), al(AlarmCode::OutOfRange, b'R', Rule::ArcR, 2));
    // ARC.R owns R ≤ 0 only; R > N is out of the generic length range (COM.RANGES), however
    // large (docs/INTERPRETATION.md, "Arcs": "R ≤ 0 is `OUT OF RANGE` on R, rule ARC.R, R > N
    // rule COM.RANGES").
    assert_eq!(a("G02 X20 Z-5 R1000000 F1"), al(AlarmCode::OutOfRange, b'R', Rule::ComRanges, 2));
    assert_eq!(a("G02 X20 Z-5 R999999999999999999 F1"), al(AlarmCode::OutOfRange, b'R', Rule::ComRanges, 2));
    assert_eq!(a("G02 X20 Z-5 R-999999999999999999 F1"), al(AlarmCode::OutOfRange, b'R', Rule::ArcR, 2));
    assert_eq!(a("G02 X20 Z-5 R-0 F1"), al(AlarmCode::OutOfRange, b'R', Rule::ArcR, 2));
    assert_eq!(a("G02 X20 Z-5 R5.0001 F1"), al(AlarmCode::Precision, b'R', Rule::ComUnits, 2));
    assert_eq!(a("G02 X20 Z-5 I1000000 F1"), al(AlarmCode::OutOfRange, b'I', Rule::ComRanges, 2));
    assert_eq!(a("G02 X20 Z-5 K-1000000 F1"), al(AlarmCode::OutOfRange, b'K', Rule::ComRanges, 2));
    assert_eq!(a("G02 X20 Z-5 F0 R0"), al(AlarmCode::OutOfRange, b'F', Rule::ComRanges, 2));
    // (4) missing: the feed, then R.
    assert_eq!(a("G02 X20 Z-5 R5"), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2));
    assert_eq!(a("G02 X20 Z-5"), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2));
    assert_eq!(a("G02 X20 Z-5 F1"), al(AlarmCode::MissingWord, b'R', Rule::ArcFormat, 2));
    // I alone or K alone is legal.
    assert_eq!(a("G02 X10 Z-10 K-5 F1"), None);
    assert_eq!(a("G03 X30 Z0 I5 F1"), None);
    // (5) E = S first, then the centre, then the tolerance.
    assert_eq!(a("G02 X10 Z0 I0 K0 F1"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2));
    assert_eq!(a("G02 U0 W0 R5 F1"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2));
    assert_eq!(a("G02 X20 Z-5 I0 K0 F1"), al(AlarmCode::Geometry, b'I', Rule::ArcIk, 2));
    assert_eq!(a("G02 X20 Z-5 I0 F1"), al(AlarmCode::Geometry, b'I', Rule::ArcIk, 2));
    assert_eq!(a("G02 X10 Z-10.002 R5 F1"), al(AlarmCode::Geometry, b'R', Rule::ArcR, 2));
    assert_eq!(a("G02 X10 Z-10 R5 F1"), None); // c = 2R: the half circle
    assert_eq!(a("G02 X30 Z-5 K-5 F1"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2));
    // ARC.TOL: an end on the ray from the centre through S, within the tolerance, would close
    // the full circle (docs/INTERPRETATION.md, "Arcs": "even within the tolerance") — beyond S
    // or short of it, both ways round; just off the ray it is an arc of almost 360°.
    assert_eq!(a("G02 X9.998 Z0 I5 F1"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2));
    assert_eq!(a("G03 X10.002 Z0 I5 F1"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2));
    assert_eq!(a("G03 X10.002 Z0.001 I5 F1"), None);
    assert_eq!(a("G02 X9.996 Z0.001 I5 K-2.5 F1"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 2));
    // Without axis words an arc block only sets the feed; the mode is modal.
    let t = expand("G0 X10 Z0\nG02 F2\nX10 Z-10 R5\nG03 W-10 R5\n", Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(m[1], Move::arc(true, 10_000, -10_000, 10_000, -5_000, 20_000, Rule::ArcR));
    assert_eq!(m[2], Move::arc(false, 10_000, -20_000, 10_000, -15_000, 20_000, Rule::ArcR));
    // An arc ends a G92 run like any motion code: `X39` is then an arc block (without R).
    let t = expand("G0 X50 Z5\nG92 X40 Z-20 F2\nG02 X50 Z-5 R5 F1\nX39\n", Config::default());
    assert_eq!(t.alarm, al(AlarmCode::MissingWord, b'R', Rule::ArcFormat, 4));
    assert_eq!(moves(&t).last().map(|m| m.kind), Some(MoveKind::ArcCw));
}
