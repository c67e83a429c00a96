//! `expand` and `diff`: both stream — `expand` writes each event as the engine emits it, `diff`
//! runs the reference and the candidate in lockstep — so neither holds a trace, whatever its
//! length.

use crate::cli::args::{DiffArgs, EngineArg, ExpandArgs, FormatArg};
use crate::cli::config::{check_files, config, read_program};
use crate::cli::output::{Form, TraceWriter};
use crate::cli::Bad;
use cycle_kernel::conformance::{self, alarm_summary, Level};
use cycle_kernel::engine::{Engine, FailureKind, ImplEngine, SpecEngine};
use cycle_kernel::judge::{self, CaseResult};
use cyclecheck::candidate::CandidateEngine;
use cycle_kernel::{hint, readings, registry};
use cycle_vocab::text::Trace;
use cycle_vocab::Alarm;
use std::io::Write as _;
use std::ops::ControlFlow;

/// The alarm on stderr, with its hint when the configuration is the likely cause.
fn report_alarm(alarm: &Alarm, hint: Option<&str>) {
    eprintln!("{}", alarm_summary(alarm));
    if let Some(h) = hint {
        eprintln!("{h}");
    }
}

/// `expand`: the trace on stdout as it is produced; exit 0, or 2 when it ends in an alarm.
pub fn expand(a: &ExpandArgs) -> Result<u8, Bad> {
    let config = config(&a.config)?;
    let program = read_program(&a.file)?;
    let engine: &dyn Engine = match a.engine {
        EngineArg::Spec => &SpecEngine,
        EngineArg::Impl => &ImplEngine,
    };
    let form = if a.format == FormatArg::Json { Form::Json } else { Form::Gcode };
    let mut w = TraceWriter::start(std::io::stdout().lock(), form, config.grid);
    let alarm = engine
        .push(&program, &config, &mut |e| if w.event(&e) { ControlFlow::Continue(()) } else { ControlFlow::Break(()) })
        .map_err(|f| Bad(format!("the {} engine failed: {f}", engine.name())))?;
    // A closed stdout (`| head`) is the reader's choice, not an error.
    let _ = w.finish(alarm.as_ref());
    match alarm {
        Some(a) => {
            let hint = hint::hint(&config, &a, &registry::sight(&program, &config, Some(&a)));
            report_alarm(&a, hint.as_deref());
            Ok(2)
        }
        None => Ok(0),
    }
}

/// Writes a line to stdout; a closed pipe is not an error worth a panic.
pub fn emit(text: &str) {
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(text.as_bytes()).and_then(|()| stdout.flush());
}

/// `diff`: each file through the reference and the candidate in lockstep; exit 0 when every
/// file conforms (alarm or not), 1 on a divergence or a candidate failure. A candidate is
/// judged against the readings it declares in its greeting, merged with `--reading` (a
/// contradiction is exit 2).
pub fn diff(a: &DiffArgs) -> Result<u8, Bad> {
    let mut config = config(&a.config)?;
    check_files(&a.files)?;
    let candidate: Box<dyn Engine> = match a.candidate.candidate.as_deref() {
        None => Box::new(ImplEngine),
        Some(cmd) => {
            let c = CandidateEngine::new(cmd, a.candidate.limits()).map_err(|e| Bad(format!("--candidate: {e}")))?;
            let pins = readings::Pins::parse(&a.config.readings).map_err(Bad)?;
            config.readings = readings::settle(&c.declared().unwrap_or(readings::Declared::NONE), &pins).map_err(Bad)?;
            Box::new(c)
        }
    };
    let json = a.format == FormatArg::Json;
    let several = a.files.len() > 1;
    let mut diverged = false;
    let mut by_cycle = std::collections::BTreeMap::new();
    for file in &a.files {
        let program = read_program(file)?;
        let j = judge::judge(&SpecEngine, candidate.as_ref(), &program, &config);
        let alarm = j.alarm().copied();
        let cycle = j.sighting.cycle;
        *by_cycle.entry(cycle).or_insert(0) += 1;
        let mut out = String::new();
        if several && !json {
            out.push_str(&format!("== {file} ({})\n", cycle.label()));
        }
        let hint = alarm.and_then(|a| hint::hint(&config, &a, &j.sighting));
        // The level the candidate declared in its greeting (full for the production expander).
        let level = candidate.level();
        let mut doc = match &j.result {
            // No declarations in diff: a deviation cannot be declared here.
            CaseResult::Diverge(d) | CaseResult::Deviate { divergence: d, .. } => {
                out.push_str(&format!("{d}\n"));
                serde_json::json!({"conform": false, "divergence": conformance::to_json(d)})
            }
            CaseResult::Failure { engine, failure } if failure.kind == FailureKind::Panic => {
                out.push_str(&format!("PANIC in the {engine} engine: {}\n", failure.message));
                serde_json::json!({"conform": false, "panic": {"engine": engine, "message": failure.message}})
            }
            CaseResult::Failure { engine, failure } => {
                out.push_str(&format!("FAILURE of the {engine} engine ({}): {}\n", failure.kind, failure.message));
                serde_json::json!({"conform": false, "failure": {"engine": engine, "kind": failure.kind.name(), "message": failure.message}})
            }
            CaseResult::Conform => {
                let events = j.reference.as_ref().map_or(0, |r| r.events);
                let conform = match level {
                    Level::Full => "conform".to_string(),
                    l => format!("conform at comparison level {l} ({})", l.describe()),
                };
                match &alarm {
                    None => out.push_str(&format!("{conform}: {events} events\n")),
                    Some(a) => out.push_str(&format!("{conform}: {events} events, then {}\n", Trace::alarm_line(a))),
                }
                serde_json::json!({"conform": true, "events": events, "alarm": alarm})
            }
        };
        diverged |= !j.result.conforms();
        if json {
            if several {
                doc["file"] = serde_json::json!(file);
            }
            doc["cycle"] = serde_json::json!(cycle.label());
            doc["level"] = serde_json::json!(level.name());
            if let Some(h) = &hint {
                doc["hint"] = serde_json::json!(h);
            }
            emit(&format!("{doc}\n"));
        } else {
            emit(&out);
        }
        if let (CaseResult::Conform, Some(alarm)) = (&j.result, &alarm) {
            report_alarm(alarm, hint.as_deref());
        }
    }
    if several && !json {
        emit(&format!("\n{} files by cycle: {}\n", a.files.len(), registry::counts_line(&by_cycle)));
    }
    Ok(u8::from(diverged))
}
