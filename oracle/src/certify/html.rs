//! `index.html`: one self-contained page for a certification reviewer — no scripts, no external
//! files: the verdict and summary, divergences (first case in full, minimized input) and
//! candidate failures, one toolpath plot per corpus program (inline SVG), the traceability
//! matrix, and the interpretation register (`docs/INTERPRETATION.md`, compiled in).

use super::evidence::{fingerprint, INTERPRETATION_MD, RULES_MD};
use super::markdown::{escape, render};
use super::matrix::{Citation, Kind, Outcome, Row};
use super::{CaseResult, Run};
use std::fmt::Write as _;

const STYLE: &str = "
body { font-family: -apple-system, 'Segoe UI', Helvetica, Arial, sans-serif; margin: 0 auto; max-width: 1500px; padding: 0 24px 48px; color: #222; line-height: 1.4; }
h1 { margin-top: 24px; } h2 { border-bottom: 2px solid #ddd; padding-bottom: 4px; margin-top: 40px; }
nav a { margin-right: 14px; }
table { border-collapse: collapse; margin: 8px 0 16px; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 6px; vertical-align: top; text-align: left; }
th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
pre { background: #f7f7f7; border: 1px solid #ddd; padding: 8px; overflow-x: auto; font-size: 12px; }
code { font-size: 12px; }
.verdict { display: inline-block; padding: 6px 14px; border-radius: 4px; font-weight: bold; font-size: 18px; color: white; }
.pass { background: #2e7d32; } .fail { background: #c62828; }
.r-pass { color: #2e7d32; } .r-fail { color: #c62828; font-weight: bold; } .r-none { color: #888; }
.matrix { table-layout: fixed; width: 100%; }
.matrix td { font-size: 12px; overflow-wrap: anywhere; }
.matrix tr.group th { background: #e4e9f2; font-size: 13px; }
.matrix col.id { width: 8%; } .matrix col.src { width: 5%; } .matrix col.text { width: 17%; } .matrix col.status { width: 6%; }
.matrix col.cites { width: 9.5%; } .matrix col.result { width: 7%; }
.cite { font-family: monospace; font-size: 10.5px; margin-bottom: 2px; }
.plot { margin: 12px 0 28px; } .plot svg { max-width: 100%; height: auto; border: 1px solid #ddd; }
.register { max-width: 1100px; }
";

fn verdict_badge(passed: bool) -> &'static str {
    if passed {
        r#"<span class="verdict pass">PASS — every case conforms</span>"#
    } else {
        r#"<span class="verdict fail">FAIL — divergences or candidate failures</span>"#
    }
}

/// One matrix cell: the citations of a kind, the first few shown, the rest folded.
fn cite_cell(citations: &[&Citation]) -> String {
    const SHOWN: usize = 4;
    let item = |c: &Citation| format!(r#"<div class="cite" title="{f}:{l}">{f}:{l} {i}</div>"#, f = escape(c.file), l = c.line, i = escape(c.item));
    let mut s: String = citations.iter().take(SHOWN).map(|c| item(c)).collect();
    if citations.len() > SHOWN {
        let rest: String = citations.iter().skip(SHOWN).map(|c| item(c)).collect();
        let _ = write!(s, "<details><summary>{} more</summary>{rest}</details>", citations.len() - SHOWN);
    }
    if citations.is_empty() {
        s.push('—');
    }
    s
}

fn outcome_cell(o: Outcome) -> String {
    let class = match o {
        Outcome::Pass { .. } => "r-pass",
        Outcome::Fail { .. } => "r-fail",
        Outcome::NotExercised | Outcome::NotImplemented => "r-none",
    };
    format!(r#"<span class="{class}">{}</span>"#, escape(&o.label()))
}

fn matrix(rows: &[Row], out: &mut String) {
    out.push_str(r#"<table class="matrix"><colgroup><col class="id"><col class="src"><col class="text"><col class="status">"#);
    for _ in Kind::ALL {
        out.push_str(r#"<col class="cites">"#);
    }
    out.push_str(r#"<col class="result"></colgroup>"#);
    out.push_str("<tr><th>rule</th><th>source</th><th>rule text</th><th>status</th>");
    for k in Kind::ALL {
        let _ = write!(out, "<th>{}</th>", k.name());
    }
    out.push_str("<th>result in this run</th></tr>\n");
    let columns = 5 + Kind::ALL.len();
    for (i, r) in rows.iter().enumerate() {
        if i == 0 || rows[i - 1].group != r.group {
            let _ = writeln!(out, r#"<tr class="group"><th colspan="{columns}">{}</th></tr>"#, escape(&r.group.label()));
        }
        let _ = write!(
            out,
            r#"<tr id="rule-{id}"><td><b>{id}</b></td><td>{src}</td><td class="text">{text}</td><td>{status}</td>"#,
            id = escape(r.id),
            src = escape(r.source),
            text = super::markdown::inline(r.text),
            status = escape(r.status)
        );
        for k in Kind::ALL {
            let cites: Vec<&Citation> = r.of(k).collect();
            let _ = write!(out, "<td>{}</td>", cite_cell(&cites));
        }
        let _ = writeln!(out, "<td>{}</td></tr>", outcome_cell(r.outcome));
    }
    out.push_str("</table>\n");
}

fn summary(run: &Run, out: &mut String) {
    let candidate = match &run.candidate_argv {
        Some(argv) => format!(
            "external candidate <code>{}</code> (protocol {}, timeout {} ms, output cap {} bytes, {} process start(s))",
            escape(&argv.join(" ")),
            crate::candidate::SCHEMA,
            run.options.limits.timeout.as_millis(),
            run.options.limits.max_output,
            run.candidate_starts
        ),
        None => "the production expander <code>cycle-impl</code>".to_string(),
    };
    let _ = writeln!(out, "<p>{}</p>", verdict_badge(run.passed()));
    let _ = writeln!(
        out,
        "<table><tr><th>reference</th><td>the executable spec <code>cycle-spec</code></td></tr>\
         <tr><th>candidate</th><td>{candidate}</td></tr>\
         <tr><th>cases</th><td>{} ({} conform, {} diverge, {} fail)</td></tr>\
         <tr><th>cycles</th><td>{}</td></tr>\
         <tr><th>generated cases per family</th><td>{} (garbage: a fifth), seed {}</td></tr>\
         <tr><th>families</th><td>{}</td></tr>\
         <tr><th>duration</th><td>{:.1} s</td></tr>\
         <tr><th>tool</th><td>cyclecheck {}; docs/RULES.md {}; docs/INTERPRETATION.md {}</td></tr></table>",
        run.cases(),
        run.conforming(),
        run.diverging(),
        run.failures(),
        escape(&run.options.cycles.iter().map(|f| f.name).collect::<Vec<_>>().join(", ")),
        run.options.cases,
        run.options.seed,
        escape(
            &run.families
                .iter()
                .map(|f| format!("{} ({} drawn, {} kept, seed {})", f.family, f.drawn, f.kept, f.seed))
                .collect::<Vec<_>>()
                .join("; ")
        ),
        run.duration.as_secs_f64(),
        env!("CARGO_PKG_VERSION"),
        fingerprint(RULES_MD),
        fingerprint(INTERPRETATION_MD),
    );
    out.push_str("<table><tr><th>cycle run</th><th>counts the cases where</th><th>cases</th><th>conform</th><th>diverge</th><th>fail</th></tr>\n");
    for (cycle, [n, ok, div, fail]) in run.by_cycle() {
        let _ = writeln!(
            out,
            r#"<tr><td>{}</td><td>{}</td><td class="num">{n}</td><td class="num">{ok}</td><td class="num">{div}</td><td class="num">{fail}</td></tr>"#,
            escape(cycle.label()),
            escape(&cycle.describe())
        );
    }
    out.push_str("</table>\n");
}

fn divergences(run: &Run, out: &mut String) {
    if run.groups.is_empty() && run.failures() == 0 {
        out.push_str("<p>None: every case conforms.</p>\n");
        return;
    }
    for (g, group) in run.groups.iter().enumerate() {
        let first = &run.records[group.cases[0]];
        let (kind, field, rule) = group.signature;
        let _ = writeln!(
            out,
            "<h3 id=\"group-{g}\">{} case(s): {}{}{}</h3>",
            group.cases.len(),
            kind.name(),
            field.map(|f| format!(", field {f}")).unwrap_or_default(),
            rule.map(|r| format!(r##", rule <a href="#rule-{r}">{r}</a>"##)).unwrap_or_default()
        );
        if let CaseResult::Diverge(d) = &first.result {
            let _ = writeln!(out, "<p>First case <b>{}</b>:</p><pre>{}</pre>", escape(&first.name), escape(&d.to_string()));
        }
        if let Some(m) = &group.minimized {
            let _ = writeln!(
                out,
                "<p>Minimized input ({}, {} engine runs; divergence at event {}):</p><pre>{}</pre>",
                m.method,
                m.steps,
                m.divergence.index,
                escape(&String::from_utf8_lossy(&m.program))
            );
        }
        let names: Vec<&str> = group.cases.iter().take(30).map(|&i| run.records[i].name.as_str()).collect();
        let more = group.cases.len().saturating_sub(30);
        let _ = writeln!(
            out,
            "<p>Cases: {}{}</p>",
            escape(&names.join(", ")),
            if more > 0 { format!(" and {more} more (evidence.json lists all)") } else { String::new() }
        );
    }
    if run.failures() > 0 {
        out.push_str("<h3>Candidate failures</h3>\n<table><tr><th>case</th><th>engine</th><th>kind</th><th>message</th></tr>\n");
        for r in &run.records {
            if let CaseResult::Failure { engine, failure } = &r.result {
                let _ = writeln!(
                    out,
                    "<tr><td>{}</td><td>{}</td><td>{}</td><td><code>{}</code></td></tr>",
                    escape(&r.name),
                    escape(engine),
                    failure.kind,
                    escape(&failure.message)
                );
            }
        }
        out.push_str("</table>\n");
    }
}

/// The page. `plots`: (program name, path, result line, SVG) per corpus program.
pub fn page(run: &Run, rows: &[Row], plots: &[(String, String, String, String)]) -> String {
    let mut out = String::new();
    out.push_str("<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n");
    out.push_str("<title>cyclecheck certification evidence</title>\n<style>");
    out.push_str(STYLE);
    out.push_str("</style></head><body>\n<h1>cyclecheck certification evidence</h1>\n");
    out.push_str(r##"<nav><a href="#summary">Summary</a><a href="#divergences">Divergences</a><a href="#plots">Toolpath plots</a><a href="#matrix">Traceability matrix</a><a href="#register">Interpretation register</a><a href="evidence.json">evidence.json</a></nav>"##);
    out.push_str("\n<h2 id=\"summary\">Summary</h2>\n");
    summary(run, &mut out);
    out.push_str("<h2 id=\"divergences\">Divergences and failures</h2>\n");
    divergences(run, &mut out);
    let _ = writeln!(
        out,
        "<h2 id=\"plots\">Toolpath plots</h2>\n<p>One plot per corpus program of the run: Z across, X as a radius up (mm or inch), axes scaled independently. Rapids dashed, thread passes by kind, pull-outs orange, infeed points as dots; candidate moves that differ from the reference in red. Also in <code>plots/</code>.</p>"
    );
    for (name, path, result, svg) in plots {
        let _ = writeln!(
            out,
            "<div class=\"plot\"><h3>{} <small>({}) — {}</small></h3>\n{}</div>",
            escape(name),
            escape(path),
            escape(result),
            svg
        );
    }
    let implemented = rows.iter().filter(|r| r.implemented).count();
    let _ = writeln!(
        out,
        "<h2 id=\"matrix\">Traceability matrix</h2>\n<p>{} catalogue rules ({} implemented), grouped under headings: each cycle family's own rules, then the rules common to every family, then those of cycles not in the tool yet. Each row: the spec code that states the rule, the production code that implements it, the tests, proofs and fuzz targets that cite it (found in the sources at build time), and the result in this run — how many cases' reference traces carry the rule's tag, and whether a divergence names it.</p>",
        rows.len(),
        implemented
    );
    matrix(rows, &mut out);
    out.push_str("<h2 id=\"register\">Interpretation register</h2>\n<div class=\"register\">\n");
    out.push_str(&render(INTERPRETATION_MD));
    out.push_str("</div>\n</body></html>\n");
    out
}
