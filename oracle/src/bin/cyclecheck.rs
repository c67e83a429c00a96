//! `cyclecheck`: expand a program with either engine, diff the spec against the production
//! expander or a candidate on programs, run the built-in corpus through both, or write the
//! certification evidence bundle (`certify`). See the README ("The CLI") for the promised
//! behaviour.
//!
//! Exit codes: 0 success / the engines conform; 1 the engines diverge or the candidate fails
//! (`diff`, `corpus`, `certify`); 2 an alarm or bad input — the alarm, naming its code, word,
//! rule and line, goes to stderr.

use cycle_oracle::campaign::{self, Verdict};
use cycle_oracle::candidate::Limits;
use cycle_oracle::certify::{self, CaseResult};
use cycle_oracle::conformance::{self, alarm_summary};
use cycle_oracle::corpus;
use cycle_oracle::engine::{self, FailureKind, ImplEngine, SpecEngine};
use cycle_oracle::registry;
use cycle_spec::words::N as MAX_LENGTH;
use cycle_vocab::text::Trace;
use cycle_vocab::{Config, Dialect, Grid, Increment, Units};
use std::process::ExitCode;

/// The help text; the cycle names and certify's defaults come from the registry and certify.
fn usage() -> String {
    format!(
        "\
usage:
  cyclecheck expand FILE [--engine spec|impl] [--format gcode|json] [OPTIONS]
  cyclecheck diff FILE... [--candidate CMD] [--format gcode|json] [OPTIONS]
                                                            spec vs impl, or vs a candidate
  cyclecheck certify [--out DIR] [--candidate CMD] [--cycles LIST] [--cases N] [--seed S]
                                                            the certification evidence bundle
  cyclecheck corpus [--format text|json]                    every built-in example, spec vs impl
  cyclecheck gate [--cases N] [--seed S] [--no-cargo-test]  pre-merge gate
  cyclecheck fuzz [--budget SECS] [--targets T,..] [--out DIR] [--features F] [--write-seeds]
                  [--decode TARGET FILE [NAME]]             nightly fuzz campaign; seeds; a
                                                            fuzz input as a decoded regression
options:
  --dialect gsk|fanuc|nc201 input conventions (default gsk)
  --units metric|inch       (default metric)
  --increment isb|isc       least increment (default isb)
  --param N=V               machine parameter: 19, 107, 18, 5130, 5131, 5140..5145, max_passes, x_radius
  --start-x X --start-z Z   machine position at program start, mm or inch (default 0 0)
candidate options (diff, certify; docs/CANDIDATE.md):
  --candidate CMD           an external expander speaking cyclecheck-candidate/1; CMD is split
                            like a shell command line (quotes, backslashes) and run without a shell
  --timeout-ms MS           time allowed per case (default 10000)
  --max-output BYTES        longest answer line per case (default 67108864)
certify options:
  --out DIR                 where the bundle goes (default evidence)
  --cycles LIST             all (default) or a comma list of {cycles}
  --cases N                 generated cases per family (default {cases}; garbage gets a fifth)
  --seed S                  seed of the generated campaign (default {seed})
exit: 0 ok / conform, 1 the engines diverge or the candidate fails, 2 an alarm or bad input",
        cycles = registry::names(),
        cases = certify::DEFAULT_CASES,
        seed = certify::DEFAULT_SEED,
    )
}

/// `writeln!` into the output buffer (a `String` cannot fail).
macro_rules! outln {
    ($out:ident, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = writeln!($out, $($arg)*);
    }};
}

/// `write!` into the output buffer.
macro_rules! outp {
    ($out:ident, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = write!($out, $($arg)*);
    }};
}

/// Writes the output to stdout at once; a closed pipe (`cyclecheck corpus | head`) is not an
/// error worth a panic.
fn emit(text: &str) {
    use std::io::Write as _;
    let mut stdout = std::io::stdout().lock();
    let _ = stdout.write_all(text.as_bytes()).and_then(|()| stdout.flush());
}

/// Bad input: a message for stderr, exit 2.
struct Bad(String);

