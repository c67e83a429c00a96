//! The switch of the spec-alone judge (docs/MUTATION.md, "The spec on its own, issue #33"):
//! with `CYCLECHECK_SPEC_ALONE=1`, each test that compares the reference spec with the production
//! expander (the conformance relation, a differential replay, the two lexers side by side) skips
//! that comparison and says so on stderr, so the tests left judge the spec on its own — its
//! unit tests, the manuals' examples, the snapshots, the properties. Without the variable (or
//! with `0` or an empty value) every comparison runs as always.

/// The variable that switches the comparisons off.
pub const VAR: &str = "CYCLECHECK_SPEC_ALONE";

/// Whether the comparisons are switched off (the variable set, neither empty nor `0`).
pub fn on() -> bool {
    std::env::var(VAR).is_ok_and(|v| !v.is_empty() && v != "0")
}

/// True when the comparison named by `what` is to be skipped; it then says so on stderr.
pub fn skip(what: &str) -> bool {
    let on = on();
    if on {
        eprintln!("{VAR}: skipped {what} (a comparison with the production expander)");
    }
    on
}
