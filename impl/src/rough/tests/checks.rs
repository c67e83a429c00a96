//! Every alarm of the contour cycles' register with its code, word, rule and line: the cycle
//! blocks' words, CNT.FIND / CNT.MAX, the contour blocks' checks, the cycle checks, the pass
//! bound.
use super::*;

/// G71.FORMAT, G71.DEPTH, G71.RETRACT, G72.DEPTH, G70.FORMAT, CNT.PQ: the words and values of
/// the cycle blocks, and the missing words in their order.
#[test]
fn cycle_block_words() {
    let a = |src: &str| alarm_of(&format!("G0 X41 Z0\n{src}"));
    let oor = |w: u8, rule: Rule| al(AlarmCode::OutOfRange, w, rule, 2);
    let wna = |w: u8| al(AlarmCode::WordNotAllowed, w, Rule::PrjWord, 2);
    // First blocks.
    assert_eq!(a("G71 U0 R1"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U-1"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U1000000"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U999999999999999999"), oor(b'U', Rule::G71Depth));
    assert_eq!(a("G71 U1 R-0.001"), oor(b'R', Rule::G71Retract));
    assert_eq!(a("G71 U1 R1000000"), oor(b'R', Rule::G71Retract));
    assert_eq!(a("G71 U1.0001"), al(AlarmCode::Precision, b'U', Rule::ComUnits, 2));
    assert_eq!(a("G71 U1 R0"), None);
    assert_eq!(a("G71 U1 F1"), wna(b'F'));
    assert_eq!(a("G71 W1"), wna(b'W'));
    assert_eq!(a("G72 W0"), oor(b'W', Rule::G72Depth));
    assert_eq!(a("G72 W1 R-1"), oor(b'R', Rule::G72Depth));
    assert_eq!(a("G72 U1"), wna(b'U'));
    assert_eq!(a("G72 W1 R1 S100 T0101 M8 N5"), None);
    // Second blocks: allowed P Q U W F (and S T …); values; missing F, P, Q.
    assert_eq!(a("G71 P1 Q2 F1 X1"), wna(b'X'));
    assert_eq!(a("G71 P1 Q2 F1 R1"), wna(b'R'));
    assert_eq!(a("G72 Q2 F1 I1"), wna(b'I'));
    assert_eq!(a("G70 P1 Q2 R1"), wna(b'R'));
    for code in ["G70", "G71", "G72"] {
        assert_eq!(a(&format!("{code} P1.0 Q2 F1")), al(AlarmCode::NotInteger, b'P', Rule::ComRanges, 2), "{code}");
        assert_eq!(a(&format!("{code} P0 Q2 F1")), oor(b'P', Rule::CntPq), "{code}");
        assert_eq!(a(&format!("{code} P1 Q100000 F1")), oor(b'Q', Rule::CntPq), "{code}");
        assert_eq!(a(&format!("{code} P1 Q-2 F1")), oor(b'Q', Rule::CntPq), "{code}");
        assert_eq!(a(&format!("{code} P1 Q2 U1000000 F1")), oor(b'U', Rule::ComRanges), "{code}");
        assert_eq!(a(&format!("{code} P1 Q2 W-1000000 F1")), oor(b'W', Rule::ComRanges), "{code}");
        assert_eq!(a(&format!("{code} P1 Q2")), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2), "{code}");
        assert_eq!(a(&format!("{code} Q2 F1")), al(AlarmCode::MissingWord, b'P', Rule::CntPq, 2), "{code}");
        assert_eq!(a(&format!("{code} P1 F1")), al(AlarmCode::MissingWord, b'Q', Rule::CntPq, 2), "{code}");
        assert_eq!(a(&format!("{code} P1")), al(AlarmCode::MissingWord, b'F', Rule::ComLead, 2), "{code}");
        // With a modal feed F may be omitted (then P, Q are looked for).
        assert_eq!(alarm_of(&format!("G1 X41 Z0 F1\n{code} P1 Q2")), al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, 2), "{code}");
    }
}

/// A G71 cycle from X41 Z0 (Δd 2, e 1, F0.2) around the contour `body` (its blocks N50 …),
/// the cycle block on line 3: `G71 P50 Q<nf>`.
fn g71(nf: u32, body: &str) -> String {
    format!("G0 X41 Z0\nG71 U2 R1\nG71 P50 Q{nf} F0.2\n{body}")
}

