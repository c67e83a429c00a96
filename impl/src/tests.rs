//! Tests of the whole expander that belong to no one module: every example program, the check
//! order of a block, the stream's rules, no panic on random input; the helpers the modules' tests
//! share. The thread cycles' hand-checked examples: [`threads`]; the front end's rules: [`front`];
//! the declared readings: [`readings`]; issue #29's group A points 1–4: [`thread_points`].
extern crate std;

use crate::expander::Expander;
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Dialect, Grid, Increment, Units};
use std::string::String;

mod cycle_fill;
mod front;
mod readings;
mod thread_points;
mod threads;

pub fn expand(program: &str, config: Config) -> Trace {
    Trace::collect(config.grid, Expander::new(program.as_bytes(), config))
}

pub fn gcode(program: &str, config: Config) -> String {
    expand(program, config).to_gcode()
}

pub fn fanuc() -> Config {
    Config { dialect: Dialect::Fanuc, ..Config::default() }
}

pub fn inch() -> Config {
    Config { grid: Grid { units: Units::Inch, increment: Increment::Isb }, ..Config::default() }
}

/// Every example program expands without an alarm (the G78 example excepted, see
/// `g78_example_alarm`); `--nocapture` prints the traces for review.
#[test]
fn corpus_and_programs_expand() {
    for (name, src, cfg) in [
        ("g92", include_str!("../../corpus/g92_example.nc"), Config::default()),
        ("g76", include_str!("../../corpus/g76_example.nc"), Config::default()),
        ("g78", include_str!("../../corpus/g78_example.nc"), Config::default()),
        ("f76_ex1", include_str!("../../corpus/f76_ex1.nc"), Config::default()),
        ("f76_ex1_microns", include_str!("../../corpus/f76_ex1_microns.nc"), fanuc()),
        ("f76_ex2", include_str!("../../corpus/f76_ex2.nc"), Config::default()),
        ("g92_inch", include_str!("../../tests/programs/g92_inch.nc"), inch()),
        ("g76_multistart", include_str!("../../tests/programs/g76_multistart.nc"), Config::default()),
        ("g76_mode0", include_str!("../../tests/programs/g76_mode0.nc"), Config::default()),
        ("g76_mode1", include_str!("../../tests/programs/g76_mode1.nc"), Config::default()),
        ("g76_mode2", include_str!("../../tests/programs/g76_mode2.nc"), Config::default()),
        ("g78_mode0", include_str!("../../tests/programs/g78_mode0.nc"), Config::default()),
        ("g78_mode1", include_str!("../../tests/programs/g78_mode1.nc"), Config::default()),
        ("g78_mode2", include_str!("../../tests/programs/g78_mode2.nc"), Config::default()),
        ("g78_mode3", include_str!("../../tests/programs/g78_mode3.nc"), Config::default()),
        ("g78_mode4", include_str!("../../tests/programs/g78_mode4.nc"), Config::default()),
        ("g92_internal", include_str!("../../tests/programs/g92_internal.nc"), Config::default()),
        ("g92_taper", include_str!("../../tests/programs/g92_taper.nc"), Config::default()),
        ("g92_multistart", include_str!("../../tests/programs/g92_multistart.nc"), Config::default()),
        ("g76_internal", include_str!("../../tests/programs/g76_internal.nc"), Config::default()),
        ("g76_taper", include_str!("../../tests/programs/g76_taper.nc"), Config::default()),
        ("g76_inch", include_str!("../../tests/programs/g76_inch.nc"), inch()),
        ("g78_constant", include_str!("../../tests/programs/g78_constant.nc"), Config::default()),
    ] {
        let t = expand(src, cfg);
        assert_eq!(t.alarm.is_some(), name == "g78", "{name}");
        std::println!("== {name}\n{}", gcode(src, cfg));
    }
}

use cycle_vocab::{Alarm, AlarmCode, Event, Move, MoveKind, Params, Pass, PassKind, Rule};
use std::vec::Vec;

fn alarm(code: AlarmCode, word: Option<u8>, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, word, rule, line))
}

pub fn moves(t: &Trace) -> Vec<Move> {
    t.moves().copied().collect()
}

