//! Properties of the peck cycles G74/G75 and the drilling cycles G83/G84 (M003, read as
//! docs/INTERPRETATION.md says) over their legal input space (proptest), checked on the traces of
//! BOTH engines. Cases: `CYCLECHECK_CASES` (default 10 000), metric ISB.
//!
//! - G74/G75 (G74.PECK, G74.E, G74.COLUMN, G74.RELIEF and G75's): one pass header per column,
//!   the column count exactly ⌈|travel| / 2Δi⌉ + 1 (one without travel); columns stepping away
//!   from A by at most the step, the first at A, the last exactly at E; in each column every peck
//!   advances by exactly the peck toward E (the last exactly to E, none past it), the count
//!   exactly ⌈depth / peck⌉; after every peck but the last a rapid back by e; the cycle ends at A.
//! - G83 (G83.PECK): the pecks from the R level, each exactly a peck deeper, the last exactly at
//!   the bottom, none past it, ⌈depth / Q⌉ of them (one without Q); a rapid back to the R level
//!   after each but the last; the dwell once, at the bottom; the end at the initial level.
//! - G84 (G84.PATH): the spindle reverses once, at the bottom, and turns forward once, back at
//!   the R level; the lead in equals the lead out (F under G99, F / S under G98); the dwell at
//!   the bottom; the end at the initial level.

use cycle_vocab::text::{fixed, Trace};
use cycle_vocab::{Config, Event, MoveKind, SpindleState};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("CYCLECHECK_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(10_000)
}

