//! The candidate engine: one child at a time, greeted when it starts, restarted after any
//! failure, and fed ahead of the campaign when it is told the next cases ([`Engine::prefetch`]).
//!
//! Requests are queued in the order the campaign will ask for their traces. A legacy child, or
//! one that did not announce `pipeline`, has one request in flight at a time — the next one is
//! sent as soon as the previous answer is read, so the child computes while the campaign judges;
//! a pipelining child has up to [`WINDOW`]. A case's clock starts when its request is sent or
//! when the answer before it arrived, whichever is later. When a case fails (other than by a
//! refusal) while later requests were in flight, the failure cannot be told from theirs: the
//! case is run again alone on a fresh child, and that run's outcome is the case's.

use super::child::{Outgoing, Running};
use super::{hello, parse_hello, parse_response, schema_for_case, split_command, version_of, Limits, Speaks};
use cycle_kernel::conformance::Level;
use cycle_kernel::engine::{Engine, Failure, FailureKind};
use cycle_kernel::readings::Declared;
use cycle_vocab::text::Trace;
use cycle_vocab::Config;
use std::collections::VecDeque;
use std::sync::Mutex;
use std::time::{Duration, Instant};

/// The most requests in flight to a child that announced `pipeline`.
pub const WINDOW: usize = 32;

/// The candidate engine: one child at a time, restarted after any failure.
pub struct CandidateEngine {
    argv: Vec<String>,
    limits: Limits,
    state: Mutex<State>,
}

/// A case asked for or announced, and its request to the current child when sent.
struct Queued {
    program: Vec<u8>,
    config: Config,
    version: u8,
    sent: Option<(u64, Instant)>,
}

struct State {
    running: Option<Running>,
    /// What the running child said to the greeting.
    speaks: Speaks,
    /// Whether children are greeted: not after a child failed to answer the greeting.
    greet: bool,
    /// The readings the first greeted child declared: every later child must declare the same.
    declared: Option<Declared>,
    /// The failure to start or greet the child [`CandidateEngine::declared`] started: the first
    /// case's, as if that case had started the child.
    pending: Option<Failure>,
    queue: VecDeque<Queued>,
    /// When the running child last answered (or started).
    last_answer: Instant,
    next_id: u64,
    starts: u64,
    /// The weakest level a greeted child declared.
    weakest: Level,
}

impl CandidateEngine {
    /// An engine for `command` (split by [`split_command`]); the child starts at the first case.
    pub fn new(command: &str, limits: Limits) -> Result<CandidateEngine, String> {
        let argv = split_command(command)?;
        let state = State {
            running: None,
            speaks: Speaks::LEGACY,
            greet: true,
            declared: None,
            pending: None,
            queue: VecDeque::new(),
            last_answer: Instant::now(),
            next_id: 0,
            starts: 0,
            weakest: Level::Full,
        };
        Ok(CandidateEngine { argv, limits, state: Mutex::new(state) })
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
        self.lock().starts
    }

    /// What the last child said to the greeting (legacy before any).
    pub fn speaks(&self) -> Speaks {
        self.lock().speaks
    }

    /// Starts a child (when none runs) and greets it: what it says it speaks, or why it could
    /// not be started or greeted. `certify --level` asks this before its run.
    pub fn greet(&self) -> Result<Speaks, Failure> {
        let mut s = self.lock();
        if s.running.is_none() {
            self.start(&mut s)?;
        }
        Ok(s.speaks)
    }

    /// The weakest comparison level a child of this engine declared (`full` before any).
    pub fn weakest_level(&self) -> Level {
        self.lock().weakest
    }

