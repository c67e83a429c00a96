//! Operator events on the manuals' programs (issue #22; register "Operator events"), each run by
//! both engines, required to conform, and snapshotted as canonical G-code in
//! `snapshots/operator/`. The holds are placed by searching the uninterrupted trace U (the first
//! thread move of a pass, a rapid, …), so a snapshot names the script it ran. Rule IDs:
//! G92.HOLD, G92.SINGLE, G92.RESET, G76.HOLD, G76.SINGLE, G162.NOSTOP, OP.HOLD, OP.RESUME,
//! OP.RESET, OP.SINGLE, OP.SCOPE, OP.AT, OP.REACH, OP.SCRIPT.

use cycle_kernel::{conformance, spec_alone};
use cycle_kernel::operator::{parse_script, script_args};
use cycle_vocab::text::Trace;
use cycle_vocab::{AlarmCode, Config, Dialect, Event, MoveKind, Rule};

/// The program: `G0 X65 Z5; G92 X58.7 Z-28 F3 J3 K1;`.
const G92: &str = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nM30\n";

fn program(path: &str) -> String {
    std::fs::read_to_string(format!("{}/../{path}", env!("CARGO_MANIFEST_DIR"))).unwrap()
}

/// U's event indices: the `n`-th (0-based) move of `kind` (and, for thread moves, not a
/// pull-out when `main`).
fn nth_move(u: &Trace, kind: MoveKind, n: usize) -> usize {
    u.events
        .iter()
        .enumerate()
        .filter(|(_, e)| matches!(e, Event::Move(m) if m.kind == kind))
        .nth(n)
        .map(|(i, _)| i)
        .unwrap_or_else(|| panic!("no move {n} of {kind:?} in\n{}", u.to_gcode()))
}

/// Runs `text` under `config` with the script `ops` (its `{…}` placeholders already filled),
/// checks both engines conform (unless `CYCLECHECK_SPEC_ALONE=1`) and snapshots the spec's trace as `name`.
fn run(name: &str, text: &str, config: Config, ops: &[String]) -> Trace {
    let config = Config { operator: parse_script(ops).unwrap(), ..config };
    let spec = cycle_spec::expand(text.as_bytes(), &config);
    if !spec_alone::skip(&format!("{name}: the conformance of the production expander")) {
        let imp = Trace::collect(config.grid, cycle_impl::Expander::new(text.as_bytes(), config));
        if let Err(d) = conformance::check(&spec, &imp) {
            panic!("{name}: the production expander diverges from the spec\n{d}");
        }
    }
    let description = format!("{text}\nscript:{}\nNo.0018 bit 6 = {}", script_args(&config.operator), config.params.no18_bit6_hold.unwrap_or(0));
    insta::with_settings!({ snapshot_path => "snapshots/operator", description => description, omit_expression => true }, {
        insta::assert_snapshot!(name, spec.to_gcode());
    });
    spec
}

fn bit6(v: i64) -> Config {
    let mut c = Config::default();
    c.params.no18_bit6_hold = Some(v);
    c
}

fn u(text: &str, config: Config) -> Trace {
    cycle_spec::expand(text.as_bytes(), &config)
}

fn count(t: &Trace, f: impl Fn(&Event) -> bool) -> usize {
    t.events.iter().filter(|e| f(e)).count()
}

/// The "done when": a hold halfway along the thread cut of `G92 X58.7 Z-28 F3 J3 K1`.
#[test]
fn g92_hold_halfway_both_ways() {
    let e = nth_move(&u(G92, bit6(0)), MoveKind::Thread, 0);
    let ops = [format!("hold:{e}@1/2"), "start".into()];
    let back = run("g92_hold_bit6_0", G92, bit6(0), &ops);
    let on = run("g92_hold_bit6_1", G92, bit6(1), &ops);
    let lines = |t: &Trace| t.to_gcode().lines().map(str::to_string).collect::<Vec<_>>();
    let b = lines(&back);
    let i = b.iter().position(|l| l.starts_with("(PRESS HOLD")).unwrap();
    assert_eq!(b[i], "(PRESS HOLD AT X58.700 Z-11.000)");
    assert_eq!(&b[i + 1..i + 7], ["G32 X58.700 Z-11.000 F3.0000", "G32 X64.700 Z-12.000 F3.0000", "G00 X65.000 Z-12.000", "G00 X65.000 Z5.000", "(STOP FEED HOLD)", "(CYCLE START)"]);
    let o = lines(&on);
    let i = o.iter().position(|l| l.starts_with("(PRESS HOLD")).unwrap();
    assert_eq!(&o[i + 1..], ["G32 X58.700 Z-27.000 F3.0000", "G32 X64.700 Z-28.000 F3.0000", "(STOP FEED HOLD)", "(CYCLE START)", "G00 X65.000 Z-28.000", "G00 X65.000 Z5.000"]);
}

