//! Hints for alarms whose likely cause is the configuration rather than the program: a G20/G21
//! against the configured units (COM.UNITS), a G code of another dialect (PRJ.DIALECT,
//! PRJ.SUPPORTED) — `cyclecheck expand` and `diff` print them under the alarm. A hint reads the
//! G codes of the alarm's block from the case's [`Sighting`] (the judge's one read of the
//! program), never the program.

use crate::registry::{Sighting, FAMILIES};
use cycle_vocab::{Alarm, Config, Dialect, Rule, Units};

const DIALECTS: [(Dialect, &str); 3] = [(Dialect::Gsk, "gsk"), (Dialect::Fanuc, "fanuc"), (Dialect::Nc201, "nc201")];

/// The dialects other than the configured one under which G code `g` means something: a cycle
/// family's code, or G90/G91 (absolute/incremental) under `nc201`.
fn dialects_of(g: u64, config: &Config) -> Vec<&'static str> {
    DIALECTS
        .iter()
        .filter(|(d, _)| *d != config.dialect)
        .filter(|(d, _)| FAMILIES.iter().any(|f| f.codes.contains(&g) && f.dialects.contains(d)) || (*d == Dialect::Nc201 && matches!(g, 90 | 91)))
        .map(|(_, name)| *name)
        .collect()
}

/// A hint for `alarm`, when its likely cause is the configuration; `sighting` is the program
/// as read against that alarm ([`crate::registry::sight`]).
pub fn hint(config: &Config, alarm: &Alarm, sighting: &Sighting) -> Option<String> {
    if alarm.word != Some(b'G') {
        return None;
    }
    let codes = &sighting.alarm_codes;
    match alarm.rule {
        Rule::ComUnits => {
            let (g, units) = match config.grid.units {
                Units::Metric if codes.contains(&20) => ("G20 selects inch", "inch"),
                Units::Inch if codes.contains(&21) => ("G21 selects millimetres", "metric"),
                _ => return None,
            };
            Some(format!("hint: {g} and a trace's units are fixed by the configuration: run with --units {units}"))
        }
        Rule::PrjDialect | Rule::PrjSupported => codes.iter().find_map(|&g| {
            let others = dialects_of(g, config);
            let first = others.first()?;
            Some(format!("hint: G{g} is a code of the {} dialect: run with --dialect {first}", others.join(" or ")))
        }),
        _ => None,
    }
}

#[cfg(test)]
mod tests;
