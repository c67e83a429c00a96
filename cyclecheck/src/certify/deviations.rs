//! Declared deviations (`certify --deviations FILE`): what a candidate's authors say it does
//! differently from the reference, on purpose. A case whose *first* divergence matches a
//! declaration is reported as deviating as declared — never as conforming, and the rest of that
//! case is not compared; a declaration no case matches is reported as unused.
//!
//! The file is TOML, one `[[deviation]]` table per declaration:
//!
//! ```toml
//! [[deviation]]
//! rule = "G92.PULLOUT"   # required: the reference's rule at the first divergence (docs/RULES.md)
//! family = "g92"         # optional: the registry family the case runs
//! dialect = "fanuc"      # optional: gsk, fanuc, nc201
//! field = "z"            # optional: the divergent field (see [`field_of`])
//! reason = "no pull-out" # required
//! ```

use cycle_kernel::conformance::{Divergence, DivergenceKind};
use cycle_kernel::registry::{self, CycleRun};
use cycle_vocab::{Dialect, Rule};
use serde::Deserialize;
use serde_json::{json, Value};
use toml::Spanned;

/// One declaration.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Deviation {
    pub rule: Rule,
    /// A registry family's name (`g92`).
    pub family: Option<&'static str>,
    pub dialect: Option<Dialect>,
    /// A divergence's field as [`field_of`] names it.
    pub field: Option<String>,
    pub reason: String,
    /// Its `[[deviation]]` line in the file (1-based; 0 when read back from a bundle).
    pub line: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct File {
    #[serde(default)]
    deviation: Vec<Spanned<Raw>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct Raw {
    rule: Spanned<String>,
    family: Option<Spanned<String>>,
    dialect: Option<Spanned<String>>,
    field: Option<String>,
    reason: String,
}

/// The dialect named `name` (`gsk`, `fanuc`, `nc201`).
pub fn dialect(name: &str) -> Option<Dialect> {
    [Dialect::Gsk, Dialect::Fanuc, Dialect::Nc201].into_iter().find(|d| dialect_name(*d) == name)
}

/// A dialect's name as the protocol writes it.
pub fn dialect_name(d: Dialect) -> &'static str {
    match d {
        Dialect::Gsk => "gsk",
        Dialect::Fanuc => "fanuc",
        Dialect::Nc201 => "nc201",
    }
}

fn line_of(text: &str, offset: usize) -> usize {
    text[..offset.min(text.len())].bytes().filter(|&b| b == b'\n').count() + 1
}

/// Parses a deviations file; `origin` names it in messages. Bad TOML, a missing or unknown
/// key, an unknown rule, family or dialect: an error naming the key and the line.
pub fn parse(text: &str, origin: &str) -> Result<Vec<Deviation>, String> {
    let file: File = toml::from_str(text).map_err(|e| format!("{origin}: {}", e.to_string().trim_end()))?;
    file.deviation
        .into_iter()
        .map(|d| {
            let line = line_of(text, d.span().start);
            let d = d.into_inner();
            let at = |key: &str, span: std::ops::Range<usize>| format!("{origin} line {}: {key}", line_of(text, span.start));
            let rule = Rule::from_id(d.rule.get_ref())
                .ok_or_else(|| format!("{} = {:?} is no rule ID of docs/RULES.md", at("rule", d.rule.span()), d.rule.get_ref()))?;
            let family = match d.family {
                None => None,
                Some(f) => Some(registry::find(f.get_ref()).map(|f| f.name).ok_or_else(|| {
                    format!("{} = {:?} is no family (one of {})", at("family", f.span()), f.get_ref(), registry::names())
                })?),
            };
            let dialect = match d.dialect {
                None => None,
                Some(s) => Some(self::dialect(s.get_ref()).ok_or_else(|| format!("{} = {:?} is no dialect (gsk, fanuc, nc201)", at("dialect", s.span()), s.get_ref()))?),
            };
            if d.reason.trim().is_empty() {
                return Err(format!("{origin} line {line}: reason is empty: say why the candidate deviates"));
            }
            Ok(Deviation { rule, family, dialect, field: d.field, reason: d.reason, line })
        })
        .collect()
}

/// Reads and parses a deviations file.
pub fn read(path: &std::path::Path) -> Result<Vec<Deviation>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    parse(&text, &path.display().to_string())
}

/// The field a divergence is declared by: the divergent field when there is one (`x`, `z`,
/// `feed`, `kind`, `event`, `code`, …); `alarm` for an alarm where the other trace has none;
/// `length` for missing or extra events.
pub fn field_of(d: &Divergence) -> &'static str {
    match (d.field, d.kind) {
        (Some(f), _) => f,
        (None, DivergenceKind::UnexpectedAlarm | DivergenceKind::MissingAlarm) => "alarm",
        (None, _) => "length",
    }
}

impl Deviation {
    /// Whether the case's first divergence `d` (the case runs `cycle` under `dialect`) is this
    /// declaration's: every key it gives is equal. `field = "alarm"` also takes an alarm
    /// mismatch (any of its fields).
    pub fn matches(&self, d: &Divergence, cycle: CycleRun, dialect: Dialect) -> bool {
        let field_ok = self.field.as_deref().is_none_or(|f| f == field_of(d) || (f == "alarm" && d.kind == DivergenceKind::AlarmMismatch));
        d.rule == Some(self.rule)
            && self.family.is_none_or(|f| cycle.name() == f)
            && self.dialect.is_none_or(|x| x == dialect)
            && field_ok
    }

    /// The declaration as `evidence.json` lists it (without its count).
    pub fn json(&self) -> Value {
        json!({
            "rule": self.rule.id(),
            "family": self.family,
            "dialect": self.dialect.map(dialect_name),
            "field": self.field,
            "reason": self.reason,
            "line": self.line,
        })
    }

    /// The declaration from its JSON ([`Deviation::json`]).
    pub fn from_json(v: &Value) -> Result<Deviation, String> {
        let text = |k: &str| v[k].as_str().map(str::to_string);
        let parse_text = format!(
            "[[deviation]]\nrule = {}\nreason = {}\n{}{}{}",
            v["rule"],
            v["reason"],
            text("family").map(|f| format!("family = {f:?}\n")).unwrap_or_default(),
            text("dialect").map(|f| format!("dialect = {f:?}\n")).unwrap_or_default(),
            text("field").map(|f| format!("field = {f:?}\n")).unwrap_or_default(),
        );
        let mut d = parse(&parse_text, "evidence.json deviations")?.pop().ok_or("no deviation")?;
        d.line = v["line"].as_u64().unwrap_or(0) as usize;
        Ok(d)
    }

    /// One line for reports: `G92.PULLOUT (family g92, dialect fanuc, field z)`.
    pub fn label(&self) -> String {
        let keys: Vec<String> = [
            self.family.map(|f| format!("family {f}")),
            self.dialect.map(|d| format!("dialect {}", dialect_name(d))),
            self.field.as_ref().map(|f| format!("field {f}")),
        ]
        .into_iter()
        .flatten()
        .collect();
        if keys.is_empty() {
            self.rule.id().to_string()
        } else {
            format!("{} ({})", self.rule.id(), keys.join(", "))
        }
    }
}

/// The first declaration the divergence matches.
pub fn find(list: &[Deviation], d: &Divergence, cycle: CycleRun, dialect: Dialect) -> Option<usize> {
    list.iter().position(|x| x.matches(d, cycle, dialect))
}

#[cfg(test)]
mod tests;
