//! Where an action takes effect (OP.SCRIPT): the point P along a move of U, whether the part of a
//! move being executed passes it, and the moves cut short there.

use cycle_vocab::{Action, Alarm, AlarmCode, Along, Move, Script};

/// A fraction of a move, num / den, 0 ≤ num ≤ den, den ≥ 1.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Fraction {
    pub num: u64,
    pub den: u64,
}

impl Fraction {
    /// The start of a move: "a move started afresh covers [0, 1]".
    pub const START: Fraction = Fraction { num: 0, den: 1 };

    /// The fraction of a point along a move.
    pub fn of(along: &Along) -> Fraction {
        Fraction { num: u64::from(along.num), den: u64::from(along.den) }
    }

    /// Whether it is the move's end (1).
    pub fn is_end(&self) -> bool {
        self.num == self.den
    }
}

/// OP.SCRIPT (PRJ): "Move e 'passes' f when the part of it being executed covers f: a move
/// started afresh covers [0, 1]; the rest of a move resumed after a hold at f′ covers [f′, 1]
/// (fractions compared exactly, num·den′ against num′·den)." The part from `from` covers
/// `along` when along ≥ from.
pub fn covers(from: Fraction, along: &Along) -> bool {
    u64::from(along.num) * from.den >= from.num * u64::from(along.den)
}

/// OP.SCRIPT (PRJ): "The point on the grid, per axis (X diameter, Z): P = S + trunc((E − S)·num/den),
/// truncated toward S, where S and E are move e's start and end in U."
pub fn point(s: (i64, i64), e: (i64, i64), along: &Along) -> (i64, i64) {
    let axis = |s: i64, e: i64| {
        // Integer division truncates toward 0, that is toward S.
        let part = (i128::from(e) - i128::from(s)) * i128::from(along.num) / i128::from(along.den);
        s + part as i64
    };
    (axis(s.0, e.0), axis(s.1, e.1))
}

/// PRJ.TRACE, "Operator events": "A move cut short at P keeps every field of the original move
/// (kind, feed or lead, angle, lead change, angle of change, floor, centre 0, rule) and ends at
/// P". The move `m` ending at `p` instead.
pub fn ending_at(m: Move, p: (i64, i64)) -> Move {
    Move { x: p.0, z: p.1, ..m }
}

/// OP.SCRIPT (PRJ): "Checked with the configuration (before the first block, after the other
/// configuration checks): 1 ≤ den ≤ 1 000 000 and num ≤ den for every Hold and Reset, else
/// `OUT OF RANGE` on line 0, no word (OP.SCRIPT)."
pub fn check_script(script: &Script) -> Result<(), Alarm> {
    for action in script.actions() {
        if let Action::Hold(along) | Action::Reset(along) = action {
            if !along.is_legal() {
                return Err(Alarm::new(AlarmCode::OutOfRange, None, cycle_vocab::Rule::OpScript, 0));
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
