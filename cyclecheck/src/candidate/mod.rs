//! A vendor's expander as an [`Engine`]: a child process speaking the candidate protocol
//! `cyclecheck-candidate/1` to `/4` (`docs/CANDIDATE.md`); and the production expander speaking
//! it ([`serve`], `cyclecheck serve`).
//!
//! One JSON request per line on the child's stdin — `{"schema", "id", "program" (or
//! "program_hex"), "config"}` — and one JSON response per line on its stdout: `{"id", "trace"}`
//! with the trace exactly as `cyclecheck expand --format json` prints it, or `{"id", "error"}`.
//! Each child is first greeted ([`hello`]): it answers the versions it speaks, and whether it
//! takes requests pipelined, or refuses the greeting (a legacy candidate).
//!
//! The child is hostile until proven otherwise:
//! - the command line is split here ([`split_command`]) and executed directly, never through a
//!   shell, and programs travel inside JSON strings, never on a command line;
//! - each case has a timeout and an output cap ([`Limits`]);
//! - a timeout, a crash, garbage, an oversized answer become that case's [`Failure`]; the child
//!   is killed and a fresh one started for the next case, so a campaign always goes on;
//! - stdin and stdout are served by their own threads, so a child that neither reads nor writes
//!   cannot block the harness; the last few KiB of its stderr are kept for crash reports;
//! - the child runs in a process group of its own, killed whole — with anything it started —
//!   after a failure, at the end of the run and on SIGINT/SIGTERM ([`crate::reaper`]).

use cycle_kernel::conformance::Level;
use cycle_kernel::engine::{Failure, FailureKind};
use cycle_kernel::readings::Declared;
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Dialect, Grid, Params, Readings, Script};
use serde::{Deserialize, Serialize};
use std::time::Duration;

mod child;
mod engine;
mod serve;
mod split;
mod wire;
pub use engine::{CandidateEngine, WINDOW};
pub use serve::serve;
pub use split::split_command;

/// The protocol's first schema version: the thread cycles' events (rapids, feeds, thread moves,
/// ROUGH/FINISH/SPRING passes).
pub const SCHEMA: &str = "cyclecheck-candidate/1";
/// The second: version 1 and arcs (`arc_cw`, `arc_ccw` with `cx`, `cz`), SEMI passes and the
/// contour alarms (`BLOCK_NOT_FOUND`, `CONTOUR_TOO_LONG`) — what G02/G03 and G70–G72 produce.
pub const SCHEMA_2: &str = "cyclecheck-candidate/2";

/// The third: version 2 and the dwell and spindle events (`{"event": "dwell", ms, rule}`,
/// `{"event": "spindle", state, rule}`) — what G73, G74, G75, G83 and G84 produce (G73 and the
/// peck cycles need no new event, but a version-2 candidate may not know their codes: the
/// version says which codes a request can hold).
pub const SCHEMA_3: &str = "cyclecheck-candidate/3";

/// The fourth: version 3 and operator events — `config.operator`, the script (OP.SCRIPT), and
/// the events `press`, `stop`, `resume` and the alarm `OPERATOR` (3005). A request carries it
/// whenever its configuration has a script, whatever the program; a candidate that does not
/// model operator events refuses it and the case is reported as refused, not as a divergence.
pub const SCHEMA_4: &str = "cyclecheck-candidate/4";

/// The schema a case's request carries: version 4 when the configuration has an operator
/// script, else the program's ([`schema_for`]).
pub fn schema_for_case(program: &[u8], config: &Config) -> &'static str {
    if config.operator.is_empty() {
        schema_for(program)
    } else {
        SCHEMA_4
    }
}

/// The schema a program's request carries: version 3 when a block of it writes G73, G74, G75,
/// G80, G83 or G84, else version 2 when one writes G02, G03, G70, G71 or G72 (read with the
/// reference's lexer, up to its first lexing alarm), else version 1 — so a candidate that
/// speaks an earlier version still runs every family of that version, and refuses (never
/// silently misreads) the programs whose traces need a later one.
// The request is written before the judge runs (so before its sighting): the protocol
// version a program needs is read here, on the candidate's side of the run.
#[allow(clippy::disallowed_methods)]
pub fn schema_for(program: &[u8]) -> &'static str {
    let mut version = 1;
    for b in cycle_spec::lex::blocks(program).map_while(Result::ok) {
        for g in b.g_codes().filter(|g| !g.point && !g.negative) {
            match g.to_string().as_str() {
                "73" | "74" | "75" | "80" | "83" | "84" => return SCHEMA_3,
                "2" | "3" | "70" | "71" | "72" => version = 2,
                _ => {}
            }
        }
    }
    if version == 2 {
        SCHEMA_2
    } else {
        SCHEMA
    }
}

