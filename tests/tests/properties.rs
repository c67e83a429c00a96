//! Properties of the thread cycles over the whole legal input space (proptest), checked on the
//! traces of BOTH engines (each must satisfy them on its own; their agreement is checked in
//! `differential.rs`). Cases per property: `CYCLECHECK_CASES` (default 10 000).
//!
//! G92: the cycle ends where it started (G92.PATH), the pull-out stays within J/K
//! (G92.PULLOUT), every synchronized move keeps the lead (COM.LEAD).
//! G76/G78: rough depths never decrease and strictly increase when Δdmin ≥ one increment
//! (G76.DEPTH.1, G76.DEPTH.MIN); the last rough depth is k − d and the finish depth k
//! (G76.DEPTH.LAST, G76.FINISH); every cut but the last rough one is ≥ Δdmin; the pass count
//! stays within PRJ.MAXPASS; every point stays inside the envelope of the start point, the
//! thread and the pull-out (COM.POINTS); the cycle ends at its start point (G76.PATH).
//! G162: depths strictly increase, never pass P and end at P; full passes Q, 2Q, …; the split
//! cuts sum exactly to the remainder (G162.PQ, G162.SPLIT); a variable pitch is never ≤ 0 and a
//! growing one stays in the F range (G162.I); every pass starts and ends at S, at feed H, never
//! at rapid (G162.PATH, G162.H).

use cycle_vocab::text::{fixed, Trace};
use cycle_vocab::{AlarmCode, Config, Event, Grid, Increment, MoveKind, PassKind, Units};
use proptest::prelude::*;

fn cases() -> u32 {
    std::env::var("CYCLECHECK_CASES").ok().and_then(|v| v.parse().ok()).unwrap_or(10_000)
}

