//! `index.html`: one self-contained page for a certification reviewer — no scripts, no external
//! files, nothing folded away (it prints whole): the verdict, what was tested (time, build,
//! host, candidate executable and its SHA-256) and the summary, divergences (first case in full,
//! minimized input) and candidate failures, one toolpath plot per corpus program (inline SVG),
//! the traceability matrix with its coverage line, and the interpretation register
//! (`docs/INTERPRETATION.md`, compiled in).

use super::evidence::{fingerprint, INTERPRETATION_MD, RULES_MD};
use super::markdown::{escape, render};
use super::matrix::{coverage, Citation, Kind, Outcome, Row};
use super::{CaseRecord, CaseResult, Run, MAX_LISTED_FAILURES};
use cycle_kernel::conformance::word_text;
use std::fmt::Write as _;

/// One corpus program's plot on the page.
pub struct PlotEntry {
    pub name: String,
    pub path: String,
    /// Its result, and its ending when it ends in an alarm ([`result_line`]).
    pub result: String,
    pub svg: String,
}

/// A corpus program's result for its heading: `conform`, and how its trace ends when it ends
/// in an alarm — as the program is written to (`corpus::Program::expect_alarm`) or not.
pub fn result_line(r: &CaseRecord) -> String {
    // The reference's ending as recorded (`clean`, or the alarm's short form), so a merged
    // bundle, which has no traces, words it as the run did.
    let expected = cycle_kernel::corpus::find(&r.name).and_then(|p| p.expect_alarm).map(|e| {
        let word = e.word.map(|w| format!(" {}", word_text(w))).unwrap_or_default();
        format!("alarm {}{word} {}", e.code.number(), e.rule)
    });
    match r.ending.as_str() {
        ending if !ending.starts_with("alarm ") => r.result.short(),
        ending if expected.as_deref() == Some(ending) => {
            format!("{}; the trace ends in {ending} by design (the program as printed is refused)", r.result.short())
        }
        ending => format!("{}; the trace ends in {ending}", r.result.short()),
    }
}