fn bad<T>(msg: impl Into<String>) -> Result<T, Bad> {
    Err(Bad(msg.into()))
}

/// The options of `expand` and `diff`; each takes a value.
const OPTIONS: &[&str] = &[
    "--engine",
    "--format",
    "--dialect",
    "--units",
    "--increment",
    "--param",
    "--start-x",
    "--start-z",
    "--candidate",
    "--timeout-ms",
    "--max-output",
];

/// The parsed command line of `expand` and `diff`.
struct Options {
    files: Vec<String>,
    engine: Option<String>,
    /// `diff --candidate`: the candidate command and its limits.
    candidate: Option<String>,
    limits: Limits,
    format: Option<String>,
    config: Config,
    start: (Option<String>, Option<String>),
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match run(&args) {
        Ok(code) => ExitCode::from(code),
        Err(Bad(msg)) => {
            eprintln!("cyclecheck: {msg}");
            ExitCode::from(2)
        }
    }
}

fn run(args: &[String]) -> Result<u8, Bad> {
    let Some(command) = args.first() else {
        return bad(format!("no command\n{}", usage()));
    };
    let rest = &args[1..];
    match command.as_str() {
        "-h" | "--help" | "help" => {
            emit(&format!("{}\n", usage()));
            Ok(0)
        }
        "expand" => expand(parse(rest, true)?),
        "diff" => diff(parse(rest, false)?),
        "corpus" => corpus_command(rest),
        "certify" => certify_command(rest),
        "gate" => cycle_oracle::gate::command(rest).map_err(Bad),
        "fuzz" => cycle_oracle::nightly::command(rest).map_err(Bad),
        other => bad(format!("unknown command {other:?}\n{}", usage())),
    }
}

/// Splits `--name=value` or takes the value from the next argument.
fn option_value<'a>(arg: &'a str, it: &mut impl Iterator<Item = &'a String>) -> Result<(&'a str, &'a str), Bad> {
    if let Some((name, value)) = arg.split_once('=') {
        return Ok((name, value));
    }
    match it.next() {
        Some(v) => Ok((arg, v.as_str())),
        None => bad(format!("{arg} needs a value")),
    }
}

