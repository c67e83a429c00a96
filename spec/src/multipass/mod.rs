//! G76 — GSK enhanced multi-pass thread cycle (M001), FANUC-style G76 (M003), and G78 — GSK
//! multi-pass thread cycle with five infeed modes (M000).
//!
//! Two blocks: the first (no X, U, Z, W) sets P(m)(r)(a) Q(Δdmin) R(d) D L E and is kept per
//! code; the second describes one thread: X(U) Z(W) R(i) P(k) Q(Δd) J K F(I). The cycle cuts
//! the rough passes of [`schedule`], then m finishing passes at depth k, each from its infeed
//! point Bn ([`infeed`]) with the pull-out of [`crate::pullout`].
//!
//! The manuals' examples run through this module: G76.EXAMPLE (`corpus/g76_example.nc`),
//! F76.EX1 and F76.EX2 (`corpus/f76_ex*.nc`), and G78.EXAMPLE (`corpus/g78_example.nc`), whose
//! printed infeed mode 05 [`check_p_digits`] refuses (G78.MODE).

pub mod infeed;
pub mod schedule;
pub mod unit;

use crate::emit::{start_angle, Out};
use crate::exact::round_div;
use crate::pullout::{self, Amounts, ThreadLine};
use crate::tangent::round_mul_tan_degrees;
use crate::words::{alarm, N};
use crate::config::{params, Params};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Grid, PassKind, Rule};
use infeed::{flank, infeed_x, infeed_z, t};
use schedule::{rough_passes, DepthMode, TooMany};

/// Which multi-pass cycle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Cycle {
    G76,
    G78,
}

impl Cycle {
    fn format_rule(self) -> Rule {
        match self {
            Cycle::G76 => Rule::G76Format,
            Cycle::G78 => Rule::G78Format,
        }
    }
    fn pullout_rule(self) -> Rule {
        match self {
            Cycle::G76 => Rule::G76Pullout,
            Cycle::G78 => Rule::G78Pullout,
        }
    }
}

/// The first block's words as given (G76.FORMAT); `None` = omitted (default applies).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct FirstBlock {
    /// P(m)(r)(a), six digits.
    pub p: Option<i64>,
    /// Q(Δdmin), increments.
    pub q_min: Option<i64>,
    /// R(d), increments.
    pub r_finish: Option<i64>,
    /// D: G76 infeed mode e, G78 depth mode.
    pub d_mode: Option<i64>,
    /// L starts.
    pub l_starts: Option<i64>,
    /// E lead-in, increments.
    pub e_leadin: Option<i64>,
}

/// The second block, resolved against the current position.
#[derive(Clone, Copy, Debug)]
pub struct SecondBlock {
    /// Start point A (current position).
    pub a: (i128, i128),
    /// Thread end D (omitted axis = A).
    pub d: (i128, i128),
    /// R(i), radius.
    pub i: i128,
    /// P(k), thread height, radius.
    pub k: i64,
    /// Q(Δd), first cut, radius.
    pub dd: i64,
    /// J and K pull-out words: G76 as written (not kept), G78 the modal values (written or kept).
    pub j: Option<i64>,
    pub k_pull: Option<i64>,
    /// Lead, lead counts.
    pub lead: i64,
    pub line: u32,
}

/// G76.FORMAT (M001) / G78.MODE (M000) / F76.FORMAT (M003): the digits of P(m)(r)(a) as written in a first block.
/// m = 0 is `OUT OF RANGE` on P (G76.FINISH, OPEN); the G78 mode (middle digits) > 4 is `OUT OF
/// RANGE` on P (G78.MODE); under `fanuc` the tool angle must be 80, 60, 55, 40, 30, 29 or 0
/// (F76.FORMAT).
pub fn check_p_digits(cycle: Cycle, p: i64, dialect: Dialect, line: u32) -> Result<(), Alarm> {
    let (m, mid, a) = p_digits(p);
    if m == 0 {
        return Err(alarm(AlarmCode::OutOfRange, b'P', Rule::G76Finish, line));
    }
    if cycle == Cycle::G78 && mid > 4 {
        return Err(alarm(AlarmCode::OutOfRange, b'P', Rule::G78Mode, line));
    }
    if dialect == Dialect::Fanuc && !fanuc_angle(a) {
        return Err(alarm(AlarmCode::OutOfRange, b'P', Rule::F76Format, line));
    }
    Ok(())
}

