//! Operator events in G76, G78 and G162, the operator alarms, the corpus replayed, and a
//! property of G92.HOLD: every expected run below is worked out from the register by hand.

use crate::tests::operator::{bit6, hold, lines, operator_alarm, play, reset, single, u_lines, EXAMPLE};
use crate::expand;
use cycle_vocab::readings::ThreadZRef;
use cycle_vocab::{Action, Alarm, AlarmCode, Config, Dialect, Event, Params, Readings, Rule};

/// G76, two starts with a lead-in (E1), no pull-out (P010060: r = 00 input). U: 0 `G00 X40 Z5`;
/// pass 1: 1 header, start 1: 2 rapid to the lead-in point X38.2 Z4.48, 3 the lead-in to X36.2,
/// 4 the cut, 5, 6 the rapids; start 2: 7 – 11 the same at 180°; pass 2 from 12.
const G76_LEADIN: &str = "G0 X40 Z5\nG76 P010060 Q100 R0.1 L2 E1\nG76 X36 Z-20 P1 Q0.8 F2\n";

/// G76.HOLD on the lead-in of the second start: no pull-out, so X to A.x, then Z to A; the cut
/// is repeated from its first move (7), not from the pass header.
#[test]
fn g76_leadin_second_start() {
    let u = u_lines(G76_LEADIN, &Config::default());
    assert_eq!(u[7..9], ["G00 X38.200 Z4.480 ; G76.LEADIN", "G32 X36.200 Z4.480 F2.0000 Q180000 ; G76.LEADIN"]);
    let t = play(G76_LEADIN, &bit6(0), &[hold(8, 1, 2), Action::Start]);
    assert_eq!(lines(&t)[..8], u[..8]);
    assert_eq!(
        lines(&t)[8..14],
        [
            "(PRESS HOLD AT X37.200 Z4.480) ; G76.HOLD",
            "G32 X37.200 Z4.480 F2.0000 Q180000 ; G76.LEADIN",
            "G00 X40.000 Z4.480 ; G76.HOLD",
            "G00 X40.000 Z5.000 ; G76.HOLD",
            "(STOP FEED HOLD) ; G76.HOLD",
            "(CYCLE START) ; OP.RESUME",
        ]
    );
    assert_eq!(lines(&t)[14..], u[7..]);
    // The first start's cut begins at the pass header.
    let t = play(G76_LEADIN, &bit6(0), &[hold(4, 1, 2), Action::Start]);
    assert_eq!(lines(&t)[10..], u[1..]);
    // G76.SINGLE: one stop after each start's return to A (events 6, 11, 17, 22).
    let t = play(G76_LEADIN, &Config::default(), &[single(true, 1)]);
    let stops: Vec<usize> = lines(&t).iter().enumerate().filter(|(_, l)| l.starts_with("(STOP SINGLE BLOCK) ; G76.SINGLE")).map(|(i, _)| i).collect();
    assert_eq!(stops, [7, 14, 22, 29]);
}

/// G78 with a pull-out. U: 0 `G00 X40 Z5`; 1 header; 2 `G00 X36.2 Z4.48`; 3 cut to Z-18.52;
/// 4 pull-out to X40.2 Z-20.52; 5, 6 rapids; 7 header 2; 8 `G00 X36 Z4.48`; 9 cut; 10 pull-out
/// to X40 Z-20.52 (= A.x: ③ is not emitted); 11 `G00 X40 Z5` — under `thread.zref=groove`,
/// where the centre mode (00) stands at A.z − t(T) = 4.48 (under the letter it is A.z itself).
const G78: &str = "G0 X40 Z5\nG78 P010060 Q100 R0.1\nG78 X36 Z-20 P1 Q0.8 F2\n";

