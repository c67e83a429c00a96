//! Edges of the shared modules (`program`, `lex`, `words`, `operator/`, `sub`, …) that the
//! spec-alone mutation run of 2026-11-28 (sixth session, docs/MUTATION.md) found unpinned, each
//! worked by hand from docs/INTERPRETATION.md, the crate's documented API and the manuals.

use crate::expand_into;
use crate::tests::operator::{bit6, hold, lines, operator_alarm, play, u_lines};
use crate::tests::util::alarm_of;
use core::ops::ControlFlow;
use cycle_vocab::{Action, AlarmCode, Config, Rule, Script};

/// `expand_into` (the crate's API, `lib.rs`): "When `sink` answers `Break` it gets no further
/// event and the expansion stops after the block it is in (the result is then `None`, unless
/// that block itself ended in an alarm)". Block 2 would be `MISSING WORD F` (COM.LEAD: G01
/// moving with no feed set), but the sink broke at block 1's move: no alarm, one event.
#[test]
fn a_sink_that_breaks_ends_the_expansion_after_its_block() {
    let src = "G0 X10\nG1 X20\n";
    assert_eq!(alarm_of(src), (AlarmCode::MissingWord, Some('F'), Rule::ComLead, 2));
    let mut seen = 0;
    let alarm = expand_into(src.as_bytes(), &Config::default(), &mut |_| {
        seen += 1;
        ControlFlow::Break(())
    });
    assert_eq!((alarm, seen), (None, 1));
}

/// `expand_into` with an operator script (OP.SCRIPT): "a sink's `Break` then ends the run with
/// `None`". U: 0 `G00 X10`. `Hold(0, 1/2)` stops at X5 (OP.HOLD); the next action is no `Start`,
/// so the run ends there with `Hold(0, 1/1)` not fired: OP.REACH. A sink that breaks at the first
/// event (the press) gets nothing more and no alarm.
#[test]
fn a_sink_that_breaks_ends_an_operator_run_with_no_alarm() {
    let (src, script) = ("G0 X10\n", [hold(0, 1, 2), hold(0, 1, 1)]);
    let t = play(src, &Config::default(), &script);
    assert_eq!(t.alarm, operator_alarm(Rule::OpReach, 0));
    assert_eq!(lines(&t), ["(PRESS HOLD AT X5.000 Z0.000) ; OP.HOLD", "G00 X5.000 Z0.000 ; PRJ.MODAL", "(STOP FEED HOLD) ; OP.HOLD"]);
    let config = Config { operator: Script::of(&script).unwrap(), ..Config::default() };
    let mut seen = 0;
    let alarm = expand_into(src.as_bytes(), &config, &mut |_| {
        seen += 1;
        ControlFlow::Break(())
    });
    assert_eq!((alarm, seen), (None, 1));
}

/// OP.HOLD (docs/INTERPRETATION.md, "Feed hold"): "in G92/G76/G78 a rapid (①, ③, ④, the rapids to
/// the lead-in point or to Bn)" is held as a plain move; only a thread move of a cut is G76.HOLD.
/// U of `tests::operator_cycles`' G76 with a lead-in: 2 is the rapid from A (X40 Z5) to the
/// lead-in point X38.2 Z4.48. `Hold(2, 1/2)`: P = (40 + trunc(−1.8/2), 5 + trunc(−0.52/2)) =
/// X39.1 Z4.74; the press, the rapid to P (its own rule), the stop, cycle start, the rest of the
/// rapid, and U goes on — no retract, the cut is not repeated.
#[test]
fn hold_on_a_g76_rapid_is_op_hold() {
    let src = "G0 X40 Z5\nG76 P010060 Q100 R0.1 L2 E1\nG76 X36 Z-20 P1 Q0.8 F2\n";
    let u = u_lines(src, &Config::default());
    assert_eq!(u[2], "G00 X38.200 Z4.480 ; G76.LEADIN");
    let t = play(src, &bit6(0), &[hold(2, 1, 2), Action::Start]);
    let held = ["(PRESS HOLD AT X39.100 Z4.740) ; OP.HOLD", "G00 X39.100 Z4.740 ; G76.LEADIN", "(STOP FEED HOLD) ; OP.HOLD", "(CYCLE START) ; OP.RESUME"];
    let expected: Vec<String> = u[..2].iter().cloned().chain(held.map(String::from)).chain(u[2..].iter().cloned()).collect();
    assert_eq!(lines(&t), expected);
    assert_eq!(t.alarm, None);
}
