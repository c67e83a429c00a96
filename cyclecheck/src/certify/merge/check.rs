//! Whether shard bundles can be merged: each is a shard (`parameters.shard`) of the same run —
//! the same build of `cyclecheck` (this one), candidate (command and file hashes), options,
//! seeds and documents — and together they are shards 1/N … N/N, each once.

use super::super::evidence::SCHEMA;
use super::super::identity::{BUILD, LONG_VERSION};
use super::super::shard::Shard;
use serde_json::Value;
use std::path::{Path, PathBuf};

/// A shard bundle's `evidence.json`, read.
pub struct ShardBundle {
    pub dir: PathBuf,
    pub shard: Shard,
    pub doc: Value,
}

/// What must be equal in every shard, as (what it is, JSON pointer into `evidence.json`).
const SAME: [(&str, &str); 10] = [
    ("the cyclecheck build", "/identity/build"),
    ("the cyclecheck build", "/tool"),
    ("the candidate (command, executable and file hashes)", "/identity/candidate"),
    ("the candidate", "/candidate/name"),
    ("the candidate", "/candidate/command"),
    ("the candidate options", "/candidate/timeout_ms"),
    ("the candidate options", "/candidate/max_output_bytes"),
    ("the candidate options", "/candidate/max_failures"),
    ("the comparison level the candidate declared", "/candidate/level"),
    ("the documents compiled in (docs/RULES.md, docs/INTERPRETATION.md)", "/documents"),
];

/// Reads `DIR/evidence.json` of a shard bundle.
pub fn read(dir: &Path) -> Result<ShardBundle, String> {
    let path = dir.join("evidence.json");
    let text = std::fs::read_to_string(&path).map_err(|e| format!("{}: {e} (not an evidence bundle?)", path.display()))?;
    let doc: Value = serde_json::from_str(&text).map_err(|e| format!("{}: not JSON: {e}", path.display()))?;
    if doc["schema"] != SCHEMA {
        return Err(format!("{}: schema {} where this cyclecheck reads {SCHEMA}", path.display(), doc["schema"]));
    }
    let shard = match doc["parameters"]["shard"].as_str() {
        Some(s) => Shard::parse(s).map_err(|e| format!("{}: parameters.shard: {e}", path.display()))?,
        None => return Err(format!("{} is not a shard's bundle (no parameters.shard): run certify --shard K/N", dir.display())),
    };
    Ok(ShardBundle { dir: dir.to_path_buf(), shard, doc })
}

/// The parameters but the shard, and each family's seed and size (not the cases kept).
fn run_parameters(doc: &Value) -> Value {
    let mut p = doc["parameters"].clone();
    if let Some(m) = p.as_object_mut() {
        m.remove("shard");
    }
    let families: Vec<Value> =
        doc["families"].as_array().into_iter().flatten().map(|f| serde_json::json!([f["family"], f["seed"], f["drawn"]])).collect();
    serde_json::json!({ "parameters": p, "families": families })
}

fn differ(what: &str, a: &ShardBundle, b: &ShardBundle, va: &Value, vb: &Value) -> String {
    format!(
        "cannot merge: {} ({}) and {} ({}) differ in {what}:\n  {va}\n  {vb}",
        a.dir.display(),
        a.shard,
        b.dir.display(),
        b.shard
    )
}

/// Checks that `bundles` are the shards 1/N … N/N of one run of this build; sorts them by shard.
pub fn check(bundles: &mut [ShardBundle]) -> Result<(), String> {
    let Some(first) = bundles.first() else { return Err("merge: no bundles given".to_string()) };
    let this_build = serde_json::to_value(BUILD).unwrap_or(Value::Null);
    if first.doc["identity"]["build"] != this_build || first.doc["tool"]["build"] != LONG_VERSION {
        return Err(format!(
            "cannot merge: {} was written by cyclecheck {}, this is cyclecheck {LONG_VERSION}; merge with the build that wrote the shards",
            first.dir.display(),
            first.doc["tool"]["build"]
        ));
    }
    for b in &bundles[1..] {
        for (what, pointer) in SAME {
            let (va, vb) = (first.doc.pointer(pointer), b.doc.pointer(pointer));
            if va != vb {
                return Err(differ(what, first, b, va.unwrap_or(&Value::Null), vb.unwrap_or(&Value::Null)));
            }
        }
        let (pa, pb) = (run_parameters(&first.doc), run_parameters(&b.doc));
        if pa != pb {
            return Err(differ("the run's options or seeds (cycles, cases, seed, families)", first, b, &pa, &pb));
        }
        if b.shard.count != first.shard.count {
            return Err(format!(
                "cannot merge: {} is shard {} and {} is shard {}: shards of different counts",
                first.dir.display(),
                first.shard,
                b.dir.display(),
                b.shard
            ));
        }
    }
    bundles.sort_by_key(|b| b.shard.index);
    for pair in bundles.windows(2) {
        if pair[0].shard == pair[1].shard {
            return Err(format!("cannot merge: shard {} is given twice ({} and {})", pair[0].shard, pair[0].dir.display(), pair[1].dir.display()));
        }
    }
    let count = first_count(bundles);
    let missing: Vec<String> = (1..=count).filter(|k| !bundles.iter().any(|b| b.shard.index == *k)).map(|k| format!("{k}/{count}")).collect();
    if !missing.is_empty() {
        return Err(format!("cannot merge: shard(s) {} missing", missing.join(", ")));
    }
    Ok(())
}

fn first_count(bundles: &[ShardBundle]) -> u32 {
    bundles.first().map_or(0, |b| b.shard.count)
}
