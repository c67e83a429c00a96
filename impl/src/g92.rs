//! G92 single thread cycle (M002): the modal run and the cycle's checks and path.

use crate::fixed::{abs_diff, sat};
use crate::emit::{Cycle, Path, Plan};
use crate::passes::Cut;
use crate::pullout::{g92_amounts, offsets, tenths_of_lead, travel, Offsets};
use crate::config::Params;
use cycle_vocab::{Alarm, AlarmCode, Config, Pass, PassKind, Rule};

/// G92.MODAL: what a run keeps (end point, R, cycle count) and what the program keeps
/// (J, K, L).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct G92State {
    /// End point of the run (X diameter, Z), absolute.
    pub end: (i64, i64),
    /// R, radius.
    pub r: i64,
    /// Cycles cut in this run.
    pub index: u32,
    /// J, K as absolute values (G92.JK.7), kept for the whole program; −1 until one is written
    /// (an absolute value is never negative).
    pub j: i64,
    pub k: i64,
    /// L, kept for the whole program.
    pub starts: u32,
}

impl G92State {
    pub const fn new() -> G92State {
        G92State { end: (0, 0), r: 0, index: 0, j: -1, k: -1, starts: 1 }
    }

    /// G92.MODAL: a new run (G92 after another motion mode) starts with R = 0 and the end point
    /// at the current position.
    pub fn new_run(&mut self, pos: (i64, i64)) {
        self.end = pos;
        self.r = 0;
        self.index = 0;
    }
}

/// The pull-out of the last G92 cycle with what it was made from. A modal run repeats it block
/// after block (only X changes), so its two divisions are done once per change of its inputs:
/// the lead, J, K, W, R and the side. The configuration (No.19, the grid) is the machine's and
/// fixed for the program.
#[derive(Clone, Copy, Debug, Default)]
pub struct PullMemo {
    /// The inputs the kept values were made from; all 0 (W = 0, which no cycle has: G92.FORMAT
    /// comes first) before the first.
    made_from: PullInputs,
    /// G92.PULLOUT: the resolved K is not below the long-axis travel (the cycle's alarm).
    long_k: bool,
    offsets: Option<Offsets>,
}

/// A pull-out's inputs as plain integers, compared as a whole (J and K as [`G92State`] keeps
/// them: −1 for none written).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
struct PullInputs {
    lead: i64,
    j: i64,
    k: i64,
    w: i64,
    r: i64,
    s: i64,
}

/// The J or K kept in [`G92State`] as the word: `None` for −1 (none written).
fn jk_word(key: i64) -> Option<i64> {
    (key >= 0).then_some(key)
}

impl PullMemo {
    /// From the G92.JK.1–7 amounts (No.19 of the lead where J or K is omitted, No.5131 for
    /// JK.1's J): whether K reaches the long-axis travel (G92.PULLOUT's alarm), and the
    /// G92.PULLOUT offsets — the kept ones when the inputs are the last cycle's. Inlined: the
    /// kept values are read where they are used; a change of inputs is [`PullMemo::make`].
    #[inline(always)]
    fn get(&mut self, config: &Config, params: &Params, inputs: PullInputs) -> (bool, Option<Offsets>) {
        if self.made_from != inputs {
            self.make(config, params, inputs.lead, inputs.j, inputs.k, inputs.w, inputs.r, inputs.s);
        }
        (self.long_k, self.offsets)
    }

    /// The amounts and offsets for new inputs, kept. The inputs one by one, so that the caller
    /// keeps them in registers, not in memory.
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn make(&mut self, config: &Config, params: &Params, lead: i64, j: i64, k: i64, w: i64, r: i64, s: i64) {
        let inputs = PullInputs { lead, j, k, w, r, s };
        let c = tenths_of_lead(params.no19_pullout, inputs.lead, config.grid);
        let amounts = g92_amounts(jk_word(inputs.j), jk_word(inputs.k), c, params.p5131_chamfer_angle);
        let long_k = amounts.is_some_and(|am| am.k.unsigned_abs() >= travel(w, r));
        let offsets = amounts.map(|am| offsets(am, inputs.w, inputs.r, inputs.s));
        *self = PullMemo { made_from: inputs, long_k, offsets };
    }
}