/// How much of a garbage answer a report quotes.
const SNIPPET: usize = 200;

/// Per-case limits on a candidate.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Limits {
    /// How long one case may take, from sending the request to the end of the answer line.
    pub timeout: Duration,
    /// The most bytes one answer line may have.
    pub max_output: usize,
}

impl Limits {
    /// 10 s per case, in ms.
    pub const DEFAULT_TIMEOUT_MS: u64 = 10_000;
    pub const DEFAULT_TIMEOUT: Duration = Duration::from_millis(Limits::DEFAULT_TIMEOUT_MS);
    /// 64 MiB per answer (a trace of ~500 000 events).
    pub const DEFAULT_MAX_OUTPUT: usize = 64 << 20;
}

impl Default for Limits {
    fn default() -> Limits {
        Limits { timeout: Limits::DEFAULT_TIMEOUT, max_output: Limits::DEFAULT_MAX_OUTPUT }
    }
}

/// The version number of a schema name (`cyclecheck-candidate/3` → 3), if it is one of ours.
pub fn version_of(schema: &str) -> Option<u8> {
    [SCHEMA, SCHEMA_2, SCHEMA_3, SCHEMA_4].iter().position(|s| *s == schema).map(|i| i as u8 + 1)
}

/// A request's configuration: `Config`'s fields as it serializes them, but `readings` always
/// written with every reading (the letter too), so a candidate knows what it is judged against.
#[derive(Serialize)]
struct WireConfig<'a> {
    dialect: Dialect,
    grid: Grid,
    params: &'a Params,
    start_x: i64,
    start_z: i64,
    #[serde(skip_serializing_if = "no_script")]
    operator: &'a Script,
    readings: &'a Readings,
}

fn no_script(s: &&Script) -> bool {
    s.is_empty()
}

/// The request line for case `id` (without the newline). The program goes as `program` when it
/// is UTF-8, else as `program_hex` (two lowercase hex digits per byte). Every parameter is
/// named: those the configuration leaves unset with the reference's defaults; every declared
/// reading is named, those at the letter too.
pub fn request(id: u64, program: &[u8], config: &Config) -> String {
    #[derive(Serialize)]
    struct Request<'a> {
        schema: &'static str,
        id: u64,
        config: WireConfig<'a>,
        #[serde(skip_serializing_if = "Option::is_none")]
        program: Option<&'a str>,
        #[serde(skip_serializing_if = "Option::is_none")]
        program_hex: Option<String>,
    }
    let config = Config { params: cycle_spec::config::params(config).as_set(), ..*config };
    let text = std::str::from_utf8(program).ok();
    let program_hex = text.is_none().then(|| program.iter().map(|b| format!("{b:02x}")).collect());
    let wire = WireConfig {
        dialect: config.dialect,
        grid: config.grid,
        params: &config.params,
        start_x: config.start_x,
        start_z: config.start_z,
        operator: &config.operator,
        readings: &config.readings,
    };
    let req = Request { schema: schema_for_case(program, &config), id, config: wire, program: text, program_hex };
    serde_json::to_string(&req).expect("a request serializes")
}

/// The schema of the greeting ([`hello`]) and of its answer.
pub const HELLO: &str = "cyclecheck-candidate/hello";

/// The versions this build speaks, offered in the greeting.
pub const VERSIONS: [u8; 4] = [1, 2, 3, 4];

/// The greeting sent first to every child (id 0, which no case has):
/// `{"schema":"cyclecheck-candidate/hello","id":0,"versions":[1,2,3,4]}`.
pub fn hello() -> String {
    serde_json::json!({ "schema": HELLO, "id": 0, "versions": VERSIONS }).to_string()
}

/// What a child said to the greeting.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Speaks {
    /// Bit v − 1 set for each version v it speaks (of those offered).
    pub versions: u8,
    /// Whether it takes several requests before answering the first (answering in order).
    pub pipeline: bool,
    /// The declared readings it follows (`"readings"`; undeclared: the letter).
    pub declared: Declared,
    /// What its traces hold, so what is compared (`"level"`, [`Level::Full`] when absent).
    pub level: Level,
}

impl Speaks {
    /// A legacy candidate (it refused the greeting): sent every version, one request at a time,
    /// judged against the letter.
    pub const LEGACY: Speaks = Speaks { versions: 0b1111, pipeline: false, declared: Declared::NONE, level: Level::Full };

    pub fn speaks(self, version: u8) -> bool {
        (1..=8).contains(&version) && self.versions & (1 << (version - 1)) != 0
    }

