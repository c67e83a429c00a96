//! Comparison levels, declared deviations and the third-party report, end to end through the
//! `cyclecheck` binary, with a candidate that emits moves only
//! (`fixtures/motion_candidate.py`: `cyclecheck serve` cut down, its greeting declaring
//! `"level": "motion"`; `--plant-bug` moves the first pull-out one increment).
//!
//! Needs `python3`; without it each test says why and passes vacuously (the unit tests of
//! `conformance`, `certify::deviations` and `thirdparty` cover the logic in-process).

use serde_json::Value;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn python3() -> bool {
    let ok = Command::new("python3").arg("--version").output().is_ok_and(|o| o.status.success());
    if !ok {
        eprintln!("SKIPPED: python3 is not installed; these tests need it");
    }
    ok
}

fn exe() -> &'static str {
    env!("CARGO_BIN_EXE_cyclecheck")
}

fn temp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cyclecheck-levels-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    d
}

/// The fixture's command line, with `args`.
fn candidate(args: &str) -> String {
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/motion_candidate.py");
    format!("python3 '{}' '{}' {args}", script.display(), exe())
}

fn certify(out: &Path, candidate: &str, extra: &[&str]) -> Output {
    Command::new(exe())
        .args(["certify", "--cycles", "g92", "--cases", "10", "--out"])
        .arg(out)
        .args(["--candidate", candidate])
        .args(extra)
        .output()
        .expect("cyclecheck runs")
}