#[test]
fn g78_hold_on_the_cut_and_on_the_pullout() {
    let groove = |c: Config| Config { readings: Readings { thread_zref: ThreadZRef::Groove, ..Readings::default() }, ..c };
    let u = u_lines(G78, &groove(Config::default()));
    // Cut at 1/2: P = (36.2, 4.48 − 11.5); P + (E − S) = P + (4, −2).
    let t = play(G78, &groove(bit6(0)), &[hold(3, 1, 2), Action::Start]);
    assert_eq!(
        lines(&t)[3..10],
        [
            "(PRESS HOLD AT X36.200 Z-7.020) ; G76.HOLD",
            "G32 X36.200 Z-7.020 F2.0000 ; G76.PATH",
            "G32 X40.200 Z-9.020 F2.0000 ; G76.HOLD",
            "G00 X40.000 Z-9.020 ; G76.HOLD",
            "G00 X40.000 Z5.000 ; G76.HOLD",
            "(STOP FEED HOLD) ; G76.HOLD",
            "(CYCLE START) ; OP.RESUME",
        ]
    );
    assert_eq!(lines(&t)[10..], u[1..]);
    // Pull-out of pass 2 at 1/2: to E = X40 Z-20.52, already at A.x: the X rapid has no length.
    let t = play(G78, &groove(bit6(0)), &[hold(10, 1, 2), Action::Start]);
    assert_eq!(
        lines(&t)[10..16],
        [
            "(PRESS HOLD AT X38.000 Z-19.520) ; G76.HOLD",
            "G32 X38.000 Z-19.520 F2.0000 ; G78.PULLOUT",
            "G32 X40.000 Z-20.520 F2.0000 ; G76.HOLD",
            "G00 X40.000 Z5.000 ; G76.HOLD",
            "(STOP FEED HOLD) ; G76.HOLD",
            "(CYCLE START) ; OP.RESUME",
        ]
    );
    assert_eq!(lines(&t)[16..], u[7..]);
    // bit 6 = 1: runs on to the pull-out's end; single block stops after 6 and 11 (G76.SINGLE).
    let t = play(G78, &groove(bit6(1)), &[single(true, 0), hold(3, 1, 2), Action::Start]);
    let l = lines(&t);
    assert_eq!(l[1..3], ["(STOP SINGLE BLOCK) ; OP.SINGLE", "(CYCLE START) ; OP.SINGLE"]);
    assert_eq!(l[5..10], ["(PRESS HOLD AT X36.200 Z-7.020) ; G76.HOLD".to_string(), u[3].clone(), u[4].clone(), "(STOP FEED HOLD) ; G76.HOLD".into(), "(CYCLE START) ; OP.RESUME".into()]);
    assert_eq!(l[12..14], ["(STOP SINGLE BLOCK) ; G76.SINGLE", "(CYCLE START) ; G76.SINGLE"]);
    assert_eq!(l.last().unwrap(), "(CYCLE START) ; G76.SINGLE");
}

fn nc201() -> Config {
    Config { dialect: Dialect::Nc201, ..Config::default() }
}

/// G162, two passes. U: 0 `G00 X30 Z5`; pass 1: 1 header, 2 ①, 3 ② to Z-18, 4 ③ the leg,
/// 5 ④, 6 ⑤; pass 2: 7 – 12.
const G162: &str = "G0 X30 Z5\nG162 X24 Z-20 H500 P1 Q0.5 V2 F1.5\n";

