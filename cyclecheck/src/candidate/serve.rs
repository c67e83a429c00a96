//! `cyclecheck serve`: the production expander (`cycle_impl::Expander`) answering the candidate
//! protocol — a reference peer for vendors' own harnesses, and the compiled candidate whose rate
//! `cyclecheck bench-harness` measures.
//!
//! It answers the greeting with every version it speaks of those offered and `"pipeline":
//! true`, each request of a version it speaks with the trace, anything else with an error. It
//! reads ahead: answers are written when no further request is waiting in its input buffer, so
//! pipelined requests are answered in batches.

use super::{version_of, HELLO, VERSIONS};
use cycle_vocab::text::Trace;
use cycle_vocab::Config;
use serde::{Deserialize, Serialize};
use std::io::{BufRead, BufReader, Read, Write};

/// One request line, as far as `serve` reads it (other fields are ignored).
#[derive(Deserialize)]
struct Incoming {
    #[serde(default)]
    schema: String,
    id: u64,
    #[serde(default)]
    versions: Vec<u64>,
    program: Option<String>,
    program_hex: Option<String>,
    config: Option<Config>,
}

#[derive(Serialize)]
struct Answer<'a> {
    id: u64,
    trace: &'a Trace,
}

/// Serves requests from `input` until it ends, answering on `output`.
pub fn serve<R: Read, W: Write>(input: R, output: W) -> std::io::Result<()> {
    let mut input = BufReader::with_capacity(1 << 16, input);
    let mut output = std::io::BufWriter::with_capacity(1 << 16, output);
    let mut line = Vec::new();
    loop {
        if input.buffer().is_empty() {
            output.flush()?;
        }
        line.clear();
        if input.read_until(b'\n', &mut line)? == 0 {
            return output.flush();
        }
        if line.iter().all(u8::is_ascii_whitespace) {
            continue;
        }
        answer(&line, &mut output)?;
        output.write_all(b"\n")?;
    }
}

/// Writes the answer to one request line (without the newline).
fn answer(line: &[u8], out: &mut impl Write) -> std::io::Result<()> {
    let refuse = |out: &mut dyn Write, id: u64, why: String| serde_json::to_writer(out, &serde_json::json!({ "id": id, "error": why }));
    let req: Incoming = match serde_json::from_slice(line) {
        Ok(req) => req,
        Err(e) => {
            let id = serde_json::from_slice::<serde_json::Value>(line).ok().and_then(|v| v["id"].as_u64()).unwrap_or(0);
            return refuse(out, id, format!("bad request: {e}")).map_err(std::io::Error::from);
        }
    };
    if req.schema == HELLO {
        let versions: Vec<u8> = VERSIONS.into_iter().filter(|v| req.versions.contains(&u64::from(*v))).collect();
        let hello = serde_json::json!({ "schema": HELLO, "id": req.id, "versions": versions, "pipeline": true });
        return serde_json::to_writer(out, &hello).map_err(std::io::Error::from);
    }
    if version_of(&req.schema).is_none() {
        let why = format!("unsupported schema {:?} (cyclecheck serve speaks versions 1 to {})", req.schema, VERSIONS.len());
        return refuse(out, req.id, why).map_err(std::io::Error::from);
    }
    let program = match (req.program, req.program_hex.as_deref().map(unhex)) {
        (Some(text), None) => text.into_bytes(),
        (None, Some(Some(bytes))) => bytes,
        _ => return refuse(out, req.id, "one of \"program\" and \"program_hex\" (hex digit pairs) expected".into()).map_err(std::io::Error::from),
    };
    let Some(config) = req.config else {
        return refuse(out, req.id, "no \"config\"".into()).map_err(std::io::Error::from);
    };
    let trace = Trace::collect(config.grid, cycle_impl::Expander::new(&program, config));
    serde_json::to_writer(out, &Answer { id: req.id, trace: &trace }).map_err(std::io::Error::from)
}

/// The bytes of a `program_hex`, if it is pairs of hex digits.
fn unhex(text: &str) -> Option<Vec<u8>> {
    let pairs = text.as_bytes().chunks_exact(2);
    if !pairs.remainder().is_empty() {
        return None;
    }
    pairs.map(|p| std::str::from_utf8(p).ok().and_then(|p| u8::from_str_radix(p, 16).ok())).collect()
}

#[cfg(test)]
mod tests {
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
}