fn evidence(out: &Path) -> Value {
    serde_json::from_slice(&std::fs::read(out.join("evidence.json")).expect("evidence.json")).expect("JSON")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// The rules of the divergence groups of a bundle, with their counts.
fn group_rules(doc: &Value) -> Vec<(String, u64)> {
    doc["divergences"].as_array().unwrap().iter().map(|g| (g["signature"]["rule"].as_str().unwrap().to_string(), g["count"].as_u64().unwrap())).collect()
}

fn deviations_file(dir: &Path, rules: &[&str]) -> PathBuf {
    std::fs::create_dir_all(dir).unwrap();
    let path = dir.join("deviations.toml");
    let text: String = rules.iter().map(|r| format!("[[deviation]]\nrule = \"{r}\"\nfamily = \"g92\"\nfield = \"z\"\nreason = \"the pull-out end one increment off, on purpose\"\n\n")).collect();
    std::fs::write(&path, text).unwrap();
    path
}

/// (a) A moves-only candidate conforms at level motion, and nothing calls that a full pass;
/// `--level full` refuses it before the run.
#[test]
fn a_motion_candidate_passes_at_motion_and_never_as_full() {
    if !python3() {
        return;
    }
    let out = temp("motion");
    let o = certify(&out, &candidate(""), &[]);
    let text = stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{text}{}", String::from_utf8_lossy(&o.stderr));
    assert!(text.contains("PASS at comparison level motion"), "{text}");
    let doc = evidence(&out);
    assert_eq!((doc["candidate"]["level"].as_str(), doc["summary"]["level"].as_str()), (Some("motion"), Some("motion")));
    assert_eq!(doc["summary"]["verdict"], "PASS at comparison level motion");
    assert!(doc["summary"]["conform"].as_u64().unwrap() > 10);
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(html.contains("PASS at comparison level motion") && html.contains("This is not a full comparison"));
    assert!(!html.contains(">PASS —"), "a motion run is never a plain PASS");
    // The same candidate asked for a full comparison: refused before the run, exit 1.
    let refused = temp("motion-full");
    let o = certify(&refused, &candidate(""), &["--level", "full"]);
    assert_eq!(o.status.code(), Some(1));
    assert!(stdout(&o).contains("declares comparison level motion") && !refused.exists(), "{}", stdout(&o));
    // At level full the whole trace is compared: pass headers are missing from its trace.
    let full = temp("full-claim");
    let o = certify(&full, &candidate("--level full --plant-bug"), &["--level", "full"]);
    assert_eq!(o.status.code(), Some(1));
    let _ = [out, full].map(std::fs::remove_dir_all);
}

/// (b, c, d, e) A planted one-increment error: a divergence unless a declaration names its
/// rule; then "PASS with N declared deviations"; an unused declaration is listed; shards merge
/// with conform, deviate and diverge kept apart.
#[test]
fn declared_deviations_absorb_only_what_they_name() {
    if !python3() {
        return;
    }
    let dir = temp("deviations");
    let bug = candidate("--plant-bug");
    // Undeclared: the planted error is found, grouped by the pull-out's rules.
    let plain = dir.join("plain");
    let o = certify(&plain, &bug, &[]);
    assert_eq!(o.status.code(), Some(1), "{}", stdout(&o));
    let doc = evidence(&plain);
    let groups = group_rules(&doc);
    let diverging = doc["summary"]["diverge"].as_u64().unwrap();
    assert!(groups.len() >= 2 && diverging > 0, "{groups:?}");
    let rules: Vec<&str> = groups.iter().map(|(r, _)| r.as_str()).collect();

    // (b) Declarations for every rule but the last group's: that group still diverges.
    let (kept, left) = rules.split_at(rules.len() - 1);
    let partial = deviations_file(&dir.join("b"), &[kept, &["G92.PATH"]].concat());
    let b = dir.join("b/bundle");
    let o = certify(&b, &bug, &["--deviations", partial.to_str().unwrap()]);
    let text = stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{text}");
    let doc = evidence(&b);
    assert_eq!(group_rules(&doc), vec![groups.last().unwrap().clone()], "only {left:?} is not absorbed");
    let left_count = groups.last().unwrap().1;
    assert_eq!((doc["summary"]["diverge"].as_u64(), doc["summary"]["deviate"].as_u64()), (Some(left_count), Some(diverging - left_count)));
    assert!(doc["summary"]["verdict"].as_str().unwrap().starts_with("FAIL"));

    // (c, d) Every rule declared, and one declaration no case uses.
    let all = deviations_file(&dir.join("c"), &[&rules[..], &["G76.INFEED.Z"]].concat());
    let c = dir.join("c/bundle");
    let o = certify(&c, &bug, &["--deviations", all.to_str().unwrap()]);
    let text = stdout(&o);
    assert_eq!(o.status.code(), Some(0), "{text}");
    assert!(text.contains(&format!("PASS at comparison level motion with {diverging} declared deviations")), "{text}");
    assert!(text.contains("UNUSED") && text.contains("G76.INFEED.Z"), "{text}");
    let doc = evidence(&c);
    assert_eq!(doc["summary"]["conform"].as_u64().unwrap() + diverging, doc["summary"]["cases"].as_u64().unwrap(), "deviations never count as conforming");
    assert_eq!(doc["deviations"]["unused"], serde_json::json!([rules.len()]));
    let html = std::fs::read_to_string(c.join("index.html")).unwrap();
    assert!(html.contains("0 — unused") && html.contains("the rest of that case was not compared"));

    // (e) Shards of (b) merge into (b)'s counts.
    let shards: Vec<PathBuf> = (1..=2).map(|k| dir.join(format!("shard{k}"))).collect();
    for (k, s) in shards.iter().enumerate() {
        let shard = format!("{}/2", k + 1);
        certify(s, &bug, &["--deviations", partial.to_str().unwrap(), "--shard", &shard]);
    }
    let merged = dir.join("merged");
    let o = Command::new(exe()).arg("merge").arg("--out").arg(&merged).args(&shards).output().unwrap();
    assert_eq!(o.status.code(), Some(1), "{}{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    let (m, whole) = (evidence(&merged), evidence(&b));
    for key in ["cases", "conform", "deviate", "diverge", "fail", "verdict", "level"] {
        assert_eq!(m["summary"][key], whole["summary"][key], "{key}");
    }
    assert_eq!(m["deviations"]["declared"], whole["deviations"]["declared"]);
    assert_eq!(m["deviations"]["unused"], whole["deviations"]["unused"]);
    let _ = std::fs::remove_dir_all(&dir);
}

/// (f) `third-party --check` passes on the report it wrote and fails when a count changes.
#[test]
fn third_party_check_compares_counts() {
    if !python3() {
        return;
    }
    let dir = temp("third-party");
    let fake = dir.join("candidates/fake");
    std::fs::create_dir_all(&fake).unwrap();
    let notes = ["G92.PULLOUT", "G92.JK.1", "G92.JK.2", "G92.JK.3", "G92.JK.4", "G92.JK.5"].map(|r| format!("\"{r}\" = \"The fixture moves the pull-out on purpose.\"\n")).concat();
    let manifest = format!(
        "name = \"fake\"\nexpander = \"fake 1.0\"\ncommand = {:?}\nsetup = \"true\"\nci = true\n[[campaign]]\ncycles = \"g92\"\ncases = 6\nseed = 3\n[notes]\n{notes}[[finding]]\ntitle = \"a finding\"\nprogram = \"G0 X1\"\noutput = \"boom\"\n",
        candidate("--plant-bug")
    );
    std::fs::write(fake.join("candidate.toml"), manifest).unwrap();
    let ghost = dir.join("candidates/ghost");
    std::fs::create_dir_all(&ghost).unwrap();
    std::fs::write(ghost.join("candidate.toml"), "name = \"ghost\"\nexpander = \"ghost 0\"\ncommand = \"/nonexistent/ghost\"\nsetup = \"none\"\n[[campaign]]\ncycles = \"g92\"\ncases = 1\nseed = 1\n").unwrap();
    let out = dir.join("THIRD-PARTY.md");
    let run = |extra: &[&str]| {
        Command::new(exe()).arg("third-party").arg("--candidates").arg(dir.join("candidates")).arg("--out").arg(&out).arg("--skip-missing").args(extra).output().unwrap()
    };
    let o = run(&[]);
    assert_eq!(o.status.code(), Some(0), "{}{}", stdout(&o), String::from_utf8_lossy(&o.stderr));
    let doc = std::fs::read_to_string(&out).unwrap();
    assert!(doc.contains("| family | cases | conform | deviate as declared | diverge | refused | failed |"), "{doc}");
    assert!(doc.contains("**Not installed here**") && doc.contains("#### a finding") && doc.contains("#### Divergence group G92."), "{doc}");
    assert!(!doc.contains("no note"), "{doc}");
    let o = run(&["--check"]);
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    // One count changed by hand: the check fails, naming the line.
    let row = doc.lines().find(|l| l.starts_with("| G92 |")).unwrap().to_string();
    let cases: u64 = row.split('|').nth(2).unwrap().trim().parse().unwrap();
    let changed = row.replacen(&format!("| {cases} |"), &format!("| {} |", cases + 1), 1);
    std::fs::write(&out, doc.replace(&row, &changed)).unwrap();
    let o = run(&["--check"]);
    let text = stdout(&o);
    assert_eq!(o.status.code(), Some(1), "{text}");
    assert!(text.contains(&format!("- Campaign 1: cycles g92; 6 cases per family; seed 3 :: {changed}")) && text.contains(&format!("+ Campaign 1: cycles g92; 6 cases per family; seed 3 :: {row}")), "{text}");
    let _ = std::fs::remove_dir_all(&dir);
}

/// `diff --candidate` honours the greeting's level.
#[test]
fn diff_compares_at_the_declared_level() {
    if !python3() {
        return;
    }
    let program = Path::new(env!("CARGO_MANIFEST_DIR")).join("../corpus/g92_example.nc");
    let o = Command::new(exe()).arg("diff").arg(&program).args(["--candidate", &candidate("")]).output().unwrap();
    assert_eq!(o.status.code(), Some(0), "{}", stdout(&o));
    assert!(stdout(&o).starts_with("conform at comparison level motion"), "{}", stdout(&o));
    let o = Command::new(exe()).arg("diff").arg(&program).args(["--format", "json", "--candidate", &candidate("--plant-bug")]).output().unwrap();
    let doc: Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!((o.status.code(), doc["level"].as_str(), doc["divergence"]["level"].as_str()), (Some(1), Some("motion"), Some("motion")));
}

/// A bad deviations file stops certify before anything runs: exit 2, the key and the line named.
#[test]
fn a_bad_deviations_file_is_refused_with_its_line() {
    let dir = temp("bad-deviations");
    std::fs::create_dir_all(&dir).unwrap();
    let file = dir.join("d.toml");
    std::fs::write(&file, "[[deviation]]\nrule = \"G92.PULLOUT\"\nreason = \"r\"\n\n[[deviation]]\nrule = \"G92.NOPE\"\nreason = \"r\"\n").unwrap();
    let out = dir.join("bundle");
    let o = Command::new(exe()).args(["certify", "--cycles", "g92", "--cases", "1", "--out"]).arg(&out).arg("--deviations").arg(&file).output().unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(err.contains("line 6: rule") && err.contains("G92.NOPE") && !out.exists(), "{err}");
    let _ = std::fs::remove_dir_all(&dir);
}