/// The Z of the first move of every pass (where each pass starts its cut).
pub fn pass_start_z(t: &Trace) -> Vec<i64> {
    t.events
        .windows(2)
        .filter_map(|w| match w {
            [Event::Pass(_), Event::Move(m)] => Some(m.z),
            _ => None,
        })
        .collect()
}

pub fn passes(t: &Trace) -> Vec<Pass> {
    t.events
        .iter()
        .filter_map(|e| match e {
            Event::Pass(p) => Some(*p),
            _ => None,
        })
        .collect()
}

fn threads(t: &Trace) -> Vec<(i64, i64)> {
    t.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z)).collect()
}

/// PRJ.SUPPORTED: M codes up to M99 are read (M02/M30 end the program), M100 is refused; M99
/// in the main program is UNSUPPORTED (SUB.RETURN).
#[test]
fn m_code_range() {
    let t = expand("G0 X1 Z1 M97\nG0 X2\n", Config::default());
    assert_eq!((t.alarm, moves(&t).len()), (None, 2));
    let t = expand("G0 X1 Z1\nM99\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::Unsupported, Some(b'M'), Rule::SubReturn, 2));
    let t = expand("G0 X1 Z1\nM100\n", Config::default());
    assert_eq!(t.alarm, alarm(AlarmCode::UnsupportedCode, Some(b'M'), Rule::PrjSupported, 2));
}

/// The check order of a block and the alarm each check names.
#[test]
fn check_order() {
    let c = Config::default();
    let a = |src: &str| expand(src, c).alarm;
    assert_eq!(a("G5 X1"), alarm(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1));
    assert_eq!(a("G1.0 X1"), alarm(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1));
    assert_eq!(a("G0 G0"), alarm(AlarmCode::Conflict, Some(b'G'), Rule::PrjWord, 1));
    assert_eq!(a("G0 G1 G5"), alarm(AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1));
    assert_eq!(a("G0 G1 M100"), alarm(AlarmCode::UnsupportedCode, Some(b'M'), Rule::PrjSupported, 1));
    assert_eq!(a("M3.5"), alarm(AlarmCode::NotInteger, Some(b'M'), Rule::ComRanges, 1));
    assert_eq!(a("G0 X1 U1 Z1 W1"), alarm(AlarmCode::Conflict, Some(b'U'), Rule::ComAbsInc, 1));
    assert_eq!(a("G0 Z1 W1 F1 I1"), alarm(AlarmCode::Conflict, Some(b'W'), Rule::ComAbsInc, 1));
    assert_eq!(a("G92 F1 I1 Q1"), alarm(AlarmCode::Conflict, Some(b'I'), Rule::ComLead, 1));
    assert_eq!(a("G0 X1 R1 I1"), alarm(AlarmCode::WordNotAllowed, Some(b'I'), Rule::PrjWord, 1));
    assert_eq!(a("G76 P011060 F2"), alarm(AlarmCode::WordNotAllowed, Some(b'F'), Rule::PrjWord, 1));
    assert_eq!(a("G76 X1 Z1 L2"), alarm(AlarmCode::WordNotAllowed, Some(b'L'), Rule::PrjWord, 1));
    // Values alphabetically: X before Z.
    assert_eq!(a("G0 Z1.0001 X1.0001"), alarm(AlarmCode::Precision, Some(b'X'), Rule::ComUnits, 1));
    assert_eq!(a("G0 X1000000"), alarm(AlarmCode::OutOfRange, Some(b'X'), Rule::ComRanges, 1));
    assert_eq!(a("G76 P011060 D3"), alarm(AlarmCode::OutOfRange, Some(b'D'), Rule::G76Mode, 1));
    assert_eq!(a("G76 P011060 D1.0"), alarm(AlarmCode::NotInteger, Some(b'D'), Rule::ComRanges, 1));
    assert_eq!(a("G78 P010060 D2"), alarm(AlarmCode::OutOfRange, Some(b'D'), Rule::G78DepthMode, 1));
    assert_eq!(a("G76 P001060"), alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::G76Finish, 1));
    assert_eq!(a("G76 P1000000"), alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::ComRanges, 1));
    assert_eq!(a("G76 Q-1"), alarm(AlarmCode::OutOfRange, Some(b'Q'), Rule::ComRanges, 1));
    assert_eq!(a("G76 X1 Z1 P0 Q1"), alarm(AlarmCode::OutOfRange, Some(b'P'), Rule::ComRanges, 1));
    assert_eq!(a("G76 X1 Z1 J-1 P1 Q1"), alarm(AlarmCode::OutOfRange, Some(b'J'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 L100"), alarm(AlarmCode::OutOfRange, Some(b'L'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 J100000"), alarm(AlarmCode::OutOfRange, Some(b'J'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 F0"), alarm(AlarmCode::OutOfRange, Some(b'F'), Rule::ComRanges, 1));
    assert_eq!(a("G92 X1 Z1 I255"), alarm(AlarmCode::OutOfRange, Some(b'I'), Rule::ComRanges, 1));
    assert_eq!(a("G1 X1"), alarm(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 1));
    assert_eq!(a("G1"), None);
    assert_eq!(a("G92 X1 Z1"), alarm(AlarmCode::MissingWord, Some(b'F'), Rule::ComLead, 1));
    // Step 5 of G76: d ≥ k, W = 0, side, COM.POINTS, pass bound, K.
    let g76 = |second: &str| expand(&std::format!("G0 X60 Z10\nG76 P011060 Q0.1 R0.1\nG76 {second}\n"), c).alarm;
    assert_eq!(g76("X33.8 Z-60 P0.1 Q0.7 F4"), alarm(AlarmCode::OutOfRange, Some(b'R'), Rule::G76DepthLast, 3));
    assert_eq!(g76("X33.8 Z10 P0.1 Q0.7 F4"), alarm(AlarmCode::OutOfRange, Some(b'R'), Rule::G76DepthLast, 3));
    assert_eq!(g76("X33.8 Z10 P2.4 Q0.7 F4"), alarm(AlarmCode::Geometry, Some(b'Z'), Rule::G76Format, 3));
    let g78 = expand("G0 X60 Z10\nG78 P010060 Q0.1 R0.1\nG78 X33.8 Z10 P2.4 Q0.7 F4\n", c).alarm;
    assert_eq!(g78, alarm(AlarmCode::Geometry, Some(b'Z'), Rule::G78Format, 3));
    assert_eq!(g76("X60 Z-60 P2.4 Q0.7 F4"), alarm(AlarmCode::Geometry, Some(b'X'), Rule::ComSide, 3));
    assert_eq!(g76("X58 Z-60 P2.4 Q0.7 F4"), alarm(AlarmCode::Geometry, Some(b'X'), Rule::ComPoints, 3));
    assert_eq!(g76("X55.2 Z-60 P2.4 Q0.7 F4 J1"), None); // A exactly at B is allowed
    assert_eq!(g76("X33.8 Z-60 P2.4 Q0.7 F4 J1 K69.999"), None);
    assert_eq!(g76("X33.8 Z-60 P2.4 Q0.7 F4 J1 K70"), alarm(AlarmCode::Geometry, Some(b'K'), Rule::G76Pullout, 3));
    // Config first, on line 0.
    let bad = Config { start_z: 1_000_000_000, ..Config::default() };
    assert_eq!(expand("G0 X1\n#", bad).alarm, alarm(AlarmCode::OutOfRange, Some(b'Z'), Rule::ComRanges, 0));
    let bad = Config { params: Params { p5131_chamfer_angle: Some(0), ..Params::default() }, ..Config::default() };
    assert_eq!(expand("", bad).alarm, alarm(AlarmCode::OutOfRange, None, Rule::G76Pullout, 0));
    let bad = Config { dialect: Dialect::Fanuc, params: Params { p5143_tool_angle: Some(45), ..Params::default() }, ..Config::default() };
    assert_eq!(expand("", bad).alarm, alarm(AlarmCode::OutOfRange, None, Rule::F76Format, 0));
    // No.107 ≠ 0 refused when a G92 cycle runs.
    let n107 = Config { params: Params { no107_pullout_speed: Some(5), ..Params::default() }, ..Config::default() };
    assert_eq!(expand("G0 X35 Z5\nG92 F3\nG92 X29 Z-20", n107).alarm, alarm(AlarmCode::Unsupported, None, Rule::G92Jk8, 3));
}

/// PRJ.NOOP, M30, streaming after an alarm.
#[test]
fn stream_rules() {
    let c = Config::default();
    assert!(expand("G0 X0 Z0\nG1 X0 F1\n", c).events.is_empty());
    let t = expand("G0 X1\nM30\n#\n", c);
    assert_eq!((t.events.len(), t.alarm), (1, None));
    let t = expand("G0 X1 M02 (end)\nG0 X2\n", c);
    assert_eq!(moves(&t), [Move::rapid(1_000, 0, Rule::PrjModal)]);
    let mut e = Expander::new(b"G0 X1\nG0 X2 #\nG0 X3\n", c);
    assert!(matches!(e.next(), Some(Ok(_))));
    assert_eq!(e.next(), Some(Err(Alarm::new(AlarmCode::BadCharacter, Some(b'#'), Rule::PrjLex, 2))));
    assert_eq!(e.next(), None);
    assert_eq!(e.next(), None);
    // G01 carries the modal feed (from a G92 I lead, too).
    let t = expand("G92 F2\nG1 X5 Z-1\n", c);
    assert_eq!(moves(&t), [Move::feed(5_000, -1_000, 20_000, Rule::PrjModal)]);
}

/// A fixed-seed xorshift generator for the random drivers (here and in the
/// modules' tests).
pub fn xorshift(state: &mut u64) -> u64 {
    *state ^= *state << 13;
    *state ^= *state >> 7;
    *state ^= *state << 17;
    *state
}

/// The grid of round `round` of a random driver: every units/increment pair in turn.
pub fn grid_of_round(round: u32) -> Grid {
    Grid {
        units: if round.is_multiple_of(2) { Units::Metric } else { Units::Inch },
        increment: if round % 4 < 2 { Increment::Isb } else { Increment::Isc },
    }
}

/// No input panics: random bytes, random word soups, random and extreme configurations.
#[test]
fn no_panic_on_random_input() {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    let extremes = [0i64, 1, -1, 999_999_999, -999_999_999, 1_000_000_000, i64::MAX, i64::MIN];
    let alphabet = b"GXZUWRPQFIJKLDEMNOST0123456789.-  ;\n(";
    for round in 0..20_000u32 {
        let mut params = Params::default();
        if round % 3 == 0 {
            let r = xorshift(&mut s);
            params.no19_pullout = Some((r % 300) as i64);
            params.p5130_chamfer = Some(((r >> 9) as u32 % 120) as i64);
            params.p5131_chamfer_angle = Some(((r >> 17) as u32 % 95) as i64);
            params.p5140_min_cut = Some(extremes[(r >> 24) as usize % extremes.len()]);
            params.p5141_finish_allowance = Some(extremes[(r >> 28) as usize % extremes.len()]);
            params.p5142_finish_passes = Some(((r >> 32) as u32 % 120) as i64);
            params.p5143_tool_angle = Some(((r >> 40) as u32 % 110) as i64);
            params.max_passes = Some(([0, 1, 50, 10_000, u32::MAX][(r >> 48) as usize % 5]) as i64);
        }
        let r = xorshift(&mut s);
        let cfg = Config {
            dialect: if r & 1 == 0 { Dialect::Gsk } else { Dialect::Fanuc },
            grid: Grid {
                units: if r & 2 == 0 { Units::Metric } else { Units::Inch },
                increment: if r & 4 == 0 { Increment::Isb } else { Increment::Isc },
            },
            params,
            start_x: if r & 8 == 0 { 0 } else { extremes[(r >> 8) as usize % extremes.len()] },
            start_z: if r & 16 == 0 { 0 } else { extremes[(r >> 16) as usize % extremes.len()] },
            operator: cycle_vocab::Script::EMPTY,
            readings: cycle_vocab::Readings::default(),
        };
        let mut buf = [0u8; 96];
        let soup = round % 2 == 0;
        for b in buf.iter_mut() {
            let v = xorshift(&mut s);
            *b = if soup { alphabet[(v % alphabet.len() as u64) as usize] } else { (v >> 32) as u8 };
        }
        let mut n = 0;
        for _ in Expander::new(&buf, cfg) {
            n += 1;
            if n > 200_000 {
                break;
            }
        }
    }
}

/// Legal cycles with random extreme words never panic and end where they started.
#[test]
fn no_panic_on_extreme_cycles() {
    let mut s = 0x1234_5678_9abc_def1u64;
    let vals = ["0", "0.001", "1", "-1", "999999.999", "-999999.999", "0.5", "2.4", "99999.999", "-50"];
    let leads = ["1", "9999", "0.0001", "4"];
    for _ in 0..3_000 {
        let mut r = || xorshift(&mut s);
        let mut w: Vec<String> = Vec::new();
        for _ in 0..16 {
            w.push(String::from(vals[(r() % vals.len() as u64) as usize]));
        }
        let u = |i: usize| w[i].trim_start_matches('-');
        let (p, l, f1, f2) = (10_000 + r() % 990_000, 1 + r() % 3, leads[(r() % 4) as usize], leads[(r() % 4) as usize]);
        let src = std::format!(
            "G0 X{} Z{}\nG76 P{p:06} Q{} R{} L{l}\nG76 X{} Z{} R{} P{} Q{} F{f1} J{} K{}\nG92 X{} Z{} R{} F{f2} J{} K{}\nX{}\n",
            w[0], w[1], u(2), u(3), w[4], w[5], w[6], u(7), u(8), u(9), u(10), w[11], w[12], w[13], w[14], w[15], w[0],
        );
        let cfg = Config { params: Params { max_passes: Some(2_000), ..Params::default() }, ..Config::default() };
        let t = expand(&src, cfg);
        // With no alarm the cycles returned to the start point.
        if t.alarm.is_none() {
            // The start point: the first rapid of line 1, or X0 Z0 when it moved nothing.
            let start = match t.moves().next() {
                Some(m) if m.rule == Rule::PrjModal => (m.x, m.z),
                _ => (0, 0),
            };
            if let Some(last) = t.moves().last() {
                assert_eq!(start, (last.x, last.z), "{src}");
            }
        }
    }
}

/// Both ways of taking the stream: `fill` equals the iterator for every buffer size, on the
/// seed's examples, the bound cases and alarms inside contours.
pub fn assert_fill_agrees(program: &str, config: Config, sizes: &[usize]) {
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

/// A G73 case from A = X50 Z10 (g73.c = visit) over a contour with a rapid, an arc and two
/// feeds: the contour, A and the words (the cycle-fill tests of `tests::cycle_fill` and `g73`).
pub fn g73_case() -> (crate::contour::Contour, (i64, i64), crate::g73::Words) {
    use crate::contour::{Contour, Element, Kind};
    let mut contour = Contour::new();
    let e = Element::ZERO;
    for el in [
        Element { x: 0, z: 1_000, kind: Kind::Rapid, ..e },
        Element { x: 12_000, z: -5_000, cx: 0, cz: -5_000, kind: Kind::Arc(false), ..e },
        Element { x: 12_000, z: -15_000, kind: Kind::Feed, ..e },
        Element { x: 20_000, z: -30_000, kind: Kind::Feed, ..e },
    ] {
        assert!(contour.push(el));
    }
    let w = crate::g73::Words { di: 18_000, dk: 5_000, d: 4, allowance: (500, 500), feed: 1_000, count_word: b'R', visit_c: true };
    (contour, (50_000, 10_000), w)
}

/// One cycle's own `fill` against its `next_event`, from position `at`, for every buffer size:
/// the same events, and every call with room writes at least one event until it says done. (The
/// stream takes a cycle's events one at a time when its `fill` writes none, so a `fill` that
/// never writes cannot be seen in the expander's trace; this sees it.)
pub fn assert_cycle_fill<C: Clone>(
    cycle: &C,
    at: (i64, i64),
    mut next: impl FnMut(&mut C, &mut (i64, i64)) -> Option<Event>,
    mut fill: impl FnMut(&mut C, &mut (i64, i64), &mut [Event]) -> (usize, bool),
    sizes: &[usize],
) {
    let (mut c, mut pos, mut want) = (cycle.clone(), at, Vec::new());
    while let Some(e) = next(&mut c, &mut pos) {
        want.push(e);
    }
    let want_end = pos;
    for &size in sizes {
        let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
        let mut buffer = std::vec![filler; size];
        let (mut c, mut pos, mut got) = (cycle.clone(), at, Vec::new());
        loop {
            let (n, done) = fill(&mut c, &mut pos, &mut buffer);
            assert!(n > 0 || done, "buffer of {size}: nothing written, not done");
            got.extend_from_slice(&buffer[..n]);
            if done {
                break;
            }
        }
        assert_eq!((got.as_slice(), pos), (want.as_slice(), want_end), "buffer of {size}");
    }
}
