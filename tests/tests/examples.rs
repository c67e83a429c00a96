//! The manuals' examples and one program per feature (`cycle_kernel::corpus`), expanded by the
//! reference spec under each program's configuration (dialect, units, declared readings,
//! parameters) and snapshotted as canonical G-code (insta) in the folder of the family each runs
//! (`snapshots/<family>/`, `cycle_kernel::registry::cycle_run`); apart from that, the production
//! expander is checked against the spec by the conformance relation on each. Rule IDs:
//! G92.EXAMPLE, G76.EXAMPLE, G78.EXAMPLE, F76.EX1, F76.EX2, F76.MICRONS, COM.MULTISTART,
//! G76.MODE, G78.MODE, G78.DEPTHMODE, COM.UNITS, G162.* (G162.SPLIT: the manual's P2.5 Q1
//! sequence), G32, G33, G34, G71.EXAMPLE, G72.EXAMPLE (and G70.PATH, G70.RETURN).

use cycle_kernel::{conformance, corpus, registry, spec_alone};
use cycle_vocab::text::Trace;
use cycle_vocab::{AlarmCode, Config, Dialect, Event, MoveKind, PassKind, Rule};

fn gsk() -> Config {
    Config::default()
}

fn fanuc() -> Config {
    Config { dialect: Dialect::Fanuc, ..Config::default() }
}

/// Expands with both engines, requires them to conform, and returns the spec's trace (under
/// `CYCLECHECK_SPEC_ALONE=1` the spec's trace only: `cycle_kernel::spec_alone`).
fn expand_both(name: &str, program: &str, config: Config) -> Trace {
    let spec = cycle_spec::expand(program.as_bytes(), &config);
    if spec_alone::skip(&format!("{name}: the conformance of the production expander")) {
        return spec;
    }
    let imp = Trace::collect(config.grid, cycle_impl::Expander::new(program.as_bytes(), config));
    if let Err(d) = conformance::check(&spec, &imp) {
        panic!("{name}: the production expander diverges from the spec\n{d}");
    }
    spec
}

/// Every built-in program matches its snapshot, `snapshots/<family>/examples__<name>.snap` — the
/// spec's trace, whatever the production expander does (that is the next test); every program is
/// checked before the test fails, naming those that differ.
#[test]
fn every_program_matches_its_snapshot() {
    let mut differ = Vec::new();
    for p in corpus::PROGRAMS {
        let trace = cycle_spec::expand(p.text.as_bytes(), &p.config());
        let folder = registry::cycle_run(p.text.as_bytes(), &p.config(), Some(&trace)).name();
        let checked = std::panic::catch_unwind(|| {
            insta::with_settings!({ snapshot_path => format!("snapshots/{folder}"), description => p.text, omit_expression => true }, {
                insta::assert_snapshot!(p.name, trace.to_gcode());
            });
        });
        if checked.is_err() {
            differ.push(format!("{folder}/{}", p.name));
        }
    }
    assert!(differ.is_empty(), "snapshots missing or changed: {differ:?}");
}

/// The production expander conforms to the spec on every built-in program; every program is
/// checked before the test fails, naming those that diverge.
#[test]
fn every_program_conforms() {
    if spec_alone::skip("every_program_conforms") {
        return;
    }
    let diverge: Vec<&str> = corpus::PROGRAMS
        .iter()
        .filter(|p| std::panic::catch_unwind(|| expand_both(p.name, p.text, p.config())).is_err())
        .map(|p| p.name)
        .collect();
    assert!(diverge.is_empty(), "the production expander diverges on: {diverge:?}");
}

/// Thread cuts (the first synchronized move after each pass header): (X, Z) of its end.
fn cuts(trace: &Trace) -> Vec<(PassKind, i64, i64)> {
    let mut out = Vec::new();
    let mut kind = None;
    for e in &trace.events {
        match e {
            Event::Pass(p) => kind = Some(p.kind),
            Event::Move(m) if m.kind == MoveKind::Thread => {
                if let Some(k) = kind.take() {
                    out.push((k, m.x, m.z));
                }
            }
            Event::Move(_) | Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => {}
        }
    }
    out
}

fn pass_depths(trace: &Trace) -> Vec<(PassKind, i64)> {
    trace
        .events
        .iter()
        .filter_map(|e| match e {
            Event::Pass(p) => Some((p.kind, p.diameter_depth)),
            Event::Move(_) | Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => None,
        })
        .collect()
}

/// G92.EXAMPLE: four cycles at X58.7, X57.7, X57, X56.9 to Z-28 with the J3 K1 pull-out
/// (G92.PATH, G92.PULLOUT, G92.MODAL), ending where they started.
#[test]
fn g92_example_cuts_four_cycles_with_pullout() {
    let trace = expand_both("g92", include_str!("../../corpus/g92_example.nc"), gsk());
    assert_eq!(trace.alarm, None);
    let threads: Vec<(i64, i64)> =
        trace.moves().filter(|m| m.kind == MoveKind::Thread).map(|m| (m.x, m.z)).collect();
    let mut expect = Vec::new();
    for x in [58_700, 57_700, 57_000, 56_900] {
        expect.push((x, -27_000)); // thread to K = 1 before the end
        expect.push((x + 6_000, -28_000)); // pull-out J = 3 (radius) at the end Z
    }
    assert_eq!(threads, expect);
    assert!(trace.moves().filter(|m| m.kind == MoveKind::Thread).all(|m| m.feed == 30_000));
    let last = trace.moves().last().unwrap();
    assert_eq!((last.x, last.z), (65_000, 5_000));
}

