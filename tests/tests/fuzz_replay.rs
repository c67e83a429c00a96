//! Replays every committed fuzz input through the fuzz targets' bodies
//! (`cycle_oracle::fuzzing`), on stable Rust, without libFuzzer:
//!
//! - the seed corpus, `fuzz/corpus/<target>/` (the manuals' examples and one program per
//!   feature, the plain and fixed-seed random inputs of every family and harness);
//! - the regression cases, `tests/fuzz_regressions/<target>/`: minimized crashes and divergences
//!   that `cyclecheck fuzz` copies there. `diff_spec_impl/planted-depth-bug-*` is the case the
//!   fuzzer found for the planted depth rounding error (README, "Fuzzing"); it passes on this
//!   impl and fails with `--features cycle-impl/planted-depth-bug`.

use cycle_oracle::fuzzing::{self, Target};
use cycle_oracle::gate::committed_inputs;
use std::path::Path;

fn root() -> &'static Path {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
}

#[test]
fn every_committed_fuzz_input_passes() {
    let mut failures = Vec::new();
    let mut count = 0;
    for t in Target::ALL {
        let inputs = committed_inputs(root(), t);
        assert!(inputs.len() >= 20, "{}: only {} committed inputs", t.name(), inputs.len());
        for (path, bytes) in inputs {
            count += 1;
            if let Err(report) = t.run(&bytes) {
                failures.push(format!("{} {}:\n{report}", t.name(), path.display()));
            }
        }
    }
    assert!(failures.is_empty(), "{} of {count} committed inputs fail:\n\n{}", failures.len(), failures.join("\n\n"));
}

/// The committed seed corpus holds the built-in seeds, byte for byte (`cyclecheck fuzz
/// --write-seeds` rewrites them), so the manuals' examples stay in it.
#[test]
fn seed_corpus_is_committed() {
    for t in Target::ALL {
        for (file, bytes) in fuzzing::seeds(t) {
            let path = root().join("fuzz/corpus").join(t.name()).join(&file);
            let on_disk = std::fs::read(&path).unwrap_or_else(|e| panic!("{}: {e} (run `cyclecheck fuzz --write-seeds`)", path.display()));
            assert!(on_disk == bytes, "{} differs from the built-in seed", path.display());
        }
    }
}

/// The planted-bug regression case is a G78 program (the G76.DEPTH.1 schedule) on the rounding edge the planted error
/// breaks (a pass whose n·Δd² is r² + r); `every_committed_fuzz_input_passes` replays it, and
/// fails on it only with `--features cycle-impl/planted-depth-bug`.
#[test]
fn planted_bug_case_is_committed() {
    let dir = root().join("tests/fuzz_regressions/diff_spec_impl");
    let case = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .find(|e| e.file_name().to_string_lossy().starts_with("planted-depth-bug-"))
        .expect("the planted-bug regression case is committed");
    let c = fuzzing::CycleInput::from_bytes(&std::fs::read(case.path()).unwrap()).case();
    assert!(c.text().contains("G78"), "{}", c.text());
}
