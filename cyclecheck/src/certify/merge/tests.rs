//! merge(shards 1/4 … 4/4) is the unsharded run, with a planted bug; bundles that are not the
//! shards of one run are refused.

use super::super::{bundle, run_engine, Options};
use super::{merge, Request};
use cycle_kernel::engine::{Engine, SpecEngine};
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Event};
use serde_json::Value;
use std::path::{Path, PathBuf};

/// The planted bug: the spec with X one increment off on every third move, panicking on
/// programs whose length is a multiple of 11 — several divergence groups (one per rule) and
/// failures.
struct Planted;

impl Engine for Planted {
    fn name(&self) -> &str {
        "planted"
    }
    fn expand(&self, program: &[u8], config: &Config) -> Trace {
        assert!(!program.len().is_multiple_of(11), "planted panic");
        let mut t = cycle_spec::expand(program, config);
        for (i, e) in t.events.iter_mut().enumerate() {
            if let Event::Move(m) = e {
                m.x += i64::from(i % 3 == 2);
            }
        }
        t
    }
}

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cyclecheck-merge-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Certifies into `out` as the CLI does, against `engine`.
fn certify(options: &Options, engine: &dyn Engine, out: &Path) {
    let staging = bundle::Staging::create(out).unwrap();
    let mut cases = std::io::BufWriter::new(staging.create_file("cases.jsonl").unwrap());
    let plan = super::super::readings_plan::Plan::drawn(options.readings.clone());
    let run = run_engine(options, &plan, engine, None, &mut cases, &mut |_| {}).unwrap();
    drop(cases);
    for (rel, contents) in bundle::files(&run) {
        staging.write(&rel, &contents).unwrap();
    }
    staging.commit().unwrap();
}

fn evidence(dir: &Path) -> Value {
    serde_json::from_str(&std::fs::read_to_string(dir.join("evidence.json")).unwrap()).unwrap()
}

/// The fields that legitimately differ between a merged bundle and the unsharded one, removed:
/// start time and host, duration, candidate process starts, the z3 lemmas' times, the shards.
fn without_run_specifics(mut doc: Value) -> Value {
    for pointer in ["/identity", "/summary", "/candidate", ""] {
        let Some(Value::Object(m)) = doc.pointer_mut(pointer) else { panic!("no {pointer}") };
        for key in ["started_utc", "host", "duration_s", "process_starts", "merged_from"] {
            m.remove(key);
        }
    }
    fn drop_seconds(v: &mut Value) {
        match v {
            Value::Object(m) => {
                m.remove("seconds");
                m.values_mut().for_each(drop_seconds);
            }
            Value::Array(a) => a.iter_mut().for_each(drop_seconds),
            _ => {}
        }
    }
    drop_seconds(&mut doc["proofs"]);
    doc
}

fn shards(options: &Options, root: &Path, n: u32) -> Vec<PathBuf> {
    (1..=n)
        .map(|k| {
            let dir = root.join(format!("shard-{k}"));
            let shard = Some(super::super::shard::Shard { index: k, count: n });
            certify(&Options { shard, ..options.clone() }, &Planted, &dir);
            dir
        })
        .collect()
}

