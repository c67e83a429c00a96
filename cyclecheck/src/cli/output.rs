//! A trace written as it is produced: canonical G-code line by line, or the JSON of
//! `Trace::to_json` event by event (the same text, byte for byte). A write error (a closed pipe:
//! `cyclecheck expand … | head`) stops the writing quietly.

use cycle_vocab::text::{fixed, Trace};
use cycle_vocab::{Alarm, Event, Grid};
use std::io::{BufWriter, Write};

/// The two printed forms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Form {
    Gcode,
    Json,
}

/// A trace being written to `out`.
pub struct TraceWriter<W: Write> {
    out: BufWriter<W>,
    form: Form,
    grid: Grid,
    events: usize,
    /// A write failed: nothing more is written.
    pub failed: bool,
}

/// `value` as pretty JSON, its lines after the first indented by `indent` spaces.
fn pretty<T: serde::Serialize>(value: &T, indent: usize) -> String {
    let text = serde_json::to_string_pretty(value).expect("trace parts serialize");
    text.replace('\n', &format!("\n{}", " ".repeat(indent)))
}

impl<W: Write> TraceWriter<W> {
    /// Starts the trace: the G-code header, or the JSON up to the events.
    pub fn start(out: W, form: Form, grid: Grid) -> TraceWriter<W> {
        let mut w = TraceWriter { out: BufWriter::with_capacity(1 << 16, out), form, grid, events: 0, failed: false };
        let head = match form {
            Form::Gcode => format!("(CYCLECHECK TRACE {} GRID {})\n", grid.unit_name(), fixed(1, grid.decimals())),
            Form::Json => format!("{{\n  \"grid\": {},\n  \"events\": [", pretty(&grid, 2)),
        };
        w.put(head.as_bytes());
        w
    }

    fn put(&mut self, bytes: &[u8]) {
        if !self.failed && self.out.write_all(bytes).is_err() {
            self.failed = true;
        }
    }

    /// One event; `false` once writing has failed.
    pub fn event(&mut self, e: &Event) -> bool {
        let text = match self.form {
            Form::Gcode => format!("{}\n", Trace::event_line(self.grid, e)),
            Form::Json => format!("{}\n    {}", if self.events == 0 { "" } else { "," }, pretty(e, 4)),
        };
        self.events += 1;
        self.put(text.as_bytes());
        !self.failed
    }

    /// Ends the trace with its alarm and flushes.
    pub fn finish(mut self, alarm: Option<&Alarm>) -> std::io::Result<()> {
        let tail = match (self.form, alarm) {
            (Form::Gcode, Some(a)) => format!("{}\n", Trace::alarm_line(a)),
            (Form::Gcode, None) => String::new(),
            (Form::Json, _) => {
                let close = if self.events == 0 { "]" } else { "\n  ]" };
                format!("{close},\n  \"alarm\": {}\n}}\n", pretty(&alarm, 2))
            }
        };
        self.put(tail.as_bytes());
        if self.failed {
            return Err(std::io::Error::other("write failed"));
        }
        self.out.flush()
    }
}

#[cfg(test)]
mod tests;