fn parse(args: &[String], allow_engine: bool) -> Result<Options, Bad> {
    let mut o = Options {
        files: Vec::new(),
        engine: None,
        candidate: None,
        limits: Limits::default(),
        format: None,
        config: Config::default(),
        start: (None, None),
    };
    let mut units = Units::Metric;
    let mut increment = Increment::Isb;
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        if !arg.starts_with("--") {
            if allow_engine && !o.files.is_empty() {
                return bad(format!("expand takes one FILE (also got {arg:?})"));
            }
            o.files.push(arg.clone());
            continue;
        }
        let name = arg.split_once('=').map_or(arg.as_str(), |(n, _)| n);
        if name == "--help" {
            return bad(usage());
        }
        if !OPTIONS.contains(&name) {
            return bad(format!("unknown option {name:?}\n{}", usage()));
        }
        let (name, value) = option_value(arg, &mut it)?;
        match name {
            "--engine" if allow_engine => match value {
                "spec" | "impl" => o.engine = Some(value.to_string()),
                _ => return bad(format!("--engine takes spec or impl, not {value:?}")),
            },
            "--engine" => return bad("diff compares spec and impl; it takes no --engine"),
            "--format" => match value {
                "gcode" | "json" => o.format = Some(value.to_string()),
                _ => return bad(format!("--format takes gcode or json, not {value:?}")),
            },
            "--dialect" => {
                o.config.dialect = match value {
                    "gsk" => Dialect::Gsk,
                    "fanuc" => Dialect::Fanuc,
                    "nc201" => Dialect::Nc201,
                    _ => return bad(format!("--dialect takes gsk, fanuc or nc201, not {value:?}")),
                }
            }
            "--units" => {
                units = match value {
                    "metric" => Units::Metric,
                    "inch" => Units::Inch,
                    _ => return bad(format!("--units takes metric or inch, not {value:?}")),
                }
            }
            "--increment" => {
                increment = match value {
                    "isb" => Increment::Isb,
                    "isc" => Increment::Isc,
                    _ => return bad(format!("--increment takes isb or isc, not {value:?}")),
                }
            }
            "--param" => {
                let Some((n, v)) = value.split_once('=') else {
                    return bad(format!("--param takes N=V, not {value:?}"));
                };
                let Ok(v) = v.trim().parse::<i64>() else {
                    return bad(format!("--param {n}: {v:?} is not an integer"));
                };
                if o.config.params.set(n.trim(), v).is_err() {
                    let names = cycle_vocab::Params::NAMES.join(", ");
                    return bad(format!("--param {n}: unknown parameter (one of {names})"));
                }
            }
            "--start-x" => o.start.0 = Some(value.to_string()),
            "--start-z" => o.start.1 = Some(value.to_string()),
            "--candidate" | "--timeout-ms" | "--max-output" if allow_engine => {
                return bad(format!("{name} is an option of diff and certify; expand takes --engine spec|impl"))
            }
            "--candidate" => o.candidate = Some(value.to_string()),
            "--timeout-ms" | "--max-output" => candidate_limit(&mut o.limits, name, value)?,
            _ => return bad(format!("unknown option {name:?}\n{}", usage())),
        }
    }
    o.config.grid = Grid { units, increment };
    let decimals = o.config.grid.decimals();
    if let Some(x) = &o.start.0 {
        o.config.start_x = grid_value(x, decimals).map_err(|e| Bad(format!("--start-x {x:?}: {e}")))?;
    }
    if let Some(z) = &o.start.1 {
        o.config.start_z = grid_value(z, decimals).map_err(|e| Bad(format!("--start-z {z:?}: {e}")))?;
    }
    // The reference's own ranges decide which parameter values are legal.
    if let Err(a) = cycle_spec::config::check(&o.config) {
        return bad(format!("the configuration is refused: {a}"));
    }
    Ok(o)
}

/// A decimal in mm (inch) as a count of the least increment: exact, within ±N.
fn grid_value(text: &str, decimals: u32) -> Result<i64, String> {
    let (negative, digits) = match text.as_bytes().first() {
        Some(b'-') => (true, &text[1..]),
        Some(b'+') => (false, &text[1..]),
        _ => (false, text),
    };
    let (int, frac) = digits.split_once('.').unwrap_or((digits, ""));
    let all_digits = |s: &str| s.bytes().all(|b| b.is_ascii_digit());
    if int.is_empty() && frac.is_empty() || !all_digits(int) || !all_digits(frac) {
        return Err("not a decimal number".to_string());
    }
    let frac = frac.trim_end_matches('0');
    if frac.len() > decimals as usize {
        return Err(format!("more than {decimals} decimals (the least increment)"));
    }
    let too_large = || format!("outside ±{}", cycle_vocab::text::fixed(MAX_LENGTH, decimals));
    let int = int.trim_start_matches('0');
    if int.len() > 18 {
        return Err(too_large());
    }
    let int: i64 = if int.is_empty() { 0 } else { int.parse().map_err(|_| too_large())? };
    let frac_count: i64 = if frac.is_empty() { 0 } else { frac.parse::<i64>().map_err(|_| too_large())? };
    let scale = 10i64.pow(decimals);
    let count = int
        .checked_mul(scale)
        .and_then(|v| v.checked_add(frac_count * 10i64.pow(decimals - frac.len() as u32)))
        .filter(|v| *v <= MAX_LENGTH)
        .ok_or_else(too_large)?;
    Ok(if negative { -count } else { count })
}

/// `--timeout-ms MS` or `--max-output BYTES` (both at least 1).
fn candidate_limit(limits: &mut Limits, name: &str, value: &str) -> Result<(), Bad> {
    let Some(n) = value.trim().parse::<u64>().ok().filter(|&n| n >= 1) else {
        return bad(format!("{name} takes a whole number of at least 1, not {value:?}"));
    };
    match name {
        "--timeout-ms" => limits.timeout = std::time::Duration::from_millis(n),
        _ => limits.max_output = usize::try_from(n).unwrap_or(usize::MAX),
    }
    Ok(())
}