/// CNT.FIND, CNT.MAX, CNT.RANGE for G71/G72: the contour right after the P/Q block, N(nf)
/// before the end, at most 1 000 blocks; a lexing alarm inside is that alarm; the find comes
/// before the blocks' own checks.
#[test]
fn contour_find_and_bound() {
    let nf = |line| al(AlarmCode::BlockNotFound, b'Q', Rule::CntFind, line);
    let np = |line| al(AlarmCode::BlockNotFound, b'P', Rule::CntFind, line);
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN60 Z-10\n")), None);
    // The block after the P/Q block is not N50, or there is none.
    assert_eq!(alarm_of(&g71(60, "N49 G1 X20\nN50 X10\nN60 Z-10\n")), np(3));
    assert_eq!(alarm_of(&g71(60, "G1 X20\nN50 X10\nN60 Z-10\n")), np(3));
    assert_eq!(alarm_of(&g71(60, "")), np(3));
    assert_eq!(alarm_of(&g71(60, "(only a comment)\n\n")), np(3));
    // Blank and comment lines are no blocks: N50 is still the next block.
    assert_eq!(alarm_of(&g71(60, "\n(c)\nN50 G1 X20\n;\nN60 Z-10\n")), None);
    // N(nf) missing before the end; N(nf) = N(ns) is a one-block contour (c = 0 then).
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN61 Z-10\n")), nf(3));
    assert_eq!(alarm_of(&g71(50, "N50 G1 X20\n")), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 3));
    // N50.0 and N050 are N50; N(nf) is the first one at or after N(ns).
    assert_eq!(alarm_of(&g71(60, "N050 G1 X20\nN60.0 Z-10\nN60 X50\n")), None);
    // A lexing alarm while the contour is read, on its line — before a missing N(nf).
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 Z-5 #\nN59 X30\n")), al(AlarmCode::BadCharacter, b'#', Rule::PrjLex, 5));
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 Z-5 (open\n")), al(AlarmCode::UnclosedComment, b'(', Rule::PrjLex, 5));
    // The find before the blocks' checks: a bad block and no N(nf) is BLOCK NOT FOUND.
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 G04 Z-5\nN59 X30\n")), nf(3));
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nN55 G04 Z-5\nN60 X30\n")), al(AlarmCode::WordNotAllowed, b'G', Rule::CntWords, 5));
    // CNT.MAX: 1 000 blocks are a contour; a 1 001st without N(nf) is CONTOUR TOO LONG, even
    // when it is N(nf) itself or the program would end without N(nf) after it.
    let body = |blocks: usize, last: &str| {
        let mut s = String::from("N50 G1 X20\n");
        for i in 1..blocks - 1 {
            s += &format!("W-0.01 (block {})\n", i + 1);
        }
        s + last
    };
    let t = expand(&g71(60, &body(1_000, "N60 X50\n")), Config::default());
    assert_eq!(t.alarm, None);
    // Every one of the 998 W-0.01 steps is an element of the semi-finish pass.
    assert_eq!(moves(&t).iter().filter(|m| m.rule == Rule::G71Lastpass).count(), 1 + 998 + 1);
    let long = |line| al(AlarmCode::ContourTooLong, b'Q', Rule::CntMax, line);
    assert_eq!(alarm_of(&g71(60, &body(1_001, "N60 X50\n"))), long(3));
    assert_eq!(alarm_of(&g71(60, &body(1_001, "X50\n"))), long(3));
    assert_eq!(alarm_of(&g71(60, &body(1_000, "X50\n"))), nf(3));
    assert_eq!(alarm_of(&g71(60, &body(1_002, "N60 X50\n"))), long(3));
}

