//! The declared readings on the harness's side (`cycle_vocab::Readings`; docs/INTERPRETATION.md,
//! "Declared readings"): `--reading NAME=VALUE` ([`Pins`]), the readings a candidate run is
//! judged against (its greeting's declaration merged with the flags, [`settle`]), the readings a
//! generated case draws ([`from_bits`]: one bit per reading, 0 the letter) and the per-value
//! counts of a run ([`Counts`]).

use cycle_vocab::readings::{G162Lead, G73C, G75Relief, G94K, G96Rapid, ThreadZRef};
use cycle_vocab::Readings;
use std::collections::BTreeMap;

/// The manuals' letter throughout (`Readings::default()`, as a constant).
pub const LETTER: Readings = Readings {
    g94_k: G94K::EndMinusStart,
    g73_c: G73C::Visit,
    g75_relief: G75Relief::MinusZ,
    g162_lead: G162Lead::Steps,
    thread_zref: ThreadZRef::Start,
    g96_rapid: G96Rapid::Refuse,
};

/// Readings named on the command line (`--reading NAME=VALUE`, repeatable), in order; each name
/// at most once.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Pins(pub Vec<(&'static str, &'static str)>);

/// The legal names, for messages: `g94.k, g73.c, …`.
pub fn names() -> String {
    Readings::NAMES.join(", ")
}

/// The legal values of `name`, for messages: `end-minus-start (the letter), start-minus-end`.
pub fn values_of(name: &str) -> String {
    let values = Readings::values(name).unwrap_or(&[]);
    values.iter().enumerate().map(|(i, v)| if i == 0 { format!("{v} (the letter)") } else { v.to_string() }).collect::<Vec<_>>().join(", ")
}

/// The interned name and value of a reading, if legal.
fn intern(name: &str, value: &str) -> Option<(&'static str, &'static str)> {
    let name = *Readings::NAMES.iter().find(|n| **n == name)?;
    let value = *Readings::values(name)?.iter().find(|v| **v == value)?;
    Some((name, value))
}

impl Pins {
    /// Reads `NAME=VALUE` flags; an unknown name or value is refused, naming it and listing the
    /// legal ones.
    pub fn parse<S: AsRef<str>>(flags: &[S]) -> Result<Pins, String> {
        let mut pins = Vec::new();
        for flag in flags {
            let flag = flag.as_ref();
            let Some((name, value)) = flag.split_once('=') else {
                return Err(format!("--reading takes NAME=VALUE, not {flag:?} (names: {})", names()));
            };
            let (name, value) = (name.trim(), value.trim());
            if Readings::values(name).is_none() {
                return Err(format!("--reading {name}: no such reading (one of {})", names()));
            }
            let Some(pin) = intern(name, value) else {
                return Err(format!("--reading {name}={value}: {name} is one of {}", values_of(name)));
            };
            if pins.iter().any(|(n, _)| *n == pin.0) {
                return Err(format!("--reading {name} given twice"));
            }
            pins.push(pin);
        }
        Ok(Pins(pins))
    }

    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// `readings` with the pinned ones set.
    pub fn apply(&self, mut readings: Readings) -> Readings {
        for (name, value) in &self.0 {
            readings.set(name, value).expect("pins are legal readings");
        }
        readings
    }

    /// The pins as a JSON-style map, for a bundle.
    pub fn map(&self) -> BTreeMap<&'static str, &'static str> {
        self.0.iter().copied().collect()
    }
}

/// A candidate's declaration in its greeting answer: `{"g94.k": "start-minus-end", …}`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Declared {
    /// The readings, the undeclared ones at the letter.
    pub readings: Readings,
    /// Bit i set: the candidate declared `Readings::NAMES[i]`.
    pub names: u8,
}

impl Declared {
    /// Nothing declared: the letter throughout.
    pub const NONE: Declared = Declared { readings: LETTER, names: 0 };

    /// Reads the greeting's `"readings"` value (absent: nothing declared).
    pub fn parse(value: Option<&serde_json::Value>) -> Result<Declared, String> {
        let mut d = Declared::default();
        let Some(value) = value else { return Ok(d) };
        let Some(map) = value.as_object() else {
            return Err(format!("\"readings\" is an object of reading names and values ({})", names()));
        };
        for (name, value) in map {
            let Some(i) = Readings::NAMES.iter().position(|n| n == name) else {
                return Err(format!("\"readings\" names {name:?}: no such reading (one of {})", names()));
            };
            let Some(v) = value.as_str().and_then(|v| intern(name, v)) else {
                return Err(format!("\"readings\": {name} is one of {}, not {value}", values_of(name)));
            };
            d.readings.set(v.0, v.1).expect("interned");
            d.names |= 1 << i;
        }
        Ok(d)
    }

