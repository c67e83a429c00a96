//! Points along a move (OP.SCRIPT).

use crate::fixed::sat;
use cycle_vocab::Along;

/// A fraction `num / den` of a move, 0 ≤ num ≤ den, 1 ≤ den ≤ 1 000 000 (checked with the
/// configuration, `config::check_script`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Frac {
    pub num: u32,
    pub den: u32,
}

impl Frac {
    /// The start of a move: a move started afresh covers [0, 1].
    pub const ZERO: Frac = Frac { num: 0, den: 1 };

    /// OP.SCRIPT: the fraction of a point along a move.
    pub const fn of(a: &Along) -> Frac {
        Frac { num: a.num, den: a.den }
    }

    /// OP.SCRIPT: `self ≥ other`, exactly (num·den′ against num′·den; u32 products fit u64).
    pub fn at_least(self, other: Frac) -> bool {
        u64::from(self.num) * u64::from(other.den) >= u64::from(other.num) * u64::from(self.den)
    }

    /// The end of the move (num = den).
    pub const fn is_one(self) -> bool {
        self.num >= self.den
    }
}

/// OP.SCRIPT: the point P at the fraction `f` of the move from `s` to `e`, per axis
/// `s + trunc((e − s)·num/den)`, truncated toward `s`. Positions are below 2^62 and num ≤ 10^6,
/// so the product stays below 2^83: exact in i128; den ≥ 1 (a den of 0 never passes the check
/// and is read as 1 here, so the division cannot fault).
pub fn point(s: (i64, i64), e: (i64, i64), f: Frac) -> (i64, i64) {
    let axis = |s: i64, e: i64| {
        let d = i128::from(e) - i128::from(s);
        let off = d * i128::from(f.num) / i128::from(f.den.max(1));
        sat(i128::from(s) + off)
    };
    (axis(s.0, e.0), axis(s.1, e.1))
}
