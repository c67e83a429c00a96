//! G92 — single thread cycle (M002, GSK980TDi 3.24.9).
//!
//! One cycle from the start point A: ① rapid X to the thread start C, ② thread C → D (with the
//! pull-out), ③ rapid X back to A.x, ④ rapid Z back to A.z (G92.PATH). The modal run
//! (G92.MODAL) is handled by [`crate::program`]; this module expands one cycle. The manual's
//! example (G92.EXAMPLE, `corpus/g92_example.nc`: one run of four cycles) is expanded here.

use crate::config::Params;
use crate::emit::{start_angle, Out};
use crate::exact::round_div;
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::pullout::{self, Amounts, ThreadLine};
use crate::tangent::round_mul_tan_degrees;
use crate::words::{alarm, Read, F, I_TPI, JK_MAX, N, U, W, X, Z};
use cycle_vocab::{Alarm, AlarmCode, Dialect, Grid, PassKind, Rule};

/// G92 as a family of the interpreter: G92.FORMAT words, G92.MODAL memory.
#[derive(Debug, Default)]
pub struct G92 {
    /// J, K, L: modal for the whole program (G92.MODAL).
    j: Option<i64>,
    k: Option<i64>,
    l: Option<i64>,
    run: Run,
}

/// A G92 modal run (G92.MODAL): kept end X, end Z (absolute), R, and the pass index.
#[derive(Clone, Copy, Debug, Default)]
struct Run {
    end_x: Option<i128>,
    end_z: Option<i128>,
    r: i128,
    index: u32,
}

/// G92.FORMAT (M002): `G92 X(U) Z(W) [R] F|I [J] [K] [L]`; R signed, J and K |v| ≤ 99 999 999
/// (COM.RANGES), L 1…99.
const WORDS: Words = Words::of(&[
    F,
    I_TPI,
    (b'J', Read::Length { lo: -JK_MAX, hi: JK_MAX }),
    (b'K', Read::Length { lo: -JK_MAX, hi: JK_MAX }),
    (b'L', Read::Integer { lo: 1, hi: 99, rule: Rule::ComRanges }),
    (b'R', Read::Length { lo: -N, hi: N }),
    U,
    W,
    X,
    Z,
]);

impl Family for G92 {
    fn modal(&self) -> bool {
        true
    }
    fn thread(&self) -> bool {
        true
    }
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }

    /// G92.MODAL (M002): a block with axis words (and G92, or no motion code in G92 mode) cuts
    /// one cycle; end X, end Z and R are kept within the run, F/I, J, K, L for the whole
    /// program. A new run starts with R = 0 and the end point at the current position. A block
    /// without axis words does not cut.
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        let (v, line) = (b.values, b.line);
        if b.new_run {
            self.run = Run::default();
        }
        st.take_lead(v);
        self.j = v.get(b'J').or(self.j);
        self.k = v.get(b'K').or(self.k);
        self.l = v.get(b'L').or(self.l);
        if let Some(r) = v.get(b'R') {
            self.run.r = r as i128;
        }
        if !b.kind.axes {
            return Ok(());
        }
        // G92.FORMAT / COM.LEAD: the lead is required.
        let Some(lead) = st.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        st.missing_words_checked()?;
        let a = st.position();
        let (x, z) = st.end_point(v);
        let dx = x.or(self.run.end_x).unwrap_or(a.0);
        let dz = z.or(self.run.end_z).unwrap_or(a.1);
        self.run.end_x = Some(dx);
        self.run.end_z = Some(dz);
        self.run.index = self.run.index.saturating_add(1);
        let l = self.l.unwrap_or(1) as u32;
        let cycle = G92Cycle { a, d: (dx, dz), r: self.run.r, lead, j: self.j, k: self.k, l, index: self.run.index, line };
        expand(&cycle, &st.params(), st.config.grid, &mut st.out)
    }
}

/// One G92 cycle, all words resolved (absolute end point, modal values filled in).
#[derive(Clone, Copy, Debug)]
pub struct G92Cycle {
    /// Start point A = the current position (X diameter, Z).
    pub a: (i128, i128),
    /// Thread end D (X diameter, Z).
    pub d: (i128, i128),
    /// R: thread start X − thread end X, radius increments (COM.AXES: X is a diameter, so R
    /// enters X doubled).
    pub r: i128,
    /// The lead, lead counts.
    pub lead: i64,
    /// J and K as written (modal), absolute values (G92.JK.7).
    pub j: Option<i64>,
    pub k: Option<i64>,
    /// L starts.
    pub l: u32,
    /// Pass index within the run.
    pub index: u32,
    pub line: u32,
}