    fn lock(&self) -> std::sync::MutexGuard<'_, State> {
        self.state.lock().unwrap_or_else(std::sync::PoisonError::into_inner)
    }

    /// Starts a child and greets it. A greeting not answered (timeout, crash, garbage) is the
    /// failure of the case that started the child, and later children are not greeted.
    fn start(&self, s: &mut State) -> Result<(), Failure> {
        let mut running = Running::start(&self.argv, self.limits)?;
        s.starts += 1;
        s.speaks = Speaks::LEGACY;
        if s.greet {
            running.send(vec![Outgoing::Line(hello().into_bytes())]);
            let answer = running.answer(Instant::now() + self.limits.timeout, self.limits, self.limits.timeout);
            match answer.and_then(|(line, _)| parse_hello(&line)) {
                Ok(speaks) if s.declared.is_some_and(|d| d != speaks.declared) => {
                    running.stop();
                    let first = s.declared.map(|d| cycle_kernel::readings::line(&d.readings)).unwrap_or_default();
                    let message = format!(
                        "greeting the candidate: it now declares the readings {}, where its first greeting declared {first}",
                        cycle_kernel::readings::line(&speaks.declared.readings)
                    );
                    return Err(Failure { kind: FailureKind::Garbage, message });
                }
                Ok(speaks) => {
                    s.speaks = speaks;
                    s.declared = Some(speaks.declared);
                    s.weakest = s.weakest.min(speaks.level);
                }
                Err(f) => {
                    s.greet = false;
                    running.stop();
                    return Err(Failure { message: format!("greeting the candidate: {}", f.message), ..f });
                }
            }
        }
        s.last_answer = Instant::now();
        s.running = Some(running);
        Ok(())
    }

    /// The readings the candidate declares in its greeting, starting (and greeting) a child if
    /// none runs. A legacy candidate declares none. A child that cannot be started or greeted:
    /// the failure is the next case's, as if that case had started it.
    pub fn declared(&self) -> Result<Declared, Failure> {
        let mut s = self.lock();
        if s.running.is_none() {
            if let Err(f) = self.start(&mut s) {
                s.pending = Some(f.clone());
                return Err(f);
            }
        }
        Ok(s.speaks.declared)
    }

    /// Stops the child; requests in flight to it are to be sent again to the next.
    fn stop(s: &mut State) {
        if let Some(r) = s.running.take() {
            r.stop();
        }
        s.queue.iter_mut().for_each(|q| q.sent = None);
    }

    /// Sends queued requests to the running child while fewer than its window are in flight
    /// (`alone`: only the first). A pipelining child's window is topped up once half of it is
    /// answered, in one batch. Requests of versions it did not announce are never sent.
    fn fill(s: &mut State, alone: bool) {
        let Some(running) = &s.running else { return };
        let window = if alone { 1 } else if s.speaks.pipeline { WINDOW } else { 1 };
        let mut in_flight = s.queue.iter().filter(|q| q.sent.is_some()).count();
        if window > 1 && in_flight > window / 2 {
            return;
        }
        let mut batch = Vec::new();
        for q in s.queue.iter_mut() {
            if in_flight >= window {
                break;
            }
            if q.sent.is_some() || !s.speaks.speaks(q.version) {
                continue;
            }
            s.next_id += 1;
            batch.push(Outgoing::Request(s.next_id, q.program.clone(), Box::new(q.config)));
            q.sent = Some((s.next_id, Instant::now()));
            in_flight += 1;
        }
        running.send(batch);
    }

    /// Reads and drops the answers to every request in flight (the campaign asked for another
    /// case than those it announced), then forgets the queue.
    fn abandon(&self, s: &mut State) {
        while let Some(q) = s.queue.pop_front() {
            let Some((_, sent)) = q.sent else { continue };
            let Some(running) = s.running.as_mut() else { break };
            let deadline = sent.max(s.last_answer) + self.limits.timeout;
            if running.answer(deadline, self.limits, self.limits.timeout).is_err() {
                Self::stop(s);
                break;
            }
            s.last_answer = Instant::now();
        }
        s.queue.clear();
    }

    /// The answer to the first queued case, which leaves the queue.
    fn ask_first(&self, s: &mut State, alone: bool) -> Result<Trace, Failure> {
        if let Some(f) = s.pending.take() {
            s.queue.pop_front();
            return Err(f);
        }
        if s.running.is_none() {
            if let Err(f) = self.start(s) {
                s.queue.pop_front();
                return Err(f);
            }
        }
        let version = s.queue[0].version;
        if !s.speaks.speaks(version) {
            s.queue.pop_front();
            Self::fill(s, alone);
            return Err(Failure {
                kind: FailureKind::Refused,
                message: format!("not sent: the candidate speaks versions {} of the protocol, not {version}", s.speaks.list()),
            });
        }
        Self::fill(s, alone);
        let (id, sent) = s.queue[0].sent.expect("the first request is sent by fill");
        let running = s.running.as_mut().expect("started above");
        let deadline = sent.max(s.last_answer) + self.limits.timeout;
        let result = running.answer(deadline, self.limits, self.limits.timeout).and_then(|(line, usual)| match usual {
            Some((got, trace)) if got == id => Ok(trace),
            _ => parse_response(id, &line),
        });
        s.last_answer = Instant::now();
        let others_in_flight = s.queue.iter().skip(1).any(|q| q.sent.is_some());
        match &result {
            Err(f) if f.kind != FailureKind::Refused => {
                // The child's state is unknown: stop it; the next case starts a fresh one.
                Self::stop(s);
                if others_in_flight {
                    return self.ask_first(s, true);
                }
            }
            _ => {}
        }
        s.queue.pop_front();
        Self::fill(s, false);
        result
    }
}

fn queued(program: &[u8], config: &Config) -> Queued {
    let version = version_of(schema_for_case(program, config)).unwrap_or(1);
    Queued { program: program.to_vec(), config: *config, version, sent: None }
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
        let mut s = self.lock();
        let announced = s.queue.front().is_some_and(|q| q.program == program && q.config == *config);
        if !announced {
            self.abandon(&mut s);
            s.queue.push_back(queued(program, config));
        }
        self.ask_first(&mut s, false)
    }

    /// The level the running child (or the last one) declared in its greeting.
    fn level(&self) -> Level {
        self.lock().speaks.level
    }

    /// Queues the case's request, sent as soon as the child has room for it.
    fn prefetch(&self, program: &[u8], config: &Config) {
        let mut s = self.lock();
        s.queue.push_back(queued(program, config));
        Self::fill(&mut s, false);
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
