//! The passes of a G76/G78 cycle: the geometry of one pass ([`Cut`]) and the pass plan
//! ([`Multi`]): the rough passes from the depth schedule, then the finishing passes, each pass's
//! cut computed when the cycle reaches it. Read by the running cycle (`emit::Cycle`), built by
//! `multipass`.

use crate::fixed::Tan;
use crate::schedule::{Rough, Schedule};
use cycle_vocab::readings::ThreadZRef;
use cycle_vocab::{Pass, PassKind, Rule};

/// The geometry of one pass: where the cut starts (C or Bn) and ends (D or En), X on diameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cut {
    pub p0: (i64, i64),
    pub end: (i64, i64),
}

/// Infeed flank of a rough pass (G76.MODE, G78.MODE).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flank {
    Right,
    Centre,
    Left,
}

/// A flank's Z offset (before σ) as a function of the depth: base + mul·t(δ).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FlankZ {
    base: i64,
    mul: i64,
}

impl FlankZ {
    /// Infeed Z and the modes (declared reading thread.zref), with t(T) = `t_target`:
    /// `start` (the letter) measures every mode from B.z = A.z — right t(δ), centre 0, left
    /// −t(δ); `groove` ends every mode's last rough pass at t(T) — right t(δ), centre t(T),
    /// left 2·t(T) − t(δ).
    pub fn of(flank: Flank, zref: ThreadZRef, t_target: i64) -> FlankZ {
        let groove = zref == ThreadZRef::Groove;
        match flank {
            Flank::Right => FlankZ { base: 0, mul: 1 },
            Flank::Centre => FlankZ { base: if groove { t_target } else { 0 }, mul: 0 },
            Flank::Left => FlankZ { base: if groove { t_target.saturating_mul(2) } else { 0 }, mul: -1 },
        }
    }
}

/// The pass plan of a multi-pass cycle and its fixed geometry.
#[derive(Clone, Copy, Debug)]
pub struct Multi {
    /// The Z offsets of even and odd rough passes (G76.MODE, G78.MODE, thread.zref).
    pub(crate) flanks: (FlankZ, FlankZ),
    pub(crate) sched: Schedule,
    /// The current rough pass, `None` once finishing.
    pub(crate) rough: Option<Rough>,
    /// Finishing passes done (including the current one).
    pub(crate) finish: u32,
    pub(crate) m: u32,
    pub(crate) index: u32,
    /// B.x = C.x + 2·s·k, diameter: where a cut at depth 0 would start.
    pub(crate) bx: i64,
    /// A.z.
    pub(crate) az: i64,
    /// σ = −s (s the side, ±1): the sign of the infeed's Z offset, and of X on radius per
    /// increment of depth.
    pub(crate) sigma: i64,
    pub(crate) k: i64,
    /// −2·R(i): the cut's X travel on diameter.
    pub(crate) taper: i64,
    /// W.
    pub(crate) w: i64,
    /// tan(a/2), a the tool angle (looked up once; a is a legal word, ≤ 178 half degrees).
    pub(crate) tan: Tan,
    /// G76.FINISH.Z: the Z offset of the last rough pass, where the finishing passes cut.
    pub(crate) finish_off: i64,
}

impl Multi {
    /// G76.INFEED.Z: t(δ) = round(δ·tan(a/2)).
    fn t(&self, depth: i64) -> i64 {
        i64::try_from(self.tan.times(depth.max(0).unsigned_abs())).unwrap_or(i64::MAX)
    }

    /// G76.INFEED.X, G76.INFEED.Z, G76.PATH: the cut of a pass at radius depth δ with Z offset
    /// `off`: from (B.x + 2σ·δ, A.z + σ·off), travelling (−2i, W). Legal words keep every term
    /// below 2^40 (lengths ≤ 10^9, tan(a/2) ≤ 57): the 64-bit arithmetic is exact and never
    /// wraps; wrapping operations keep an impossible overflow from panicking.
    fn cut(&self, depth: i64, off: i64) -> Cut {
        let x = self.bx.wrapping_add(self.sigma.wrapping_mul(depth).wrapping_mul(2));
        let z = self.az.wrapping_add(self.sigma.wrapping_mul(off));
        Cut { p0: (x, z), end: (x.wrapping_add(self.taper), z.wrapping_add(self.w)) }
    }

    /// The Z offset (before σ) of flank `f` at depth δ.
    #[inline(always)]
    pub(crate) fn offset(&self, f: FlankZ, depth: i64) -> i64 {
        if f.mul == 0 {
            return f.base;
        }
        f.base.saturating_add(f.mul.saturating_mul(self.t(depth)))
    }

    /// The cut of rough pass `r` (G76.DEPTH.*, G76.MODE, G78.MODE). Inlined into the pass
    /// change, which keeps its state in registers (outlined, it cost ~20 instructions a pass).
    #[inline(always)]
    fn rough_cut(&self, r: &Rough) -> Cut {
        let f = if r.n % 2 == 1 { self.flanks.1 } else { self.flanks.0 };
        self.cut(r.depth, self.offset(f, r.depth))
    }

    /// The header of the current pass: a rough pass (G76.DEPTH.*), or a finishing pass at
    /// depth k (G76.FINISH: the first finishing pass, then spring passes).
    #[inline]
    pub fn header(&self) -> Pass {
        match &self.rough {
            Some(r) => {
                Pass { index: self.index, kind: PassKind::Rough, diameter_depth: r.depth.saturating_mul(2), rule: r.rule }
            }
            None => {
                let kind = if self.finish <= 1 { PassKind::Finish } else { PassKind::Spring };
                Pass { index: self.index, kind, diameter_depth: self.k.saturating_mul(2), rule: Rule::G76Finish }
            }
        }
    }

    /// The cut of the first pass.
    pub(crate) fn begin(&mut self) -> Cut {
        let r = self.sched.first();
        self.rough = Some(r);
        self.index = 1;
        self.rough_cut(&r)
    }

    /// Moves on to the pass after the current one and returns its cut, or `None` when the
    /// cycle is done.
    #[inline]
    pub fn advance(&mut self) -> Option<Cut> {
        self.index = self.index.checked_add(1)?;
        if let Some(prev) = self.rough {
            if let Some(r) = self.sched.next(&prev) {
                self.rough = Some(r);
                return Some(self.rough_cut(&r));
            }
            self.rough = None;
        }
        if self.finish >= self.m {
            return None;
        }
        self.finish += 1;
        // G76.FINISH.Z: at the Z of the last rough pass.
        Some(self.cut(self.k, self.finish_off))
    }
}
