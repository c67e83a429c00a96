//! The trace (PRJ.TRACE): what an expander emits, one event at a time.
//!
//! Coordinates are absolute end points in increments: X as a diameter, Z. Thread moves carry the
//! lead (lead grid, COM.LEAD), the spindle start angle in 0.001° (COM.MULTISTART) and, for a
//! variable lead (G34, G162.I), the lead change over a spindle angle and the floor where a
//! shrinking lead stops. Pass headers carry the pass index, its kind and its depth on diameter
//! (twice the radius depth), so depths derived from diameters stay exact.
//!
//! **Variable lead** (docs/INTERPRETATION.md, "Trace"): a thread move with `lead_change ≠ 0` is
//! synchronized at its own start; there the lead is `feed`, and it changes continuously by
//! `lead_change` per `lead_change_angle` of spindle rotation. After a long-axis travel `s` (lead
//! counts) the lead `L` satisfies `L² = feed² + 720 000·lead_change·s / lead_change_angle`. A
//! shrinking lead stops changing once it is ≤ `lead_floor` (0: no floor). With `lead_steps` the
//! lead is instead `feed` for the first `lead_change_angle` of rotation, then changes by
//! `lead_change` at the end of each such angle (a shrinking lead steps only while it is above
//! `lead_floor`). A constant lead has `lead_change = lead_change_angle = lead_floor = 0` and
//! `lead_steps` false.
//!
//! **Arcs** (G02/G03, ARC.*): an arc move carries its end point and its centre, absolute, X of
//! the centre on diameter like every X (the centre as the engines decided it: given by I/K, or
//! the R-centre rounded once to the grid). Its start is the position before it; the arc runs
//! about the centre on the circle through that start, clockwise (`ArcCw`, G02) or counter-clockwise
//! (`ArcCcw`, G03) viewed with +Z to the right and +X up (ARC.DIR). Other moves have centre 0, 0.

use crate::rule::Rule;

/// The kind of a move.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum MoveKind {
    /// Positioning at rapid rate (`G00`).
    Rapid,
    /// Linear feed (`G01`); `feed` is the modal feed on the lead grid.
    Feed,
    /// Spindle-synchronized thread move (`G32`), thread cuts and pull-outs alike.
    Thread,
    /// Clockwise arc at feed (`G02`), about the centre `cx`, `cz`.
    ArcCw,
    /// Counter-clockwise arc at feed (`G03`), about the centre `cx`, `cz`.
    ArcCcw,
}

/// One motion to an absolute end point.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Move {
    pub kind: MoveKind,
    /// End X, diameter, increments.
    pub x: i64,
    /// End Z, increments.
    pub z: i64,
    /// Feed (Feed, arcs) or lead (Thread) in lead counts; 0 for Rapid.
    pub feed: i64,
    /// An arc's centre: X (diameter) and Z, increments, absolute; 0 for other moves.
    #[cfg_attr(feature = "std", serde(default))]
    pub cx: i64,
    #[cfg_attr(feature = "std", serde(default))]
    pub cz: i64,
    /// Spindle start angle of a thread move, 0.001°; 0 otherwise.
    pub angle: u32,
    /// Lead change of a thread move per `lead_change_angle`, lead counts, signed; 0 for a
    /// constant lead.
    pub lead_change: i64,
    /// The spindle angle over which the lead changes by `lead_change`, 0.001° (360 000: per
    /// revolution); 0 when `lead_change` is 0.
    #[cfg_attr(feature = "std", serde(default))]
    pub lead_change_angle: u32,
    /// The lead at or below which a shrinking lead stops changing (G162.I), lead counts; 0: none.
    #[cfg_attr(feature = "std", serde(default))]
    pub lead_floor: i64,
    /// The lead changes in steps of `lead_change`, one at the end of every `lead_change_angle`
    /// of spindle rotation (G162.I under `g162.lead=steps`), instead of continuously; false for
    /// a constant or continuously changing lead.
    #[cfg_attr(feature = "std", serde(default, skip_serializing_if = "core::ops::Not::not"))]
    pub lead_steps: bool,
    /// The rule this move realises.
    pub rule: Rule,
}

impl Move {
    pub const fn rapid(x: i64, z: i64, rule: Rule) -> Move {
        Move { kind: MoveKind::Rapid, x, z, feed: 0, cx: 0, cz: 0, angle: 0, lead_change: 0, lead_change_angle: 0, lead_floor: 0, lead_steps: false, rule }
    }

    pub const fn feed(x: i64, z: i64, feed: i64, rule: Rule) -> Move {
        Move { kind: MoveKind::Feed, x, z, feed, cx: 0, cz: 0, angle: 0, lead_change: 0, lead_change_angle: 0, lead_floor: 0, lead_steps: false, rule }
    }

    pub const fn thread(x: i64, z: i64, lead: i64, angle: u32, rule: Rule) -> Move {
        Move { kind: MoveKind::Thread, x, z, feed: lead, cx: 0, cz: 0, angle, lead_change: 0, lead_change_angle: 0, lead_floor: 0, lead_steps: false, rule }
    }

