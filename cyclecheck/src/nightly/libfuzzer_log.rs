//! Reading libFuzzer's output into the figures of `cyclecheck fuzz`'s summary
//! ([`crate::nightly`]), in both of libFuzzer's modes:
//!
//! - one process (no `-fork`): status lines `#N\tpulse  cov: C ft: F corp: K/Sb lim: L exec/s: E
//!   rss: RMb`, then, with `-print_final_stats=1`, `stat::number_of_executed_units: N`,
//!   `stat::average_exec_per_sec: E`, `stat::new_units_added: U`, `stat::peak_rss_mb: R`, which
//!   take precedence;
//! - `-fork=N`: the parent prints `INFO: -fork=N: fuzzing in separate process(s)`, then one line
//!   per finished job, `#N: cov: C ft: F corp: K exec/s: E oom/timeout/crash: a/b/c time: Ts job:
//!   J dft_time: D` (N the executions of all jobs so far, E the last job's own rate), and ends
//!   with `INFO: fuzzed for T seconds, wrapping up soon` and `INFO: exiting: X time: Ts`. The jobs'
//!   own status lines and final stats stay in their logs, which libFuzzer deletes: it prints no
//!   RSS in this mode, except in the log of a job that crashed (`INFO: log from the inner
//!   process:`), whose lines must not be taken for the whole run's.

use serde::Serialize;

/// libFuzzer's figures for one run, as it printed them.
#[derive(Clone, Debug, Default, PartialEq, Serialize)]
pub struct Stats {
    /// Executions: all the jobs' in fork mode.
    pub executions: u64,
    /// One process: libFuzzer's average. Fork mode: executions ÷ seconds of the run (all jobs
    /// together; each job's line gives only its own rate).
    pub execs_per_sec: u64,
    /// Covered edges (`cov:`) and features (`ft:`) at the last status line.
    pub coverage_edges: u64,
    pub features: u64,
    /// New corpus inputs (`stat::new_units_added`; one process only).
    pub new_units: u64,
    /// Peak resident set size in MB: `stat::peak_rss_mb`, else the highest `rss: NMb` of the
    /// status lines; `None` when libFuzzer printed none (fork mode, no crashed job).
    pub peak_rss_mb: Option<u64>,
    /// Fork mode only: libFuzzer's `-fork=N` (0: one process), the jobs finished, and the jobs
    /// that ran out of memory, timed out or crashed (`oom/timeout/crash:`).
    pub fork: u64,
    pub jobs: u64,
    pub ooms: u64,
    pub timeouts: u64,
    pub crashes: u64,
}

/// The value after the word `key` (`cov:` → `350`), parsed.
fn field<T: std::str::FromStr>(line: &str, key: &str) -> Option<T> {
    let mut words = line.split_whitespace();
    words.by_ref().find(|w| *w == key)?;
    words.next()?.parse().ok()
}

/// The `rss: NMb` of a status line, in MB.
fn rss(line: &str) -> Option<u64> {
    let mut words = line.split_whitespace();
    words.by_ref().find(|w| *w == "rss:")?;
    words.next()?.strip_suffix("Mb")?.parse().ok()
}

/// Reads libFuzzer's output (see the module documentation).
pub fn parse_stats(log: &str) -> Stats {
    let mut s = Stats::default();
    let mut seconds = 0u64;
    // In fork mode, after "INFO: log from the inner process:" come one job's own lines.
    let mut inner = false;
    for line in log.lines() {
        if let Some(rest) = line.strip_prefix("INFO: -fork=") {
            s.fork = rest.split(':').next().and_then(|n| n.parse().ok()).unwrap_or(s.fork);
        }
        if line.starts_with("INFO: log from the inner process:") {
            inner = true;
        }
        if let Some(r) = rss(line) {
            s.peak_rss_mb = Some(s.peak_rss_mb.map_or(r, |p| p.max(r)));
        }
        let stat = |key: &str| line.strip_prefix(key).and_then(|v| v.trim().parse::<u64>().ok());
        if let Some(v) = stat("stat::peak_rss_mb:") {
            s.peak_rss_mb = Some(if s.fork > 0 { s.peak_rss_mb.map_or(v, |p| p.max(v)) } else { v });
        }
        if s.fork > 0 {
            // The parent's last line, after a crashed job's log too.
            if let Some(t) = line.strip_prefix("INFO: exiting: ").and_then(|r| field::<String>(r, "time:")) {
                seconds = t.trim_end_matches('s').parse().unwrap_or(seconds);
            }
            if inner {
                continue;
            }
            let Some(n) = line.strip_prefix('#').and_then(|r| r.split_whitespace().next()?.strip_suffix(':')?.parse().ok()) else {
                continue;
            };
            s.executions = n;
            s.coverage_edges = field(line, "cov:").unwrap_or(s.coverage_edges);
            s.features = field(line, "ft:").unwrap_or(s.features);
            s.jobs += 1;
            if let Some(t) = field::<String>(line, "time:") {
                seconds = t.trim_end_matches('s').parse().unwrap_or(seconds);
            }
            if let Some(c) = field::<String>(line, "oom/timeout/crash:") {
                let n: Vec<u64> = c.split('/').filter_map(|v| v.parse().ok()).collect();
                if let [o, t, c] = n[..] {
                    (s.ooms, s.timeouts, s.crashes) = (o, t, c);
                }
            }
            continue;
        }
        if let Some(rest) = line.strip_prefix('#') {
            if let Some(n) = rest.split_whitespace().next().and_then(|n| n.parse().ok()) {
                s.executions = n;
            }
            s.coverage_edges = field(line, "cov:").unwrap_or(s.coverage_edges);
            s.features = field(line, "ft:").unwrap_or(s.features);
            s.execs_per_sec = field(line, "exec/s:").unwrap_or(s.execs_per_sec);
        }
        if let Some(v) = stat("stat::number_of_executed_units:") {
            s.executions = v;
        }
        if let Some(v) = stat("stat::average_exec_per_sec:") {
            s.execs_per_sec = v;
        }
        if let Some(v) = stat("stat::new_units_added:") {
            s.new_units = v;
        }
    }
    if s.fork > 0 && seconds > 0 {
        s.execs_per_sec = s.executions / seconds;
    }
    s
}

#[cfg(test)]
mod tests;
