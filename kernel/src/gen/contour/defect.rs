//! The register's alarms of the contour programs, each planted by one defect at a controlled
//! rate (30 % of the cases, one defect each, alike often): the configuration and the program
//! words before the cycle (nc201, parameters, TNRC.*, G50), the cycle blocks (CNT.PQ, G71.DEPTH,
//! COM.LEAD, COM.RANGES), finding the contour (CNT.FIND both ways, CNT.MAX at 1 000 and 1 001
//! blocks, 1 000 blocks without N(nf)), the contour's blocks (CNT.WORDS, CNT.NOSUB, CNT.FIRST,
//! TNRC.SWITCH, a lexing error met while the contour is read, an ns block without axis words),
//! the shape
//! (G71/G72.TYPE2, FIRST, MONOTONE — a step back, an arc turning inside its sweep, no travel
//! along the cut) and the arcs (ARC.R: R ≤ 0, R > N, chord > 2R; ARC.TOL: off the circle, on the
//! start's ray, E = S; ARC.FORMAT: R with I/K, neither; ARC.IK: I0 K0). A geometric defect is
//! inserted as an element and a line back to where it started, so the contour after it stays
//! as drawn and the defect's alarm is the first one.

use super::shape::{self, Element, Frame, Half, Kind};
use super::program::Numbers;
use super::{ArcWords, Block, Cycle};
use crate::gen::writer::Writer;
use crate::gen::{Dice, N};
use cycle_vocab::text::fixed;
use cycle_vocab::{Config, Dialect, Grid};

/// One planted defect.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Defect {
    Clean,
    Nc201,
    BadParam,
    ManyPasses,
    NoseRadius,
    TnrcNoArc,
    TnrcSwitch,
    TnrcTool,
    TnrcToolInContour,
    G50Word,
    G50Range,
    MissingP,
    MissingQ,
    MissingFeed,
    PqValue,
    DepthValue,
    AllowValue,
    NsNotNext,
    NfMissing,
    NsTwice,
    NfAfterG70,
    TooLong,
    Lexing,
    Words,
    NoSub,
    FirstNoG,
    FirstArc,
    NsBare,
    Type2,
    First,
    Back,
    ArcTurns,
    NoTravel,
    ArcRZero,
    ArcRHuge,
    ArcChord,
    ArcOff,
    ArcRIk,
    ArcNeither,
    ArcIkZero,
    ArcRay,
    ArcFull,
}

use Defect::*;

/// The defects of every family.
const COMMON: &[Defect] = &[
    Nc201, BadParam, NoseRadius, TnrcNoArc, TnrcSwitch, TnrcTool, TnrcToolInContour, G50Word, G50Range, MissingP,
    MissingQ, MissingFeed, PqValue, NsNotNext, NfMissing, TooLong, Lexing, Words, NoSub, FirstNoG, FirstArc, NsBare, Type2, First,
    Back, ArcTurns, NoTravel, ArcRZero, ArcRHuge, ArcChord, ArcOff, ArcRIk, ArcNeither, ArcIkZero, ArcRay, ArcFull,
];
/// G71 and G72 only: the first block's values, the allowance, the pass bound.
const ROUGHING: &[Defect] = &[DepthValue, AllowValue, ManyPasses];
/// G73 only: the allowance's values, the pass bound.
const PATTERN: &[Defect] = &[AllowValue, ManyPasses];
/// G70 alone only: N(ns) twice before it, N(nf) after it.
const FINISHING: &[Defect] = &[NsTwice, NfAfterG70];

/// The defect of a case — none in 70 %, else one of its family's alike often — and a number
/// that picks the defect's variant. (Three knobs.)
pub(super) fn draw(d: &mut Dice, cycle: Cycle) -> (Defect, u32) {
    if !d.chance(30) {
        return (Clean, 0);
    }
    let own = match cycle {
        Cycle::G70 => FINISHING,
        Cycle::G73 => PATTERN,
        Cycle::G71 | Cycle::G72 => ROUGHING,
    };
    let all: Vec<Defect> = COMMON.iter().chain(own).copied().collect();
    (d.one_of(&all), d.below(1 << 16) as u32)
}

/// A number no block of the program carries.
const ABSENT: i64 = 99_999;

impl Defect {
    /// The parameters and dialect of the configuration defects.
    pub(super) fn configure(self, d: &mut Dice, config: &mut Config, u: i64) {
        let p = &mut config.params;
        match self {
            Nc201 => config.dialect = Dialect::Nc201,
            ManyPasses => p.max_passes = Some(d.range(1, 4)),
            NoseRadius => p.nose_radius = Some(d.range(1, u)),
            BadParam => match d.below(6) {
                0 => p.arc_tolerance = Some(-1),
                1 => p.arc_tolerance = Some(N + 1),
                2 => p.p5132_rough_depth = Some(0),
                3 => p.p5133_rough_retract = Some(-1),
                4 => p.nose_radius = Some(-1),
                _ => p.max_passes = Some(0),
            },
            _ => {}
        }
    }

