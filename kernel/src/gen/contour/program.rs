//! Writing a contour program: the blocks before the cycle (O, G50, spindle and feed modes, the
//! nose-radius codes, A, sometimes a G90 run the cycle does not end), the cycle's blocks (kept
//! first blocks of either cycle), the contour's blocks with their sequence numbers, and what
//! follows (G70 with and without U/W, from A or elsewhere, twice; a modal block after the
//! one-shot cycle).

use super::defect::Defect;
use super::shape::{self, Axis, Frame, Kind};
use super::{ArcWords, Block, Cycle};
use crate::gen::writer::{axis, Writer};
use crate::gen::{unit, Dice, LEAD_UNIT};
use cycle_vocab::{Config, Grid};

/// Sequence numbers: the contour's blocks' N (those of ns and nf always), as written.
pub(super) struct Numbers {
    pub(super) ns: i64,
    pub(super) nf: i64,
    /// Each block's N as written (`None`: no N).
    text: Vec<Option<String>>,
}

/// N(ns) … N(nf): steps of 10 (the seed's), of 1, downward, or only the ends numbered; spelled
/// `N50`, `N050`, `N50.0` or `N50.`.
pub(super) fn numbering(d: &mut Dice, n: usize) -> Numbers {
    // At most 99 999 (CNT.PQ) for every number of the contour.
    let most = 99_999 - 10 * n as i64 - 1_001;
    let ns = if d.chance(10) { d.range(1, most) } else { 10 * d.range(1, 90) };
    let stride = [10, 1, -1, 10][d.weighted(&[60, 15, 10, 15])];
    let only_ends = d.chance(25);
    let number = |i: usize| if stride < 0 { ns + 1_000 - i as i64 } else { ns + stride * i as i64 };
    let (ns, nf) = (number(0), number(n - 1));
    let spell = |v: i64, k: u32| match k % 4 {
        0 => v.to_string(),
        1 => format!("{v:03}"),
        2 => format!("{v}.0"),
        _ => format!("{v}."),
    };
    let style = d.below(16) as u32;
    let text = (0..n)
        .map(|i| (i == 0 || i == n - 1 || !only_ends).then(|| spell(number(i), if style < 10 { 0 } else { style + i as u32 })))
        .collect();
    Numbers { ns, nf, text }
}

/// What the blocks of a program are written from.
pub(super) struct Words {
    pub(super) grid: Grid,
    pub(super) frame: Frame,
    /// G71 U(Δd) R(e) / G72 W(Δd) R(e): the first block (`None`: none), each word if written.
    pub(super) depth: Option<(Option<i64>, Option<i64>)>,
    pub(super) allowance: (Option<i64>, Option<i64>),
    pub(super) feed: i64,
    pub(super) numbers: Numbers,
    pub(super) blocks: Vec<Block>,
    /// Only what `legal` programs write: after the cycle nothing but its G70.
    pub(super) legal: bool,
}

