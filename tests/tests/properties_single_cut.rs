//! Properties of the single cutting cycles G90 and G94 (M003) over their legal input space
//! (proptest), checked on the traces of BOTH engines. Cases: `CYCLECHECK_CASES` (default 10 000).
//!
//! A modal run of one to five cycles from a start point A, each with its end point D and taper
//! (G90 I, G94 K) drawn so that the taper rule holds (G90.TAPER, G94.TAPER), repeats omitting
//! the words they keep (G90.MODAL, G94.MODAL). For every cycle: the pass header's index counts
//! the run and its depth is the infeed of step ① (PRJ.TRACE); the moves are exactly ① the rapid
//! to the cut start C (C.x = D.x + 2I, resp. C.z = D.z + k with k = −K under the letter
//! `g94.k=end-minus-start`, the default: the taper exact), ② the feed to D,
//! ③ the feed back to A's X (G94: A's Z), ④ the rapid to A (G90.PATH, G94.PATH) — each left out
//! when it goes nowhere (PRJ.NOOP); every point lies in the box spanned by A, C and D (the cut
//! stays between start and end); the cycle returns to its start.

use cycle_vocab::text::{fixed, Trace};
use cycle_vocab::{Config, Event, Grid, Increment, Move, MoveKind, Units};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("CYCLECHECK_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(10_000)
}

/// One cycle of a run: the end point and the taper, and which words the block writes.
#[derive(Debug, Clone)]
struct Cut {
    end: (i64, i64),
    taper: i64,
    write_x: bool,
    write_z: bool,
    write_taper: bool,
}

#[derive(Debug, Clone)]
struct Run {
    g94: bool,
    grid: Grid,
    start: (i64, i64),
    feed: i64,
    cuts: Vec<Cut>,
}

/// A taper that keeps the taper rule for the travel `t`: of its sign any size, against it up to
/// the limit (2|I| ≤ |U| for G90, |K| ≤ |W| for G94), none when there is no travel.
fn legal_taper(g94: bool, travel: i64, choice: u8, raw: i64) -> i64 {
    let limit = if g94 { travel.abs() } else { travel.abs() / 2 };
    match choice % 4 {
        0 => 0,
        1 => travel.signum() * (1 + raw.rem_euclid(1_000_000)),
        2 if limit > 0 => -travel.signum() * (1 + raw.rem_euclid(limit)),
        3 => -travel.signum() * limit,
        _ => 0,
    }
}

fn run_strategy() -> impl Strategy<Value = Run> {
    let grid = (any::<bool>(), any::<bool>()).prop_map(|(inch, isc)| Grid {
        units: if inch { Units::Inch } else { Units::Metric },
        increment: if isc { Increment::Isc } else { Increment::Isb },
    });
    let cut = (1i64..5_000_000, 1i64..5_000_000, any::<u8>(), any::<i64>(), any::<[bool; 4]>());
    (any::<bool>(), grid, -50_000_000i64..50_000_000, -50_000_000i64..50_000_000, 1i64..90_000_000, any::<bool>(), proptest::collection::vec(cut, 1..6))
        .prop_map(|(g94, grid, ax, az, feed, internal, raw)| {
            let side = if internal { 1 } else { -1 };
            let mut cuts = Vec::new();
            let mut kept = (ax, az, 0i64);
            for (i, (dx, dz, choice, t, writes)) in raw.into_iter().enumerate() {
                // The travel along the cycle's own axis is never 0 (G90 W, G94 U).
                let end = (ax + side * dx, az - dz);
                let travel = if g94 { end.1 - az } else { end.0 - ax };
                let taper = legal_taper(g94, travel, choice, t);
                let first = i == 0;
                let write_x = first || end.0 != kept.0 || writes[0];
                let write_z = first || end.1 != kept.1 || writes[1];
                let write_taper = taper != kept.2 || writes[2];
                kept = (end.0, end.1, taper);
                cuts.push(Cut { end, taper, write_x, write_z, write_taper });
            }
            Run { g94, grid, start: (ax, az), feed, cuts }
        })
}

