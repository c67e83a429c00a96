//! The concordance (`docs/CONCORDANCE.md`, issue #29 item 4) maps every line of the five seed
//! manuals to the catalogue rules it states, or says why none. The seeds are not in the
//! repository: the concordance is its copy of where each rule stands in them, and this test
//! checks its form — each file covered from line 1 to its count without gap or overlap, every ID
//! a rule of `docs/RULES.md`, every rule reached from some line (or listed, with a reason, as a
//! project rule without a seed line), every "no rule" row with its reason.

use cycle_vocab::Rule;
use std::collections::BTreeMap;

const CONCORDANCE: &str = include_str!("../../docs/CONCORDANCE.md");
const RULES_MD: &str = include_str!("../../docs/RULES.md");

/// The seed files and their line counts as an editor counts them (three have no final newline,
/// so `wc -l` prints one less for 002, 003 and 004).
const SEEDS: [(&str, u32); 5] = [
    ("000_59c747a38260c660.txt", 195),
    ("001_1aea90d5f3b16b8d.txt", 174),
    ("002_0f7b0b4f8da1513f.txt", 109),
    ("003_b2c47ef6d53aacbe.txt", 155),
    ("004_bcbbac4311b6debe.txt", 90),
];

/// How a "—" (no rule) row's note may begin.
const REASONS: [&str; 9] =
    ["blank", "heading", "markup", "metadata", "caption", "prose", "advice", "not modelled", "repeats"];

const WHERE: &str = "Where the project rules are reached";
const WITHOUT: &str = "Project rules without a seed line";

/// One row of a file's table.
#[derive(Debug)]
struct Row {
    first: u32,
    last: u32,
    rules: Vec<String>,
    note: String,
}

/// The concordance as read: the file sections (name, recorded count, rows), the where-table
/// (rule → its places) and the rules listed without a seed line (rule → reason).
#[derive(Default)]
struct Doc {
    files: Vec<(String, u32, Vec<Row>)>,
    places: BTreeMap<String, Vec<String>>,
    without: BTreeMap<String, String>,
}

/// The catalogue's rules and their source keys (`M001, M002`, `PRJ`, …).
fn catalogue(rules_md: &str) -> BTreeMap<String, String> {
    let keys = ["M000", "M001", "M002", "M003", "M004", "PRJ"];
    rules_md
        .lines()
        .filter_map(|l| {
            let cells: Vec<&str> = l.strip_prefix("| ")?.split('|').map(str::trim).collect();
            let (id, source) = (*cells.first()?, *cells.get(1)?);
            let is_source = !source.is_empty() && source.split(", ").all(|s| keys.contains(&s));
            (id.starts_with(|c: char| c.is_ascii_uppercase()) && is_source).then(|| (id.to_string(), source.to_string()))
        })
        .collect()
}

/// The cells of a table row, trimmed, without the header and separator rows.
fn cells(line: &str) -> Option<Vec<&str>> {
    let inner = line.strip_prefix('|')?.strip_suffix('|')?;
    let c: Vec<&str> = inner.split('|').map(str::trim).collect();
    (!c[0].starts_with("---") && !["lines", "project rule", "ID"].contains(&c[0])).then_some(c)
}

/// `12` or `12–15`.
fn range(s: &str) -> Option<(u32, u32)> {
    match s.split_once('–') {
        Some((a, b)) => Some((a.parse().ok()?, b.parse().ok()?)),
        None => s.parse().ok().map(|a| (a, a)),
    }
}

