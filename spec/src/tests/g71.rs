//! G71, G72, G70 (M003) on the seed's two examples and the feature programs: every number below
//! is worked out by hand from docs/INTERPRETATION.md, "Contours, arcs and the stock-removal
//! cycles", not taken from the spec's output.

use crate::expand;
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Event, Grid, Increment, MoveKind, PassKind, Rule, Units};

fn run(src: &str) -> Trace {
    let t = expand(src.as_bytes(), &Config::default());
    assert_eq!(t.alarm, None, "{}", t.to_gcode());
    t
}

type M = (MoveKind, i64, i64);

fn moves(t: &Trace) -> Vec<M> {
    t.moves().map(|m| (m.kind, m.x, m.z)).collect()
}

fn passes(t: &Trace) -> Vec<(u32, PassKind, i64, Rule)> {
    t.events.iter().filter_map(|e| if let Event::Pass(p) = e { Some((p.index, p.kind, p.diameter_depth, p.rule)) } else { None }).collect()
}

use MoveKind::{ArcCcw, ArcCw, Feed, Rapid};

/// One G71 layer from the previous return point: ① infeed X at feed (ns is G01), ② cut to z,
/// ③ 45° retract (X + 2e, z + e; s = c = −1, e = 1 mm), ④ rapid back to Z0.
fn layer71(x: i64, z: i64) -> Vec<M> {
    vec![(Feed, x, 0), (Feed, x, z), (Feed, x + 2_000, z + 1_000), (Rapid, x + 2_000, 0)]
}

/// G71.EXAMPLE (M003 example 1). A = X41 Z0, Δd = 2, e = 1, Δu = 0.5, Δw = 0.2; s = c = −1.
/// Q = the contour + (0.5, 0.2): X0.5 Z0.2, arc (centre X0.5 Z−5.3, r 5.5) to X11.5 Z−5.3,
/// X11.5 Z−15.3, X17.5 Z−25.3, X17.5 Z−40.3, arc (centre X32.5 Z−40.3, r 7.5) to X29.5 Z−47.648,
/// X29.5 Z−60.3, X41.5 Z−60.3. Layers X_k = 41 − 4k while X_k > 0.5. Cut ends by hand:
/// * X37, X33: on the last line (Z−60.3).
/// * X29: on the fillet: u − c_u = 29 000 − 32 500 = −3 500, √(15 000² − 3 500²) = √212 750 000
///   = 14 585.95; below the centre (σ = −1, the arc runs to Z−47.648): z = −40 300 − 7 292.98 →
///   Z−47.593. X25: √(225e6 − 7 500²) = 12 990.38 → Z−46.795. X21: √(225e6 − 11 500²) =
///   9 630.68 → Z−45.115.
/// * X17, X13: on the taper X11.5 Z−15.3 → X17.5 Z−25.3: z = −15 300 − (x − 11 500)·10/6:
///   X17 → −24 466.67 → Z−24.467; X13 → Z−17.800 exactly.
/// * X9: on the ball (σ = +1): √(11 000² − 8 500²) = √48 750 000 = 6 982.12, v = −10 600 +
///   6 982.12, z = −1 808.94 → Z−1.809. X5: √(121e6 − 4 500²) = 10 037.43 → Z−0.281.
/// * X1 would end at √(121e6 − 500²) = 10 988.63 → z = +194.3 → Z+0.194, behind A.z = 0: the
///   cut is not positive ("c·(z_k − A.z) > 0"), so the layers end after X5 — nine layers, not
///   the ten the register's example sentence lists (its own existence rule excludes X1).
#[test]
fn example1_g71_layers_semi_and_g70() {
    let t = run(include_str!("../../../corpus/g71_example.nc"));
    let ends = [(37_000, -60_300), (33_000, -60_300), (29_000, -47_593), (25_000, -46_795), (21_000, -45_115)];
    let ends2 = [(17_000, -24_467), (13_000, -17_800), (9_000, -1_809), (5_000, -281)];
    let mut expect = vec![(Rapid, 41_000, 0)];
    for (x, z) in ends.iter().chain(ends2.iter()) {
        expect.extend(layer71(*x, *z));
    }
    // SEMI: one move to Q₀ in the ns mode (G01), then Q in its modes, then the rapid to A.
    expect.extend([
        (Feed, 500, 200),
        (ArcCcw, 11_500, -5_300),
        (Feed, 11_500, -15_300),
        (Feed, 17_500, -25_300),
        (Feed, 17_500, -40_300),
        (ArcCw, 29_500, -47_648),
        (Feed, 29_500, -60_300),
        (Feed, 41_500, -60_300),
        (Rapid, 41_000, 0),
    ]);
    // G70: the register's list, then the rapid back to X41 Z0.
    expect.extend([
        (Feed, 0, 0),
        (ArcCcw, 11_000, -5_500),
        (Feed, 11_000, -15_500),
        (Feed, 17_000, -25_500),
        (Feed, 17_000, -40_500),
        (ArcCw, 29_000, -47_848),
        (Feed, 29_000, -60_500),
        (Feed, 41_000, -60_500),
        (Rapid, 41_000, 0),
    ]);
    assert_eq!(moves(&t), expect);
    // Pass headers: ROUGH k with 2k·Δd on diameter, SEMI |A.x − Q₀.x| = 40.5, FINISH |S.x − P₀.x| = 41.
    let mut p: Vec<_> = (1..=9).map(|k| (k, PassKind::Rough, 4_000 * i64::from(k), Rule::G71Layer)).collect();
    p.push((10, PassKind::Semi, 40_500, Rule::G71Lastpass));
    p.push((1, PassKind::Finish, 41_000, Rule::G70Path));
    assert_eq!(passes(&t), p);
    // Centres: the SEMI arcs about the translated centres, G70's about the contour's; feeds.
    let arcs: Vec<_> = t.moves().filter(|m| m.kind != Feed && m.kind != Rapid).map(|m| (m.cx, m.cz, m.feed)).collect();
    assert_eq!(arcs, vec![(500, -5_300, 1_000_000), (32_500, -40_300, 1_000_000), (0, -5_500, 300_000), (32_000, -40_500, 300_000)]);
    // Rule tags: ①② G71.LAYER, ③④ G71.RETRACT, SEMI G71.LASTPASS, G71.RETURN, G70.PATH, G70.RETURN.
    let rules: Vec<Rule> = t.moves().map(|m| m.rule).collect();
    assert_eq!(&rules[1..5], &[Rule::G71Layer, Rule::G71Layer, Rule::G71Retract, Rule::G71Retract]);
    assert_eq!(rules[37..46].iter().filter(|&&r| r == Rule::G71Lastpass).count(), 8);
    assert_eq!((rules[45], rules[54]), (Rule::G71Return, Rule::G70Return));
    assert!(rules[46..54].iter().all(|&r| r == Rule::G70Path));
}

