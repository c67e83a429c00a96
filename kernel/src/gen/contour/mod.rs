//! The contour families g71, g72 and g70 (M003): G71 / G72 stock removal over a finishing
//! contour, then sometimes G70 (with and without U/W), and G70 alone finishing a contour written
//! before it (CNT.FLOW: that contour first runs as ordinary blocks).
//!
//! The contours are random **monotone** contours of lines and arcs ([`shape`]: G00/G01/G02/G03,
//! arcs by R and by I/K, quadrant and tangent arcs, very short elements, vertices and
//! horizontal pieces exactly on a layer, layer ends on arcs and on rounding ties), outside and
//! inside (s = ±1), both cutting directions, allowances of every sign, Δd from one increment to
//! more than the stock, e = 0 to large, first blocks present or absent (5132/5133), F in contour
//! blocks, sequence numbers spelled `N050`, `N50`, `N50.0`, G50 (S the maximum), G97–G99 and the nose-radius
//! codes, and the register's alarms at a controlled rate ([`defect`]: every CNT.*, ARC.*,
//! TNRC.*, G50, TYPE2, FIRST, MONOTONE, the pass bound, nc201). Knob 0 is a plain legal program.

mod defect;
mod program;
pub mod shape;

use super::writer::{tail, Writer};
use super::{config, unit, Case, Dice, LEAD_UNIT, N};
use cycle_vocab::text::fixed;
use cycle_vocab::Config;
use defect::Defect;
use program::{numbering, write, Words};
use shape::{Axis, Element, Frame, Kind, Plan};

/// Which family a program is built for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cycle {
    G71,
    G72,
    /// G70 alone: its contour stands before it.
    G70,
    /// G73 pattern repeating, either format, then sometimes G70.
    G73,
}

impl Cycle {
    fn family(self) -> &'static str {
        match self {
            Cycle::G71 => "g71",
            Cycle::G72 => "g72",
            Cycle::G70 => "g70",
            Cycle::G73 => "g73",
        }
    }
}

/// A G71 program.
pub fn g71(dice: &mut Dice) -> Case {
    build(Cycle::G71, dice).case
}

/// A G72 program.
pub fn g72(dice: &mut Dice) -> Case {
    build(Cycle::G72, dice).case
}

/// A G73 program (over the same contours: G73 takes any contour, G73.USE).
pub fn g73(dice: &mut Dice) -> Case {
    build(Cycle::G73, dice).case
}

/// A program whose first cycle is a G70 finishing the contour written before it.
pub fn g70(dice: &mut Dice) -> Case {
    build(Cycle::G70, dice).case
}

/// How an arc block writes its centre.
#[derive(Clone, Debug, PartialEq, Eq)]
enum ArcWords {
    Ik,
    R,
    /// R as given (a defect's value).
    RText(String),
    /// R and I/K (a CONFLICT).
    RIk,
    /// Neither (MISSING WORD R).
    Neither,
}

/// One contour block before it is written.
#[derive(Clone, Debug)]
struct Block {
    el: Element,
    arc: ArcWords,
    /// The motion code written instead of the element's: `Some("")` writes none.
    g: Option<String>,
    /// Words a defect adds.
    extra: Vec<(char, String)>,
    /// F written in the block (CNT.FST).
    feed: Option<i64>,
    /// A block without axis words: it moves nothing (its motion code, if any, sets the
    /// contour's mode; its F waits for the next move).
    bare: bool,
}

impl Block {
    fn of(el: Element, arc: ArcWords) -> Block {
        Block { el, arc, g: None, extra: Vec::new(), feed: None, bare: false }
    }
}

/// A built program and, for the properties, what it was built from.
#[derive(Clone, Debug)]
pub struct Built {
    pub case: Case,
    pub frame: Frame,
    /// The contour, the ns block first (what the program writes, when no defect changed it).
    pub elements: Vec<Element>,
    /// Δd and e as the cycle uses them (the first block's, else 5132/5133), Δd in increments of
    /// the infeed axis (a radius for G71).
    pub depth: i64,
    pub retract: i64,
    /// (Δu, Δw): Δu a diameter count.
    pub allowance: (i64, i64),
    pub feed: i64,
    /// G70's (U, W) when the program finishes with G70 after roughing.
    pub finish: Option<(i64, i64)>,
    /// Whether a defect was planted.
    pub defect: bool,
    /// Whether the program writes the cycle's first block, and an arc by R.
    pub first_block: bool,
    pub arc_by_r: bool,
}

/// The program of `cycle` the dice describe.
pub fn build(cycle: Cycle, dice: &mut Dice) -> Built {
    build_as(cycle, dice, false)
}

