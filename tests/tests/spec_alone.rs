//! The spec-alone judge (docs/MUTATION.md, "The spec on its own, issue #33") stays what the
//! document says: its command is the one written there; every test target of `cycle-tests` and
//! `cycle-kernel` is in it or excluded with a reason; and every test source in it that compares
//! the spec with the production expander goes through the switch (`cycle_kernel::spec_alone`).

use std::path::{Path, PathBuf};

/// The judge's integration-test targets (beside the `--lib` unit tests of the three packages).
const JUDGE: &[&str] = &[
    "examples",
    "families",
    "operator",
    "properties",
    "properties_contour",
    "properties_g73",
    "properties_operator",
    "properties_peck",
    "properties_single_cut",
    "traced_rules",
];

/// The targets left out, each with its reason.
const EXCLUDED: &[(&str, &str)] = &[
    ("differential", "the differential campaigns: spec against impl"),
    ("fuzz_replay", "the committed fuzz cases replayed: spec against impl, lexer against lexer"),
    ("lexers", "the two lexers side by side"),
    ("fill", "the production expander alone (buffer sizes against its own iterator)"),
    ("zero_alloc", "the production expander alone"),
    ("spec_alone", "this check of the judge's list"),
    ("concordance", "the concordance document's form; runs no engine"),
    ("thread_words", "the thread-words document's form; runs no engine"),
];

fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("..")
}

/// The judge's command, as docs/MUTATION.md must state it.
fn command() -> String {
    let targets: Vec<String> = JUDGE.iter().map(|t| format!("--test {t}")).collect();
    format!(
        "CYCLECHECK_SPEC_ALONE=1 CYCLECHECK_CASES=200 cargo test -p cycle-spec -p cycle-kernel -p cycle-tests --lib {}",
        targets.join(" ")
    )
}

/// The integration-test targets of a package: its `tests/*.rs` files.
fn targets(dir: &str) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(root().join(dir))
        .unwrap()
        .filter_map(Result::ok)
        .filter_map(|e| e.file_name().to_str()?.strip_suffix(".rs").map(str::to_string))
        .collect();
    names.sort();
    names
}

#[test]
fn the_document_states_the_judge() {
    let doc = std::fs::read_to_string(root().join("docs/MUTATION.md")).unwrap();
    let joined = doc.replace("\\\n", " ").split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(joined.contains(&command()), "docs/MUTATION.md does not state the judge:\n{}", command());
}

#[test]
fn every_target_is_judged_or_excluded() {
    let mut all = targets("tests/tests");
    all.extend(targets("kernel/tests"));
    for t in &all {
        let judged = JUDGE.contains(&t.as_str());
        let excluded = EXCLUDED.iter().any(|(e, _)| e == t);
        assert!(judged != excluded, "{t}: in the judge {judged}, excluded {excluded}; it must be exactly one");
    }
    for t in JUDGE.iter().chain(EXCLUDED.iter().map(|(e, _)| e)) {
        assert!(all.iter().any(|a| a == t), "{t} is no test target of cycle-tests or cycle-kernel");
    }
}

/// What compares the two engines (or the two lexers) in a test source.
const COMPARISONS: &[&str] =
    &["conformance::check(", "ImplEngine.expand", "&ImplEngine", "Target::DiffSpecImpl", "Target::ParseBlocks", "parse_blocks("];

/// The judge's test sources: its integration targets and the kernel's unit-test modules.
fn judged_sources() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = JUDGE
        .iter()
        .map(|t| if *t == "traced_rules" { root().join("kernel/tests/traced_rules.rs") } else { root().join(format!("tests/tests/{t}.rs")) })
        .collect();
    let mut dirs = vec![root().join("kernel/src")];
    while let Some(d) = dirs.pop() {
        for e in std::fs::read_dir(d).unwrap().filter_map(Result::ok) {
            let p = e.path();
            if p.is_dir() {
                dirs.push(p);
            } else if p.file_name().is_some_and(|n| n == "tests.rs") || p.parent().is_some_and(|d| d.ends_with("tests")) {
                files.push(p);
            }
        }
    }
    files
}

#[test]
fn every_comparison_in_the_judge_goes_through_the_switch() {
    for f in judged_sources() {
        let text = std::fs::read_to_string(&f).unwrap();
        let compares: Vec<&str> = COMPARISONS.iter().copied().filter(|c| text.contains(c)).collect();
        // The impl engine against the impl expander called directly: no spec in it.
        let impl_only = f.ends_with("kernel/src/engine/tests.rs");
        if !compares.is_empty() && !impl_only {
            assert!(text.contains("spec_alone::"), "{}: compares ({compares:?}) without the switch", f.display());
        }
    }
}
