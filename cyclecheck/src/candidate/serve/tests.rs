use super::super::{hello, parse_hello, parse_response, request, Speaks};
use super::*;

fn served(lines: &[String]) -> Vec<String> {
    let input: String = lines.iter().map(|l| format!("{l}\n")).collect();
    let mut out = Vec::new();
    serve(input.as_bytes(), &mut out).unwrap();
    String::from_utf8(out).unwrap().lines().map(str::to_string).collect()
}

/// The greeting, then requests of each kind answered in order with the production
/// expander's traces; what it cannot serve is refused.
#[test]
fn serves_the_protocol_in_order() {
    let c = Config::default();
    let g92 = b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n";
    let arcs = b"G0 X1 Z1\nG02 X2 Z0 R1 F1\n";
    let garbage = b"G0\xff X1\n";
    let requests = [hello(), request(1, g92, &c), request(2, arcs, &c), request(3, garbage, &c)];
    let mut odd = request(4, g92, &c).replace("cyclecheck-candidate/1", "cyclecheck-candidate/9");
    odd.push_str("\n{\"id\": 5, \"schema\": \"cyclecheck-candidate/1\"}\nnot json");
    let answers = served(&[&requests[..], &[odd]].concat());
    assert_eq!(answers.len(), 7, "{answers:?}");
    assert_eq!(parse_hello(answers[0].as_bytes()), Ok(Speaks { versions: 0b1111, pipeline: true, declared: cycle_kernel::readings::Declared::NONE, level: cycle_kernel::conformance::Level::Full }));
    for (i, program) in [&g92[..], arcs, garbage].into_iter().enumerate() {
        let expected = Trace::collect(c.grid, cycle_impl::Expander::new(program, c));
        assert_eq!(parse_response(i as u64 + 1, answers[i + 1].as_bytes()), Ok(expected));
    }
    assert!(answers[4].contains("unsupported schema") && answers[4].contains("\"id\":4"), "{}", answers[4]);
    assert_eq!(parse_response(5, answers[5].as_bytes()).unwrap_err().kind, cycle_kernel::engine::FailureKind::Refused);
    assert!(answers[6].contains("\"id\":0") && answers[6].contains("bad request"), "{}", answers[6]);
}

/// The greeting's answer lists only the versions offered.
#[test]
fn answers_only_the_versions_offered() {
    let answers = served(&["{\"schema\":\"cyclecheck-candidate/hello\",\"id\":0,\"versions\":[2,4,7]}".to_string()]);
    assert_eq!(parse_hello(answers[0].as_bytes()), Ok(Speaks { versions: 0b1010, pipeline: true, declared: cycle_kernel::readings::Declared::NONE, level: cycle_kernel::conformance::Level::Full }));
    assert_eq!(unhex("4730ff"), Some(vec![0x47, 0x30, 0xff]));
    assert_eq!(unhex("473"), None);
    assert_eq!(unhex("zz"), None);
}

/// `serve` takes every reading from the request's configuration.
#[test]
fn takes_the_readings_from_each_request() {
    let mut c = Config::default();
    c.readings.set("g94.k", "start-minus-end").unwrap();
    c.readings.set("thread.zref", "groove").unwrap();
    let line = request(4, b"G0 X1\n", &c);
    let req: Incoming = serde_json::from_str(&line).unwrap();
    assert_eq!(req.config.map(|r| r.readings), Some(c.readings));
    let letter: Incoming = serde_json::from_str(&request(5, b"G0 X1\n", &Config::default())).unwrap();
    assert!(letter.config.unwrap().readings.is_letter());
}
