//! Nothing a run starts outlives it: each candidate runs in a process group of its own
//! (`process_group(0)`), registered here while it lives, and killed whole — the candidate and
//! every process it started — when its case times out or fails, when the run ends, and when
//! `cyclecheck` is interrupted: [`install`] sets a SIGINT/SIGTERM handler that kills every
//! registered group, removes the registered staging directories (a half-written bundle) and
//! exits with status 130.

use nix::sys::signal::{killpg, Signal};
use nix::unistd::Pid;
use std::collections::BTreeSet;
use std::path::PathBuf;
use std::sync::Mutex;

/// The exit status after SIGINT or SIGTERM.
pub const INTERRUPTED: i32 = 130;

static GROUPS: Mutex<BTreeSet<u32>> = Mutex::new(BTreeSet::new());
static DIRECTORIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn lock<T>(m: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    m.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
}

/// A process group to kill on interruption (its leader's pid).
pub fn register_group(pgid: u32) {
    lock(&GROUPS).insert(pgid);
}

/// Kills every process of the group with SIGKILL and forgets it. A group already gone is fine.
pub fn kill_group(pgid: u32) {
    if let Ok(pid) = i32::try_from(pgid) {
        let _ = killpg(Pid::from_raw(pid), Signal::SIGKILL);
    }
    lock(&GROUPS).remove(&pgid);
}

/// A directory to remove on interruption (a bundle's staging directory).
pub fn register_directory(dir: PathBuf) {
    lock(&DIRECTORIES).push(dir);
}

pub fn unregister_directory(dir: &std::path::Path) {
    lock(&DIRECTORIES).retain(|d| d != dir);
}

/// Kills every registered group and removes every registered directory.
pub fn clean_up() {
    let groups: Vec<u32> = lock(&GROUPS).iter().copied().collect();
    for g in groups {
        kill_group(g);
    }
    for d in lock(&DIRECTORIES).drain(..) {
        let _ = std::fs::remove_dir_all(d);
    }
}

/// Installs the SIGINT/SIGTERM handler (once per process).
pub fn install() -> Result<(), String> {
    ctrlc::set_handler(|| {
        clean_up();
        eprintln!("cyclecheck: interrupted; candidates killed, no bundle written");
        std::process::exit(INTERRUPTED);
    })
    .map_err(|e| format!("cannot install the signal handler: {e}"))
}