    /// Blocks before the cycle's start: the nose-radius codes (legal ones now and then too) and
    /// G50's refused words. Returns whether G41 or G42 is in force at the cycle.
    pub(super) fn before_cycle(self, w: &mut Writer, d: &mut Dice, dec: u32) -> bool {
        match self {
            TnrcNoArc => w.line(d.one_of(&["G41 G03 U1 W-1 R1 F0.1", "G02 G40 W-1 R2 F0.1"])),
            TnrcSwitch => w.line(d.one_of(&["G41\nG42", "G42\nG41 X1", "G41 G42"])),
            TnrcTool => w.line(d.one_of(&["G42\nT0202", "G41 T0101"])),
            G50Word => w.line(d.one_of(&["G50 U1", "G50 X1 W1", "G50 F1"])),
            G50Range => w.line(&format!("G50 X{}", fixed(N + 1, dec))),
            NoseRadius | TnrcToolInContour => {
                w.line(d.one_of(&["G41", "G42"]));
                return true;
            }
            _ if d.chance(10) => {
                w.line(d.one_of(&["G41", "G42"]));
                if d.chance(50) {
                    w.line("G40");
                    return false;
                }
                return true;
            }
            _ => {}
        }
        false
    }

    /// P(ns) and Q(nf) of the cycle block as written (`None`: missing).
    pub(super) fn pq(self, v: u32, n: &Numbers, cycle: Cycle) -> (Option<String>, Option<String>) {
        let (p, q) = (Some(n.ns.to_string()), Some(n.nf.to_string()));
        match self {
            MissingP => (None, q),
            MissingQ => (p, None),
            PqValue => match v % 4 {
                0 => (Some("0".into()), q),
                1 => (p, Some("100000".into())),
                2 => (Some(format!("{}.0", n.ns)), q),
                _ => (p, Some("-5".into())),
            },
            NfMissing | NfAfterG70 => (p, Some(ABSENT.to_string())),
            // 1 000 blocks without N(nf): the search goes on to the program's end.
            TooLong if v % 3 == 2 => (p, Some(ABSENT.to_string())),
            // G70 alone: its P names no block; G71, G72: a block stands before N(ns) (`between`).
            NsNotNext if cycle == Cycle::G70 => (Some(ABSENT.to_string()), q),
            _ => (p, q),
        }
    }

    /// A block between the cycle block and the contour (G71, G72), or after the contour
    /// (G70 alone): CNT.FIND's defects.
    pub(super) fn between(self, w: &mut Writer, n: &Numbers, cycle: Cycle) {
        match (self, cycle) {
            (NsNotNext, Cycle::G71 | Cycle::G72 | Cycle::G73) => w.line("M08"),
            (NsTwice, _) => w.line(&format!("N{} M08", n.ns)),
            _ => {}
        }
    }

    /// After a G70 alone: N(nf) too late (the G70's Q names it).
    pub(super) fn after_g70(self, w: &mut Writer) {
        if self == NfAfterG70 {
            w.line(&format!("N{ABSENT} G00 X1"));
        }
    }

    /// A word of the first block replaced by an illegal value (G71.DEPTH, G71.RETRACT,
    /// G72.DEPTH): (letter, text).
    pub(super) fn first_block_word(self, v: u32, depth_letter: char) -> Option<(char, String)> {
        (self == DepthValue).then(|| match v % 3 {
            0 => (depth_letter, "0".to_string()),
            1 => (depth_letter, "-1".to_string()),
            _ => ('R', "-1".to_string()),
        })
    }

    /// An allowance beyond N (COM.RANGES).
    pub(super) fn second_block_word(self, v: u32, dec: u32) -> Option<(char, String)> {
        (self == AllowValue).then(|| (if v.is_multiple_of(2) { 'U' } else { 'W' }, fixed(N + 1, dec)))
    }

