//! `cyclecheck third-party`: the report on third-party expanders from one command. Each
//! `candidates/*/candidate.toml` ([`manifest`]) names an expander nobody here wrote, the adapter
//! that runs it behind the candidate protocol, its declared deviations and its campaigns; each
//! campaign runs through the certify machinery in-process ([`crate::certify::run_engine`]), and
//! one Markdown document ([`report`]) says, per candidate and family, what conforms, deviates as
//! declared, diverges, is refused or fails — with each divergence group minimized and the
//! manifest's note on which side follows the manual. `--check` ([`check`]) regenerates it and
//! compares its deterministic content with the committed file.

pub mod check;
pub mod manifest;
pub mod reduce;
pub mod report;

use crate::candidate::{CandidateEngine, Limits};
use crate::certify::{self, deviations::Deviation, Run};
use cycle_kernel::engine::FailureKind;
use manifest::{Campaign, Manifest};
use std::path::{Path, PathBuf};

/// Where the manifests are by default.
pub const DEFAULT_CANDIDATES: &str = "candidates";
/// Where the report goes by default.
pub const DEFAULT_OUT: &str = "docs/THIRD-PARTY.md";

/// What `third-party` was asked.
#[derive(Clone, Debug)]
pub struct Request {
    pub candidates: PathBuf,
    /// Only these candidates (`--only`, repeatable); all when empty.
    pub only: Vec<String>,
    /// Only the candidates whose manifest says `ci = true` (`--ci`).
    pub ci: bool,
    pub out: PathBuf,
    /// Compare with `out` instead of writing it.
    pub check: bool,
    /// List a candidate whose command cannot be started as not installed here.
    pub skip_missing: bool,
    /// The repository root: commands and deviation files are relative to it.
    pub root: PathBuf,
}

/// One campaign's run and the minimized reproducers of its failures.
pub struct CampaignRun {
    pub campaign: Campaign,
    pub run: Run,
    pub reproducers: Vec<reduce::Reproducer>,
}

/// What happened to one candidate.
pub enum Outcome {
    /// Its command could not be started, or it exited before answering the greeting (with
    /// `--skip-missing`): why.
    NotInstalled(String),
    Ran(Vec<CampaignRun>),
}

/// One candidate's part of the report.
pub struct CandidateReport {
    pub manifest: Manifest,
    pub declarations: Vec<Deviation>,
    pub outcome: Outcome,
}

impl CandidateReport {
    /// The declarations no case of any campaign matched.
    pub fn unused(&self) -> Vec<usize> {
        let Outcome::Ran(runs) = &self.outcome else { return Vec::new() };
        (0..self.declarations.len()).filter(|k| runs.iter().all(|c| !c.run.tally.by_declaration.contains_key(k))).collect()
    }
}

/// The manifests the request selects, read and checked (bad ones: an error for exit 2).
pub fn selected(request: &Request) -> Result<Vec<Manifest>, String> {
    let all = manifest::read_all(&request.candidates)?;
    if let Some(missing) = request.only.iter().find(|n| !all.iter().any(|m| &m.name == *n)) {
        let names: Vec<&str> = all.iter().map(|m| m.name.as_str()).collect();
        return Err(format!("--only {missing}: no such candidate in {} ({})", request.candidates.display(), names.join(", ")));
    }
    Ok(all.into_iter().filter(|m| request.only.is_empty() || request.only.contains(&m.name)).filter(|m| !request.ci || m.ci).collect())
}

/// Runs every campaign of `m`; `progress` hears a line per campaign.
pub fn run_candidate(m: &Manifest, request: &Request, progress: &mut dyn FnMut(&str)) -> Result<CandidateReport, String> {
    let declarations = m.declarations(&request.root).map_err(|e| format!("{}: deviations: {e}", m.path.display()))?;
    let limits = Limits { timeout: m.timeout_ms.map_or(Limits::DEFAULT_TIMEOUT, std::time::Duration::from_millis), ..Limits::default() };
    if request.skip_missing {
        let probe = CandidateEngine::new(&m.command, limits)?;
        if let Err(f) = probe.greet() {
            if matches!(f.kind, FailureKind::Spawn | FailureKind::Crash) {
                return Ok(CandidateReport { manifest: m.clone(), declarations, outcome: Outcome::NotInstalled(f.to_string()) });
            }
        }
    }
    let mut runs = Vec::new();
    for (i, campaign) in m.campaigns.iter().enumerate() {
        progress(&format!("third-party: {} campaign {} ({})", m.name, i + 1, campaign.label()));
        let mut options = certify::Options { deviations: declarations.clone(), limits, ..campaign.options(&m.command)? };
        options.max_failures = m.max_failures.unwrap_or(options.max_failures);
        let engine = CandidateEngine::new(&m.command, limits)?;
        let argv = Some(engine.argv().to_vec());
        let plan = certify::readings_plan::Plan::declared(engine.declared().ok(), options.readings.clone())?;
        let mut run = certify::run_engine(&options, &plan, &engine, argv, &mut std::io::sink(), &mut |_| {}).map_err(|e| e.0)?;
        run.candidate_starts = engine.starts();
        run.level = engine.weakest_level();
        let reproducers = reduce::reproducers(&engine, &run);
        runs.push(CampaignRun { campaign: campaign.clone(), run, reproducers });
    }
    Ok(CandidateReport { manifest: m.clone(), declarations, outcome: Outcome::Ran(runs) })
}

/// The `third-party` command: runs the selected candidates, then writes `out` — or, with
/// `check`, compares with it. `Ok(true)`: written, or the check found no difference.
pub fn command(request: &Request, progress: &mut dyn FnMut(&str)) -> Result<(bool, String), String> {
    let all = manifest::read_all(&request.candidates)?;
    let manifests = selected(request)?;
    let reports = manifests.iter().map(|m| run_candidate(m, request, progress)).collect::<Result<Vec<_>, _>>()?;
    let previous = std::fs::read_to_string(&request.out).ok();
    let document = report::document(&all, &reports, previous.as_deref());
    let summary = report::summary(&reports);
    if request.check {
        let Some(committed) = previous else {
            return Ok((false, format!("{summary}--check: {} cannot be read: nothing to compare with\n", request.out.display())));
        };
        return Ok(match check::compare(&committed, &document, &reports) {
            Ok(()) => (true, format!("{summary}--check: {} is up to date\n", request.out.display())),
            Err(diff) => (false, format!("{summary}--check: {} differs from this run:\n{diff}", request.out.display())),
        });
    }
    write(&request.out, &document).map_err(|e| format!("cannot write {}: {e}", request.out.display()))?;
    Ok((true, format!("{summary}wrote {}\n", request.out.display())))
}

fn write(path: &Path, text: &str) -> std::io::Result<()> {
    if let Some(dir) = path.parent().filter(|d| !d.as_os_str().is_empty()) {
        std::fs::create_dir_all(dir)?;
    }
    let staged = path.with_extension("md.tmp");
    std::fs::write(&staged, text)?;
    std::fs::rename(&staged, path)
}
