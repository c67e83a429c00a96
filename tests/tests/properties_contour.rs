//! Properties of the stock-removal cycles G71 and G72 and of the G70 that follows them (M003),
//! over random **monotone** contours of lines and arcs, checked on the traces of BOTH engines
//! (each must satisfy them on its own; their agreement is `differential.rs`'s). Cases:
//! `CYCLECHECK_CASES` (default 10 000), from the fixed seed `CYCLECHECK_SEED`.
//!
//! The programs are `cycle_kernel::gen::contour::legal`'s: G71 or G72, outside and inside, both
//! cutting directions, allowances of every sign, Δd from an increment to beyond the stock, e from
//! 0 up, lines, rapids and arcs (by R and by I/K) that end exactly on their circles, so the
//! translated contour Q is known exactly. Work is in the frame of the cycle in half increments
//! (T the depth from A along the infeed axis, W the length along the cut; X counts and 2·Z are
//! Euclidean there), doubled so that half a count is an integer; arcs are decided on squares.
//!
//! For every layer k (G71.LAYER, G71.RETRACT; G72's): the header is index k, ROUGH, depth 2kΔd;
//! the infeed stands exactly at A.p + s·k·Δd (so every depth step is Δd, the layers monotone), in
//! the ns block's mode, along the infeed axis only; the cut runs along the cutting axis only, is
//! positive, and **ends within half an increment of where Q leaves the layer** — so no roughing
//! move enters the finished part plus its allowance by more than the one rounding, and every cut
//! reaches it; the 45° retract and the rapid back along the cut axis follow, never toward the
//! part. The layers are complete: a next layer would lie beyond Q₀ or cut at most half an
//! increment. The semi-finish pass (G71.LASTPASS) is the contour translated by (Δu, Δw) at the
//! roughing feed, arcs about their translated centres; the cycle returns to its start
//! (G71.RETURN); the pass count stays within `max_passes` (PRJ.MAXPASS). A following G70 is the
//! contour translated by its U, W (G70.PATH, G70.UW) and returns to its start (G70.RETURN).

use cycle_kernel::gen::contour::shape::{Axis, Element, Frame, Half, Kind};
use cycle_kernel::gen::contour::{self, Built};
use cycle_kernel::gen::{self, Dice};
use cycle_vocab::text::Trace;
use cycle_vocab::{Event, Move, MoveKind, Pass, PassKind};
use proptest::test_runner::{Config as ProptestConfig, RngAlgorithm, TestCaseError, TestError, TestRng, TestRunner};

fn cases() -> u32 {
    std::env::var("CYCLECHECK_CASES").ok().and_then(|v| v.trim().parse().ok()).unwrap_or(10_000)
}

fn seed() -> [u8; 32] {
    let s: u64 = std::env::var("CYCLECHECK_SEED").ok().and_then(|v| v.trim().parse().ok()).unwrap_or(0x5eed_c0a7_0c0a_7000);
    gen::seed_bytes(s)
}

/// A check's failure.
type Checked = Result<(), String>;

fn ensure(ok: bool, what: impl FnOnce() -> String) -> Checked {
    if ok {
        Ok(())
    } else {
        Err(what())
    }
}

/// The passes of a trace, each with the moves after its header.
fn passes(t: &Trace) -> Vec<(Pass, Vec<Move>)> {
    let mut out: Vec<(Pass, Vec<Move>)> = Vec::new();
    for e in &t.events {
        match e {
            Event::Pass(p) => out.push((*p, Vec::new())),
            Event::Move(m) => {
                if let Some(last) = out.last_mut() {
                    last.1.push(*m);
                }
            }
            // G70–G72 neither dwell nor switch the spindle: such an event is not a move.
            Event::Dwell(_) | Event::Spindle(_) | Event::Press(_) | Event::Stop(_) | Event::Resume(_) => panic!("a contour cycle's trace has {e:?}"),
        }
    }
    out
}

/// A move as the properties compare it: kind, end, feed (when `feed`), centre.
fn shape_of(m: &Move, feed: bool) -> (MoveKind, i64, i64, i64, i64, i64) {
    (m.kind, m.x, m.z, if feed { m.feed } else { 0 }, m.cx, m.cz)
}