/// G92.TAPER (M002): C.x = D.x + R (radius), U = D.x − A.x (diameter). When R ≠ 0, U ≠ 0 and
/// they differ in sign, 2·|R| ≤ |U| is required, else `GEOMETRY` on R.
pub fn taper_ok(r: i128, u: i128) -> bool {
    if r != 0 && u != 0 && (r < 0) != (u < 0) {
        2 * r.abs() <= u.abs()
    } else {
        true
    }
}

/// COM.SIDE (M001, M002) for G92: s = sign(A.x − C.x); 0 has no retract direction.
pub fn side(a_x: i128, c_x: i128) -> i128 {
    (a_x - c_x).signum()
}

/// No.19 (G92.JK.1, G92.JK.2): the pull-out amount c = round(No.19 × lead / 10), converted from
/// the lead grid to the length grid (half up).
pub fn no19_amount(no19: u32, lead: i64, grid: Grid) -> i128 {
    round_div(no19 as i128 * lead as i128, 10 * grid.lead_counts_per_increment() as i128)
}

/// No.5131 for G92 (`000_…` line 79, `001_…` line 62: 5131 is the thread chamfer angle of G76,
/// G78 and G92): the short-axis amount of G92.JK.1, round(c·tan(5131°)), with the exact tangent
/// of G76.PULLOUT; 45° (the default) gives c itself.
pub fn jk1_short(c: i128, angle_5131: u32) -> i128 {
    let c = i64::try_from(c).unwrap_or(i64::MAX);
    round_mul_tan_degrees(c, angle_5131).unwrap_or(0) as i128
}

/// G92.JK.1–G92.JK.7 (M002) as one function of J, K (absolute values, JK.7), the No.19 amount c
/// and `c_short`, JK.1's short-axis amount ([`jk1_short`]). Returns the resolved (J, K) and the
/// rule that decided them, or `None` for no pull-out.
///
/// | J | K | result | rule |
/// |---|---|---|---|
/// | – | – | (c_short, c) | JK.1 (No.5131) |
/// | – | K | (c, K); K = 0 → (c, c) | JK.2 |
/// | 0 | any | none | JK.4 / JK.6 |
/// | J | – | (J, J) | JK.3 |
/// | J | 0 | (J, J) | JK.5 |
/// | J | K | (J, K) | PULLOUT |
///
/// A resolved amount of 0 means no pull-out.
pub fn resolve_jk(j: Option<i64>, k: Option<i64>, c: i128, c_short: i128) -> Option<(Amounts, Rule)> {
    let j = j.map(|v| v.unsigned_abs() as i128);
    let k = k.map(|v| v.unsigned_abs() as i128);
    let (amounts, rule) = match (j, k) {
        (None, None) => (Amounts { j: c_short, k: c }, Rule::G92Jk1),
        (None, Some(0)) => (Amounts { j: c, k: c }, Rule::G92Jk2),
        (None, Some(k)) => (Amounts { j: c, k }, Rule::G92Jk2),
        (Some(0), None) | (Some(0), Some(0)) => return None, // G92.JK.4
        (Some(0), Some(_)) => return None,                   // G92.JK.6
        (Some(j), None) => (Amounts { j, k: j }, Rule::G92Jk3),
        (Some(j), Some(0)) => (Amounts { j, k: j }, Rule::G92Jk5),
        (Some(j), Some(k)) => (Amounts { j, k }, Rule::G92Pullout),
    };
    if amounts.j == 0 || amounts.k == 0 {
        None
    } else {
        Some((amounts, rule))
    }
}

