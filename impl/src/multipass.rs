//! G76 / G78 / FANUC G76 multi-pass cycles (M001, M000, M003): first-block values, the
//! second block's checks (step 5 of the check order) and the pass plan.

use crate::emit::{Cycle, Path, Plan};
use crate::passes::{Flank, FlankZ, Multi};
use crate::fixed::{sat, Tan};
use crate::pullout::{multi_amounts, offsets, tenths_of_lead, travel};
use crate::schedule::{Schedule, ScheduleParams};
use crate::config::Params;
use cycle_vocab::{Alarm, AlarmCode, Config, Rule};

/// Which multi-pass code.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Code {
    G76,
    G78,
}

/// The values of a first block, kept for later cycles of the same code (G76.FORMAT).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FirstBlock {
    /// m: finishing passes, 1…99.
    pub m: u32,
    /// r: chamfer width in tenths of the lead, when input (G76 only).
    pub r: Option<u32>,
    /// a: tool angle, degrees.
    pub a: u32,
    /// G76 D(e) 0…2, or the G78 infeed mode 0…4.
    pub mode: u32,
    /// G78 depth mode: false = constant (D0).
    pub degressive: bool,
    /// Δdmin, increments.
    pub dmin: i64,
    /// d, increments.
    pub d: i64,
    /// L, starts.
    pub starts: u32,
    /// E, lead-in distance (radius), 0 = none.
    pub e: i64,
}

impl FirstBlock {
    /// G76.DEFAULTS / G78.MODE / G78.DEPTHMODE: every value from its default.
    pub fn defaults(p: &Params, code: Code) -> FirstBlock {
        FirstBlock {
            m: p.p5142_finish_passes,
            r: None,
            a: p.p5143_tool_angle,
            mode: match code {
                Code::G76 => 0,
                Code::G78 => p.p5144_infeed_mode,
            },
            degressive: match code {
                Code::G76 => true,
                Code::G78 => p.p5145_depth_mode != 0,
            },
            dmin: p.p5140_min_cut,
            d: p.p5141_finish_allowance,
            starts: 1,
            e: 0,
        }
    }
}

/// The words of a second block, converted and range-checked.
#[derive(Clone, Copy, Debug)]
pub struct Second {
    /// D: thread end point (X diameter, Z).
    pub d: (i64, i64),
    /// R(i), radius.
    pub i: i64,
    /// P(k), radius.
    pub k: i64,
    /// Q(Δd), radius.
    pub dd: i64,
    pub j: Option<i64>,
    pub kk: Option<i64>,
    pub lead: i64,
}

/// G76.MODE / G78.MODE: the flanks of the rough passes, (even n, odd n).
fn flanks(code: Code, mode: u32) -> (Flank, Flank) {
    match (code, mode) {
        (Code::G76, 1) | (Code::G78, 3) => (Flank::Centre, Flank::Right),
        (Code::G76, 2) | (Code::G78, 4) => (Flank::Right, Flank::Left),
        (Code::G78, 0) => (Flank::Centre, Flank::Centre),
        (Code::G78, 1) => (Flank::Left, Flank::Left),
        _ => (Flank::Right, Flank::Right), // G76 e = 0, G78 mode 2
    }
}