/// CNT.WORDS, CNT.NOSUB and every block check inside a contour, on the block's own line:
/// G codes other than G00–G03, M codes, other letters; conflicts; values; arcs; no MISSING
/// WORD F; T while compensating. The first block's alarm in program order is the one named.
#[test]
fn contour_block_checks() {
    let a = |block: &str| alarm_of(&g71(60, &format!("N50 G1 X20\n{block}\nN60 X50\n")));
    let wna = |w: u8, rule: Rule| al(AlarmCode::WordNotAllowed, w, rule, 5);
    for g in ["G04", "G70", "G50 X1", "G90", "G41", "G40", "G20", "G21", "G1.5", "G5", "G32", "G96", "G0 G99"] {
        assert_eq!(a(&format!("{g} Z-5")), wna(b'G', Rule::CntWords), "{g}");
    }
    assert_eq!(a("M98 P100"), wna(b'M', Rule::CntNosub));
    assert_eq!(a("M99"), wna(b'M', Rule::CntNosub));
    assert_eq!(a("M98.0"), wna(b'M', Rule::CntNosub));
    assert_eq!(a("M3 Z-5"), wna(b'M', Rule::CntWords));
    assert_eq!(a("M30"), wna(b'M', Rule::CntWords));
    assert_eq!(a("M1.5"), wna(b'M', Rule::CntWords));
    // M before the two-motion-codes conflict; G before M.
    assert_eq!(a("G0 G1 M3"), wna(b'M', Rule::CntWords));
    assert_eq!(a("G4 M98"), wna(b'G', Rule::CntWords));
    for l in ["O1", "P1", "Q1", "J1", "L1", "D1", "E1", "H1", "A1", "B1", "V1"] {
        assert_eq!(a(&format!("Z-5 {l}")), wna(l.as_bytes()[0], Rule::CntWords), "{l}");
    }
    // Arc words in a G00/G01 block are PRJ.WORD, as in any block; alphabetical order decides.
    assert_eq!(a("Z-5 R1"), wna(b'R', Rule::PrjWord));
    assert_eq!(a("Z-5 I1 O1"), wna(b'I', Rule::PrjWord));
    assert_eq!(a("Z-5 K1 J1"), wna(b'J', Rule::CntWords));
    // Conflicts.
    assert_eq!(a("G0 G1 Z-5"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 5));
    assert_eq!(a("G1 G1 Z-5"), al(AlarmCode::Conflict, b'G', Rule::PrjWord, 5));
    assert_eq!(a("X1 U1"), al(AlarmCode::Conflict, b'U', Rule::ComAbsInc, 5));
    assert_eq!(a("Z1 W1 O1"), al(AlarmCode::Conflict, b'W', Rule::ComAbsInc, 5));
    assert_eq!(a("G2 X30 W-5 R5 I1"), al(AlarmCode::Conflict, b'R', Rule::ArcFormat, 5));
    // Values.
    assert_eq!(a("Z-5 F0"), al(AlarmCode::OutOfRange, b'F', Rule::ComRanges, 5));
    assert_eq!(a("Z-1000000"), al(AlarmCode::OutOfRange, b'Z', Rule::ComRanges, 5));
    assert_eq!(a("Z-5.0001"), al(AlarmCode::Precision, b'Z', Rule::ComUnits, 5));
    assert_eq!(a("G2 X30 W-5 R0"), al(AlarmCode::OutOfRange, b'R', Rule::ArcR, 5));
    // Arcs: missing R, then the geometry, each on its line; no feed is needed.
    assert_eq!(a("G2 X30 W-5"), al(AlarmCode::MissingWord, b'R', Rule::ArcFormat, 5));
    assert_eq!(a("G2 X20 W0 R5"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 5));
    assert_eq!(a("G2 X30 W-5 I0 K0"), al(AlarmCode::Geometry, b'I', Rule::ArcIk, 5));
    assert_eq!(a("G2 X30 W-50 R5"), al(AlarmCode::Geometry, b'R', Rule::ArcR, 5));
    assert_eq!(a("G3 X30 W-5 K-6"), al(AlarmCode::Geometry, b'X', Rule::ArcTol, 5));
    // No MISSING WORD F in a contour (the cycle block's F is the feed).
    assert_eq!(alarm_of("G0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\nN60 G2 X30 W-5 R5\n"), None);
    // T while G41/G42 is in force (TNRC.SWITCH, the contour block's line).
    let comp = |body: &str| alarm_of(&format!("G42\nG0 X41 Z0\nG71 U2 R1\nG71 P50 Q60 F0.2\nN50 G1 X20\n{body}\nN60 X50\n"));
    assert_eq!(comp("Z-5 T0202"), al(AlarmCode::WordNotAllowed, b'T', Rule::TnrcSwitch, 6));
    assert_eq!(comp("Z-5 S500"), None);
    // The first alarm in program order.
    assert_eq!(
        alarm_of(&g71(60, "N50 G1 X20\nZ-5 O1\nG4 Z-6\nN60 X50\n")),
        al(AlarmCode::WordNotAllowed, b'O', Rule::CntWords, 5)
    );
    // Blocks without axis words move nothing; their F waits for the next move (G70).
    assert_eq!(alarm_of(&g71(60, "N50 G1 X20\nF0.5 S300 T0101\nN60 X50 Z-5\n")), None);
}

