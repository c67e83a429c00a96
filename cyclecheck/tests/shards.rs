//! `certify --shard` and `merge` as a user runs them: bad shards refused with exit 2, and two
//! shards merged into the unsharded run's verdict, counts and cases.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cyclecheck")).args(args).output().unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn evidence(dir: &Path) -> serde_json::Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("evidence.json")).unwrap()).unwrap()
}

#[test]
fn bad_shards_and_merges_exit_2_naming_the_problem() {
    let missing = "/nonexistent/shard-bundle";
    for (args, names) in [
        (vec!["certify", "--shard", "0/4"], "--shard takes K/N with 1 <= K <= N"),
        (vec!["certify", "--shard", "5/4"], "not \"5/4\""),
        (vec!["certify", "--shard", "a/b"], "not \"a/b\""),
        (vec!["gate", "--shard", "1/0"], "--shard takes K/N"),
        (vec!["merge", "--out", "x"], "<BUNDLE>"),
        (vec!["merge", "--out", "x", missing], missing),
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(names), "{args:?} should name {names:?}: {}", stderr(&o));
    }
}

#[test]
fn two_shards_merge_into_the_unsharded_run() {
    let root = std::env::temp_dir().join(format!("cyclecheck-shards-cli-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    let dir = |name: &str| -> PathBuf { root.join(name) };
    let certify = |out: &str, extra: &[&str]| {
        let out = dir(out);
        let mut args = vec!["certify", "--cycles", "g92", "--cases", "10", "--out", out.to_str().unwrap()];
        args.extend_from_slice(extra);
        let o = run(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", stderr(&o));
        o
    };
    certify("whole", &[]);
    let one = certify("one", &["--shard", "1/2"]);
    assert!(String::from_utf8_lossy(&one.stdout).contains("(shard 1/2: merge the shards with cyclecheck merge)"));
    certify("two", &["--shard", "2/2"]);
    let (one, two, merged) = (dir("one"), dir("two"), dir("merged"));
    let o = run(&["merge", "--out", merged.to_str().unwrap(), two.to_str().unwrap(), one.to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(String::from_utf8_lossy(&o.stdout).contains("PASS (merged from 2 shards)"));
    let (whole, joined) = (evidence(&dir("whole")), evidence(&merged));
    for key in ["by_cycle", "by_rule", "divergences", "matrix", "families"] {
        assert_eq!(joined[key], whole[key], "{key}");
    }
    for key in ["passed", "cases", "conform", "diverge", "fail"] {
        assert_eq!(joined["summary"][key], whole["summary"][key], "summary.{key}");
    }
    let cases = |d: &Path| std::fs::read(d.join("cases.jsonl")).unwrap();
    assert_eq!(cases(&merged), cases(&dir("whole")));
    std::fs::remove_dir_all(&root).unwrap();
}
