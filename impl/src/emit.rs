//! The running cycle: a small state machine that yields one trace event per call (PRJ.TRACE):
//! pass headers, then per start the moves of G92.PATH / G76.PATH, skipping moves to the current
//! position (PRJ.NOOP). No buffering: each move is computed from the pass geometry and a step
//! counter.

use crate::fixed::start_angle;
use crate::multipass::Multi;
use crate::pullout::Offsets;
use cycle_vocab::{Event, Move, Pass, Rule};

/// The geometry of one pass: where the cut starts (C or Bn) and ends (D or En), X on diameter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Cut {
    pub p0: (i64, i64),
    pub end: (i64, i64),
}

/// What stays fixed for a whole cycle.
#[derive(Clone, Copy, Debug)]
pub struct Path {
    /// The start point A (X diameter).
    pub a: (i64, i64),
    /// Lead, lead counts.
    pub lead: i64,
    /// Number of starts L (≥ 1).
    pub starts: u32,
    /// G76.LEADIN: offset of the lead-in point from Bn on X, diameter (s·2E); 0 = no lead-in.
    pub leadin: i64,
    /// The pull-out, as offsets from the pass end; `None`: no pull-out.
    pub pull: Option<Offsets>,
    /// Rule of rapids and the thread cut.
    pub rule_path: Rule,
    /// Rule of the pull-out move.
    pub rule_pull: Rule,
}

/// Which passes follow the first.
#[derive(Clone, Copy, Debug)]
pub enum Plan {
    /// G92: one pass.
    Single,
    /// G76/G78: rough passes from the schedule, then the finishing passes.
    Multi(Multi),
}

/// A cycle being expanded.
#[derive(Clone, Copy, Debug)]
pub struct Cycle {
    path: Path,
    plan: Plan,
    cut: Cut,
    header: Option<Pass>,
    start: u32,
    /// The spindle start angle of `start` (COM.MULTISTART), computed once per start.
    angle: u32,
    step: u8,
}

/// Steps of one start: approach, lead-in, cut, pull-out, retract X, retract Z.
const STEPS: u8 = 6;

fn add(p: (i64, i64), d: (i64, i64)) -> (i64, i64) {
    (p.0.saturating_add(d.0), p.1.saturating_add(d.1))
}

impl Cycle {
    /// A cycle whose first pass has the header `header` and geometry `cut`.
    pub fn new(path: Path, plan: Plan, header: Pass, cut: Cut) -> Cycle {
        Cycle { path, plan, cut, header: Some(header), start: 0, angle: 0, step: 0 }
    }

    /// Where the cut of the current pass ends, after the pull-out if any.
    fn cut_exit(&self) -> (i64, i64) {
        match self.path.pull {
            Some(o) => add(self.cut.end, o.end),
            None => self.cut.end,
        }
    }

    /// The move of `step` for the current start, or `None` when the step has no move.
    #[inline]
    fn move_at(&self, step: u8) -> Option<Move> {
        let p = &self.path;
        let thread = |(x, z): (i64, i64), rule: Rule| Some(Move::thread(x, z, p.lead, self.angle, rule));
        match step {
            // G76.PATH / G92.PATH ①: rapid to the infeed point (to the lead-in point first).
            0 => {
                let (x, z) = self.cut.p0;
                Some(Move::rapid(x.saturating_add(p.leadin), z, p.rule_path))
            }
            // G76.LEADIN: synchronized X move from the lead-in point to Bn.
            1 if p.leadin != 0 => thread(self.cut.p0, Rule::G76LeadIn),
            // ②: the cut, to the pull-out start or to the end.
            2 => match p.pull {
                Some(o) => thread(add(self.cut.end, o.start), p.rule_path),
                None => thread(self.cut.end, p.rule_path),
            },
            // G92.PULLOUT / G76.PULLOUT: the pull-out segment.
            3 => p.pull.and_then(|o| thread(add(self.cut.end, o.end), p.rule_pull)),
            // ③: rapid X back to A.x.
            4 => Some(Move::rapid(p.a.0, self.cut_exit().1, p.rule_path)),
            // ④: rapid Z back to A.z.
            5 => Some(Move::rapid(p.a.0, p.a.1, p.rule_path)),
            _ => None,
        }
    }

    /// The next event of the cycle, updating the machine position; `None` when it is done.
    /// Bounded work: at most [`STEPS`] skipped moves and one pass change per call.
    #[inline]
    pub fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event> {
        loop {
            if let Some(h) = self.header.take() {
                return Some(Event::Pass(h));
            }
            if self.step >= STEPS {
                self.step = 0;
                self.start = self.start.saturating_add(1);
                self.angle = start_angle(self.start, self.path.starts);
                if self.start >= self.path.starts {
                    self.start = 0;
                    self.angle = 0;
                    let Plan::Multi(multi) = &mut self.plan else {
                        return None;
                    };
                    let (header, cut) = multi.advance()?;
                    self.header = Some(header);
                    self.cut = cut;
                }
                continue;
            }
            let mv = self.move_at(self.step);
            self.step += 1;
            if let Some(m) = mv {
                // PRJ.NOOP: a move to the current position is not emitted.
                if (m.x, m.z) != *pos {
                    *pos = (m.x, m.z);
                    return Some(Event::Move(m));
                }
            }
        }
    }
}