/// CNT.FIRST, G71.TYPE2, G71.FIRST, G71.MONOTONE (and G72's): the cycle checks after the
/// contour's own, in the register's order. Lines (docs/INTERPRETATION.md, G71 "Alarm lines"):
/// CNT.FIRST, TYPE2 and FIRST on the ns block's, c = 0 on the cycle block's, the monotonicity of
/// an element on the element's.
#[test]
fn cycle_checks() {
    let a = |body: &str| alarm_of(&g71(60, body));
    // CNT.FIRST: the ns block writes no motion code, or an arc.
    assert_eq!(a("N50 X20\nN60 Z-10\n"), al(AlarmCode::MissingWord, b'G', Rule::CntFirst, 4));
    assert_eq!(a("N50 G2 X20 Z0 R5\nN60 G1 Z-10\n"), al(AlarmCode::Geometry, b'R', Rule::ArcR, 4));
    assert_eq!(a("N50 G2 X31 Z0 R5\nN60 G1 Z-10\n"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntFirst, 4));
    assert_eq!(a("N50 G3 X31 R5\nN60 G1 Z-10\n"), al(AlarmCode::WordNotAllowed, b'G', Rule::CntFirst, 4));
    // An ns block without motion code is checked as G00/G01: an arc word in it is PRJ.WORD.
    assert_eq!(a("N50 X20 R5\nN60 G1 Z-10\n"), al(AlarmCode::WordNotAllowed, b'R', Rule::PrjWord, 4));
    // G71.TYPE2 (the ns block moves Z) before G71.FIRST; by motion, not by words.
    assert_eq!(a("N50 G1 X20 Z-1\nN60 Z-10\n"), al(AlarmCode::Unsupported, b'Z', Rule::G71Type2, 4));
    assert_eq!(a("N50 G1 X41 W-1\nN60 Z-10\n"), al(AlarmCode::Unsupported, b'Z', Rule::G71Type2, 4));
    assert_eq!(a("N50 G1 X20 Z0\nN60 Z-10\n"), None);
    assert_eq!(a("N50 G1 X41\nN60 Z-10\n"), al(AlarmCode::Geometry, b'X', Rule::G71First, 4));
    assert_eq!(a("N50 G1 Z0\nN60 Z-10\n"), al(AlarmCode::Geometry, b'X', Rule::G71First, 4));
    // G71.MONOTONE: c = 0 (the contour ends at A′'s Z), then element by element, X before Z.
    assert_eq!(a("N50 G1 X20\nN60 X30\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 3));
    assert_eq!(a("N50 G1 X20\nN55 Z-10\nN60 Z0\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 3));
    assert_eq!(a("N50 G1 X20\nZ-10\nX18\nN60 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    assert_eq!(a("N50 G1 X20\nZ-10\nZ-5\nN60 Z-20\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 6));
    assert_eq!(a("N50 G1 X20\nZ-10\nX18 Z-5\nN60 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    // Equal X or equal Z pieces are legal; a rapid is an element like any.
    assert_eq!(a("N50 G1 X20\nZ-10\nX30\nG0 X35 Z-12\nN60 G1 Z-20\n"), None);
    // Arcs: a quadrant point strictly inside the sweep. From X20 Z-10: G02 to X30 Z-15 about
    // X30 Z-10 (I5) is a quarter (legal); G03 the long way round turns in X first.
    assert_eq!(a("N50 G1 X20\nZ-10\nG2 X30 Z-15 I5\nN60 G1 Z-20\n"), None);
    assert_eq!(a("N50 G1 X20\nZ-10\nG3 X30 Z-15 I5\nN60 G1 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    // A half circle through an extreme Z (its ends monotone: X20 → X40 at one Z): Z turns.
    assert_eq!(a("N50 G1 X20\nZ-10\nG2 X40 Z-10 R5\nN60 G1 Z-20\n"), al(AlarmCode::Geometry, b'Z', Rule::G71Monotone, 6));
    // An arc whose ends go the wrong way fails on its ends (X).
    assert_eq!(a("N50 G1 X20\nZ-10\nG2 X10 Z-15 I-5\nN60 G1 Z-20\n"), al(AlarmCode::Geometry, b'X', Rule::G71Monotone, 6));
    // G72: TYPE2 on X, FIRST on Z, c = 0 on X; Z (the layer axis) before X.
    let b = |body: &str| alarm_of(&format!("G0 X41 Z1\nG72 W1 R1\nG72 P50 Q60 F0.2\n{body}"));
    assert_eq!(b("N50 G0 X40 Z-20\nN60 G1 X10\n"), al(AlarmCode::Unsupported, b'X', Rule::G72Type2, 4));
    assert_eq!(b("N50 G0 X41 Z1\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'Z', Rule::G72First, 4));
    assert_eq!(b("N50 G0 Z-20\nN60 G1 Z-10\n"), al(AlarmCode::Geometry, b'X', Rule::G72Monotone, 3));
    assert_eq!(b("N50 G0 Z-20\nX30 Z-21\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'Z', Rule::G72Monotone, 5));
    assert_eq!(b("N50 G0 Z-20\nX50 Z-21\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'Z', Rule::G72Monotone, 5));
    assert_eq!(b("N50 G0 Z-20\nX50 Z-19\nN60 G1 X10\n"), al(AlarmCode::Geometry, b'X', Rule::G72Monotone, 5));
    assert_eq!(b("N50 G0 Z-20\nX30 Z-19\nN60 G1 X10\n"), None);
}

/// PRJ.MAXPASS: K layers + the semi-finish pass against `max_passes`, before any motion of the
/// cycle — `TOO MANY PASSES` on U (G71) or W (G72), the cycle block's line. 10 000 layers run
/// within max_passes = 10 001, and one more is refused.
#[test]
fn pass_bound() {
    // A = X41 Z0, Δd = 0.001: layer k at X41 − 0.002k; Q₀ = X20.998: layers while
    // 0.002k < 20.002, k ≤ 10 000.
    let src = "G0 X41 Z0\nG71 U0.001 R0.001\nG71 P50 Q60 F0.2\nN50 G1 X20.998\nN60 Z-10\n";
    let t = expand(src, with_max_passes(10_001));
    assert_eq!(t.alarm, None);
    let p = passes(&t);
    assert_eq!(p.len(), 10_001);
    assert_eq!(p[9_999], Pass { index: 10_000, kind: PassKind::Rough, diameter_depth: 20_000, rule: Rule::G71Layer });
    assert_eq!(p[10_000].kind, PassKind::Semi);
    let cuts = layer_cuts(&t.events);
    assert_eq!(cuts[9_999].1, (21_000, -10_000));
    let refused = expand(src, with_max_passes(10_000));
    assert_eq!(refused.alarm, al(AlarmCode::TooManyPasses, b'U', Rule::PrjMaxPass, 3));
    // Before any motion of the cycle: only the G0 rapid stands in the trace.
    assert_eq!(refused.events.len(), 1);
    // The default bound (10 000) refuses it as well; G72 names W.
    assert_eq!(alarm_of(src), al(AlarmCode::TooManyPasses, b'U', Rule::PrjMaxPass, 3));
    let g72 = "G0 X41 Z1\nG72 W0.001 R0\nG72 P50 Q60 F0.2\nN50 G0 Z-20\nN60 G1 X10\n";
    // Layers at Z1 − 0.001k while above Q₀.z = −20: k ≤ 20 999, then the semi-finish pass.
    let t = expand(g72, with_max_passes(21_000));
    assert_eq!((t.alarm, passes(&t).len()), (None, 21_000));
    assert_eq!(expand(g72, with_max_passes(20_999)).alarm, al(AlarmCode::TooManyPasses, b'W', Rule::PrjMaxPass, 3));
    // The cut-positive end counts: Δw moves the contour behind A.z, so the deep layers (the
    // contour's start) do not cut and are no layers; the bound sees only the layers that cut.
    let behind = "G0 X41 Z0\nG71 U0.5 R0\nG71 P50 Q60 W5 F0.2\nN50 G1 X1\nN60 X40 Z-39\n";
    let t = expand(behind, Config::default());
    assert_eq!(t.alarm, None);
    // Q from X1 Z5 to X40 Z-34 (a line): the cut at X_k is behind Z0 while X_k < 6.
    let cuts = layer_cuts(&t.events);
    assert!(cuts.iter().all(|c| c.1 .1 < 0));
    assert_eq!(cuts.last().unwrap().1 .0, 7_000);
    assert_eq!(expand(behind, with_max_passes(cuts.len() as i64)).alarm, al(AlarmCode::TooManyPasses, b'U', Rule::PrjMaxPass, 3));
    assert_eq!(expand(behind, with_max_passes(cuts.len() as i64 + 1)).alarm, None);
}
