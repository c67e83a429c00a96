//! Tests of the protocol's messages: schemas, requests, greetings, responses.
use super::*;
use cycle_kernel::engine::Engine as _;

#[test]
fn requests_carry_schema_id_program_and_config() {
    let r: serde_json::Value = serde_json::from_str(&request(7, b"G0 X1\n", &Config::default())).unwrap();
    assert_eq!(r["schema"], SCHEMA);
    assert_eq!(r["id"], 7);
    assert_eq!(r["program"], "G0 X1\n");
    assert_eq!(r["config"]["dialect"], "gsk");
    assert_eq!(r["config"]["grid"]["units"], "metric");
    assert_eq!(r["config"]["params"]["no19_pullout"], 10);
    // Every reading, at the letter too; the configuration reads back as it was.
    for (name, value) in Readings::default().pairs() {
        assert_eq!(r["config"]["readings"][name], value, "{name}");
    }
    let mut config = Config::default();
    config.readings.set("g96.rapid", "allow").unwrap();
    let r: serde_json::Value = serde_json::from_str(&request(8, b"G0 X1\n", &config)).unwrap();
    assert_eq!(r["config"]["readings"].as_object().map(|m| m.len()), Some(Readings::NAMES.len()));
    assert_eq!(r["config"]["readings"]["g96.rapid"], "allow");
    let back: Config = serde_json::from_value(r["config"].clone()).unwrap();
    assert_eq!(back, Config { params: cycle_spec::config::params(&config).as_set(), ..config });
    let r: serde_json::Value = serde_json::from_str(&request(1, b"G0\xff", &Config::default())).unwrap();
    assert_eq!(r["program_hex"], "4730ff");
    assert!(r.get("program").is_none());
}

/// Version 3 for the programs that write G73–G75, G80, G83 or G84, else version 2 for an arc
/// or a contour cycle.
#[test]
fn the_schema_follows_the_program() {
    for (program, schema) in [
        (&b"G0 X1\nG92 X1 Z-1 F1\nG90 X1 Z-2 I-1 F1\n"[..], SCHEMA),
        (b"G0 X1 Z1\nG02 X2 Z0 R1 F1\n", SCHEMA_2),
        (b"g3 x2 z0 i1 f1\n", SCHEMA_2),
        (b"G71 U1 R1\n", SCHEMA_2),
        (b"G70 P1 Q2\n", SCHEMA_2),
        (b"G72 W1\n", SCHEMA_2),
        (b"G0 X0 Z2\nG74 R1\n", SCHEMA_3),
        (b"G02 X2 Z0 R1 F1\nG73 U1 W1 R2\n", SCHEMA_3),
        (b"G98 M29 S60\nG84 Z-21 R2 F60\n", SCHEMA_3),
        (b"G83 Z-30 R0.5 Q2000 F0.2\n", SCHEMA_3),
        (b"G75 R1\n", SCHEMA_3),
        (b"G80\n", SCHEMA_3),
        (b"G2.0 X1\n", SCHEMA),
        (b"G32 X1 Z-1 F1\n#\nG02 X1 R1\n", SCHEMA),
    ] {
        assert_eq!(schema_for(program), schema, "{}", String::from_utf8_lossy(program));
    }
}

/// A configuration with an operator script asks for version 4 and carries the script.
#[test]
fn an_operator_script_asks_for_version_4() {
    use cycle_vocab::{Action, Along, Script};
    let script = Script::of(&[Action::Hold(Along { event: 3, num: 1, den: 2 }), Action::Start]).unwrap();
    let config = Config { operator: script, ..Config::default() };
    assert_eq!(schema_for_case(b"G0 X1\n", &config), SCHEMA_4);
    assert_eq!(schema_for_case(b"G0 X1\n", &Config::default()), SCHEMA);
    let r: serde_json::Value = serde_json::from_str(&request(2, b"G0 X1\n", &config)).unwrap();
    assert_eq!(r["schema"], SCHEMA_4);
    assert_eq!(r["config"]["operator"][0]["hold"]["den"], 2);
    assert_eq!(r["config"]["operator"][1], "start");
    let plain: serde_json::Value = serde_json::from_str(&request(3, b"G0 X1\n", &Config::default())).unwrap();
    assert!(plain["config"].get("operator").is_none(), "no script, no field");
}

