//! G162 — Russian multi-pass thread cycle (M004, 4.2.13), under `--dialect nc201`.
//!
//! From the start point S each pass cuts ① a feed at H to its infeed point, ② the thread at the
//! lead F (variable by I over J, start angle B), ③ the 45° run-out leg V at H, ④ the retract of
//! X to S.x at H, ⑤ the return of Z to S.z at H (G162.PATH). Multi-pass depths are Q, 2Q, …,
//! then the remainder split D/2, D/4, D/8, rest (G162.SPLIT); a flank infeed angle A translates
//! each pass along Z (G162.A). The block's words are read by [`crate::program`]; this module
//! checks the cycle (check step 5) and emits it. Every choice is the one recorded in
//! docs/INTERPRETATION.md, "G162 (M004)".

pub mod unit;

use crate::emit::{LeadLaw, Out};
use crate::exact::{isqrt, round_div};
use crate::multipass::check_max_passes;
use crate::tangent::round_mul_tan_tenths;
use crate::words::{alarm, lead_max};
use cycle_vocab::readings::G162Lead;
use cycle_vocab::{Alarm, AlarmCode, Config, Grid, PassKind, Rule};

/// One G162 block, its words resolved to the grid (X as diameter counts).
#[derive(Clone, Copy, Debug)]
pub struct G162Block {
    /// S: the position before the block (X diameter, Z).
    pub s: (i128, i128),
    /// The X word (G162.X), diameter, absolute: the depth-0 line's start for a multi-pass
    /// thread, the thread's end for a single pass ([`depth_zero_x`]).
    pub x0: i128,
    /// Ze: the end Z including the run-out leg, absolute.
    pub ze: i128,
    /// H: the feed of segments ①, ③–⑤, lead counts.
    pub h: i64,
    /// (P, Q): depth and allowance per pass, radius; `None` = single pass.
    pub depth: Option<(i64, i64)>,
    /// V: the run-out leg, radius (Z extent).
    pub v: i64,
    /// Wd: the taper as a diameter difference over segment ②.
    pub wd: i128,
    /// A in tenths of a degree, signed.
    pub a_tenths: i64,
    /// The lead F (or the modal feed), lead counts.
    pub lead: i64,
    /// B in 0.001°, 0…360 000.
    pub b: i64,
    /// I, lead counts, signed (0: constant).
    pub i: i64,
    /// J in 0.001° (360 000 when omitted).
    pub j: i64,
    pub line: u32,
}

/// G162.FORMAT (M004): the cutting direction dz = sign(Ze − S.z); Ze = S.z leaves no thread:
/// `GEOMETRY` on Z.
pub fn cut_direction(s_z: i128, ze: i128, line: u32) -> Result<i128, Alarm> {
    match (ze - s_z).signum() {
        0 => Err(alarm(AlarmCode::Geometry, b'Z', Rule::G162Format, line)),
        dz => Ok(dz),
    }
}

/// G162.V (M004): the run-out leg must leave a thread: V < |Ze − S.z|, else `GEOMETRY` on V.
pub fn leg_fits(v: i64, s_z: i128, ze: i128, line: u32) -> Result<(), Alarm> {
    if (v as i128) < (ze - s_z).abs() {
        Ok(())
    } else {
        Err(alarm(AlarmCode::Geometry, b'V', Rule::G162V, line))
    }
}

/// G162.RETRACT (M004): the side s = sign(S.x − X0): +1 cuts deeper toward −X (external), −1
/// toward +X. S.x = X0 gives no approach direction: `GEOMETRY` on X.
pub fn side(s_x: i128, x0: i128, line: u32) -> Result<i128, Alarm> {
    match (s_x - x0).signum() {
        0 => Err(alarm(AlarmCode::Geometry, b'X', Rule::G162Retract, line)),
        s => Ok(s),
    }
}