    /// The versions, as a list for a report: `1, 2`.
    pub fn list(self) -> String {
        let v: Vec<String> = VERSIONS.iter().filter(|&&v| self.speaks(v)).map(u8::to_string).collect();
        if v.is_empty() {
            "none".to_string()
        } else {
            v.join(", ")
        }
    }
}

/// Reads the answer to the greeting: `{"id": 0, "versions": [..], "pipeline": bool, "readings":
/// {name: value, …}, "level": name}` (versions not offered are ignored; `pipeline` defaults to
/// false; `readings`, the declared readings the candidate follows, to none: the letter; `level`
/// to `full`), or a refusal `{"id": 0, "error"}` — a legacy candidate, [`Speaks::LEGACY`].
/// Anything else — an unknown reading, value or level too — is garbage.
pub fn parse_hello(line: &[u8]) -> Result<Speaks, Failure> {
    let garbage = |why: &str| Failure { kind: FailureKind::Garbage, message: format!("{why}; answer: {}", snippet(line)) };
    let value: serde_json::Value = serde_json::from_slice(line).map_err(|e| garbage(&format!("not JSON ({e})")))?;
    let Some(object) = value.as_object() else { return Err(garbage("not a JSON object")) };
    if object.get("id").and_then(serde_json::Value::as_u64) != Some(0) {
        return Err(garbage("the greeting's \"id\" is 0"));
    }
    match (object.get("versions"), object.get("error")) {
        (None, Some(_)) => Ok(Speaks::LEGACY),
        (Some(serde_json::Value::Array(list)), None) => {
            let mut versions = 0u8;
            for v in list {
                match v.as_u64() {
                    Some(v) if VERSIONS.contains(&(v as u8)) && v <= 8 => versions |= 1 << (v - 1),
                    Some(_) => {}
                    None => return Err(garbage("\"versions\" lists integers")),
                }
            }
            let pipeline = match object.get("pipeline") {
                None => false,
                Some(p) => p.as_bool().ok_or_else(|| garbage("\"pipeline\" is true or false"))?,
            };
            let declared = Declared::parse(object.get("readings")).map_err(|e| garbage(&e))?;
            let level = match object.get("level") {
                None => Level::Full,
                Some(l) => l.as_str().ok_or_else(|| garbage("\"level\" is a level's name")).and_then(|l| Level::parse(l).map_err(|e| garbage(&e)))?,
            };
            Ok(Speaks { versions, pipeline, declared, level })
        }
        _ => Err(garbage("exactly one of \"versions\" (a list) and \"error\" expected")),
    }
}

/// Reads the answer line to request `id`: the trace, or the failure it amounts to.
pub fn parse_response(id: u64, line: &[u8]) -> Result<Trace, Failure> {
    if let Some((got, trace)) = usual_answer(line) {
        if got == id {
            return Ok(trace);
        }
    }
    let garbage = |why: String| Failure { kind: FailureKind::Garbage, message: format!("{why}; answer: {}", snippet(line)) };
    let value: serde_json::Value = serde_json::from_slice(line).map_err(|e| garbage(format!("not JSON ({e})")))?;
    let Some(object) = value.as_object() else {
        return Err(garbage("not a JSON object".to_string()));
    };
    match object.get("id").and_then(serde_json::Value::as_u64) {
        Some(got) if got == id => {}
        Some(got) => return Err(garbage(format!("answer to request {got}, expected {id}"))),
        None => return Err(garbage("no numeric \"id\"".to_string())),
    }
    match (object.get("trace"), object.get("error")) {
        (Some(trace), None) => {
            serde_json::from_value(trace.clone()).map_err(|e| garbage(format!("\"trace\" is not a trace ({e})")))
        }
        (None, Some(error)) => Err(Failure {
            kind: FailureKind::Refused,
            message: error.as_str().map_or_else(|| error.to_string(), str::to_string),
        }),
        _ => Err(garbage("exactly one of \"trace\" and \"error\" expected".to_string())),
    }
}

/// The usual answer, `{"id", "trace"}` and nothing else, read straight into its id and trace;
/// anything else is left to [`parse_response`]'s long way, which says what is wrong.
pub(crate) fn usual_answer(line: &[u8]) -> Option<(u64, Trace)> {
    #[derive(Deserialize)]
    #[serde(deny_unknown_fields)]
    struct Answer {
        id: u64,
        trace: Trace,
    }
    wire::read(line).or_else(|| serde_json::from_slice::<Answer>(line).ok().map(|a| (a.id, a.trace)))
}

/// The start of `bytes`, as lossy text, for a report.
fn snippet(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(&bytes[..bytes.len().min(SNIPPET)]).into_owned();
    if bytes.len() > SNIPPET {
        format!("{text:?}… ({} bytes)", bytes.len())
    } else {
        format!("{text:?}")
    }
}

#[cfg(test)]
mod tests;
