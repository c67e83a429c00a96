use super::*;
use serde_json::{json, Value};

/// The derived reading, for comparison.
fn derived(line: &str) -> Option<(u64, Trace)> {
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    struct Answer {
        id: u64,
        trace: Trace,
    }
    serde_json::from_str::<Answer>(line).ok().map(|a| (a.id, a.trace))
}

/// Every corpus program's trace reads back the same; and where a changed answer is read
/// at all, it is read as the derived reading reads it.
#[test]
fn reads_what_the_derived_reading_reads() {
    let mut kinds = std::collections::BTreeSet::new();
    for (name, program, config) in cycle_kernel::corpus::cases() {
        let trace = Trace::collect(config.grid, cycle_impl::Expander::new(&program, config));
        let line = serde_json::to_string(&json!({ "id": 3, "trace": trace })).unwrap();
        assert_eq!(read(line.as_bytes()), Some((3, trace.clone())), "{name}");
        let doc: Value = serde_json::from_str(&line).unwrap();
        for (i, e) in doc["trace"]["events"].as_array().unwrap().iter().enumerate().take(12) {
            kinds.insert(e["event"].as_str().unwrap().to_string());
            for key in e.as_object().unwrap().keys().cloned().chain(["x", "index", "bogus", "ms"].map(String::from)) {
                for value in [None, Some(Value::Null), Some(json!(1)), Some(json!("ROUGH")), Some(json!(-1))] {
                    let mut d = doc.clone();
                    let event = d["trace"]["events"][i].as_object_mut().unwrap();
                    match &value {
                        None => event.remove(&key),
                        Some(v) => event.insert(key.clone(), v.clone()),
                    };
                    let changed = serde_json::to_string(&d).unwrap();
                    if let Some(fast) = read(changed.as_bytes()) {
                        assert_eq!(Some(fast), derived(&changed), "{name}: event {i}, {key} = {value:?}");
                    }
                }
            }
        }
    }
    assert!(kinds.len() >= 4, "{kinds:?}");
}