#[test]
fn responses_are_traces_refusals_or_garbage() {
    let trace = cycle_spec::expand(b"G0 X65 Z5\nG92 X58.7 Z-28 F3\n", &Config::default());
    let ok = format!("{{\"id\":3,\"trace\":{}}}", serde_json::to_string(&trace).unwrap());
    assert_eq!(parse_response(3, ok.as_bytes()), Ok(trace));
    let kind = |id, line: &str| parse_response(id, line.as_bytes()).unwrap_err().kind;
    assert_eq!(kind(3, &ok.replace("G92.PATH", "NO.SUCH.RULE")), FailureKind::Garbage);
    assert_eq!(kind(4, &ok), FailureKind::Garbage);
    assert_eq!(kind(1, "{\"id\":1,\"error\":\"G76 not supported\"}"), FailureKind::Refused);
    for garbage in ["", "hello", "[1]", "{\"id\":1}", "{\"trace\":{}}", "{\"id\":1,\"trace\":{\"x\":1}}"] {
        assert_eq!(kind(1, garbage), FailureKind::Garbage, "{garbage:?}");
    }
    let e = parse_response(1, b"not json at all").unwrap_err();
    assert!(e.message.contains("\"not json at all\""), "{e}");
}

/// The greeting's answers: versions (only those offered count), a refusal (legacy), or
/// garbage.
#[test]
fn the_greeting_is_answered_with_versions_or_refused() {
    let g: serde_json::Value = serde_json::from_str(&hello()).unwrap();
    assert_eq!((g["schema"].as_str(), g["id"].as_u64()), (Some(HELLO), Some(0)));
    assert_eq!(g["versions"], serde_json::json!([1, 2, 3, 4]));
    let speaks = |line: &str| parse_hello(line.as_bytes());
    assert_eq!(speaks(r#"{"id":0,"versions":[1,3,9]}"#), Ok(Speaks { versions: 0b101, pipeline: false, declared: Declared::NONE, level: Level::Full }));
    assert_eq!(speaks(r#"{"id":0,"versions":[],"pipeline":true}"#), Ok(Speaks { versions: 0, pipeline: true, declared: Declared::NONE, level: Level::Full }));
    assert_eq!(speaks(r#"{"id":0,"versions":[1],"level":"motion"}"#).map(|s| s.level), Ok(Level::Motion));
    assert_eq!(speaks(r#"{"id":0,"error":"unsupported schema"}"#), Ok(Speaks::LEGACY));
    for bad in ["", "[]", r#"{"id":1,"versions":[1]}"#, r#"{"id":0,"versions":1}"#, r#"{"id":0,"versions":["1"]}"#, r#"{"id":0}"#,
        r#"{"id":0,"versions":[1],"pipeline":1}"#, r#"{"id":0,"versions":[1],"error":"x"}"#,
        r#"{"id":0,"versions":[1],"level":"moves"}"#, r#"{"id":0,"versions":[1],"level":2}"#] {
        assert_eq!(speaks(bad).map_err(|f| f.kind), Err(FailureKind::Garbage), "{bad}");
    }
    assert_eq!(Speaks { versions: 0b101, pipeline: false, declared: Declared::NONE, level: Level::Full }.list(), "1, 3");
    let declared = speaks(r#"{"id":0,"versions":[1],"readings":{"g94.k":"start-minus-end"}}"#).unwrap().declared;
    assert_eq!(declared.pairs(), vec![("g94.k", "start-minus-end")]);
    // Both additions of the greeting together: a level and readings.
    let both = speaks(r#"{"id":0,"versions":[1],"level":"motion","readings":{"g73.c":"skip"}}"#).unwrap();
    assert_eq!((both.level, both.declared.pairs()), (Level::Motion, vec![("g73.c", "skip")]));
    for bad in [r#"{"id":0,"versions":[1],"readings":{"g95.k":"x"}}"#, r#"{"id":0,"versions":[1],"readings":{"g73.c":"sometimes"}}"#] {
        let f = speaks(bad).unwrap_err();
        assert!(f.kind == FailureKind::Garbage && f.message.contains("\"readings\""), "{f}");
    }
    assert!(!Speaks::LEGACY.speaks(5) && Speaks::LEGACY.speaks(4) && !Speaks::LEGACY.speaks(0));
    assert_eq!((version_of(SCHEMA_3), version_of(HELLO)), (Some(3), None));
}

#[test]
fn a_missing_command_is_a_spawn_failure_every_time() {
    let e = CandidateEngine::new("/nonexistent/candidate --x", Limits::default()).unwrap();
    for _ in 0..2 {
        let f = e.try_expand(b"G0 X1", &Config::default()).unwrap_err();
        assert_eq!(f.kind, FailureKind::Spawn, "{f}");
    }
    assert_eq!(e.starts(), 0);
}
