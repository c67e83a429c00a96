//! The README as a user reads it: its `--help` excerpts are what the binary prints, and the
//! names it states are the code's; docs/CERTIFY.md states the certify numbers the code uses.

use cyclecheck::certify::{MAX_LISTED_FAILURES, MAX_MINIMIZED};
use cycle_kernel::fuzzing::Target;
use cycle_kernel::registry::FAMILIES;
use std::process::Command;

fn readme() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../README.md")).expect("README.md")
}

fn certify_page() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/CERTIFY.md")).expect("docs/CERTIFY.md")
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
}

#[test]
fn certify_page_numbers_are_the_code_s() {
    // The page wraps its lines: compare with every run of white space as one space.
    let c = certify_page().split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(c.contains(&format!("up to {MAX_MINIMIZED} groups")), "MAX_MINIMIZED");
    assert!(c.contains(&format!("the first {MAX_LISTED_FAILURES} listed")), "MAX_LISTED_FAILURES");
    assert!(c.contains(cyclecheck::certify::evidence::SCHEMA), "the evidence schema");
}