fn both(program: &str, config: Config) -> [(&'static str, Trace); 2] {
    [
        ("spec", cycle_spec::expand(program.as_bytes(), &config)),
        ("impl", Trace::collect(config.grid, cycle_impl::Expander::new(program.as_bytes(), config))),
    ]
}

fn grid_strategy() -> impl Strategy<Value = Grid> {
    (prop_oneof![Just(Units::Metric), Just(Units::Inch)], prop_oneof![Just(Increment::Isb), Just(Increment::Isc)])
        .prop_map(|(units, increment)| Grid { units, increment })
}

/// A length in increments, log-uniform over 1…max so every magnitude is exercised.
fn magnitude(max: i64) -> impl Strategy<Value = i64> {
    (0u32..=30, any::<u64>()).prop_map(move |(bits, r)| {
        let hi = (1i64 << bits).min(max);
        1 + (r % hi as u64) as i64
    })
}

/// A lead in lead counts within the range for the units.
fn lead_for(grid: Grid, raw: u64) -> i64 {
    let max = match grid.units {
        Units::Metric => 99_990_000,
        Units::Inch => 999_000,
    };
    1 + (raw % max as u64) as i64
}

fn len(v: i64, g: Grid) -> String {
    fixed(v, g.decimals())
}

// ---------------------------------------------------------------- G92

#[derive(Debug, Clone)]
struct G92Case {
    grid: Grid,
    start_x: i64,
    start_z: i64,
    end_x: i64,
    w: i64,
    r: i64,
    j: Option<i64>,
    k: Option<i64>,
    lead: i64,
    repeats: Vec<i64>,
}

fn g92_case() -> impl Strategy<Value = G92Case> {
    (
        grid_strategy(),
        magnitude(400_000_000),
        -1000i64..1000,
        magnitude(300_000_000),
        any::<bool>(),
        magnitude(400_000_000),
        (any::<bool>(), -50i64..=50),
        (proptest::option::of(magnitude(99_999_999)), proptest::option::of(magnitude(99_999_999))),
        any::<u64>(),
        proptest::collection::vec(magnitude(10_000), 0..4),
    )
        .prop_map(|(grid, start_x, start_z, depth, internal, w, (taper, rs), (j, k), raw_lead, repeats)| {
            // External: the start lies outside the thread (larger X); internal: inside.
            let end_x = if internal { start_x + depth } else { (start_x - depth).max(1) };
            let r = if taper { rs * 1000 } else { 0 };
            G92Case { grid, start_x, start_z, end_x, w: -w, r, j, k, lead: lead_for(grid, raw_lead), repeats }
        })
}

impl G92Case {
    fn program(&self) -> String {
        let g = self.grid;
        let mut p = format!("G00 X{} Z{}\nG92 X{} W{}", len(self.start_x, g), len(self.start_z, g), len(self.end_x, g), len(self.w, g));
        if self.r != 0 {
            p += &format!(" R{}", len(self.r, g));
        }
        p += &format!(" F{}", fixed(self.lead, g.lead_decimals()));
        if let Some(j) = self.j {
            p += &format!(" J{}", len(j, g));
        }
        if let Some(k) = self.k {
            p += &format!(" K{}", len(k, g));
        }
        p.push('\n');
        let mut x = self.end_x;
        for step in &self.repeats {
            x += if self.end_x < self.start_x { -step } else { *step };
            p += &format!("X{}\n", len(x, g));
        }
        p
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    /// G92.PATH, G92.PULLOUT, COM.LEAD.
    #[test]
    fn g92_cycle_returns_keeps_lead_and_pulls_out_within_jk(case in g92_case()) {
        let program = case.program();
        let config = Config { grid: case.grid, ..Config::default() };
        for (engine, trace) in both(&program, config) {
            let ctx = format!("{engine} on\n{program}\n{}", trace.to_gcode());
            let (ax, az) = (case.start_x, case.start_z);
            // Position at every pass header and at the end is the start point A.
            let mut pos = (0, 0);
            let mut seen_pass = false;
            for e in &trace.events {
                match e {
                    Event::Pass(_) => {
                        if seen_pass { prop_assert_eq!(pos, (ax, az), "{}", ctx); }
                        seen_pass = true;
                    }
                    Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => prop_assert!(false, "no dwell or spindle event in a thread cycle: {}", ctx),
                    Event::Move(m) => {
                        if m.kind == MoveKind::Thread {
                            prop_assert_eq!(m.feed, case.lead, "lead kept: {}", ctx);
                        }
                        if seen_pass && m.kind == MoveKind::Thread {
                            // Pull-out bound (G92.PULLOUT): Z never passes the thread end; on
                            // the start side it stays at A.z, except that with X the long axis
                            // the pull-out runs J along Z toward A and may overshoot A.z by at
                            // most J (or the No.19 amount, at most one lead, when J is omitted).
                            let end_z = az + case.w;
                            let x_long = case.r.abs() >= case.w.abs();
                            let slack = if x_long { case.j.map_or(case.lead, i64::abs).max(case.lead) } else { 0 };
                            prop_assert!(m.z >= end_z && m.z <= az + slack, "Z within the thread: {}", ctx);
                        }
                        pos = (m.x, m.z);
                    }
                }
            }
            if trace.alarm.is_none() && seen_pass {
                prop_assert_eq!(pos, (ax, az), "cycle ends at A: {}", ctx);
            }
            // Straight threads: each pull-out moves exactly J (radius) and K.
            if trace.alarm.is_none() && case.r == 0 {
                let threads: Vec<_> = trace.moves().filter(|m| m.kind == MoveKind::Thread).collect();
                let mut before = None;
                for e in &trace.events {
                    if let Event::Move(m) = e {
                        if m.kind == MoveKind::Thread {
                            if let Some((bx, bz)) = before {
                                let (dx, dz): (i64, i64) = (m.x - bx, m.z - bz);
                                if dx != 0 {
                                    prop_assert!(dx.abs() % 2 == 0 && dz.abs() > 0, "pull-out: {}", ctx);
                                    if let (Some(j), Some(k)) = (case.j, case.k) {
                                        if j != 0 && k != 0 && case.w.abs() > k {
                                            prop_assert_eq!((dx.abs() / 2, dz.abs()), (j, k), "J/K: {}", ctx);
                                        }
                                    }
                                }
                            }
                        }
                        before = Some((m.x, m.z));
                    }
                }
                let _ = threads;
            }
        }
    }
}

// ---------------------------------------------------------------- G76 / G78

#[derive(Debug, Clone)]
struct MultiCase {
    grid: Grid,
    code: u32,
    m: u32,
    angle: u32,
    mode: u32,
    degressive: bool,
    dmin: i64,
    d: i64,
    k: i64,
    dd: i64,
    i: i64,
    internal: bool,
    clearance: i64,
    end_x: i64,
    w: i64,
    jk: Option<(i64, i64)>,
    lead: i64,
    starts: u32,
    e: i64,
}

fn multi_case() -> impl Strategy<Value = MultiCase> {
    (
        (grid_strategy(), prop_oneof![Just(76u32), Just(78u32)], 1u32..=99, 0u32..=99, 0u32..=4, any::<bool>()),
        (magnitude(999_999_999), magnitude(999_999_999), any::<u64>(), magnitude(999_999_999)),
        (any::<bool>(), -3i64..=3, any::<bool>(), magnitude(1_000_000), magnitude(300_000_000), magnitude(400_000_000)),
        (proptest::option::of((1i64..=2_000_000, 1i64..=2_000_000)), any::<u64>(), 1u32..=4, prop_oneof![Just(0i64), 1i64..=5_000]),
    )
        .prop_map(|((grid, code, m, angle, mode, degressive), (k, dd, dsel, dmin_raw), (taper, tf, internal, clearance, end_x, w), (jk, raw_lead, starts, e))| {
            // d < k, Δdmin anywhere from 0 to around Δd (ties included).
            let d = (dsel % k as u64) as i64;
            let dmin = match dsel % 4 { 0 => 0, 1 => dd, 2 => dd / 7, _ => dmin_raw % (dd + 1) };
            let i = if taper { tf * (w / 8).max(1) } else { 0 };
            // The pull-out must start on the thread: K below the Z travel |W| = w + 1.
            let jk = jk.map(|(j, kk)| (j, kk.min(w)));
            MultiCase {
                grid, code, m, angle, mode: if code == 76 { mode % 3 } else { mode }, degressive,
                dmin, d, k, dd, i, internal, clearance, end_x: end_x + 2 * k + 2 * i.abs() + 2, w: -w - 1,
                jk, lead: lead_for(grid, raw_lead), starts, e,
            }
        })
        // COM.RANGES: the start point and the thread end must be words within ±N themselves.
        .prop_filter("start and end X within ±N", |c| c.start().0.abs() <= N && c.end_x <= N)
}

/// The nine-digit range of every length word (COM.RANGES).
const N: i64 = 999_999_999;

impl MultiCase {
    /// Start point A: outside the thread crest by the clearance (external), or inside (internal).
    fn start(&self) -> (i64, i64) {
        let crest_x = self.end_x + 2 * self.i + if self.internal { -2 * self.k } else { 2 * self.k };
        let x = if self.internal { crest_x - 2 * self.clearance } else { crest_x + 2 * self.clearance };
        (x, 5 * 10i64.pow(self.grid.decimals()))
    }

    fn program(&self) -> String {
        let g = self.grid;
        let (ax, az) = self.start();
        let c = self.code;
        let middle = if c == 76 { 0 } else { self.mode };
        let mut p = format!("G00 X{} Z{}\n", len(ax, g), len(az, g));
        p += &format!("G{c} P{:02}{:02}{:02} Q{} R{}", self.m, middle, self.angle, len(self.dmin, g), len(self.d, g));
        if c == 76 {
            p += &format!(" D{}", self.mode);
        } else {
            p += &format!(" D{}", u32::from(self.degressive));
        }
        p += &format!(" L{} E{}\n", self.starts, len(self.e, g));
        p += &format!("G{c} X{} W{} R{} P{} Q{} F{}", len(self.end_x, g), len(self.w, g), len(self.i, g), len(self.k, g), len(self.dd, g), fixed(self.lead, g.lead_decimals()));
        if let Some((j, k)) = self.jk {
            p += &format!(" J{} K{}", len(j, g), len(k, g));
        } else {
            p += " J0";
        }
        p.push('\n');
        p
    }

    fn degressive_schedule(&self) -> bool {
        self.code == 76 || self.degressive
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), max_global_rejects: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    /// G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST, G76.FINISH, G78.DEPTHMODE, PRJ.MAXPASS,
    /// COM.POINTS, G76.PATH.
    #[test]
    fn multipass_depths_bounds_and_envelope(case in multi_case()) {
        let program = case.program();
        let config = Config { grid: case.grid, ..Config::default() };
        let max_passes = cycle_spec::config::params(&config).max_passes as usize;
        let (ax, az) = case.start();
        for (engine, trace) in both(&program, config) {
            let ctx = format!("{engine} on\n{program}\n(alarm {:?})", trace.alarm);
            if let Some(a) = trace.alarm {
                // Legal cycles may only be refused for their pass count, and then before any
                // motion of the cycle (only the positioning move precedes it).
                prop_assert_eq!(a.code, AlarmCode::TooManyPasses, "{}", ctx);
                prop_assert!(trace.events.len() <= 1, "alarm before motion: {}", ctx);
                continue;
            }
            let passes: Vec<_> = trace.events.iter().filter_map(|e| match e { Event::Pass(p) => Some(*p), _ => None }).collect();
            prop_assert!(passes.len() * case.starts as usize <= max_passes, "{}", ctx);
            let rough: Vec<i64> = passes.iter().filter(|p| p.kind == PassKind::Rough).map(|p| p.diameter_depth / 2).collect();
            let finish: Vec<_> = passes.iter().filter(|p| p.kind != PassKind::Rough).collect();
            prop_assert!(!rough.is_empty(), "{}", ctx);
            prop_assert_eq!(*rough.last().unwrap(), case.k - case.d, "last rough is k - d: {}", ctx);
            prop_assert_eq!(finish.len(), case.m as usize, "{}", ctx);
            prop_assert!(finish.iter().all(|p| p.diameter_depth == 2 * case.k), "finish at k: {}", ctx);
            prop_assert_eq!(finish[0].kind, PassKind::Finish, "{}", ctx);
            prop_assert!(finish[1..].iter().all(|p| p.kind == PassKind::Spring), "{}", ctx);
            for (n, pair) in rough.windows(2).enumerate() {
                let cut = pair[1] - pair[0];
                prop_assert!(cut >= 0, "never decreasing at pass {}: {}", n + 2, ctx);
                let strict = if case.degressive_schedule() { case.dmin >= 1 } else { true };
                if strict { prop_assert!(cut > 0, "strictly increasing at pass {}: {}", n + 2, ctx); }
                let last = n + 2 == rough.len();
                if !last && case.degressive_schedule() {
                    prop_assert!(cut >= case.dmin, "cut >= dmin at pass {}: {}", n + 2, ctx);
                }
                if !last && !case.degressive_schedule() {
                    prop_assert_eq!(cut, case.dd, "constant cut at pass {}: {}", n + 2, ctx);
                }
            }
            // Envelope (COM.POINTS): X between the full-depth thread and the start point or
            // the pull-out / lead-in beyond it; Z between A and the thread end, widened by the
            // largest flank shift (|tan(a/2)| ≤ 1.18 for a ≤ 99°).
            let (j, _) = case.jk.unwrap_or((0, 0));
            let full_start = case.end_x + 2 * case.i;
            // The thread's profile: full depth at both ends, and the crest k above it.
            let crest = if case.internal { -2 * case.k } else { 2 * case.k };
            let profile = [full_start, case.end_x, full_start + crest, case.end_x + crest];
            let (plo, phi) = (*profile.iter().min().unwrap(), *profile.iter().max().unwrap());
            let outer = 2 * (j.max(case.e));
            let (xlo, xhi) = if case.internal {
                (ax.min(plo) - outer, phi)
            } else {
                (plo, ax.max(phi) + outer)
            };
            let shift = 3 * case.k + 1;
            // With X the long axis (|i| ≥ |W|) the pull-out runs J along Z toward A (G92.PULLOUT
            // geometry, which G76 shares) and may overshoot A.z by at most J.
            let z_slack = if case.i.abs() >= case.w.abs() { j } else { 0 };
            let (zlo, zhi) = (az + case.w - shift, az + shift + z_slack);
            let mut last = (ax, az);
            for m in trace.moves() {
                prop_assert!(m.x >= xlo && m.x <= xhi, "X {} outside [{}, {}]: {}", m.x, xlo, xhi, ctx);
                prop_assert!(m.z >= zlo && m.z <= zhi, "Z {} outside [{}, {}]: {}", m.z, zlo, zhi, ctx);
                if m.kind == MoveKind::Thread { prop_assert_eq!(m.feed, case.lead, "{}", ctx); }
                last = (m.x, m.z);
            }
            prop_assert_eq!(last, (ax, az), "cycle ends at A: {}", ctx);
        }
    }
}

// ---------------------------------------------------------------- G162 (M004, nc201)

#[derive(Debug, Clone)]
struct G162Case {
    grid: Grid,
    /// Start point S (X diameter).
    sx: i64,
    sz: i64,
    x0: i64,
    ze: i64,
    /// (P, Q), radius; `None` = single pass.
    pq: Option<(i64, i64)>,
    v: i64,
    /// Taper, diameter.
    w: i64,
    a_half: i64,
    lead: i64,
    i: i64,
    j: i64,
    b: i64,
    h: i64,
}

fn g162_case() -> impl Strategy<Value = G162Case> {
    (
        grid_strategy(),
        (any::<bool>(), any::<bool>(), any::<bool>()),
        (magnitude(50_000_000), 1i64..=200, any::<u64>()),
        (0i64..=5_000_000, -4_000_000i64..=4_000_000, 1i64..=100_000_000),
        (-120i64..=120, any::<u64>(), any::<u64>(), 1i64..=1_000_000, 0i64..=360_000),
        (any::<u64>(), -10_000_000i64..=10_000_000),
    )
        .prop_map(|(grid, (internal, toward_plus, single), (p, ratio, qr), (v, w, len), (a_half, fr, ir, j, b), (sr, sz))| {
            // Q around P/ratio: ties (D = 0), Q > P and remainders of any size all occur.
            let q = match qr % 4 {
                0 => (p / ratio).max(1),
                1 => p,
                2 => p + 1 + (qr >> 8) as i64 % p.max(1),
                _ => ((p / ratio) + (qr >> 8) as i64 % 7).max(1),
            };
            let w = 2 * (w / 2);
            // S lies outside the whole depth-0 path (G162.RETRACT): room for 2V and the taper.
            let room = 2 * v + w.abs() + 2 * (1 + (sr % 1_000_000) as i64);
            let sx = 2 * (sr >> 20) as i64 % 200_000_000;
            let x0 = if internal { sx + room } else { sx - room };
            let len = len + v;
            let ze = if toward_plus { sz + len } else { sz - len };
            let lead = lead_for(grid, fr);
            // I: none, shrinking, or growing within the F range at the end (G162.I).
            let c = grid.lead_counts_per_increment() as i128;
            let s2 = if 2 * (len - v) as i128 > w.abs() as i128 { 2 * (len - v) as i128 * c } else { w.abs() as i128 * c };
            let fmax: i64 = if grid.units == Units::Metric { 99_990_000 } else { 999_000 };
            let room_i = (j as i128 * (fmax as i128 * fmax as i128 - lead as i128 * lead as i128)) / (360_000 * s2.max(1));
            let mut i = match ir % 3 {
                0 => 0,
                1 => -(1 + (ir >> 2) as i64 % fmax),
                _ if room_i >= 1 => 1 + ((ir >> 2) as i128 % room_i.min(fmax as i128)) as i64,
                _ => 0,
            };
            // Under the letter (g162.lead=steps) the stepped lead must stay within the range too.
            while i > 0 && !stepped_within(lead as i128, i as i128, j as i128, s2, fmax as i128) {
                i /= 2;
            }
            G162Case {
                grid,
                sx,
                sz,
                x0,
                ze,
                pq: if single { None } else { Some((p, q)) },
                v,
                w,
                a_half,
                lead,
                i,
                j,
                b,
                h: 1 + (fr >> 32) as i64 % 99_990_000,
            }
        })
}

/// G162.I under `g162.lead=steps`: the first step above Fmax, k* = ⌊(Fmax − F)/I⌋ + 1, is not
/// reached during the thread (s2 twice its long-axis travel, lead counts):
/// (2·k*·F + I·k*·(k* − 1))·J ≥ 360 000·s2.
fn stepped_within(f: i128, i: i128, j: i128, s2: i128, fmax: i128) -> bool {
    let k = (fmax - f) / i + 1;
    (2 * k * f + i * k * (k - 1)) * j >= 360_000 * s2
}

impl G162Case {
    fn program(&self) -> String {
        let g = self.grid;
        let (d, ld) = (g.decimals(), g.lead_decimals());
        let mut block = format!(
            "G162 X{} Z{} H{} F{} V{} W{} A{} B{} J{}",
            len(self.x0, g),
            len(self.ze, g),
            fixed(self.h, ld),
            fixed(self.lead, ld),
            fixed(self.v, d),
            fixed(self.w, d),
            fixed(self.a_half * 5, 1),
            fixed(self.b, 3),
            fixed(self.j, 3)
        );
        if let Some((p, q)) = self.pq {
            block += &format!(" P{} Q{}", fixed(p, d), fixed(q, d));
        }
        if self.i != 0 {
            block += &format!(" I{}", fixed(self.i, ld));
        }
        format!("G0 X{} Z{}\n{block}\nM30\n", len(self.sx, g), len(self.sz, g))
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() })]

    /// G162.PQ, G162.SPLIT: depths strictly increase, never pass P and end at P; the full passes
    /// are Q, 2Q, …; the split cuts (at most four, the first round(D/2)) sum exactly to the
    /// remainder D. G162.I: a variable pitch is never ≤ 0 and a growing one stays within the F
    /// range. G162.PATH: every pass returns to S at H, nothing moves at rapid.
    #[test]
    fn g162_depths_split_and_pitch(case in g162_case()) {
        let program = case.program();
        let config = Config {
            dialect: cycle_vocab::Dialect::Nc201,
            grid: case.grid,
            params: cycle_vocab::Params { max_passes: Some(1_000_000), ..cycle_vocab::Params::default() },
            ..Config::default()
        };
        for (engine, trace) in both(&program, config) {
            let ctx = format!("{engine} on\n{program}\n{}", trace.to_gcode());
            prop_assert!(trace.alarm.is_none(), "legal program refused: {}", ctx);
            let depths: Vec<i64> = trace.events.iter().filter_map(|e| match e {
                Event::Pass(p) => Some(p.diameter_depth / 2),
                _ => None,
            }).collect();
            match case.pq {
                None => prop_assert_eq!(depths.clone(), vec![0], "single pass: {}", ctx),
                Some((p, q)) => {
                    prop_assert!(depths.windows(2).all(|w| w[0] < w[1]), "strictly increasing: {}", ctx);
                    prop_assert!(depths.iter().all(|&d| d > 0 && d <= p), "within 0 < d ≤ P: {}", ctx);
                    prop_assert_eq!(depths.last().copied(), Some(p), "ends at P: {}", ctx);
                    let k = (p / q) as usize;
                    let full: Vec<i64> = (1..=k as i64).map(|n| n * q).collect();
                    prop_assert_eq!(&depths[..k], &full[..], "full passes Q, 2Q, …: {}", ctx);
                    let remainder = p - k as i64 * q;
                    let split: Vec<i64> = depths[k..].iter().scan(k as i64 * q, |prev, &d| {
                        let cut = d - *prev;
                        *prev = d;
                        Some(cut)
                    }).collect();
                    prop_assert!(split.len() <= 4, "at most D/2, D/4, D/8, rest: {}", ctx);
                    prop_assert_eq!(split.iter().sum::<i64>(), remainder, "cuts sum to D: {}", ctx);
                    if remainder > 0 {
                        prop_assert_eq!(split[0], (remainder + 1) / 2, "first split cut round(D/2): {}", ctx);
                    }
                }
            }
            let fmax = if case.grid.units == Units::Metric { 99_990_000i128 } else { 999_000 };
            let c = case.grid.lead_counts_per_increment() as i128;
            // From the first pass header on (the G00 to S before it may be a no-op).
            let first = trace.events.iter().position(|e| matches!(e, Event::Pass(_))).unwrap_or(0);
            let mut pos = (case.sx, case.sz);
            let mut at_s = true;
            for e in &trace.events[first..] {
                match e {
                    Event::Pass(_) => prop_assert!(at_s, "each pass starts at S: {}", ctx),
                    Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => prop_assert!(false, "no dwell or spindle event in a thread cycle: {}", ctx),
                    Event::Move(m) => {
                        prop_assert!(m.kind != MoveKind::Rapid, "no rapid in G162: {}", ctx);
                        if m.kind == MoveKind::Feed {
                            prop_assert_eq!(m.feed, case.h, "feed H: {}", ctx);
                        } else {
                            prop_assert_eq!(m.feed, case.lead, "{}", ctx);
                            // Never ≤ 0: a shrinking lead stops at a positive floor.
                            prop_assert!(m.feed > 0 && (m.lead_change >= 0 || m.lead_floor > 0), "{}", ctx);
                            if m.lead_change > 0 {
                                let (dz, dx) = ((m.z - pos.1).abs() as i128, (m.x - pos.0).abs() as i128);
                                let s2 = if 2 * dz > dx { 2 * dz * c } else { dx * c };
                                let j = m.lead_change_angle as i128;
                                let f = m.feed as i128;
                                if m.lead_steps {
                                    prop_assert!(stepped_within(f, m.lead_change as i128, j, s2, fmax), "{}", ctx);
                                } else {
                                    prop_assert!(j * f * f + 360_000 * m.lead_change as i128 * s2 <= j * fmax * fmax, "{}", ctx);
                                }
                            }
                        }
                        pos = (m.x, m.z);
                    }
                }
                at_s = pos == (case.sx, case.sz);
            }
            prop_assert!(at_s, "the cycle ends at S: {}", ctx);
        }
    }
}
