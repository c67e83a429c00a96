//! Operator events in the thread cycles (G92.HOLD, G92.SINGLE, G92.RESET, G76.HOLD,
//! G76.SINGLE, G162.NOSTOP) on the whole expander: the long axis, lead-in and multi-start,
//! G78, G162's segments, single block in a modal run, resets, and random holds whose cut is
//! repeated.
extern crate std;

use super::{bit6, cat, hold, lines, nc201, plain, reset, run, single, strs, with, EXAMPLE};
use crate::tests::{expand, xorshift};
use cycle_vocab::{Action, Config, Event};
use std::format;
use std::vec;
use std::vec::Vec;

const XLONG: &str = "G0 X100 Z10\nG92 X40 Z0 R20 F2 J1 K4\n";
const G76L2: &str = "G00 X40 Z5\nG76 P011060 Q0.1 R0.05 L2 E0.5\nG76 X37.4 Z-20 P1.3 Q0.9 F6 J1 K2\n";
const G78: &str = "G00 X40 Z5\nG78 P010260 Q0.1 R0.05\nG78 X37.4 Z-20 P1.3 Q0.9 F6 J1 K2\n";
const G162V: &str = "G0 X45 Z0\nG162 X40 Z-20 H300 V2 F2\n";
const G162V0: &str = "G0 X45 Z0\nG162 X40 Z-20 H300 F2\n";

