//! What G71 (stock removal along Z) and G72 (along X) share (M003): one cycle written once over
//! an **infeed axis** p and a **cutting axis** q — G71: p = X, q = Z; G72: p = Z, q = X ("As G71
//! with X and Z exchanged", docs/INTERPRETATION.md, "G72"). Each code's family unit, formats and
//! kept first block are in [`crate::g71`] and [`crate::g72`].
//!
//! Check order (step 5, docs/INTERPRETATION.md, "G71"): (1) find the contour (CNT.FIND,
//! CNT.MAX); (2) each contour block's own checks; (3) CNT.FIRST; (4) TYPE2, then FIRST; (5)
//! MONOTONE; (6) the pass bound — all before any motion. Then the layers, the semi-finish pass
//! and the return ([`emit`]).

pub mod checks;
pub mod layers;

use crate::contour::block::{read, Reader};
use crate::contour::path::{run, Feed};
use crate::contour::{self, Contour, Mode, Point};
use crate::emit::Out;
use crate::family::{BlockIn, Source, State};
use crate::words::alarm;
use cycle_vocab::{Alarm, AlarmCode, PassKind, Rule};
use layers::Roughing;

/// Which of the two cycles: its axes, letters and rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axes {
    G71,
    G72,
}

impl Axes {
    /// The infeed coordinate p of a point (G71 X, G72 Z).
    pub fn p(self, pt: Point) -> i128 {
        match self {
            Axes::G71 => pt.0,
            Axes::G72 => pt.1,
        }
    }
    /// The cutting coordinate q of a point (G71 Z, G72 X).
    pub fn q(self, pt: Point) -> i128 {
        match self {
            Axes::G71 => pt.1,
            Axes::G72 => pt.0,
        }
    }
    /// The point (X, Z) with infeed coordinate `p` and cutting coordinate `q`.
    pub fn point(self, p: i128, q: i128) -> Point {
        match self {
            Axes::G71 => (p, q),
            Axes::G72 => (q, p),
        }
    }
    /// The address letters of p and q.
    pub fn p_letter(self) -> u8 {
        match self {
            Axes::G71 => b'X',
            Axes::G72 => b'Z',
        }
    }
    pub fn q_letter(self) -> u8 {
        match self {
            Axes::G71 => b'Z',
            Axes::G72 => b'X',
        }
    }
    /// The first-block word of the depth Δd: G71 U, G72 W (the pass bound's word).
    pub fn depth_word(self) -> u8 {
        match self {
            Axes::G71 => b'U',
            Axes::G72 => b'W',
        }
    }
    /// The rules: (TYPE2, FIRST, MONOTONE, LAYER, RETRACT, LASTPASS, RETURN).
    pub fn rules(self) -> [Rule; 7] {
        match self {
            Axes::G71 => [
                Rule::G71Type2,
                Rule::G71First,
                Rule::G71Monotone,
                Rule::G71Layer,
                Rule::G71Retract,
                Rule::G71Lastpass,
                Rule::G71Return,
            ],
            Axes::G72 => [
                Rule::G72Type2,
                Rule::G72First,
                Rule::G72Monotone,
                Rule::G72Layer,
                Rule::G72Retract,
                Rule::G72Lastpass,
                Rule::G72Return,
            ],
        }
    }
}

/// COM.UNITS: the counts of a radius length on an axis — X is a diameter count (2), Z (1).
pub fn counts_per_length(letter: u8) -> i128 {
    if letter == b'X' {
        2
    } else {
        1
    }
}

/// The half-increment units of one count on an axis (u = X, v = 2Z): X 1, Z 2.
pub fn half_units(letter: u8) -> i128 {
    if letter == b'X' {
        1
    } else {
        2
    }
}

/// A cycle's first block as kept (G71.PARAM): Δd and e as written, `None` where the last first
/// block omitted them (or none was given); they fall back to 5132 and 5133.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct First {
    pub depth: Option<i64>,
    pub retract: Option<i64>,
}

/// One cycle as checked: A, the contour, its signs, Δd and e, the roughing feed.
#[derive(Clone, Debug)]
pub struct Cycle {
    pub ax: Axes,
    pub a: Point,
    /// The roughing contour Q: the contour translated by (Δu, Δw) (G71.ALLOW).
    pub q: Contour,
    pub s: i128,
    pub c: i128,
    pub depth: i64,
    pub retract: i64,
    pub feed: i64,
    pub line: u32,
}

