//! G162 multi-pass thread cycle of the Russian controller (M004, 4.2.13; `--dialect nc201`):
//! the depth split (G162.PQ, G162.SPLIT) as a pure step function, the cycle's checks (step 5 of
//! the check order) and the per-pass move state machine (G162.PATH), all in integers.
//!
//! Lengths are grid increments, X a diameter count, depths, P, Q and V radius counts; leads and
//! feeds (F, H, I) lead counts; angles (B, J) 0.001°, A tenths of a degree
//! (docs/INTERPRETATION.md, "G162 (M004)").

use crate::fixed::{sat, Tan};
use crate::batch::{self, Batch};
use crate::emit::emit;
use crate::config::Params;
use cycle_vocab::readings::G162Lead;
use cycle_vocab::{Alarm, AlarmCode, Config, Event, Move, Pass, PassKind, Rule, Units};

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
    // A shrinking lead that is already ≤ |I| never changes; I = 0 is a constant lead.
    if w.i == 0 || (w.i < 0 && w.lead <= w.i.saturating_abs()) {
        return (0, 0, 0);
    }
    let floor = if w.i < 0 { w.i.saturating_abs() } else { 0 };
    (w.i, w.j, floor)
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
    lead: i64,
    angle: u32,
    change: i64,
    change_angle: u32,
    floor: i64,
    /// G162.I under g162.lead = steps (the letter): the lead changes in steps (`lead_steps`).
    stepped: bool,
    /// tan of |A| (A in tenths of a degree; looked up once) and σ = s·sign(A).
    tan: Tan,
    sigma: i64,
    /// The split, or `None` for a single pass.
    split: Option<SplitParams>,
    pass: Step,
    /// The end points of the current pass's five moves (G162.PATH), computed once per pass.
    points: [(i64, i64); STEPS as usize],
    header: Option<Pass>,
    step: u8,
}

/// Moves of one pass: ① approach, ② thread, ③ leg, ④ retract X, ⑤ return Z.
const STEPS: u8 = 5;

impl Cycle {
    /// G162.A: t(d) = σ·round(d·tan|A|).
    fn shift(&self, depth: i64) -> i128 {
        let t = self.tan.times(depth.max(0).unsigned_abs());
        i128::from(self.sigma) * i128::from(t)
    }

    fn header(&self) -> Pass {
        Pass {
            index: self.pass.n,
            kind: PassKind::Rough,
            diameter_depth: self.pass.depth.saturating_mul(2),
            rule: self.pass.rule,
        }
    }

    /// The end points of the current pass's moves (G162.PATH table): ① Bn, ② En, ③ the leg's
    /// end, ④ S.x at the leg's Z, ⑤ S.
    fn pass_points(&self) -> [(i64, i64); STEPS as usize] {
        let d = i128::from(self.pass.depth);
        let t = self.shift(self.pass.depth);
        let s = i128::from(self.s);
        let bx = i128::from(self.x0) - 2 * s * d;
        let ex = bx + i128::from(self.wd);
        let lz = sat(i128::from(self.ze) + t);
        [
            // ① from S (or the previous pass's return point) to Bn.
            (sat(bx), sat(i128::from(self.start.1) + t)),
            // ② the thread to En.
            (sat(ex), sat(i128::from(self.ze1) + t)),
            // ③ the 45° run-out leg: V outward on X (radius), V toward dz on Z.
            (sat(ex + 2 * s * i128::from(self.v)), lz),
            // ④ retract X to S.x, opposite to the approach.
            (self.start.0, lz),
            // ⑤ return Z to S.
            self.start,
        ]
    }

    /// Makes `pass` the current pass, its header pending.
    fn begin(&mut self, pass: Step) {
        self.pass = pass;
        self.step = 0;
        self.points = self.pass_points();
        self.header = Some(self.header());
    }

    /// The move of `step` of the current pass (G162.PATH table).
    #[inline(always)]
    fn move_at(&self, step: u8) -> Option<Move> {
        let &(x, z) = self.points.get(usize::from(step))?;
        Some(match step {
            // ② the thread; stepped under g162.lead = steps (a constant lead stays plain).
            1 => {
                let m = Move::variable_thread(x, z, self.lead, self.angle, self.change, self.change_angle, self.floor, Rule::G162F);
                if self.stepped {
                    m.stepped()
                } else {
                    m
                }
            }
            2 => Move::feed(x, z, self.h, Rule::G162V),
            3 => Move::feed(x, z, self.h, Rule::G162Retract),
            // ① feed H to Bn; ⑤ return Z.
            _ => Move::feed(x, z, self.h, Rule::G162Path),
        })
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
            if let Some(h) = self.header.take() {
                return Some(Event::Pass(h));
            }
            if self.step >= STEPS {
                let split = self.split?;
                let pass = next(&split, &self.pass)?;
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
    let leg_end = x0 + i128::from(w.taper) + 2 * si * i128::from(w.v);
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
    let mut c = Cycle {
        start,
        x0: sat(x0),
        s,
        wd: w.taper,
        ze: sat(ze),
        ze1: sat(ze1),
        v: w.v,
        h: w.h,
        lead: w.lead,
        // B = 360° is the zero mark itself.
        angle: if w.b >= 360_000 { 0 } else { w.b },
        change,
        change_angle,
        floor,
        stepped,
        // |A| beyond 89° (never a legal word): 0, as `mul_tan`.
        tan: u32::try_from(w.a.unsigned_abs()).ok().and_then(Tan::tenths).unwrap_or(Tan::ZERO),
        sigma: s * w.a.signum(),
        split: w.split,
        pass,
        points: [(0, 0); STEPS as usize],
        header: None,
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

/// The most events of one pass: its header and five moves.
const PASS_EVENTS: usize = 1 + STEPS as usize;

impl Batch<PASS_EVENTS> for Cycle {
    fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        Cycle::next_event(self, pos)
    }

    fn begun(&self) -> bool {
        self.header.is_none() && self.step < STEPS
    }

    fn ready(&mut self) -> bool {
        if self.step < STEPS {
            return true;
        }
        match self.split.and_then(|sp| next(&sp, &self.pass)) {
            Some(pass) => {
                self.begin(pass);
                true
            }
            None => false,
        }
    }

    /// The pass's header and moves, unrolled, each event built in place.
    #[inline(always)]
    fn write_unit(&mut self, pos: &mut (i64, i64), slots: &mut [Event; PASS_EVENTS]) -> usize {
        let mut n = 0;
        let mut put = |e: Event| {
            if let Some(slot) = slots.get_mut(n) {
                *slot = e;
                n += 1;
            }
        };
        if let Some(h) = self.header.take() {
            put(Event::Pass(h));
        }
        for step in 0..STEPS {
            if let Some(e) = self.move_at(step).and_then(|m| emit(m, pos)) {
                put(e);
            }
        }
        self.step = STEPS;
        n
    }
}

impl Cycle {
    /// Writes the cycle's next events into `out`, the same events as [`Cycle::next_event`],
    /// whole passes at a time ([`batch::fill`]); how many, and whether the cycle is done.
    pub fn fill(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
        batch::fill(self, pos, out)
    }
}

#[cfg(test)]
mod tests;