/// Step 5 of the check order for a second block (docs/INTERPRETATION.md, "G76/G78 cycle check
/// order"): d ≥ k (G76.DEPTH.LAST), W = 0 (G76.FORMAT), side (COM.SIDE), A between B and C
/// (COM.POINTS), pass bound (PRJ.MAXPASS), K against the long-axis travel (G76.PULLOUT /
/// G78.PULLOUT); then the cycle (G76.PATH).
pub fn cycle(
    config: &Config,
    params: &Params,
    code: Code,
    first: &FirstBlock,
    a: (i64, i64),
    sec: &Second,
    line: u32,
) -> Result<Cycle, Alarm> {
    let alarm = |code: AlarmCode, word: u8, rule: Rule| Alarm::new(code, Some(word), rule, line);
    // d ≥ k (OPEN): no rough pass could exist.
    if first.d >= sec.k {
        return Err(alarm(AlarmCode::OutOfRange, b'R', Rule::G76DepthLast));
    }
    let w = sat(i128::from(sec.d.1) - i128::from(a.1));
    if w == 0 {
        // G76.FORMAT / G78.FORMAT: each code's own format rule names the missing Z travel.
        let rule = match code {
            Code::G76 => Rule::G76Format,
            Code::G78 => Rule::G78Format,
        };
        return Err(alarm(AlarmCode::Geometry, b'Z', rule));
    }
    // C.x = D.x + i (radius); s = sign(A.x − C.x).
    let cx = i128::from(sec.d.0) + 2 * i128::from(sec.i);
    let s = (i128::from(a.0) - cx).signum();
    if s == 0 {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::ComSide));
    }
    // B.x = C.x + s·k; A must not lie between B and C.
    let bx = cx + s * (2 * i128::from(sec.k));
    if s * (i128::from(a.0) - bx) < 0 {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::ComPoints));
    }
    let target = sec.k - first.d; // 1 ≤ T ≤ N
    let sched =
        Schedule::new(&ScheduleParams { first_cut: sec.dd, min_cut: first.dmin, target, constant: !first.degressive });
    let max = params.max_passes;
    let too_many = alarm(AlarmCode::TooManyPasses, b'Q', Rule::PrjMaxPass);
    let rough = sched.rough_pass_count(max).ok_or(too_many)?;
    let total = (u64::from(rough) + u64::from(first.m)).saturating_mul(u64::from(first.starts));
    if total > u64::from(max) {
        return Err(too_many);
    }
    let p = params;
    let chamfer = tenths_of_lead(first.r.unwrap_or(p.p5130_chamfer), sec.lead, config.grid);
    let amounts = multi_amounts(sec.j, sec.kk, chamfer, p.p5131_chamfer_angle);
    let rule_pull = match code {
        Code::G76 => Rule::G76Pullout,
        Code::G78 => Rule::G78Pullout,
    };
    if let Some(am) = amounts {
        if am.k.unsigned_abs() >= travel(w, sec.i) {
            return Err(alarm(AlarmCode::Geometry, b'K', rule_pull));
        }
    }
    let s = sat(s);
    // Beyond 89° (never a legal word): 0, as `mul_tan`.
    let tan = Tan::half_degrees(first.a).unwrap_or(Tan::ZERO);
    let t_target = i64::try_from(tan.times(target.max(0).unsigned_abs())).unwrap_or(i64::MAX);
    let zref = config.readings.thread_zref;
    let (even, odd) = flanks(code, first.mode);
    // The last rough pass (n = `rough`, at depth T) sets the finishing passes' Z.
    let last = FlankZ::of(if rough % 2 == 1 { odd } else { even }, zref, t_target);
    let mut multi = Multi {
        flanks: (FlankZ::of(even, zref, t_target), FlankZ::of(odd, zref, t_target)),
        sched,
        rough: None,
        finish: 0,
        m: first.m,
        index: 0,
        bx: sat(bx),
        az: a.1,
        sigma: -s,
        k: sec.k,
        taper: sat(-2 * i128::from(sec.i)),
        w,
        tan,
        finish_off: 0,
    };
    multi.finish_off = multi.offset(last, target);
    let cut = multi.begin();
    let path = Path {
        a,
        lead: sec.lead,
        starts: first.starts.max(1),
        leadin: sat(i128::from(s) * (2 * i128::from(first.e))),
        pull: amounts.map(|am| offsets(am, w, sec.i, s)),
        rule_path: Rule::G76Path,
        rule_pull,
    };
    Ok(Cycle::new(path, Plan::Multi(multi), cut))
}