/// G72.EXAMPLE (M003 example 2). A = X41 Z1, Δd = 1 (Z), e = 1, Δu = 0.1, Δw = 0.2; s = −1
/// (A′.z = −31 < 1), c = −1 (B.x = 14 < 41). Q: X41.1 Z−30.8, X20.1 Z−19.8, X20.1 Z−1.8,
/// X14.1 Z1.2. Layers Z_k = 1 − k while Z_k > −30.8: Z0 … Z−30 (31 layers), each cut along X
/// from X41: Z0 on X20.1 Z−1.8 → X14.1 Z1.2: x = 20.1 − 1.8·6/3 = 16.5; Z−30 on the first
/// line: x = 41.1 − 0.8·21/11 = 39.5727 → X39.573; Z−25: 41.1 − 5.8·21/11 = 30.0273 → X30.027.
/// Layer path: infeed in Z at rapid (ns G00), cut, retract to (x + 2, Z + 1), rapid to X41.
#[test]
fn example2_g72_layers() {
    let t = run(include_str!("../../../corpus/g72_example.nc"));
    let p = passes(&t);
    assert_eq!(p.len(), 31 + 1 + 1);
    assert!(p[..31].iter().enumerate().all(|(k, p)| *p == (k as u32 + 1, PassKind::Rough, 2_000 * (k as i64 + 1), Rule::G72Layer)));
    assert_eq!(p[31], (32, PassKind::Semi, 63_600, Rule::G72Lastpass));
    let m = moves(&t);
    assert_eq!(&m[1..5], &[(Rapid, 41_000, 0), (Feed, 16_500, 0), (Feed, 18_500, 1_000), (Rapid, 41_000, 1_000)]);
    let layer = |k: usize| m[1 + 4 * (k - 1)..1 + 4 * k].to_vec();
    assert_eq!(layer(26)[1], (Feed, 30_027, -25_000));
    assert_eq!(layer(31), vec![(Rapid, 41_000, -30_000), (Feed, 39_573, -30_000), (Feed, 41_573, -29_000), (Rapid, 41_000, -29_000)]);
    // SEMI: rapid to Q₀ (ns G00), Q at the roughing feed, rapid to A; then G70 from X41 Z1.
    assert_eq!(
        &m[125..],
        &[
            (Rapid, 41_100, -30_800),
            (Feed, 20_100, -19_800),
            (Feed, 20_100, -1_800),
            (Feed, 14_100, 1_200),
            (Rapid, 41_000, 1_000),
            (Rapid, 41_000, -31_000),
            (Feed, 20_000, -20_000),
            (Feed, 20_000, -2_000),
            (Feed, 14_000, 1_000),
            (Rapid, 41_000, 1_000),
        ]
    );
}

