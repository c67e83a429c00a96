//! The peak resident memory of a fuzz run's target processes, sampled from `/proc` (Linux): in
//! fork mode libFuzzer prints no RSS (its jobs' logs are deleted), so `cyclecheck fuzz` watches
//! the processes itself. Every [`PERIOD`] it reads the high-water mark (`VmHWM`) of each process
//! under the run (`cargo fuzz run` and its descendants) whose name is the target's; a job that
//! starts and ends between two samples is missed. Elsewhere than Linux it finds nothing.

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;
use std::thread::JoinHandle;
use std::time::Duration;

/// Time between two samples.
pub const PERIOD: Duration = Duration::from_millis(200);

/// A sampling thread; [`Sampler::finish`] stops it.
pub struct Sampler {
    stop: Arc<AtomicBool>,
    handle: JoinHandle<Option<u64>>,
}

/// Starts sampling the processes named `name` (the kernel keeps 15 bytes of it) under `root`.
pub fn start(root: u32, name: &str) -> Sampler {
    let stop = Arc::new(AtomicBool::new(false));
    let comm: String = name.chars().take(15).collect();
    let flag = Arc::clone(&stop);
    let handle = std::thread::spawn(move || {
        let mut peak = None;
        while !flag.load(Ordering::Relaxed) {
            if let Some(kb) = sample(root, &comm) {
                peak = Some(peak.map_or(kb, |p: u64| p.max(kb)));
            }
            std::thread::sleep(PERIOD);
        }
        peak.map(|kb| kb / 1024)
    });
    Sampler { stop, handle }
}

impl Sampler {
    /// Stops sampling: the peak seen, in MB, or `None` when no such process was seen.
    pub fn finish(self) -> Option<u64> {
        self.stop.store(true, Ordering::Relaxed);
        self.handle.join().ok().flatten()
    }
}

/// `pid (comm) state ppid …` → (comm, ppid); the name may hold spaces and parentheses.
fn parse_stat(stat: &str) -> Option<(&str, u32)> {
    let open = stat.find('(')?;
    let close = stat.rfind(')')?;
    let ppid = stat.get(close + 1..)?.split_whitespace().nth(1)?.parse().ok()?;
    Some((stat.get(open + 1..close)?, ppid))
}

/// The largest `VmHWM` (kB) of the processes named `comm` under `root`, now.
fn sample(root: u32, comm: &str) -> Option<u64> {
    let mut parent: HashMap<u32, (String, u32)> = HashMap::new();
    for entry in std::fs::read_dir("/proc").ok()?.flatten() {
        let Some(pid) = entry.file_name().to_str().and_then(|p| p.parse::<u32>().ok()) else { continue };
        let Ok(stat) = std::fs::read_to_string(entry.path().join("stat")) else { continue };
        if let Some((name, ppid)) = parse_stat(&stat) {
            parent.insert(pid, (name.to_string(), ppid));
        }
    }
    let under_root = |mut pid: u32| {
        for _ in 0..64 {
            if pid == root {
                return true;
            }
            match parent.get(&pid) {
                Some(&(_, ppid)) if ppid != 0 => pid = ppid,
                _ => return false,
            }
        }
        false
    };
    parent
        .iter()
        .filter(|(&pid, (name, _))| name == comm && under_root(pid))
        .filter_map(|(pid, _)| {
            let status = std::fs::read_to_string(format!("/proc/{pid}/status")).ok()?;
            let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
            line.split_whitespace().nth(1)?.parse().ok()
        })
        .max()
}

#[cfg(test)]
mod tests;
