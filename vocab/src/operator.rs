//! Operator events as input (OP.SCRIPT): what the machinist does while a program runs.
//!
//! A [`Script`] is a time-ordered list of at most [`SCRIPT_MAX`] actions, carried in the
//! configuration. Each action waits for its moment, which comes after the previous action's:
//!
//! - [`Action::Hold`] and [`Action::Reset`] are pressed when the machine reaches a point
//!   ([`Along`]) of a move of the **uninterrupted** trace (the trace of the same program and
//!   configuration without a script): the first time it gets there after the previous action.
//! - [`Action::Start`] (cycle start) is pressed at the next feed-hold stop.
//! - [`Action::SingleBlock`] switches single-block mode when the machine is about to begin the
//!   event `before` of the uninterrupted trace.
//!
//! What each action does in each cycle is the interpretation register's ("Operator events"):
//! G92.HOLD, G92.SINGLE, G76.HOLD, G76.SINGLE, G162.NOSTOP, OP.HOLD, OP.RESUME, OP.RESET,
//! OP.SINGLE, OP.SCOPE, OP.AT, OP.REACH.

/// The most actions one script holds (OP.SCRIPT): a fixed bound, so the production expander
/// keeps its script without a heap.
pub const SCRIPT_MAX: usize = 16;

/// The largest denominator of a point along a move (OP.SCRIPT).
pub const ALONG_DEN_MAX: u32 = 1_000_000;

/// A point along move `event` of the uninterrupted trace (0-based index into its event list,
/// pass headers included): the fraction `num / den` of the way from the move's start to its
/// end, 0 ≤ num ≤ den, 1 ≤ den ≤ [`ALONG_DEN_MAX`]. On the grid each axis is
/// `start + trunc((end − start) · num / den)`, truncated toward the start.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
pub struct Along {
    pub event: u32,
    pub num: u32,
    pub den: u32,
}

impl Along {
    /// Whether the fraction is legal (OP.SCRIPT): 1 ≤ den ≤ [`ALONG_DEN_MAX`], num ≤ den.
    pub const fn is_legal(&self) -> bool {
        self.den >= 1 && self.den <= ALONG_DEN_MAX && self.num <= self.den
    }
}

/// One operator action.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(rename_all = "snake_case"))]
pub enum Action {
    /// Feed hold pressed at a point of a move.
    Hold(Along),
    /// Reset (or emergency stop, or a drive alarm) at a point of a move.
    Reset(Along),
    /// Cycle start pressed at the next feed-hold stop.
    Start,
    /// Single-block mode switched on or off before event `before` of the uninterrupted trace.
    SingleBlock { on: bool, before: u32 },
}

/// A script of operator actions, in the order they happen; empty by default.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[cfg_attr(feature = "std", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "std", serde(try_from = "std::vec::Vec<Action>", into = "std::vec::Vec<Action>"))]
pub struct Script {
    len: u8,
    actions: [Action; SCRIPT_MAX],
}

/// A script would exceed [`SCRIPT_MAX`] actions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ScriptFull;

impl core::fmt::Display for ScriptFull {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "an operator script holds at most {SCRIPT_MAX} actions")
    }
}

impl Script {
    /// No actions: the program runs uninterrupted.
    pub const EMPTY: Script = Script { len: 0, actions: [Action::Start; SCRIPT_MAX] };

    /// The actions, in order.
    pub fn actions(&self) -> &[Action] {
        &self.actions[..usize::from(self.len)]
    }

    pub const fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Appends an action.
    pub fn push(&mut self, action: Action) -> Result<(), ScriptFull> {
        let slot = self.actions.get_mut(usize::from(self.len)).ok_or(ScriptFull)?;
        *slot = action;
        self.len += 1;
        Ok(())
    }

    /// The script of these actions.
    pub fn of(actions: &[Action]) -> Result<Script, ScriptFull> {
        let mut s = Script::EMPTY;
        for a in actions {
            s.push(*a)?;
        }
        Ok(s)
    }
}

impl Default for Script {
    fn default() -> Script {
        Script::EMPTY
    }
}

#[cfg(feature = "std")]
impl TryFrom<std::vec::Vec<Action>> for Script {
    type Error = ScriptFull;
    fn try_from(v: std::vec::Vec<Action>) -> Result<Script, ScriptFull> {
        Script::of(&v)
    }
}

#[cfg(feature = "std")]
impl From<Script> for std::vec::Vec<Action> {
    fn from(s: Script) -> std::vec::Vec<Action> {
        s.actions().to_vec()
    }
}

#[cfg(test)]
mod tests;
