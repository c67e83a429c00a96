//! SVG toolpath plots: Z across, X up — X as a **radius** (the diameter of the trace halved), in
//! mm (inch); the two axes are scaled independently so that thread depths stay visible.
//!
//! Rapids are dashed grey, feeds solid grey (arcs drawn as arcs: with the axes scaled
//! independently a circle is an axis-aligned ellipse), thread moves coloured by the kind of their pass
//! (rough, finish, spring), pull-outs (moves tagged with a pull-out rule) orange, the infeed
//! point of each pass (where its first thread move starts) a dot, a feed hold or reset pressed by
//! the operator a brown diamond (its retract in the pull-out manner orange). When the candidate's trace
//! differs, each candidate move that differs from the reference at its index is drawn red and
//! thick, and the first divergence is labelled.
//!
//! The view is zoomed to the cycles: it spans the moves from the first pass header on (and every
//! divergent move); positioning moves before the first pass are clipped at its edge.

use super::markdown::escape;
use cycle_vocab::text::{fixed, Trace};
use cycle_vocab::{Config, Event, Move, MoveKind, PassKind, Rule};
use std::fmt::Write as _;

const WIDTH: f64 = 960.0;
const HEIGHT: f64 = 440.0;
const LEFT: f64 = 70.0;
const RIGHT: f64 = 20.0;
const TOP: f64 = 66.0;
const BOTTOM: f64 = 45.0;

const RAPID: &str = "#8c8c8c";
const FEED: &str = "#555555";
const ROUGH: &str = "#1f77b4";
const FINISH: &str = "#2ca02c";
const SPRING: &str = "#9467bd";
const PULLOUT: &str = "#ff7f0e";
const DIVERGENT: &str = "#d62728";
const PRESS: &str = "#8c564b";

/// Whether a move realises a pull-out (its rule tag), the programmed one or the retract in the
/// pull-out manner after a feed hold (G92.HOLD, G76.HOLD).
fn is_pullout(rule: Rule) -> bool {
    matches!(
        rule,
        Rule::G92Pullout
            | Rule::G92Jk1
            | Rule::G92Jk2
            | Rule::G92Jk3
            | Rule::G92Jk4
            | Rule::G92Jk5
            | Rule::G92Jk6
            | Rule::G92Jk7
            | Rule::G76Pullout
            | Rule::G78Pullout
            | Rule::G92Hold
            | Rule::G76Hold
    )
}

fn pass_colour(kind: Option<PassKind>) -> &'static str {
    match kind {
        Some(PassKind::Rough | PassKind::Semi) => ROUGH,
        Some(PassKind::Finish) => FINISH,
        Some(PassKind::Spring) => SPRING,
        None => FEED,
    }
}

/// A segment of a trace: from, to (X diameter, Z, increments), the move, and its pass kind.
struct Segment {
    index: usize,
    from: (i64, i64),
    to: (i64, i64),
    m: Move,
    pass: Option<PassKind>,
    first_thread_of_pass: bool,
}

/// An arc's geometry in mm with X as a radius: (centre z, centre r), radius, start angle, and the
/// signed sweep (radians, negative clockwise as seen with Z right and X up; a full turn when the
/// end is the start's direction). `None` for other moves.
fn arc_geometry(seg: &Segment, scale: f64) -> Option<((f64, f64), f64, f64, f64)> {
    let cw = match seg.m.kind {
        MoveKind::ArcCw => true,
        MoveKind::ArcCcw => false,
        _ => return None,
    };
    let point = |(x, z): (i64, i64)| (z as f64 / scale, x as f64 / 2.0 / scale);
    let (c, a, b) = (point((seg.m.cx, seg.m.cz)), point(seg.from), point(seg.to));
    let radius = ((a.0 - c.0).powi(2) + (a.1 - c.1).powi(2)).sqrt();
    let (start, end) = ((a.1 - c.1).atan2(a.0 - c.0), (b.1 - c.1).atan2(b.0 - c.0));
    let tau = std::f64::consts::TAU;
    let mut sweep = (end - start).rem_euclid(tau); // counter-clockwise
    if sweep == 0.0 {
        sweep = tau;
    }
    Some((c, radius, start, if cw { sweep - tau } else { sweep }))
}

