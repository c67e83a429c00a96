//! The [`Source`] of a harness body's values, and how a body stops.

/// Why a body stopped early.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    /// An assumption did not hold: the case is outside the harness's domain (not a failure).
    Rejected,
    /// A checked property did not hold.
    Failed(&'static str),
}

/// What a harness body returns.
pub type Outcome = Result<(), Stop>;

/// Values for a harness body, and the place its verdicts go.
pub trait Source {
    /// A value in `lo..=hi` (`lo <= hi`). Every other draw is made from this one, except under
    /// Kani, where each width draws natively.
    fn bounded_i128(&mut self, lo: i128, hi: i128) -> i128;

    /// A value in `lo..=hi` (`lo <= hi`).
    fn bounded_i64(&mut self, lo: i64, hi: i64) -> i64 {
        self.bounded_i128(i128::from(lo), i128::from(hi)) as i64
    }

    /// A value in `lo..=hi` (`lo <= hi`).
    fn bounded_u64(&mut self, lo: u64, hi: u64) -> u64 {
        self.bounded_i128(i128::from(lo), i128::from(hi)) as u64
    }

    /// A value in `lo..=hi` (`lo <= hi`).
    fn bounded_u32(&mut self, lo: u32, hi: u32) -> u32 {
        self.bounded_i128(i128::from(lo), i128::from(hi)) as u32
    }

    /// Any `u128`, as two 64-bit halves (high half drawn first).
    fn any_u128(&mut self) -> u128 {
        let hi = self.bounded_u64(0, u64::MAX);
        let lo = self.bounded_u64(0, u64::MAX);
        (u128::from(hi) << 64) | u128::from(lo)
    }

    /// A value in `lo..=hi` from a small finite domain (an angle, a mode, a choice) that the
    /// exhaustive driver enumerates whole, whatever its width.
    fn every_u32(&mut self, lo: u32, hi: u32) -> u32 {
        self.bounded_u32(lo, hi)
    }

    /// Either boolean.
    fn bool(&mut self) -> bool {
        self.every_u32(0, 1) == 1
    }

    /// An index in `0..n` (`n >= 1`): which of `n` alternatives.
    fn choose(&mut self, n: u32) -> u32 {
        self.every_u32(0, n - 1)
    }

    /// Restricts the harness to cases where `cond` holds; a concrete source discards the case.
    fn assume(&mut self, cond: bool) -> Outcome {
        assumption(cond)
    }

    /// The verdict of one checked property (use [`check!`](crate::check), which also emits the
    /// Kani assertion).
    fn verdict(&mut self, ok: bool, msg: &'static str) -> Outcome {
        if ok {
            Ok(())
        } else {
            Err(Stop::Failed(msg))
        }
    }

    /// Records that a cover condition was evaluated (use [`cover!`](crate::cover)).
    fn cover(&mut self, _cond: bool, _msg: &'static str) {}

    /// The program text the body built, for a report or a regression's reader (most sources
    /// ignore it).
    fn note_program(&mut self, _program: &[u8]) {}
}

/// `Ok` when `cond` holds, else the case is rejected.
pub(crate) fn assumption(cond: bool) -> Outcome {
    if cond {
        Ok(())
    } else {
        Err(Stop::Rejected)
    }
}
