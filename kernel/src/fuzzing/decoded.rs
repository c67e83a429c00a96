//! Committed fuzz cases, stored decoded: what a case means is written out, so it does not
//! depend on the fuzz targets' byte encodings (`input.rs`, `cycle_harness::FuzzSource`).
//!
//! The seeds (`fuzz/seeds/<target>/`) and the regressions (`tests/fuzz_regressions/<target>/`)
//! of the program targets (`parse_blocks`, `diff_spec_impl`, `gcode_roundtrip`) are pairs:
//! `NAME.nc`, the program's exact bytes, and `NAME.json`, a [`ProgramCase`]:
//!
//! ```json
//! {
//!   "built": {"family": "multipass", "knobs": [3, 0, 17]},
//!   "config": {"dialect": "gsk", "grid": {"units": "metric", "increment": "isc"}, "params": {}, "start_x": 0, "start_z": 0},
//!   "expect": {"conform": true, "reference_ends": "clean"},
//!   "origin": {"target": "diff_spec_impl", "found_by": "cyclecheck fuzz", "date": "2026-11-23"}
//! }
//! ```
//!
//! `impl_invariants` cases are `NAME.json` alone, a [`HarnessCase`]: the harness, the values
//! its body drew, the expected outcome, the program it built (for the reader) and the origin.
//! Each top-level key is written on one line of its own.

use cycle_vocab::{Alarm, Config};
use serde::{Deserialize, Serialize};
use std::path::Path;

/// Where a committed case came from.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Origin {
    pub target: String,
    pub found_by: String,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub date: Option<String>,
}

/// How a trace (the reference's, or the lexer's) ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Ending {
    Clean,
    Alarm(Alarm),
}

impl std::fmt::Display for Ending {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Ending::Clean => write!(f, "clean"),
            Ending::Alarm(a) => write!(f, "with {a}"),
        }
    }
}

/// What the lexer makes of a program: its blocks, and how it ends.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Lexed {
    pub blocks: usize,
    pub ends: Ending,
}

/// The verdict a program case expects (each target sets its own fields).
#[derive(Clone, Debug, Default, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Expect {
    /// `diff_spec_impl`: the engines conform.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub conform: Option<bool>,
    /// `diff_spec_impl`: how the reference trace ends.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub reference_ends: Option<Ending>,
    /// `gcode_roundtrip`: both engines' G-code reads back as their motions.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub round_trips: Option<bool>,
    /// `parse_blocks`: the lexer's outcome.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub lexer: Option<Lexed>,
    /// `parse_blocks`: the lexer's invariants hold and both engines conform under both
    /// configurations.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub passes: Option<bool>,
}

/// The generator family and knobs that built a program (`crate::gen`): provenance, which the
/// seed encoder uses while they still build exactly this program and configuration.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Built {
    pub family: String,
    /// Trailing zero knobs left out (a missing knob is 0).
    pub knobs: Vec<u32>,
}

/// `NAME.json` of a program case (the program is `NAME.nc`).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProgramCase {
    /// Absent for `parse_blocks`, which runs under its own two configurations.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub config: Option<Config>,
    pub expect: Expect,
    pub origin: Origin,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub built: Option<Built>,
}

/// The outcome an `impl_invariants` case expects.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HarnessExpect {
    /// Every property held.
    Holds,
    /// An assumption discarded the case.
    Rejected,
}

/// `NAME.json` of an `impl_invariants` case.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HarnessCase {
    /// A name of `cycle_proofs::invariants::HARNESSES`.
    pub harness: String,
    /// The values the body drew, in order (past the end, each draw is its range's low end).
    pub draws: Vec<i128>,
    pub expect: HarnessExpect,
    /// The program the harness built from the draws, for the reader (not read back).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub program: Option<String>,
    pub origin: Origin,
}

