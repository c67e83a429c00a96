//! The evidence bundle on disk, written atomically: the whole bundle is staged in a hidden
//! sibling directory (`.NAME.staging-PID`) — created before the run, which checks `--out` up
//! front, and filled during it (`cases.jsonl`, one line per case as it is judged) — then every
//! file and directory fsynced and the directory renamed into place. A reader — or a run killed
//! half-way — sees the previous complete bundle or the new complete one, never a half-written
//! report; an interrupted or failed run removes its staging directory ([`crate::reaper`]).
//! Replacing a previous bundle takes two renames (old aside, new in), so for that instant `DIR`
//! is absent, never partial.
//!
//! An existing `DIR` is replaced only when it is empty or holds an `evidence.json` (a previous
//! bundle): `--out ~` must not delete a home directory.

use super::evidence;
use super::html;
use super::matrix;
use super::plot;
use super::{CaseRecord, CaseResult, Run};
use crate::reaper;
use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// The bundle's files but `cases.jsonl` (written during the run): relative path → contents.
pub fn files(run: &Run) -> Vec<(String, Vec<u8>)> {
    files_with_plots(run, &mut |r| {
        let (reference, candidate) = r.traces.as_ref()?;
        let (cand, div) = match &r.result {
            CaseResult::Diverge(d) | CaseResult::Deviate { divergence: d, .. } => (candidate.as_ref(), Some((d.index, d.rule))),
            _ => (None, None),
        };
        Some(plot::svg(&r.name, &r.config, reference, cand, div))
    })
}

/// [`files`], each corpus program's plot given by `svg_of` (a merge copies the shards' plots).
pub fn files_with_plots(run: &Run, svg_of: &mut dyn FnMut(&CaseRecord) -> Option<String>) -> Vec<(String, Vec<u8>)> {
    let rows = matrix::rows(Some(run));
    let mut plots = Vec::new();
    let mut files = Vec::new();
    for r in &run.corpus {
        let (Some(svg), super::Origin::Corpus { path }) = (svg_of(r), &r.origin) else { continue };
        files.push((format!("plots/{}.svg", r.name), svg.clone().into_bytes()));
        plots.push(html::PlotEntry { name: r.name.clone(), path: path.to_string(), result: html::result_line(r), svg });
    }
    let doc = evidence::document(run, &rows);
    let json = serde_json::to_string_pretty(&doc).expect("JSON values serialize");
    files.insert(0, ("evidence.json".to_string(), format!("{json}\n").into_bytes()));
    files.insert(1, ("index.html".to_string(), html::page(run, &rows, &plots).into_bytes()));
    files
}

fn sync_dir(dir: &Path) -> io::Result<()> {
    // Directories can be opened and fsynced on Unix; elsewhere this is best effort.
    match File::open(dir) {
        Ok(d) => d.sync_all().or(Ok(())),
        Err(_) => Ok(()),
    }
}

/// Whether `dir` may be replaced: empty, or a previous bundle.
fn replaceable(dir: &Path) -> io::Result<bool> {
    Ok(dir.join("evidence.json").is_file() || fs::read_dir(dir)?.next().is_none())
}

/// Refuses an `out` that exists and is no bundle (nor empty).
fn check_out(out: &Path) -> io::Result<()> {
    if out.exists() && (!out.is_dir() || !replaceable(out)?) {
        return Err(io::Error::new(
            io::ErrorKind::AlreadyExists,
            format!("{} exists and is not an evidence bundle (no evidence.json); choose another --out", out.display()),
        ));
    }
    Ok(())
}

/// A bundle being written: its staging directory, removed unless committed.
pub struct Staging {
    out: PathBuf,
    parent: PathBuf,
    name: String,
    dir: PathBuf,
    committed: bool,
}

impl Staging {
    /// Checks `out` (a directory name; absent, empty or a previous bundle) and creates the
    /// staging directory beside it, which shows the place is writable.
    pub fn create(out: &Path) -> io::Result<Staging> {
        let name = out
            .file_name()
            .filter(|n| *n != "." && *n != "..")
            .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, format!("{} names no directory", out.display())))?
            .to_string_lossy()
            .into_owned();
        let parent = match out.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        check_out(out)?;
        fs::create_dir_all(&parent)?;
        let dir = parent.join(format!(".{name}.staging-{}", std::process::id()));
        if dir.exists() {
            fs::remove_dir_all(&dir)?;
        }
        fs::create_dir(&dir)?;
        reaper::register_directory(dir.clone());
        Ok(Staging { out: out.to_path_buf(), parent, name, dir, committed: false })
    }

    /// A new file of the bundle, for writing.
    pub fn create_file(&self, rel: &str) -> io::Result<File> {
        let path = self.dir.join(rel);
        if let Some(dir) = path.parent() {
            fs::create_dir_all(dir)?;
        }
        File::create(path)
    }

    /// Writes a file of the bundle.
    pub fn write(&self, rel: &str, contents: &[u8]) -> io::Result<()> {
        self.create_file(rel)?.write_all(contents)
    }

    /// Fsyncs everything staged and renames it into place as `out`.
    pub fn commit(mut self) -> io::Result<()> {
        sync_tree(&self.dir)?;
        check_out(&self.out)?;
        if self.out.exists() {
            let old = self.parent.join(format!(".{}.old-{}", self.name, std::process::id()));
            fs::rename(&self.out, &old)?;
            fs::rename(&self.dir, &self.out)?;
            sync_dir(&self.parent)?;
            fs::remove_dir_all(&old)?;
        } else {
            fs::rename(&self.dir, &self.out)?;
        }
        self.committed = true;
        reaper::unregister_directory(&self.dir);
        sync_dir(&self.parent)
    }
}

impl Drop for Staging {
    fn drop(&mut self) {
        if !self.committed {
            let _ = fs::remove_dir_all(&self.dir);
            reaper::unregister_directory(&self.dir);
        }
    }
}

/// Fsyncs every file under `dir`, then the directories, deepest first.
fn sync_tree(dir: &Path) -> io::Result<()> {
    for entry in fs::read_dir(dir)? {
        let path = entry?.path();
        if path.is_dir() {
            sync_tree(&path)?;
        } else {
            File::open(&path)?.sync_all()?;
        }
    }
    sync_dir(dir)
}

/// Writes `files` as the bundle directory `out`, atomically (see the module documentation).
pub fn write(out: &Path, files: &[(String, Vec<u8>)]) -> io::Result<()> {
    let staging = Staging::create(out)?;
    for (rel, contents) in files {
        staging.write(rel, contents)?;
    }
    staging.commit()
}

#[cfg(test)]
mod tests;