fn parse(text: &str) -> Result<Doc, String> {
    let mut doc = Doc::default();
    let mut section = String::new();
    for line in text.lines() {
        if let Some(h) = line.strip_prefix("## ") {
            section = h.to_string();
            if let Some((name, count)) = h.split_once(" — ") {
                let n = count.strip_suffix(" lines").and_then(|c| c.parse().ok());
                let n = n.ok_or_else(|| format!("heading `{h}`: no line count"))?;
                doc.files.push((name.to_string(), n, Vec::new()));
            }
            continue;
        }
        let Some(c) = cells(line) else { continue };
        if section == WHERE {
            let places = c.get(1).map(|p| p.split(", ").map(str::to_string).collect()).unwrap_or_default();
            doc.places.insert(c[0].to_string(), places);
        } else if section == WITHOUT {
            doc.without.insert(c[0].to_string(), c.get(1).unwrap_or(&"").to_string());
        } else if let Some((name, _, rows)) = doc.files.last_mut().filter(|f| section.starts_with(&f.0)) {
            let &[lines, rules, note] = c.as_slice() else { return Err(format!("{name}: row `{line}` has not three cells")) };
            let (first, last) = range(lines).ok_or_else(|| format!("{name}: bad range `{lines}`"))?;
            let rules = if rules == "—" { Vec::new() } else { rules.split(' ').map(str::to_string).collect() };
            rows.push(Row { first, last, rules, note: note.to_string() });
        }
    }
    Ok(doc)
}

/// Every fault of the concordance `text` against the catalogue `rules_md`, each naming the file
/// and range or the ID.
fn faults(text: &str, rules_md: &str) -> Vec<String> {
    let cat = catalogue(rules_md);
    let doc = match parse(text) {
        Ok(d) => d,
        Err(e) => return vec![e],
    };
    let mut out = Vec::new();
    let names: Vec<&str> = doc.files.iter().map(|f| f.0.as_str()).collect();
    for (name, count) in SEEDS {
        match doc.files.iter().find(|f| f.0 == name) {
            None => out.push(format!("{name}: no section")),
            Some(f) if f.1 != count => out.push(format!("{name}: recorded {} lines, the seed has {count}", f.1)),
            Some(_) => {}
        }
    }
    if names.len() != SEEDS.len() {
        out.push(format!("sections {names:?}: expected exactly the five seeds"));
    }
    let mut reached: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for (name, count, rows) in &doc.files {
        let mut next = 1;
        for r in rows {
            let at = if r.first == r.last { format!("{name} {}", r.first) } else { format!("{name} {}–{}", r.first, r.last) };
            if r.first != next {
                out.push(format!("{at}: expected the row to start at line {next} (gap or overlap)"));
            }
            if r.last < r.first {
                out.push(format!("{at}: the range runs backwards"));
            }
            next = r.last.max(r.first) + 1;
            for id in &r.rules {
                if !cat.contains_key(id) || Rule::from_id(id).is_none() {
                    out.push(format!("{at}: {id} is not a rule of docs/RULES.md"));
                }
                let place = format!("{}:{}", &name[..3.min(name.len())], at.rsplit(' ').next().unwrap_or(""));
                reached.entry(id.clone()).or_default().push(place);
            }
            if r.note.is_empty() {
                out.push(format!("{at}: no note"));
            }
            if r.rules.is_empty() {
                out.extend(no_rule_fault(&at, &r.note, *count, (r.first, r.last)));
            }
        }
        if next != count + 1 {
            out.push(format!("{name}: the rows end at line {}, the file at {count}", next - 1));
        }
    }
    for (id, source) in &cat {
        let listed = doc.without.get(id);
        match (reached.get(id), listed) {
            (None, None) => out.push(format!("{id}: no seed line reaches it")),
            (Some(p), Some(_)) => out.push(format!("{id}: listed without a seed line but reached at {p:?}")),
            (None, Some(reason)) if source != "PRJ" || reason.is_empty() => {
                out.push(format!("{id}: only a PRJ rule may be listed without a seed line, with a reason"))
            }
            _ => {}
        }
        if source == "PRJ" && listed.is_none() && doc.places.get(id) != reached.get(id) {
            out.push(format!("{id}: the where-table lists {:?}, the rows name it at {:?}", doc.places.get(id), reached.get(id)));
        }
    }
    for id in doc.places.keys().chain(doc.without.keys()) {
        if cat.get(id).map(String::as_str) != Some("PRJ") {
            out.push(format!("{id}: listed as a project rule, but docs/RULES.md gives no PRJ rule of that ID"));
        }
    }
    out
}

