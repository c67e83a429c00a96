//! Running z3 on the lemma files: each query through `z3 -smt2 -in` with a hard timeout, its
//! verdict and wall time.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::Instant;

/// The hard timeout per query, seconds (z3 `-T:`).
pub const TIMEOUT_S: u32 = 60;

/// The line that separates a lemma's model and assumptions from its negated property.
pub const GOAL_MARKER: &str = "; negated property";

/// The z3 binary: `$Z3` if set, else `z3` on PATH (Debian: `apt-get install -y z3`).
pub fn binary() -> String {
    std::env::var("Z3").unwrap_or_else(|_| "z3".to_string())
}

/// `z3 --version`, or a panic that says how to install it.
pub fn version() -> String {
    let out = Command::new(binary()).arg("--version").output().unwrap_or_else(|e| {
        panic!("cannot run `{}` ({e}): install z3 (Debian: apt-get install -y z3) or set Z3", binary())
    });
    String::from_utf8_lossy(&out.stdout).trim().to_string()
}

/// A verdict and how long z3 took.
#[derive(Clone, Debug)]
pub struct Run {
    /// z3's first output line: `unsat`, `sat`, `unknown`, `timeout`, or an error.
    pub result: String,
    pub seconds: f64,
    /// Everything z3 printed (a model after `(get-model)`).
    pub output: String,
}

/// Runs z3 on SMT-LIB2 text.
pub fn check(text: &str) -> Run {
    let start = Instant::now();
    let mut child = Command::new(binary())
        .args(["-smt2", "-in", &format!("-T:{TIMEOUT_S}")])
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot run `{}` ({e}): install z3 (apt-get install -y z3)", binary()));
    child.stdin.take().expect("stdin").write_all(text.as_bytes()).expect("write to z3");
    let out = child.wait_with_output().expect("z3 output");
    let seconds = start.elapsed().as_secs_f64();
    let stdout = String::from_utf8_lossy(&out.stdout);
    let result = stdout.lines().next().unwrap_or("(no output)").trim().to_string();
    let result = if result.starts_with("(error") { stdout.trim().to_string() } else { result };
    Run { result, seconds, output: stdout.trim().to_string() }
}

/// The lemma files, sorted by name (their numbers are the proof order).
pub fn lemma_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("lemmas");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("dir entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "smt2"))
        .collect();
    files.sort();
    files
}

/// A lemma: its name (the file stem) and text.
pub fn lemma(path: &Path) -> (String, String) {
    let name = path.file_stem().expect("file name").to_string_lossy().to_string();
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    (name, text)
}

/// The lemma by its name (file stem).
pub fn lemma_named(name: &str) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("lemmas").join(format!("{name}.smt2"));
    lemma(&path).1
}

/// The lemma's model and assumptions alone (its negated property cut off), to check that they
/// have a model: a lemma whose assumptions contradict each other would be `unsat` vacuously.
pub fn assumptions_only(text: &str) -> String {
    let at = text.find(GOAL_MARKER).expect("lemma without the negated-property marker");
    format!("{}(check-sat)\n", &text[..at])
}