/// The feature programs run without an alarm under the configuration their headers name.
#[test]
fn feature_programs_run() {
    let programs = [
        include_str!("../../../tests/programs/g71_bore.nc"),
        include_str!("../../../tests/programs/g70_arcs_ik.nc"),
        include_str!("../../../tests/programs/g71_vertex_on_layer.nc"),
        include_str!("../../../tests/programs/g71_deep_cut.nc"),
        include_str!("../../../tests/programs/g70_after_g71.nc"),
    ];
    for p in programs {
        run(p);
    }
    let inch = Config { grid: Grid { units: Units::Inch, increment: Increment::Isb }, ..Config::default() };
    assert_eq!(expand(include_str!("../../../tests/programs/g72_inch.nc").as_bytes(), &inch).alarm, None);
    let isc = Config { grid: Grid { units: Units::Metric, increment: Increment::Isc }, ..Config::default() };
    let t = expand(include_str!("../../../tests/programs/g71_isc.nc").as_bytes(), &isc);
    assert_eq!(t.alarm, None);
    // On ISB the ISC program's four decimals are PRECISION on its first such word.
    let isb = expand(include_str!("../../../tests/programs/g71_isc.nc").as_bytes(), &Config::default());
    assert_eq!(isb.alarm.map(|a| (a.code, a.rule)), Some((cycle_vocab::AlarmCode::Precision, Rule::ComUnits)));
}

/// g71_bore: s = +1 (the ns block moves X outward from X16 to X40), layers X19 … X37 step 3;
/// Q = contour + (−0.4, 0.1). X31 meets the fillet (centre X36 Z−18 + the allowance = X35.6
/// Z−17.9, r 3): u − c_u = −4 600, √(6 000² − 4 600²) = √14 840 000 = 3 852.27 above the centre:
/// z = −17 900 + 1 926.14 → Z−15.974. X37 on the chamfer X39.6 Z0.1 → X35.6 Z−1.9: z = 0.1 −
/// 2.6·2/4 = −1.2. X19 … X28 on the bottom face at Z−29.9. Retracts toward the axis: X − 1.
#[test]
fn bore_layers() {
    let t = run(include_str!("../../../tests/programs/g71_bore.nc"));
    let cuts: Vec<(i64, i64)> = t.moves().filter(|m| m.rule == Rule::G71Layer && m.z != 2_000).map(|m| (m.x, m.z)).collect();
    assert_eq!(cuts, vec![(19_000, -29_900), (22_000, -29_900), (25_000, -29_900), (28_000, -29_900), (31_000, -15_974), (34_000, -15_009), (37_000, -1_200)]);
    let m = moves(&t);
    assert_eq!(&m[1..5], &[(Rapid, 19_000, 2_000), (Feed, 19_000, -29_900), (Feed, 18_000, -29_400), (Rapid, 18_000, 2_000)]);
}

