//! The child process: its three pipe threads — requests written to its stdin, answer lines
//! read from its stdout (each capped), the tail of its stderr kept — and its process group.

use super::Limits;
use cycle_vocab::text::Trace;
use cycle_vocab::Config;
use cycle_kernel::engine::{Failure, FailureKind};
use std::io::{BufRead, BufReader, Read, Write};
use std::os::unix::process::CommandExt as _;
use std::process::{Child, ChildStdout, Command, Stdio};
use std::sync::mpsc::{self, Receiver, RecvTimeoutError, Sender};
use std::sync::{Arc, Mutex};
use std::time::{Duration, Instant};

/// How much of the child's stderr is kept for reports (the last bytes).
const STDERR_TAIL: usize = 4096;

/// A line for the child: as it is, or a case's request ([`super::request`]) to be written.
pub(super) enum Outgoing {
    Line(Vec<u8>),
    Request(u64, Vec<u8>, Box<Config>),
}

/// An answer line and its usual reading, if any: id and trace.
pub(super) type Answer = (Vec<u8>, Option<(u64, Trace)>);

/// What the stdout thread saw.
pub(super) enum Line {
    /// One answer line, without its newline, and — read here, off the campaign's thread — its
    /// id and trace when it is the usual answer ([`super::usual_answer`]).
    Text(Vec<u8>, Option<(u64, Trace)>),
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
        let usual = super::usual_answer(&line);
        if lines.send(Line::Text(line, usual)).is_err() {
            return;
        }
    }
}

/// A running child and its three pipe threads.
pub(super) struct Running {
    pub(super) child: Child,
    pub(super) requests: Option<Sender<Vec<Outgoing>>>,
    lines: Receiver<Line>,
    stderr: Arc<Mutex<Vec<u8>>>,
}

impl Running {
    pub(super) fn start(argv: &[String], limits: Limits) -> Result<Running, Failure> {
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
        let (requests, to_write) = mpsc::channel::<Vec<Outgoing>>();
        std::thread::spawn(move || {
            // Requests are written here, off the campaign's thread; those queued meanwhile go
            // out in the same write.
            let mut bytes = Vec::new();
            while let Ok(batch) = to_write.recv() {
                bytes.clear();
                for out in batch.into_iter().chain(to_write.try_iter().flatten()) {
                    match out {
                        Outgoing::Line(line) => bytes.extend_from_slice(&line),
                        Outgoing::Request(id, program, config) => bytes.extend_from_slice(super::request(id, &program, &config).as_bytes()),
                    }
                    bytes.push(b'\n');
                }
                if stdin.write_all(&bytes).and_then(|()| stdin.flush()).is_err() {
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
    pub(super) fn stderr_tail(&self) -> String {
        let tail = self.stderr.lock().map(|t| String::from_utf8_lossy(&t).trim().to_string()).unwrap_or_default();
        if tail.is_empty() {
            String::new()
        } else {
            format!("; stderr: {tail}")
        }
    }

    /// Sends lines, each written with its newline. A failed send means the writer thread ended
    /// (the child closed stdin or exited): the answer, or its absence, tells what happened.
    pub(super) fn send(&self, batch: Vec<Outgoing>) {
        if let (Some(requests), false) = (&self.requests, batch.is_empty()) {
            let _ = requests.send(batch);
        }
    }

    /// The next answer line, by `deadline` (with its usual reading, if any): or the failure its
    /// absence amounts to.
    pub(super) fn answer(&mut self, deadline: Instant, limits: Limits, timeout: Duration) -> Result<Answer, Failure> {
        match self.lines.recv_timeout(deadline.saturating_duration_since(Instant::now())) {
            Ok(Line::Text(answer, usual)) => Ok((answer, usual)),
            Ok(Line::TooLong(n)) => Err(Failure {
                kind: FailureKind::OutputTooLarge,
                message: format!("answer line over {} bytes (read {n})", limits.max_output),
            }),
            Ok(Line::End(why)) => Err(crash(self, &why)),
            Err(RecvTimeoutError::Disconnected) => Err(crash(self, "output reader ended")),
            Err(RecvTimeoutError::Timeout) => Err(Failure {
                kind: FailureKind::Timeout,
                message: format!("no answer within {} ms{}", timeout.as_millis(), self.stderr_tail()),
            }),
        }
    }

    /// Kills the child's process group (the child and whatever it started) and reaps the child.
    pub(super) fn stop(mut self) {
        self.requests = None;
        crate::reaper::kill_group(self.child.id());
        let _ = self.child.wait();
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