/// A legal G71 (`axis` G71) or G72 program: no defect, the other parameters at their defaults,
/// only arcs that end exactly on their circles (quadrant and lattice arcs, [`shape`]) — the
/// contour a property can check a trace against exactly.
pub fn legal(axis: Axis, dice: &mut Dice) -> Built {
    build_as(if axis == Axis::G71 { Cycle::G71 } else { Cycle::G72 }, dice, true)
}

fn build_as(cycle: Cycle, dice: &mut Dice, legal: bool) -> Built {
    let mut config = config(&mut dice.fork(48), dice.fork(1).chance(30));
    if legal {
        config = Config { dialect: config.dialect, grid: config.grid, ..Config::default() };
    }
    let grid = config.grid;
    let mut w = Writer::new(&mut dice.fork(2));
    let d = &mut dice.fork(36);
    let axis_of = match cycle {
        Cycle::G72 => Axis::G72,
        Cycle::G71 => Axis::G71,
        Cycle::G70 | Cycle::G73 => [Axis::G71, Axis::G72][d.below(2) as usize],
    };
    // The unit of the geometry: 1 mm (0.1 in), or a few increments — small contours where
    // rounding ties and layers on vertices are frequent.
    let u = if d.chance(10) { d.range(2, 40) } else { unit(grid) };
    let (defect, variant) = defect::draw(&mut dice.fork(3), cycle);
    let (defect, variant) = if legal { (Defect::Clean, 0) } else { (defect, variant) };

    // Parameters: 5132, 5133 (G71.PARAM), the arc tolerance (ARC.TOL), sometimes a few passes.
    let pd = &mut dice.fork(8);
    if pd.chance(15) {
        config.params.p5132_rough_depth = Some(pd.range((u / 10).max(1), 2 * u));
    }
    if pd.chance(15) {
        config.params.p5133_rough_retract = Some(pd.range(0, u));
    }
    if pd.chance(10) && !legal {
        config.params.arc_tolerance = Some(if pd.chance(30) { 0 } else { pd.range(1, 50) });
    }
    if cycle == Cycle::G73 && pd.chance(15) {
        // G73's values when no first block gives them (G73.ESCAPE, G73.COUNT).
        config.params.p5135_escape_x = Some(pd.range(0, 5 * u));
        config.params.p5136_escape_z = Some(pd.range(0, 2 * u));
        config.params.p5137_count = Some(pd.range(1, 6));
    }
    let cp = cycle_spec::config::params(&config);

    // The layers: Δd against the stock's depth D (both in increments of the infeed axis).
    let (stock, depth) = match d.weighted(&[66, 8, 8, 9, 9]) {
        0 => {
            let (stock, n) = (d.range(2 * u, 30 * u), d.range(3, 40));
            (stock, (stock + n - 1) / n)
        }
        1 => (d.range(1, 300), d.range(1, 3)),            // Δd of an increment or three
        2 => {
            let stock = d.range(2 * u, 30 * u);
            (stock, stock + d.range(0, 5 * u))             // Δd beyond the stock: no layer
        }
        3 => {
            let m = d.range(u / 4, 4 * u).max(1);
            (m * d.range(1, 10), m)                        // a layer exactly at Q₀ (no allowance)
        }
        _ => {
            let stock = d.range(10 * u, 60 * u);
            (stock, (stock / d.range(40, 250)).max(1))
        }
    };
    let depth = depth.max(1);
    let frame = frame(d, axis_of, stock, u);
    let first = if d.chance(12) && defect != Defect::DepthValue { None } else { Some((Some(depth).filter(|_| !d.chance(10)), retract(d, depth, u))) };
    // Allowances up to twice the stock (G71: its diameter), at most 5 units.
    let most = (2 * stock * if axis_of == Axis::G71 { 2 } else { 1 }).min(5 * u).max(1);
    let allowance = (allowance(d, most), allowance(d, most));
    let feed = d.range(LEAD_UNIT / 50, LEAD_UNIT);
    let used_depth = match first {
        Some((Some(v), _)) => v,
        _ => cp.p5132_rough_depth,
    };
    let used_retract = match first {
        Some((_, Some(v))) => v,
        _ => cp.p5133_rough_retract,
    };

    // The contour.
    let (hp, _) = frame.h();
    let per = if axis_of == Axis::G71 { 2 } else { 1 };
    let allow_p = if axis_of == Axis::G71 { allowance.0.unwrap_or(0) } else { allowance.1.unwrap_or(0) };
    let pieces = match defect {
        Defect::TooLong => 1_000,
        _ if d.chance(2) => d.range(40, 400) as usize,
        _ => d.range(1, 8) as usize,
    };
    let plan = Plan {
        unit: u,
        depth: stock * per * hp,
        layer_t: -frame.s * allow_p * hp,
        layer_step: used_depth.max(1) * per * hp,
        pieces,
        exact: legal || cp.arc_tolerance == 0,
    };
    let ns_feed = d.chance(30);
    let elements = shape::monotone(&mut dice.fork(shape::KNOBS), frame, &plan, ns_feed);
    let bd = &mut dice.fork(8);
    let mut blocks: Vec<Block> = elements
        .iter()
        .map(|e| {
            let by = if matches!(e.kind, Kind::Arc { .. }) && (e.exact || cp.arc_tolerance > 0) && bd.chance(40) { ArcWords::R } else { ArcWords::Ik };
            Block::of(*e, by)
        })
        .collect();
    if bd.chance(30) {
        // F in some contour blocks: ignored by roughing, G70's from that block on (CNT.FST).
        for (i, b) in blocks.iter_mut().enumerate() {
            if (i * 7 + bd.below(5) as usize).is_multiple_of(3) {
                b.feed = Some(bd.range(LEAD_UNIT / 100, LEAD_UNIT / 2));
            }
        }
    }
    if bd.chance(12) {
        // A block without axis words: the next element's motion code alone (it sets the mode),
        // an F alone, or both.
        let i = 1 + bd.below(blocks.len() as u64) as usize;
        let kind = blocks.get(i).map_or(Kind::Feed, |b| b.el.kind);
        let el = Element { kind, end: blocks[i - 1].el.end, centre: None, exact: true };
        let how = bd.below(3);
        let g = (how == 1).then(String::new);
        let feed = (how != 0).then(|| bd.range(LEAD_UNIT / 100, LEAD_UNIT / 2));
        blocks.insert(i, Block { g, feed, bare: true, ..Block::of(el, ArcWords::Ik) });
    }
    defect.apply(variant, &mut dice.fork(12), frame, &mut blocks, (cp.arc_tolerance, u, grid));

    let arc_by_r = blocks.iter().any(|b| b.arc == ArcWords::R && matches!(b.el.kind, Kind::Arc { .. }));

    // The program.
    let numbers = numbering(&mut dice.fork(8), blocks.len());
    let words = Words { grid, frame, depth: first, allowance, feed, numbers, blocks, legal };
    let finish = write(cycle, (defect, variant), &mut w, &mut dice.fork(28), &mut config, &words);
    tail(&mut w, &mut dice.fork(2));
    defect.configure(&mut dice.fork(2), &mut config, u);
    Built {
        case: Case { family: cycle.family(), program: w.finish(), config },
        frame,
        elements,
        depth: used_depth,
        retract: used_retract,
        allowance: (allowance.0.unwrap_or(0), allowance.1.unwrap_or(0)),
        feed,
        finish,
        defect: defect != Defect::Clean,
        first_block: first.is_some(),
        arc_by_r,
    }
}

