//! The README as a user reads it: its `--help` excerpts are what the binary prints, and the
//! names and numbers it states are the code's.

use cyclecheck::certify::{MAX_LISTED_FAILURES, MAX_MINIMIZED};
use cycle_kernel::fuzzing::Target;
use cycle_kernel::registry::FAMILIES;
use std::process::Command;

fn readme() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md")).expect("README.md")
}

/// The text block after `<!-- help:NAME … -->`.
fn excerpt(readme: &str, name: &str) -> String {
    let marker = format!("<!-- help:{name} ");
    let after = readme.split(&marker).nth(1).unwrap_or_else(|| panic!("no {marker} in the README"));
    let block = after.split("```text\n").nth(1).expect("a text block follows the marker");
    block.split("\n```").next().unwrap().to_string()
}

fn help(args: &[&str]) -> String {
    let o = Command::new(env!("CARGO_BIN_EXE_cyclecheck")).args(args).output().unwrap();
    assert!(o.status.success());
    String::from_utf8(o.stdout).unwrap().trim_end().to_string()
}

#[test]
fn help_excerpts_are_what_the_binary_prints() {
    let r = readme();
    assert_eq!(excerpt(&r, "cyclecheck"), help(&["--help"]), "regenerate the README's excerpt");
    assert_eq!(excerpt(&r, "certify"), help(&["certify", "--help"]), "regenerate the README's excerpt");
}

#[test]
fn names_and_numbers_are_the_code_s() {
    let r = readme();
    for t in Target::ALL {
        assert!(r.contains(&format!("`{}`", t.name())), "fuzz target {} not in the README", t.name());
    }
    for f in FAMILIES {
        assert!(r.contains(f.name), "family {} not in the README", f.name);
    }
    assert!(r.contains(&format!("up to {MAX_MINIMIZED}\n  groups")) || r.contains(&format!("up to {MAX_MINIMIZED} groups")));
    assert!(r.contains(&format!("the first {MAX_LISTED_FAILURES} listed")));
    assert!(r.contains(cyclecheck::certify::evidence::SCHEMA));
}
