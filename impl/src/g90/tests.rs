//! G90 and G94 (M003; docs/INTERPRETATION.md, "G90 and G94") on the whole expander: the seed's
//! fragments as the register reads them, the paths and their rule tags, pass headers, every
//! alarm with its word and rule, modal runs, grids, and `fill` against the iterator.
extern crate std;

use crate::tests::{expand, gcode, moves, passes};
use crate::expander::Expander;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Event, Grid, Increment, Move, Pass, PassKind, Rule, Units};
use std::vec::Vec;

fn al(code: AlarmCode, word: u8, rule: Rule, line: u32) -> Option<Alarm> {
    Some(Alarm::new(code, Some(word), rule, line))
}

fn alarm_of(src: &str) -> Option<Alarm> {
    expand(src, Config::default()).alarm
}

fn pass(index: u32, diameter_depth: i64, rule: Rule) -> Pass {
    Pass { index, kind: PassKind::Rough, diameter_depth, rule }
}

/// G90.EXAMPLE: `G90X40.Z-40.I-5.F0.3;35.` read as `G90 X40. Z-40. I-5. F0.3` and `X35.`, from
/// X50 Z2: pass 1 depth 10.000 (C.x = 40 + 2·(−5) = 30), rapid X30 Z2 (G90.TAPER), feed X40
/// Z-40, feed X50 Z-40, rapid X50 Z2; pass 2 with I-5 kept: cut start X25.
#[test]
fn g90_seed_taper() {
    let src = "G0 X50 Z2\nG90X40.Z-40.I-5.F0.3;X35.;\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let want = "(CYCLECHECK TRACE MM GRID 0.001)\n\
                G00 X50.000 Z2.000\n\
                (PASS 1 ROUGH DEPTH 10.000)\n\
                G00 X30.000 Z2.000\n\
                G01 X40.000 Z-40.000 F0.3000\n\
                G01 X50.000 Z-40.000 F0.3000\n\
                G00 X50.000 Z2.000\n\
                (PASS 2 ROUGH DEPTH 12.500)\n\
                G00 X25.000 Z2.000\n\
                G01 X35.000 Z-40.000 F0.3000\n\
                G01 X50.000 Z-40.000 F0.3000\n\
                G00 X50.000 Z2.000\n";
    assert_eq!(gcode(src, Config::default()), want);
    assert_eq!(passes(&t), [pass(1, 20_000, Rule::G90Path), pass(2, 25_000, Rule::G90Path)]);
    let m = moves(&t);
    assert_eq!(m[1], Move::rapid(30_000, 2_000, Rule::G90Taper));
    assert_eq!(m[2], Move::feed(40_000, -40_000, 3_000, Rule::G90Path));
    assert_eq!(m[3], Move::feed(50_000, -40_000, 3_000, Rule::G90Path));
    assert_eq!(m[4], Move::rapid(50_000, 2_000, Rule::G90Path));
    assert_eq!(m[5], Move::rapid(25_000, 2_000, Rule::G90Taper));
}

