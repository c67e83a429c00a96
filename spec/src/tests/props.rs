//! Properties of G71 + G70 over many generated OD contours (lines and I/K quarter arcs, monotone
//! by construction), each checked exactly against the roughing contour Q: every layer one Δd
//! deeper than the last, cut ends within the one rounding of where Q leaves the layer and no
//! vertex of Q inside a cut, the layers monotone and complete, the SEMI pass the translated
//! contour, G70 the contour, the cycle ending at its start, the count within `max_passes`.

use crate::expand;
use cycle_vocab::{Config, Event, Move, MoveKind, PassKind};
use num_bigint::BigInt;
use MoveKind::{ArcCcw, ArcCw, Feed, Rapid};

type P = (i64, i64);

/// One generated element of the contour: its end, and for arcs (cw, centre).
#[derive(Clone, Copy, Debug)]
struct El {
    end: P,
    arc: Option<(bool, P)>,
}

struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> i64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % n.max(1)) as i64
    }
}

/// A length in mm with three decimals (ISB metric).
fn mm(v: i64) -> String {
    format!("{}{}.{:03}", if v < 0 { "-" } else { "" }, v.abs() / 1_000, v.abs() % 1_000)
}

fn big(v: i64) -> BigInt {
    BigInt::from(v)
}

/// |z − z*| ≤ ½ exactly, z* where the element from `s` to `e` meets X = `x`; and the sign of
/// c·(z* − az) − ½ (c = −1), to decide whether the cut would be positive after the rounding.
fn crossing_checks(s: P, el: &El, x: i64, z: i64, az: i64) -> (bool, bool) {
    match el.arc {
        None => {
            let (num, den) = (big(s.1) * big(el.end.0 - s.0) + big(x - s.0) * big(el.end.1 - s.1), big(el.end.0 - s.0));
            let sign = if den < big(0) { -1 } else { 1 };
            let near = (big(2) * (big(z) * &den - &num)).magnitude() <= den.magnitude();
            // az − z* > ½ ⇔ 2·sign(den)·(az·den − num) > |den|.
            let ahead = big(2 * sign) * (big(az) * &den - &num) > BigInt::from(den.magnitude().clone());
            (near, ahead)
        }
        Some((cw, c)) => {
            // Generated arcs: G03 above the centre (σ = +1), G02 below (σ = −1).
            let sigma: i64 = if cw { -1 } else { 1 };
            let m = big(s.0 - c.0).pow(2) + big(2 * (s.1 - c.1)).pow(2) - big(x - c.0).pow(2);
            let t = big(sigma * 2 * (z - c.1));
            let (lo, hi) = (&t - 1, &t + 1);
            let near = hi >= big(0) && m <= &hi * &hi && (lo <= big(0) || &lo * &lo <= m);
            // z* < az − ½ ⇔ σ√M < w, w = 2az − 1 − 2cz.
            let w = big(2 * az - 1 - 2 * c.1);
            let ahead = if sigma > 0 { w > big(0) && m < &w * &w } else { w > big(0) || m > &w * &w };
            (near, ahead)
        }
    }
}