#[test]
fn merged_shards_are_the_unsharded_run() {
    let root = tmp("equal");
    let options = Options { cases: 12, ..Options::default() };
    certify(&options, &Planted, &root.join("whole"));
    let parts = shards(&options, &root, 4);
    assert_eq!(evidence(&parts[2])["parameters"]["shard"], "3/4");
    // Given in any order.
    let bundles = vec![parts[3].clone(), parts[0].clone(), parts[2].clone(), parts[1].clone()];
    let merged = merge(&Request { bundles, out: root.join("merged"), kani_log: None }).unwrap();
    let (whole, joined) = (evidence(&root.join("whole")), evidence(&root.join("merged")));
    let summary = &whole["summary"];
    assert_eq!(summary["passed"], false);
    assert!(summary["divergence_groups"].as_u64().unwrap() >= 3, "{summary}");
    assert!(summary["fail"].as_u64().unwrap() >= 1 && summary["conform"].as_u64().unwrap() >= 1, "{summary}");
    assert_eq!(joined["merged_from"].as_array().map(Vec::len), Some(4));
    assert_eq!(merged.cases(), summary["cases"].as_u64().unwrap() as usize);
    for key in ["by_cycle", "by_rule", "divergences", "failures", "matrix", "families", "configurations", "readings"] {
        assert_eq!(joined[key], whole[key], "{key} differs");
    }
    assert_eq!(without_run_specifics(joined), without_run_specifics(whole));
    let read = |dir: &str, file: &str| std::fs::read(root.join(dir).join(file)).unwrap();
    assert_eq!(read("merged", "cases.jsonl"), read("whole", "cases.jsonl"), "cases.jsonl, line for line");
    assert_eq!(read("merged", "plots/g92_example.svg"), read("whole", "plots/g92_example.svg"));
    let page = String::from_utf8(read("merged", "index.html")).unwrap();
    assert!(page.contains("merged from 4 shards"), "the page names its shards");
    std::fs::remove_dir_all(&root).unwrap();
}

#[test]
fn bundles_of_different_runs_or_missing_shards_are_refused() {
    let root = tmp("refuse");
    let options = Options { cycles: Options::parse_cycles("g92").unwrap(), cases: 8, ..Options::default() };
    let parts = shards(&options, &root, 3);
    let other_seed = root.join("other-seed");
    let shard = Some(super::super::shard::Shard { index: 3, count: 3 });
    certify(&Options { seed: 7, shard, ..options.clone() }, &Planted, &other_seed);
    let whole = root.join("whole");
    certify(&options, &SpecEngine, &whole);
    let other_build = root.join("other-build");
    certify(&Options { shard, ..options.clone() }, &Planted, &other_build);
    let mut doc = evidence(&other_build);
    doc["identity"]["build"]["commit"] = "0000000000000000000000000000000000000000".into();
    std::fs::write(other_build.join("evidence.json"), doc.to_string()).unwrap();
    let attempt = |bundles: Vec<&PathBuf>| {
        let out = root.join("out");
        merge(&Request { bundles: bundles.into_iter().cloned().collect(), out, kani_log: None }).map(|_| ()).unwrap_err()
    };
    let [a, b, c] = [&parts[0], &parts[1], &parts[2]];
    assert!(attempt(vec![a, b]).contains("shard(s) 3/3 missing"));
    assert!(attempt(vec![a, b, b, c]).contains("shard 2/3 is given twice"));
    assert!(attempt(vec![a, b, &other_seed]).contains("differ in the run's options or seeds"));
    assert!(attempt(vec![&other_build, a, b]).contains("was written by cyclecheck"));
    assert!(attempt(vec![a, b, &other_build]).contains("differ in the cyclecheck build"));
    assert!(attempt(vec![a, &whole]).contains("is not a shard's bundle"));
    assert!(!root.join("out").exists(), "a refused merge writes nothing");
    std::fs::remove_dir_all(&root).unwrap();
}

/// A divergence below the `full` level (indexed among the moves, its level named) reads back
/// from a shard's JSON as it was written.
#[test]
fn a_motion_level_divergence_reads_back() {
    use cycle_kernel::conformance::{to_json, Level, Lockstep};
    let c = Config::default();
    let reference = cycle_spec::expand(b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n", &c);
    let mut moves: Vec<Event> = reference.events.iter().copied().filter(|e| matches!(e, Event::Move(_))).collect();
    if let Event::Move(m) = &mut moves[3] {
        m.z += 1;
    }
    let mut lockstep = Lockstep::new(c.grid, c.grid, moves.into_iter().map(Ok)).at_level(Level::Motion);
    reference.events.iter().for_each(|&e| lockstep.reference(e));
    let d = lockstep.finish(reference.alarm).unwrap_err();
    assert_eq!((d.index, d.level, d.field), (3, Level::Motion, Some("z")));
    assert_eq!(super::read::divergence(&to_json(&d)), Ok(d));
}