/// G90.EXAMPLE: `G90X40.Z40.F0.3;` read as `Z-40.`: a straight cut, ① tagged G90.PATH.
#[test]
fn g90_seed_straight() {
    let t = expand("G0 X50 Z2\nG90 X40. Z-40. F0.3\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t), [pass(1, 10_000, Rule::G90Path)]);
    assert_eq!(
        moves(&t)[1..],
        [
            Move::rapid(40_000, 2_000, Rule::G90Path),
            Move::feed(40_000, -40_000, 3_000, Rule::G90Path),
            Move::feed(50_000, -40_000, 3_000, Rule::G90Path),
            Move::rapid(50_000, 2_000, Rule::G90Path),
        ]
    );
}

/// G94.EXAMPLE: `G90X40.Z-3.5.F0.3;-7.;-10.;` under the G94 heading, read as `G94 X40. Z-3.5
/// F0.3`, `Z-7.`, `Z-10.`: three face cuts from X50 down to X40; depth = the Z infeed.
#[test]
fn g94_seed_face_steps() {
    let src = "G0 X50 Z2\nG94X40.Z-3.5F0.3;Z-7.;Z-10.;\n";
    let t = expand(src, Config::default());
    assert_eq!(t.alarm, None);
    let depths: Vec<(u32, i64)> = passes(&t).iter().map(|p| (p.index, p.diameter_depth)).collect();
    assert_eq!(depths, [(1, 11_000), (2, 18_000), (3, 24_000)]);
    assert!(passes(&t).iter().all(|p| p.rule == Rule::G94Path && p.kind == PassKind::Rough));
    let mut want = std::vec![Move::rapid(50_000, 2_000, Rule::PrjModal)];
    for z in [-3_500, -7_000, -10_000] {
        want.push(Move::rapid(50_000, z, Rule::G94Path));
        want.push(Move::feed(40_000, z, 3_000, Rule::G94Path));
        want.push(Move::feed(40_000, 2_000, 3_000, Rule::G94Path));
        want.push(Move::rapid(50_000, 2_000, Rule::G94Path));
    }
    assert_eq!(moves(&t), want);
    assert!(gcode(src, Config::default()).contains("(PASS 1 ROUGH DEPTH 5.500)\n"));
}

/// G94.TAPER (declared reading g94.k): the letter `end-minus-start` C.z = D.z − K (`G94 X20
/// Z-5 K-2` starts at Z−3), `start-minus-end` C.z = D.z + K (Z−7); ① tagged G94.TAPER; depth
/// |A.z − C.z|.
#[test]
fn g94_taper() {
    let t = expand("G0 X50 Z2\nG94 X20 Z-5 K-2 F0.2\n", Config::default());
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t), [pass(1, 10_000, Rule::G94Path)]);
    assert_eq!(moves(&t)[1], Move::rapid(50_000, -3_000, Rule::G94Taper));
    let mut c = Config::default();
    c.readings.g94_k = cycle_vocab::readings::G94K::StartMinusEnd;
    let t = expand("G0 X50 Z2\nG94 X20 Z-5 K-2 F0.2\n", c);
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t), [pass(1, 18_000, Rule::G94Path)]);
    assert_eq!(
        moves(&t)[1..],
        [
            Move::rapid(50_000, -7_000, Rule::G94Taper),
            Move::feed(20_000, -5_000, 2_000, Rule::G94Path),
            Move::feed(20_000, 2_000, 2_000, Rule::G94Path),
            Move::rapid(50_000, 2_000, Rule::G94Path),
        ]
    );
}

