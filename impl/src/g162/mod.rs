//! G162 multi-pass thread cycle of the Russian controller (M004, 4.2.13; `--dialect nc201`):
//! the depth split (G162.PQ, G162.SPLIT) as a pure step function, the cycle's checks (step 5 of
//! the check order) and the per-pass move state machine (G162.PATH), all in integers.
//!
//! Lengths are grid increments, X a diameter count, depths, P, Q and V radius counts; leads and
//! feeds (F, H, I) lead counts; angles (B, J) 0.001°, A tenths of a degree
//! (docs/INTERPRETATION.md, "G162 (M004)").

use crate::fixed::{sat, Tan};
use crate::emit::emit;
use crate::config::Params;
use cycle_vocab::readings::G162Lead;
use cycle_vocab::{Alarm, AlarmCode, Config, Event, Move, Pass, PassKind, Rule, Units};

mod fill;
mod split;

pub use split::{first, next, pass_count, pitch_along_long_axis, Norm, SplitParams, Step};

/// The words of a G162 block, converted and range-checked (step 3), with the missing-word
/// checks done (step 4). Positions are not yet resolved against the start point.
#[derive(Clone, Copy, Debug)]
pub struct Words {
    /// X word as a diameter count (doubled when `x_radius` = 1); a distance under G91.
    pub x: i64,
    /// Z word; a distance under G91.
    pub z: i64,
    /// G91 was in force.
    pub incremental: bool,
    /// H, lead counts per minute.
    pub h: i64,
    /// P and Q, or `None` for a single pass.
    pub split: Option<SplitParams>,
    /// V, radius; 0 when omitted.
    pub v: i64,
    /// W (the taper) as a diameter count; 0 when omitted.
    pub taper: i64,
    /// A in tenths of a degree, signed (|A| ≤ 890); 0 when omitted.
    pub a: i64,
    /// The lead of segment ②, lead counts (F, or the modal feed).
    pub lead: i64,
    /// B, 0.001°, 0…360 000.
    pub b: u32,
    /// I, lead counts, signed; 0 when omitted.
    pub i: i64,
    /// J, 0.001°; 360 000 when omitted.
    pub j: u32,
}

/// The largest lead, lead counts (COM.RANGES of F).
pub const fn max_lead(units: Units) -> i64 {
    match units {
        Units::Metric => 99_990_000,
        Units::Inch => 999_000,
    }
}

fn sign(v: i128) -> i64 {
    sat(v.signum())
}

/// The variable lead of segment ② (G162.I, G162.J): (change, angle, floor), all 0 for a
/// constant lead.
fn variable_lead(w: &Words) -> (i64, u32, i64) {
    // A shrinking lead that is already ≤ |I| = −I never changes (F ≥ 1, so `F ≤ −I` holds only
    // for I < 0); I = 0 is a constant lead. The floor is |I| for I < 0, else 0.
    let minus_i = w.i.saturating_neg();
    if w.i == 0 || w.lead <= minus_i {
        return (0, 0, 0);
    }
    (w.i, w.j, minus_i.max(0))
}

/// A G162 cycle being expanded: fixed geometry, the current pass and the step within it.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    /// S: the start point, where every pass returns.
    start: (i64, i64),
    /// X0: the depth-0 line at the thread start (diameter).
    x0: i64,
    /// Side s (±1): s = +1 cuts deeper toward −X.
    s: i64,
    /// Wd: the X change over segment ② (diameter).
    wd: i64,
    /// Ze: end Z including the leg; Ze1: end Z of segment ②.
    ze: i64,
    ze1: i64,
    /// V, radius.
    v: i64,
    /// H, feed of segments ①, ③–⑤.
    h: i64,
    /// tan of |A| (A in tenths of a degree; looked up once) and σ = s·sign(A).
    tan: Tan,
    sigma: i64,
    /// The split, or `None` for a single pass.
    split: Option<SplitParams>,
    /// The split's P, Q (≥ 1) and k = ⌊P / Q⌋ full passes, as `split::next` reads them: the
    /// full passes are stepped here without a division.
    norm: (u64, u64, u64),
    /// Segment ②'s move but its end point, built once: lead F, start angle B, the variable
    /// lead of G162.I/J, stepped under g162.lead = steps (the letter; a constant lead stays
    /// plain).
    thread: Move,
    pass: Step,
    /// The end points of the current pass's five moves (G162.PATH), computed once per pass.
    points: [(i64, i64); STEPS as usize],
    /// The current pass's header is still to be emitted. (A flag, not the header itself: the
    /// header is built from `pass` when it is written, from values in registers.)
    header: bool,
    step: u8,
}

