//! The depth schedule under proof, as a trait, so a deliberately wrong schedule can be plugged
//! into the same harness bodies (see [`mutants`]).

use cycle_impl::schedule::{self, Rough, ScheduleParams};

/// A G76/G78 rough-pass depth schedule (G76.DEPTH.1, G76.DEPTH.MIN, G76.DEPTH.LAST,
/// G78.DEPTHMODE): `cycle_impl::schedule::Schedule` prepared from `p` and asked one question.
pub trait Schedule {
    /// The first rough pass.
    fn first(&self, p: &ScheduleParams) -> Rough;
    /// The rough pass after `prev`; `None` after the last one.
    fn next(&self, p: &ScheduleParams, prev: &Rough) -> Option<Rough>;
    /// The number of rough passes, `None` when above `limit` (PRJ.MAXPASS).
    fn rough_pass_count(&self, p: &ScheduleParams, limit: u32) -> Option<u32>;
}

/// The production schedule, `cycle_impl::schedule::Schedule`.
#[derive(Clone, Copy, Debug, Default)]
pub struct Production;

impl Schedule for Production {
    fn first(&self, p: &ScheduleParams) -> Rough {
        schedule::Schedule::new(p).first()
    }

    fn next(&self, p: &ScheduleParams, prev: &Rough) -> Option<Rough> {
        schedule::Schedule::new(p).next(prev)
    }

    fn rough_pass_count(&self, p: &ScheduleParams, limit: u32) -> Option<u32> {
        schedule::Schedule::new(p).rough_pass_count(limit)
    }
}

/// Deliberately wrong schedules: each harness suite must reject at least one of them
/// (`mutant_schedule_is_caught`), which shows the harnesses are not vacuous.
pub mod mutants {
    use super::{Production, Schedule};
    use cycle_impl::schedule::{Rough, ScheduleParams};

    /// Clamps to k instead of k − d: the target seen by the schedule is T + d, with the
    /// finishing allowance d fixed here (G76.DEPTH.LAST read wrongly).
    #[derive(Clone, Copy, Debug)]
    pub struct ClampToK {
        pub finish_allowance: i64,
    }

    impl ClampToK {
        fn widen(&self, p: &ScheduleParams) -> ScheduleParams {
            ScheduleParams { target: p.target.saturating_add(self.finish_allowance), ..*p }
        }
    }

    impl Schedule for ClampToK {
        fn first(&self, p: &ScheduleParams) -> Rough {
            Production.first(&self.widen(p))
        }
        fn next(&self, p: &ScheduleParams, prev: &Rough) -> Option<Rough> {
            Production.next(&self.widen(p), prev)
        }
        fn rough_pass_count(&self, p: &ScheduleParams, limit: u32) -> Option<u32> {
            Production.rough_pass_count(&self.widen(p), limit)
        }
    }

    /// The last rough pass lands one increment beyond k − d.
    #[derive(Clone, Copy, Debug)]
    pub struct LastPlusOne;

    fn bump(r: Rough) -> Rough {
        if r.last { Rough { depth: r.depth + 1, ..r } } else { r }
    }

    impl Schedule for LastPlusOne {
        fn first(&self, p: &ScheduleParams) -> Rough {
            bump(Production.first(p))
        }
        fn next(&self, p: &ScheduleParams, prev: &Rough) -> Option<Rough> {
            Production.next(p, prev).map(bump)
        }
        fn rough_pass_count(&self, p: &ScheduleParams, limit: u32) -> Option<u32> {
            Production.rough_pass_count(p, limit)
        }
    }

    /// Ignores the minimum cut Δdmin (G76.DEPTH.MIN dropped).
    #[derive(Clone, Copy, Debug)]
    pub struct NoMinimum;

    fn no_min(p: &ScheduleParams) -> ScheduleParams {
        ScheduleParams { min_cut: 0, ..*p }
    }

    impl Schedule for NoMinimum {
        fn first(&self, p: &ScheduleParams) -> Rough {
            Production.first(&no_min(p))
        }
        fn next(&self, p: &ScheduleParams, prev: &Rough) -> Option<Rough> {
            Production.next(&no_min(p), prev)
        }
        fn rough_pass_count(&self, p: &ScheduleParams, limit: u32) -> Option<u32> {
            Production.rough_pass_count(&no_min(p), limit)
        }
    }

    /// Counts one pass too many (an off-by-one in the PRJ.MAXPASS count).
    #[derive(Clone, Copy, Debug)]
    pub struct CountOffByOne;

    impl Schedule for CountOffByOne {
        fn first(&self, p: &ScheduleParams) -> Rough {
            Production.first(p)
        }
        fn next(&self, p: &ScheduleParams, prev: &Rough) -> Option<Rough> {
            Production.next(p, prev)
        }
        fn rough_pass_count(&self, p: &ScheduleParams, limit: u32) -> Option<u32> {
            Production.rough_pass_count(p, limit).map(|c| c + 1)
        }
    }
}
