//! The committed fuzz cases on disk, for `cyclecheck fuzz` and `cyclecheck gate`: the decoded
//! seeds (`fuzz/seeds/<target>/`), libFuzzer's corpus encoded from them (`fuzz/corpus/<target>/`,
//! not committed), and the regressions (`tests/fuzz_regressions/<target>/`).
//!
//! `impl_invariants` cases are decoded, encoded and replayed by the proof harnesses' bodies,
//! in this process ([`super::invariants`]).

use super::decoded::{self, Origin};
use super::invariants;
use super::replay::regression;
use super::seeds::{encode, seeds};
use super::Target;
use std::path::{Path, PathBuf};

/// Where the decoded seeds of `target` are committed.
pub fn seeds_dir(root: &Path, target: Target) -> PathBuf {
    root.join("fuzz/seeds").join(target.name())
}

/// Where libFuzzer reads the encoded seeds of `target`.
pub fn corpus_dir(root: &Path, target: Target) -> PathBuf {
    root.join("fuzz/corpus").join(target.name())
}

/// Where the regressions of `target` are committed.
pub fn regressions_dir(root: &Path, target: Target) -> PathBuf {
    root.join("tests/fuzz_regressions").join(target.name())
}

/// Writes the built-in seeds of every target, decoded, into `fuzz/seeds/` (each folder then
/// holds exactly them), and encodes them into `fuzz/corpus/`. Returns the number of seeds.
pub fn write_seeds(root: &Path) -> Result<usize, String> {
    let mut n = 0;
    for t in Target::PROGRAMS {
        let mut files = Vec::new();
        for (name, program, case) in seeds(t) {
            files.extend(decoded::program_files(&name, &program, &case)?);
            n += 1;
        }
        decoded::write_dir(&seeds_dir(root, t), &files)?;
    }
    let dir = seeds_dir(root, Target::ImplInvariants);
    decoded::write_dir(&dir, &invariants::seed_files()?)?;
    n += decoded::load_harnesses(&dir)?.len();
    encode_corpus(root, &Target::ALL)?;
    Ok(n)
}

/// Encodes the decoded seeds of `targets` into libFuzzer's corpus folders (each then holds
/// exactly them, one file per seed). Returns the number of inputs written.
pub fn encode_corpus(root: &Path, targets: &[Target]) -> Result<usize, String> {
    let mut n = 0;
    for &t in targets {
        let (seeds, corpus) = (seeds_dir(root, t), corpus_dir(root, t));
        if t == Target::ImplInvariants {
            n += invariants::encode_dir(&seeds, &corpus)?;
            continue;
        }
        let mut files = Vec::new();
        for (name, program, case) in decoded::load_programs(&seeds)? {
            let bytes = encode(t, &program, &case).map_err(|e| format!("{}/{name}: {e}", seeds.display()))?;
            files.push((name, bytes));
        }
        if files.is_empty() {
            return Err(format!("{}: no seeds (run `cyclecheck fuzz --write-seeds`)", seeds.display()));
        }
        n += files.len();
        decoded::write_dir(&corpus, &files)?;
    }
    Ok(n)
}

/// Commits a fuzz input of `target` as a decoded regression `NAME` in
/// `tests/fuzz_regressions/<target>/`. Returns the body's report on the input in this build
/// (or that it passes here).
pub fn write_regression(root: &Path, target: Target, data: &Path, name: &str, found_by: &str) -> Result<String, String> {
    let dir = regressions_dir(root, target);
    let date = today();
    if target == Target::ImplInvariants {
        let origin = Origin { target: target.name().to_string(), found_by: found_by.to_string(), date: Some(date) };
        return invariants::decode_file(data, &dir, name, origin);
    }
    let bytes = std::fs::read(data).map_err(|e| format!("{}: {e}", data.display()))?;
    let origin = Origin { target: target.name().to_string(), found_by: found_by.to_string(), date: Some(date) };
    let (program, case) = regression(target, &bytes, origin).ok_or("not a program target")?;
    std::fs::create_dir_all(&dir).map_err(|e| format!("{}: {e}", dir.display()))?;
    for (file, content) in decoded::program_files(name, &program, &case)? {
        std::fs::write(dir.join(&file), content).map_err(|e| format!("{file}: {e}"))?;
    }
    Ok(match target.run(&bytes) {
        Ok(()) => "passes in this build (built without the fuzz run's features?)".to_string(),
        Err(report) => report,
    })
}

/// Today's date (UTC), `YYYY-MM-DD`.
pub fn today() -> String {
    let secs = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map_or(0, |d| d.as_secs());
    civil_date((secs / 86_400) as i64)
}

/// The proleptic Gregorian date of a day number counted from 1970-01-01 (H. Hinnant's
/// `civil_from_days`).
pub fn civil_date(days: i64) -> String {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z.rem_euclid(146_097);
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let day = doy - (153 * mp + 2) / 5 + 1;
    let month = if mp < 10 { mp + 3 } else { mp - 9 };
    let year = yoe + era * 400 + i64::from(month <= 2);
    format!("{year:04}-{month:02}-{day:02}")
}

#[cfg(test)]
mod tests;