/// JSON with each top-level key on a line of its own, its value compact.
pub fn to_json<T: Serialize>(value: &T) -> Result<String, String> {
    let value = serde_json::to_value(value).map_err(|e| e.to_string())?;
    let serde_json::Value::Object(map) = value else { return Err("not a JSON object".to_string()) };
    let lines: Vec<String> = map.iter().map(|(k, v)| format!("  {}: {v}", serde_json::Value::from(k.as_str()))).collect();
    Ok(format!("{{\n{}\n}}\n", lines.join(",\n")))
}

/// The files of a program case: `NAME.nc` and `NAME.json`.
pub fn program_files(name: &str, program: &[u8], case: &ProgramCase) -> Result<Vec<(String, Vec<u8>)>, String> {
    Ok(vec![(format!("{name}.nc"), program.to_vec()), (format!("{name}.json"), to_json(case)?.into_bytes())])
}

/// The files in `dir` (name, bytes), sorted by name; none when it does not exist.
pub fn read_dir(dir: &Path) -> Result<Vec<(String, Vec<u8>)>, String> {
    let Ok(entries) = std::fs::read_dir(dir) else { return Ok(Vec::new()) };
    let mut out = Vec::new();
    for e in entries {
        let path = e.map_err(|e| format!("{}: {e}", dir.display()))?.path();
        let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
        if path.is_file() && !name.starts_with('.') && name != "README.md" {
            out.push((name, std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?));
        }
    }
    out.sort();
    Ok(out)
}

/// Makes `dir` hold exactly `files` (other files are removed).
pub fn write_dir(dir: &Path, files: &[(String, Vec<u8>)]) -> Result<(), String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for (name, _) in read_dir(dir)? {
        if !files.iter().any(|(n, _)| *n == name) {
            std::fs::remove_file(dir.join(&name)).map_err(|e| format!("{name}: {e}"))?;
        }
    }
    for (name, bytes) in files {
        std::fs::write(dir.join(name), bytes).map_err(|e| format!("{}: {e}", dir.join(name).display()))?;
    }
    Ok(())
}

fn parse<T: for<'de> Deserialize<'de>>(name: &str, bytes: &[u8]) -> Result<T, String> {
    serde_json::from_slice(bytes).map_err(|e| format!("{name}: {e}"))
}

/// The program cases in `dir`: (name, program, case), by name. Every `NAME.json` needs its
/// `NAME.nc` and every `NAME.nc` its `NAME.json`.
pub fn load_programs(dir: &Path) -> Result<Vec<(String, Vec<u8>, ProgramCase)>, String> {
    let files = read_dir(dir)?;
    let find = |n: &str| files.iter().find(|(f, _)| f == n).map(|(_, b)| b);
    let mut out = Vec::new();
    for (file, bytes) in &files {
        let here = || format!("{}/{file}", dir.display());
        match (file.strip_suffix(".json"), file.strip_suffix(".nc")) {
            (Some(name), _) => {
                let program = find(&format!("{name}.nc")).ok_or_else(|| format!("{}: no {name}.nc beside it", here()))?;
                out.push((name.to_string(), program.clone(), parse(&here(), bytes)?));
            }
            (_, Some(name)) if find(&format!("{name}.json")).is_none() => return Err(format!("{}: no {name}.json beside it", here())),
            (_, Some(_)) => {}
            _ => return Err(format!("{}: neither NAME.nc nor NAME.json", here())),
        }
    }
    Ok(out)
}

/// The `impl_invariants` cases in `dir`: (name, case), by name.
pub fn load_harnesses(dir: &Path) -> Result<Vec<(String, HarnessCase)>, String> {
    let mut out = Vec::new();
    for (file, bytes) in read_dir(dir)? {
        let here = format!("{}/{file}", dir.display());
        let name = file.strip_suffix(".json").ok_or_else(|| format!("{here}: not NAME.json"))?;
        out.push((name.to_string(), parse(&here, &bytes)?));
    }
    Ok(out)
}

#[cfg(test)]
mod tests;
