//! The contour generators reach the register's alarms, mostly build legal cycles, and reach
//! the edges of the legal input space.

use super::super::tests::{assert_reaches, random_knobs};
use super::shape::Axis;
use super::{build, Cycle};
use crate::engine::{Engine, SpecEngine};
use cycle_vocab::{Event, MoveKind, Rule};

/// Rules every contour family reaches: finding and checking its contour, arcs, program words.
const CONTOUR: &[Rule] = &[
    Rule::CntPq,
    Rule::CntFind,
    Rule::CntMax,
    Rule::CntWords,
    Rule::CntNosub,
    Rule::CntFirst,
    Rule::ArcR,
    Rule::ArcTol,
    Rule::ArcIk,
    Rule::ArcFormat,
    Rule::TnrcNoarc,
    Rule::TnrcSwitch,
    Rule::TnrcRadius,
    Rule::PrjDialect,
    Rule::PrjWord,
    Rule::ComLead,
    Rule::ComRanges,
    Rule::G71Param,
];

#[test]
fn g71_reaches_the_rules() {
    let own = [Rule::G71Type2, Rule::G71First, Rule::G71Monotone, Rule::G71Depth, Rule::G71Retract, Rule::PrjMaxPass];
    assert_reaches(super::g71, &[CONTOUR, &own].concat());
}

#[test]
fn g72_reaches_the_rules() {
    let own = [Rule::G72Type2, Rule::G72First, Rule::G72Monotone, Rule::G72Depth, Rule::PrjMaxPass];
    assert_reaches(super::g72, &[CONTOUR, &own].concat());
}

/// G70 alone: its contour runs first as ordinary blocks (CNT.FLOW), so the M98 / M99 the NoSub
/// defect writes there is judged as a call or a return (SUB.CALL, SUB.RETURN) before G70 reads
/// it as a contour (CNT.NOSUB: reached by G71, G72).
#[test]
fn g70_reaches_the_rules() {
    let rules: Vec<Rule> = CONTOUR.iter().copied().filter(|&r| r != Rule::CntNosub).chain([Rule::SubCall, Rule::SubReturn]).collect();
    assert_reaches(super::g70, &rules);
}

/// The alarms' words: MONOTONE fails on both axes (steps back, arcs turning inside their
/// sweep), c = 0 on the cutting axis, ARC.TOL for an end off the circle and on the start's ray.
#[test]
fn the_shape_alarms_name_both_axes() {
    let mut seen = std::collections::BTreeSet::new();
    let mut s = 0x51ed_2701_aa55_0f0fu64;
    for _ in 0..6_000 {
        for cycle in [Cycle::G71, Cycle::G72] {
            let c = build(cycle, &mut crate::gen::Dice::new(&random_knobs(&mut s))).case;
            if let Some(a) = SpecEngine.expand(&c.program, &c.config).alarm {
                seen.insert((a.rule, a.word.map(char::from)));
            }
        }
    }
    for want in [
        (Rule::G71Monotone, Some('X')),
        (Rule::G71Monotone, Some('Z')),
        (Rule::G72Monotone, Some('X')),
        (Rule::G72Monotone, Some('Z')),
        (Rule::ArcTol, Some('X')),
        (Rule::ArcR, Some('R')),
        (Rule::ComRanges, Some('R')),
        (Rule::TnrcSwitch, Some('T')),
        (Rule::TnrcSwitch, Some('G')),
    ] {
        assert!(seen.contains(&want), "never {want:?}: {seen:?}");
    }
}

/// The legal programs reach the edges the layers turn on: OD and ID, both cutting directions,
/// allowances of every sign, no layer (Δd beyond the stock), many layers, e = 0, no first block,
/// arcs by R and by I/K both ways, G70 after roughing with and without U/W, a Q vertex exactly
/// on a layer, F in contour blocks, N spellings.
#[test]
fn legal_programs_reach_the_edges() {
    let mut hits = std::collections::BTreeMap::<&str, usize>::new();
    let mut s = 0x00dd_ba11_c0ff_ee00u64;
    for _ in 0..3_000 {
        for cycle in [Cycle::G71, Cycle::G72] {
            let b = build(cycle, &mut crate::gen::Dice::new(&random_knobs(&mut s)));
            let t = SpecEngine.expand(&b.case.program, &b.case.config);
            if t.alarm.is_some() {
                continue;
            }
            let text = b.case.text().to_ascii_uppercase();
            let layers = t.events.iter().filter(|e| matches!(e, Event::Pass(p) if p.kind == cycle_vocab::PassKind::Rough)).count();
            let f = b.frame;
            let (du, dw) = b.allowance;
            let allow_p = if f.axis == Axis::G71 { du } else { dw };
            let per = if f.axis == Axis::G71 { 2 } else { 1 };
            let on_layer = b.elements.iter().skip(1).any(|e| {
                let t = f.s * (f.p(e.end) + allow_p - f.p(f.a));
                t > 0 && t % (b.depth * per) == 0
            });
            for (name, hit) in [
                ("inside", f.s > 0),
                ("cut +", f.c > 0),
                ("allowance < 0", du < 0 || dw < 0),
                ("allowance > 0", du > 0 && dw > 0),
                ("no layer", layers == 0),
                ("40+ layers", layers >= 40),
                ("e = 0", b.retract == 0),
                ("no first block", !b.first_block),
                ("arc by R", b.arc_by_r),
                ("G02", t.moves().any(|m| m.kind == MoveKind::ArcCw)),
                ("G03", t.moves().any(|m| m.kind == MoveKind::ArcCcw)),
                ("arc by I/K", text.contains('I') && text.contains('K')),
                ("G70 with U/W", b.finish.is_some_and(|uw| uw != (0, 0))),
                ("G70 without", b.finish == Some((0, 0))),
                ("vertex on a layer", on_layer),
                ("N050", text.split(|c: char| !c.is_ascii_alphanumeric()).any(|w| w.starts_with("N0"))),
                ("N50.0", text.split([' ', '\n', '(', ';']).any(|w| w.starts_with('N') && w.ends_with(".0"))),
            ] {
                *hits.entry(name).or_default() += usize::from(hit);
            }
        }
    }
    for (name, n) in &hits {
        assert!(*n >= 20, "{name}: {n} of the legal programs ({hits:?})");
    }
}

/// The bench cases have exactly the layers and elements asked for, without an alarm.
#[test]
fn bench_cases_have_their_layers_and_elements() {
    for g72 in [false, true] {
        for (layers, elements) in [(1, 3), (10, 10), (1_000, 100), (37, 1_000)] {
            let c = super::layers_bench(g72, layers, elements);
            let t = SpecEngine.expand(&c.program, &c.config);
            assert_eq!(t.alarm, None, "{}", c.text());
            let rough = t.events.iter().filter(|e| matches!(e, Event::Pass(p) if p.kind == cycle_vocab::PassKind::Rough)).count();
            let contour = c.text().lines().filter(|l| l.starts_with('N')).count();
            assert_eq!((rough, contour), (layers, elements), "g72 {g72}");
        }
    }
}
