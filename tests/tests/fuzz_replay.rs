//! Replays every committed fuzz case through the fuzz targets' bodies, on stable Rust, without
//! libFuzzer, and checks each case's expected verdict. The cases are stored decoded
//! (`cycle_kernel::fuzzing::decoded`), so they keep their meaning whatever the byte encodings:
//!
//! - the seeds, `fuzz/seeds/<target>/` (the manuals' examples and one program per feature, the
//!   plain and fixed-seed random cases of every family and harness), written by `cyclecheck
//!   fuzz --write-seeds` and encoded from there into libFuzzer's `fuzz/corpus/<target>/`;
//! - the regressions, `tests/fuzz_regressions/<target>/`, written decoded by `cyclecheck fuzz`.
//!   `diff_spec_impl/planted-depth-bug-*` is the case the fuzzer found for the planted depth
//!   rounding error (docs/FUZZING.md); it passes on this impl and fails with `--features
//!   cycle-impl/planted-depth-bug`.

use cycle_kernel::fuzzing::committed::{regressions_dir, seeds_dir};
use cycle_kernel::fuzzing::decoded::{self, load_harnesses, load_programs};
use cycle_kernel::fuzzing::{replay, seeds, Target};
use cycle_kernel::fuzzing::invariants;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

/// Replays the cases in `dir`; (cases, failure reports).
fn replay_dir(target: Target, dir: &Path) -> (usize, Vec<String>) {
    let here = |name: &str| format!("{} {}/{name}", target.name(), dir.display());
    let results: Vec<(String, Result<(), String>)> = if target == Target::ImplInvariants {
        let cases = load_harnesses(dir).unwrap_or_else(|e| panic!("{e}"));
        cases.iter().map(|(name, case)| (here(name), invariants::replay(case))).collect()
    } else {
        let cases = load_programs(dir).unwrap_or_else(|e| panic!("{e}"));
        cases.iter().map(|(name, program, case)| (here(name), replay::replay(target, program, case))).collect()
    };
    let failures = results.iter().filter_map(|(n, r)| r.as_ref().err().map(|e| format!("{n}:\n{e}"))).collect();
    (results.len(), failures)
}

#[test]
fn every_committed_case_replays_with_its_verdict() {
    let (mut count, mut failures) = (0, Vec::new());
    for t in Target::ALL {
        let (seeds, f) = replay_dir(t, &seeds_dir(root(), t));
        assert!(seeds >= 20, "{}: only {seeds} committed seeds", t.name());
        let (regressions, g) = replay_dir(t, &regressions_dir(root(), t));
        count += seeds + regressions;
        failures.extend(f.into_iter().chain(g));
    }
    assert!(failures.is_empty(), "{} of {count} committed fuzz cases fail:\n\n{}", failures.len(), failures.join("\n\n"));
}

/// The committed seeds are the built-in ones, file for file (`cyclecheck fuzz --write-seeds`
/// rewrites them), so the manuals' examples, every family and every harness stay in them.
#[test]
fn committed_seeds_are_the_built_in_set() {
    for t in Target::ALL {
        let mut built_in = if t == Target::ImplInvariants {
            invariants::seed_files().unwrap()
        } else {
            let mut files = Vec::new();
            for (name, program, case) in seeds::seeds(t) {
                files.extend(decoded::program_files(&name, &program, &case).unwrap());
            }
            files
        };
        built_in.sort();
        let dir = seeds_dir(root(), t);
        let on_disk = decoded::read_dir(&dir).unwrap();
        let names = |files: &[(String, Vec<u8>)]| files.iter().map(|(n, _)| n.clone()).collect::<Vec<_>>();
        assert_eq!(names(&on_disk), names(&built_in), "{}: run `cyclecheck fuzz --write-seeds`", dir.display());
        for ((name, disk), (_, want)) in on_disk.iter().zip(&built_in) {
            assert!(disk == want, "{}/{name} differs from the built-in seed (run `cyclecheck fuzz --write-seeds`)", dir.display());
        }
    }
}

/// The planted-bug regression is a G78 program (the G76.DEPTH.1 schedule) on the rounding edge
/// the planted error breaks (a pass whose n·Δd² is r² + r), expected to conform:
/// `every_committed_case_replays_with_its_verdict` fails on it only with `--features
/// cycle-impl/planted-depth-bug`.
#[test]
fn planted_bug_case_is_committed() {
    let cases = load_programs(&regressions_dir(root(), Target::DiffSpecImpl)).unwrap();
    let (_, program, case) =
        cases.iter().find(|(name, _, _)| name.starts_with("planted-depth-bug-")).expect("the planted-bug regression is committed");
    assert!(String::from_utf8_lossy(program).contains("G78"), "{}", String::from_utf8_lossy(program));
    assert_eq!(case.expect.conform, Some(true));
}

/// A case whose harness no longer draws as it did is reported, not silently run as another case.
#[test]
fn a_harness_case_with_misfit_draws_fails() {
    let (_, mut case) = load_harnesses(&regressions_dir(root(), Target::ImplInvariants)).unwrap().remove(0);
    assert_eq!(invariants::replay(&case), Ok(()));
    case.draws.push(7);
    assert!(invariants::replay(&case).unwrap_err().contains("it draws differently now"));
}