/// One G92 cycle from `a` with the run's values: checks in the register's order — W = 0
/// (G92.FORMAT), taper (G92.TAPER), side (COM.SIDE), No.107 (G92.JK.8), K against the long-axis
/// travel (G92.PULLOUT), pass bound (PRJ.MAXPASS), step ③ opposite to ① (G92.PATH) — then the
/// cycle (G92.PATH). Inlined into the block interpreter, so that the cycle is built where it
/// runs (`Run`), not copied there.
#[inline(always)]
pub fn cycle(
    config: &Config,
    params: &Params,
    st: &G92State,
    pull: &mut PullMemo,
    a: (i64, i64),
    lead: i64,
    line: u32,
) -> Result<Cycle, Alarm> {
    let alarm = |code: AlarmCode, word: Option<u8>, rule: Rule| refused(code, word, rule, line);
    let d = st.end;
    let r = st.r;
    // G92.FORMAT: W = 0 is a face thread. (Saturating, as the exact difference taken to i64;
    // the saturation out of line.)
    let w = d.1.checked_sub(a.1).unwrap_or_else(|| sat_sub(d.1, a.1));
    if w == 0 {
        return Err(alarm(AlarmCode::Geometry, Some(b'Z'), Rule::G92Format));
    }
    // G92.TAPER: U = D.x − A.x (diameter); R and U of different signs need 2|R| ≤ |U| (exact,
    // in i128; only a taper has R ≠ 0). U = 0 has no sign: sign(R)·sign(U) is then 0.
    if r != 0 {
        let u = i128::from(d.0) - i128::from(a.0);
        if i128::from(r.signum()) * u.signum() < 0 && 2 * i128::from(r).abs() > u.abs() {
            return Err(alarm(AlarmCode::Geometry, Some(b'R'), Rule::G92Taper));
        }
    }
    // COM.SIDE: s = sign(A.x − C.x), C.x = D.x + 2R: exact in i64 where it fits (every position
    // below 2^62, lib.rs "Magnitudes"), else [`wide_side`].
    let (cx, s) = match r.checked_mul(2).and_then(|r2| d.0.checked_add(r2)) {
        Some(cx) => (cx, i64::from(a.0 > cx) - i64::from(a.0 < cx)),
        None => wide_side(a.0, d.0, r),
    };
    if s == 0 {
        return Err(alarm(AlarmCode::Geometry, Some(b'X'), Rule::ComSide));
    }
    // G92.JK.8: only No.107 = 0 is modelled.
    if params.no107_pullout_speed != 0 {
        return Err(alarm(AlarmCode::Unsupported, None, Rule::G92Jk8));
    }
    let (long_k, pull) = pull.get(config, params, PullInputs { lead, j: st.j, k: st.k, w, r, s });
    if long_k {
        return Err(alarm(AlarmCode::Geometry, Some(b'K'), Rule::G92Pullout));
    }
    // PRJ.MAXPASS: one pass × L starts.
    if st.starts > params.max_passes {
        return Err(alarm(AlarmCode::TooManyPasses, Some(b'L'), Rule::PrjMaxPass));
    }
    // G92.PATH — step ③ opposite to ① (DEPARTS, `002_…` line 55), the last check: ③ starts at
    // X₃ (the pull-out's end, else D.x); X₃ beyond A.x (s·(A.x − X₃) < 0) is refused, on J
    // when the pull-out's short-axis move carries X there, else on X.
    // s·(A.x − x) < 0 with s = ±1, as a comparison (no product). X₃ = D.x + the pull-out's X;
    // where that leaves i64, X₃ lies past every i64 on the side of the pull-out's sign.
    let beyond = |x: i64| if s == 1 { a.0 < x } else { a.0 > x };
    let e = pull.map_or(0, |o| o.end.0);
    let past = match d.0.checked_add(e) {
        Some(x3) => beyond(x3),
        None => (s == 1) == (e > 0),
    };
    if past {
        let word = if beyond(d.0) { b'X' } else { b'J' };
        return Err(alarm(AlarmCode::Geometry, Some(word), Rule::G92Path));
    }
    let path = Path {
        a,
        lead,
        starts: st.starts.max(1),
        leadin: 0,
        pull,
        rule_path: Rule::G92Path,
        rule_pull: Rule::G92Pullout,
    };
    // Pass header: the X infeed from the start point, |A.x − C.x| on diameter.
    let depth = abs_diff(a.0, cx);
    let header = Pass { index: st.index, kind: PassKind::Rough, diameter_depth: depth, rule: Rule::G92Path };
    Ok(Cycle::new(path, Plan::Single(header), Cut { p0: (cx, a.1), end: d }))
}

/// C.x = D.x + 2R and the side sign(A.x − C.x) of [`cycle`] where C.x leaves i64: both exact
/// in i128, C.x then saturated to i64.
#[cold]
#[inline(never)]
fn wide_side(ax: i64, dx: i64, r: i64) -> (i64, i64) {
    let cx = i128::from(dx) + 2 * i128::from(r);
    (sat(cx), sat((i128::from(ax) - cx).signum()))
}

/// [`cycle`]'s alarm, made out of line: the alarm comes back whole (8 bytes in a register), so
/// that the cycle returned beside it in the same `Result` is not taken apart byte by byte where
/// the alarm's fields would lie.
#[cold]
#[inline(never)]
fn refused(code: AlarmCode, word: Option<u8>, rule: Rule, line: u32) -> Alarm {
    Alarm::new(code, word, rule, line)
}

/// `a − b` saturated, where it leaves i64 ([`cycle`]'s W).
#[cold]
#[inline(never)]
fn sat_sub(a: i64, b: i64) -> i64 {
    a.saturating_sub(b)
}

#[cfg(test)]
mod tests;