/// A "—" row's note: a known reason; `repeats` names lines of the same file outside the row.
fn no_rule_fault(at: &str, note: &str, count: u32, own: (u32, u32)) -> Option<String> {
    let Some(reason) = REASONS.iter().find(|r| note.starts_with(*r)) else {
        return Some(format!("{at}: a row without rules needs a reason ({REASONS:?}), not `{note}`"));
    };
    if *reason != "repeats" {
        return None;
    }
    let what = note["repeats ".len().min(note.len())..].split([' ', ':', ',']).next().unwrap_or("");
    match range(what) {
        Some((a, b)) if a >= 1 && b <= count && a <= b && (b < own.0 || a > own.1) => None,
        _ => Some(format!("{at}: `{note}` must name the lines of this file it repeats")),
    }
}

#[test]
fn the_concordance_covers_every_line_and_every_rule() {
    let f = faults(CONCORDANCE, RULES_MD);
    assert!(f.is_empty(), "docs/CONCORDANCE.md:\n{}", f.join("\n"));
}

#[test]
fn the_catalogue_is_read_whole() {
    let cat = catalogue(RULES_MD);
    assert_eq!(cat.len(), Rule::ALL.len(), "docs/RULES.md read as {} rules", cat.len());
    assert_eq!(cat.get("PRJ.MAXPASS").map(String::as_str), Some("PRJ"));
    assert_eq!(cat.get("COM.AXES").map(String::as_str), Some("M001, M002"));
}

/// The checks fail, naming the file and range or the ID, on broken copies of the concordance.
#[test]
fn faults_are_named() {
    let first = |needle: &str, with: &str| CONCORDANCE.replacen(needle, with, 1);
    let has = |text: &str, want: &str| {
        let f = faults(text, RULES_MD);
        assert!(f.iter().any(|m| m.contains(want)), "expected a fault containing `{want}`, got {f:#?}");
    };
    // A gap: the second row of 000 starts one line late.
    has(&first("| 2 | — | blank |", "| 3 | — | blank |"), "000_59c747a38260c660.txt 3: expected the row to start at line 2");
    // The last row of 004 stops short of line 90.
    has(&first("| 90 | — | caption", "| 89 | — | caption"), "004_bcbbac4311b6debe.txt 89: expected the row to start at line 90");
    // An ID that is no rule.
    has(&first("| 22–25 | COM.ABSINC |", "| 22–25 | COM.ABSINC G76.NOPE |"), "001_1aea90d5f3b16b8d.txt 22–25: G76.NOPE is not a rule");
    // A rule no line reaches any more (G34 stands on one row only).
    has(&first("| 155 | G34 |", "| 155 | G33 |"), "G34: no seed line reaches it");
    // A row without rules and without a reason; a repeat that names no lines.
    has(&first("| 6 | — | prose: G96", "| 6 | — | G96"), "003_b2c47ef6d53aacbe.txt 6: a row without rules needs a reason");
    has(&first("| 124 | — | repeats 23 |", "| 124 | — | repeats 999 |"), "003_b2c47ef6d53aacbe.txt 124: `repeats 999`");
    // A wrong line count; the where-table out of step with the rows.
    has(&first("— 109 lines", "— 108 lines"), "002_0f7b0b4f8da1513f.txt: recorded 108 lines, the seed has 109");
    has(&first("| PRJ.SUPPORTED | 002:97 |", "| PRJ.SUPPORTED | 002:99 |"), "PRJ.SUPPORTED: the where-table lists");
    // A rule listed without a seed line although a row reaches it.
    let listed = format!("{CONCORDANCE}\n| G76.HOLD | a reason |\n");
    has(&listed, "G76.HOLD: listed without a seed line but reached");
}
