//! A third-party candidate's manifest, `candidates/NAME/candidate.toml`: what is tested (the
//! expander and its version), the adapter command, its setup, its declared deviations, its
//! campaigns, a note per divergence rule and the findings reported upstream.

use crate::certify::{self, deviations};
use cycle_vocab::Params;
use serde::Deserialize;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// The `[notes]` key of a divergence group without a reference rule (extra events, or an
/// alarm after a reference trace that ends cleanly).
pub const NO_RULE: &str = "none";

/// One manifest, read and checked.
#[derive(Clone, Debug)]
pub struct Manifest {
    /// The manifest file.
    pub path: PathBuf,
    pub name: String,
    /// What is tested, with its version: `ncplot7py 0.2.0 (PyPI, LGPL-3.0)`.
    pub expander: String,
    /// The `--candidate` command, run from the repository root.
    pub command: String,
    /// The one setup command (documented; never run by `third-party`).
    pub setup: String,
    /// The declared deviations file, if any, relative to the repository root.
    pub deviations: Option<String>,
    /// Whether `.ci/run` checks it.
    pub ci: bool,
    /// Per-case time limit, when not the default.
    pub timeout_ms: Option<u64>,
    /// Consecutive candidate failures that stop a campaign, when not the default (0: never).
    pub max_failures: Option<u32>,
    pub campaigns: Vec<Campaign>,
    /// One sentence per rule ID of a divergence group: which side follows the manual, and why.
    pub notes: BTreeMap<String, String>,
    pub findings: Vec<Finding>,
}

/// One campaign: as `certify --cycles --cases --seed`, under one dialect, with parameters.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Campaign {
    pub cycles: String,
    pub cases: u32,
    pub seed: u64,
    pub dialect: Option<String>,
    #[serde(default)]
    pub params: BTreeMap<String, i64>,
}

/// A hand-written upstream report (a crash, a hang, a NaN), printed verbatim.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Finding {
    pub title: String,
    pub program: String,
    pub output: String,
    pub version: Option<String>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    name: String,
    expander: String,
    command: String,
    setup: String,
    deviations: Option<String>,
    #[serde(default)]
    ci: bool,
    timeout_ms: Option<u64>,
    max_failures: Option<u32>,
    #[serde(default)]
    campaign: Vec<Campaign>,
    #[serde(default)]
    notes: BTreeMap<String, String>,
    #[serde(default)]
    finding: Vec<Finding>,
}

impl Campaign {
    /// The certify options of this campaign for `command` (deviations and limits apart).
    pub fn options(&self, command: &str) -> Result<certify::Options, String> {
        let dialect = match &self.dialect {
            None => None,
            Some(d) => Some(deviations::dialect(d).ok_or_else(|| format!("dialect {d:?}: one of gsk, fanuc, nc201"))?),
        };
        let mut params = Params::default();
        for (name, value) in &self.params {
            params.set(name, *value).map_err(|_| format!("params.{name}: unknown parameter (one of {})", Params::NAMES.join(", ")))?;
        }
        Ok(certify::Options {
            candidate: Some(command.to_string()),
            cycles: certify::Options::parse_cycles(&self.cycles)?,
            operator: certify::Options::parse_operator(&self.cycles),
            cases: self.cases,
            seed: self.seed,
            dialect,
            params,
            ..certify::Options::default()
        })
    }

    /// One line: `cycles g92,f76; 200 cases per family; seed 1; dialect fanuc; params 5143 = 60`.
    pub fn label(&self) -> String {
        let mut s = format!("cycles {}; {} cases per family; seed {}", self.cycles, self.cases, self.seed);
        if let Some(d) = &self.dialect {
            s.push_str(&format!("; dialect {d}"));
        }
        if !self.params.is_empty() {
            let p: Vec<String> = self.params.iter().map(|(n, v)| format!("{n} = {v}")).collect();
            s.push_str(&format!("; params {}", p.join(", ")));
        }
        s
    }
}

impl Manifest {
    /// Reads and checks `path`: TOML errors name the line, a bad campaign names its number.
    pub fn read(path: &Path) -> Result<Manifest, String> {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        let raw: Raw = toml::from_str(&text).map_err(|e| format!("{}: {}", path.display(), e.to_string().trim_end()))?;
        let m = Manifest {
            path: path.to_path_buf(),
            name: raw.name,
            expander: raw.expander,
            command: raw.command,
            setup: raw.setup,
            deviations: raw.deviations,
            ci: raw.ci,
            timeout_ms: raw.timeout_ms,
            max_failures: raw.max_failures,
            campaigns: raw.campaign,
            notes: raw.notes,
            findings: raw.finding,
        };
        if m.campaigns.is_empty() {
            return Err(format!("{}: no [[campaign]]", path.display()));
        }
        for (i, c) in m.campaigns.iter().enumerate() {
            c.options(&m.command).map_err(|e| format!("{}: campaign {}: {e}", path.display(), i + 1))?;
        }
        crate::candidate::split_command(&m.command).map_err(|e| format!("{}: command: {e}", path.display()))?;
        for rule in m.notes.keys() {
            if rule != NO_RULE && cycle_vocab::Rule::from_id(rule).is_none() {
                return Err(format!("{}: notes: {rule:?} is no rule ID of docs/RULES.md (nor {NO_RULE:?})", path.display()));
            }
        }
        Ok(m)
    }

    /// The declared deviations, read from `root` (the repository root).
    pub fn declarations(&self, root: &Path) -> Result<Vec<deviations::Deviation>, String> {
        match &self.deviations {
            None => Ok(Vec::new()),
            Some(f) => deviations::read(&root.join(f)),
        }
    }
}

/// Every `DIR/*/candidate.toml`, read, sorted by name; two manifests of one name are refused.
pub fn read_all(dir: &Path) -> Result<Vec<Manifest>, String> {
    let entries = std::fs::read_dir(dir).map_err(|e| format!("--candidates {}: {e}", dir.display()))?;
    let mut paths: Vec<PathBuf> = entries.filter_map(Result::ok).map(|e| e.path().join("candidate.toml")).filter(|p| p.is_file()).collect();
    paths.sort();
    let mut list = paths.iter().map(|p| Manifest::read(p)).collect::<Result<Vec<_>, _>>()?;
    list.sort_by(|a, b| a.name.cmp(&b.name));
    if let Some(w) = list.windows(2).find(|w| w[0].name == w[1].name) {
        return Err(format!("{} and {} are both named {:?}", w[0].path.display(), w[1].path.display(), w[0].name));
    }
    Ok(list)
}

#[cfg(test)]
mod tests;
