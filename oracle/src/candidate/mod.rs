//! A vendor's expander as an [`Engine`]: a child process speaking the candidate protocol
//! `cyclecheck-candidate/1` (`docs/CANDIDATE.md`).
//!
//! One JSON request per line on the child's stdin — `{"schema", "id", "program" (or
//! "program_hex"), "config"}` — and one JSON response per line on its stdout: `{"id", "trace"}`
//! with the trace exactly as `cyclecheck expand --format json` prints it, or `{"id", "error"}`.
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

use crate::engine::{Engine, Failure, FailureKind};
use cycle_vocab::text::Trace;
use cycle_vocab::Config;
use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::process::CommandExt as _;
use std::process::{Child, ChildStdout, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::time::Duration;

mod split;
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

/// How much of the child's stderr is kept for reports (the last bytes).
const STDERR_TAIL: usize = 4096;

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

/// The request line for case `id` (without the newline). The program goes as `program` when it
/// is UTF-8, else as `program_hex` (two lowercase hex digits per byte). Every parameter is
/// named: those the configuration leaves unset with the reference's defaults.
pub fn request(id: u64, program: &[u8], config: &Config) -> String {
    let config = Config { params: cycle_spec::config::params(config).as_set(), ..*config };
    let mut req = serde_json::json!({ "schema": schema_for_case(program, &config), "id": id, "config": config });
    match std::str::from_utf8(program) {
        Ok(text) => req["program"] = text.into(),
        Err(_) => req["program_hex"] = program.iter().map(|b| format!("{b:02x}")).collect::<String>().into(),
    }
    req.to_string()
}

/// Reads the answer line to request `id`: the trace, or the failure it amounts to.
pub fn parse_response(id: u64, line: &[u8]) -> Result<Trace, Failure> {
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

/// The start of `bytes`, as lossy text, for a report.
fn snippet(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(&bytes[..bytes.len().min(SNIPPET)]).into_owned();
    if bytes.len() > SNIPPET {
        format!("{text:?}… ({} bytes)", bytes.len())
    } else {
        format!("{text:?}")
    }
}

/// What the stdout thread saw.
enum Line {
    /// One answer line, without its newline.
    Text(Vec<u8>),
    /// A line longer than the cap (the thread stops reading).
    TooLong(usize),
    /// End of output (the child exited or closed stdout), or a read error.
    End(String),
}

/// Reads lines of at most `cap` bytes and sends them; stops at the end, an error or an
/// oversized line.
fn read_lines(stdout: ChildStdout, cap: usize, lines: Sender<Line>) {
    let mut reader = BufReader::new(stdout);
    loop {
        let mut line = Vec::new();
        loop {
            let buf = match reader.fill_buf() {
                Ok(buf) => buf,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(e) => {
                    let _ = lines.send(Line::End(format!("read error: {e}")));
                    return;
                }
            };
            if buf.is_empty() {
                let _ = lines.send(Line::End("end of output".to_string()));
                return;
            }
            let (take, done) = match buf.iter().position(|&b| b == b'\n') {
                Some(i) => (i + 1, true),
                None => (buf.len(), false),
            };
            line.extend_from_slice(&buf[..take]);
            reader.consume(take);
            if line.len() > cap.saturating_add(2) {
                let _ = lines.send(Line::TooLong(line.len()));
                return;
            }
            if done {
                break;
            }
        }
        while matches!(line.last(), Some(b'\n' | b'\r')) {
            line.pop();
        }
        if lines.send(Line::Text(line)).is_err() {
            return;
        }
    }
}

/// A running child and its three pipe threads.
struct Running {
    child: Child,
    requests: Option<Sender<Vec<u8>>>,
    lines: Receiver<Line>,
    stderr: Arc<Mutex<Vec<u8>>>,
}

impl Running {
    fn start(argv: &[String], limits: Limits) -> Result<Running, Failure> {
        let mut child = Command::new(&argv[0])
            .args(&argv[1..])
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .process_group(0)
            .spawn()
            .map_err(|e| Failure { kind: FailureKind::Spawn, message: format!("cannot start {:?}: {e}", argv[0]) })?;
        crate::reaper::register_group(child.id());
        let (Some(mut stdin), Some(stdout), Some(mut stderr_pipe)) = (child.stdin.take(), child.stdout.take(), child.stderr.take()) else {
            crate::reaper::kill_group(child.id());
            let _ = child.wait();
            return Err(Failure { kind: FailureKind::Spawn, message: "no pipes to the child".to_string() });
        };
        let (requests, to_write) = mpsc::channel::<Vec<u8>>();
        std::thread::spawn(move || {
            for line in to_write {
                if stdin.write_all(&line).and_then(|()| stdin.flush()).is_err() {
                    return;
                }
            }
        });
        let (send_line, lines) = mpsc::channel();
        let cap = limits.max_output;
        std::thread::spawn(move || read_lines(stdout, cap, send_line));
        let stderr = Arc::new(Mutex::new(Vec::new()));
        let tail = Arc::clone(&stderr);
        std::thread::spawn(move || {
            let mut buf = [0u8; 4096];
            while let Ok(n @ 1..) = stderr_pipe.read(&mut buf) {
                if let Ok(mut t) = tail.lock() {
                    t.extend_from_slice(&buf[..n]);
                    let excess = t.len().saturating_sub(STDERR_TAIL);
                    t.drain(..excess);
                }
            }
        });
        Ok(Running { child, requests: Some(requests), lines, stderr })
    }

    /// The last lines the child wrote to stderr, if any.
    fn stderr_tail(&self) -> String {
        let tail = self.stderr.lock().map(|t| String::from_utf8_lossy(&t).trim().to_string()).unwrap_or_default();
        if tail.is_empty() {
            String::new()
        } else {
            format!("; stderr: {tail}")
        }
    }

    /// Kills the child's process group (the child and whatever it started) and reaps the child.
    fn stop(mut self) {
        self.requests = None;
        crate::reaper::kill_group(self.child.id());
        let _ = self.child.wait();
    }
}

/// The candidate engine: one child at a time, restarted after any failure.
pub struct CandidateEngine {
    argv: Vec<String>,
    limits: Limits,
    state: Mutex<State>,
}

#[derive(Default)]
struct State {
    running: Option<Running>,
    next_id: u64,
    starts: u64,
}

impl CandidateEngine {
    /// An engine for `command` (split by [`split_command`]); the child starts at the first case.
    pub fn new(command: &str, limits: Limits) -> Result<CandidateEngine, String> {
        let argv = split_command(command)?;
        Ok(CandidateEngine { argv, limits, state: Mutex::new(State::default()) })
    }

    /// The command as split.
    pub fn argv(&self) -> &[String] {
        &self.argv
    }

    pub fn limits(&self) -> Limits {
        self.limits
    }

    /// How many times a child was started (1 + restarts after failures, when it ran at all).
    pub fn starts(&self) -> u64 {
        self.state.lock().map_or(0, |s| s.starts)
    }

    fn ask(&self, state: &mut State, program: &[u8], config: &Config) -> Result<Trace, Failure> {
        if state.running.is_none() {
            state.running = Some(Running::start(&self.argv, self.limits)?);
            state.starts += 1;
        }
        state.next_id += 1;
        let id = state.next_id;
        let running = state.running.as_mut().expect("started above");
        let mut line = request(id, program, config).into_bytes();
        line.push(b'\n');
        if let Some(requests) = &running.requests {
            // A failed send means the writer thread ended (the child closed stdin or exited):
            // the answer (or its absence) tells what happened.
            let _ = requests.send(line);
        }
        let timeout = self.limits.timeout;
        match running.lines.recv_timeout(timeout) {
            Ok(Line::Text(answer)) => parse_response(id, &answer),
            Ok(Line::TooLong(n)) => Err(Failure {
                kind: FailureKind::OutputTooLarge,
                message: format!("answer line over {} bytes (read {n})", self.limits.max_output),
            }),
            Ok(Line::End(why)) => Err(crash(running, &why)),
            Err(RecvTimeoutError::Disconnected) => Err(crash(running, "output reader ended")),
            Err(RecvTimeoutError::Timeout) => Err(Failure {
                kind: FailureKind::Timeout,
                message: format!("no answer within {} ms{}", timeout.as_millis(), running.stderr_tail()),
            }),
        }
    }
}

/// The failure of a child that stopped answering: `why`, its exit status (waiting up to 200 ms
/// for it to exit) and its last stderr lines.
fn crash(running: &mut Running, why: &str) -> Failure {
    let mut status = "still running".to_string();
    for _ in 0..20 {
        if let Ok(Some(s)) = running.child.try_wait() {
            status = s.to_string();
            break;
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    Failure { kind: FailureKind::Crash, message: format!("{why}, {status}{}", running.stderr_tail()) }
}

impl Engine for CandidateEngine {
    fn name(&self) -> &str {
        "candidate"
    }

    /// The trace; a failure panics with its description (a campaign turns a panic into a
    /// finding, never a pass). Use [`Engine::try_expand`] to get failures classified.
    fn expand(&self, program: &[u8], config: &Config) -> Trace {
        self.try_expand(program, config).unwrap_or_else(|f| panic!("candidate failure: {f}"))
    }

    fn try_expand(&self, program: &[u8], config: &Config) -> Result<Trace, Failure> {
        let mut state = self.state.lock().unwrap_or_else(std::sync::PoisonError::into_inner);
        let result = self.ask(&mut state, program, config);
        // After anything but a trace or a well-formed refusal the child's state is unknown:
        // stop it, the next case starts a fresh one.
        if let Err(f) = &result {
            if f.kind != FailureKind::Refused {
                if let Some(r) = state.running.take() {
                    r.stop();
                }
            }
        }
        result
    }
}

impl Drop for CandidateEngine {
    /// Closes the child's stdin (its signal to exit), gives it a moment, then kills its process
    /// group: the child if it is still running, and whatever it left behind.
    fn drop(&mut self) {
        let state = self.state.get_mut().unwrap_or_else(std::sync::PoisonError::into_inner);
        if let Some(mut r) = state.running.take() {
            r.requests = None;
            for _ in 0..50 {
                if let Ok(Some(_)) = r.child.try_wait() {
                    break;
                }
                std::thread::sleep(Duration::from_millis(10));
            }
            r.stop();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn requests_carry_schema_id_program_and_config() {
        let r: serde_json::Value = serde_json::from_str(&request(7, b"G0 X1\n", &Config::default())).unwrap();
        assert_eq!(r["schema"], SCHEMA);
        assert_eq!(r["id"], 7);
        assert_eq!(r["program"], "G0 X1\n");
        assert_eq!(r["config"]["dialect"], "gsk");
        assert_eq!(r["config"]["grid"]["units"], "metric");
        assert_eq!(r["config"]["params"]["no19_pullout"], 10);
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

    #[test]
    fn a_missing_command_is_a_spawn_failure_every_time() {
        let e = CandidateEngine::new("/nonexistent/candidate --x", Limits::default()).unwrap();
        for _ in 0..2 {
            let f = e.try_expand(b"G0 X1", &Config::default()).unwrap_err();
            assert_eq!(f.kind, FailureKind::Spawn, "{f}");
        }
        assert_eq!(e.starts(), 0);
    }
}