/// Step 5 in order (G90: W = 0, then the taper; G94: U = 0, then the taper), with the taper
/// bounds' edges; PRJ.NOOP: U = 0 with I = 0 is a cut along Z at the start X.
#[test]
fn cycle_checks() {
    let a = |second: &str| alarm_of(&std::format!("G0 X50 Z2\n{second}\n"));
    assert_eq!(a("G90 X40 F0.3"), al(AlarmCode::Geometry, b'Z', Rule::G90Format, 2));
    assert_eq!(a("G90 X40 Z2 I6 F0.3"), al(AlarmCode::Geometry, b'Z', Rule::G90Format, 2));
    // U = −10 on diameter: I > 0 of the other sign needs 2|I| ≤ 10.
    assert_eq!(a("G90 X40 Z-40 I5.001 F0.3"), al(AlarmCode::Geometry, b'I', Rule::G90Taper, 2));
    assert_eq!(a("G90 X40 Z-40 I5 F0.3"), None);
    assert_eq!(a("G90 X40 Z-40 I-50 F0.3"), None); // same sign: no bound
    assert_eq!(a("G90 X60 Z-40 I-5 F0.3"), None); // U = +10, 2|I| = 10
    assert_eq!(a("G90 X60 Z-40 I-5.001 F0.3"), al(AlarmCode::Geometry, b'I', Rule::G90Taper, 2));
    assert_eq!(a("G90 Z-40 I-5 F0.3"), None); // U = 0: no bound
    assert_eq!(a("G94 Z-5 F0.3"), al(AlarmCode::Geometry, b'X', Rule::G94Format, 2));
    assert_eq!(a("G94 Z-5 K9 F0.3"), al(AlarmCode::Geometry, b'X', Rule::G94Format, 2));
    // W = −7: k = C.z − D.z = −K (the letter) > 0 needs |K| ≤ 7.
    assert_eq!(a("G94 X40 Z-5 K-7.001 F0.3"), al(AlarmCode::Geometry, b'K', Rule::G94Taper, 2));
    assert_eq!(a("G94 X40 Z-5 K-7 F0.3"), None);
    assert_eq!(a("G94 X40 Z-5 K70 F0.3"), None); // k and W of one sign: no bound
    assert_eq!(a("G94 X40 Z9 K7 F0.3"), None);
    assert_eq!(a("G94 X40 Z9 K7.001 F0.3"), al(AlarmCode::Geometry, b'K', Rule::G94Taper, 2));
    assert_eq!(a("G94 X40 K-70 F0.3"), None); // Z omitted: W = 0, no bound (a face cut at A.z)
    // PRJ.NOOP: ① and ③ are moves to the current position.
    let t = expand("G0 X50 Z2\nG90 Z-40 F0.3\n", Config::default());
    assert_eq!(passes(&t), [pass(1, 0, Rule::G90Path)]);
    assert_eq!(moves(&t)[1..], [Move::feed(50_000, -40_000, 3_000, Rule::G90Path), Move::rapid(50_000, 2_000, Rule::G90Path)]);
    // I = 5 at U = −10: the cut starts at A.x, ① is not emitted; the depth is 0.
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 I5 F0.3\n", Config::default());
    assert_eq!(passes(&t)[0].diameter_depth, 0);
    assert_eq!(moves(&t)[1], Move::feed(40_000, -40_000, 3_000, Rule::G90Path));
}

/// Steps 2–4 for G90/G94 blocks: codes, conflicts, allowed words (alphabetically), values,
/// the missing feed.
#[test]
fn word_alarms() {
    let a = alarm_of;
    assert_eq!(a("G90 G94 X1 Z1 F1"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 1));
    assert_eq!(a("G1 G90 X1 Z1 F1"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 1));
    assert_eq!(a("G90 G90 X1 Z1 F1"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 1));
    assert_eq!(a("G91 X1"), al(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, 1));
    assert_eq!(a("G90.0 X1"), al(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, 1));
    assert_eq!(a("G90 X40 U1 Z-4 F1"), al(AlarmCode::Conflict, b'U', Rule::ComAbsInc, 1));
    assert_eq!(a("G94 X40 Z-4 W1 F1"), al(AlarmCode::Conflict, b'W', Rule::ComAbsInc, 1));
    // F with I is no conflict in G90: I is the taper.
    assert_eq!(a("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3"), None);
    assert_eq!(a("G90 X40 Z-40 R1 F0.3"), al(AlarmCode::WordNotAllowed, b'R', Rule::PrjWord, 1));
    assert_eq!(a("G90 X40 Z-40 K1 P1 F0.3"), al(AlarmCode::WordNotAllowed, b'K', Rule::PrjWord, 1));
    assert_eq!(a("G94 X40 Z-4 I1 F0.3"), al(AlarmCode::WordNotAllowed, b'I', Rule::PrjWord, 1));
    assert_eq!(a("G94 X40 Z-4 R1 F0.3"), al(AlarmCode::WordNotAllowed, b'R', Rule::PrjWord, 1));
    // Modal: the words of the mode's code.
    assert_eq!(a("G0 X50 Z2\nG90 X40 Z-40 F0.3\nX30 J1"), al(AlarmCode::WordNotAllowed, b'J', Rule::PrjWord, 3));
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(expand("G90 X40 Z-40 L1 F0.3", fanuc).alarm, al(AlarmCode::WordNotAllowed, b'L', Rule::PrjWord, 1));
    // Values, alphabetically.
    assert_eq!(a("G90 X40 Z-40 I1000000 F0.3"), al(AlarmCode::OutOfRange, b'I', Rule::ComRanges, 1));
    assert_eq!(a("G90 X40 Z-40 I999999999999999999 F0.3"), al(AlarmCode::OutOfRange, b'I', Rule::ComRanges, 1));
    assert_eq!(a("G90 X40 Z-40 I0.0001 F0"), al(AlarmCode::OutOfRange, b'F', Rule::ComRanges, 1));
    assert_eq!(a("G90 X40 Z-40 I0.0001 F1"), al(AlarmCode::Precision, b'I', Rule::ComUnits, 1));
    assert_eq!(a("G94 X40 Z-4 K-1000000 F1"), al(AlarmCode::OutOfRange, b'K', Rule::ComRanges, 1));
    assert_eq!(a("G94 X1000000 Z-4 F1"), al(AlarmCode::OutOfRange, b'X', Rule::ComRanges, 1));
    // (4) no feed: only with axis words, before the cycle's checks.
    assert_eq!(a("G0 X50 Z2\nG90 X40"), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2));
    assert_eq!(a("G0 X50 Z2\nG94 Z-3"), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2));
    assert_eq!(a("G90 I-5\nG94 K1"), None);
}