/// G162.RETRACT (M004): the retract ④ goes toward +s, opposite to the approach, so the depth-0
/// path's farthest point — the leg end X0 + Wd + 2s·V — must not lie beyond S.x: else
/// `GEOMETRY` on X.
pub fn retract_side_ok(s_x: i128, x0: i128, wd: i128, v: i64, s: i128, line: u32) -> Result<(), Alarm> {
    let leg_end = x0 + wd + 2 * s * v as i128;
    if s * (s_x - leg_end) >= 0 {
        Ok(())
    } else {
        Err(alarm(AlarmCode::Geometry, b'X', Rule::G162Retract, line))
    }
}

/// G162.X (M004, `004_…` line 34: X is the thread's start X for a multi-pass thread, its "конечной
/// точки" — end — for a single pass): the X where segment ② starts at depth 0. Multi-pass: the X
/// word; single pass (`depth` = `None`): the X word − Wd, so that the pass ends ② at the X word.
/// The side, the checks and the path all use this X as X0.
pub fn depth_zero_x(x_word: i128, wd: i128, depth: Option<(i64, i64)>) -> i128 {
    match depth {
        Some(_) => x_word,
        None => x_word - wd,
    }
}

/// G162.W (M004; OPEN reference): the taper Wd (diameter) is the X change over segment ②,
/// signed, positive away from the axis; W omitted or 0: cylindrical. The thread of a pass at X
/// `start_x` ends at `start_x + Wd`.
pub fn thread_end_x(start_x: i128, wd: i128) -> i128 {
    start_x + wd
}

/// G162.PQ (M004): k = ⌊P / Q⌋ full passes at Q, 2Q, …, kQ, and the remainder D = P − kQ < Q.
pub fn full_passes(p: i64, q: i64) -> (i64, i64) {
    (p / q, p % q)
}

/// G162.SPLIT (M004; OPEN zero remainder, allowance below one increment): after kQ the
/// remainder D is cut at the targets kQ + D/2, kQ + 3D/4, kQ + 7D/8 (each exact value rounded
/// once, half up) and P; a target not above the previous depth is dropped. D = 0: none.
/// The depths returned strictly increase and the last is P = kQ + D.
pub fn split_depths(kq: i64, d: i64) -> Vec<i64> {
    let mut depths = Vec::new();
    if d == 0 {
        return depths;
    }
    let targets = [4, 6, 7].map(|eighths| round_div(8 * kq as i128 + eighths * d as i128, 8) as i64);
    let mut previous = kq;
    for depth in targets.into_iter().chain([kq + d]) {
        if depth > previous {
            depths.push(depth);
            previous = depth;
        }
    }
    depths
}

/// G162.PQ, G162.SPLIT: the number of passes, k plus the split passes kept.
pub fn pass_count(p: i64, q: i64) -> u128 {
    let (k, d) = full_passes(p, q);
    k as u128 + split_depths(k * q, d).len() as u128
}

/// G162.A (M004; OPEN sign and Z shift): t(d) = σ·round(d·tan|A|), σ = s·sign(A), A in tenths
/// of a degree (|A| ≤ 89°, decided exactly by [`crate::tangent`]). Viewed with +Z right and +X
/// up, A turns the radial infeed counter-clockwise: an external thread (s = +1) with A > 0
/// shifts toward +Z. The whole pass is translated by t(d).
pub fn z_shift(depth: i64, a_tenths: i64, s: i128) -> i128 {
    let magnitude = round_mul_tan_tenths(depth, a_tenths.unsigned_abs() as u32).unwrap_or(0);
    s * a_tenths.signum() as i128 * magnitude as i128
}

/// G162.B (M004): the spindle start angle of segment ②, 0.001°; B = 360° is the zero mark.
pub fn start_angle(b: i64) -> u32 {
    (b % 360_000) as u32
}

