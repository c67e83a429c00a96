//! The proofs: z3 on every lemma of smt/lemmas/, each `unsat` within the timeout, with a table
//! of results and times. Alone in its test binary so that the lemmas run one after the other and
//! the times are not inflated by other tests running in parallel.

use cycle_smt::z3;

/// Every lemma is `unsat` (the negated property has no model), each within the timeout.
#[test]
fn every_lemma_is_unsat() {
    let version = z3::version();
    let files = z3::lemma_files();
    assert!(files.len() >= 13, "lemma files missing: {files:?}");
    let mut table = format!("{version}, timeout {} s per lemma\n{:<26} {:<8} {:>7}\n", z3::TIMEOUT_S, "lemma", "result", "seconds");
    let mut failed = Vec::new();
    let mut total = 0.0;
    for path in &files {
        let (name, text) = z3::lemma(path);
        let run = z3::check(&text);
        table += &format!("{name:<26} {:<8} {:>7.2}\n", run.result, run.seconds);
        total += run.seconds;
        if run.result != "unsat" {
            failed.push(format!("{name}: {}", run.result));
        }
    }
    table += &format!("{:<26} {:<8} {total:>7.2}\n", "total", "");
    println!("{table}");
    assert!(failed.is_empty(), "lemmas not proved: {failed:?}\n{table}");
}