/// P(m)(r)(a): all six digits, leading zeros implied: (m, middle, a).
pub fn p_digits(p: i64) -> (u32, u32, u32) {
    let p = p.clamp(0, 999_999) as u32;
    (p / 10_000, (p / 100) % 100, p % 100)
}

/// F76.FORMAT (M003, `003_…` line 5: "牙顶角<80、60、55、40、30、29、0>"): the FANUC tool angles.
pub fn fanuc_angle(a: u32) -> bool {
    matches!(a, 80 | 60 | 55 | 40 | 30 | 29 | 0)
}

/// PRJ.MAXPASS (PRJ): `passes × starts` thread cuts must not exceed `max_passes` (1…1 000 000);
/// otherwise `TOO MANY PASSES` on `word`, before any motion of the cycle.
pub fn check_max_passes(passes: u128, starts: u128, params: &Params, word: u8, line: u32) -> Result<(), Alarm> {
    let max = max_passes(params, line)?;
    if passes.saturating_mul(starts) > max as u128 {
        return Err(alarm(AlarmCode::TooManyPasses, word, Rule::PrjMaxPass, line));
    }
    Ok(())
}

/// The `max_passes` parameter, checked against its range 1…1 000 000.
fn max_passes(params: &Params, line: u32) -> Result<u64, Alarm> {
    param(params.max_passes, 1, 1_000_000, Rule::PrjMaxPass, line).map(|v| v as u64)
}

/// A machine parameter used by a cycle must lie in its documented range (docs/INTERPRETATION.md,
/// Parameters); otherwise `OUT OF RANGE` without a word, under the rule that uses it.
fn param(v: i64, lo: i64, hi: i64, rule: Rule, line: u32) -> Result<i64, Alarm> {
    if (lo..=hi).contains(&v) {
        Ok(v)
    } else {
        Err(Alarm::new(AlarmCode::OutOfRange, None, rule, line))
    }
}

/// The first block with its defaults applied (G76.DEFAULTS, G78.MODE, G78.DEPTHMODE).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Settings {
    /// m finishing passes.
    pub m: u32,
    /// r chamfer width in tenths of the lead, when input (G76 only).
    pub r: Option<u32>,
    /// a tool angle, degrees.
    pub a: u32,
    /// G76 e (0…2) or G78 infeed mode (0…4).
    pub mode: u32,
    pub depth_mode: DepthMode,
    pub dmin: i64,
    pub d: i64,
    pub l: u32,
    pub e: i64,
}

/// G76.DEFAULTS (M001): omitted m → 5142, a → 5143, Δdmin → 5140, d → 5141; r "not input";
/// G76 e omitted → 0; G78 mode → 5144, depth mode → 5145; L → 1; E → 0. Parameters are checked
/// against their ranges when used.
pub fn settings(cycle: Cycle, first: &FirstBlock, config: &Config, line: u32) -> Result<Settings, Alarm> {
    let p = params(config);
    let (m, mid, a, r) = match first.p {
        Some(v) => {
            let (m, mid, a) = p_digits(v);
            (m, mid, a, if cycle == Cycle::G76 { Some(mid) } else { None })
        }
        None => {
            let m = param(p.p5142_finish_passes, 1, 99, Rule::G76Defaults, line)? as u32;
            let a = param(p.p5143_tool_angle, 0, 99, Rule::G76Defaults, line)? as u32;
            let mid = match cycle {
                Cycle::G76 => 0,
                Cycle::G78 => param(p.p5144_infeed_mode, 0, 4, Rule::G78Mode, line)? as u32,
            };
            (m, mid, a, None)
        }
    };
    if config.dialect == Dialect::Fanuc && !fanuc_angle(a) {
        return Err(Alarm::new(AlarmCode::OutOfRange, None, Rule::F76Format, line));
    }
    let (mode, depth_mode) = match cycle {
        Cycle::G76 => (first.d_mode.unwrap_or(0) as u32, DepthMode::Degressive),
        Cycle::G78 => {
            let dm = match first.d_mode {
                Some(v) => v,
                None => param(p.p5145_depth_mode, 0, 1, Rule::G78DepthMode, line)?,
            };
            (mid, if dm == 0 { DepthMode::Constant } else { DepthMode::Degressive })
        }
    };
    let dmin = match first.q_min {
        Some(v) => v,
        None => param(p.p5140_min_cut, 0, N, Rule::G76Defaults, line)?,
    };
    let d = match first.r_finish {
        Some(v) => v,
        None => param(p.p5141_finish_allowance, 0, N, Rule::G76Defaults, line)?,
    };
    Ok(Settings {
        m,
        r,
        a,
        mode,
        depth_mode,
        dmin,
        d,
        l: first.l_starts.unwrap_or(1).clamp(1, 999) as u32,
        e: first.e_leadin.unwrap_or(0),
    })
}