/// The points that bound a segment: its ends, and for an arc the quadrant points its sweep
/// passes (mm, (z, r)).
fn extent(seg: &Segment, scale: f64) -> Vec<(f64, f64)> {
    let point = |(x, z): (i64, i64)| (z as f64 / scale, x as f64 / 2.0 / scale);
    let mut out = vec![point(seg.from), point(seg.to)];
    if let Some((c, radius, start, sweep)) = arc_geometry(seg, scale) {
        let quarter = std::f64::consts::FRAC_PI_2;
        for k in 0..4 {
            let angle = quarter * f64::from(k);
            let along = if sweep >= 0.0 { (angle - start).rem_euclid(std::f64::consts::TAU) } else { (start - angle).rem_euclid(std::f64::consts::TAU) };
            if along < sweep.abs() {
                out.push((c.0 + radius * angle.cos(), c.1 + radius * angle.sin()));
            }
        }
    }
    out
}

fn segments(trace: &Trace, start: (i64, i64)) -> Vec<Segment> {
    let mut out = Vec::new();
    let mut at = start;
    let mut pass = None;
    let mut pass_has_thread = true;
    for (index, e) in trace.events.iter().enumerate() {
        match e {
            Event::Pass(p) => {
                pass = Some(p.kind);
                pass_has_thread = false;
            }
            Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => {}
            Event::Move(m) => {
                let first = m.kind == MoveKind::Thread && !pass_has_thread;
                if m.kind == MoveKind::Thread {
                    pass_has_thread = true;
                }
                out.push(Segment { index, from: at, to: (m.x, m.z), m: *m, pass, first_thread_of_pass: first });
                at = (m.x, m.z);
            }
        }
    }
    out
}

/// Whether the candidate's event at `index` differs from the reference's (fields compared as the
/// conformance relation does: everything but the rule tag).
fn differs(reference: &Trace, candidate: &Trace, index: usize) -> bool {
    match (reference.events.get(index), candidate.events.get(index)) {
        (Some(Event::Move(r)), Some(Event::Move(c))) => {
            (r.kind, r.x, r.z, r.feed, r.cx, r.cz, r.angle, r.lead_change, r.lead_change_angle, r.lead_floor, r.lead_steps)
                != (c.kind, c.x, c.z, c.feed, c.cx, c.cz, c.angle, c.lead_change, c.lead_change_angle, c.lead_floor, c.lead_steps)
        }
        (Some(Event::Pass(r)), Some(Event::Pass(c))) => (r.index, r.kind, r.diameter_depth) != (c.index, c.kind, c.diameter_depth),
        (None, None) => false,
        _ => true,
    }
}

/// A clip-path id unique per plot (several plots share one page).
fn clip_id(title: &str) -> String {
    let safe: String = title.chars().map(|c| if c.is_ascii_alphanumeric() { c } else { '_' }).collect();
    format!("view_{safe}")
}

/// Tick positions: about eight round values covering lo…hi.
fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = (hi - lo).max(1e-9);
    let raw = span / 8.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 2.5, 5.0, 10.0].iter().map(|m| m * mag).find(|s| *s >= raw).unwrap_or(10.0 * mag);
    let mut v = (lo / step).ceil() * step;
    let mut out = Vec::new();
    while v <= hi + step * 1e-6 && out.len() < 20 {
        out.push(if v.abs() < step * 1e-9 { 0.0 } else { v });
        v += step;
    }
    out
}