impl Run {
    fn program(&self) -> String {
        let d = self.grid.decimals();
        let l = |v: i64| fixed(v, d);
        let (code, taper) = if self.g94 { ("G94", 'K') } else { ("G90", 'I') };
        let mut p = format!("G0 X{} Z{}\n", l(self.start.0), l(self.start.1));
        for (i, c) in self.cuts.iter().enumerate() {
            let mut block = if i == 0 { code.to_string() } else { String::new() };
            if c.write_x {
                block.push_str(&format!(" X{}", l(c.end.0)));
            }
            if c.write_z {
                block.push_str(&format!(" Z{}", l(c.end.1)));
            }
            if c.write_taper {
                // G94.TAPER, the letter: K = D.z − C.z, the opposite of the drawn k = C.z − D.z.
                let written = if self.g94 { -c.taper } else { c.taper };
                block.push_str(&format!(" {taper}{}", l(written)));
            }
            if i == 0 {
                block.push_str(&format!(" F{}", fixed(self.feed % 999_000 + 1, self.grid.lead_decimals())));
            }
            p.push_str(block.trim_start());
            p.push('\n');
        }
        p
    }

    fn config(&self) -> Config {
        Config { grid: self.grid, ..Config::default() }
    }

    /// The moves of cycle `c` as the register lays them out, before PRJ.NOOP.
    fn expected(&self, c: &Cut) -> [(MoveKind, i64, i64); 4] {
        let (a, d) = (self.start, c.end);
        if self.g94 {
            let cz = d.1 + c.taper;
            [(MoveKind::Rapid, a.0, cz), (MoveKind::Feed, d.0, d.1), (MoveKind::Feed, d.0, a.1), (MoveKind::Rapid, a.0, a.1)]
        } else {
            let cx = d.0 + 2 * c.taper;
            [(MoveKind::Rapid, cx, a.1), (MoveKind::Feed, d.0, d.1), (MoveKind::Feed, a.0, d.1), (MoveKind::Rapid, a.0, a.1)]
        }
    }
}

fn check(run: &Run, engine: &str, t: &Trace) -> Result<(), TestCaseError> {
    prop_assert_eq!(t.alarm, None, "{}: {}", engine, run.program());
    let mut events = t.events.iter();
    // The rapid to the start point (none from the machine's origin to itself: PRJ.NOOP).
    if run.start != (0, 0) {
        prop_assert!(matches!(events.next(), Some(Event::Move(m)) if (m.x, m.z) == run.start), "{}: start", engine);
    }
    let mut at = run.start;
    for (n, c) in run.cuts.iter().enumerate() {
        let expected = run.expected(c);
        let (cx, cz) = (expected[0].1, expected[0].2);
        // The pass header: its index in the run, its depth the infeed of step ①.
        let Some(Event::Pass(p)) = events.next() else { return Err(TestCaseError::fail(format!("{engine}: no header for cycle {}", n + 1))) };
        let depth = if run.g94 { 2 * (run.start.1 - cz).abs() } else { (run.start.0 - cx).abs() };
        prop_assert_eq!((p.index, p.diameter_depth), (n as u32 + 1, depth), "{}: header of cycle {}", engine, n + 1);
        let (lo_x, hi_x) = (run.start.0.min(c.end.0).min(cx), run.start.0.max(c.end.0).max(cx));
        let (lo_z, hi_z) = (run.start.1.min(c.end.1).min(cz), run.start.1.max(c.end.1).max(cz));
        for (kind, x, z) in expected {
            if (x, z) == at {
                continue; // PRJ.NOOP
            }
            let Some(Event::Move(m)) = events.next() else { return Err(TestCaseError::fail(format!("{engine}: a move is missing"))) };
            let Move { kind: k, x: mx, z: mz, .. } = *m;
            prop_assert_eq!((k, mx, mz), (kind, x, z), "{}: cycle {}", engine, n + 1);
            prop_assert!((lo_x..=hi_x).contains(&mx) && (lo_z..=hi_z).contains(&mz), "{}: outside the box", engine);
            at = (x, z);
        }
        prop_assert_eq!(at, run.start, "{}: cycle {} does not return to its start", engine, n + 1);
    }
    prop_assert!(events.next().is_none(), "{}: events after the run", engine);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn single_cuts_follow_their_path_return_and_keep_their_words(run in run_strategy()) {
        let program = run.program();
        let config = run.config();
        let spec = cycle_spec::expand(program.as_bytes(), &config);
        let imp = Trace::collect(config.grid, cycle_impl::Expander::new(program.as_bytes(), config));
        check(&run, "spec", &spec)?;
        check(&run, "impl", &imp)?;
    }
}
