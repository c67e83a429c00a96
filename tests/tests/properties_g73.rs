//! Properties of G73 pattern repeating (M003, read as docs/INTERPRETATION.md says) over random
//! contours of lines and quarter arcs (not monotone: G73 takes any contour, G73.USE), both
//! formats, checked exactly on the traces of BOTH engines. Cases: `CYCLECHECK_CASES` (default
//! 10 000), metric ISB.
//!
//! Pass n = 1 … d is exactly: its header (index n, ROUGH, depth |2·round(Δi·(d − n)/d)|, G73.DEPTH),
//! the rapid to A + Tₙ, then the contour translated by Tₙ = (2·round(Δi·(d − n)/d) + Δu,
//! round(Δk·(d − n)/d) + Δw) block by block in each block's mode, arcs about translated centres
//! (G73.PATH); after pass d the rapid to A; moves to the current position left out (PRJ.NOOP).
//! So every pass lies between the blank offset and the allowance, the offsets never grow in
//! magnitude, and the last pass is the contour plus the allowance.

use cycle_vocab::text::{fixed, Trace};
use cycle_vocab::{Config, Event, MoveKind};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("CYCLECHECK_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(10_000)
}

/// A contour element: its kind, end point (X diameter, Z) and, for an arc, its centre.
#[derive(Debug, Clone, Copy)]
struct El {
    kind: MoveKind,
    end: (i64, i64),
    centre: (i64, i64),
}

/// A move as compared: kind, x, z, feed, cx, cz.
type Shape = (MoveKind, i64, i64, i64, i64, i64);

#[derive(Debug, Clone)]
struct G73 {
    a: (i64, i64),
    elements: Vec<El>,
    escape: (i64, i64),
    count: i64,
    allowance: (i64, i64),
    format_b: bool,
}

/// round(v / d) half away from zero, d > 0.
fn round_div(v: i64, d: i64) -> i64 {
    let q = (2 * v.abs() + d) / (2 * d);
    q * v.signum()
}

impl G73 {
    /// Tₙ (a diameter count, Z).
    fn shift(&self, n: i64) -> (i64, i64) {
        let d = self.count;
        (2 * round_div(self.escape.0 * (d - n), d) + self.allowance.0, round_div(self.escape.1 * (d - n), d) + self.allowance.1)
    }

    fn program(&self) -> String {
        let f3 = |v: i64| fixed(v, 3);
        let mut s = format!("G00 X{} Z{}\n", f3(self.a.0), f3(self.a.1));
        let (uw, n) = (format!("U{} W{}", f3(self.allowance.0), f3(self.allowance.1)), self.elements.len());
        if self.format_b {
            s += &format!("G73 P1 Q{n} I{} K{} {uw} D{} F0.2\n", f3(self.escape.0), f3(self.escape.1), self.count);
        } else {
            s += &format!("G73 U{} W{} R{}\nG73 P1 Q{n} {uw} F0.2\n", f3(self.escape.0), f3(self.escape.1), self.count);
        }
        let mut at = self.a;
        for (i, e) in self.elements.iter().enumerate() {
            let code = match e.kind {
                MoveKind::Rapid => "G00",
                MoveKind::Feed => "G01",
                MoveKind::ArcCw => "G02",
                _ => "G03",
            };
            s += &format!("N{} {code} X{} Z{}", i + 1, f3(e.end.0), f3(e.end.1));
            if matches!(e.kind, MoveKind::ArcCw | MoveKind::ArcCcw) {
                s += &format!(" I{} K{}", f3((e.centre.0 - at.0) / 2), f3(e.centre.1 - at.1));
            }
            s += "\n";
            at = e.end;
        }
        s
    }