/// G76.PULLOUT (M001) / G78.PULLOUT (M000): the pull-out amounts, `None` for no pull-out.
/// J and K both omitted: K = chamfer width (r × lead / 10 when r was input, else 5130 × lead /
/// 10, converted to the length grid), J = round(K·tan 5131°). J omitted, K given:
/// J = round(K·tan 5131°). J given, K omitted or 0: K = J. A resolved J or K of 0: none.
#[allow(clippy::too_many_arguments)]
pub fn pullout_amounts(
    cycle: Cycle,
    j: Option<i64>,
    k: Option<i64>,
    r: Option<u32>,
    lead: i64,
    grid: Grid,
    params: &Params,
    line: u32,
) -> Result<Option<Amounts>, Alarm> {
    let rule = cycle.pullout_rule();
    let angle = |line| param(params.p5131_chamfer_angle, 1, 89, rule, line).map(|v| v as u32);
    let tan_of = |k: i128, deg: u32| round_mul_tan_degrees(k as i64, deg).unwrap_or(0) as i128;
    let (jv, kv) = match (j, k) {
        (None, None) => {
            let tenths = match r {
                Some(r) => r as i64,
                None => param(params.p5130_chamfer, 0, 99, rule, line)?,
            };
            let width = chamfer_width(tenths, lead, grid);
            (tan_of(width, angle(line)?), width)
        }
        (None, Some(k)) => (tan_of(k as i128, angle(line)?), k as i128),
        (Some(j), None) | (Some(j), Some(0)) => (j as i128, j as i128),
        (Some(j), Some(k)) => (j as i128, k as i128),
    };
    Ok(if jv == 0 || kv == 0 { None } else { Some(Amounts { j: jv, k: kv }) })
}

/// The chamfer width: tenths × lead / 10 lead counts, converted to the length grid, half up.
pub fn chamfer_width(tenths: i64, lead: i64, grid: Grid) -> i128 {
    round_div(tenths as i128 * lead as i128, 10 * grid.lead_counts_per_increment() as i128)
}