    /// The contour's defects, on `blocks` (the ns block first) drawn in `f`, `u` the geometry's
    /// unit.
    pub(super) fn apply(self, v: u32, d: &mut Dice, f: Frame, blocks: &mut Vec<Block>, (tolerance, u, grid): (i64, i64, Grid)) {
        let (hp, hq) = f.h();
        let len = blocks.len();
        let j = 1 + d.below((len - 1).max(1) as u64) as usize;
        let before = f.half(blocks[j - 1].el.end);
        let a_prime = blocks[0].el.end;
        let line = |to: Half| Block::of(Element { kind: Kind::Feed, end: f.xz(to), centre: None, exact: true }, ArcWords::Ik);
        let rho = 2 * d.range(u / 2, 2 * u).max(1);
        let quarter = |words: ArcWords| {
            let arc = shape::quadrant(f, before, rho, true)[0];
            Block::of(Element { kind: arc.kind, end: f.xz(arc.end), centre: arc.centre.map(|c| f.xz(c)), exact: true }, words)
        };
        let arc = |end: Half, centre: Half, cw: bool| {
            Block::of(Element { kind: Kind::Arc { cw }, end: f.xz(end), centre: Some(f.xz(centre)), exact: false }, ArcWords::Ik)
        };
        let back = line(before);
        let inserted = match self {
            TooLong => {
                blocks.truncate(if v % 3 == 1 { 1_001 } else { 1_000 });
                return;
            }
            Lexing => {
                let i = d.below(len as u64) as usize;
                blocks[i].extra.push(('#', String::new()));
                return;
            }
            Words | NoSub | TnrcToolInContour => {
                let i = d.below(len as u64) as usize;
                let linear = !matches!(blocks[i].el.kind, Kind::Arc { .. });
                let word = match self {
                    NoSub => ('M', d.one_of(&["98", "99", "098", "98.0"]).to_string()),
                    TnrcToolInContour => ('T', "0101".to_string()),
                    _ => {
                        let mut words = vec![
                            ("G", "4"),
                            ("P", "1"),
                            ("J", "1"),
                            ("L", "2"),
                            ("M", "3"),
                            ("M", "-99"),
                            ("G", "41"),
                            ("G", "50"),
                            ("G", "1.0"),
                            ("G", "-1"),
                            ("O", "1"),
                            ("Q", "1"),
                            ("E", "1"),
                        ];
                        if linear {
                            words.extend([("R", "1"), ("I", "1")]);
                        }
                        let (l, v) = d.one_of(&words);
                        (l.chars().next().unwrap_or('G'), v.to_string())
                    }
                };
                blocks[i].extra.push(word);
                return;
            }
            FirstNoG => {
                blocks[0].g = Some(String::new());
                return;
            }
            FirstArc => {
                blocks[0].g = Some(d.one_of(&["02", "3"]).to_string());
                blocks[0].arc = ArcWords::RText(fixed(100 * u, grid.decimals()));
                let code = match blocks[1].el.kind {
                    Kind::Rapid => "0",
                    Kind::Feed => "1",
                    Kind::Arc { cw: true } => "2",
                    Kind::Arc { cw: false } => "3",
                };
                blocks[1].g = Some(code.to_string());
                return;
            }
            // The ns block without axis words (its end is A): G71.FIRST; G70 moves to P₀ all the
            // same.
            NsBare => {
                blocks[0].bare = true;
                blocks[0].g = Some(d.one_of(&["00", "1"]).to_string());
                blocks[0].el.end = f.a;
                blocks.insert(1, line(f.half(a_prime)));
                return;
            }
            Type2 | First => {
                let (t, w) = f.half(a_prime);
                blocks[0].el.end = f.xz(if self == First { (0, 0) } else { (t, w + hq * d.range(1, u)) });
                blocks.insert(1, line((t, w)));
                return;
            }
            NoTravel => {
                blocks.truncate(1);
                let (t, _) = f.half(a_prime);
                blocks.push(line(((t / (2 * hp)) * hp, 0)));
                return;
            }
            Back => {
                let to = if d.chance(50) { (before.0 + hp * d.range(1, u), before.1) } else { (before.0, before.1 - hq * d.range(1, u)) };
                line(to)
            }
            ArcTurns => {
                // Through the frame's extreme T (φ = 0°: the infeed axis turns) or extreme W.
                let (a0, a1) = if d.chance(50) { (-20f64, 40f64) } else { (50f64, 110f64) };
                let r = rho as f64 * 2.0;
                let polar = |deg: f64| (r * deg.to_radians().cos(), r * deg.to_radians().sin());
                let even = |v: f64| (v / 2.0).round() as i64 * 2;
                let from = polar(a0);
                let centre = (before.0 - even(from.0), before.1 - even(from.1));
                let to = polar(a1);
                arc(f.snap((centre.0 as f64 + to.0, centre.1 as f64 + to.1)), centre, f.cw(true))
            }
            ArcRZero => quarter(ArcWords::RText(d.one_of(&["0", "-1", "-0.5", "0.000"]).to_string())),
            ArcRHuge => quarter(ArcWords::RText(fixed(N + 1, grid.decimals()))),
            ArcChord => quarter(ArcWords::RText(fixed((rho / 8).max(1), grid.decimals()))),
            ArcRIk => quarter(ArcWords::RIk),
            ArcNeither => quarter(ArcWords::Neither),
            ArcOff => {
                let mut b = quarter(ArcWords::Ik);
                let (t, w) = f.half(b.el.end);
                b.el.end = f.xz((t, w + hq * (2 * tolerance + 2)));
                b
            }
            ArcIkZero => {
                let mut b = quarter(ArcWords::Ik);
                b.el.centre = Some(blocks[j - 1].el.end);
                b
            }
            ArcRay => {
                // A centre m·g before the start, g = (2, 2) half units: the end one g beyond
                // or short of the start (within the tolerance), or as far again (beyond it).
                let m = d.range(100, 2_000);
                let centre = (before.0 - 2 * m, before.1 - 2 * m);
                let k = [m + 1, m - 1, 2 * m][d.below(3) as usize];
                arc((centre.0 + 2 * k, centre.1 + 2 * k), centre, d.chance(50))
            }
            ArcFull => arc(before, (before.0 - rho, before.1), d.chance(50)),
            _ => return,
        };
        blocks.insert(j, back);
        blocks.insert(j, inserted);
    }
}