#[test]
fn g92_hold_without_cycle_start_ends_at_the_stop() {
    let e = nth_move(&u(G92, bit6(0)), MoveKind::Thread, 0);
    let t = run("g92_hold_no_start", G92, bit6(0), &[format!("hold:{e}@3/4")]);
    assert!(matches!(t.events.last(), Some(Event::Stop(_))) && t.alarm.is_none());
}

#[test]
fn g92_hold_on_the_pullout_and_on_a_rapid() {
    let u0 = u(G92, bit6(0));
    let (pull, rapid) = (nth_move(&u0, MoveKind::Thread, 1), nth_move(&u0, MoveKind::Rapid, 2));
    run("g92_hold_pullout", G92, bit6(0), &[format!("hold:{pull}@1/3"), "start".into()]);
    let t = run("g92_hold_rapid", G92, bit6(0), &[format!("hold:{rapid}@1/2"), "start".into()]);
    assert!(t.events.iter().any(|e| e.rule() == Rule::OpHold));
}

#[test]
fn g92_single_block_stops_after_each_cycle_of_the_modal_run() {
    let t = run("g92_example_single_block", &program("corpus/g92_example.nc"), bit6(0), &["single:on@0".into()]);
    assert_eq!(count(&t, |e| matches!(e, Event::Stop(s) if s.rule == Rule::G92Single)), 4, "one stop per cycle");
}

#[test]
fn g92_reset_in_the_thread() {
    let e = nth_move(&u(G92, bit6(0)), MoveKind::Thread, 0);
    let t = run("g92_reset", G92, bit6(0), &[format!("reset:{e}@0.25")]);
    assert!(matches!(t.events.last(), Some(Event::Move(m)) if m.z == -3_000));
}

#[test]
fn g76_multistart_hold_repeats_the_cut() {
    let text = program("tests/programs/g76_multistart.nc");
    let e = nth_move(&u(&text, bit6(0)), MoveKind::Thread, 4);
    let t = run("g76_multistart_hold", &text, bit6(0), &[format!("hold:{e}@1/2"), "start".into()]);
    assert!(t.events.iter().any(|e| e.rule() == Rule::G76Hold));
    run("g76_multistart_single_block", &text, bit6(0), &["single:on@0".into()]);
}

#[test]
fn g78_hold_finishes_the_segment() {
    let text = program("tests/programs/g78_mode3.nc");
    let e = nth_move(&u(&text, bit6(1)), MoveKind::Thread, 2);
    run("g78_hold_bit6_1", &text, bit6(1), &[format!("hold:{e}@0.5"), "start".into()]);
}

#[test]
fn g162_hold_is_deferred_to_the_end_of_segment_3() {
    let text = program("corpus/g162_cone.nc");
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    let e = nth_move(&u(&text, nc201), MoveKind::Thread, 1);
    let t = run("g162_cone_hold", &text, nc201, &[format!("hold:{e}@1/2"), "start".into()]);
    assert!(t.events.iter().any(|e| matches!(e, Event::Stop(s) if s.rule == Rule::G162NoStop)));
    run("g162_cone_single_block", &text, nc201, &["single:on@0".into()]);
}

#[test]
fn operator_alarms() {
    let g90 = program("corpus/g90_example.nc");
    let e = nth_move(&u(&g90, Config::default()), MoveKind::Feed, 0);
    let t = run("g90_hold_out_of_scope", &g90, Config::default(), &[format!("hold:{e}@1/2")]);
    assert_eq!(t.alarm.map(|a| (a.code, a.rule)), Some((AlarmCode::Operator, Rule::OpScope)));
    let t = run("g92_hold_on_a_header", G92, bit6(0), &["hold:1@1/2".into()]);
    assert_eq!(t.alarm.map(|a| (a.code, a.rule)), Some((AlarmCode::Operator, Rule::OpAt)));
    let t = run("g92_hold_never_reached", G92, bit6(0), &["hold:99@1/2".into()]);
    assert_eq!(t.alarm.map(|a| (a.code, a.rule, a.line)), Some((AlarmCode::Operator, Rule::OpReach, 0)));
}