/// Moves of one pass: ① approach, ② thread, ③ leg, ④ retract X, ⑤ return Z.
const STEPS: u8 = 5;

impl Cycle {
    /// G162.A: t(d) = σ·round(d·tan|A|).
    fn shift(&self, depth: i64) -> i128 {
        if self.sigma == 0 {
            return 0;
        }
        let t = self.tan.times(depth.max(0).unsigned_abs());
        i128::from(self.sigma) * i128::from(t)
    }

    fn pass_header(&self) -> Pass {
        Pass {
            index: self.pass.n,
            kind: PassKind::Rough,
            diameter_depth: self.pass.depth.saturating_mul(2),
            rule: self.pass.rule,
        }
    }

    /// The end points of the current pass's moves (G162.PATH table): ① Bn, ② En, ③ the leg's
    /// end, ④ S.x at the leg's Z, ⑤ S.
    #[inline(always)]
    fn pass_points(&self) -> [(i64, i64); STEPS as usize] {
        let d = i128::from(self.pass.depth);
        let t = self.shift(self.pass.depth);
        let s = i128::from(self.s);
        let bx = i128::from(self.x0) - s * (2 * d);
        let ex = bx + i128::from(self.wd);
        let lz = sat(i128::from(self.ze) + t);
        [
            // ① from S (or the previous pass's return point) to Bn.
            (sat(bx), sat(i128::from(self.start.1) + t)),
            // ② the thread to En.
            (sat(ex), sat(i128::from(self.ze1) + t)),
            // ③ the 45° run-out leg: V outward on X (radius), V toward dz on Z.
            (sat(ex + s * (2 * i128::from(self.v))), lz),
            // ④ retract X to S.x, opposite to the approach.
            (self.start.0, lz),
            // ⑤ return Z to S.
            self.start,
        ]
    }

    /// Makes `pass` the current pass, its header pending.
    #[inline(always)]
    fn begin(&mut self, pass: Step) {
        self.pass = pass;
        self.step = 0;
        self.points = self.pass_points();
        self.header = true;
    }

    /// The move of `step` of the current pass (G162.PATH table).
    #[inline(always)]
    fn move_at(&self, step: u8) -> Option<Move> {
        let &(x, z) = self.points.get(usize::from(step))?;
        Some(match step {
            // ② the thread; stepped under g162.lead = steps (a constant lead stays plain).
            1 => Move { x, z, ..self.thread },
            2 => Move::feed(x, z, self.h, Rule::G162V),
            3 => Move::feed(x, z, self.h, Rule::G162Retract),
            // ① feed H to Bn; ⑤ return Z.
            _ => Move::feed(x, z, self.h, Rule::G162Path),
        })
    }

    /// The pass after the current one (G162.PQ, G162.SPLIT: `split::next`), a full pass
    /// stepped from the cached P, Q and k; `None` after the last.
    #[inline(always)]
    fn next_pass(&self) -> Option<Step> {
        let split = self.split?;
        let (p, q, k) = self.norm;
        let prev = &self.pass;
        if prev.stage == 0 && u64::from(prev.n) < k && prev.depth.max(0).unsigned_abs() < p {
            // As `split::next`: full pass n at depth nQ ≤ kQ ≤ P.
            let n = prev.n.checked_add(1)?;
            let depth = split::full_depth(n, q);
            return Some(Step { n, depth: i64::try_from(depth).unwrap_or(i64::MAX), last: depth >= p, rule: Rule::G162Pq, stage: 0 });
        }
        next(&split, prev)
    }