/// Writes the program; returns G70's (U, W) when a G70 finishes a roughing cycle.
pub(super) fn write(cycle: Cycle, (defect, v): (Defect, u32), w: &mut Writer, d: &mut Dice, config: &mut Config, p: &Words) -> Option<(i64, i64)> {
    let dec = p.grid.decimals();
    let lead_dec = p.grid.lead_decimals();
    let a = p.frame.a;
    let u = unit(p.grid);
    // Before the cycle: O, G50, spindle and feed modes, the nose-radius codes, then A.
    if d.chance(8) {
        w.line("O0071");
    }
    let by_config = d.chance(10);
    if !by_config && d.chance(20) {
        let (gx, gz) = (w.length(d.range(0, 300 * u), dec), w.length(d.range(-50 * u, 200 * u), dec));
        w.block(&[('G', "50".into()), ('X', gx), ('Z', gz)]);
    }
    // No G96 here: it needs an earlier G50 S (G96.SMAX) and refuses the G00 to A (G96.RAPID).
    if d.chance(10) {
        w.line(d.one_of(&["G50 S2500", "G97 S800", "G99", "G98", "G40 T0202", "M3 S500 T0101"]));
    }
    let comp = defect.before_cycle(w, d, dec);
    if by_config {
        (config.start_x, config.start_z) = a;
    } else {
        let (x, z) = (w.length(a.0, dec), w.length(a.1, dec));
        w.block(&[('G', "00".into()), ('X', x), ('Z', z)]);
    }
    // A G90 run from A: the one-shot cycle does not end it (CNT.MODAL), a later axis block
    // repeats it.
    let g90 = !p.legal && d.chance(3);
    if g90 {
        let (x, z) = (w.length(a.0 - 2 * u, dec), w.length(a.1 - 3 * u, dec));
        w.block(&[('G', "90".into()), ('X', x), ('Z', z), ('F', "0.2".into())]);
    }
    let feed = w.length(p.feed, lead_dec);
    let pq = defect.pq(v, &p.numbers, cycle);
    if cycle == Cycle::G70 {
        // The contour runs as ordinary blocks first (CNT.FLOW): it needs a feed for G01.
        let feed_where = if defect == Defect::MissingFeed { 2 } else { d.weighted(&[55, 45]) };
        if feed_where == 1 {
            w.block(&[('F', feed.clone())]);
        }
        contour(w, d, p, (feed_where == 0).then_some(p.feed));
        defect.between(w, &p.numbers, cycle);
        let back = if !d.chance(15) { a } else { (a.0 + 2 * d.range(-u, u), a.1 + d.range(-u, u)) };
        let (x, z) = (w.length(back.0, dec), w.length(back.1, dec));
        w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);
        let uw = finish_words(d, u);
        g70_block(w, dec, &pq, uw, (defect != Defect::MissingFeed && d.chance(70)).then_some(feed));
        defect.after_g70(w);
        after(w, d, p, &pq, g90);
        return None;
    }
    let mut second = if cycle == Cycle::G73 {
        g73_blocks(w, d, dec, u)
    } else {
        first_blocks(w, d, p, (defect, v), dec, u)
    };
    second.extend(pq.0.clone().map(|t| ('P', t)));
    second.extend(pq.1.clone().map(|t| ('Q', t)));
    second.extend(p.allowance.0.map(|v| ('U', w.length(v, dec))));
    second.extend(p.allowance.1.map(|v| ('W', w.length(v, dec))));
    if let Some(word) = defect.second_block_word(v, dec) {
        second.retain(|(l, _)| *l != word.0);
        second.push(word);
    }
    // The roughing feed: mostly the second block's F; sometimes the modal feed from before.
    if defect != Defect::MissingFeed {
        if !p.legal && d.chance(5) {
            w.block(&[('F', feed)]);
        } else {
            second.push(('F', feed));
        }
    }
    if !comp && d.chance(10) {
        second.push(('S', "500".into()));
        second.push(('T', "0101".into()));
    }
    w.block(&second);
    defect.between(w, &p.numbers, cycle);
    contour(w, d, p, None);
    let finish = d.chance(50).then(|| {
        // From A (the cycle's end), or from elsewhere.
        if !p.legal && d.chance(15) {
            let (x, z) = (w.length(a.0 + 2 * d.range(0, u), dec), w.length(a.1 + d.range(0, u), dec));
            w.block(&[('G', "0".into()), ('X', x), ('Z', z)]);
        }
        let uw = finish_words(d, u);
        let f = d.chance(60).then(|| w.length(d.range(LEAD_UNIT / 100, LEAD_UNIT / 2), lead_dec));
        g70_block(w, dec, &pq, uw, f);
        (uw.0.unwrap_or(0), uw.1.unwrap_or(0))
    });
    after(w, d, p, &pq, g90);
    finish
}

