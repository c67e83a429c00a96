//! G71, G72 and the contour (docs/INTERPRETATION.md, "Contours, arcs and the stock-removal
//! cycles") on the whole expander: the seed's two examples move by move, the flow and modal state
//! around the cycles, and `fill` against the iterator; the layers of random monotone contours
//! ([`layers`]) and every alarm of the register ([`checks`]) apart. G70 alone: `finish`'s tests.
extern crate std;

use super::{cut_on, Axis};
use crate::contour::Kind;
use crate::tests::{assert_fill_agrees, expand, gcode, moves, passes};
use crate::expander::Expander;
use cycle_vocab::{Alarm, AlarmCode, Config, Event, Move, MoveKind, Params, Pass, PassKind, Rule};
use std::format;
use std::string::String;
use std::vec::Vec;

mod checks;
mod fill;
mod layers;
mod stepping;

pub const EXAMPLE_1: &str = "N010 G50 X150 Z100\nN020 G00 X41 Z0\nN030 G71 U2 R1\nN040 G71 P50 Q120 U0.5 W0.2 F100\n\
N050 G01 X0 Z0\nN060 G03 X11 W-5.5 R5.5\nN070 G01 W-10\nN080 X17 W-10\nN090 W-15\nN100 G02 X29 W-7.348 R7.5\n\
N110 G01 W-12.652\nN120 X41\nN130 G70 P50 Q120 F30\n";

pub const EXAMPLE_2: &str = "N010 G50 X150 Z100\nN020 G00 X41 Z1\nN030 G72 W1 R1\nN040 G72 P50 Q80 U0.1 W0.2 F100\n\
N050 G00 X41 Z-31\nN060 G01 X20 Z-20\nN070 Z-2\nN080 X14 Z1\nN090 G70 P50 Q80 F30\n";

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

fn with_max_passes(max: i64) -> Config {
    Config { params: Params { max_passes: Some(max), ..Params::default() }, ..Config::default() }
}

/// A length in mm with three decimals.
fn mm(v: i64) -> String {
    format!("{}{}.{:03}", if v < 0 { "-" } else { "" }, v.abs() / 1000, v.abs() % 1000)
}

/// The cut ② of every ROUGH pass: the second move after its header.
fn layer_cuts(events: &[Event]) -> Vec<(u32, (i64, i64))> {
    let mut out = Vec::new();
    for (i, e) in events.iter().enumerate() {
        if let Event::Pass(Pass { index, kind: PassKind::Rough, .. }) = e {
            let cut = events[i + 1..].iter().filter_map(|e| if let Event::Move(m) = e { Some(m) } else { None }).nth(1);
            out.push((*index, cut.map(|m| (m.x, m.z)).unwrap()));
        }
    }
    out
}

