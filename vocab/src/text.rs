//! The trace as an owned value, and its two printed forms: JSON and canonical expanded G-code.
//!
//! Canonical G-code (documented in docs/TRACE.md, parsed by vendors):
//!
//! ```text
//! (CYCLECHECK TRACE MM GRID 0.001)
//! G00 X65.000 Z5.000
//! (PASS 1 ROUGH DEPTH 3.150)
//! G00 X58.700 Z5.000
//! G32 X58.700 Z-27.000 F3.0000
//! (ALARM 2001 LINE 3 WORD P RULE G76.REQUIRED)
//! ```
//!
//! One motion per line with both axes, X as a diameter, lengths with the grid's decimals, F with
//! the lead grid's decimals. `G32` lines add `Q` (start angle, 0.001°) only when non-zero; a
//! variable lead adds `K` (lead change, lead grid), `J` (the angle of that change, 0.001°, only
//! when it is not 360 000, one revolution) and `R` (the lead floor, lead grid, only when
//! non-zero). A pass header prints the radius depth.

use crate::alarm::Alarm;
use crate::trace::{Button, Event, Move, MoveKind, SpindleState, StopReason};
use crate::units::Grid;
use serde::{Deserialize, Serialize};
use std::fmt::Write as _;

/// A whole expansion: its events and the alarm that ended it, if any.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Trace {
    pub grid: Grid,
    pub events: Vec<Event>,
    pub alarm: Option<Alarm>,
}

/// Formats `count` units of `10^-decimals` as a decimal: `fixed(-28000, 3)` = `-28.000`.
pub fn fixed(count: i64, decimals: u32) -> String {
    let scale = 10u64.pow(decimals);
    let sign = if count < 0 { "-" } else { "" };
    let mag = count.unsigned_abs();
    if decimals == 0 {
        return format!("{sign}{mag}");
    }
    format!("{sign}{}.{:0width$}", mag / scale, mag % scale, width = decimals as usize)
}

impl Trace {
    /// Collects a streaming expansion (an iterator that ends after its first alarm).
    pub fn collect(grid: Grid, stream: impl IntoIterator<Item = Result<Event, Alarm>>) -> Trace {
        let mut events = Vec::new();
        for item in stream {
            match item {
                Ok(e) => events.push(e),
                Err(a) => return Trace { grid, events, alarm: Some(a) },
            }
        }
        Trace { grid, events, alarm: None }
    }

    /// The moves only.
    pub fn moves(&self) -> impl Iterator<Item = &Move> {
        self.events.iter().filter_map(|e| match e {
            Event::Move(m) => Some(m),
            _ => None,
        })
    }

    /// One line of canonical G-code for an event.
    pub fn event_line(grid: Grid, event: &Event) -> String {
        let d = grid.decimals();
        match event {
            Event::Pass(p) => {
                let depth = if p.diameter_depth % 2 == 0 {
                    fixed(p.diameter_depth / 2, d)
                } else {
                    fixed(p.diameter_depth * 5, d + 1)
                };
                format!("(PASS {} {} DEPTH {})", p.index, p.kind.name(), depth)
            }
            Event::Dwell(d) => format!("G04 P{}", d.ms),
            Event::Press(p) => {
                let button = match p.button {
                    Button::Hold => "HOLD",
                    Button::Reset => "RESET",
                };
                format!("(PRESS {button} AT X{} Z{})", fixed(p.x, d), fixed(p.z, d))
            }
            Event::Stop(s) => match s.reason {
                StopReason::FeedHold => "(STOP FEED HOLD)".to_string(),
                StopReason::SingleBlock => "(STOP SINGLE BLOCK)".to_string(),
            },
            Event::Resume(_) => "(CYCLE START)".to_string(),
            Event::Spindle(s) => match s.state {
                SpindleState::Forward => "M03".to_string(),
                SpindleState::Reverse => "M04".to_string(),
            },
            Event::Move(m) => {
                let (x, z) = (fixed(m.x, d), fixed(m.z, d));
                let f = fixed(m.feed, grid.lead_decimals());
                match m.kind {
                    MoveKind::Rapid => format!("G00 X{x} Z{z}"),
                    MoveKind::Feed => format!("G01 X{x} Z{z} F{f}"),
                    MoveKind::Thread => {
                        let mut line = format!("G32 X{x} Z{z} F{f}");
                        if m.angle != 0 {
                            let _ = write!(line, " Q{}", m.angle);
                        }
                        if m.lead_change != 0 {
                            let _ = write!(line, " K{}", fixed(m.lead_change, grid.lead_decimals()));
                            if m.lead_change_angle != 360_000 {
                                let _ = write!(line, " J{}", m.lead_change_angle);
                            }
                        }
                        if m.lead_floor != 0 {
                            let _ = write!(line, " R{}", fixed(m.lead_floor, grid.lead_decimals()));
                        }
                        if m.lead_steps {
                            line.push_str(" L1");
                        }
                        line
                    }
                    // The centre as absolute I (X, diameter) and K (Z), as a control reads them
                    // in absolute arc-centre mode (G90.1): the arc's start is not on its line.
                    MoveKind::ArcCw | MoveKind::ArcCcw => {
                        let g = if m.kind == MoveKind::ArcCw { "G02" } else { "G03" };
                        format!("{g} X{x} Z{z} I{} K{} F{f}", fixed(m.cx, d), fixed(m.cz, d))
                    }
                }
            }
        }
    }

    /// The alarm as a G-code comment line.
    pub fn alarm_line(alarm: &Alarm) -> String {
        let word = match alarm.word {
            Some(b) if b.is_ascii_graphic() && b != b'(' && b != b')' => format!(" WORD {}", b as char),
            Some(b) => format!(" WORD 0x{b:02X}"),
            None => String::new(),
        };
        format!("(ALARM {} LINE {}{} RULE {})", alarm.code.number(), alarm.line, word, alarm.rule)
    }

    /// Canonical expanded G-code, one line per event, a header first and the alarm last.
    pub fn to_gcode(&self) -> String {
        let mut out = format!(
            "(CYCLECHECK TRACE {} GRID {})\n",
            self.grid.unit_name(),
            fixed(1, self.grid.decimals())
        );
        for e in &self.events {
            out.push_str(&Trace::event_line(self.grid, e));
            out.push('\n');
        }
        if let Some(a) = &self.alarm {
            out.push_str(&Trace::alarm_line(a));
            out.push('\n');
        }
        out
    }

    /// The trace as pretty JSON.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).expect("a trace always serializes")
    }

    /// Reads a trace from its JSON form.
    pub fn from_json(text: &str) -> Result<Trace, serde_json::Error> {
        serde_json::from_str(text)
    }
}

#[cfg(test)]
mod tests;