/// G71's or G72's first blocks (the other cycle's, an earlier one of this cycle, this one);
/// returns the second block's G word.
fn first_blocks(w: &mut Writer, d: &mut Dice, p: &Words, (defect, v): (Defect, u32), dec: u32, u: i64) -> Vec<(char, String)> {
    let (code, depth_letter, other) = match p.frame.axis {
        Axis::G71 => ("71", 'U', ("72", 'W')),
        Axis::G72 => ("72", 'W', ("71", 'U')),
    };
    // First blocks: the other cycle's (kept apart), an earlier one of this cycle (replaced).
    if d.chance(8) {
        let (dd, e) = (w.length(d.range(1, 3 * u), dec), w.length(d.range(0, u), dec));
        w.block(&[('G', other.0.into()), (other.1, dd), ('R', e)]);
    }
    if let Some((dd, e)) = p.depth {
        if d.chance(8) {
            let (d2, e2) = (w.length(d.range(1, 3 * u), dec), w.length(d.range(0, u), dec));
            w.block(&[('G', code.into()), (depth_letter, d2), ('R', e2)]);
        }
        let mut first = vec![('G', code.to_string())];
        first.extend(dd.map(|v| (depth_letter, w.length(v, dec))));
        first.extend(e.map(|v| ('R', w.length(v, dec))));
        if let Some(word) = defect.first_block_word(v, depth_letter) {
            first.retain(|(l, _)| *l != word.0);
            first.push(word);
        }
        w.block(&first);
    }
    vec![('G', code.to_string())]
}

/// G73's words: format (a)'s first block `G73 U(Δi) W(Δk) R(d)` (words omitted now and then:
/// 5135–5137), or format (b)'s I K D in the second block (sometimes after a format (a) first
/// block whose values they do not change); d mostly 1…12, sometimes 1, 0, with a point, large.
/// Returns the second block's words so far.
fn g73_blocks(w: &mut Writer, d: &mut Dice, dec: u32, u: i64) -> Vec<(char, String)> {
    let escape = |d: &mut Dice| match d.weighted(&[70, 15, 15]) {
        0 => d.range(0, 10 * u),
        1 => 0,
        _ => -d.range(1, 3 * u),
    };
    let count = |d: &mut Dice| match d.weighted(&[80, 8, 3, 3, 6]) {
        0 => d.range(2, 12).to_string(),
        1 => "1".to_string(),
        2 => "0".to_string(),
        3 => format!("{}.", d.range(1, 5)),
        _ => d.range(13, 40).to_string(),
    };
    let format_b = d.chance(35);
    if !format_b || d.chance(20) {
        let mut first = vec![('G', "73".to_string())];
        for (letter, v) in [('U', escape(d)), ('W', escape(d) / 2)] {
            if !d.chance(10) {
                first.push((letter, w.length(v, dec)));
            }
        }
        if !d.chance(10) {
            first.push(('R', count(d)));
        }
        if first.len() > 1 || d.chance(50) {
            w.block(&first);
        }
    }
    let mut second = vec![('G', "73".to_string())];
    if format_b {
        let (i, k, n) = (escape(d), escape(d) / 2, count(d));
        second.extend([('I', w.length(i, dec)), ('K', w.length(k, dec)), ('D', n)]);
        if d.chance(8) {
            second.remove(1 + d.below(3) as usize);
        }
    }
    second
}

/// What may follow the cycle (not in `legal` programs): a second G70, a block in the motion
/// mode from before the cycle (G00, or the G90 run), a G01 at the modal feed.
fn after(w: &mut Writer, d: &mut Dice, p: &Words, pq: &(Option<String>, Option<String>), g90: bool) {
    if p.legal {
        return;
    }
    let (dec, u, a) = (p.grid.decimals(), unit(p.grid), p.frame.a);
    if d.chance(10) {
        let uw = finish_words(d, u);
        g70_block(w, dec, pq, uw, None);
    }
    match d.weighted(&[85, 10, 5]) {
        0 if !g90 => {}
        // G90 keeps its end Z: X alone repeats it; G00 goes to X and Z.
        0 | 1 if g90 => {
            let x = w.length(a.0 - 4 * u, dec);
            w.block(&[('X', x)]);
        }
        0 | 1 => {
            let (x, z) = (w.length(a.0 - 4 * u, dec), w.length(a.1 + u, dec));
            w.block(&[('X', x), ('Z', z)]);
        }
        _ => {
            let z = w.length(-u, dec);
            w.block(&[('G', "01".into()), ('W', z)]);
        }
    }
}

