//! `cyclecheck`: expand a program with either engine, diff the spec against the production
//! expander or a candidate on programs, run the built-in corpus through both, write the
//! certification evidence bundle (`certify`), gate a merge, fuzz, serve the production expander
//! as a candidate, measure the harness's rates. See the README ("The CLI") and `cyclecheck help`.
//!
//! Exit codes: 0 success / the engines conform; 1 the engines diverge or the candidate fails
//! (`diff`, `corpus`, `certify`, `bench-harness`), a gate step or a fuzz campaign fails; 2 bad input — and for
//! `expand`, a program that ends in an alarm (named on stderr); 130 interrupted.

mod args;
mod certify_cmd;
mod config;
mod corpus_cmd;
mod expand;
mod output;

use args::{Cli, Command};
use clap::Parser as _;
use cyclecheck::{bench_harness as bench, candidate, certify, gate, nightly};
use std::process::ExitCode;

/// Bad input: a message for stderr, exit 2.
pub struct Bad(pub String);

pub fn bad<T>(msg: impl Into<String>) -> Result<T, Bad> {
    Err(Bad(msg.into()))
}

pub fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => {
            // --help and --version print to stdout and exit 0; a usage error exits 2.
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() { 2 } else { 0 });
        }
    };
    if let Err(e) = cyclecheck::reaper::install() {
        eprintln!("cyclecheck: {e}");
    }
    let result = match cli.command {
        Command::Expand(a) => expand::expand(&a),
        Command::Diff(a) => expand::diff(&a),
        Command::Corpus(a) => corpus_cmd::run(&a),
        Command::Certify(a) => certify_cmd::run(&a),
        Command::Merge(a) => certify_cmd::merge(&a),
        Command::ThirdParty(a) => certify_cmd::third_party(&a),
        Command::Gate(a) => {
            let o = gate::Options {
                cases: a.cases,
                seed: a.seed,
                cargo_test: !a.no_cargo_test,
                test_cases: a.test_cases,
                proof_cases: a.proof_cases,
                shard: a.shard,
                ..gate::Options::default()
            };
            gate::command(&o).map_err(Bad)
        }
        Command::Fuzz(a) => fuzz_request(a).and_then(|r| nightly::command(r).map_err(Bad)),
        Command::Serve => candidate::serve(std::io::stdin().lock(), std::io::stdout().lock()).map(|()| 0).map_err(|e| Bad(format!("serve: {e}"))),
        Command::BenchHarness(a) => bench_harness(&a),
    };
    cyclecheck::reaper::clean_up();
    match result {
        Ok(code) => ExitCode::from(code),
        Err(Bad(msg)) => {
            eprintln!("cyclecheck: {msg}");
            ExitCode::from(2)
        }
    }
}

fn fuzz_request(a: args::FuzzArgs) -> Result<nightly::Request, Bad> {
    if a.write_seeds {
        return Ok(nightly::Request::WriteSeeds);
    }
    if let Some(d) = a.decode {
        let Some(target) = cycle_kernel::fuzzing::Target::by_name(&d[0]) else {
            return bad(format!("--decode: no target {:?} (one of {})", d[0], nightly::target_names()));
        };
        return Ok(nightly::Request::Decode { target, file: d[1].clone().into(), name: d.get(2).cloned() });
    }
    let targets = a.targets.map_or_else(|| cycle_kernel::fuzzing::Target::ALL.to_vec(), |t| t.0);
    Ok(nightly::Request::Campaign {
        budget: a.budget,
        targets,
        out: a.out,
        features: a.features,
        fork: a.fork,
        rss_limit_mb: a.rss_limit_mb,
    })
}

/// `bench-harness`: the three rates and their ratios, as a Markdown table on stdout.
fn bench_harness(a: &args::BenchArgs) -> Result<u8, Bad> {
    let exe = std::env::current_exe().map_err(|e| Bad(format!("cannot find this executable: {e}")))?;
    let default_binary = std::path::PathBuf::from("fuzz/target/x86_64-unknown-linux-gnu/release/diff_spec_impl");
    let fuzz_binary = a.fuzz_binary.clone().or_else(|| default_binary.is_file().then_some(default_binary));
    let existing = |p: &str| Some(std::path::PathBuf::from(p)).filter(|p| p.exists());
    let o = bench::Options {
        campaign: certify::Options { cases: a.cases, ..certify::Options::default() },
        rounds: a.rounds,
        serve: format!("'{}' serve", exe.display()),
        fuzz_binary,
        fuzz_seeds: existing("fuzz/seeds/diff_spec_impl"),
        fuzz_dict: existing("fuzz/gcode.dict"),
        fuzz_runs: a.fuzz_runs,
        fuzz_args: a.fuzz_arg.clone(),
    };
    let report = bench::run(&o).map_err(Bad)?;
    print!("{}", report.table());
    let failed = report.in_process.bad + report.serve.bad + report.serve_lockstep.bad > 0 || matches!(report.fuzz, Some(Err(_)));
    Ok(u8::from(failed))
}