/// G162.I, G162.J (M004, `004_…` lines 75–77): the lead changes by I per J of spindle rotation —
/// in steps under `g162.lead=steps` (the letter, `stepped`), continuously under `continuous`; a
/// shrinking lead stops once ≤ |I| (floor |I|: stepped, it steps only while above |I|). I = 0,
/// or I < 0 with F ≤ |I| already: constant (never stepped).
pub fn lead_law(lead: i64, i: i64, j: i64, reading: G162Lead) -> LeadLaw {
    if i == 0 || (i < 0 && lead <= -i) {
        return LeadLaw::default();
    }
    let stepped = reading == G162Lead::Steps;
    LeadLaw { change: i, change_angle: j as u32, floor: if i < 0 { -i } else { 0 }, stepped }
}

/// COM.LONGAXIS (M001, M002): twice the long-axis travel of a move in lead counts, from its Z
/// travel and its X travel as a diameter difference: Z long when 2·|ΔZ| > |ΔXd| (ΔZ > ΔX as a
/// radius), else X. Twice, so that an odd diameter difference stays an integer.
pub fn long_travel_twice(dz: i128, dxd: i128, grid: Grid) -> i128 {
    let c = grid.lead_counts_per_increment() as i128;
    let (z2, x2) = (2 * dz.abs(), dxd.abs());
    if z2 > x2 {
        z2 * c
    } else {
        x2 * c
    }
}

/// G162.I (M004): a growing lead must stay within the F range during segment ②, else
/// `GEOMETRY` on I (s2 = twice the long-axis travel, lead counts).
/// * `continuous`: the lead at the end of ②, J·F² + 360 000·I·s2 ≤ J·Fmax² (the lead law of
///   docs/INTERPRETATION.md "Trace").
/// * `steps` (the letter): [`stepped_lead_exceeds`].
pub fn growing_lead_ok(lead: i64, i: i64, j: i64, s2: i128, grid: Grid, reading: G162Lead, line: u32) -> Result<(), Alarm> {
    if i <= 0 {
        return Ok(());
    }
    let (f, fmax, j) = (lead as i128, lead_max(grid) as i128, j as i128);
    let exceeds = match reading {
        G162Lead::Continuous => j * f * f + 360_000 * i as i128 * s2 > j * fmax * fmax,
        G162Lead::Steps => stepped_lead_exceeds(f, i as i128, j, s2, fmax),
    };
    if exceeds {
        return Err(alarm(AlarmCode::Geometry, b'I', Rule::G162I, line));
    }
    Ok(())
}

/// G162.I under `g162.lead=steps` (docs/INTERPRETATION.md "Growing pitch bound"): the lead
/// F + k·I is reached during ② when the travel before its step, (k·F + I·k(k − 1)/2)·J / 360 000
/// lead counts, is less than the long-axis travel s2/2. The first step above Fmax is
/// k* = ⌊(Fmax − F)/I⌋ + 1; it is reached — the bound fails — when
/// (2·k*·F + I·k*·(k* − 1))·J < 360 000·s2. Exact: F, Fmax < 2^27, I ≥ 1, k*·I ≤ Fmax + I, J < 2^30,
/// so every product stays below 2^90.
pub fn stepped_lead_exceeds(f: i128, i: i128, j: i128, s2: i128, fmax: i128) -> bool {
    let k = (fmax - f) / i + 1;
    (2 * k * f + i * k * (k - 1)) * j < 360_000 * s2
}

/// G162.F (M004, the manual's example): the F a programmer writes for a pitch `pitch` measured
/// along a cone of long-axis length `long` and radius difference `short`: F = pitch·long /
/// √(long² + short²), rounded once, half up, to the lead grid. (`pitch` in lead counts, the two
/// lengths in any one unit.) The controller does not apply this; F is always the long-axis pitch.
pub fn long_axis_pitch(pitch: i64, long: i64, short: i64) -> i64 {
    // round(√(num/den)) = the largest q with (2q − 1)²·den ≤ 4·num (√(num/den) ≥ q − ½).
    let (p, l, s) = (pitch as u128, long as u128, short as u128);
    let num = p * p * l * l;
    let den = l * l + s * s;
    let mut q = isqrt(num / den) + 1;
    while q > 0 && (2 * q - 1) * (2 * q - 1) * den > 4 * num {
        q -= 1;
    }
    q as i64
}