/// The contour translated by `shift` (a diameter count, Z) as moves from `from`: the move to its
/// first point in the ns block's mode, then each element in its own mode, every move to the
/// current position left out (PRJ.NOOP).
fn run(elements: &[Element], shift: (i64, i64), feed: i64, from: (i64, i64)) -> Vec<Move> {
    let mut at = from;
    let mut out = Vec::new();
    for e in elements {
        let end = (e.end.0 + shift.0, e.end.1 + shift.1);
        if end == at {
            continue;
        }
        let rule = cycle_vocab::Rule::G71Lastpass;
        out.push(match (e.kind, e.centre) {
            (Kind::Rapid, _) => Move::rapid(end.0, end.1, rule),
            (Kind::Arc { cw }, Some(c)) => Move::arc(cw, end.0, end.1, c.0 + shift.0, c.1 + shift.1, feed, rule),
            _ => Move::feed(end.0, end.1, feed, rule),
        });
        at = end;
    }
    out
}

/// One piece of Q in the frame, doubled half units: a line, or an arc about a centre (on its
/// circle exactly: the generator's arcs end on their circles).
#[derive(Clone, Copy, Debug)]
struct Piece {
    from: Half,
    to: Half,
    centre: Option<Half>,
}

/// Q in the frame, doubled: (Q₀, its pieces).
fn q_frame(b: &Built) -> (Half, Vec<Piece>) {
    let f = b.frame;
    let (du, dw) = b.allowance;
    let at = |p: (i64, i64)| {
        let (t, w) = f.half((p.0 + du, p.1 + dw));
        (2 * t, 2 * w)
    };
    let q0 = at(b.elements[0].end);
    let mut from = q0;
    let pieces = b.elements[1..]
        .iter()
        .map(|e| {
            let to = at(e.end);
            let p = Piece { from, to, centre: e.centre.filter(|_| matches!(e.kind, Kind::Arc { .. })).map(at) };
            from = to;
            p
        })
        .collect();
    (q0, pieces)
}

/// Where Q leaves the layer at depth `t` (doubled): the W of the last point of Q with T ≥ t —
/// an integer, a quotient (num, den > 0), or a root wc + σ√m.
#[derive(Clone, Copy, Debug)]
enum Leave {
    Ratio(i128, i128),
    Root { wc: i128, sigma: i128, m: i128 },
}

fn leaves(q0: Half, pieces: &[Piece], t: i64) -> Leave {
    let mut w = i128::from(q0.1);
    for p in pieces {
        let (t0, w0, t1, w1) = (i128::from(p.from.0), i128::from(p.from.1), i128::from(p.to.0), i128::from(p.to.1));
        let t = i128::from(t);
        if t1 >= t {
            w = w1;
            continue;
        }
        if t0 < t {
            break;
        }
        // The piece crosses the layer: T falls from t0 ≥ t to t1 < t.
        return match p.centre {
            None => Leave::Ratio(w0 * (t0 - t1) + (t0 - t) * (w1 - w0), t0 - t1),
            Some((tc, wc)) => {
                let (tc, wc) = (i128::from(tc), i128::from(wc));
                let r2 = (t0 - tc).pow(2) + (w0 - wc).pow(2);
                let side = if w0 != wc { (w0 - wc).signum() } else { (w1 - wc).signum() };
                Leave::Root { wc, sigma: side, m: r2 - (t - tc).pow(2) }
            }
        };
    }
    Leave::Ratio(w, 1)
}

/// Whether the leaving point's W is ≤ `bound` (`le`) or ≥ it, exactly.
fn compare(l: Leave, bound: i128, le: bool) -> bool {
    match l {
        Leave::Ratio(n, d) => {
            if le {
                n <= bound * d
            } else {
                n >= bound * d
            }
        }
        Leave::Root { wc, sigma, m } => {
            // wc + σ√m ≤ bound ⇔ σ√m ≤ r, r = bound − wc (and ≥ alike with the sides swapped).
            let (s, r) = if le { (sigma, bound - wc) } else { (-sigma, wc - bound) };
            if s >= 0 {
                r >= 0 && m <= r * r
            } else {
                r >= 0 || m >= r * r
            }
        }
    }
}