#[test]
fn generated_contours() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let (mut layers, mut on_arcs) = (0, 0);
    for case in 0..300 {
        let a: P = (60_000 + rng.below(20_000), 1_000 * rng.below(3));
        let x0 = 1_000 * rng.below(20);
        let (dd, e) = (300 + rng.below(2_700), rng.below(1_000));
        let (du, dw) = (rng.below(1_000) - 200, rng.below(600) - 300);
        let mut src = format!("G00 X{} Z{}\nG71 U{} R{}\n", mm(a.0), mm(a.1), mm(dd), mm(e));
        let n = 2 + rng.below(7) as usize;
        src.push_str(&format!("G71 P1 Q{n} U{} W{} F0.2\nN1 G01 X{}\n", mm(du), mm(dw), mm(x0)));
        let mut els = vec![El { end: (x0, a.1), arc: None }];
        for i in 2..=n {
            let s = els[els.len() - 1].end;
            let kind = rng.below(3);
            let r = 500 + rng.below(5_500);
            let el = match kind {
                0 => El { end: (s.0 + 2 * r, s.1 - r), arc: Some((false, (s.0, s.1 - r))) },
                1 => El { end: (s.0 + 2 * r, s.1 - r), arc: Some((true, (s.0 + 2 * r, s.1))) },
                _ => El { end: (s.0 + rng.below(8_000), s.1 - rng.below(15_000) - if i == n { 1_000 } else { 0 }), arc: None },
            };
            let (u, w) = (el.end.0 - s.0, el.end.1 - s.1);
            src.push_str(&match kind {
                0 => format!("N{i} G03 U{} W{} I0 K{}\n", mm(u), mm(w), mm(-r)),
                1 => format!("N{i} G02 U{} W{} I{} K0\n", mm(u), mm(w), mm(r)),
                _ => format!("N{i} G01 U{} W{}\n", mm(u), mm(w)),
            });
            els.push(el);
        }
        src.push_str(&format!("G70 P1 Q{n}\n"));
        let (k, arcs) = check(case, &src, a, &els, dd, e, (du, dw));
        layers += k;
        on_arcs += arcs;
    }
    // The cases exercise many layers, a good share of them ending on arcs.
    assert!(layers > 3_000 && on_arcs > 500, "{layers} layers, {on_arcs} on arcs");
}

/// The trace split at its pass headers: (header, moves after it); the moves before the first
/// header come with `None`.
fn split(events: &[Event]) -> Vec<(Option<cycle_vocab::Pass>, Vec<Move>)> {
    let mut parts = vec![(None, Vec::new())];
    for ev in events {
        match ev {
            Event::Pass(p) => parts.push((Some(*p), Vec::new())),
            Event::Move(m) => parts.last_mut().expect("a part").1.push(*m),
            Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => {}
        }
    }
    parts
}

/// Checks one program; returns its number of layers and how many of them end on an arc.
fn check(case: usize, src: &str, a: P, els: &[El], dd: i64, e: i64, shift: P) -> (i64, i64) {
    let t = expand(src.as_bytes(), &Config::default());
    assert_eq!(t.alarm, None, "case {case}\n{src}");
    let q: Vec<El> = els.iter().map(|el| El { end: (el.end.0 + shift.0, el.end.1 + shift.1), arc: el.arc.map(|(cw, c)| (cw, (c.0 + shift.0, c.1 + shift.1))) }).collect();
    let parts = split(&t.events);
    let rough: Vec<_> = parts.iter().filter(|p| p.0.is_some_and(|h| h.kind == PassKind::Rough)).collect();
    let layers = rough.len() as i64;
    let (mut last_cut, mut on_arcs) = (i64::MAX, 0);
    for (k, (h, mv)) in rough.iter().enumerate() {
        let k = k as i64 + 1;
        let xk = a.0 - 2 * k * dd;
        assert_eq!((h.map(|h| (h.index, h.diameter_depth))), Some((k as u32, 2 * k * dd)), "case {case}");
        // ① one Δd deeper than the last (from A), ② the cut, ③ the 45° retract, ④ back to A.z.
        assert_eq!((mv[0].kind, mv[0].x, mv[0].z), (Feed, xk, a.1), "case {case} k {k}");
        let zk = mv[1].z;
        assert_eq!((mv[1].kind, mv[1].x), (Feed, xk));
        let back: Vec<_> = mv[2..].iter().map(|m| (m.kind, m.x, m.z)).collect();
        let expect = if e == 0 { vec![(Rapid, xk, a.1)] } else { vec![(Feed, xk + 2 * e, zk + e), (Rapid, xk + 2 * e, a.1)] };
        assert_eq!(back, expect, "case {case} k {k}");
        // Layers monotone: positive cuts, never longer than the one before.
        assert!(a.1 - zk > 0 && a.1 - zk <= last_cut, "case {case} k {k}");
        last_cut = a.1 - zk;
        // Exactly against Q: within the rounding of where Q leaves X_k; no vertex of Q inside.
        let (near, _) = leave(&q, xk, zk, a.1);
        assert!(near, "case {case} k {k}: Z{zk} is not Q's crossing at X{xk}\n{src}");
        assert!(q.iter().all(|v| !(v.end.1 > zk && v.end.1 < a.1) || v.end.0 <= xk), "case {case} k {k}");
        on_arcs += i64::from(q.iter().find(|v| v.end.0 > xk).is_some_and(|v| v.arc.is_some()));
    }
    // Complete: the next layer is not between A and Q₀, or its cut would not be positive.
    let next = a.0 - 2 * (layers + 1) * dd;
    if next > q[0].end.0 {
        let (_, ahead) = leave(&q, next, 0, a.1);
        assert!(!ahead, "case {case}: layer {} missing", layers + 1);
    }
    // SEMI: the translated contour at the roughing feed, then the rapid to A.
    let semi = &parts[rough.len() + 1];
    assert_eq!(semi.0.map(|h| (h.index, h.kind, h.diameter_depth)), Some((layers as u32 + 1, PassKind::Semi, (a.0 - q[0].end.0).abs())));
    assert_eq!(path(&semi.1), expected_path(&q, a), "case {case}");
    // G70: the contour itself, then the rapid back to its start.
    let finish = &parts[rough.len() + 2];
    assert_eq!(finish.0.map(|h| h.kind), Some(PassKind::Finish));
    assert_eq!(path(&finish.1), expected_path(els, a), "case {case}");
    assert!(parts.len() == rough.len() + 3 && (layers + 1) <= 10_000);
    (layers, on_arcs)
}

