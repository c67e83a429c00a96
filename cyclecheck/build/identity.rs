//! The build's identity, for `cyclecheck --version` and the evidence bundle
//! (`src/certify/identity.rs`): the git commit of the sources, whether the sources compiled in
//! differ from it (`dirty`), the rustc, the profile and the target — `unknown` where there is
//! no git checkout (an installed crate) or no git.

use std::path::{Path, PathBuf};
use std::process::Command;

/// The paths compiled into the binary (the crates it links and the documents it includes): the
/// dirty flag looks at these only, and a change to any of them reruns the build script.
const SOURCES: &[&str] = &["vocab", "spec", "impl", "harness", "proofs", "kernel", "cyclecheck", "docs", "Cargo.toml", "Cargo.lock"];

fn git(root: &Path, args: &[&str]) -> Option<String> {
    // `--no-optional-locks`: `git status` must not rewrite the index this script watches.
    let out = Command::new("git").arg("--no-optional-locks").arg("-C").arg(root).args(args).output().ok()?;
    out.status.success().then(|| String::from_utf8_lossy(&out.stdout).trim().to_string())
}

/// Emits the identity as `CYCLECHECK_*` environment variables of the crate.
pub fn emit(root: &Path) {
    let commit = git(root, &["rev-parse", "HEAD"]).filter(|c| c.len() == 40 && c.bytes().all(|b| b.is_ascii_hexdigit()));
    let dirty = match &commit {
        Some(_) => {
            let mut args = vec!["status", "--porcelain", "--untracked-files=no", "--"];
            args.extend(SOURCES);
            git(root, &args).map(|s| (!s.is_empty()).to_string())
        }
        None => None,
    };
    if commit.is_some() {
        // What moves the commit or the index: HEAD, the branch's ref, packed refs, the index.
        let mut watched = vec!["HEAD".to_string(), "packed-refs".to_string(), "index".to_string()];
        watched.extend(git(root, &["rev-parse", "--symbolic-full-name", "HEAD"]).filter(|r| r.starts_with("refs/")));
        for name in watched {
            if let Some(p) = git(root, &["rev-parse", "--git-path", &name]) {
                let p = root.join(PathBuf::from(p));
                if p.exists() {
                    println!("cargo:rerun-if-changed={}", p.display());
                }
            }
        }
    }
    for s in SOURCES {
        let p = root.join(s);
        if p.exists() {
            println!("cargo:rerun-if-changed={}", p.display());
        }
    }
    let rustc = std::env::var("RUSTC").unwrap_or_else(|_| "rustc".to_string());
    let rustc = Command::new(rustc)
        .arg("--version")
        .output()
        .ok()
        .map(|o| String::from_utf8_lossy(&o.stdout).trim().to_string())
        .filter(|v| !v.is_empty())
        .unwrap_or_else(|| "unknown".to_string());
    let commit = commit.unwrap_or_else(|| "unknown".to_string());
    let dirty = dirty.unwrap_or_else(|| "unknown".to_string());
    let version = std::env::var("CARGO_PKG_VERSION").unwrap_or_default();
    let state = match dirty.as_str() {
        "true" => ", dirty",
        "false" => "",
        _ => ", dirty: unknown",
    };
    let short = if commit == "unknown" { commit.clone() } else { commit[..12].to_string() };
    println!("cargo:rustc-env=CYCLECHECK_GIT_COMMIT={commit}");
    println!("cargo:rustc-env=CYCLECHECK_GIT_DIRTY={dirty}");
    println!("cargo:rustc-env=CYCLECHECK_RUSTC={rustc}");
    println!("cargo:rustc-env=CYCLECHECK_PROFILE={}", std::env::var("PROFILE").unwrap_or_else(|_| "unknown".to_string()));
    println!("cargo:rustc-env=CYCLECHECK_TARGET={}", std::env::var("TARGET").unwrap_or_else(|_| "unknown".to_string()));
    println!("cargo:rustc-env=CYCLECHECK_LONG_VERSION={version} (commit {short}{state}; {rustc})");
}