    /// The declared readings as (name, value), in order.
    pub fn pairs(&self) -> Vec<(&'static str, &'static str)> {
        let all = self.readings.pairs();
        (0..Readings::NAMES.len()).filter(|i| self.names & (1 << i) != 0).map(|i| all[i]).collect()
    }
}

/// The readings a candidate run is judged against: the greeting's declaration, and the flags for
/// the readings it leaves undeclared (the others at the letter). A flag that contradicts the
/// declaration is an error naming both.
pub fn settle(declared: &Declared, pins: &Pins) -> Result<Readings, String> {
    let mut readings = declared.readings;
    for (name, value) in &pins.0 {
        let i = Readings::NAMES.iter().position(|n| n == name).expect("pins are legal");
        if declared.names & (1 << i) != 0 && declared.readings.get(name) != Some(value) {
            let said = declared.readings.get(name).unwrap_or_default();
            return Err(format!("--reading {name}={value} contradicts the candidate's greeting, which declares {name}={said}"));
        }
        readings.set(name, value).expect("pins are legal");
    }
    Ok(readings)
}

/// The readings of the bits `bits`: bit i chooses reading i's second value (0: the letter).
pub fn from_bits(bits: u8) -> Readings {
    let mut r = Readings::default();
    for (i, name) in Readings::NAMES.iter().enumerate() {
        let values = Readings::values(name).expect("a reading has values");
        let v = values[usize::from(bits >> i & 1) % values.len()];
        r.set(name, v).expect("a legal value");
    }
    r
}

/// The bits of [`from_bits`] for `readings`.
pub fn bits(readings: &Readings) -> u8 {
    let mut b = 0;
    for (i, (name, value)) in readings.pairs().iter().enumerate() {
        let values = Readings::values(name).expect("a reading has values");
        if values.iter().position(|v| v == value) == Some(1) {
            b |= 1 << i;
        }
    }
    b
}

/// One line naming readings: `g94.k=start-minus-end, others the letter`, or `the letter
/// throughout`.
pub fn line(readings: &Readings) -> String {
    let letter = Readings::default();
    let changed: Vec<String> = readings.pairs().iter().zip(letter.pairs()).filter(|(a, b)| a != &b).map(|((n, v), _)| format!("{n}={v}")).collect();
    match changed.len() {
        0 => "the letter throughout".to_string(),
        n if n == Readings::NAMES.len() => changed.join(", "),
        _ => format!("{}, others the letter", changed.join(", ")),
    }
}

/// Cases per reading and value: `{"g94.k": {"end-minus-start": 120, "start-minus-end": 98}, …}`.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Counts(pub BTreeMap<String, BTreeMap<String, usize>>);

impl Counts {
    /// Counts one case run under `readings`.
    pub fn add(&mut self, readings: &Readings) {
        for (name, value) in readings.pairs() {
            *self.0.entry(name.to_string()).or_default().entry(value.to_string()).or_default() += 1;
        }
    }

    /// Adds counts read back from a bundle (`merge`).
    pub fn add_json(&mut self, value: &serde_json::Value) {
        for (name, values) in value.as_object().into_iter().flatten() {
            for (v, n) in values.as_object().into_iter().flatten() {
                *self.0.entry(name.clone()).or_default().entry(v.clone()).or_default() += n.as_u64().unwrap_or(0) as usize;
            }
        }
    }

    /// Cases run with reading `name` at `value`.
    pub fn get(&self, name: &str, value: &str) -> usize {
        self.0.get(name).and_then(|m| m.get(value)).copied().unwrap_or(0)
    }

    pub fn json(&self) -> serde_json::Value {
        serde_json::to_value(&self.0).unwrap_or(serde_json::Value::Null)
    }

    /// Per reading, in order: `g94.k: end-minus-start 120, start-minus-end 98`.
    pub fn lines(&self) -> Vec<String> {
        Readings::NAMES
            .iter()
            .map(|name| {
                let values = Readings::values(name).unwrap_or(&[]);
                let counts: Vec<String> = values.iter().map(|v| format!("{v} {}", self.get(name, v))).collect();
                format!("{name}: {}", counts.join(", "))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests;
