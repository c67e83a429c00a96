use super::*;

#[test]
fn reads_one_process_output() {
    let log = "INFO: Seed: 1\n#2\tINITED cov: 100 ft: 120 corp: 3/10b exec/s: 0 rss: 30Mb\n\
            #4096\tpulse  cov: 350 ft: 900 corp: 40/2Kb lim: 43 exec/s: 2048 rss: 40Mb\n\
            #9000\tDONE   cov: 360 ft: 950 corp: 42/2Kb lim: 43 exec/s: 1500 rss: 41Mb\n\
            Done 9000 runs in 6 second(s)\nstat::number_of_executed_units: 9001\n\
            stat::average_exec_per_sec:     1500\nstat::new_units_added:          39\nstat::peak_rss_mb:              41\n";
    assert_eq!(
        parse_stats(log),
        Stats {
            executions: 9001,
            execs_per_sec: 1500,
            coverage_edges: 360,
            features: 950,
            new_units: 39,
            peak_rss_mb: Some(41),
            ..Stats::default()
        }
    );
    assert_eq!(parse_stats("nothing here"), Stats::default());
}

#[test]
fn status_lines_give_the_peak_rss_without_final_stats() {
    let log = "#2\tINITED cov: 100 ft: 120 corp: 3/10b exec/s: 0 rss: 30Mb\n\
            #512\tpulse  cov: 350 ft: 900 corp: 40/2Kb lim: 43 exec/s: 256 rss: 52Mb\n\
            #600\tNEW    cov: 351 ft: 901 corp: 41/2Kb lim: 43 exec/s: 250 rss: 50Mb L: 9/9 MS: 1 ChangeBit-\n";
    let s = parse_stats(log);
    assert_eq!((s.executions, s.coverage_edges, s.peak_rss_mb, s.fork), (600, 351, Some(52), 0));
}

/// A real `cyclecheck fuzz --budget 20 --targets diff_spec_impl --fork 2` log (2026-11-25;
/// addresses and some NEW_FUNC lines shortened).
const FORK_LOG: &str = "\
Dictionary: 60 entries
INFO: Running with entropic power schedule (0xFF, 100).
INFO: Seed: 1167950949
INFO: Loaded 1 modules   (43610 inline 8-bit counters): 43610 [0x55fa3daff680, 0x55fa3db0a0da), 
INFO: -fork=2: fuzzing in separate process(s)
INFO: -fork=2: 182 seed inputs, starting to fuzz in /tmp/libFuzzerTemp.FuzzWithFork31669.dir
#1466: cov: 8126 ft: 23001 corp: 182 exec/s: 733 oom/timeout/crash: 0/0/0 time: 2s job: 1 dft_time: 0
  NEW_FUNC: 0x55fa3d7e3cd0 in cycle_oracle::gen::multipass::any /work/wt/fork/oracle/src/gen/multipass.rs:34
#2741: cov: 8630 ft: 26237 corp: 364 exec/s: 425 oom/timeout/crash: 0/0/0 time: 3s job: 2 dft_time: 0
#4951: cov: 8940 ft: 28710 corp: 500 exec/s: 552 oom/timeout/crash: 0/0/0 time: 7s job: 3 dft_time: 0
#7417: cov: 9234 ft: 29886 corp: 659 exec/s: 493 oom/timeout/crash: 0/0/0 time: 9s job: 4 dft_time: 0
  NEW_FUNC: 0x55fa3d884000 in <cycle_spec::emit::Out>::thread /work/wt/fork/spec/src/emit.rs:94
#10695: cov: 9465 ft: 30829 corp: 798 exec/s: 546 oom/timeout/crash: 0/0/0 time: 14s job: 5 dft_time: 0
#13779: cov: 9692 ft: 31912 corp: 998 exec/s: 440 oom/timeout/crash: 0/0/0 time: 18s job: 6 dft_time: 0
#16635: cov: 9818 ft: 32697 corp: 1114 exec/s: 357 oom/timeout/crash: 0/0/0 time: 24s job: 7 dft_time: 0
INFO: fuzzed for 25 seconds, wrapping up soon
INFO: exiting: 0 time: 25s
";

#[test]
fn reads_fork_mode_output() {
    assert_eq!(
        parse_stats(FORK_LOG),
        Stats {
            executions: 16635,
            execs_per_sec: 16635 / 25,
            coverage_edges: 9818,
            features: 32697,
            fork: 2,
            jobs: 7,
            ..Stats::default()
        }
    );
}

#[test]
fn a_crashed_jobs_log_gives_its_rss_not_the_runs_figures() {
    // libFuzzer's layout when a job crashes (FuzzerFork.cpp): the parent's job line, then the
    // job's own log, then the exit line.
    let head = FORK_LOG.split("INFO: fuzzed for").next().unwrap_or_default();
    let log = format!(
            "{head}#17002: cov: 9820 ft: 32701 corp: 1115 exec/s: 380 oom/timeout/crash: 1/0/1 time: 26s job: 8 dft_time: 0\n\
            INFO: log from the inner process:\nINFO: Seed: 77\n\
            #1114\tINITED cov: 9818 ft: 32697 corp: 1114/301Kb exec/s: 0 rss: 512Mb\n\
            #1300\tNEW    cov: 9820 ft: 32701 corp: 1115/302Kb lim: 900 exec/s: 300 rss: 540Mb L: 80/80 MS: 1 ChangeBit-\n\
            thread '<unnamed>' panicked at fuzz_targets/diff_spec_impl.rs:9:5:\n==31700== ERROR: libFuzzer: deadly signal\n\
            stat::number_of_executed_units: 1301\nstat::average_exec_per_sec:     300\nstat::peak_rss_mb:              541\n\
            INFO: exiting: 77 time: 27s\n"
        );
    let s = parse_stats(&log);
    assert_eq!((s.executions, s.coverage_edges, s.features, s.jobs), (17002, 9820, 32701, 8));
    assert_eq!((s.ooms, s.timeouts, s.crashes, s.peak_rss_mb), (1, 0, 1, Some(541)));
    // The parent's "INFO: exiting: 77 time: 27s" comes after the inner log.
    assert_eq!(s.execs_per_sec, 17002 / 27);
}
