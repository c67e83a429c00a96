//! What a bundle says it tested, and with what: the time (UTC), the build of `cyclecheck` —
//! its git commit and whether its sources differed from it, captured at build time by
//! `cyclecheck/build/main.rs` (`unknown` for a build without a git checkout) — the rustc that built it,
//! the host (name, OS, kernel, architecture), and the candidate's command with its resolved
//! executable and the SHA-256 of that file and of every other file its command line names.

use serde::{Deserialize, Serialize};
use sha2::{Digest, Sha256};
use std::path::{Path, PathBuf};

/// The build of this `cyclecheck`.
#[derive(Clone, Copy, Debug, Serialize)]
pub struct Build {
    pub version: &'static str,
    /// The git commit the sources were built from, or `unknown`.
    pub commit: &'static str,
    /// `true` when the sources compiled in differed from that commit, `false`, or `unknown`.
    pub dirty: &'static str,
    pub rustc: &'static str,
    pub profile: &'static str,
    pub target: &'static str,
}

/// This binary's build.
pub const BUILD: Build = Build {
    version: env!("CARGO_PKG_VERSION"),
    commit: env!("CYCLECHECK_GIT_COMMIT"),
    dirty: env!("CYCLECHECK_GIT_DIRTY"),
    rustc: env!("CYCLECHECK_RUSTC"),
    profile: env!("CYCLECHECK_PROFILE"),
    target: env!("CYCLECHECK_TARGET"),
};

/// `0.1.0 (commit 1a2b3c4…, dirty; rustc 1.95.0 …)`: for `--version` and the page.
pub const LONG_VERSION: &str = env!("CYCLECHECK_LONG_VERSION");

/// The machine a run ran on.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Host {
    pub name: String,
    /// `linux`, with the distribution's name when it says it.
    pub os: String,
    pub kernel: String,
    pub arch: String,
}

/// A file and its SHA-256 (lowercase hex), or why it could not be read.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Hashed {
    pub path: String,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub sha256: Option<String>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub error: Option<String>,
}

/// The candidate as run.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Candidate {
    pub command: Vec<String>,
    /// The executable the command's first word resolves to (through `PATH` when it has no
    /// `/`), with its hash.
    pub executable: Hashed,
    /// The other words of the command that name files (a script, a model, …), with their hashes.
    pub files: Vec<Hashed>,
}

/// The identity of a run.
#[derive(Clone, Debug, Serialize)]
pub struct Identity {
    /// When the run started, ISO 8601 UTC.
    pub started_utc: String,
    pub build: Build,
    pub host: Host,
    pub candidate: Option<Candidate>,
}

impl Identity {
    /// The identity of a run starting now, against the candidate command `argv` when external.
    pub fn capture(argv: Option<&[String]>) -> Identity {
        Identity { started_utc: utc(std::time::SystemTime::now()), build: BUILD, host: host(), candidate: argv.map(candidate) }
    }
}

/// A time as `YYYY-MM-DDTHH:MM:SSZ`.
pub fn utc(t: std::time::SystemTime) -> String {
    let secs = t.duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    let (days, rest) = ((secs / 86_400) as i64, secs % 86_400);
    let date = cycle_kernel::fuzzing::committed::civil_date(days);
    format!("{date}T{:02}:{:02}:{:02}Z", rest / 3600, rest / 60 % 60, rest % 60)
}

fn first_line(path: &str) -> Option<String> {
    let text = std::fs::read_to_string(path).ok()?;
    Some(text.lines().next()?.trim().to_string()).filter(|s| !s.is_empty())
}

fn host() -> Host {
    let name = first_line("/proc/sys/kernel/hostname")
        .or_else(|| first_line("/etc/hostname"))
        .or_else(|| std::env::var("HOSTNAME").ok())
        .unwrap_or_else(|| "unknown".to_string());
    let distribution = std::fs::read_to_string("/etc/os-release").ok().and_then(|t| {
        t.lines().find_map(|l| l.strip_prefix("PRETTY_NAME=").map(|v| v.trim_matches('"').to_string()))
    });
    let os = match distribution {
        Some(d) => format!("{} ({d})", std::env::consts::OS),
        None => std::env::consts::OS.to_string(),
    };
    let kernel = first_line("/proc/sys/kernel/osrelease").unwrap_or_else(|| "unknown".to_string());
    Host { name, os, kernel, arch: std::env::consts::ARCH.to_string() }
}

/// The SHA-256 of a file's bytes, lowercase hex.
pub fn sha256_file(path: &Path) -> std::io::Result<String> {
    let mut hasher = Sha256::new();
    std::io::copy(&mut std::fs::File::open(path)?, &mut hasher)?;
    Ok(hex(&hasher.finalize()))
}

/// The SHA-256 of bytes, lowercase hex.
pub fn sha256(bytes: &[u8]) -> String {
    hex(&Sha256::digest(bytes))
}

fn hex(bytes: &[u8]) -> String {
    bytes.iter().map(|b| format!("{b:02x}")).collect()
}

fn hashed(path: &Path) -> Hashed {
    let shown = path.display().to_string();
    match sha256_file(path) {
        Ok(h) => Hashed { path: shown, sha256: Some(h), error: None },
        Err(e) => Hashed { path: shown, sha256: None, error: Some(e.to_string()) },
    }
}

/// Where a command's first word is executed from: itself when it has a `/`, else the first
/// executable file of that name in `PATH` (as `execvp` looks).
pub fn resolve(program: &str) -> Option<PathBuf> {
    use std::os::unix::fs::PermissionsExt as _;
    let executable = |p: &Path| p.metadata().is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0);
    let found = if program.contains('/') {
        Some(PathBuf::from(program)).filter(|p| p.is_file())
    } else {
        let path = std::env::var_os("PATH")?;
        std::env::split_paths(&path).map(|d| d.join(program)).find(|p| executable(p))
    };
    found.map(|p| p.canonicalize().unwrap_or(p))
}

fn candidate(argv: &[String]) -> Candidate {
    let executable = match argv.first().and_then(|a| resolve(a)) {
        Some(p) => hashed(&p),
        None => Hashed { path: argv.first().cloned().unwrap_or_default(), sha256: None, error: Some("not found".to_string()) },
    };
    let files = argv
        .iter()
        .skip(1)
        .map(Path::new)
        .filter(|p| p.is_file())
        .map(|p| hashed(&p.canonicalize().unwrap_or_else(|_| p.to_path_buf())))
        .collect();
    Candidate { command: argv.to_vec(), executable, files }
}

#[cfg(test)]
mod tests;