/// The second block of G71 / G72 (M003): missing words "in this order: no feed … `MISSING WORD
/// F` (COM.LEAD); no P → `MISSING WORD P`, no Q → `MISSING WORD Q` (CNT.PQ)"; F "is the roughing
/// feed and becomes the modal feed"; then the cycle checks in order and the cycle.
pub fn second_block(ax: Axes, first: First, st: &mut State, b: &BlockIn, src: &mut Source) -> Result<(), Alarm> {
    let (v, line) = (b.values, b.line);
    st.take_feed(v);
    let Some(feed) = st.feed else {
        return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
    };
    let Some(ns) = v.get(b'P') else {
        return Err(alarm(AlarmCode::MissingWord, b'P', Rule::CntPq, line));
    };
    let Some(nf) = v.get(b'Q') else {
        return Err(alarm(AlarmCode::MissingWord, b'Q', Rule::CntPq, line));
    };
    st.missing_words_checked()?;
    let params = st.params();
    let a = st.position();
    let blocks = contour::ahead(src, ns, nf, line)?; // (1)
    let contour = read(&blocks, a, &Reader { config: st.config, side: st.side })?; // (2)
    contour::first(&contour)?; // (3)
    checks::first(ax, &contour, a)?; // (4)
    let s = (ax.p(contour.ns().end) - ax.p(a)).signum();
    let c = checks::monotone(ax, &contour, s, line)?; // (5)
    let cycle = Cycle {
        ax,
        a,
        q: contour.translated(v.get(b'U').unwrap_or(0), v.get(b'W').unwrap_or(0)),
        s,
        c,
        depth: first.depth.unwrap_or(params.p5132_rough_depth),
        retract: first.retract.unwrap_or(params.p5133_rough_retract),
        feed,
        line,
    };
    let rough = Roughing::new(&cycle);
    // (6) PRJ.MAXPASS: "layers + 1 (the semi-finish pass) > `max_passes` is `TOO MANY PASSES`".
    let layers = rough.count(i128::from(params.max_passes));
    if layers >= i128::from(params.max_passes) {
        return Err(alarm(AlarmCode::TooManyPasses, ax.depth_word(), Rule::PrjMaxPass, line));
    }
    emit(&cycle, &rough, layers, &mut st.out)
}

/// The moves of a checked cycle: each layer (G71.LAYER) with its 45° retract and rapid back
/// (G71.RETRACT), the semi-finish pass (G71.LASTPASS) and the return (G71.RETURN).
pub fn emit(cy: &Cycle, rough: &Roughing, layers: i128, out: &mut Out) -> Result<(), Alarm> {
    let (ax, a, line) = (cy.ax, cy.a, cy.line);
    let [.., layer, retract, lastpass, back] = ax.rules();
    let ns_mode = cy.q.ns().mode;
    for k in 1..=layers {
        let Some((p, q_end)) = rough.layer(k) else { break };
        layer_pass(cy, k, p, q_end, ns_mode, out, [layer, retract])?;
    }
    // G71.LASTPASS: "pass header index K + 1 (K layers), kind SEMI, diameter_depth =
    // |A.x − Q₀.x|" (G72: 2·|A.z − Q₀.z|), then Q at the roughing feed.
    let q0 = cy.q.ns().end;
    let depth = (ax.p(a) - ax.p(q0)).abs() * half_units(ax.p_letter());
    out.pass(index(layers + 1), PassKind::Semi, depth, lastpass, line)?;
    run(out, &cy.q, Feed::Roughing(cy.feed), lastpass, line)?;
    // G71.RETURN: "One rapid from Q's last point to A".
    out.rapid(a.0, a.1, back, line)
}

/// G71.LAYER, G71.RETRACT (M003, OPEN): layer k at infeed `p`, cut to `q_end` — "① infeed in X
/// only to X_k (Z unchanged), in the ns block's mode (G00 rapid, G01 feed at the roughing feed);
/// ② cut at feed to (X_k, z_k); ③ retract at 45°, at feed, to (X_k − s·2e, z_k − c·e); ④ rapid
/// along Z to A.z"; the header "index k, kind ROUGH, diameter_depth = 2k·Δd".
fn layer_pass(cy: &Cycle, k: i128, p: i128, q_end: i128, ns_mode: Mode, out: &mut Out, rules: [Rule; 2]) -> Result<(), Alarm> {
    let (ax, a, line, f) = (cy.ax, cy.a, cy.line, cy.feed);
    let [layer, retract] = rules;
    out.pass(index(k), PassKind::Rough, 2 * k * i128::from(cy.depth), layer, line)?;
    let infeed = ax.point(p, ax.q(a));
    match ns_mode {
        Mode::Rapid => out.rapid(infeed.0, infeed.1, layer, line)?,
        _ => out.feed(infeed.0, infeed.1, f, layer, line)?,
    }
    let cut = ax.point(p, q_end);
    out.feed(cut.0, cut.1, f, layer, line)?;
    let e = i128::from(cy.retract);
    let back_p = p - cy.s * e * counts_per_length(ax.p_letter());
    let back_q = q_end - cy.c * e * counts_per_length(ax.q_letter());
    let off = ax.point(back_p, back_q);
    out.feed(off.0, off.1, f, retract, line)?;
    let home = ax.point(back_p, ax.q(a));
    out.rapid(home.0, home.1, retract, line)
}

/// A pass index: at most `max_passes` ≤ 1 000 000 (checked before any motion).
fn index(k: i128) -> u32 {
    u32::try_from(k).unwrap_or(u32::MAX)
}