/// G71.EXAMPLE (the seed's example 1, corpus `g71_example.nc`): A = X41 Z0, Δd = 2, e = 1,
/// Q = the contour shifted by U0.5 W0.2, Q₀ = X0.5 Z0.2. The register lists layers at X37 … X1;
/// its own rule (a layer exists while its cut is positive, c·(z_k − A.z) > 0) ends them at X5:
/// at X1 the shifted ball N060 (centre X0.5 Z−5.3, radius 5.5) is at Z+0.194, behind A.z, so
/// layer 10 would cut backwards. Nine layers, then the semi-finish pass and the return; the G70
/// then finishes the contour at F30 and returns to X41 Z0.
#[test]
fn example_1_g71_then_g70() {
    let t = expand(EXAMPLE_1, Config::default());
    assert_eq!(t.alarm, None);
    let cuts = layer_cuts(&t.events);
    let want: [(i64, i64); 9] = [
        (37_000, -60_300),
        (33_000, -60_300),
        (29_000, -47_593),
        (25_000, -46_795),
        (21_000, -45_115),
        (17_000, -24_467),
        (13_000, -17_800),
        (9_000, -1_809),
        (5_000, -281),
    ];
    assert_eq!(cuts.iter().map(|c| c.1).collect::<Vec<_>>(), want);
    // Layer 10 at X1: the cut end on the shifted N060 arc lies behind A.z = 0.
    let z10 = cut_on(Axis::G71, Kind::Arc(false), (500, 200), (11_500, -5_300), (500, -5_300), 1_000);
    assert_eq!(z10, 194);
    // The whole trace (roughing feed F100 = 1 000 000 lead counts).
    let f = 1_000_000;
    let mut m = Vec::new();
    m.push(Move::rapid(41_000, 0, Rule::PrjModal));
    for (x, z) in want {
        m.push(Move::feed(x, 0, f, Rule::G71Layer));
        m.push(Move::feed(x, z, f, Rule::G71Layer));
        m.push(Move::feed(x + 2_000, z + 1_000, f, Rule::G71Retract));
        m.push(Move::rapid(x + 2_000, 0, Rule::G71Retract));
    }
    let semi = Rule::G71Lastpass;
    m.extend([
        Move::feed(500, 200, f, semi),
        Move::arc(false, 11_500, -5_300, 500, -5_300, f, semi),
        Move::feed(11_500, -15_300, f, semi),
        Move::feed(17_500, -25_300, f, semi),
        Move::feed(17_500, -40_300, f, semi),
        Move::arc(true, 29_500, -47_648, 32_500, -40_300, f, semi),
        Move::feed(29_500, -60_300, f, semi),
        Move::feed(41_500, -60_300, f, semi),
        Move::rapid(41_000, 0, Rule::G71Return),
    ]);
    let g70 = Rule::G70Path;
    let f30 = 300_000;
    m.extend([
        Move::feed(0, 0, f30, g70),
        Move::arc(false, 11_000, -5_500, 0, -5_500, f30, g70),
        Move::feed(11_000, -15_500, f30, g70),
        Move::feed(17_000, -25_500, f30, g70),
        Move::feed(17_000, -40_500, f30, g70),
        Move::arc(true, 29_000, -47_848, 32_000, -40_500, f30, g70),
        Move::feed(29_000, -60_500, f30, g70),
        Move::feed(41_000, -60_500, f30, g70),
        Move::rapid(41_000, 0, Rule::G70Return),
    ]);
    assert_eq!(moves(&t), m);
    let p = passes(&t);
    assert_eq!(p.len(), 11);
    for (k, pass) in p.iter().take(9).enumerate() {
        assert_eq!(*pass, Pass { index: k as u32 + 1, kind: PassKind::Rough, diameter_depth: 4_000 * (k as i64 + 1), rule: Rule::G71Layer });
    }
    assert_eq!(p[9], Pass { index: 10, kind: PassKind::Semi, diameter_depth: 40_500, rule: Rule::G71Lastpass });
    assert_eq!(p[10], Pass { index: 1, kind: PassKind::Finish, diameter_depth: 41_000, rule: Rule::G70Path });
    std::println!("{}", gcode(EXAMPLE_1, Config::default()));
}

