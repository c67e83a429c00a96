//! The committed cases of the `impl_invariants` fuzz target, run by the proof harnesses' bodies
//! (`cycle_proofs::invariants`) in this process: decoding a fuzz input into a case, replaying a
//! case with its verdict checked, the built-in seeds, and their fuzz encoding.

use super::decoded::{self, HarnessCase, HarnessExpect, Origin};
use cycle_proofs::invariants::{self as harness, Decoded};
use cycle_proofs::source::{Outcome, Stop};
use std::path::Path;

fn text(program: Option<&[u8]>) -> Option<String> {
    program.map(|p| String::from_utf8_lossy(p).into_owned())
}

fn seen(outcome: Outcome) -> HarnessExpect {
    if outcome == Err(Stop::Rejected) {
        HarnessExpect::Rejected
    } else {
        HarnessExpect::Holds
    }
}

/// The committed case of a decoded input. A failing input expects every property to hold: the
/// outcome it must have once the bug is fixed.
pub fn case_of(d: &Decoded, origin: Origin) -> HarnessCase {
    HarnessCase {
        harness: d.harness.to_string(),
        draws: d.draws.clone(),
        expect: seen(d.outcome),
        program: text(d.program.as_deref()),
        origin,
    }
}

/// Replays a case through its harness body and checks its verdict: `Err` says what differs.
pub fn replay(case: &HarnessCase) -> Result<(), String> {
    let (outcome, program) = harness::replay(&case.harness, &case.draws)?;
    harness::report(&case.harness, &case.draws, outcome, program.as_deref())?;
    if seen(outcome) != case.expect {
        return Err(format!("the harness now returns {:?}; the case expects {:?}", seen(outcome), case.expect));
    }
    if case.program.is_some() && text(program.as_deref()) != case.program {
        return Err(format!("the harness now builds another program from these draws:\n{}", text(program.as_deref()).unwrap_or_default()));
    }
    Ok(())
}

/// The built-in seeds (`cycle_proofs::invariants::seeds`) as committed cases, by name.
pub fn seeds() -> Vec<(String, HarnessCase)> {
    harness::seeds()
        .into_iter()
        .map(|(name, d)| {
            let origin = Origin { target: "impl_invariants".into(), found_by: format!("built-in seed: {name}"), date: None };
            (name, case_of(&d, origin))
        })
        .collect()
}

/// The files of the built-in seeds (`NAME.json`).
pub fn seed_files() -> Result<Vec<(String, Vec<u8>)>, String> {
    seeds().iter().map(|(name, case)| Ok((format!("{name}.json"), decoded::to_json(case)?.into_bytes()))).collect()
}

/// The fuzz input of a case.
pub fn encode(case: &HarnessCase) -> Result<Vec<u8>, String> {
    harness::encode(&case.harness, &case.draws).ok_or_else(|| format!("no harness {:?}", case.harness))
}

/// Encodes the cases in `seeds` into `corpus` (which then holds exactly them).
pub fn encode_dir(seeds: &Path, corpus: &Path) -> Result<usize, String> {
    let files = decoded::load_harnesses(seeds)?
        .iter()
        .map(|(name, case)| Ok((name.clone(), encode(case).map_err(|e| format!("{name}: {e}"))?)))
        .collect::<Result<Vec<_>, String>>()?;
    if files.is_empty() {
        return Err(format!("{}: no seeds", seeds.display()));
    }
    decoded::write_dir(corpus, &files)?;
    Ok(files.len())
}

/// Decodes the fuzz input `file` into the case `dir/NAME.json`; returns the body's report on it.
pub fn decode_file(file: &Path, dir: &Path, name: &str, origin: Origin) -> Result<String, String> {
    let bytes = std::fs::read(file).map_err(|e| format!("{}: {e}", file.display()))?;
    let d = harness::decode(&bytes);
    let json = decoded::to_json(&case_of(&d, origin))?;
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    std::fs::write(dir.join(format!("{name}.json")), json).map_err(|e| format!("{name}.json: {e}"))?;
    Ok(match harness::report(d.harness, &d.draws, d.outcome, d.program.as_deref()) {
        Ok(()) => format!("harness {}: passes in this build ({:?})", d.harness, seen(d.outcome)),
        Err(report) => report,
    })
}