    /// The current pass. (Public, hidden: the proof harnesses `g162_split_*` in cycle-proofs.)
    #[doc(hidden)]
    pub fn pass(&self) -> Step {
        self.pass
    }

    /// This cycle with `pass` as the current pass and its five moves done (the state in which
    /// `next_event` turns to the next pass). (Public, hidden: the proof harnesses `g162_split_*`
    /// in cycle-proofs.)
    #[doc(hidden)]
    pub fn at_pass(mut self, pass: Step) -> Cycle {
        self.begin(pass);
        self.header = false;
        self.step = STEPS;
        self
    }

    /// The segment (1…5, G162.PATH) of the last move emitted; after a pass header, 0. Read by
    /// the operator layer (G162.NOSTOP).
    pub fn segment(&self) -> u8 {
        self.step
    }

    /// The next event, updating the machine position; `None` when the cycle is done. Bounded
    /// work: at most `STEPS` (5) skipped moves and one pass change per call.
    pub fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        loop {
            if self.header {
                self.header = false;
                return Some(Event::Pass(self.pass_header()));
            }
            if self.step >= STEPS {
                let pass = self.next_pass()?;
                self.begin(pass);
                continue;
            }
            let mv = self.move_at(self.step);
            self.step += 1;
            if let Some(e) = mv.and_then(|m| emit(m, pos)) {
                return Some(e);
            }
        }
    }
}

/// Step 5 of the check order for G162 (docs/INTERPRETATION.md, "Cycle checks"): Ze = S.z
/// (G162.FORMAT), V against the thread length (G162.V), side and retract side (G162.RETRACT),
/// pass bound (PRJ.MAXPASS), growing-pitch bound (G162.I); then the cycle.
pub fn cycle(config: &Config, params: &Params, w: &Words, start: (i64, i64), line: u32) -> Result<Cycle, Alarm> {
    let alarm = |code: AlarmCode, word: u8, rule: Rule| Alarm::new(code, Some(word), rule, line);
    let (sx, sz) = (i128::from(start.0), i128::from(start.1));
    // NC201.ABSINC: G91 values are distances from S.
    let (xw, ze) =
        if w.incremental { (sx + i128::from(w.x), sz + i128::from(w.z)) } else { (i128::from(w.x), i128::from(w.z)) };
    // G162.X: multi-pass, X is the depth-0 line at the thread's start; a single pass ends ② at
    // X, so its depth-0 line (the start of ②) is X − Wd.
    let x0 = if w.split.is_some() { xw } else { xw - i128::from(w.taper) };
    // 1. No thread length.
    if ze == sz {
        return Err(alarm(AlarmCode::Geometry, b'Z', Rule::G162Format));
    }
    // 2. The leg leaves no thread.
    let length = (ze - sz).abs();
    if i128::from(w.v) >= length {
        return Err(alarm(AlarmCode::Geometry, b'V', Rule::G162V));
    }
    // 3. No approach direction.
    let s = sign(sx - x0);
    if s == 0 {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::G162Retract));
    }
    // 4. The depth-0 path (its leg end) must lie on the approach side of S.
    let si = i128::from(s);
    let leg_end = x0 + i128::from(w.taper) + si * (2 * i128::from(w.v));
    if si * (sx - leg_end) < 0 {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::G162Retract));
    }
    // 5. The pass bound.
    let pass = match &w.split {
        Some(sp) => {
            pass_count(sp, params.max_passes).ok_or(alarm(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass))?;
            first(sp)
        }
        None => Step { n: 1, depth: 0, last: true, rule: Rule::G162X, stage: 0 },
    };
    let dz = sign(ze - sz);
    let ze1 = ze - i128::from(dz) * i128::from(w.v);
    // 6. A growing pitch must stay within the F range (G162.I, by the reading g162.lead).
    let stepped = config.readings.g162_lead == G162Lead::Steps;
    if w.i > 0 && !growing_lead_fits(config, w, ze1 - sz, stepped) {
        return Err(alarm(AlarmCode::Geometry, b'I', Rule::G162I));
    }
    let (change, change_angle, floor) = variable_lead(w);
    // B = 360° is the zero mark itself.
    let angle = if w.b >= 360_000 { 0 } else { w.b };
    let mut c = Cycle {
        start,
        x0: sat(x0),
        s,
        wd: w.taper,
        ze: sat(ze),
        ze1: sat(ze1),
        v: w.v,
        h: w.h,
        // |A| beyond 89° (never a legal word): 0, as `mul_tan`.
        tan: u32::try_from(w.a.unsigned_abs()).ok().and_then(Tan::tenths).unwrap_or(Tan::ZERO),
        sigma: s * w.a.signum(),
        split: w.split,
        norm: w.split.map_or((1, 1, 1), |sp| {
            let n = split::norm(&sp);
            (n.p, n.q, n.k)
        }),
        thread: {
            let m = Move::variable_thread(0, 0, w.lead, angle, change, change_angle, floor, Rule::G162F);
            if stepped {
                m.stepped()
            } else {
                m
            }
        },
        pass,
        points: [(0, 0); STEPS as usize],
        header: false,
        step: 0,
    };
    c.begin(pass);
    Ok(c)
}