/// G72.EXAMPLE (the seed's example 2, corpus `g72_example.nc`): A = X41 Z1, Δd = 1, e = 1,
/// Q₀ = X41.1 Z−30.8: layers at Z0, −1, …, −30, each a rapid infeed (the ns block is G00), a
/// cut along X to the shifted contour, the 45° retract (+2e on X, +e on Z) and the rapid back
/// to X41; the semi-finish pass (depth = the Z distance 31.8), the return, then G70.
#[test]
fn example_2_g72_then_g70() {
    let t = expand(EXAMPLE_2, Config::default());
    assert_eq!(t.alarm, None);
    let cuts = layer_cuts(&t.events);
    assert_eq!(cuts.len(), 31);
    for (i, (index, (x, z))) in cuts.iter().enumerate() {
        assert_eq!((*index, *z), (i as u32 + 1, -(i as i64) * 1_000));
        // The shifted contour: N080 (X14.1 Z1.2 back to X20.1 Z−1.8) above Z−1.8, N070 at X20.1
        // down to Z−19.8, N060 to X41.1 Z−30.8 below it.
        let zk = -(i as i64) * 1_000;
        let want = if zk > -1_800 {
            // x = 20.1 + (zk + 1.8)·(14.1 − 20.1)/3
            20_100 + ((zk + 1_800) * -6_000) / 3_000
        } else if zk >= -19_800 {
            20_100
        } else {
            let num = (zk + 19_800) as f64 * 21_000.0 / -11_000.0;
            20_100 + num.round() as i64
        };
        assert_eq!(*x, want, "layer {}", i + 1);
    }
    let m = moves(&t);
    // Layer 1: rapid infeed to Z0, cut to X16.5, retract to X18.5 Z1, rapid to X41.
    assert_eq!(
        m[1..5],
        [
            Move::rapid(41_000, 0, Rule::G72Layer),
            Move::feed(16_500, 0, 1_000_000, Rule::G72Layer),
            Move::feed(18_500, 1_000, 1_000_000, Rule::G72Retract),
            Move::rapid(41_000, 1_000, Rule::G72Retract),
        ]
    );
    let p = passes(&t);
    assert_eq!(p[0], Pass { index: 1, kind: PassKind::Rough, diameter_depth: 2_000, rule: Rule::G72Layer });
    assert_eq!(p[31], Pass { index: 32, kind: PassKind::Semi, diameter_depth: 63_600, rule: Rule::G72Lastpass });
    let semi = Rule::G72Lastpass;
    let f = 1_000_000;
    let g70 = Rule::G70Path;
    let f30 = 300_000;
    let tail: Vec<Move> = m[m.len() - 10..].to_vec();
    assert_eq!(
        tail,
        [
            Move::rapid(41_100, -30_800, semi),
            Move::feed(20_100, -19_800, f, semi),
            Move::feed(20_100, -1_800, f, semi),
            Move::feed(14_100, 1_200, f, semi),
            Move::rapid(41_000, 1_000, Rule::G72Return),
            Move::rapid(41_000, -31_000, g70),
            Move::feed(20_000, -20_000, f30, g70),
            Move::feed(20_000, -2_000, f30, g70),
            Move::feed(14_000, 1_000, f30, g70),
            Move::rapid(41_000, 1_000, Rule::G70Return),
        ]
    );
    assert_eq!(p[32], Pass { index: 1, kind: PassKind::Finish, diameter_depth: 0, rule: Rule::G70Path });
}