/// Checks the cycle in the register's order — Ze ≠ S.z (G162.FORMAT), V (G162.V), side and
/// retract side (G162.RETRACT), the pass bound (PRJ.MAXPASS), the growing lead (G162.I) — and
/// emits every pass (G162.PATH).
pub fn expand(c: &G162Block, config: &Config, out: &mut Out) -> Result<(), Alarm> {
    let line = c.line;
    let (sx, sz) = c.s;
    let x0 = depth_zero_x(c.x0, c.wd, c.depth);
    let dz = cut_direction(sz, c.ze, line)?;
    leg_fits(c.v, sz, c.ze, line)?;
    let s = side(sx, x0, line)?;
    retract_side_ok(sx, x0, c.wd, c.v, s, line)?;
    if let Some((p, q)) = c.depth {
        check_max_passes(pass_count(p, q), 1, &crate::config::params(config), b'Q', line)?;
    }
    // Ze1: where the thread ② ends and the leg ③ begins.
    let ze1 = c.ze - dz * c.v as i128;
    let reading = config.readings.g162_lead;
    growing_lead_ok(c.lead, c.i, c.j, long_travel_twice(ze1 - sz, c.wd, config.grid), config.grid, reading, line)?;

    let pass = Pass { c, x0, s, ze1, law: lead_law(c.lead, c.i, c.j, reading), angle: start_angle(c.b) };
    match c.depth {
        None => pass.emit(1, 0, Rule::G162X, out),
        Some((p, q)) => {
            let (k, d) = full_passes(p, q);
            let full = (1..=k).map(|n| (n * q, Rule::G162Pq));
            let split = split_depths(k * q, d).into_iter().map(|depth| (depth, Rule::G162Split));
            for (n, (depth, rule)) in full.chain(split).enumerate() {
                pass.emit(n as u32 + 1, depth, rule, out)?;
            }
            Ok(())
        }
    }
}

/// What every pass of one cycle shares.
struct Pass<'a> {
    c: &'a G162Block,
    /// X0 as [`depth_zero_x`] gives it.
    x0: i128,
    s: i128,
    ze1: i128,
    law: LeadLaw,
    angle: u32,
}

impl Pass<'_> {
    /// G162.PATH (M004): the header, then ① feed H to Bn = (X0 − 2s·d, S.z + t), ② thread to
    /// (Bn.x + Wd, Ze1 + t), ③ leg at H to (+2s·V, Ze + t), ④ X to S.x at H, ⑤ Z to S.z at H.
    fn emit(&self, index: u32, depth: i64, rule: Rule, out: &mut Out) -> Result<(), Alarm> {
        let c = self.c;
        let (line, s, h) = (c.line, self.s, c.h);
        out.segment(0);
        out.pass(index, PassKind::Rough, 2 * depth as i128, rule, line)?;
        let t = z_shift(depth, c.a_tenths, s);
        let bn = (self.x0 - 2 * s * depth as i128, c.s.1 + t);
        out.segment(1);
        out.feed(bn.0, bn.1, h, Rule::G162Path, line)?;
        let en = (thread_end_x(bn.0, c.wd), self.ze1 + t);
        out.segment(2);
        out.variable_thread(en.0, en.1, c.lead, self.angle, self.law, Rule::G162F, line)?;
        let leg = (en.0 + 2 * s * c.v as i128, c.ze + t);
        out.segment(3);
        out.feed(leg.0, leg.1, h, Rule::G162V, line)?;
        out.segment(4);
        out.feed(c.s.0, leg.1, h, Rule::G162Retract, line)?;
        out.segment(5);
        out.feed(c.s.0, c.s.1, h, Rule::G162Path, line)
    }
}

#[cfg(test)]
mod tests;