/// The frame: s, c and A for `axis`, the stock `stock` increments deep along the infeed axis.
fn frame(d: &mut Dice, axis: Axis, stock: i64, u: i64) -> Frame {
    let (s, c) = match axis {
        Axis::G71 => (if d.chance(25) { 1 } else { -1 }, if d.chance(20) { 1 } else { -1 }),
        Axis::G72 => (if d.chance(20) { 1 } else { -1 }, if d.chance(25) { 1 } else { -1 }),
    };
    let a = match axis {
        // Outside: A′ at X ≥ 0 (the seed's X0); inside: a bore.
        Axis::G71 if s < 0 => (2 * stock + 2 * d.range(0, 60 * u), d.range(-5 * u, 10 * u)),
        Axis::G71 => (d.range(2 * u, 40 * u), d.range(-5 * u, 10 * u)),
        Axis::G72 if c < 0 => (d.range(20 * u, 160 * u), d.range(-5 * u, 10 * u)),
        Axis::G72 => (d.range(2 * u, 40 * u), d.range(-5 * u, 10 * u)),
    };
    // Now and then far from the origin, near the words' limit N: the whole contour moved.
    let far = if d.chance(3) { N - 40_000 * u.max(1_000) } else { 0 };
    let a = (a.0 + far * d.one_of(&[1, -1]), a.1 + far * d.one_of(&[1, -1]));
    Frame { axis, a, s, c }
}

/// e as the first block writes it: from 0 to far beyond Δd, or omitted (5133).
fn retract(d: &mut Dice, depth: i64, u: i64) -> Option<i64> {
    Some(match d.weighted(&[55, 12, 13, 20]) {
        0 => d.range(u / 2, u),
        1 => 0,
        2 => d.range(depth, depth + 5 * u),
        _ => return None,
    })
}