/// CNT.FLOW, CYC.ONESHOT, CNT.MODAL: after G71/G72 the program resumes after N(nf); the motion
/// mode is what it was before (a G90 run goes on); the modal feed is the cycle block's F; the
/// machine ends at A. The contour blocks' F, S, T do not change the machine's state.
#[test]
fn flow_and_modal_state() {
    // G01 before; after the cycle `Z-1` is a G01 move at the G71's F0.3 (not the contour's F9).
    let src = "G1 X41 Z0 F0.1\nG71 U2 R1\nG71 P50 Q60 F0.3\nN50 G1 X20 F9\nN60 Z-10 F8\nZ-1\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let m = moves(&t);
    assert_eq!(*m.last().unwrap(), Move::feed(41_000, -1_000, 3_000, Rule::PrjModal));
    assert_eq!(m[m.len() - 2], Move::rapid(41_000, 0, Rule::G71Return));
    // The roughing feed is the cycle's, never the contour's.
    assert!(m.iter().filter(|m| m.kind == MoveKind::Feed && m.rule != Rule::PrjModal).all(|m| m.feed == 3_000));
    // The contour is not run again after G71: nothing between the return and `Z-1`.
    assert_eq!(m.iter().filter(|m| m.rule == Rule::PrjModal).count(), 2);
    // A G90 run goes on after G71: `X35` after the contour is another G90 cycle.
    let src = "G0 X50 Z2\nG90 X40 Z-10 F0.2\nG71 P50 Q60 F0.3\nN50 G1 X30\nN60 Z-10\nX35\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(p.last().unwrap(), &Pass { index: 2, kind: PassKind::Rough, diameter_depth: 15_000, rule: Rule::G90Path });
    // G71 uses the parameters when no first block was given (5132 = 1 mm, 5133 = 0.5 mm) and
    // keeps a first block's values apart from G72's.
    let t = expand("G0 X41 Z0\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", Config::default());
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1 .0).collect::<Vec<_>>(), [39_000, 37_000]);
    let t = expand("G0 X41 Z0\nG72 W3\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", Config::default());
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1 .0).collect::<Vec<_>>(), [39_000, 37_000]);
    let cfg = Config { params: Params { p5132_rough_depth: Some(1_500), p5133_rough_retract: Some(0), ..Params::default() }, ..Config::default() };
    let t = expand("G0 X41 Z0\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", cfg);
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1 .0).collect::<Vec<_>>(), [38_000]);
    // e = 0: no retract move; the rapid back follows the cut.
    let m = moves(&t);
    assert_eq!(m[2..4], [Move::feed(38_000, -10_000, 3_000, Rule::G71Layer), Move::rapid(38_000, 0, Rule::G71Retract)]);
    // A first block's omitted word falls back to its parameter.
    let t = expand("G0 X41 Z0\nG71 U1.5 R2\nG71 R0.25\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\n", Config::default());
    let m = moves(&t);
    assert_eq!(m[3], Move::feed(39_500, -9_750, 3_000, Rule::G71Retract));
    // Inside (s = +1): from X10 outward to X30, cutting toward −Z.
    let t = expand("G0 X10 Z2\nG71 U1 R0.5\nG71 P50 Q60 U-0.2 F0.3\nN50 G0 X30 Z2\nN60 G1 Z-20\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(layer_cuts(&t.events).iter().map(|c| c.1).collect::<Vec<_>>(), [(12_000, -20_000), (14_000, -20_000), (16_000, -20_000), (18_000, -20_000), (20_000, -20_000), (22_000, -20_000), (24_000, -20_000), (26_000, -20_000), (28_000, -20_000)]);
    let m = moves(&t);
    // Rapid infeeds (ns G00), retract inward (−X) at 45°.
    assert_eq!(m[0..4], [Move::rapid(10_000, 2_000, Rule::PrjModal), Move::rapid(12_000, 2_000, Rule::G71Layer), Move::feed(12_000, -20_000, 3_000, Rule::G71Layer), Move::feed(11_000, -19_500, 3_000, Rule::G71Retract)]);
}

#[test]
fn fill_equals_the_iterator() {
    // Every buffer size from 1 to one more than the whole stream.
    for program in [EXAMPLE_1, EXAMPLE_2] {
        let events = Expander::new(program.as_bytes(), Config::default()).count();
        let sizes: Vec<usize> = (1..=events + 1).collect();
        assert_fill_agrees(program, Config::default(), &sizes);
    }
    let sizes: Vec<usize> = (1..=40).chain([64, 100, 1_000, 4_096]).collect();
    for program in [
        EXAMPLE_1,
        EXAMPLE_2,
        "G0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\nN55 Z-5 M8\nN60 X50\n",
        "G0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\nZ-10\nX18\nN60 Z-20\n",
        "G0 X10 Z2\nG71 U1 R0.5\nG71 P50 Q60 U-0.2 F0.3\nN50 G0 X30 Z2\nN60 G1 Z-20\nG1 X5\n",
        "G0 X50 Z5\nN50 G1 X20 Z0 F0.1\nN60 Z-10 F0.2\nN70 G2 X30 Z-15 R5\nN80 G0 X50\nG0 X50 Z5\nG70 P50 Q80 U0.4 W0.1\nG1 Z6\n",
        "G0 X41 Z0\nG71 U1 R0\nG71 P50 Q60 F0.3\nN50 G1 X35\nN60 Z-10\nG70 P50 Q60\nG0 X#",
    ] {
        assert_fill_agrees(program, Config::default(), &sizes);
    }
    let src = "G0 X41 Z0\nG71 U0.001 R0.001\nG71 P50 Q60 F0.2\nN50 G1 X20.998\nN60 Z-10\n";
    assert_fill_agrees(src, with_max_passes(10_001), &[1, 5, 7, 64, 4_096]);
}
