//! The declared readings a certification run judges its cases under ([`Plan`]): in process
//! (spec vs the production expander) each generated case draws its own, so both engines run
//! under every value; a candidate run judges every case under the readings the candidate
//! declares in its greeting, merged with `--reading` (the letter for the others).

use cycle_kernel::readings::{self, Counts, Declared, Pins};
use cycle_vocab::{Config, Readings};
use serde_json::{json, Value};

/// How a run's cases get their readings.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Plan {
    /// Drawn per generated case (`cycle_kernel::gen::drawn`), the corpus programs at the letter; the
    /// `--reading` pins fixed in every case.
    Drawn { pinned: Pins },
    /// Every case under `readings`: what the candidate `declared`, and the pins.
    Declared { readings: Readings, declared: Vec<(&'static str, &'static str)>, pinned: Pins },
}

impl Plan {
    /// The plan of an in-process run.
    pub fn drawn(pinned: Pins) -> Plan {
        Plan::Drawn { pinned }
    }

    /// The plan of a candidate run: its greeting's declaration (`None`: it could not be greeted,
    /// nothing declared) merged with the pins; a pin that contradicts the declaration is an
    /// error naming both.
    pub fn declared(declared: Option<Declared>, pinned: Pins) -> Result<Plan, String> {
        let d = declared.unwrap_or(Declared::NONE);
        let readings = readings::settle(&d, &pinned)?;
        Ok(Plan::Declared { readings, declared: d.pairs(), pinned })
    }

    /// Sets a case's readings: all of them for a candidate run, the pinned ones otherwise.
    pub fn apply(&self, config: &mut Config) {
        match self {
            Plan::Drawn { pinned } => config.readings = pinned.apply(config.readings),
            Plan::Declared { readings, .. } => config.readings = *readings,
        }
    }

    /// One line for a report: `readings: g94.k=start-minus-end, others the letter` or
    /// `readings: drawn per case`.
    pub fn line(&self) -> String {
        match self {
            Plan::Declared { readings, .. } => format!("readings: {}", readings::line(readings)),
            Plan::Drawn { pinned } if pinned.is_empty() => "readings: drawn per case".to_string(),
            Plan::Drawn { pinned } => {
                let pins: Vec<String> = pinned.0.iter().map(|(n, v)| format!("{n}={v}")).collect();
                format!("readings: drawn per case, but {} (--reading)", pins.join(", "))
            }
        }
    }

    /// The plan as `parameters.readings` of `evidence.json` (equal in the shards of one run).
    pub fn json(&self) -> Value {
        match self {
            Plan::Drawn { pinned } => json!({ "mode": "drawn", "pinned": pinned.map() }),
            Plan::Declared { readings, declared, pinned } => json!({
                "mode": "declared",
                "values": readings.pairs().iter().copied().collect::<std::collections::BTreeMap<_, _>>(),
                "declared_by_candidate": declared.iter().copied().collect::<std::collections::BTreeMap<_, _>>(),
                "pinned": pinned.map(),
            }),
        }
    }

    /// The top-level `readings` of `evidence.json`: the plan, its line, and the cases run under
    /// each value of each reading.
    pub fn evidence(&self, counts: &Counts) -> Value {
        let mut v = self.json();
        v["line"] = json!(self.line());
        v["cases"] = counts.json();
        v
    }

    /// The plan read back from `parameters.readings` (`merge`); a bundle without one ran
    /// before the readings: drawn nothing, the letter.
    pub fn from_json(v: &Value) -> Result<Plan, String> {
        let pairs = |key: &str| -> Result<Vec<String>, String> {
            Ok(v[key].as_object().into_iter().flatten().map(|(n, val)| format!("{n}={}", val.as_str().unwrap_or_default())).collect())
        };
        let pinned = Pins::parse(&pairs("pinned")?).map_err(|e| format!("parameters.readings.pinned: {e}"))?;
        match v["mode"].as_str() {
            None | Some("drawn") => Ok(Plan::Drawn { pinned }),
            Some("declared") => {
                let values = Pins::parse(&pairs("values")?).map_err(|e| format!("parameters.readings.values: {e}"))?;
                let declared = Pins::parse(&pairs("declared_by_candidate")?).map_err(|e| format!("parameters.readings.declared_by_candidate: {e}"))?;
                Ok(Plan::Declared { readings: values.apply(Readings::default()), declared: declared.0, pinned })
            }
            Some(m) => Err(format!("parameters.readings.mode: {m:?} is neither drawn nor declared")),
        }
    }
}

#[cfg(test)]
mod tests;