/// Checks the second block in the register's order — d < k (G76.DEPTH.LAST), W ≠ 0
/// (G76.FORMAT), side (COM.SIDE), A not between B and C (COM.POINTS), the pass bound
/// (PRJ.MAXPASS), K against the long axis (G76.PULLOUT) — and emits the cycle (G76.PATH, M001):
/// rough passes, then G76.FINISH passes, each at its infeed point Bn.
pub fn expand(cycle: Cycle, first: &FirstBlock, second: &SecondBlock, config: &Config, out: &mut Out) -> Result<(), Alarm> {
    let line = second.line;
    let set = settings(cycle, first, config, line)?;
    let (ax, az) = second.a;
    let (dx, dz) = second.d;
    let k = second.k;
    // G76.DEPTH.LAST (OPEN): d ≥ k leaves no rough pass.
    if set.d >= k {
        return Err(alarm(AlarmCode::OutOfRange, b'R', Rule::G76DepthLast, line));
    }
    // COM.POINTS / G76.FORMAT: W = 0 is a face thread.
    let w = dz - az;
    if w == 0 {
        return Err(alarm(AlarmCode::Geometry, b'Z', cycle.format_rule(), line));
    }
    let i = second.i;
    let cx = dx + 2 * i;
    // COM.SIDE: s = sign(A.x − C.x).
    let s = (ax - cx).signum();
    if s == 0 {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::ComSide, line));
    }
    // COM.POINTS: B.x = C.x + s·k; A must not lie between B and C.
    let bx = cx + 2 * s * k as i128;
    if s * (ax - bx) < 0 {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::ComPoints, line));
    }
    // Depth schedule and PRJ.MAXPASS.
    let p = params(config);
    let limit = max_passes(&p, line)?;
    let rough = match rough_passes(k, set.d, second.dd, set.dmin, set.depth_mode, limit) {
        Ok(r) => r,
        Err(TooMany) => return Err(alarm(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass, line)),
    };
    check_max_passes(rough.len() as u128 + set.m as u128, set.l as u128, &p, b'Q', line)?;
    // Pull-out amounts and K against the long-axis travel.
    let pull = pullout_amounts(cycle, second.j, second.k_pull, set.r, second.lead, config.grid, &p, line)?;
    if let Some(a) = pull {
        if a.k >= pullout::long_travel(w, i) {
            return Err(alarm(AlarmCode::Geometry, b'K', cycle.pullout_rule(), line));
        }
    }

    // Emission.
    let t_last = t(k - set.d, set.a);
    let cut = Cut { a: (ax, az), i, w, s, lead: second.lead, e: set.e, pull, l: set.l, cycle, line };
    let zref = config.readings.thread_zref;
    let mut index: u32 = 0;
    let mut last_z = az;
    for (n, pass) in rough.iter().enumerate() {
        index += 1;
        let fl = flank(cycle, set.mode, n as u64 + 1);
        let bn = (infeed_x(cx, s, k, pass.depth), infeed_z(az, s, t(pass.depth, set.a), t_last, fl, zref));
        last_z = bn.1;
        out.begin_cut(cut.long());
        out.pass(index, PassKind::Rough, 2 * pass.depth as i128, pass.rule, line)?;
        cut.emit(bn, out)?;
    }
    // G76.FINISH: m passes at depth k, the first FINISH, the rest SPRING. G76.FINISH.Z
    // (`000_…` line 126: "精车 Z 轴起切点与最后一刀粗车一致"): at the Z of the last rough pass, under
    // either `thread.zref` (under `groove` that is A.z + σ·t(T) in every mode).
    let bn = (infeed_x(cx, s, k, k), last_z);
    for f in 0..set.m {
        index += 1;
        let kind = if f == 0 { PassKind::Finish } else { PassKind::Spring };
        out.begin_cut(cut.long());
        out.pass(index, kind, 2 * k as i128, Rule::G76Finish, line)?;
        cut.emit(bn, out)?;
    }
    Ok(())
}

/// What every pass of one cycle shares.
struct Cut {
    a: (i128, i128),
    i: i128,
    w: i128,
    s: i128,
    lead: i64,
    e: i64,
    pull: Option<Amounts>,
    l: u32,
    cycle: Cycle,
    line: u32,
}

impl Cut {
    /// COM.LONGAXIS of the cut, for G76.HOLD's retract.
    fn long(&self) -> pullout::LongAxis {
        pullout::long_axis(self.w, self.i)
    }

    /// G76.PATH (M001), per start (G76.MULTISTART): [lead-in] rapid A → Bn; thread Bn → En =
    /// Bn + (−i on X, W on Z) with the pull-out; rapid X to A.x; rapid Z to A.z.
    fn emit(&self, bn: (i128, i128), out: &mut Out) -> Result<(), Alarm> {
        let line = self.line;
        let en = (bn.0 - 2 * self.i, bn.1 + self.w);
        let thread = ThreadLine { end_x: en.0, end_z: en.1, r: self.i, w: self.w, s: self.s };
        let segment = match self.pull {
            Some(a) => pullout::segment(&thread, a).ok(),
            None => None,
        };
        for j in 0..self.l {
            if j > 0 {
                // G76.HOLD: each start is a cut; the pass's first one began at its header.
                out.begin_cut(self.long());
            }
            let angle = start_angle(j, self.l);
            if self.e > 0 {
                // G76.LEADIN: rapid to E beyond Bn on X, then a synchronized X move into Bn.
                out.rapid(bn.0 + 2 * self.s * self.e as i128, bn.1, Rule::G76LeadIn, line)?;
                out.thread(bn.0, bn.1, self.lead, angle, Rule::G76LeadIn, line)?;
            } else {
                out.rapid(bn.0, bn.1, Rule::G76InfeedX, line)?;
            }
            match segment {
                Some((start, end)) => {
                    out.thread(start.0, start.1, self.lead, angle, Rule::G76Path, line)?;
                    out.pullout(end.0, end.1, self.lead, angle, self.cycle.pullout_rule(), line)?;
                }
                None => out.thread(en.0, en.1, self.lead, angle, Rule::G76Path, line)?,
            }
            let z_now = out.z as i128;
            out.rapid(self.a.0, z_now, Rule::G76Path, line)?;
            out.rapid(self.a.0, self.a.1, Rule::G76Path, line)?;
        }
        Ok(())
    }
}