/// G162.I: the lead at the end of segment ② stays ≤ the F maximum. `dz2` is the Z travel of ②.
/// s2 = twice the long-axis travel in lead counts (COM.LONGAXIS: Z long when 2|ΔZ| > |Wd|).
/// Continuous: J·F² + 360 000·I·s2 ≤ J·Fmax². Stepped (the letter): the first step above Fmax,
/// k* = ⌊(Fmax − F)/I⌋ + 1, is not reached during ②: (2·k*·F + I·k*·(k* − 1))·J ≥ 360 000·s2.
fn growing_lead_fits(config: &Config, w: &Words, dz2: i128, stepped: bool) -> bool {
    let c = i128::from(config.grid.lead_counts_per_increment());
    let (z2, xd) = (2 * dz2.abs(), i128::from(w.taper).abs());
    let s2 = if z2 > xd { z2 * c } else { xd * c };
    let (f, fmax, j) = (i128::from(w.lead), i128::from(max_lead(config.grid.units)), i128::from(w.j));
    if stepped {
        // 1 ≤ I, F ≤ Fmax < 2^27: k* ≤ 2^27 and I·k* ≤ Fmax − F + I < 2^28, so I·k*·(k* − 1)
        // and 2·k*·F are below 2^55; with J < 2^30 the left side stays below 2^86. s2 < 2^66
        // for coordinates within i64: 360 000·s2 < 2^85. Exact in i128 (saturating never acts).
        let i = i128::from(w.i).max(1);
        let k = (fmax - f).max(0) / i + 1;
        let lhs = (2 * k * f).saturating_add(i.saturating_mul(k).saturating_mul(k - 1)).saturating_mul(j);
        return lhs >= 360_000i128.saturating_mul(s2);
    }
    // j ≤ 10^9, f ≤ 10^8: j·f² ≤ 10^25; I ≤ 10^8 and s2 ≤ 2^66: the product stays below 2^127
    // for any coordinates within i64 (saturating beyond, which only makes the check stricter).
    let lhs = j.saturating_mul(f * f).saturating_add(360_000i128.saturating_mul(i128::from(w.i)).saturating_mul(s2));
    lhs <= j.saturating_mul(fmax * fmax)
}

#[cfg(test)]
mod tests;