/// The per-radius counts along the infeed and the cutting axis (X counts are diameters).
fn per(f: Frame) -> (i64, i64) {
    match f.axis {
        Axis::G71 => (2, 1),
        Axis::G72 => (1, 2),
    }
}

fn point(f: Frame, p: i64, q: i64) -> (i64, i64) {
    match f.axis {
        Axis::G71 => (p, q),
        Axis::G72 => (q, p),
    }
}

/// Every property of one engine's trace of `b`.
fn check(b: &Built, t: &Trace) -> Checked {
    ensure(t.alarm.is_none(), || format!("an alarm: {:?}", t.alarm))?;
    let f = b.frame;
    let a = f.a;
    let (per_p, per_q) = per(f);
    let (hp, hq) = f.h();
    let ps = passes(t);
    let k_layers = ps.iter().filter(|(p, _)| p.kind == PassKind::Rough).count();
    let max_passes = b.case.config.params.max_passes.unwrap_or(10_000);
    ensure((k_layers as i64) < max_passes, || format!("{k_layers} layers and SEMI exceed max_passes {max_passes}"))?;
    let feed = b.feed;
    let ns_rapid = b.elements[0].kind == Kind::Rapid;
    let (q0, pieces) = q_frame(b);
    let step = b.depth * per_p;

    // The layers.
    let mut at = a;
    for (k, (p, ms)) in ps.iter().take(k_layers).enumerate() {
        let k = k as i64 + 1;
        let here = || format!("layer {k}");
        ensure(p.kind == PassKind::Rough && p.index as i64 == k, || format!("{}: header {p:?}", here()))?;
        ensure(p.diameter_depth == 2 * k * b.depth, || format!("{}: depth {} ≠ 2kΔd = {}", here(), p.diameter_depth, 2 * k * b.depth))?;
        let pk = f.p(a) + f.s * k * step;
        let infeed = point(f, pk, f.q(a));
        let (infeed_move, cut) = (ms.first(), ms.get(1));
        let want_infeed = if ns_rapid { Move::rapid(infeed.0, infeed.1, p.rule) } else { Move::feed(infeed.0, infeed.1, feed, p.rule) };
        ensure(infeed_move.is_some_and(|m| shape_of(m, true) == shape_of(&want_infeed, true)), || {
            format!("{}: infeed {infeed_move:?}, want {want_infeed:?} (from {at:?})", here())
        })?;
        let Some(cut) = cut else { return Err(format!("{}: no cut", here())) };
        ensure(cut.kind == MoveKind::Feed && cut.feed == feed && f.p((cut.x, cut.z)) == pk, || format!("{}: cut {cut:?}", here()))?;
        let qk = f.q((cut.x, cut.z));
        ensure(f.c * (qk - f.q(a)) > 0, || format!("{}: the cut is not positive ({cut:?})", here()))?;
        // Within the one rounding of where Q leaves the layer: never into the part, always to it.
        let tk = 2 * f.s * (pk - f.p(a)) * hp;
        ensure(tk < q0.0, || format!("{}: at T {tk}, not before Q₀ {q0:?}", here()))?;
        let wk = 2 * f.c * (qk - f.q(a)) * hq;
        let leave = leaves(q0, &pieces, tk);
        ensure(compare(leave, i128::from(wk - hq), false), || format!("{}: the cut ends at W {wk} (doubled), beyond where Q leaves the layer ({leave:?}) by more than half an increment", here()))?;
        ensure(compare(leave, i128::from(wk + hq), true), || format!("{}: the cut ends at W {wk} (doubled), short of where Q leaves the layer ({leave:?}) by more than half an increment", here()))?;
        // The 45° retract and the rapid back along the cut axis, each left out when it goes
        // nowhere (e = 0; a cut exactly e long).
        let e = b.retract;
        let off = (pk - f.s * e * per_p, qk - f.c * e * per_q);
        let (r, home) = (point(f, off.0, off.1), point(f, off.0, f.q(a)));
        let mut want = Vec::new();
        if r != (cut.x, cut.z) {
            want.push(Move::feed(r.0, r.1, feed, p.rule));
        }
        if home != r {
            want.push(Move::rapid(home.0, home.1, p.rule));
        }
        let got: Vec<_> = ms[2..].iter().map(|m| shape_of(m, true)).collect();
        let want: Vec<_> = want.iter().map(|m| shape_of(m, true)).collect();
        ensure(got == want, || format!("{}: retract and return {got:?}, want {want:?}", here()))?;
        at = home;
    }
    // Complete: a next layer lies beyond Q₀ or would cut at most half an increment.
    let next = 2 * (k_layers as i64 + 1) * step * hp;
    if next < q0.0 {
        ensure(compare(leaves(q0, &pieces, next), i128::from(hq), true), || format!("layer {} would cut more than half an increment", k_layers + 1))?;
    }

    // The semi-finish pass and the return.
    let Some((semi, ms)) = ps.get(k_layers) else { return Err("no SEMI pass".into()) };
    let q0_abs = (b.elements[0].end.0 + b.allowance.0, b.elements[0].end.1 + b.allowance.1);
    let depth = match f.axis {
        Axis::G71 => (a.0 - q0_abs.0).abs(),
        Axis::G72 => 2 * (a.1 - q0_abs.1).abs(),
    };
    ensure(semi.kind == PassKind::Semi && semi.index as usize == k_layers + 1 && semi.diameter_depth == depth, || format!("SEMI header {semi:?}, depth {depth}"))?;
    let mut want = run(&b.elements, b.allowance, feed, at);
    let last = want.last().map_or(at, |m| (m.x, m.z));
    if last != a {
        want.push(Move::rapid(a.0, a.1, semi.rule));
    }
    let got: Vec<_> = ms.iter().map(|m| shape_of(m, true)).collect();
    let want: Vec<_> = want.iter().map(|m| shape_of(m, true)).collect();
    ensure(got == want, || format!("SEMI pass and return:\n got  {got:?}\n want {want:?}"))?;

    // G70: the contour translated by its U, W, from A back to A.
    match (b.finish, ps.get(k_layers + 1)) {
        (None, None) => Ok(()),
        (Some(uw), Some((fin, ms))) => {
            let p0 = (b.elements[0].end.0 + uw.0, b.elements[0].end.1 + uw.1);
            ensure(fin.kind == PassKind::Finish && fin.index == 1 && fin.diameter_depth == (a.0 - p0.0).abs(), || format!("G70 header {fin:?}"))?;
            let mut want = run(&b.elements, uw, 0, a);
            let last = want.last().map_or(a, |m| (m.x, m.z));
            if last != a {
                want.push(Move::rapid(a.0, a.1, fin.rule));
            }
            let got: Vec<_> = ms.iter().map(|m| shape_of(m, false)).collect();
            let want: Vec<_> = want.iter().map(|m| shape_of(m, false)).collect();
            ensure(got == want, || format!("G70:\n got  {got:?}\n want {want:?}"))?;
            ensure(ps.len() == k_layers + 2, || "passes after G70".into())
        }
        (finish, pass) => Err(format!("G70 {finish:?}, pass {pass:?}")),
    }
}