const STYLE: &str = "
body { font-family: -apple-system, 'Segoe UI', Helvetica, Arial, sans-serif; margin: 0 auto; max-width: 1500px; padding: 0 24px 48px; color: #222; line-height: 1.4; }
h1 { margin-top: 24px; } h2 { border-bottom: 2px solid #ddd; padding-bottom: 4px; margin-top: 40px; }
nav a { margin-right: 14px; }
table { border-collapse: collapse; margin: 8px 0 16px; font-size: 13px; }
th, td { border: 1px solid #ccc; padding: 3px 6px; vertical-align: top; text-align: left; }
th { background: #f3f3f3; }
td.num { text-align: right; font-variant-numeric: tabular-nums; }
pre { background: #f7f7f7; border: 1px solid #ddd; padding: 8px; overflow-x: auto; font-size: 12px; white-space: pre-wrap; }
code { font-size: 12px; }
.verdict { display: inline-block; padding: 6px 14px; border-radius: 4px; font-weight: bold; font-size: 18px; color: white; }
.pass { background: #2e7d32; } .fail { background: #c62828; }
.r-pass { color: #2e7d32; } .r-fail { color: #c62828; font-weight: bold; } .r-none { color: #888; }
.coverage { font-size: 16px; font-weight: bold; }
.matrix { table-layout: fixed; width: 100%; }
.matrix td { font-size: 12px; overflow-wrap: normal; word-break: normal; hyphens: none; }
.matrix .id, .matrix .nb { white-space: nowrap; }
.matrix tr.group th { background: #e4e9f2; font-size: 13px; }
.matrix col.id { width: 9.5em; } .matrix col.src { width: 4.5em; } .matrix col.text { width: 30%; } .matrix col.status { width: 5.5em; }
.matrix col.result { width: 9em; }
.kind { margin-bottom: 3px; } .kind b { display: inline-block; min-width: 5.5em; }
.cite { display: inline-block; white-space: nowrap; font-family: monospace; font-size: 10.5px; margin-right: 12px; }
.mention { color: #777; }
.plot { margin: 12px 0 28px; break-inside: avoid; } .plot svg { max-width: 100%; height: auto; border: 1px solid #ddd; }
.alarmed { color: #c62828; }
.register { max-width: 1100px; }
@media print {
  @page { size: A4 landscape; margin: 12mm; }
  body { max-width: none; padding: 0; font-size: 11px; }
  nav { display: none; }
  .matrix td { font-size: 10px; } .cite { font-size: 8.5px; }
  tr, .plot, pre { break-inside: avoid; }
}
";

/// The verdict as [`Run::verdict`] words it: plain PASS only for a full comparison in which
/// every case conforms.
fn verdict_badge(run: &Run) -> String {
    let verdict = escape(&run.verdict());
    match (run.passed(), run.deviating() > 0) {
        (true, false) => format!(r#"<span class="verdict pass">{verdict} — every case conforms</span>"#),
        (true, true) => format!(r#"<span class="verdict pass">{verdict} — every other case conforms</span>"#),
        (false, _) => format!(r#"<span class="verdict fail">{verdict} — divergences or candidate failures</span>"#),
    }
}

/// The citations of one row: per kind, every citation (nothing folded), each kept whole on
/// its line; then the mentions in module documentation, apart.
fn citations_cell(r: &Row) -> String {
    let item = |c: &Citation| format!(r#"<span class="cite">{}:{} {}</span>"#, escape(c.file), c.line, escape(c.item));
    let mut s = String::new();
    for k in Kind::ALL {
        let cites: Vec<&Citation> = r.of(k).collect();
        if !cites.is_empty() {
            let _ = write!(s, r#"<div class="kind"><b>{}</b> {}</div>"#, k.name(), cites.iter().map(|c| item(c)).collect::<String>());
        }
    }
    let mentions: Vec<&Citation> = r.mentions().collect();
    if !mentions.is_empty() {
        let list: String = mentions.iter().map(|c| format!(r#"<span class="cite">{}:{}</span>"#, escape(c.file), c.line)).collect();
        let _ = write!(s, r#"<div class="kind mention"><b>mentioned</b> in module docs: {list}</div>"#);
    }
    if s.is_empty() {
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
    out.push_str(r#"<table class="matrix"><colgroup><col class="id"><col class="src"><col class="text"><col class="status"><col class="result"><col class="cites"></colgroup>"#);
    out.push_str("<tr><th>rule</th><th>source</th><th>rule text</th><th>status</th><th>result in this run</th><th>code and checks that cite it (file:line item)</th></tr>\n");
    for (i, r) in rows.iter().enumerate() {
        if i == 0 || rows[i - 1].group != r.group {
            let _ = writeln!(out, r#"<tr class="group"><th colspan="6">{}</th></tr>"#, escape(&r.group.label()));
        }
        let _ = writeln!(
            out,
            r#"<tr id="rule-{id}"><td class="id"><b>{id}</b></td><td class="nb">{src}</td><td class="text">{text}</td><td class="nb">{status}</td><td>{result}</td><td>{cites}</td></tr>"#,
            id = escape(r.id),
            src = escape(r.source),
            text = super::markdown::inline(r.text),
            status = escape(r.status),
            result = outcome_cell(r.outcome),
            cites = citations_cell(r),
        );
    }
    out.push_str("</table>\n");
}

/// What was tested, and with what.
fn identity(run: &Run, out: &mut String) {
    let id = &run.identity;
    let b = &id.build;
    let dirty = match b.dirty {
        "true" => " <b>(sources differ from this commit)</b>",
        "false" => "",
        _ => " (whether the sources differ from it is unknown)",
    };
    let _ = write!(
        out,
        "<table><tr><th>run started (UTC)</th><td>{}</td></tr>\
         <tr><th>cyclecheck build</th><td>version {}, commit <code>{}</code>{dirty}; {}; profile {}, target {}</td></tr>\
         <tr><th>host</th><td>{} — {}, kernel {}, {}</td></tr>",
        escape(&id.started_utc),
        escape(b.version),
        escape(b.commit),
        escape(b.rustc),
        escape(b.profile),
        escape(b.target),
        escape(&id.host.name),
        escape(&id.host.os),
        escape(&id.host.kernel),
        escape(&id.host.arch),
    );
    if let Some(s) = run.options.shard {
        let _ = write!(out, "<tr><th>shard</th><td>{s} of the run: <code>cyclecheck merge</code> joins the shards into the run's bundle</td></tr>");
    }
    if !run.merged_from.is_empty() {
        let shards: Vec<String> = run
            .merged_from
            .iter()
            .map(|s| format!("{} on {} ({}, {:.1} s, {} cases)", s.shard, escape(&s.host), escape(&s.started_utc), s.duration_s, s.cases))
            .collect();
        let _ = write!(out, "<tr><th>merged from {} shards</th><td>{}</td></tr>", shards.len(), shards.join("<br>"));
    }
    if let Some(c) = &id.candidate {
        let hashed = |h: &super::identity::Hashed| match (&h.sha256, &h.error) {
            (Some(sha), _) => format!("<code>{}</code> SHA-256 <code>{sha}</code>", escape(&h.path)),
            (None, e) => format!("<code>{}</code> ({})", escape(&h.path), escape(e.as_deref().unwrap_or("unreadable"))),
        };
        let _ = write!(out, "<tr><th>candidate executable</th><td>{}</td></tr>", hashed(&c.executable));
        for f in &c.files {
            let _ = write!(out, "<tr><th>file on its command line</th><td>{}</td></tr>", hashed(f));
        }
    }
    out.push_str("</table>\n");
}

/// The readings the cases ran under, and the cases per value of each reading.
fn readings_cell(run: &Run) -> String {
    let line = run.readings.line();
    let line = line.strip_prefix("readings: ").unwrap_or(&line);
    let counts = run.tally.readings.lines().iter().map(|l| escape(l)).collect::<Vec<_>>().join("<br>");
    format!("{}<br><small>cases per value: {counts}</small>", escape(line))
}

fn summary(run: &Run, out: &mut String) {
    let candidate = match &run.candidate_argv {
        Some(argv) => format!(
            "external candidate <code>{}</code> (protocol {}, timeout {} ms, output cap {} bytes, stop after {} consecutive failures, {} process start(s))",
            escape(&argv.join(" ")),
            crate::candidate::SCHEMA,
            run.options.limits.timeout.as_millis(),
            run.options.limits.max_output,
            run.options.max_failures,
            run.candidate_starts
        ),
        None => "the production expander <code>cycle-impl</code>".to_string(),
    };
    let _ = writeln!(out, "<p>{}</p>", verdict_badge(run));
    super::verdict::html(run, out);
    if let Some(st) = run.stopped {
        let _ = writeln!(
            out,
            r#"<p class="r-fail">STOPPED after {} consecutive candidate failures (<code>--max-failures</code>): {} of at most {} cases judged.</p>"#,
            st.consecutive_failures, st.judged, st.planned
        );
    }
    let rows = super::matrix::rows(Some(run));
    let (exercised, implemented) = coverage(&rows);
    let _ = writeln!(out, r##"<p class="coverage">Rules exercised: {exercised} of {implemented} implemented (<a href="#matrix">traceability matrix</a>).</p>"##);
    identity(run, out);
    let _ = writeln!(
        out,
        "<table><tr><th>reference</th><td>the executable spec <code>cycle-spec</code></td></tr>\
         <tr><th>candidate</th><td>{candidate}</td></tr>\
         <tr><th>declared readings</th><td>{}</td></tr>\
         <tr><th>cases</th><td>{} ({} conform, {} deviate as declared, {} diverge, {} fail)</td></tr>\
         <tr><th>cycles</th><td>{}</td></tr>\
         <tr><th>generated cases per family</th><td>{} (garbage: a fifth), seed {}</td></tr>\
         <tr><th>families</th><td>{}</td></tr>\
         <tr><th>duration</th><td>{:.1} s</td></tr>\
         <tr><th>documents compiled in</th><td>cyclecheck {}; docs/RULES.md {}; docs/INTERPRETATION.md {}</td></tr></table>",
        readings_cell(run),
        run.cases(),
        run.conforming(),
        run.deviating(),
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
    out.push_str("<table><tr><th>cycle run</th><th>counts the cases where</th><th>cases</th><th>conform</th><th>deviate as declared</th><th>diverge</th><th>fail</th></tr>\n");
    for (cycle, [n, ok, dev, div, fail]) in run.by_cycle() {
        let _ = writeln!(
            out,
            r#"<tr><td>{}</td><td>{}</td><td class="num">{n}</td><td class="num">{ok}</td><td class="num">{dev}</td><td class="num">{div}</td><td class="num">{fail}</td></tr>"#,
            escape(cycle.label()),
            escape(&cycle.describe())
        );
    }
    out.push_str("</table>\n");
}

fn divergences(run: &Run, out: &mut String) {
    if run.groups.is_empty() && run.failures() == 0 {
        let deviate = if run.deviating() > 0 { " (the cases that deviate as declared aside, listed above)" } else { "" };
        let _ = writeln!(out, "<p>None: every case conforms{deviate}.</p>");
        return;
    }
    for (g, group) in run.groups.iter().enumerate() {
        let first = &group.first;
        let (kind, field, rule) = group.signature;
        let _ = writeln!(
            out,
            "<h3 id=\"group-{g}\">{} case(s): {}{}{}</h3>",
            group.count,
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
        let names: Vec<&str> = group.names.iter().take(30).map(String::as_str).collect();
        let more = group.count.saturating_sub(names.len());
        let _ = writeln!(
            out,
            "<p>Cases: {}{}</p>",
            escape(&names.join(", ")),
            if more > 0 { format!(" and {more} more (cases.jsonl lists all, with their group {g})") } else { String::new() }
        );
    }
    if run.failures() > 0 {
        out.push_str("<h3>Candidate failures</h3>\n<table><tr><th>case</th><th>engine</th><th>kind</th><th>message</th></tr>\n");
        for r in &run.failures {
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
        if run.failures() > run.failures.len() {
            let _ = writeln!(out, "<p>The first {MAX_LISTED_FAILURES} of {} failures; cases.jsonl lists all.</p>", run.failures());
        }
    }
}

/// The page, with a plot per corpus program.
/// The proof properties and how each was checked in this bundle: Kani (an imported log, or not
/// run here), the z3 lemmas on its rules (run now), the drivers (`cargo test`).
fn proofs(run: &Run, out: &mut String) {
    let p = &run.proofs;
    let z3 = match &p.z3_version {
        None if p.left_to_merge => "this bundle is a shard: cyclecheck merge runs the z3 lemmas".to_string(),
        Some(v) => format!("z3 ran here ({}): {} of {} lemmas unsat", escape(v), p.lemmas.iter().filter(|l| l.proved()).count(), p.lemmas.len()),
        None => "z3 is not on this machine's PATH: the lemmas were not run".to_string(),
    };
    let kani = match &p.kani {
        Some(k) => format!("Kani log imported (Kani {}, CBMC {})", escape(k.kani_version.as_deref().unwrap_or("unknown")), escape(k.cbmc_version.as_deref().unwrap_or("unknown"))),
        None => "no Kani log imported (`--kani-log`): Kani was not run here".to_string(),
    };
    let _ = writeln!(
        out,
        "<h2 id=\"proofs\">Proofs: how each property was checked</h2>\n<p>{z3}. {kani}. The drivers (bounded-exhaustive and random) run every harness body under <code>cargo test</code>, not in this run. Nothing below is a proof unless z3 answered <code>unsat</code> or Kani SUCCESSFUL.</p>\n<table><tr><th>property</th><th>rules</th><th>Kani</th><th>z3 lemmas</th></tr>"
    );
    for prop in super::kani::PROPERTIES {
        let lemmas: Vec<String> = p.lemmas_for(prop.rules).iter().map(|l| format!("{} <b>{}</b>", escape(l.name), escape(&l.result))).collect();
        let _ = writeln!(
            out,
            "<tr><td><code>{}</code>: {}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            escape(prop.harness),
            escape(prop.statement),
            escape(&prop.rules.join(", ")),
            escape(&p.kani_status(prop.harness, prop.checked_by)),
            if lemmas.is_empty() { "—".to_string() } else { lemmas.join("<br>") }
        );
    }
    out.push_str("</table>\n");
}

pub fn page(run: &Run, rows: &[Row], plots: &[PlotEntry]) -> String {
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
    for p in plots {
        let class = if p.result.contains("the trace ends in") { " class=\"alarmed\"" } else { "" };
        let _ = writeln!(
            out,
            "<div class=\"plot\"><h3>{} <small>({}) — <span{class}>{}</span></small></h3>\n{}</div>",
            escape(&p.name),
            escape(&p.path),
            escape(&p.result),
            p.svg
        );
    }
    proofs(run, &mut out);
    let (exercised, implemented) = coverage(rows);
    let _ = writeln!(
        out,
        "<h2 id=\"matrix\">Traceability matrix</h2>\n<p class=\"coverage\">Rules exercised in this run: {exercised} of {implemented} implemented ({} catalogue rules).</p>\n<p>Grouped under headings: each cycle family's own rules, then the rules common to every family, then those of cycles not in the tool yet. Each row: the result in this run — how many cases' reference traces or alarms carry the rule's tag, how many built-in programs that illustrate it ran and conformed, and whether a divergence names it — then the spec code that states the rule, the production code that implements it, the tests, proofs and fuzz targets that check it (found in the sources at build time), and apart the mentions in module documentation, which check nothing.</p>",
        rows.len(),
    );
    matrix(rows, &mut out);
    out.push_str("<h2 id=\"register\">Interpretation register</h2>\n<div class=\"register\">\n");
    out.push_str(&render(INTERPRETATION_MD));
    out.push_str("</div>\n</body></html>\n");
    out
}