/// PRJ.DIALECT: under nc201 G90 stays the absolute mode and G94 is not defined.
#[test]
fn nc201() {
    let c = Config { dialect: Dialect::Nc201, ..Config::default() };
    let t = expand("G91 G0 X10\nG90 G1 X4 Z-1 F1\n", c);
    assert_eq!((t.alarm, moves(&t).len()), (None, 2));
    assert_eq!(moves(&t)[1], Move::feed(4_000, -1_000, 10_000, Rule::PrjModal));
    assert_eq!(expand("G94 X1 Z1 F1", c).alarm, al(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, 1));
    assert_eq!(expand("G0 X1\nG94", c).alarm, al(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, 2));
}

/// G90.MODAL, G94.MODAL: a run keeps X, Z and the taper; a block without axis words sets the
/// taper and the feed; G76/G78 do not end a run; another motion mode does, and so does the
/// other cutting code; the code written again in its own mode goes on with the run.
#[test]
fn modal_runs() {
    let c = Config::default();
    let cut_starts = |t: &cycle_vocab::text::Trace| -> Vec<(i64, i64)> {
        t.events
            .windows(2)
            .filter_map(|w| match w {
                [Event::Pass(_), Event::Move(m)] => Some((m.x, m.z)),
                _ => None,
            })
            .collect()
    };
    let indices = |t: &cycle_vocab::text::Trace| passes(t).iter().map(|p| p.index).collect::<Vec<_>>();
    // The taper and the feed set by a block without axis words.
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 F0.3\nI-5 F0.5\nX35\n", c);
    assert_eq!((t.alarm, indices(&t)), (None, std::vec![1, 2]));
    assert_eq!(cut_starts(&t), [(40_000, 2_000), (25_000, 2_000)]);
    assert_eq!(moves(&t)[6], Move::feed(35_000, -40_000, 5_000, Rule::G90Path));
    // G76/G78 first blocks between the blocks of a run: the run goes on.
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG76 P011060 Q0.1 R0.1\nG78 P010060\nX35\n", c);
    assert_eq!((t.alarm, indices(&t)), (None, std::vec![1, 2]));
    assert_eq!(cut_starts(&t)[1], (25_000, 2_000));
    // The code written again in its mode: the same run (index 2, I and Z kept).
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG90 X35\n", c);
    assert_eq!((indices(&t), cut_starts(&t)[1]), (std::vec![1, 2], (25_000, 2_000)));
    // U and W from the start point; the next block's U too.
    let t = expand("G0 X50 Z2\nG90 U-10 W-42 F0.3\nU-15\n", c);
    assert_eq!(moves(&t)[2], Move::feed(40_000, -40_000, 3_000, Rule::G90Path));
    assert_eq!(moves(&t)[6], Move::feed(35_000, -40_000, 3_000, Rule::G90Path));
    // A new run after G00: I = 0, the omitted Z at the current position (W = 0).
    assert_eq!(
        expand("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG0 X50\nG90 X35\n", c).alarm,
        al(AlarmCode::Geometry, b'Z', Rule::G90Format, 4)
    );
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG0 X50\nG90 X35 Z-40\n", c);
    assert_eq!((indices(&t), cut_starts(&t)[1]), (std::vec![1, 1], (35_000, 2_000)));
    // G94 after G90 is a new run: X omitted is the current X (U = 0), K is 0.
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG94 Z-3\n", c);
    assert_eq!(t.alarm, al(AlarmCode::Geometry, b'X', Rule::G94Format, 3));
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG94 X40 Z-3\n", c);
    assert_eq!((t.alarm, indices(&t)), (None, std::vec![1, 1]));
    assert_eq!(cut_starts(&t)[1], (50_000, -3_000));
    // A thread move ends the run; a G92 run after it starts anew, and so does G90 after G92.
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 I-5 F0.3\nG32 Z1 F1\nG0 Z2\nG90 X35 Z-40 F0.3\n", c);
    assert_eq!((t.alarm, indices(&t)), (None, std::vec![1, 1]));
    assert_eq!(cut_starts(&t)[1], (35_000, 2_000));
    let t = expand("G0 X50 Z2\nG90 X40 Z-40 F0.3\nG92 X48 Z-20 F1\nG90 X35 Z-40 F0.3\nX30\n", c);
    assert_eq!((t.alarm, indices(&t)), (None, std::vec![1, 1, 1, 2]));
}

