//! Properties of operator events (issue #22; register "Operator events"), on both engines, for
//! feed holds placed on the thread cuts of generated G92, G76, G78 and FANUC G76 cases:
//!
//! - G92.HOLD / G76.HOLD, No.0018 bit 6 = 0: the retract in the pull-out manner never goes deeper
//!   than the thread (it ends on the side of the cut, through the hold point, that the programmed
//!   pull-out goes to), the retract ends at the start point A, then the stop; after cycle start the run ends **exactly** as the
//!   uninterrupted trace U, from a cut's first event (a pass header or the rapid leaving A).
//! - bit 6 = 1: U's events run on unchanged to the cut's last thread move, then the stop; after
//!   cycle start the rest is U's rest.
//! - OP.RESET: the trace ends at the point pressed, without an alarm.
//! - OP.SINGLE / G92.SINGLE / G76.SINGLE: without its stop/resume pairs the trace is U.

use cycle_kernel::gen;
use cycle_vocab::text::Trace;
use cycle_vocab::{Action, Along, Config, Event, Move, MoveKind, Rule, Script, StopReason};
use proptest::prelude::*;

/// Each engine's interrupted trace and its own uninterrupted trace U (rule tags are each
/// engine's own: the events are compared whole against the same engine's U).
fn engines(program: &[u8], config: &Config) -> [(&'static str, Trace, Trace); 2] {
    let plain = Config { operator: Script::EMPTY, ..*config };
    let run = |c: &Config| Trace::collect(c.grid, cycle_impl::Expander::new(program, *c));
    [("spec", cycle_spec::expand(program, config), cycle_spec::expand(program, &plain)), ("impl", run(config), run(&plain))]
}

fn is_pullout(rule: Rule) -> bool {
    use Rule::*;
    matches!(rule, G92Pullout | G92Jk1 | G92Jk2 | G92Jk3 | G92Jk4 | G92Jk5 | G92Jk6 | G92Jk7 | G76Pullout | G78Pullout)
}

/// A thread family's case and a main cut of its U (a thread move with Z travel that is not a
/// pull-out): (case, U, index, the cut's start, the start point A of its cycle).
fn held_case(knobs: &[u32], pick: u32) -> Option<(gen::Case, Trace, usize, (i64, i64))> {
    let families = ["g92", "g76", "g78", "f76"];
    let family = cycle_kernel::registry::find(families[pick as usize % families.len()])?;
    let case = gen::build(family.build, knobs);
    let u = cycle_spec::expand(&case.program, &case.config);
    let mut at = (case.config.start_x, case.config.start_z);
    let mut cuts = Vec::new();
    for (i, e) in u.events.iter().enumerate() {
        if let Event::Move(m) = e {
            if m.kind == MoveKind::Thread && m.z != at.1 && !is_pullout(m.rule) {
                cuts.push((i, at));
            }
            at = (m.x, m.z);
        }
    }
    let (i, from) = *cuts.get((pick / 4) as usize % cuts.len().max(1))?;
    Some((case, u, i, from))
}

/// The sign of the cross product of the cut's direction with q − p (X on diameter, exact).
fn side(dir: (i64, i64), p: (i64, i64), q: (i64, i64)) -> i32 {
    let c = i128::from(dir.1) * i128::from(q.0 - p.0) - i128::from(dir.0) * i128::from(q.1 - p.1);
    c.signum() as i32
}

fn script(actions: &[Action]) -> Script {
    Script::of(actions).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 160, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn a_hold_pulls_out_returns_and_resumes_as_uninterrupted(knobs in gen::knobs(), pick in any::<u32>(), num in 0u32..=1000, finish in any::<bool>()) {
        let Some((mut case, u, e, from)) = held_case(&knobs, pick) else { return Ok(()) };
        prop_assume!(u.alarm.is_none());
        case.config.params.no18_bit6_hold = Some(i64::from(finish));
        case.config.operator = script(&[Action::Hold(Along { event: e as u32, num, den: 1000 }), Action::Start]);
        let Event::Move(cut) = u.events[e] else { unreachable!() };
        let dir = (cut.x - from.0, cut.z - from.1);
        for (engine, t, u) in engines(&case.program, &case.config) {
            let ctx = format!("{engine}: {case:?}\n{}", t.to_gcode());
            prop_assert_eq!(t.alarm, u.alarm, "{}", ctx);
            prop_assert_eq!(&t.events[..e], &u.events[..e], "before the hold: U. {}", ctx);
            let Event::Press(p) = t.events[e] else { return Err(TestCaseError::fail(format!("no press at {e}: {ctx}"))) };
            let stop = t.events.iter().position(|ev| matches!(ev, Event::Stop(s) if s.reason == StopReason::FeedHold));
            let Some(stop) = stop else { return Err(TestCaseError::fail(format!("no stop: {ctx}"))) };
            prop_assert!(matches!(t.events.get(stop + 1), Some(Event::Resume(_))), "cycle start after the stop: {}", ctx);
            let rest = &t.events[stop + 2..];
            prop_assert!(rest.len() <= u.events.len(), "{}", ctx);
            prop_assert_eq!(rest, &u.events[u.events.len() - rest.len()..], "after cycle start the run ends as U: {}", ctx);
            let moves: Vec<Move> = t.events[e + 1..stop].iter().filter_map(|ev| if let Event::Move(m) = ev { Some(*m) } else { None }).collect();
            if finish {
                // bit 6 = 1: U unchanged up to the cut's last thread move.
                prop_assert_eq!(&t.events[e + 1..stop], &u.events[e..e + stop - e - 1], "{}", ctx);
                prop_assert_eq!(moves.last().map(|m| m.kind), Some(MoveKind::Thread), "the stop follows a thread move: {}", ctx);
            } else {
                let a = start_point(&u, e, (case.config.start_x, case.config.start_z));
                // The retract in the pull-out manner (a thread move tagged G92.HOLD/G76.HOLD)
                // ends on the side of the cut the programmed pull-out goes to.
                if let Some(Event::Move(pullout)) = u.events.get(e + 1).filter(|n| matches!(n, Event::Move(m) if is_pullout(m.rule))) {
                    let outward = side(dir, from, (pullout.x, pullout.z));
                    for m in moves.iter().filter(|m| m.kind == MoveKind::Thread && matches!(m.rule, Rule::G92Hold | Rule::G76Hold)) {
                        let s = side(dir, (p.x, p.z), (m.x, m.z));
                        prop_assert!(s == 0 || s == outward, "the retract to X{} Z{} goes deeper than the thread: {}", m.x, m.z, ctx);
                    }
                }
                let last = moves.last().copied();
                prop_assert_eq!(last.map(|m| (m.x, m.z)), Some(a), "the retract ends at the start point: {}", ctx);
                let first_of_rest = &u.events[u.events.len() - rest.len()];
                prop_assert!(matches!(first_of_rest, Event::Pass(_)) || matches!(first_of_rest, Event::Move(m) if m.kind == MoveKind::Rapid), "the cut repeats from its first event: {}", ctx);
            }
        }
    }

    #[test]
    fn a_reset_ends_the_run_where_it_was_pressed(knobs in gen::knobs(), pick in any::<u32>(), num in 0u32..=7) {
        let Some((mut case, u, e, _)) = held_case(&knobs, pick) else { return Ok(()) };
        prop_assume!(u.alarm.is_none());
        case.config.operator = script(&[Action::Reset(Along { event: e as u32, num, den: 7 })]);
        for (engine, t, _) in engines(&case.program, &case.config) {
            let ctx = format!("{engine}: {case:?}\n{}", t.to_gcode());
            prop_assert_eq!(t.alarm, None, "{}", ctx);
            let Some(Event::Press(p)) = t.events.get(e) else { return Err(TestCaseError::fail(format!("no press at {e}: {ctx}"))) };
            prop_assert!(t.events.len() <= e + 2, "nothing after the reset: {}", ctx);
            if let Some(Event::Move(m)) = t.events.get(e + 1) {
                prop_assert_eq!((m.x, m.z), (p.x, p.z), "the move ends at the point: {}", ctx);
            }
        }
    }

    #[test]
    fn single_block_only_adds_stops_and_starts(knobs in gen::knobs(), pick in any::<u32>()) {
        let Some((mut case, _, _, _)) = held_case(&knobs, pick) else { return Ok(()) };
        case.config.operator = script(&[Action::SingleBlock { on: true, before: 0 }]);
        for (engine, t, u) in engines(&case.program, &case.config) {
            let ctx = format!("{engine}: {case:?}\n{}", t.to_gcode());
            let stops = t.events.iter().filter(|e| matches!(e, Event::Stop(s) if s.reason == StopReason::SingleBlock)).count();
            prop_assert!(stops > 0 || u.alarm.is_some(), "single block stops somewhere: {}", ctx);
            let plain: Vec<Event> = t.events.iter().filter(|e| !matches!(e, Event::Stop(_) | Event::Resume(_))).copied().collect();
            prop_assert_eq!(&plain, &u.events, "{}", ctx);
            prop_assert_eq!(t.alarm, u.alarm, "{}", ctx);
        }
    }
}

/// A, the start point of the cycle of U's event `e`: where the tool was before the cycle's first
/// pass header at or before `e` (the rapids of a cut return there).
fn start_point(u: &Trace, e: usize, program_start: (i64, i64)) -> (i64, i64) {
    let mut at = program_start;
    let mut a = program_start;
    for ev in &u.events[..e] {
        match ev {
            Event::Pass(p) if p.index == 1 => a = at,
            Event::Move(m) => at = (m.x, m.z),
            _ => {}
        }
    }
    a
}

/// The generator places legal scripts: each hold or reset on a move of U.
#[test]
fn the_operator_generator_places_holds_on_moves() {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let families: Vec<_> = cycle_kernel::registry::FAMILIES.iter().collect();
    let strategy = gen::operator::strategy(families);
    let (mut scripted, mut on_moves, mut elsewhere) = (0, 0, 0);
    for _ in 0..200 {
        let case = strategy.new_tree(&mut runner).unwrap().current();
        let u = cycle_spec::expand(&case.program, &Config { operator: Script::EMPTY, ..case.config });
        for a in case.config.operator.actions() {
            if let Action::Hold(at) | Action::Reset(at) = a {
                assert!(at.is_legal(), "{case:?}");
                match u.events.get(at.event as usize) {
                    Some(Event::Move(_)) => on_moves += 1,
                    _ => elsewhere += 1,
                }
            }
        }
        scripted += usize::from(!case.config.operator.is_empty());
    }
    assert!(scripted > 150, "{scripted} of 200 cases have a script");
    // Now and then a hold goes to a pass header or past the end (OP.AT, OP.REACH).
    assert!(elsewhere > 0 && on_moves > 8 * elsewhere, "{on_moves} on moves, {elsewhere} elsewhere");
}