#[test]
fn g162_hold_is_deferred_to_the_end_of_the_leg() {
    let u = u_lines(G162, &nc201());
    let t = play(G162, &nc201(), &[hold(3, 1, 2), Action::Start]);
    let mut expected = u[..3].to_vec();
    expected.push("(PRESS HOLD AT X23.000 Z-6.500) ; G162.NOSTOP".into());
    expected.extend(u[3..5].iter().cloned());
    expected.extend(["(STOP FEED HOLD) ; G162.NOSTOP", "(CYCLE START) ; OP.RESUME"].map(String::from));
    expected.extend(u[5..].iter().cloned());
    assert_eq!(lines(&t), expected);
    // V = 0: no ③, the stop follows ②.
    let src = "G0 X30 Z5\nG162 X24 Z-20 H500 F1.5\n";
    let u = u_lines(src, &nc201());
    let t = play(src, &nc201(), &[hold(3, 1, 2), Action::Start]);
    assert_eq!(lines(&t)[4..7], [u[3].clone(), "(STOP FEED HOLD) ; G162.NOSTOP".into(), "(CYCLE START) ; OP.RESUME".into()]);
    assert_eq!(lines(&t)[7..], u[4..]);
    // A hold on ④ is OP.HOLD.
    let t = play(G162, &nc201(), &[hold(5, 1, 2), Action::Start]);
    assert_eq!(lines(&t)[5..9], ["(PRESS HOLD AT X28.500 Z-20.000) ; OP.HOLD", "G01 X28.500 Z-20.000 F500.0000 ; G162.RETRACT", "(STOP FEED HOLD) ; OP.HOLD", "(CYCLE START) ; OP.RESUME"]);
}

#[test]
fn g162_single_block_after_segments_1_4_5() {
    let u = u_lines(G162, &nc201());
    let t = play(G162, &nc201(), &[single(true, 1)]);
    let mut expected = Vec::new();
    for (i, l) in u.iter().enumerate() {
        expected.push(l.clone());
        if [2, 5, 6, 8, 11, 12].contains(&i) {
            expected.extend(["(STOP SINGLE BLOCK) ; G162.NOSTOP", "(CYCLE START) ; G162.NOSTOP"].map(String::from));
        }
    }
    assert_eq!(lines(&t), expected);
}

/// A Hold while a stop is pending is recorded and adds no stop; a Reset then acts at once. A
/// second Hold at 1/4 of the move already held at 1/2 is behind the tool: it does not fire on
/// this pass of the move ("nothing fires behind the tool"), and the run ends in OP.REACH.
#[test]
fn presses_while_a_stop_is_pending() {
    let t = play(EXAMPLE, &bit6(1), &[hold(3, 1, 2), hold(4, 1, 2), Action::Start]);
    let l = lines(&t);
    assert_eq!(l[3..8], ["(PRESS HOLD AT X58.700 Z-11.000) ; G92.HOLD", "G32 X58.700 Z-27.000 F3.0000 ; G92.PATH", "(PRESS HOLD AT X61.700 Z-27.500) ; G92.HOLD", "G32 X64.700 Z-28.000 F3.0000 ; G92.PULLOUT", "(STOP FEED HOLD) ; G92.HOLD"]);
    assert_eq!(t.events.iter().filter(|e| matches!(e, Event::Stop(_))).count(), 1);
    let t = play(EXAMPLE, &bit6(1), &[hold(3, 1, 2), hold(3, 1, 4)]);
    assert_eq!(t.events.iter().filter(|e| matches!(e, Event::Press(_))).count(), 1, "{:?}", lines(&t));
    assert_eq!(t.alarm, operator_alarm(Rule::OpReach, 0));
    // Ahead of the tool on the same move it fires.
    let t = play(EXAMPLE, &bit6(1), &[hold(3, 1, 4), hold(3, 1, 2), Action::Start]);
    assert_eq!(lines(&t)[3..5], ["(PRESS HOLD AT X58.700 Z-3.000) ; G92.HOLD", "(PRESS HOLD AT X58.700 Z-11.000) ; G92.HOLD"]);
    let t = play(G162, &nc201(), &[hold(3, 1, 2), reset(4, 1, 2)]);
    assert_eq!(lines(&t)[4..], ["G32 X23.000 Z-18.000 F1.5000 ; G162.F", "(PRESS RESET AT X25.000 Z-19.000) ; OP.RESET", "G01 X25.000 Z-19.000 F500.0000 ; G162.V"]);
    assert_eq!(t.alarm, None);
}