/// Both engines' traces of a legal contour program satisfy every property.
fn holds(knobs: &[u32], axis: Axis) -> Result<(), TestCaseError> {
    let b = contour::legal(axis, &mut Dice::new(knobs));
    let program = &b.case.program;
    let config = b.case.config;
    for (name, t) in [
        ("spec", cycle_spec::expand(program, &config)),
        ("impl", Trace::collect(config.grid, cycle_impl::Expander::new(program, config))),
    ] {
        check(&b, &t).map_err(|e| {
            TestCaseError::fail(format!("{name}: {e}\n\nprogram ({:?}, {:?}):\n{}\n{}", config.grid, config.params, b.case.text(), t.to_gcode()))
        })?;
    }
    Ok(())
}

fn property(axis: Axis) {
    let config = ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() };
    let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &seed()));
    match runner.run(&gen::knobs(), |knobs| holds(&knobs, axis)) {
        Ok(()) => {}
        Err(TestError::Fail(reason, _)) => panic!("{axis:?}: a property fails (case shrunk)\n{reason}"),
        Err(TestError::Abort(reason)) => panic!("{axis:?}: aborted: {reason}"),
    }
}

#[test]
fn g71_layers_semi_finish_and_g70_follow_the_contour() {
    property(Axis::G71);
}

#[test]
fn g72_layers_semi_finish_and_g70_follow_the_contour() {
    property(Axis::G72);
}