type Step = (MoveKind, i64, i64, i64, i64);

fn path(m: &[Move]) -> Vec<Step> {
    m.iter().map(|m| (m.kind, m.x, m.z, m.cx, m.cz)).collect()
}

fn expected_path(q: &[El], a: P) -> Vec<Step> {
    let mut v: Vec<Step> = Vec::new();
    let mut at = a;
    for el in q {
        if el.end != at {
            v.push(match el.arc {
                Some((cw, c)) => (if cw { ArcCw } else { ArcCcw }, el.end.0, el.end.1, c.0, c.1),
                None => (Feed, el.end.0, el.end.1, 0, 0),
            });
        }
        at = el.end;
    }
    v.push((Rapid, a.0, a.1, 0, 0));
    v
}

/// Where Q leaves X = `x` (the first element ending beyond it): whether `z` is within ½ of it,
/// and whether its exact value lies more than ½ ahead of `az` (a positive cut after rounding).
fn leave(q: &[El], x: i64, z: i64, az: i64) -> (bool, bool) {
    for i in 1..q.len() {
        if q[i].end.0 > x {
            return crossing_checks(q[i - 1].end, &q[i], x, z, az);
        }
    }
    let last = q[q.len() - 1].end.1;
    (last == z, last < az)
}

/// Robustness: random blocks of the new words, extreme values included, never panic and stop
/// at their first alarm (the spec is fuzzed; this is its cheap local guard).
#[test]
fn random_programs_never_panic() {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let codes = ["G00", "G01", "G02", "G03", "G50", "G70", "G71", "G72", "G40", "G41", "G96", ""];
    let letters = ["X", "Z", "U", "W", "R", "I", "K", "P", "Q", "F", "N", "T", "M"];
    let values = ["0", "1", "-1", "2.5", "-7.348", "999999.999", "-999999.999", "0.001", "10", "20", "30"];
    let config = Config { params: cycle_vocab::Params { max_passes: Some(50), ..Default::default() }, ..Config::default() };
    for _ in 0..2_000 {
        let mut src = String::new();
        for _ in 0..rng.below(12) {
            src.push_str(&format!("N{} {}", 10 * rng.below(4), codes[rng.below(codes.len() as u64) as usize]));
            for _ in 0..rng.below(4) {
                let l = letters[rng.below(letters.len() as u64) as usize];
                if !src.rsplit('\n').next().is_some_and(|b| b.contains(l)) {
                    src.push_str(&format!(" {l}{}", values[rng.below(values.len() as u64) as usize]));
                }
            }
            src.push('\n');
        }
        let t = expand(src.as_bytes(), &config);
        assert!(t.events.len() < 100_000, "{src}");
    }
}