/// Both engines' traces of `program` (default configuration, `max_passes` raised).
fn traces(program: &str) -> [(&'static str, Trace); 2] {
    let mut config = Config::default();
    config.params.max_passes = Some(1_000_000);
    let spec = cycle_spec::expand(program.as_bytes(), &config);
    let imp = Trace::collect(config.grid, cycle_impl::Expander::new(program.as_bytes(), config));
    [("spec", spec), ("impl", imp)]
}

fn ceil_div(a: i64, b: i64) -> i64 {
    (a + b - 1) / b
}

/// A G74 (`g75`: G75) cycle: A, the travel along the peck axis (`depth`, > 0 toward −Z / −X),
/// the travel across (`across`, radius for G74, signed, 0: one column), peck, step, e, Δd.
#[derive(Debug, Clone)]
struct Peck {
    g75: bool,
    a: (i64, i64),
    depth: i64,
    across: i64,
    peck: i64,
    step: i64,
    e: i64,
    relief: i64,
}

impl Peck {
    /// E: G74 pecks along Z (down by depth), steps in X (diameter 2·across); G75 the other way.
    fn end(&self) -> (i64, i64) {
        if self.g75 {
            (self.a.0 - 2 * self.depth, self.a.1 - self.across)
        } else {
            (self.a.0 + 2 * self.across, self.a.1 - self.depth)
        }
    }
    fn program(&self) -> String {
        let (code, e) = (if self.g75 { 75 } else { 74 }, self.end());
        let (p, q) = if self.g75 { (self.peck, self.step) } else { (self.step, self.peck) };
        let mut s = format!("G00 X{} Z{}\nG{code} R{}\nG{code} X{} Z{} ", fixed(self.a.0, 3), fixed(self.a.1, 3), fixed(self.e, 3), fixed(e.0, 3), fixed(e.1, 3));
        s += &format!("P{} Q{} R{} F0.1\n", fixed(p, 3), fixed(q, 3), fixed(self.relief, 3));
        s
    }
}

fn peck_strategy() -> impl Strategy<Value = Peck> {
    (any::<bool>(), 0i64..100_000, -20_000i64..20_000, 1i64..30_000, -20_000i64..20_000, 1i64..40, 1i64..20, 0i64..2_000, 0i64..500, any::<bool>())
        .prop_map(|(g75, ax, az, depth, across, pecks, steps, e, relief, one_column)| {
            let across = if one_column { 0 } else { across };
            let peck = ceil_div(depth, pecks).max(1);
            let step = (across.abs() / steps).max(1);
            let ax = if g75 { ax + 2 * depth } else { ax };
            Peck { g75, a: (ax, az), depth, across, peck, step, e, relief }
        })
}

/// (along the peck axis, across) of a point, in the peck axis' own units (G75: radius).
fn axes(g75: bool, p: (i64, i64)) -> (i64, i64) {
    if g75 {
        (p.0, p.1)
    } else {
        (p.1, p.0)
    }
}

fn check_peck(c: &Peck, engine: &str, t: &Trace) -> Result<(), TestCaseError> {
    prop_assert!(t.alarm.is_none(), "{}: {:?}", engine, t.alarm);
    let (e, g75) = (c.end(), c.g75);
    // Along the peck axis in its trace units: G75's X is a diameter, two counts per radius count.
    let per = if g75 { 2 } else { 1 };
    let (peck, dir) = (c.peck * per, -1);
    let (end_along, end_across) = axes(g75, e);
    let (a_along, a_across) = axes(g75, c.a);
    let columns = if c.across == 0 { 1 } else { ceil_div(c.across.abs(), c.step) + 1 };
    let passes = t.events.iter().filter(|e| matches!(e, Event::Pass(_))).count() as i64;
    prop_assert_eq!(passes, columns, "{}: columns", engine);
    let (mut column, mut last_across, mut pecks) = (0, a_across, Vec::new());
    let mut at = c.a;
    let check_column = |pecks: &Vec<i64>, column: i64| -> Result<(), TestCaseError> {
        let want = ceil_div(c.depth * per, peck);
        prop_assert_eq!(pecks.len() as i64, want, "{}: pecks in column {}", engine, column);
        for (i, z) in pecks.iter().enumerate() {
            let expect = if i as i64 == want - 1 { end_along } else { a_along + dir * peck * (i as i64 + 1) };
            prop_assert_eq!(*z, expect, "{}: peck {} of column {}", engine, i + 1, column);
        }
        Ok(())
    };
    let mut prev: Option<(MoveKind, i64)> = None;
    for ev in &t.events {
        match ev {
            Event::Pass(_) => {
                if column > 0 {
                    check_column(&pecks, column)?;
                }
                column += 1;
                pecks.clear();
            }
            Event::Move(m) => {
                let (along, across) = axes(g75, (m.x, m.z));
                if m.kind == MoveKind::Feed {
                    // A peck: along the peck axis only, in the column, toward E, not past it.
                    prop_assert_eq!(axes(g75, at).1, across, "{}: a peck moves across", engine);
                    prop_assert!(along < axes(g75, at).0 && along >= end_along, "{}: peck to {} from {:?}", engine, along, at);
                    if column == 1 {
                        prop_assert_eq!(across, a_across, "{}: the first column is at A", engine);
                    }
                    if (across - last_across).abs() > 0 {
                        // A new column: away from A by at most the step (a diameter for G74).
                        let step = c.step * if g75 { 1 } else { 2 };
                        prop_assert!((across - last_across).abs() <= step, "{}: column step {}", engine, across - last_across);
                        last_across = across;
                    }
                    pecks.push(along);
                } else if let Some((MoveKind::Feed, z)) = prev {
                    // After a peck: the return by e, unless it was the column's last.
                    if z != end_along && m.kind == MoveKind::Rapid && along != a_along {
                        prop_assert_eq!(along, z + c.e * per, "{}: return by e", engine);
                    }
                }
                prev = Some((m.kind, along));
                at = (m.x, m.z);
            }
            _ => prop_assert!(false, "{}: a peck cycle dwells or turns the spindle", engine),
        }
    }
    check_column(&pecks, column)?;
    prop_assert_eq!(last_across, end_across, "{}: the last column is at E", engine);
    prop_assert_eq!(at, c.a, "{}: ends at A", engine);
    Ok(())
}

/// A G83 (`tap`: G84) cycle from the initial level `z0` at X0: R (distance to the R level),
/// the depth below the R level, Q (increments; 0: none), P (ms), the lead, G98 with S.
#[derive(Debug, Clone)]
struct Drill {
    tap: bool,
    z0: i64,
    r: i64,
    depth: i64,
    q: i64,
    p: i64,
    lead: i64,
    g98: Option<i64>,
}

impl Drill {
    fn program(&self) -> String {
        let bottom = self.z0 + self.r - self.depth;
        let mut s = format!("G00 X0 Z{}\n", fixed(self.z0, 3));
        if self.tap {
            match self.g98 {
                Some(speed) => s += &format!("G98 M29 S{speed}\nG84 Z{} R{} P{} F{}\n", fixed(bottom, 3), fixed(self.r, 3), self.p, fixed(self.lead * speed, 4)),
                None => s += &format!("M29 S500\nG84 Z{} R{} P{} F{}\n", fixed(bottom, 3), fixed(self.r, 3), self.p, fixed(self.lead, 4)),
            }
        } else {
            let q = if self.q > 0 { format!(" Q{}", self.q) } else { String::new() };
            s += &format!("G83 Z{} R{}{q} P{} F0.1\n", fixed(bottom, 3), fixed(self.r, 3), self.p);
        }
        s
    }
}

fn drill_strategy() -> impl Strategy<Value = Drill> {
    (any::<bool>(), 0i64..20_000, -5_000i64..5_000, 1i64..40_000, 0i64..60, 0i64..3_000, 2_000i64..30_000, proptest::option::of(50i64..2_000))
        .prop_map(|(tap, z0, r, depth, pecks, p, lead, g98)| {
            let q = if pecks == 0 { 0 } else { ceil_div(depth, pecks).max(1) };
            Drill { tap, z0, r, depth, q, p, lead, g98 }
        })
}

fn check_drill(c: &Drill, engine: &str, t: &Trace) -> Result<(), TestCaseError> {
    prop_assert!(t.alarm.is_none(), "{}: {:?}", engine, t.alarm);
    let (r_level, bottom) = (c.z0 + c.r, c.z0 + c.r - c.depth);
    let mut z = c.z0;
    let (mut feeds, mut dwells, mut reversed, mut forward) = (Vec::new(), 0, None, None);
    let mut leads = Vec::new();
    for ev in &t.events {
        match ev {
            Event::Pass(_) => {}
            Event::Move(m) => {
                prop_assert_eq!(m.x, 0, "{}: drilling moves on X", engine);
                // Cutting moves never pass the bottom (the last rapid, to the initial level, may
                // be below a bottom drilled above it).
                prop_assert!(m.kind == MoveKind::Rapid || m.z >= bottom, "{}: past the bottom", engine);
                match m.kind {
                    MoveKind::Feed => feeds.push(m.z),
                    MoveKind::Thread => leads.push((m.z, m.feed)),
                    _ => {}
                }
                z = m.z;
            }
            Event::Dwell(d) => {
                prop_assert_eq!(z, bottom, "{}: the dwell is at the bottom", engine);
                prop_assert_eq!(d.ms as i64, c.p, "{}: the dwell's time", engine);
                dwells += 1;
            }
            Event::Spindle(s) => match s.state {
                SpindleState::Reverse => {
                    prop_assert!(reversed.is_none(), "{}: reversed twice", engine);
                    reversed = Some(z);
                }
                SpindleState::Forward => {
                    prop_assert!(forward.is_none(), "{}: forward twice", engine);
                    forward = Some(z);
                }
            },
            Event::Press(_) | Event::Stop(_) | Event::Resume(_) => prop_assert!(false, "{}: an operator event without a script", engine),
        }
    }
    prop_assert_eq!(dwells, i64::from(c.p > 0), "{}: dwells", engine);
    prop_assert_eq!(z, c.z0, "{}: ends at the initial level", engine);
    if c.tap {
        let lead = c.lead;
        prop_assert_eq!(reversed, Some(bottom), "{}: the spindle reverses at the bottom", engine);
        prop_assert_eq!(forward, Some(r_level), "{}: forward again at the R level", engine);
        prop_assert_eq!(leads, vec![(bottom, lead), (r_level, lead)], "{}: in and out at the lead", engine);
    } else {
        prop_assert!(reversed.is_none() && forward.is_none(), "{}: G83 turns the spindle", engine);
        let want = if c.q == 0 { 1 } else { ceil_div(c.depth, c.q) };
        prop_assert_eq!(feeds.len() as i64, want, "{}: pecks", engine);
        for (i, f) in feeds.iter().enumerate() {
            let expect = if i as i64 == want - 1 { bottom } else { r_level - c.q * (i as i64 + 1) };
            prop_assert_eq!(*f, expect, "{}: peck {}", engine, i + 1);
        }
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn pecks_advance_stop_at_the_end_and_count_exactly(c in peck_strategy()) {
        for (engine, t) in traces(&c.program()) {
            check_peck(&c, engine, &t)?;
        }
    }

    #[test]
    fn drilling_pecks_and_taps_reverse_only_at_the_bottom(c in drill_strategy()) {
        for (engine, t) in traces(&c.program()) {
            check_drill(&c, engine, &t)?;
        }
    }
}