    /// A thread move whose lead starts at `lead` and changes by `change` per `change_angle`
    /// (0.001°), held once a shrinking lead is ≤ `floor` (0: no floor). A `change` of 0 gives the
    /// constant-lead form (all three fields 0).
    #[allow(clippy::too_many_arguments)]
    pub const fn variable_thread(
        x: i64,
        z: i64,
        lead: i64,
        angle: u32,
        change: i64,
        change_angle: u32,
        floor: i64,
        rule: Rule,
    ) -> Move {
        if change == 0 {
            return Move::thread(x, z, lead, angle, rule);
        }
        Move { kind: MoveKind::Thread, x, z, feed: lead, cx: 0, cz: 0, angle, lead_change: change, lead_change_angle: change_angle, lead_floor: floor, lead_steps: false, rule }
    }

    /// [`Move::variable_thread`] with the lead changing in steps (`lead_steps`); a `change` of 0
    /// gives the constant-lead form.
    pub const fn stepped(self) -> Move {
        let lead_steps = self.lead_change != 0;
        Move { lead_steps, ..self }
    }

    /// An arc at `feed` to (`x`, `z`) about the centre (`cx`, `cz`): clockwise (G02) when
    /// `clockwise`, else counter-clockwise (G03).
    pub const fn arc(clockwise: bool, x: i64, z: i64, cx: i64, cz: i64, feed: i64, rule: Rule) -> Move {
        let kind = if clockwise { MoveKind::ArcCw } else { MoveKind::ArcCcw };
        Move { kind, x, z, feed, cx, cz, angle: 0, lead_change: 0, lead_change_angle: 0, lead_floor: 0, lead_steps: false, rule }
    }
}

/// The kind of a pass (G76.FINISH).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "SCREAMING_SNAKE_CASE"))]
pub enum PassKind {
    Rough,
    /// The semi-finish pass of a stock-removal cycle (G71.LASTPASS): the contour with the
    /// finishing allowances left.
    Semi,
    Finish,
    Spring,
}

impl PassKind {
    pub const fn name(self) -> &'static str {
        match self {
            PassKind::Rough => "ROUGH",
            PassKind::Semi => "SEMI",
            PassKind::Finish => "FINISH",
            PassKind::Spring => "SPRING",
        }
    }
}

/// The header before the moves of one pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Pass {
    /// 1-based pass number within its cycle (G92: within its modal run).
    pub index: u32,
    pub kind: PassKind,
    /// Depth on diameter, increments: twice the radius depth of the pass.
    pub diameter_depth: i64,
    /// The rule that set this depth.
    pub rule: Rule,
}

/// A dwell: the tool stays where it is for `ms` milliseconds (G83/G84's P, G04's form).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Dwell {
    pub ms: u32,
    pub rule: Rule,
}

/// The spindle's direction (rigid tapping reverses it at the bottom, G84.PATH).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "SCREAMING_SNAKE_CASE"))]
pub enum SpindleState {
    /// The programmed direction (`M03` in the canonical form).
    Forward,
    /// The opposite direction (`M04`).
    Reverse,
}

/// The spindle changes direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Spindle {
    pub state: SpindleState,
    pub rule: Rule,
}

/// A button the operator pressed (OP.SCRIPT).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "SCREAMING_SNAKE_CASE"))]
pub enum Button {
    /// Feed hold.
    Hold,
    /// Reset (emergency stop, drive alarm): the motion stops at the point; nothing follows.
    Reset,
}

/// The operator pressed `button` with the tool at (`x`, `z`) (X diameter, Z, increments). It
/// comes **before** the move during which it was pressed; that move ends at the point, or runs
/// on, as `rule` says (register, "Operator events").
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Press {
    pub button: Button,
    pub x: i64,
    pub z: i64,
    pub rule: Rule,
}

/// Why the machine stopped and waits.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "SCREAMING_SNAKE_CASE"))]
pub enum StopReason {
    /// A feed hold took effect.
    FeedHold,
    /// Single-block mode: the end of a block (or of what the cycle's rule treats as one).
    SingleBlock,
}

/// The machine stops where it is and waits for cycle start.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Stop {
    pub reason: StopReason,
    pub rule: Rule,
}

/// Cycle start after a stop: the machine goes on as `rule` says (OP.RESUME, OP.SINGLE, …).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Resume {
    pub rule: Rule,
}

/// One trace event.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(tag = "event", rename_all = "snake_case"))]
pub enum Event {
    Pass(Pass),
    Move(Move),
    Dwell(Dwell),
    Spindle(Spindle),
    Press(Press),
    Stop(Stop),
    Resume(Resume),
}

impl Event {
    /// The rule behind the event.
    pub const fn rule(&self) -> Rule {
        match self {
            Event::Pass(p) => p.rule,
            Event::Move(m) => m.rule,
            Event::Dwell(d) => d.rule,
            Event::Spindle(s) => s.rule,
            Event::Press(p) => p.rule,
            Event::Stop(s) => s.rule,
            Event::Resume(r) => r.rule,
        }
    }
}
