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
use crate::tangent::round_mul_tan_half_degrees;
use crate::words::{alarm, lead_max};
use cycle_vocab::{Alarm, AlarmCode, Config, Grid, PassKind, Rule};

/// One G162 block, its words resolved to the grid (X as diameter counts).
#[derive(Clone, Copy, Debug)]
pub struct G162Block {
    /// S: the position before the block (X diameter, Z).
    pub s: (i128, i128),
    /// X0: the thread X (G162.X), diameter, absolute.
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
    /// A in half degrees, signed.
    pub a_half: i64,
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

/// G162.A (M004; OPEN sign and Z shift): t(d) = σ·round(d·tan|A|), σ = s·sign(A). Viewed with
/// +Z right and +X up, A turns the radial infeed counter-clockwise: an external thread (s = +1)
/// with A > 0 shifts toward +Z. The whole pass is translated by t(d).
pub fn z_shift(depth: i64, a_half: i64, s: i128) -> i128 {
    let magnitude = round_mul_tan_half_degrees(depth, a_half.unsigned_abs() as u32).unwrap_or(0);
    s * a_half.signum() as i128 * magnitude as i128
}

/// G162.B (M004): the spindle start angle of segment ②, 0.001°; B = 360° is the zero mark.
pub fn start_angle(b: i64) -> u32 {
    (b % 360_000) as u32
}

/// G162.I, G162.J (M004; OPEN continuous): the lead changes by I per J of spindle rotation; a
/// shrinking lead stops once ≤ |I| (floor |I|). I = 0, or I < 0 with F ≤ |I| already: constant.
pub fn lead_law(lead: i64, i: i64, j: i64) -> LeadLaw {
    if i == 0 || (i < 0 && lead <= -i) {
        return LeadLaw::default();
    }
    LeadLaw { change: i, change_angle: j as u32, floor: if i < 0 { -i } else { 0 } }
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

/// G162.I (M004): a growing lead must stay within the F range at the end of segment ②:
/// J·F² + 360 000·I·s2 ≤ J·Fmax² (s2 = twice the long-axis travel, lead counts; the lead law of
/// docs/INTERPRETATION.md "Trace"), else `GEOMETRY` on I.
pub fn growing_lead_ok(lead: i64, i: i64, j: i64, s2: i128, grid: Grid, line: u32) -> Result<(), Alarm> {
    if i <= 0 {
        return Ok(());
    }
    let (f, fmax, j) = (lead as i128, lead_max(grid) as i128, j as i128);
    if j * f * f + 360_000 * i as i128 * s2 > j * fmax * fmax {
        return Err(alarm(AlarmCode::Geometry, b'I', Rule::G162I, line));
    }
    Ok(())
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
    let dz = cut_direction(sz, c.ze, line)?;
    leg_fits(c.v, sz, c.ze, line)?;
    let s = side(sx, c.x0, line)?;
    retract_side_ok(sx, c.x0, c.wd, c.v, s, line)?;
    if let Some((p, q)) = c.depth {
        check_max_passes(pass_count(p, q), 1, &crate::config::params(config), b'Q', line)?;
    }
    // Ze1: where the thread ② ends and the leg ③ begins.
    let ze1 = c.ze - dz * c.v as i128;
    growing_lead_ok(c.lead, c.i, c.j, long_travel_twice(ze1 - sz, c.wd, config.grid), config.grid, line)?;

    let pass = Pass { c, s, ze1, law: lead_law(c.lead, c.i, c.j), angle: start_angle(c.b) };
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
        let t = z_shift(depth, c.a_half, s);
        let bn = (c.x0 - 2 * s * depth as i128, c.s.1 + t);
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
mod tests {
    use super::*;

    /// G162.SPLIT, the example: P2.5 Q1. On the ISC grid (0.0001 mm) the manual's
    /// sequence exactly; on ISB (0.001 mm) 2.4375 rounds half up to 2.438.
    #[test]
    fn p2_5_q1_depths() {
        let isc: Vec<i64> = {
            let (k, d) = full_passes(25_000, 10_000);
            (1..=k).map(|n| n * 10_000).chain(split_depths(k * 10_000, d)).collect()
        };
        assert_eq!(isc, vec![10_000, 20_000, 22_500, 23_750, 24_375, 25_000]);
        let (k, d) = full_passes(2_500, 1_000);
        assert_eq!((k, d), (2, 500));
        assert_eq!(split_depths(2_000, 500), vec![2_250, 2_375, 2_438, 2_500]);
        assert_eq!(pass_count(2_500, 1_000), 6);
    }

    /// G162.SPLIT OPEN points: a zero remainder adds nothing; allowances below one increment
    /// merge into the next cut; Q > P splits P itself.
    #[test]
    fn split_edge_cases() {
        assert_eq!(split_depths(3_000, 0), Vec::<i64>::new());
        assert_eq!(pass_count(3_000, 1_000), 3);
        assert_eq!(split_depths(2, 1), vec![3]); // targets 2.5→3, 2.75→3, 2.875→3, 3
        assert_eq!(split_depths(0, 2), vec![1, 2]); // 1, 1.5→2, 1.75→2, 2
        assert_eq!(split_depths(0, 3), vec![2, 3]); // 1.5→2, 2.25→2, 2.625→3, 3
        assert_eq!(split_depths(0, 500), vec![250, 375, 438, 500]); // P0.5 Q1
        for kq in [0, 7, 1_000] {
            for d in 1..200 {
                let v = split_depths(kq, d);
                assert_eq!(*v.last().unwrap(), kq + d, "ends at P");
                assert!(v.windows(2).all(|w| w[0] < w[1]) && v[0] > kq, "strictly increasing");
                assert!(v.len() <= 4);
            }
        }
    }

    /// G162.F (M004): 2 mm along a cone 50 mm long with a 20 mm diameter difference:
    /// 2·50/√(50² + 10²) = 1.961161…: 1.9612 on the lead grid, the manual's 1.96 to two decimals.
    #[test]
    fn manual_pitch_example() {
        let f = long_axis_pitch(20_000, 50_000, 10_000);
        assert_eq!(f, 19_612);
        assert_eq!(round_div(f as i128, 100), 196);
        // The same in any unit of length; a straight thread keeps its pitch.
        assert_eq!(long_axis_pitch(20_000, 50, 10), 19_612);
        assert_eq!(long_axis_pitch(15_000, 40_000, 0), 15_000);
        // 3-4-5: 5·4/5 = 4 exactly; 7·4/5 = 5.6 → 6; 6·4/5 = 4.8 → 5; 3·4/5 = 2.4 → 2.
        assert_eq!(long_axis_pitch(5, 4, 3), 4);
        assert_eq!(long_axis_pitch(7, 4, 3), 6);
        assert_eq!(long_axis_pitch(6, 4, 3), 5);
        assert_eq!(long_axis_pitch(3, 4, 3), 2);
    }

    /// G162.A (M004): the sign rule and the rounding, t(0.5 mm) at 30° = round(288.675) = 289.
    #[test]
    fn infeed_angle_sign_and_rounding() {
        assert_eq!(z_shift(500, 60, 1), 289);
        assert_eq!(z_shift(500, 60, -1), -289);
        assert_eq!(z_shift(500, -60, 1), -289);
        assert_eq!(z_shift(500, -60, -1), 289);
        assert_eq!(z_shift(1_000, 60, 1), 577);
        assert_eq!(z_shift(1_000, 0, 1), 0);
        assert_eq!(z_shift(1_000, 90, 1), 1_000); // 45°
        assert_eq!(z_shift(0, 60, 1), 0);
    }

    /// G162.I, G162.J: the lead law and where the shrinking stops.
    #[test]
    fn variable_pitch_law() {
        assert_eq!(lead_law(15_000, 0, 360_000), LeadLaw::default());
        assert_eq!(lead_law(15_000, 5_000, 180_000), LeadLaw { change: 5_000, change_angle: 180_000, floor: 0 });
        assert_eq!(lead_law(15_000, -5_000, 180_000), LeadLaw { change: -5_000, change_angle: 180_000, floor: 5_000 });
        // Already at or below |I|: the change has stopped before it starts.
        assert_eq!(lead_law(5_000, -5_000, 360_000), LeadLaw::default());
        assert_eq!(lead_law(4_000, -5_000, 360_000), LeadLaw::default());
        assert_eq!(start_angle(360_000), 0);
        assert_eq!(start_angle(90_000), 90_000);
    }

    /// G162.I: a growing lead may reach the F maximum at the end of ② and not beyond
    /// (L² = F² + I·s2 per revolution: F = 9000 mm, I = 1 mm/rev).
    #[test]
    fn growing_lead_bound() {
        let g = Grid::METRIC_ISB;
        let fmax = lead_max(g) as i128;
        // s2 chosen so that F² + I·s2 = Fmax² exactly (J = 360 000, per revolution).
        let f = 90_000_000i128;
        let i = 10_000i128;
        let s2 = (fmax * fmax - f * f) / i;
        assert_eq!((fmax * fmax - f * f) % i, 0);
        assert!(growing_lead_ok(f as i64, i as i64, 360_000, s2, g, 1).is_ok());
        assert_eq!(
            growing_lead_ok(f as i64, i as i64, 360_000, s2 + 1, g, 1),
            Err(alarm(AlarmCode::Geometry, b'I', Rule::G162I, 1))
        );
        assert!(growing_lead_ok(f as i64, -i as i64, 360_000, s2 * 1_000, g, 1).is_ok());
    }

    #[test]
    fn long_axis() {
        let g = Grid::METRIC_ISB;
        assert_eq!(long_travel_twice(-20_000, 0, g), 400_000);
        assert_eq!(long_travel_twice(1_000, 3_000, g), 30_000); // X long: 1.5 radius > 1
        assert_eq!(long_travel_twice(1_000, 2_000, g), 20_000); // equal: X (COM.LONGAXIS)
    }
}