/// G92.RESET on a thread move, OP.RESET on a rapid: the move to P, then nothing.
#[test]
fn resets() {
    let t = play(EXAMPLE, &bit6(0), &[reset(3, 1, 2), Action::Start]);
    assert_eq!(lines(&t)[3..], ["(PRESS RESET AT X58.700 Z-11.000) ; G92.RESET", "G32 X58.700 Z-11.000 F3.0000 ; G92.PATH"]);
    assert_eq!(t.alarm, None, "after a reset not even OP.REACH");
    let t = play(EXAMPLE, &bit6(0), &[reset(2, 1, 2)]);
    assert_eq!(lines(&t)[2..], ["(PRESS RESET AT X61.850 Z5.000) ; OP.RESET", "G00 X61.850 Z5.000 ; G92.PATH"]);
}

const G90: &str = "G0 X50 Z5\nG90 X40 Z-20 F0.2\nG0 X60\n";

/// OP.AT on a pass header; OP.SCOPE on G90 and G71 moves and on single block entering G90.
#[test]
fn at_and_scope() {
    let t = play(EXAMPLE, &bit6(0), &[hold(1, 1, 2), Action::Start]);
    assert_eq!((lines(&t).len(), t.alarm), (1, operator_alarm(Rule::OpAt, 2)));
    let t = play(G90, &Config::default(), &[hold(3, 1, 2)]);
    assert_eq!((lines(&t).len(), t.alarm), (3, operator_alarm(Rule::OpScope, 2)));
    let t = play(G90, &Config::default(), &[single(true, 0)]);
    assert_eq!(lines(&t), ["G00 X50.000 Z5.000 ; PRJ.MODAL", "(STOP SINGLE BLOCK) ; OP.SINGLE", "(CYCLE START) ; OP.SINGLE"]);
    assert_eq!(t.alarm, operator_alarm(Rule::OpScope, 2));
    // Off again before the G90 block: no alarm, and the G00 after it stops again.
    let t = play(G90, &Config::default(), &[single(true, 0), single(false, 1), single(true, 6)]);
    assert_eq!(t.alarm, None);
    assert_eq!(lines(&t).len(), 7 + 4);
    let g71 = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../corpus/g71_example.nc")).unwrap();
    let u = expand(g71.as_bytes(), &Config::default());
    let first = u.events.iter().position(|e| matches!(e, Event::Move(m) if m.rule != Rule::PrjModal)).unwrap();
    let t = play(&g71, &Config::default(), &[hold(first as u32, 1, 2)]);
    assert_eq!((t.events.len(), t.alarm), (first, operator_alarm(Rule::OpScope, 8)));
}

/// OP.REACH: a hold never reached; a hold after a feed-hold stop without Start; a program alarm
/// of U is the one alarm.
#[test]
fn reach() {
    let u = u_lines(EXAMPLE, &Config::default());
    let t = play(EXAMPLE, &bit6(0), &[hold(7, 1, 2)]);
    assert_eq!((lines(&t), t.alarm), (u.clone(), operator_alarm(Rule::OpReach, 0)));
    let t = play(EXAMPLE, &bit6(0), &[hold(3, 1, 2), hold(5, 1, 2)]);
    assert_eq!(lines(&t).last().unwrap(), "(STOP FEED HOLD) ; G92.HOLD");
    assert_eq!(t.alarm, operator_alarm(Rule::OpReach, 0));
    // All fired: the run ends at the stop without an alarm.
    let t = play(EXAMPLE, &bit6(0), &[hold(3, 1, 2)]);
    assert_eq!(t.alarm, None);
    let bad = "G0 X65 Z5\nG92 X58.7 Z5 F3\n";
    let t = play(bad, &bit6(0), &[hold(0, 1, 2), Action::Start, hold(9, 1, 2)]);
    assert_eq!(t.alarm, Some(Alarm::new(AlarmCode::Geometry, Some(b'Z'), Rule::G92Format, 2)));
}

