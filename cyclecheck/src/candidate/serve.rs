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
mod tests;