/// The plot of `reference` (and where it differs, `candidate`) for a program run under
/// `config`; `divergence`: the first divergent event and its rule, for the label.
pub fn svg(title: &str, config: &Config, reference: &Trace, candidate: Option<&Trace>, divergence: Option<(usize, Option<Rule>)>) -> String {
    let start = (config.start_x, config.start_z);
    let refs = segments(reference, start);
    let cands: Vec<Segment> = match candidate {
        Some(c) => segments(c, start).into_iter().filter(|s| differs(reference, c, s.index)).collect(),
        None => Vec::new(),
    };
    let scale = 10f64.powi(reference.grid.decimals() as i32);
    let radius = |x: i64| x as f64 / 2.0 / scale;
    let axial = |z: i64| z as f64 / scale;
    // Bounds: the cycles (from the first pass header on; everything when there is none) and the
    // divergent moves.
    let first_pass = reference.events.iter().position(|e| matches!(e, Event::Pass(_)));
    let in_view: Vec<&Segment> = refs.iter().filter(|s| first_pass.is_none_or(|p| s.index > p)).collect();
    let mut points: Vec<(f64, f64)> = Vec::new();
    if in_view.is_empty() {
        points.push((axial(start.1), radius(start.0)));
    }
    points.extend(in_view.iter().copied().chain(cands.iter()).flat_map(|s| extent(s, scale)));
    let (mut z0, mut z1, mut r0, mut r1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(z, r) in &points {
        z0 = z0.min(z);
        z1 = z1.max(z);
        r0 = r0.min(r);
        r1 = r1.max(r);
    }
    let pad = |lo: f64, hi: f64| {
        let p = ((hi - lo) * 0.05).max(0.5 / scale.sqrt());
        (lo - p, hi + p)
    };
    let (z0, z1) = pad(z0, z1);
    let (r0, r1) = pad(r0, r1);
    let (pw, ph) = (WIDTH - LEFT - RIGHT, HEIGHT - TOP - BOTTOM);
    let px = |z: i64| LEFT + (axial(z) - z0) / (z1 - z0) * pw;
    let py = |x: i64| TOP + ph - (radius(x) - r0) / (r1 - r0) * ph;
    // A segment's shape: a line, or an elliptical arc (G02 clockwise on the page, as in the
    // register's view; the large-arc flag from the sweep).
    let shape = |seg: &Segment| -> (&'static str, String) {
        let (x1, y1, x2, y2) = (px(seg.from.1), py(seg.from.0), px(seg.to.1), py(seg.to.0));
        match arc_geometry(seg, scale) {
            Some((_, radius, _, sweep)) => {
                let (rx, ry) = (radius / (z1 - z0) * pw, radius / (r1 - r0) * ph);
                let large = u8::from(sweep.abs() > std::f64::consts::PI);
                let clockwise = u8::from(sweep < 0.0);
                ("path", format!(r#"d="M {x1:.2} {y1:.2} A {rx:.2} {ry:.2} 0 {large} {clockwise} {x2:.2} {y2:.2}" fill="none""#))
            }
            None => ("line", format!(r#"x1="{x1:.2}" y1="{y1:.2}" x2="{x2:.2}" y2="{y2:.2}""#)),
        }
    };
    let unit = reference.grid.unit_name().to_lowercase();

    let mut s = String::new();
    let _ = writeln!(
        s,
        r#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {WIDTH} {HEIGHT}" width="{WIDTH}" height="{HEIGHT}" font-family="sans-serif" font-size="12" role="img" aria-label="toolpath of {t}">"#,
        t = escape(title)
    );
    let _ = writeln!(s, r#"<rect width="{WIDTH}" height="{HEIGHT}" fill="white"/>"#);
    let _ = write!(s, r#"<text x="{LEFT}" y="18" font-size="14" font-weight="bold">{}"#, escape(title));
    if let Some(a) = &reference.alarm {
        let _ = write!(s, r#"<tspan class="alarm" fill="{DIVERGENT}"> — the trace ends in {}</tspan>"#, escape(&Trace::alarm_line(a)));
    }
    s.push_str("</text>\n");
    let _ = writeln!(
        s,
        r##"<text x="{LEFT}" y="34" fill="#444">Z ({unit}) across, X as radius ({unit}) up; axes scaled independently{clip}</text>"##,
        clip = if first_pass.is_some_and(|p| p > 0) { "; positioning before the first pass clipped" } else { "" }
    );
    let _ = writeln!(
        s,
        r#"<defs><clipPath id="{id}"><rect x="{LEFT}" y="{TOP}" width="{pw}" height="{ph}"/></clipPath></defs>"#,
        id = clip_id(title)
    );
    // Axes and ticks.
    let _ = writeln!(s, r##"<rect x="{LEFT}" y="{TOP}" width="{pw}" height="{ph}" fill="none" stroke="#ccc"/>"##);
    for z in ticks(z0, z1) {
        let x = LEFT + (z - z0) / (z1 - z0) * pw;
        let _ = writeln!(
            s,
            r##"<line x1="{x:.1}" y1="{TOP}" x2="{x:.1}" y2="{b:.1}" stroke="#eee"/><text x="{x:.1}" y="{ty:.1}" text-anchor="middle" fill="#444">{z}</text>"##,
            b = TOP + ph,
            ty = TOP + ph + 16.0
        );
    }
    for r in ticks(r0, r1) {
        let y = TOP + ph - (r - r0) / (r1 - r0) * ph;
        let _ = writeln!(
            s,
            r##"<line x1="{LEFT}" y1="{y:.1}" x2="{e:.1}" y2="{y:.1}" stroke="#eee"/><text x="{tx:.1}" y="{ty:.1}" text-anchor="end" fill="#444">{r}</text>"##,
            e = LEFT + pw,
            tx = LEFT - 6.0,
            ty = y + 4.0
        );
    }
    let _ = writeln!(s, r##"<text x="{x:.1}" y="{y:.1}" text-anchor="middle" fill="#444">Z</text>"##, x = LEFT + pw / 2.0, y = HEIGHT - 6.0);
    let _ = writeln!(s, r##"<text x="14" y="{y:.1}" fill="#444">X</text>"##, y = TOP + ph / 2.0);

    // The reference path, clipped to the view.
    let _ = writeln!(s, r#"<g clip-path="url(#{})">"#, clip_id(title));
    for seg in &refs {
        let (colour, extra, class) = match seg.m.kind {
            MoveKind::Rapid => (RAPID, r#" stroke-dasharray="5 4""#, "rapid"),
            MoveKind::Feed => (FEED, "", "feed"),
            MoveKind::ArcCw | MoveKind::ArcCcw => (FEED, "", "arc"),
            MoveKind::Thread if is_pullout(seg.m.rule) => (PULLOUT, "", "pullout"),
            MoveKind::Thread => (pass_colour(seg.pass), "", "thread"),
        };
        let (tag, geometry) = shape(seg);
        let _ = writeln!(
            s,
            r#"<{tag} class="{class}" {geometry} stroke="{colour}" stroke-width="1.4"{extra}><title>event {} {}</title></{tag}>"#,
            seg.index,
            escape(&Trace::event_line(reference.grid, &Event::Move(seg.m)))
        );
    }
    for seg in refs.iter().filter(|s| s.first_thread_of_pass) {
        let _ = writeln!(
            s,
            r#"<circle class="infeed" cx="{:.2}" cy="{:.2}" r="3" fill="{}"><title>infeed point before event {}: X{} Z{}</title></circle>"#,
            px(seg.from.1),
            py(seg.from.0),
            pass_colour(seg.pass),
            seg.index,
            fixed(seg.from.0, reference.grid.decimals()),
            fixed(seg.from.1, reference.grid.decimals())
        );
    }
    press_marks(&mut s, reference, &px, &py);
    // The candidate's divergent moves.
    for seg in &cands {
        let (tag, geometry) = shape(seg);
        let _ = writeln!(
            s,
            r#"<{tag} class="divergent" {geometry} stroke="{DIVERGENT}" stroke-width="3.5" stroke-linecap="round"><title>candidate event {}: {}</title></{tag}>"#,
            seg.index,
            escape(&Trace::event_line(reference.grid, &Event::Move(seg.m)))
        );
    }
    s.push_str("</g>\n");
    if let Some((index, rule)) = divergence {
        let rule = rule.map(|r| format!(", rule {r}")).unwrap_or_default();
        let _ = writeln!(
            s,
            r#"<text x="{x:.1}" y="18" text-anchor="end" fill="{DIVERGENT}" font-weight="bold">first divergence: event {index}{rule}</text>"#,
            x = WIDTH - RIGHT
        );
    }
    legend(&mut s, !cands.is_empty());
    s.push_str("</svg>\n");
    s
}

/// A diamond where the operator pressed feed hold or reset (`Press` events, OP.SCRIPT).
fn press_marks(s: &mut String, trace: &Trace, px: &dyn Fn(i64) -> f64, py: &dyn Fn(i64) -> f64) {
    for (index, e) in trace.events.iter().enumerate() {
        if let Event::Press(p) = e {
            let (x, y) = (px(p.z), py(p.x));
            let _ = writeln!(
                s,
                r#"<path class="press" d="M{:.2},{:.2} l5,5 l-5,5 l-5,-5 z" fill="{PRESS}"><title>event {index} {}</title></path>"#,
                x,
                y - 5.0,
                escape(&Trace::event_line(trace.grid, e))
            );
        }
    }
}

fn legend(s: &mut String, divergent: bool) {
    let mut items: Vec<(&str, &str, &str)> = vec![
        ("rapid", RAPID, r#" stroke-dasharray="5 4""#),
        ("rough", ROUGH, ""),
        ("finish", FINISH, ""),
        ("spring", SPRING, ""),
        ("pull-out", PULLOUT, ""),
    ];
    if divergent {
        items.push(("divergent (candidate)", DIVERGENT, r#" stroke-width="3.5""#));
    }
    let mut x = LEFT;
    let y = 52.0;
    for (label, colour, extra) in items {
        let _ = write!(
            s,
            r#"<line x1="{x:.1}" y1="{y}" x2="{x2:.1}" y2="{y}" stroke="{colour}" stroke-width="2"{extra}/><text x="{tx:.1}" y="{ty}">{label}</text>"#,
            x2 = x + 18.0,
            tx = x + 22.0,
            ty = y + 4.0
        );
        x += 24.0 + 7.0 * label.len() as f64 + 8.0;
    }
    let _ = writeln!(
        s,
        r#"<circle cx="{x:.1}" cy="{y}" r="3" fill="{ROUGH}"/><text x="{tx:.1}" y="{ty}">infeed point</text>"#,
        tx = x + 6.0,
        ty = y + 4.0
    );
}

#[cfg(test)]
mod tests;