/// COM.UNITS: inch and ISC grids; F on the lead grid, I on the length grid.
#[test]
fn grids() {
    let inch = Config { grid: Grid { units: Units::Inch, increment: Increment::Isb }, ..Config::default() };
    let t = expand("G0 X2. Z0.1\nG90 X1.5 Z-1. I-0.1 F0.01\n", inch);
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t), [pass(1, 7_000, Rule::G90Path)]);
    assert_eq!(moves(&t)[1], Move::rapid(13_000, 1_000, Rule::G90Taper));
    assert_eq!(moves(&t)[2], Move::feed(15_000, -10_000, 1_000, Rule::G90Path));
    assert_eq!(expand("G90 X1.5 Z-1. I0.00001 F0.01", inch).alarm, al(AlarmCode::Precision, b'I', Rule::ComUnits, 1));
    let isc = Config { grid: Grid { units: Units::Metric, increment: Increment::Isc }, ..Config::default() };
    let t = expand("G0 X50 Z2\nG94 X40.0001 Z-3.5 K0.0001 F0.3\n", isc);
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t), [pass(1, 2 * 55_001, Rule::G94Path)]);
    assert_eq!(moves(&t)[1], Move::rapid(500_000, -35_001, Rule::G94Taper));
    assert_eq!(moves(&t)[2], Move::feed(400_001, -35_000, 3_000, Rule::G94Path));
    let inch_isc = Config { grid: Grid { units: Units::Inch, increment: Increment::Isc }, ..Config::default() };
    let t = expand("G0 X2. Z0.1\nG90 X1.5 Z-1. I-0.00001 F0.01\n", inch_isc);
    assert_eq!(moves(&t)[1], Move::rapid(149_998, 10_000, Rule::G90Taper));
}

/// The largest words: every sum is exact; the cycle returns to its start.
#[test]
fn extreme_words() {
    let c = Config { start_x: 999_999_999, start_z: 999_999_999, ..Config::default() };
    let t = expand("G90 X-999999.999 Z-999999.999 I-999999.999 F9999\n", c);
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t)[0].diameter_depth, 999_999_999 + 999_999_999 + 1_999_999_998);
    assert_eq!(moves(&t)[0], Move::rapid(-2_999_999_997, 999_999_999, Rule::G90Taper));
    assert_eq!(moves(&t).last(), Some(&Move::rapid(999_999_999, 999_999_999, Rule::G90Path)));
    let t = expand("G94 X-999999.999 Z-999999.999 K999999.999 F9999\n", c);
    assert_eq!(t.alarm, None);
    assert_eq!(passes(&t)[0].diameter_depth, 2 * 2_999_999_997);
}