/// g71_vertex_on_layer: X38 and X30 are contour vertices; the pieces lying on those layers
/// end the cuts where the contour leaves them (Z−35, Z−20); X34 crosses X30 Z−20 → X38 Z−25
/// at −20 − 4·5/8 = −22.5.
#[test]
fn vertex_on_layer() {
    let t = run(include_str!("../../../tests/programs/g71_vertex_on_layer.nc"));
    let cuts: Vec<(i64, i64)> = t.moves().filter(|m| m.rule == Rule::G71Layer && m.z != 2_000).map(|m| (m.x, m.z)).collect();
    assert_eq!(cuts, vec![(46_000, -35_000), (42_000, -35_000), (38_000, -35_000), (34_000, -22_500), (30_000, -20_000), (26_000, -10_000), (22_000, -10_000)]);
}

/// g71_deep_cut: Δd = 5 > the stock (|A.x − Q₀.x| = 7.6 on diameter < 10): no layer; the SEMI
/// pass is pass 1 and starts at A.
#[test]
fn deep_cut_has_only_the_semi_pass() {
    let t = run(include_str!("../../../tests/programs/g71_deep_cut.nc"));
    assert_eq!(passes(&t), vec![(1, PassKind::Semi, 7_600, Rule::G71Lastpass)]);
    assert_eq!(moves(&t)[1], (Feed, 34_400, 2_100));
}

/// g70_after_g71: the first G70 runs the contour + (0.2, 0.05) at F0.15 until N30's F0.08; the
/// second the contour itself at F0.12, then F0.08 from N30 on. The modal feed after each cycle
/// is the cycle block's own F.
#[test]
fn g70_steps_and_feeds() {
    let t = run(include_str!("../../../tests/programs/g70_after_g71.nc"));
    let finish: Vec<_> = t.moves().filter(|m| m.rule == Rule::G70Path).map(|m| (m.x, m.z, m.feed)).collect();
    assert_eq!(
        finish,
        vec![
            (20_200, 1_050, 0),
            (20_200, -11_950, 1_500),
            (30_200, -19_950, 800),
            (38_200, -23_950, 800),
            (44_200, -23_950, 800),
            (20_000, 1_000, 0),
            (20_000, -12_000, 1_200),
            (30_000, -20_000, 800),
            (38_000, -24_000, 800),
            (44_000, -24_000, 800),
        ]
    );
    // CNT.FLOW, CYC.ONESHOT, CNT.MODAL: the contour first runs as ordinary blocks (F0.5); after
    // G70 the motion mode is G00 again and the modal feed is G70's F0.2 (G70 itself runs at
    // N10's F0.5 from N10 on).
    let t2 = run("G00 X44 Z1\nN10 G01 X40 F0.5\nN20 Z-5\nG00 X44 Z1\nG70 P10 Q20 F0.2\nX50\nG1 X44\n");
    let tail: Vec<_> = t2.moves().skip(4).map(|m| (m.kind, m.x, m.z, m.feed)).collect();
    assert_eq!(
        tail,
        vec![(Feed, 40_000, 1_000, 5_000), (Feed, 40_000, -5_000, 5_000), (Rapid, 44_000, 1_000, 0), (Rapid, 50_000, 1_000, 0), (Feed, 44_000, 1_000, 2_000)]
    );
}

/// G72 with the allowance bringing Q₀ back to A's Z (D = s·(Q₀.z − A.z) = 0) and the smallest
/// Δd, one Z count (`W0.001`: "a Z length 1 … N", G72.DEPTH): A = X41 Z1, A′ = X41 Z0.5
/// (s = −1), Δw = 0.5 → Q₀ = X41 Z1 = A. No Z_k lies strictly between A.z and Q₀.z, so there is
/// no layer and the SEMI pass is pass **1** ("pass header index K + 1 (K layers)", G71.LASTPASS)
/// with diameter_depth 2·|A.z − Q₀.z| = 0; its move to Q₀ is a move to A (not emitted,
/// PRJ.NOOP), then Q at F0.2 to X20 Z1 and the rapid back to A.
#[test]
fn g72_no_layer_when_q0_is_level_with_a() {
    let t = run("G00 X41 Z1\nG72 W0.001 R1\nG72 P10 Q20 W0.5 F0.2\nN10 G00 Z0.5\nN20 G01 X20\n");
    assert_eq!(passes(&t), vec![(1, PassKind::Semi, 0, Rule::G72Lastpass)]);
    assert_eq!(moves(&t), vec![(Rapid, 41_000, 1_000), (Feed, 20_000, 1_000), (Rapid, 41_000, 1_000)]);
}