/// G70's U and W: mostly none, else small of either sign.
fn finish_words(d: &mut Dice, u: i64) -> (Option<i64>, Option<i64>) {
    if !d.chance(50) {
        return (None, None);
    }
    let mut v = || (!d.chance(25)).then(|| d.range(-u / 4, u / 4));
    (v(), v())
}

fn g70_block(w: &mut Writer, dec: u32, pq: &(Option<String>, Option<String>), uw: (Option<i64>, Option<i64>), f: Option<String>) {
    let mut words = vec![('G', "70".to_string())];
    words.extend(pq.0.clone().map(|t| ('P', t)));
    words.extend(pq.1.clone().map(|t| ('Q', t)));
    words.extend(uw.0.map(|v| ('U', w.length(v, dec))));
    words.extend(uw.1.map(|v| ('W', w.length(v, dec))));
    words.extend(f.map(|f| ('F', f)));
    w.block(&words);
}

/// The contour's blocks: N where numbered, the motion code when the mode changes (or again),
/// X/U and Z/W where they change, an arc's R or I/K, F where given. `ns_feed`: an F in the ns
/// block (G70 alone: the ordinary run needs one).
fn contour(w: &mut Writer, d: &mut Dice, p: &Words, ns_feed: Option<i64>) {
    let dec = p.grid.decimals();
    let knobs = shape::stream(d.range(0, u32::MAX as i64) as u64, 6 * p.blocks.len());
    let mut at = p.frame.a;
    let mut mode: Option<Kind> = None;
    for (i, b) in p.blocks.iter().enumerate() {
        let bd = &mut Dice::new(&knobs[6 * i..6 * i + 6]);
        let mut words: Vec<(char, String)> = Vec::new();
        if let Some(n) = &p.numbers.text[i] {
            words.push(('N', n.clone()));
        }
        let code = match b.el.kind {
            Kind::Rapid => "0",
            Kind::Feed => "1",
            Kind::Arc { cw: true } => "2",
            Kind::Arc { cw: false } => "3",
        };
        match &b.g {
            Some(g) if g.is_empty() => {}
            Some(g) => words.push(('G', g.clone())),
            None if mode != Some(b.el.kind) || bd.chance(10) => {
                words.push(('G', if bd.chance(50) { format!("0{code}") } else { code.to_string() }));
            }
            None => {}
        }
        if b.g.as_deref() != Some("") {
            mode = Some(b.el.kind);
        }
        let (x, z) = b.el.end;
        let write_x = !b.bare && (x != at.0 || bd.chance(10) || b.el.end == at);
        if write_x {
            words.push(axis(w, bd, 'X', 'U', x, at.0, dec));
        }
        if !b.bare && (z != at.1 || bd.chance(10)) {
            words.push(axis(w, bd, 'Z', 'W', z, at.1, dec));
        }
        if let (Kind::Arc { .. }, Some(c), false) = (b.el.kind, b.el.centre, b.bare) {
            let (i_, k_) = ((c.0 - at.0) / 2, c.1 - at.1);
            let mut ik = Vec::new();
            if i_ != 0 || k_ == 0 || bd.chance(40) {
                ik.push(('I', w.length(i_, dec)));
            }
            if k_ != 0 || i_ == 0 || bd.chance(40) {
                ik.push(('K', w.length(k_, dec)));
            }
            let r = || b.el.radius(at).unwrap_or(1).max(1);
            match &b.arc {
                ArcWords::Ik => words.extend(ik),
                ArcWords::R => words.push(('R', w.length(r(), dec))),
                ArcWords::RText(t) => words.push(('R', t.clone())),
                ArcWords::RIk => {
                    words.push(('R', w.length(r(), dec)));
                    words.extend(ik);
                }
                ArcWords::Neither => {}
            }
        } else if let ArcWords::RText(t) = &b.arc {
            words.push(('R', t.clone()));
        }
        if let Some(f) = b.feed.or(if i == 0 { ns_feed } else { None }) {
            words.push(('F', w.length(f, p.grid.lead_decimals())));
        }
        words.extend(b.extra.iter().cloned());
        w.block(&words);
        at = b.el.end;
    }
}