/// OP.SCRIPT: den 0, num > den: `OUT OF RANGE` on line 0, after the other configuration checks.
#[test]
fn script_checked_with_the_configuration() {
    let out_of_range = Some(Alarm::new(AlarmCode::OutOfRange, None, Rule::OpScript, 0));
    assert_eq!(play(EXAMPLE, &bit6(0), &[hold(3, 1, 0)]).alarm, out_of_range);
    assert_eq!(play(EXAMPLE, &bit6(0), &[Action::Start, reset(3, 3, 2)]).alarm, out_of_range);
    let t = play(EXAMPLE, &bit6(0), &[hold(3, 1_000_000, 1_000_000)]);
    assert_eq!((lines(&t)[3].as_str(), t.alarm), ("(PRESS HOLD AT X58.700 Z-27.000) ; G92.HOLD", None));
    let t = play(EXAMPLE, &bit6(2), &[hold(3, 1, 0)]);
    assert_eq!((t.events.len(), t.alarm), (0, Some(Alarm::new(AlarmCode::OutOfRange, None, Rule::G92Hold, 0))));
}

/// An empty script leaves every corpus trace as it is, U is recorded alike, and a script whose
/// only action switches single block off replays U exactly.
#[test]
fn corpus_unchanged() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/../corpus");
    let mut files: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).filter(|p| p.extension().is_some_and(|x| x == "nc")).collect();
    files.sort();
    assert!(files.len() >= 16);
    for path in files {
        let src = std::fs::read(&path).unwrap();
        for dialect in [Dialect::Gsk, Dialect::Fanuc, Dialect::Nc201] {
            let config = Config { dialect, ..Config::default() };
            let plain = expand(&src, &config);
            let u = crate::operator::uninterrupted(&src, &config);
            assert_eq!((&u.events, u.alarm), (&plain.events, plain.alarm), "{path:?}");
            assert_eq!(u.notes.len(), u.events.len());
            let replay = expand(&src, &Config { operator: cycle_vocab::Script::of(&[single(false, 0)]).unwrap(), ..config });
            let expected = if plain.events.is_empty() && plain.alarm.is_none() { operator_alarm(Rule::OpReach, 0) } else { plain.alarm };
            assert_eq!((&replay.events, replay.alarm), (&plain.events, expected), "{path:?} {dialect:?}");
        }
    }
}

/// G92.HOLD, bit 6 = 0, at random points of the example's moves, then Start: after the Resume
/// the run is U from the cut's first event (a thread move) or the rest of the move and U on (a
/// rapid); no retract move goes deeper than the thread (X58.7) or past its end (Z-28); the run
/// ends exactly as U.
#[test]
fn random_holds_resume_as_u() {
    let u = expand(EXAMPLE.as_bytes(), &Config::default());
    let mut seed: u64 = 0x2545_f491_4f6c_dd1d;
    for _ in 0..300 {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        let event = [0u32, 2, 3, 4, 5, 6][(seed % 6) as usize];
        let den = 1 + (seed >> 8) as u32 % 1_000_000;
        let num = (seed >> 32) as u32 % (den + 1);
        let t = play(EXAMPLE, &Config { params: Params::default(), ..bit6(0) }, &[hold(event, num, den), Action::Start]);
        assert_eq!(t.alarm, None);
        let resume = t.events.iter().position(|e| matches!(e, Event::Resume(_))).unwrap();
        let after = &t.events[resume + 1..];
        if event == 3 || event == 4 {
            assert_eq!(after, &u.events[1..], "{event} {num}/{den}");
            let press = t.events.iter().position(|e| matches!(e, Event::Press(_))).unwrap();
            for e in &t.events[press..resume] {
                if let Event::Move(m) = e {
                    assert!(m.x >= 58_700 && m.z >= -28_000, "{m:?} {event} {num}/{den}");
                }
            }
        } else {
            // OP.RESUME: the rest of the move (when it has a length), then U from the next event.
            let rest = &u.events[event as usize + 1..];
            assert!(after.ends_with(rest) && after.len() - rest.len() <= 1, "{event} {num}/{den}");
            if after.len() > rest.len() {
                assert_eq!(after[0], u.events[event as usize]);
            }
        }
        assert_eq!(t.events.last(), u.events.last());
    }
}
