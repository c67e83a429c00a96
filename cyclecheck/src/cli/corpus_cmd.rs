//! `corpus`: every built-in program through spec and impl, one line (or JSON object) each.

use crate::cli::args::{CorpusArgs, CorpusFormat};
use crate::cli::Bad;
use cycle_kernel::campaign::{self, Verdict};
use cycle_kernel::conformance::{self, alarm_summary};
use cycle_kernel::corpus;
use cycle_kernel::engine::{ImplEngine, SpecEngine};
use cycle_kernel::registry;

/// `writeln!` into the output buffer (a `String` cannot fail).
macro_rules! outln {
    ($out:ident, $($arg:tt)*) => {{
        use std::fmt::Write as _;
        let _ = writeln!($out, $($arg)*);
    }};
}

/// `corpus`: every built-in program through spec and impl; exit 0 when all conform, else 1.
pub fn run(a: &CorpusArgs) -> Result<u8, Bad> {
    let json = a.format == CorpusFormat::Json;
    let (spec, imp) = (SpecEngine, ImplEngine);
    let pins = cycle_kernel::readings::Pins::parse(&a.readings).map_err(Bad)?;
    let cases = corpus::cases().map(|(name, program, config)| (name, program, cycle_vocab::Config { readings: pins.apply(config.readings), ..config }));
    let report = campaign::run((&spec, &imp), cases);
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
            "readings": cycle_kernel::readings::line(&pins.apply(cycle_vocab::Readings::default())),
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
            "\n{} programs: {} conform, {} diverge ({} vs {}; readings: {}); by cycle: {}",
            report.cases(),
            report.conforming(),
            report.cases() - report.conforming(),
            report.engines.0,
            report.engines.1,
            cycle_kernel::readings::line(&pins.apply(cycle_vocab::Readings::default())),
            registry::counts_line(&report.by_cycle)
        );
    }
    crate::cli::expand::emit(&out);
    Ok(if report.all_conform() { 0 } else { 1 })
}