    /// The expected (kind, x, z, feed, cx, cz) of every move after the first pass header, and
    /// each pass's depth.
    fn expected(&self) -> (Vec<i64>, Vec<Shape>) {
        let (mut depths, mut moves) = (Vec::new(), Vec::new());
        let mut at = self.a;
        let mut go = |at: &mut (i64, i64), kind, to: (i64, i64), c: (i64, i64)| {
            if to != *at {
                let feed = if kind == MoveKind::Rapid { 0 } else { 2_000 };
                moves.push((kind, to.0, to.1, feed, c.0, c.1));
                *at = to;
            }
        };
        for n in 1..=self.count {
            let t = self.shift(n);
            depths.push((2 * round_div(self.escape.0 * (self.count - n), self.count)).abs());
            go(&mut at, MoveKind::Rapid, (self.a.0 + t.0, self.a.1 + t.1), (0, 0));
            for e in &self.elements {
                let arc = matches!(e.kind, MoveKind::ArcCw | MoveKind::ArcCcw);
                let c = if arc { (e.centre.0 + t.0, e.centre.1 + t.1) } else { (0, 0) };
                go(&mut at, e.kind, (e.end.0 + t.0, e.end.1 + t.1), c);
            }
        }
        go(&mut at, MoveKind::Rapid, self.a, (0, 0));
        (depths, moves)
    }
}

fn g73_strategy() -> impl Strategy<Value = G73> {
    let element = (0u8..4, -10_000i64..10_000, -10_000i64..10_000, 1i64..5_000);
    (20_000i64..100_000, 0i64..10_000, proptest::collection::vec(element, 1..8), -8_000i64..8_000, -4_000i64..4_000, 1i64..15, -600i64..600, -300i64..300, any::<bool>(), any::<bool>())
        .prop_map(|(ax, az, raw, ei, ek, count, du, dw, format_b, ns_rapid)| {
            let a = (2 * (ax / 2), az);
            // The ns block moves off A in G00 or G01; then lines and quarter arcs.
            let mut at = (a.0 - 2_000, a.1 - 1_000);
            let first = El { kind: if ns_rapid { MoveKind::Rapid } else { MoveKind::Feed }, end: at, centre: (0, 0) };
            let mut elements = vec![first];
            for (kind, dx, dz, r) in raw {
                let el = match kind {
                    0 | 1 if (dx, dz) != (0, 0) => El { kind: MoveKind::Feed, end: (at.0 + 2 * dx, at.1 + dz), centre: (0, 0) },
                    // A quarter (or three-quarter) circle of radius r about the point r toward −Z.
                    _ => {
                        let centre = (at.0, at.1 - r);
                        El { kind: if kind == 3 { MoveKind::ArcCcw } else { MoveKind::ArcCw }, end: (at.0 + 2 * r, at.1 - r), centre }
                    }
                };
                at = el.end;
                elements.push(el);
            }
            G73 { a, elements, escape: (ei, ek), count, allowance: (du, dw), format_b }
        })
}

fn check(c: &G73, engine: &str, t: &Trace) -> Result<(), TestCaseError> {
    prop_assert!(t.alarm.is_none(), "{}: {:?}", engine, t.alarm);
    let (depths, want) = c.expected();
    let first = t.events.iter().position(|e| matches!(e, Event::Pass(_))).unwrap_or(t.events.len());
    let mut got = Vec::new();
    let mut passes = Vec::new();
    for e in &t.events[first..] {
        match e {
            Event::Pass(p) => passes.push((p.index as i64, p.diameter_depth)),
            Event::Move(m) => got.push((m.kind, m.x, m.z, m.feed, m.cx, m.cz)),
            other => prop_assert!(false, "{}: G73 has {:?}", engine, other),
        }
    }
    let want_passes: Vec<(i64, i64)> = depths.iter().enumerate().map(|(i, d)| (i as i64 + 1, *d)).collect();
    prop_assert_eq!(passes, want_passes, "{}: pass headers", engine);
    prop_assert_eq!(got, want, "{}: moves", engine);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn g73_passes_are_the_contour_translated_by_shrinking_offsets(c in g73_strategy()) {
        let mut config = Config::default();
        config.params.max_passes = Some(1_000);
        let program = c.program();
        let spec = cycle_spec::expand(program.as_bytes(), &config);
        let imp = Trace::collect(config.grid, cycle_impl::Expander::new(program.as_bytes(), config));
        check(&c, "spec", &spec)?;
        check(&c, "impl", &imp)?;
    }
}