/// G92.PATH — step ③ opposite to ① (DEPARTS, `002_…` line 55: ③ retracts X "与①方向相反" and
/// returns to the start's X). The X where ③ begins, `x3` (the pull-out's end, or D.x without
/// one), must not lie beyond A.x on the side s: s·(A.x − X₃) < 0 has no move that does both.
/// Refused as `GEOMETRY` on J when the pull-out's short-axis move carried X there (D.x itself
/// is not beyond A.x), else on X. X₃ = A.x is legal (③ no move).
pub fn step3_ok(a_x: i128, d_x: i128, x3: i128, s: i128, line: u32) -> Result<(), Alarm> {
    if s * (a_x - x3) >= 0 {
        return Ok(());
    }
    let word = if s * (a_x - d_x) >= 0 { b'J' } else { b'X' };
    Err(alarm(AlarmCode::Geometry, word, Rule::G92Path, line))
}

/// Checks the cycle in the register's order — W (G92.FORMAT), the taper (G92.TAPER), the side
/// (COM.SIDE), No.19, the pull-out amounts, No.107 (G92.JK.8), K against the long axis
/// (G92.PULLOUT), the pass bound (PRJ.MAXPASS), step ③ (G92.PATH) — and emits it (G92.PATH).
pub fn expand(c: &G92Cycle, params: &Params, grid: Grid, out: &mut Out) -> Result<(), Alarm> {
    let line = c.line;
    let (ax, az) = c.a;
    let (dx, dz) = c.d;
    // G92.FORMAT: W = 0 is a face thread.
    let w = dz - az;
    if w == 0 {
        return Err(alarm(AlarmCode::Geometry, b'Z', Rule::G92Format, line));
    }
    // G92.TAPER
    let u = dx - ax;
    if !taper_ok(c.r, u) {
        return Err(alarm(AlarmCode::Geometry, b'R', Rule::G92Taper, line));
    }
    // COM.SIDE
    let cx = dx + 2 * c.r;
    let s = side(ax, cx);
    if s == 0 {
        return Err(alarm(AlarmCode::Geometry, b'X', Rule::ComSide, line));
    }
    // No.19 (parameter range 0…255)
    if params.no19_pullout > 255 {
        return Err(Alarm::new(AlarmCode::OutOfRange, None, Rule::G92Jk1, line));
    }
    let amount = no19_amount(params.no19_pullout as u32, c.lead, grid);
    let pull = resolve_jk(c.j, c.k, amount, jk1_short(amount, params.p5131_chamfer_angle as u32));
    // G92.JK.8: only No.107 = 0 is modelled.
    if params.no107_pullout_speed != 0 {
        return Err(Alarm::new(AlarmCode::Unsupported, None, Rule::G92Jk8, line));
    }
    // G92.PULLOUT: K less than the long-axis travel.
    let thread = ThreadLine { end_x: dx, end_z: dz, r: c.r, w, s };
    let segment = match pull {
        Some((amounts, rule)) => match pullout::segment(&thread, amounts) {
            Ok(seg) => Some((seg, rule)),
            Err(pullout::KTooLong) => return Err(alarm(AlarmCode::Geometry, b'K', Rule::G92Pullout, line)),
        },
        None => None,
    };
    // PRJ.MAXPASS: one pass × L starts.
    crate::multipass::check_max_passes(1, c.l as u128, params, b'L', line)?;
    // G92.PATH step ③ (DEPARTS): the last check, before any motion.
    let x3 = segment.map_or(dx, |((_, end), _)| end.0);
    step3_ok(ax, dx, x3, s, line)?;

    // PRJ.TRACE: one pass, depth = |A.x − C.x| (the X infeed of step ①). Each start is a cut
    // (G92.HOLD), the first one from the pass header on.
    let long = pullout::long_axis(w, c.r);
    out.begin_cut(long);
    out.pass(c.index, PassKind::Rough, (ax - cx).abs(), Rule::G92Path, line)?;
    for j in 0..c.l {
        if j > 0 {
            out.begin_cut(long);
        }
        let angle = start_angle(j, c.l);
        out.rapid(cx, az, Rule::G92Path, line)?; // ①
        match segment {
            Some(((start, end), rule)) => {
                out.thread(start.0, start.1, c.lead, angle, Rule::G92Path, line)?; // ②
                out.pullout(end.0, end.1, c.lead, angle, rule, line)?;
            }
            None => out.thread(dx, dz, c.lead, angle, Rule::G92Path, line)?,
        }
        let z_now = out.z as i128;
        out.rapid(ax, z_now, Rule::G92Path, line)?; // ③
        out.rapid(ax, az, Rule::G92Path, line)?; // ④
    }
    Ok(())
}

#[cfg(test)]
mod tests;