/// On the pull-out at fraction 1 the retract's thread move would end where the tool is: it is
/// omitted (PRJ.NOOP). A second hold on a thread move abandoned by a retract fires on the
/// repeated cut, which executes the move afresh ([0, 1]), even at a smaller fraction.
#[test]
fn retract_noop_and_hold_on_the_repeat() {
    let u = plain(EXAMPLE, Config::default());
    let got = run(EXAMPLE, Config::default(), &[hold(4, 1, 1), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X64.700 Z-28.000) G92.HOLD",
        "G32 X64.700 Z-28.000 F3.0000 G92.PULLOUT",
        "G00 X65.000 Z-28.000 G92.HOLD",
        "G00 X65.000 Z5.000 G92.HOLD",
        "(STOP FEED HOLD) G92.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..4], &held, &u[1..]]));
    let got = run(EXAMPLE, Config::default(), &[hold(3, 1, 2), Action::Start, hold(3, 1, 4), Action::Start]);
    let first = strs(&[
        "(PRESS HOLD AT X58.700 Z-11.000) G92.HOLD",
        "G32 X58.700 Z-11.000 F3.0000 G92.PATH",
        "G32 X64.700 Z-12.000 F3.0000 G92.HOLD",
        "G00 X65.000 Z-12.000 G92.HOLD",
        "G00 X65.000 Z5.000 G92.HOLD",
        "(STOP FEED HOLD) G92.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    let second = strs(&[
        "(PRESS HOLD AT X58.700 Z-3.000) G92.HOLD",
        "G32 X58.700 Z-3.000 F3.0000 G92.PATH",
        "G32 X64.700 Z-4.000 F3.0000 G92.HOLD",
        "G00 X65.000 Z-4.000 G92.HOLD",
        "G00 X65.000 Z5.000 G92.HOLD",
        "(STOP FEED HOLD) G92.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..3], &first, &u[1..3], &second, &u[1..]]));
}

/// X the long axis (|W| ≤ |R|): the retract's short-axis rapid is Z to A.z, then X to A.
#[test]
fn x_long_axis_g92() {
    let u = plain(XLONG, Config::default());
    assert_eq!(u[3], "G32 X48.000 Z2.000 F2.0000 G92.PATH");
    let got = run(XLONG, Config::default(), &[hold(3, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X64.000 Z6.000) G92.HOLD",
        "G32 X64.000 Z6.000 F2.0000 G92.PATH",
        "G32 X56.000 Z5.000 F2.0000 G92.HOLD",
        "G00 X56.000 Z10.000 G92.HOLD",
        "G00 X100.000 Z10.000 G92.HOLD",
        "(STOP FEED HOLD) G92.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..3], &held, &u[1..]]));
}

/// G76.HOLD with a lead-in and two starts: a cut of the second start is repeated from its
/// first move (no header); one of the first start from its pass header. The lead-in is a
/// thread move of the cut.
#[test]
fn g76_leadin_multistart_hold() {
    let u = plain(G76L2, Config::default());
    assert_eq!(u.len(), 40);
    assert_eq!(u[8], "G00 X39.200 Z4.480 G76.PATH");
    let got = run(G76L2, Config::default(), &[hold(10, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X38.200 Z-7.020) G76.HOLD",
        "G32 X38.200 Z-7.020 F6.0000 Q180000 G76.PATH",
        "G32 X40.200 Z-9.020 F6.0000 Q180000 G76.HOLD",
        "G00 X40.000 Z-9.020 G76.HOLD",
        "G00 X40.000 Z5.000 G76.HOLD",
        "(STOP FEED HOLD) G76.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..10], &held, &u[8..]]));
    // On the first start's lead-in: P + (E − S), then X to A.x, Z to A; the pass header again.
    let got = run(G76L2, Config::default(), &[hold(3, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X38.700 Z4.480) G76.HOLD",
        "G32 X38.700 Z4.480 F6.0000 G76.LEADIN",
        "G32 X40.700 Z2.480 F6.0000 G76.HOLD",
        "G00 X40.000 Z2.480 G76.HOLD",
        "G00 X40.000 Z5.000 G76.HOLD",
        "(STOP FEED HOLD) G76.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..3], &held, &u[1..]]));
    // Bit 6 = 1: on to the pull-out's end, then the stop; G76.SINGLE after each cut's return.
    let got = run(G76L2, bit6(1), &[single(true, 8), hold(10, 1, 2), Action::Start]);
    let sb = strs(&["(STOP SINGLE BLOCK) G76.SINGLE", "(CYCLE START) G76.SINGLE"]);
    let held = strs(&["(PRESS HOLD AT X38.200 Z-7.020) G76.HOLD"]);
    let stop = strs(&["(STOP FEED HOLD) G76.HOLD", "(CYCLE START) OP.RESUME"]);
    let mut want = cat(&[&u[..10], &held, &u[10..12], &stop, &u[12..14], &sb]);
    for cut in [14..21, 21..27, 27..34, 34..40] {
        want.extend(cat(&[&u[cut], &sb]));
    }
    assert_eq!(got, want);
}

/// G78 is G76.HOLD too (bit 6 = 0 and 1).
#[test]
fn g78_hold() {
    let u = plain(G78, Config::default());
    let got = run(G78, Config::default(), &[hold(3, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X38.200 Z-7.020) G76.HOLD",
        "G32 X38.200 Z-7.020 F6.0000 G76.PATH",
        "G32 X40.200 Z-9.020 F6.0000 G76.HOLD",
        "G00 X40.000 Z-9.020 G76.HOLD",
        "G00 X40.000 Z5.000 G76.HOLD",
        "(STOP FEED HOLD) G76.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..3], &held, &u[1..]]));
    let got = run(G78, bit6(1), &[hold(3, 1, 2), Action::Start]);
    let stop = strs(&["(STOP FEED HOLD) G76.HOLD", "(CYCLE START) OP.RESUME"]);
    assert_eq!(got, cat(&[&u[..3], &held[..1], &u[3..5], &stop, &u[5..]]));
}

/// G162.NOSTOP: a hold on ② stops at the end of ③ (of ② when V = 0, no ③); on ③ at its end;
/// ① is OP.HOLD; single block stops after ①, ④, ⑤ only.
#[test]
fn g162_nostop() {
    let u = plain(G162V, nc201());
    assert_eq!(u[4], "G01 X44.000 Z-20.000 F300.0000 G162.V");
    let stop = strs(&["(STOP FEED HOLD) G162.NOSTOP", "(CYCLE START) OP.RESUME"]);
    let got = run(G162V, nc201(), &[hold(3, 1, 2), Action::Start]);
    let press = strs(&["(PRESS HOLD AT X40.000 Z-9.000) G162.NOSTOP"]);
    assert_eq!(got, cat(&[&u[..3], &press, &u[3..5], &stop, &u[5..]]));
    let got = run(G162V, nc201(), &[hold(4, 1, 2), Action::Start]);
    let press = strs(&["(PRESS HOLD AT X42.000 Z-19.000) G162.NOSTOP"]);
    assert_eq!(got, cat(&[&u[..4], &press, &u[4..5], &stop, &u[5..]]));
    // A second hold while the stop is pending is recorded and adds no stop.
    let got = run(G162V, nc201(), &[hold(3, 1, 2), hold(4, 1, 2), Action::Start]);
    let press2 = strs(&["(PRESS HOLD AT X40.000 Z-9.000) G162.NOSTOP", "(PRESS HOLD AT X42.000 Z-19.000) G162.NOSTOP"]);
    assert_eq!(got, cat(&[&u[..3], &press2[..1], &u[3..4], &press2[1..], &u[4..5], &stop, &u[5..]]));
    let u0 = plain(G162V0, nc201());
    let got = run(G162V0, nc201(), &[hold(3, 1, 2), Action::Start]);
    let press = strs(&["(PRESS HOLD AT X40.000 Z-10.000) G162.NOSTOP"]);
    assert_eq!(got, cat(&[&u0[..3], &press, &u0[3..4], &stop, &u0[4..]]));
    // ① is OP.HOLD.
    let got = run(G162V, nc201(), &[hold(2, 1, 2), Action::Start]);
    let held = strs(&[
        "(PRESS HOLD AT X42.500 Z0.000) OP.HOLD",
        "G01 X42.500 Z0.000 F300.0000 G162.PATH",
        "(STOP FEED HOLD) OP.HOLD",
        "(CYCLE START) OP.RESUME",
    ]);
    assert_eq!(got, cat(&[&u[..2], &held, &u[2..]]));
    // Single block: after the plain G0 (OP.SINGLE), after ①, ④, ⑤ (G162.NOSTOP).
    let got = run(G162V, nc201(), &[single(true, 0)]);
    let sb = |r: &str| vec![format!("(STOP SINGLE BLOCK) {r}"), format!("(CYCLE START) {r}")];
    let n = sb("G162.NOSTOP");
    assert_eq!(got, cat(&[&u[..1], &sb("OP.SINGLE"), &u[1..3], &n, &u[3..6], &n, &u[6..], &n]));
}

/// G92.SINGLE in a modal run: a stop after each cut's return to A, none inside a cut.
#[test]
fn single_block_in_a_g92_run() {
    let prog = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nX57.7\n";
    let u = plain(prog, Config::default());
    assert_eq!(u.len(), 13);
    let got = run(prog, Config::default(), &[single(true, 0)]);
    let sb = |r: &str| vec![format!("(STOP SINGLE BLOCK) {r}"), format!("(CYCLE START) {r}")];
    let g = sb("G92.SINGLE");
    assert_eq!(got, cat(&[&u[..1], &sb("OP.SINGLE"), &u[1..7], &g, &u[7..], &g]));
    // Switched on before event 1: the stop after event 0 was decided by the mode before.
    let got = run(prog, Config::default(), &[single(true, 1), single(false, 7)]);
    assert_eq!(got, cat(&[&u[..7], &g, &u[7..]]));
}

/// Reset: G92.RESET on a thread move of a cut, OP.RESET on a rapid; nothing after.
#[test]
fn resets() {
    let u = plain(EXAMPLE, Config::default());
    let got = run(EXAMPLE, Config::default(), &[reset(3, 1, 2), Action::Start]);
    let want = strs(&["(PRESS RESET AT X58.700 Z-11.000) G92.RESET", "G32 X58.700 Z-11.000 F3.0000 G92.PATH"]);
    assert_eq!(got, cat(&[&u[..3], &want]));
    let got = run(EXAMPLE, Config::default(), &[reset(2, 1, 2)]);
    let want = strs(&["(PRESS RESET AT X61.850 Z5.000) OP.RESET", "G00 X61.850 Z5.000 G92.PATH"]);
    assert_eq!(got, cat(&[&u[..2], &want]));
    // While a stop is pending (bit 6 = 1) a reset acts at once.
    let got = run(EXAMPLE, bit6(1), &[hold(3, 1, 2), reset(4, 1, 2)]);
    let want = strs(&[
        "(PRESS HOLD AT X58.700 Z-11.000) G92.HOLD",
        "G32 X58.700 Z-27.000 F3.0000 G92.PATH",
        "(PRESS RESET AT X61.700 Z-27.500) G92.RESET",
        "G32 X61.700 Z-27.500 F3.0000 G92.PULLOUT",
    ]);
    assert_eq!(got, cat(&[&u[..3], &want]));
}

/// Random holds on the thread moves of the G92 example and of the two-start G76 with bit 6 = 0,
/// then Start: U up to the held move, the retract, and after the Resume U again from the cut's
/// first event to the end, as U ends. `fill` gives the same stream.
#[test]
fn random_holds_repeat_the_cut() {
    let g92 = plain(EXAMPLE, Config::default());
    let g76 = plain(G76L2, Config::default());
    // (program, U, cut first event, thread events of the cut)
    let g92_cuts: &[(usize, &[usize])] = &[(1, &[3, 4])];
    let g76_cuts: &[(usize, &[usize])] =
        &[(1, &[3, 4, 5]), (8, &[9, 10, 11]), (14, &[16, 17, 18]), (21, &[22, 23, 24]), (27, &[29, 30, 31]), (34, &[35, 36, 37])];
    let mut seed = 0x0123_4567_89ab_cdef_u64;
    for round in 0..400 {
        let (prog, u, cuts) = if round % 2 == 0 { (EXAMPLE, &g92, g92_cuts) } else { (G76L2, &g76, g76_cuts) };
        let r = xorshift(&mut seed);
        let (first, threads) = cuts[(r % cuts.len() as u64) as usize];
        let e = threads[((r >> 8) % threads.len() as u64) as usize];
        let den = 1 + ((r >> 16) % 1_000_000) as u32;
        let num = ((r >> 40) % (u64::from(den) + 1)) as u32;
        let config = with(Config::default(), &[hold(e as u32, num, den), Action::Start]);
        let t = expand(prog, config);
        let got = lines(&t);
        assert_eq!(got[..e], u[..e], "{e} {num}/{den}");
        assert!(got[e].starts_with("(PRESS HOLD AT ") && got[e].ends_with(".HOLD"), "{got:?}");
        let resume = got.iter().position(|l| l == "(CYCLE START) OP.RESUME").unwrap();
        assert!(resume - e <= 7, "{got:?}");
        assert!(got[resume - 1].starts_with("(STOP FEED HOLD) G"), "{got:?}");
        assert_eq!(got[resume + 1..], u[first..], "{e} {num}/{den}");
        // The retract ends at A on a rapid.
        assert!(got[resume - 2].starts_with("G00 X40.000 Z5.000") || got[resume - 2].starts_with("G00 X65.000 Z5.000"));
        // `fill` in small pieces: the same stream.
        let mut x = crate::expander::Expander::new(prog.as_bytes(), config);
        let mut buf = [t.events[0]; 3];
        let mut filled: Vec<Event> = Vec::new();
        loop {
            let n = x.fill(&mut buf).unwrap();
            filled.extend_from_slice(&buf[..n]);
            if n < buf.len() {
                break;
            }
        }
        assert_eq!(filled, t.events);
    }
}

/// OP.SCRIPT: a press on a move that runs on (bit 6 = 1) leaves the rest of it covering [f, 1]:
/// a later Hold behind the tool on the same move does not fire (OP.REACH at the end); one ahead
/// of it does.
#[test]
fn nothing_fires_behind_the_tool() {
    let behind = run(EXAMPLE, bit6(1), &[hold(3, 1, 2), hold(3, 1, 4)]);
    assert_eq!(behind.iter().filter(|l| l.starts_with("(PRESS")).count(), 1, "{behind:?}");
    assert!(behind.last().is_some_and(|l| l.contains("OP.REACH")), "{behind:?}");
    let ahead = run(EXAMPLE, bit6(1), &[hold(3, 1, 4), hold(3, 1, 2), Action::Start]);
    assert_eq!(ahead.iter().filter(|l| l.starts_with("(PRESS")).count(), 2, "{ahead:?}");
}
