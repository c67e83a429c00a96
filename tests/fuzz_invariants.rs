//! `fuzz-invariants`: the `impl_invariants` side of `cyclecheck fuzz`, which does not link the
//! proof harnesses (`cycle_oracle::fuzzing::committed` runs this with `cargo run -p cycle-tests
//! --bin fuzz-invariants`).
//!
//! ```text
//! fuzz-invariants write-seeds DIR               the built-in seeds, decoded, into DIR
//! fuzz-invariants encode SEEDS CORPUS           the decoded cases of SEEDS as fuzz inputs
//! fuzz-invariants decode FILE DIR NAME BY DATE  a fuzz input as the case DIR/NAME.json
//! ```

use cycle_oracle::fuzzing::decoded::{self, Origin};
use cycle_tests::invariants;
use std::path::Path;
use std::process::ExitCode;

fn run(args: &[String]) -> Result<String, String> {
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    match args.as_slice() {
        ["write-seeds", dir] => {
            let files = invariants::seed_files()?;
            decoded::write_dir(Path::new(dir), &files)?;
            Ok(format!("{} seeds\n", files.len()))
        }
        ["encode", seeds, corpus] => Ok(format!("{} inputs\n", invariants::encode_dir(Path::new(seeds), Path::new(corpus))?)),
        ["decode", file, dir, name, found_by, date] => {
            let origin = Origin { target: "impl_invariants".into(), found_by: found_by.to_string(), date: Some(date.to_string()) };
            invariants::decode_file(Path::new(file), Path::new(dir), name, origin)
        }
        _ => Err("usage: fuzz-invariants write-seeds DIR | encode SEEDS CORPUS | decode FILE DIR NAME FOUND_BY DATE".into()),
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(out) => {
            print!("{out}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("fuzz-invariants: {e}");
            ExitCode::FAILURE
        }
    }
}