fn read_program(file: &str) -> Result<Vec<u8>, Bad> {
    std::fs::read(file).map_err(|e| Bad(format!("cannot read {file}: {e}")))
}

fn expand(o: Options) -> Result<u8, Bad> {
    let Some(file) = o.files.first() else {
        return bad(format!("no FILE given\n{}", usage()));
    };
    let program = read_program(file)?;
    let name = o.engine.as_deref().unwrap_or("spec");
    let engine = engine::by_name(name).expect("engine names are checked when parsing");
    let trace = engine.expand(&program, &o.config);
    let mut out = String::new();
    match o.format.as_deref() {
        Some("json") => outln!(out, "{}", trace.to_json()),
        _ => outp!(out, "{}", trace.to_gcode()),
    }
    emit(&out);
    Ok(report_alarm(&trace))
}

/// Names the trace's alarm on stderr: 2 when there is one, else 0.
fn report_alarm(trace: &Trace) -> u8 {
    match &trace.alarm {
        Some(a) => {
            eprintln!("{}", alarm_summary(a));
            2
        }
        None => 0,
    }
}

fn diff(o: Options) -> Result<u8, Bad> {
    if o.files.is_empty() {
        return bad(format!("no FILE given\n{}", usage()));
    }
    let programs = o.files.iter().map(|f| read_program(f).map(|p| (f, p))).collect::<Result<Vec<_>, Bad>>()?;
    let certify_options = certify::Options { candidate: o.candidate.clone(), limits: o.limits, ..certify::Options::default() };
    let candidate = certify::candidate_engine(&certify_options).map_err(|e| Bad(e.0))?;
    let json = o.format.as_deref() == Some("json");
    let several = programs.len() > 1;
    let (mut diverged, mut alarmed) = (false, false);
    let mut by_cycle = std::collections::BTreeMap::new();
    for (file, program) in &programs {
        let mut out = String::new();
        let (reference, _, result) = certify::judge(&SpecEngine, candidate.as_ref(), program, &o.config);
        let cycle = registry::cycle_run(program, &o.config, reference.as_ref());
        *by_cycle.entry(cycle).or_insert(0) += 1;
        if several && !json {
            outln!(out, "== {file} ({})", cycle.label());
        }
        let mut doc = match &result {
            CaseResult::Diverge(d) => {
                diverged = true;
                if !json {
                    outln!(out, "{d}");
                }
                serde_json::json!({"conform": false, "divergence": conformance::to_json(d)})
            }
            CaseResult::Failure { engine, failure } => {
                diverged = true;
                if failure.kind == FailureKind::Panic {
                    if !json {
                        outln!(out, "PANIC in the {engine} engine: {}", failure.message);
                    }
                    serde_json::json!({"conform": false, "panic": {"engine": engine, "message": failure.message}})
                } else {
                    if !json {
                        outln!(out, "FAILURE of the {engine} engine ({}): {}", failure.kind, failure.message);
                    }
                    serde_json::json!({"conform": false, "failure": {"engine": engine, "kind": failure.kind.name(), "message": failure.message}})
                }
            }
            CaseResult::Conform => {
                let trace = reference.as_ref().expect("a conforming case has a reference trace");
                if !json {
                    match &trace.alarm {
                        None => outln!(out, "conform: {} events", trace.events.len()),
                        Some(a) => outln!(out, "conform: {} events, then {}", trace.events.len(), Trace::alarm_line(a)),
                    }
                }
                serde_json::json!({"conform": true, "events": trace.events.len(), "alarm": trace.alarm})
            }
        };
        if json {
            if several {
                doc["file"] = serde_json::json!(file);
            }
            doc["cycle"] = serde_json::json!(cycle.label());
            outln!(out, "{doc}");
        }
        emit(&out);
        if let (CaseResult::Conform, Some(trace)) = (&result, &reference) {
            alarmed |= report_alarm(trace) != 0;
        }
    }
    if several && !json {
        emit(&format!("\n{} files by cycle: {}\n", programs.len(), registry::counts_line(&by_cycle)));
    }
    Ok(if diverged {
        1
    } else if alarmed {
        2
    } else {
        0
    })
}

