//! The evidence bundle on disk, written atomically: the whole bundle is staged in a hidden
//! sibling directory (`.NAME.staging-PID`), every file and directory fsynced, then renamed into
//! place. A reader — or a run killed half-way — sees the previous complete bundle or the new
//! complete one, never a half-written report. Replacing a previous bundle takes two renames (old
//! aside, new in), so for that instant `DIR` is absent, never partial.
//!
//! An existing `DIR` is replaced only when it is empty or holds an `evidence.json` (a previous
//! bundle): `--out ~` must not delete a home directory.

use super::evidence;
use super::html;
use super::matrix;
use super::plot;
use super::{CaseResult, Run};
use std::fs::{self, File};
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// The bundle's files: relative path → contents.
pub fn files(run: &Run) -> Vec<(String, Vec<u8>)> {
    let rows = matrix::rows(Some(run));
    let mut plots = Vec::new();
    let mut files = Vec::new();
    for r in &run.records {
        let (Some((reference, candidate)), super::Origin::Corpus { path }) = (&r.traces, &r.origin) else { continue };
        let (cand, div) = match &r.result {
            CaseResult::Diverge(d) => (candidate.as_ref(), Some((d.index, d.rule))),
            _ => (None, None),
        };
        let svg = plot::svg(&r.name, &r.config, reference, cand, div);
        files.push((format!("plots/{}.svg", r.name), svg.clone().into_bytes()));
        plots.push((r.name.clone(), path.to_string(), r.result.short(), svg));
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

/// Writes `files` as the bundle directory `out`, atomically (see the module documentation).
pub fn write(out: &Path, files: &[(String, Vec<u8>)]) -> io::Result<()> {
    let name = out
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, format!("{} names no directory", out.display())))?
        .to_string_lossy()
        .into_owned();
    let parent = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    };
    if out.exists() && (!out.is_dir() || !replaceable(out)?) {
        return Err(io::Error::new(
            io::ErrorKind::AlreadyExists,
            format!("{} exists and is not an evidence bundle (no evidence.json); choose another --out", out.display()),
        ));
    }
    fs::create_dir_all(&parent)?;
    let pid = std::process::id();
    let staging = parent.join(format!(".{name}.staging-{pid}"));
    let result = (|| {
        if staging.exists() {
            fs::remove_dir_all(&staging)?;
        }
        fs::create_dir(&staging)?;
        let mut dirs = vec![staging.clone()];
        for (rel, contents) in files {
            let path = staging.join(rel);
            if let Some(dir) = path.parent() {
                if !dir.exists() {
                    fs::create_dir_all(dir)?;
                    dirs.push(dir.to_path_buf());
                }
            }
            let mut f = File::create(&path)?;
            f.write_all(contents)?;
            f.sync_all()?;
        }
        for d in dirs.iter().rev() {
            sync_dir(d)?;
        }
        if out.exists() {
            let old = parent.join(format!(".{name}.old-{pid}"));
            fs::rename(out, &old)?;
            fs::rename(&staging, out)?;
            sync_dir(&parent)?;
            fs::remove_dir_all(&old)?;
        } else {
            fs::rename(&staging, out)?;
        }
        sync_dir(&parent)
    })();
    if result.is_err() && staging.exists() {
        let _ = fs::remove_dir_all(&staging);
    }
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tmp(name: &str) -> PathBuf {
        let d = std::env::temp_dir().join(format!("cyclecheck-bundle-{name}-{}", std::process::id()));
        let _ = fs::remove_dir_all(&d);
        fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn writes_then_replaces_a_bundle_leaving_no_staging() {
        let root = tmp("replace");
        let out = root.join("evidence");
        let one = vec![("evidence.json".to_string(), b"1".to_vec()), ("plots/a.svg".to_string(), b"<svg/>".to_vec())];
        write(&out, &one).unwrap();
        assert_eq!(fs::read(out.join("plots/a.svg")).unwrap(), b"<svg/>");
        let two = vec![("evidence.json".to_string(), b"2".to_vec())];
        write(&out, &two).unwrap();
        assert_eq!(fs::read(out.join("evidence.json")).unwrap(), b"2");
        assert!(!out.join("plots").exists(), "the old bundle is replaced whole");
        let leftovers: Vec<_> = fs::read_dir(&root).unwrap().map(|e| e.unwrap().file_name()).collect();
        assert_eq!(leftovers, vec![std::ffi::OsString::from("evidence")]);
        fs::remove_dir_all(&root).unwrap();
    }

    #[test]
    fn refuses_to_replace_a_directory_that_is_no_bundle() {
        let root = tmp("refuse");
        fs::write(root.join("precious.txt"), b"keep").unwrap();
        let e = write(&root, &[("evidence.json".to_string(), b"1".to_vec())]).unwrap_err();
        assert_eq!(e.kind(), io::ErrorKind::AlreadyExists);
        assert_eq!(fs::read(root.join("precious.txt")).unwrap(), b"keep");
        fs::remove_dir_all(&root).unwrap();
    }
}