/// F76.EX1: rough depths 0.7·√n for n = 1…10, then k − d = 2.3, then one finishing pass at
/// 2.4: twelve passes (G76.DEPTH.1, G76.DEPTH.LAST, G76.FINISH).
#[test]
fn f76_ex1_twelve_passes() {
    for (program, config) in [
        (include_str!("../../corpus/f76_ex1.nc"), gsk()),
        (include_str!("../../corpus/f76_ex1_microns.nc"), fanuc()),
    ] {
        let trace = expand_both("f76_ex1", program, config);
        let rough: Vec<i64> = [700, 990, 1212, 1400, 1565, 1715, 1852, 1980, 2100, 2214, 2300]
            .iter()
            .map(|r| 2 * r)
            .collect();
        let mut expect: Vec<(PassKind, i64)> = rough.into_iter().map(|d| (PassKind::Rough, d)).collect();
        expect.push((PassKind::Finish, 4800));
        assert_eq!(pass_depths(&trace), expect);
        // Infeed X of the finishing pass is the minor diameter X33.8.
        assert_eq!(cuts(&trace).last().map(|c| c.1), Some(33_800));
    }
}

/// G76.REQUIRED: a second block without P(k) or Q(Δd) is an alarm naming the word.
#[test]
fn g76_without_k_or_delta_alarms() {
    for (program, word) in [
        ("G00 X80 Z10\nG76 P020545 Q0.15 R0.5\nG76 X60 Z-60 Q1.8 F3\n", b'P'),
        ("G00 X80 Z10\nG76 P020545 Q0.15 R0.5\nG76 X60 Z-60 P3 F3\n", b'Q'),
    ] {
        let trace = expand_both("required", program, gsk());
        let alarm = trace.alarm.expect("alarm");
        assert_eq!((alarm.code, alarm.word, alarm.rule, alarm.line), (AlarmCode::MissingWord, Some(word), Rule::G76Required, 3));
    }
}

/// G78.EXAMPLE as printed has infeed mode 05: out of range (interpretation register).
#[test]
fn g78_example_mode_05_is_out_of_range() {
    let trace = expand_both("g78", include_str!("../../corpus/g78_example.nc"), gsk());
    let alarm = trace.alarm.expect("alarm");
    assert_eq!((alarm.code, alarm.word, alarm.rule, alarm.line), (AlarmCode::OutOfRange, Some(b'P'), Rule::G78Mode, 3));
}

/// G71.EXAMPLE: nine layers X37 … X5 (G71.LAYER), the semi-finish pass along the contour shifted
/// by U0.5 W0.2 (G71.LASTPASS), the return to X41 Z0 (G71.RETURN); then G70 along the contour
/// itself (G70.PATH) and back (G70.RETURN) — the moves the register lists for example 1. G71.UW:
/// the first block's U2 is the depth (layers 4 mm apart on the diameter), the second block's U0.5
/// the allowance (the SEMI pass starts at X0.5 Z0.2).
#[test]
fn g71_example_nine_layers_semi_finish_and_g70() {
    let trace = expand_both("g71", include_str!("../../corpus/g71_example.nc"), gsk());
    assert_eq!(trace.alarm, None);
    let passes: Vec<(PassKind, u32)> =
        trace.events.iter().filter_map(|e| if let Event::Pass(p) = e { Some((p.kind, p.index)) } else { None }).collect();
    let mut want: Vec<(PassKind, u32)> = (1..=9).map(|k| (PassKind::Rough, k)).collect();
    want.extend([(PassKind::Semi, 10), (PassKind::Finish, 1)]);
    assert_eq!(passes, want);
    let layers: Vec<i64> = trace.moves().filter(|m| m.rule == Rule::G71Layer && m.z == 0).map(|m| m.x).collect();
    assert_eq!(layers, (0..9).map(|k| 37_000 - 4_000 * k).collect::<Vec<_>>());
    let semi = trace.moves().find(|m| m.rule == Rule::G71Lastpass).map(|m| (m.x, m.z));
    assert_eq!(semi, Some((500, 200)));
    let g70: Vec<(i64, i64)> = trace.moves().filter(|m| matches!(m.rule, Rule::G70Path | Rule::G70Return)).map(|m| (m.x, m.z)).collect();
    assert_eq!(
        g70,
        [(0, 0), (11_000, -5_500), (11_000, -15_500), (17_000, -25_500), (17_000, -40_500), (29_000, -47_848), (29_000, -60_500), (41_000, -60_500), (41_000, 0)]
    );
}

/// G72.EXAMPLE: 31 layers at Z0, −1, …, −30 (G72.LAYER), the semi-finish pass, the return to
/// X41 Z1 (G72.RETURN), then G70.
#[test]
fn g72_example_thirty_one_layers() {
    let trace = expand_both("g72", include_str!("../../corpus/g72_example.nc"), gsk());
    assert_eq!(trace.alarm, None);
    let layers: Vec<i64> = trace.moves().filter(|m| m.rule == Rule::G72Layer && m.x == 41_000).map(|m| m.z).collect();
    assert_eq!(layers, (0..31).map(|k| -1_000 * k).collect::<Vec<_>>());
    let last = trace.moves().find(|m| m.rule == Rule::G72Return).map(|m| (m.x, m.z));
    assert_eq!(last, Some((41_000, 1_000)));
    assert_eq!(trace.moves().last().map(|m| (m.x, m.z, m.rule)), Some((41_000, 1_000, Rule::G70Return)));
}