/// `certify`: runs the certification with a progress bar on stderr, writes the bundle, prints
/// the summary; exit 0 when every case conforms, 1 otherwise, 2 on bad options or a failed write.
fn certify_command(args: &[String]) -> Result<u8, Bad> {
    let mut options = certify::Options::default();
    let mut out_dir = std::path::PathBuf::from("evidence");
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        if !arg.starts_with("--") {
            return bad(format!("certify takes options only, not {arg:?}\n{}", usage()));
        }
        let (name, value) = option_value(arg, &mut it)?;
        match name {
            "--out" => out_dir = value.into(),
            "--candidate" => options.candidate = Some(value.to_string()),
            "--timeout-ms" | "--max-output" => candidate_limit(&mut options.limits, name, value)?,
            "--cycles" => options.cycles = certify::Options::parse_cycles(value).map_err(Bad)?,
            "--cases" => {
                options.cases = value.trim().parse().map_err(|_| Bad(format!("--cases takes a whole number, not {value:?}")))?
            }
            "--seed" => options.seed = value.trim().parse().map_err(|_| Bad(format!("--seed takes a u64, not {value:?}")))?,
            _ => return bad(format!("unknown certify option {name:?}\n{}", usage())),
        }
    }
    let mut bar = ProgressBar::new();
    let run = certify::run(&options, &mut |p| bar.show(p)).map_err(|e| Bad(e.0))?;
    bar.finish();
    let files = certify::bundle::files(&run);
    certify::bundle::write(&out_dir, &files).map_err(|e| Bad(format!("cannot write {}: {e}", out_dir.display())))?;
    let plots = files.iter().filter(|(f, _)| f.starts_with("plots/")).count();
    let mut out = run.summary();
    outln!(
        out,
        "\nwrote {}: index.html, evidence.json, {plots} plots — {}",
        out_dir.display(),
        if run.passed() { "PASS" } else { "FAIL" }
    );
    emit(&out);
    Ok(if run.passed() { 0 } else { 1 })
}

/// A progress bar on stderr: redrawn in place on a terminal, a line per phase otherwise.
struct ProgressBar {
    tty: bool,
    phase: String,
    last: Option<std::time::Instant>,
}

impl ProgressBar {
    fn new() -> ProgressBar {
        use std::io::IsTerminal as _;
        ProgressBar { tty: std::io::stderr().is_terminal(), phase: String::new(), last: None }
    }

    fn show(&mut self, p: certify::Progress) {
        let new_phase = self.phase != p.phase;
        if !self.tty {
            if new_phase {
                eprintln!("certify: {} ({} of {} cases done, {} not conforming)", p.phase, p.done, p.total, p.bad);
                self.phase = p.phase.to_string();
            }
            return;
        }
        let now = std::time::Instant::now();
        let due = self.last.is_none_or(|t| now.duration_since(t).as_millis() >= 100);
        if !(due || new_phase || p.done == p.total) {
            return;
        }
        if new_phase && !self.phase.is_empty() {
            eprintln!();
        }
        self.phase = p.phase.to_string();
        self.last = Some(now);
        const WIDTH: usize = 30;
        let filled = (p.done * WIDTH).checked_div(p.total).unwrap_or(WIDTH);
        eprint!(
            "\r{:<10} [{}{}] {:>6}/{:<6} {} not conforming ",
            p.phase,
            "#".repeat(filled),
            "-".repeat(WIDTH - filled),
            p.done,
            p.total,
            p.bad
        );
    }

    fn finish(&mut self) {
        if self.tty && !self.phase.is_empty() {
            eprintln!();
        }
    }
}