/// `fill` writes the iterator's stream for G90/G94 programs, for every buffer size up to a
/// cycle and more (the generators do not write G90/G94 yet).
#[test]
fn fill_equals_the_iterator() {
    let programs = [
        "G0 X50 Z2\nG90X40.Z-40.I-5.F0.3;X35.;\nG94 X40 Z-3.5;Z-7;Z-10\nG0 X50 Z2\nG90 Z-40\nM30\n",
        "G0 X50 Z2\nG90 X40 Z-40 I5 F0.3\nG94 X40 Z2 K-3\nG94 X40 Z-3 K7.001\n",
    ];
    for src in programs {
        let want: Vec<_> = Expander::new(src.as_bytes(), Config::default()).collect();
        for size in 1..=12 {
            let mut e = Expander::new(src.as_bytes(), Config::default());
            let mut buf = std::vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); size];
            let mut got = Vec::new();
            loop {
                match e.fill(&mut buf) {
                    Ok(0) => break,
                    Ok(n) => got.extend(buf[..n].iter().copied().map(Ok)),
                    Err(a) => got.push(Err(a)),
                }
            }
            assert_eq!(got, want, "buffer of {size}: {src}");
        }
    }
}

/// No panic on random G90/G94 programs with extreme words in every grid and dialect; without
/// an alarm the cycles return to their start (the machine ends at A).
#[test]
fn random_cycles_never_panic_and_return() {
    use crate::tests::{grid_of_round, xorshift};
    let mut s = 0x6790_6794_0000_0001u64;
    // Lengths legal on every grid (9999.9 in at the inch ISC grid is 999 990 000 increments).
    let vals = ["0", "1", "-1", "0.001", "40", "-40", "9999.9", "-9999.9", "2.5", "-7"];
    let codes = ["G90", "G94", "", "", "G76 P011060", "G0", "G1"];
    let mut checked = 0;
    let mut alarms = std::collections::BTreeMap::new();
    for round in 0..4_000u32 {
        let mut r = || xorshift(&mut s);
        let grid = grid_of_round(round);
        let dialect = [Dialect::Gsk, Dialect::Fanuc, Dialect::Gsk, Dialect::Nc201][(r() % 4) as usize];
        let mut src = std::format!("G0 X{} Z{} F0.3\n", vals[(r() % 10) as usize], vals[(r() % 10) as usize]);
        let mut taper = "";
        for _ in 0..4 {
            let code = codes[(r() % 7) as usize];
            taper = match code {
                "G90" => "I",
                "G94" => "K",
                "G0" | "G1" => "",
                _ => taper,
            };
            src.push_str(code);
            if !code.starts_with("G76") {
                for letter in [["X", "U"][(r() % 2) as usize], ["Z", "W"][(r() % 2) as usize], taper] {
                    if !letter.is_empty() && r() % 3 != 0 {
                        src.push_str(&std::format!(" {letter}{}", vals[(r() % 10) as usize]));
                    }
                }
            }
            src.push('\n');
        }
        let t = expand(&src, Config { grid, dialect, ..Config::default() });
        if let Some(a) = t.alarm {
            *alarms.entry(std::format!("{:?} {:?}", a.code, a.rule)).or_insert(0) += 1;
        }
        // Every G90/G94 cycle ends where it began (where the machine stood at its header).
        let cut = |r: Rule| matches!(r, Rule::G90Path | Rule::G90Taper | Rule::G94Path | Rule::G94Taper);
        let (mut pos, mut open) = ((0, 0), None);
        let mut close = |open: &mut Option<(i64, i64)>, pos: (i64, i64)| {
            if let Some(a) = open.take() {
                assert_eq!(pos, a, "{src}");
                checked += 1;
            }
        };
        for e in &t.events {
            match e {
                Event::Pass(p) => {
                    close(&mut open, pos);
                    open = cut(p.rule).then_some(pos);
                }
                Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => panic!("no dwell or spindle event in G90/G94"),
                Event::Move(m) => {
                    if !cut(m.rule) {
                        close(&mut open, pos);
                    }
                    pos = (m.x, m.z);
                }
            }
        }
        close(&mut open, pos);
    }
    assert!(checked > 1_500, "{checked} {alarms:?}");
}