/// An allowance (Δu or Δw) of at most `most`: mostly small and positive, sometimes omitted, 0,
/// negative, large.
fn allowance(d: &mut Dice, most: i64) -> Option<i64> {
    let small = (most / 10).max(1);
    Some(match d.weighted(&[45, 15, 15, 10, 15]) {
        0 => d.range(0, small),
        1 => return None,
        2 => -d.range(1, small),
        3 => 0,
        _ => d.one_of(&[1, -1]) * d.range(small, most),
    })
}

/// The bench case of G71 (`g72`: G72) with exactly `layers` layers over a contour of
/// `elements` elements (at least 3): the ns block, one piece along the cut (every layer's cut
/// ends beyond it), then `elements − 2` tapers back to A's X; Δd = 0.01 mm, allowances U0.02
/// W0.01, `max_passes` just enough.
pub fn layers_bench(g72: bool, layers: usize, elements: usize) -> Case {
    // The layer spacing and the allowance along the infeed axis, in its counts.
    let (step, allowance, code) = if g72 { (10i64, 10, "72") } else { (20i64, 20, "71") };
    let depth = layers as i64 * step + allowance + 2;
    let tapers = elements.saturating_sub(2).max(1) as i64;
    let (p_word, q_word) = if g72 { ('Z', 'X') } else { ('X', 'Z') };
    let a = (200_000 + depth, 0);
    let mut p = format!("G00 X{} Z{}\nG{code} {} 0.01 R0.005\n", fixed(a.0, 3), fixed(a.1, 3), if g72 { 'W' } else { 'U' });
    p.push_str(&format!("G{code} P1 Q{} U0.02 W0.01 F0.2\n", tapers + 2));
    p.push_str(&format!("N1 G00 {p_word}{}\n", fixed(if g72 { -depth } else { a.0 - depth }, 3)));
    p.push_str(&format!("N2 G01 {q_word}{}\n", fixed(if g72 { a.0 - 5_000 } else { -5_000 }, 3)));
    for i in 1..=tapers {
        let t = depth - depth * i / tapers;
        let pv = if g72 { -t } else { a.0 - t };
        let qv = if g72 { a.0 - 5_000 - 100 * i } else { -5_000 - 100 * i };
        p.push_str(&format!("N{} {p_word}{} {q_word}{}\n", i + 2, fixed(pv, 3), fixed(qv, 3)));
    }
    let mut config = Config::default();
    config.params.max_passes = Some(layers as i64 + 1);
    Case { family: if g72 { "g72" } else { "g71" }, program: p.into_bytes(), config }
}

/// The g71 bench case: about `n` passes (n − 1 layers and the semi-finish pass), a contour of
/// ten elements.
pub fn g71_bench(n: usize) -> Case {
    layers_bench(false, n.saturating_sub(1).max(1), 10)
}

/// The g72 bench case, as g71's.
pub fn g72_bench(n: usize) -> Case {
    layers_bench(true, n.saturating_sub(1).max(1), 10)
}

/// The g70 bench case: G70 alone over a contour of `n` elements (at most CNT.MAX = 1 000).
pub fn g70_bench(n: usize) -> Case {
    let n = n.clamp(2, 999);
    let mut p = String::from("G00 X100 Z2\nG01 F0.2\n");
    p.push_str("N1 G00 X10\n");
    for i in 1..n {
        p.push_str(&format!("N{} G01 X{} Z-{}\n", i + 1, fixed(10_000 + 80 * i as i64, 3), fixed(50 * i as i64, 3)));
    }
    p.push_str(&format!("G00 X100 Z2\nG70 P1 Q{n}\n"));
    Case { family: "g70", program: p.into_bytes(), config: Config::default() }
}

/// The g73 bench case: `n` passes (d = n, Δi 0.001·n, Δk 0) over a contour of ten elements.
pub fn g73_bench(n: usize) -> Case {
    let n = n.max(1);
    let mut p = format!("G00 X60 Z2\nG73 U{} W0 R{n}\nG73 P1 Q10 U0.2 W0.1 F0.2\nN1 G00 X20\n", fixed(n as i64, 3));
    for i in 2..=10 {
        p.push_str(&format!("N{i} G01 X{} Z-{}\n", fixed(20_000 + 2_000 * (i - 1), 3), fixed(3_000 * (i - 1), 3)));
    }
    let mut config = Config::default();
    config.params.max_passes = Some(n as i64 + 1);
    Case { family: "g73", program: p.into_bytes(), config }
}

#[cfg(test)]
mod tests;