fn corpus_command(args: &[String]) -> Result<u8, Bad> {
    let mut json = false;
    let mut it = args.iter();
    while let Some(arg) = it.next() {
        let (name, value) = if arg.starts_with("--") { option_value(arg, &mut it)? } else { (arg.as_str(), "") };
        match (name, value) {
            ("--format", "text") => json = false,
            ("--format", "json") => json = true,
            ("--format", v) => return bad(format!("--format of corpus takes text or json, not {v:?}")),
            _ => return bad(format!("corpus takes only --format, not {arg:?}\n{}", usage())),
        }
    }
    let (spec, imp) = (SpecEngine, ImplEngine::default());
    let report = campaign::run((&spec, &imp), corpus::cases());
    let mut out = String::new();
    if json {
        let programs: Vec<_> = report
            .outcomes
            .iter()
            .zip(corpus::PROGRAMS)
            .map(|(o, p)| {
                let divergence = match &o.verdict {
                    Verdict::Diverge(d) => Some(conformance::to_json(d)),
                    _ => None,
                };
                let alarm = match &o.verdict {
                    Verdict::Conform(a) => a.as_ref().map(alarm_summary),
                    _ => None,
                };
                serde_json::json!({
                    "name": o.name,
                    "path": p.path,
                    "cycle": o.cycle.label(),
                    "dialect": p.config().dialect,
                    "units": p.config().grid.units,
                    "rules": p.rules.iter().map(|r| r.id()).collect::<Vec<_>>(),
                    "events": o.events,
                    "passes": o.passes,
                    "conform": o.verdict.conforms(),
                    "result": o.verdict.short(),
                    "alarm": alarm,
                    "divergence": divergence,
                })
            })
            .collect();
        let doc = serde_json::json!({
            "reference": report.engines.0,
            "candidate": report.engines.1,
            "programs": programs,
            "summary": {
                "programs": report.cases(),
                "conform": report.conforming(),
                "diverge": report.cases() - report.conforming(),
                "by_cycle": report.by_cycle.iter().map(|(c, n)| (c.label(), *n)).collect::<std::collections::BTreeMap<_, _>>(),
            },
        });
        outln!(out, "{}", serde_json::to_string_pretty(&doc).expect("JSON values serialize"));
    } else {
        let width = corpus::PROGRAMS.iter().map(|p| p.name.len()).max().unwrap_or(0);
        let cycle_width = report.outcomes.iter().map(|o| o.cycle.label().len()).max().unwrap_or(0);
        for o in &report.outcomes {
            let (name, cycle) = (&o.name, o.cycle.label());
            outln!(out, "{name:width$}  {cycle:cycle_width$}  {:>6} events  {:>4} passes  {}", o.events, o.passes, o.verdict.short());
        }
        for f in &report.findings {
            outln!(out, "\n{}: {}", f.name, corpus::find(&f.name).map_or("", |p| p.path));
            match &f.verdict {
                Verdict::Diverge(d) => outln!(out, "{d}"),
                Verdict::Panic { engine, message } => outln!(out, "PANIC in the {engine} engine: {message}"),
                Verdict::Conform(_) => {}
            }
        }
        outln!(
            out,
            "\n{} programs: {} conform, {} diverge ({} vs {}); by cycle: {}",
            report.cases(),
            report.conforming(),
            report.cases() - report.conforming(),
            report.engines.0,
            report.engines.1,
            registry::counts_line(&report.by_cycle)
        );
    }
    emit(&out);
    Ok(if report.all_conform() { 0 } else { 1 })
}

#[cfg(test)]
mod tests {
    use super::grid_value;

    #[test]
    fn start_values_on_the_grid() {
        assert_eq!(grid_value("65", 3), Ok(65_000));
        assert_eq!(grid_value("-28.5", 3), Ok(-28_500));
        assert_eq!(grid_value("+.5", 4), Ok(5_000));
        assert_eq!(grid_value("1.2500", 3), Ok(1_250));
        assert_eq!(grid_value("999999.999", 3), Ok(999_999_999));
        assert!(grid_value("1000000", 3).is_err());
        assert!(grid_value("1.0001", 3).is_err());
        for bad in ["", ".", "-", "1e3", "1.2.3", "x", "99999999999999999999999"] {
            assert!(grid_value(bad, 3).is_err(), "{bad:?}");
        }
    }
}
