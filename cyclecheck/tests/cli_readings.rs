//! `--reading NAME=VALUE` on the command line (docs/INTERPRETATION.md, "Declared readings"):
//! accepted on expand, diff, corpus and certify; an unknown name or value is exit 2 naming it and
//! the legal ones; the evidence of an in-process run says the readings were drawn per case and
//! counts the cases under each value.

use std::path::PathBuf;
use std::process::{Command, Output};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cyclecheck")).args(args).output().expect("the binary runs")
}

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

fn g92() -> String {
    root().join("corpus/g92_example.nc").to_string_lossy().into_owned()
}

#[test]
fn good_readings_are_taken_everywhere_a_configuration_is_built() {
    let file = g92();
    for args in [
        vec!["expand", &file, "--reading", "g94.k=start-minus-end", "--reading", "g96.rapid=allow"],
        vec!["diff", &file, "--reading", "thread.zref=groove"],
        vec!["corpus", "--reading", "g73.c=skip"],
    ] {
        let o = run(&args);
        assert_eq!(o.status.code(), Some(0), "{args:?}: {}", text(&o.stderr));
    }
    let o = run(&["corpus", "--reading", "g94.k=start-minus-end"]);
    assert!(text(&o.stdout).contains("readings: g94.k=start-minus-end, others the letter"), "{}", text(&o.stdout));
    let o = run(&["corpus"]);
    assert!(text(&o.stdout).contains("readings: the letter throughout"), "{}", text(&o.stdout));
}

#[test]
fn a_bad_name_or_value_is_exit_2_naming_the_legal_ones() {
    let file = g92();
    for cmd in [vec!["expand", file.as_str()], vec!["diff", file.as_str()], vec!["corpus"], vec!["certify", "--out", "/nonexistent/never"]] {
        let o = run(&[&cmd[..], &["--reading", "g95.k=x"]].concat());
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{cmd:?}: {err}");
        assert!(err.contains("g95.k") && err.contains("g94.k, g73.c, g75.relief, g162.lead, thread.zref, g96.rapid"), "{cmd:?}: {err}");
        let o = run(&[&cmd[..], &["--reading", "g73.c=sometimes"]].concat());
        let err = text(&o.stderr);
        assert_eq!(o.status.code(), Some(2), "{cmd:?}: {err}");
        assert!(err.contains("sometimes") && err.contains("visit (the letter), skip"), "{cmd:?}: {err}");
    }
    let o = run(&["expand", &file, "--reading", "g73.c=skip", "--reading", "g73.c=visit"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("--reading g73.c given twice"), "{}", text(&o.stderr));
    let o = run(&["expand", &file, "--reading", "g73.c"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(text(&o.stderr).contains("NAME=VALUE"), "{}", text(&o.stderr));
}

#[test]
fn help_says_the_letter_is_the_default() {
    for cmd in ["expand", "diff", "corpus", "certify"] {
        let o = run(&[cmd, "--help"]);
        let help = text(&o.stdout).split_whitespace().collect::<Vec<_>>().join(" ");
        assert!(help.contains("--reading <NAME=VALUE>") && help.contains("The default is the manuals' letter"), "{cmd}: {help}");
        assert!(help.contains("g94.k = end-minus-start | start-minus-end"), "{cmd}: {help}");
    }
}

/// An in-process certify draws the readings per case, fixes the pinned ones, names them in
/// evidence.json and the page, and counts the cases under each value.
#[test]
fn in_process_evidence_names_drawn_readings_and_counts_them() {
    let out = std::env::temp_dir().join(format!("cyclecheck-readings-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&out);
    let o = run(&["certify", "--out", out.to_str().unwrap(), "--cycles", "g94", "--cases", "40", "--reading", "g75.relief=against-step"]);
    assert_eq!(o.status.code(), Some(0), "{}\n{}", text(&o.stdout), text(&o.stderr));
    assert!(text(&o.stdout).contains("readings: drawn per case, but g75.relief=against-step (--reading)"), "{}", text(&o.stdout));
    let e: serde_json::Value = serde_json::from_slice(&std::fs::read(out.join("evidence.json")).unwrap()).unwrap();
    let r = &e["readings"];
    assert_eq!((r["mode"].as_str(), r["pinned"]["g75.relief"].as_str()), (Some("drawn"), Some("against-step")));
    assert_eq!(r["line"], "readings: drawn per case, but g75.relief=against-step (--reading)");
    assert_eq!(e["parameters"]["readings"]["mode"], "drawn");
    let cases = e["summary"]["cases"].as_u64().unwrap();
    assert_eq!(r["cases"]["g75.relief"]["against-step"].as_u64(), Some(cases));
    for name in ["g94.k", "g73.c", "g162.lead", "thread.zref", "g96.rapid"] {
        let values = r["cases"][name].as_object().unwrap();
        assert_eq!(values.len(), 2, "{name}: {values:?}");
        assert_eq!(values.values().map(|n| n.as_u64().unwrap()).sum::<u64>(), cases, "{name}");
    }
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(html.contains("declared readings") && html.contains("drawn per case") && html.contains("g94.k: end-minus-start "), "no readings row");
    std::fs::remove_dir_all(&out).unwrap();
}
