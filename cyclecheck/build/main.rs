//! Scans the workspace at build time for rule citations, for the traceability matrix of
//! `cyclecheck certify` (`src/certify/matrix.rs`). An installed binary never reads the
//! repository: the result is compiled in.
//!
//! A citation is a rule ID of `docs/RULES.md` written in a source file (`G92.JK.3`, in a comment
//! or a string) or its `cycle_vocab::Rule` variant (`Rule::G92Jk3`, or a bare `G92Jk3` where the
//! variant name differs from the ID). IDs without a dot (`G32`, `G162`) are also G codes, so for
//! them only `Rule::Name` counts. Each citation records its file, line, the enclosing item (the
//! fn or test around it, or the item a doc comment documents) and its kind:
//!
//! | kind | where |
//! |---|---|
//! | spec | `spec/src` |
//! | impl | `impl/src` |
//! | shared | `vocab/src` (the lexer, word values and trace both engines use; not the ID list `rule.rs`) |
//! | test | `tests/`, `#[cfg(test)]` modules and `tests.rs` files, `kernel/src/corpus.rs`, `kernel/src/gen/`, `kernel/tests`, `cyclecheck/tests`, `proofs/tests` |
//! | proof | `proofs/src` |
//! | fuzz | `fuzz/fuzz_targets`, `kernel/src/fuzzing` |

mod identity;

use std::collections::{BTreeMap, BTreeSet};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// The directories (or files) scanned, from the workspace root, and the kind of their code.
const ROOTS: &[(&str, &str)] = &[
    ("spec/src", "Spec"),
    ("impl/src", "Impl"),
    ("vocab/src", "Shared"),
    ("kernel/src/corpus.rs", "Test"),
    ("kernel/src/gen", "Test"),
    ("kernel/src/fuzzing", "Fuzz"),
    ("kernel/tests", "Test"),
    ("cyclecheck/tests", "Test"),
    ("tests", "Test"),
    ("proofs/src", "Proof"),
    ("proofs/tests", "Test"),
    ("fuzz/fuzz_targets", "Fuzz"),
];

fn main() {
    let manifest = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").expect("cargo sets CARGO_MANIFEST_DIR"));
    let root = manifest.parent().expect("cyclecheck/ sits in the workspace").to_path_buf();
    let rules_md = root.join("docs/RULES.md");
    let rule_rs = root.join("vocab/src/rule.rs");
    println!("cargo:rerun-if-changed={}", rules_md.display());
    println!("cargo:rerun-if-changed={}", rule_rs.display());
        println!("cargo:rerun-if-changed=build");
    identity::emit(&root);
    lemmas(&root);

    let ids = catalogue_ids(&std::fs::read_to_string(&rules_md).unwrap_or_default());
    let variants = variants(&std::fs::read_to_string(&rule_rs).unwrap_or_default(), &ids);

    let mut citations = BTreeMap::new();
    let mut scanned = Vec::new();
    for &(rel, kind) in ROOTS {
        let path = root.join(rel);
        if !path.exists() {
            continue;
        }
        // Only existing paths: a missing one would make cargo rerun this script every build.
        println!("cargo:rerun-if-changed={}", path.display());
        scanned.push(rel);
        let mut files = Vec::new();
        rust_files(&path, &mut files);
        files.sort();
        for file in files {
            let rel_file = file.strip_prefix(&root).unwrap_or(&file).to_string_lossy().replace('\\', "/");
            if rel_file.contains("/target/") || rel_file.starts_with("tests/fuzz_regressions") || rel_file == "vocab/src/rule.rs" {
                continue;
            }
            let text = std::fs::read_to_string(&file).unwrap_or_default();
            scan(&rel_file, &text, kind, &ids, &variants, &mut citations);
        }
    }

    let mut out = String::from("/// Rule citations found in the workspace at build time (`build.rs`).\n");
    out.push_str("pub static CITATIONS: &[Citation] = &[\n");
    for ((rule, kind, file, item), line) in &citations {
        let _ = writeln!(
            out,
            "    Citation {{ rule: {rule:?}, kind: Kind::{kind}, file: {file:?}, line: {line}, item: {item:?} }},"
        );
    }
    out.push_str("];\n\n/// The paths that were scanned (those present at build time).\n");
    let _ = writeln!(out, "pub static SCANNED: &[&str] = &{scanned:?};");
    let dest = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("citations.rs");
    std::fs::write(dest, out).expect("OUT_DIR is writable");
}

/// The IDs of the catalogue's rule rows (first cell of a 4-cell table row that is not a header,
/// a source key or a separator).
fn catalogue_ids(md: &str) -> BTreeSet<String> {
    let mut ids = BTreeSet::new();
    for line in md.lines() {
        let Some(inner) = line.trim().strip_prefix('|') else { continue };
        let first = inner.split('|').next().unwrap_or("").trim();
        let cells = inner.split('|').count();
        let looks_like_id = first.chars().next().is_some_and(|c| c.is_ascii_uppercase())
            && first.chars().all(|c| c.is_ascii_alphanumeric() || c == '.');
        if looks_like_id && first != "ID" && cells >= 5 {
            ids.insert(first.to_string());
        }
    }
    ids
}

/// `Variant => "ID"` pairs of `vocab/src/rule.rs`, for the IDs of the catalogue.
fn variants(rule_rs: &str, ids: &BTreeSet<String>) -> BTreeMap<String, String> {
    let mut map = BTreeMap::new();
    for line in rule_rs.lines() {
        let Some((name, id)) = line.trim().split_once(" => \"") else { continue };
        let id = id.trim_end_matches(',').trim_end_matches('"');
        if ids.contains(id) && name.chars().all(|c| c.is_ascii_alphanumeric()) {
            map.insert(name.to_string(), id.to_string());
        }
    }
    map
}

fn rust_files(path: &Path, out: &mut Vec<PathBuf>) {
    if path.is_file() {
        if path.extension().is_some_and(|e| e == "rs") {
            out.push(path.to_path_buf());
        }
        return;
    }
    let Ok(entries) = std::fs::read_dir(path) else { return };
    for entry in entries.flatten() {
        let p = entry.path();
        if p.file_name().is_some_and(|n| n == "target" || n == "snapshots") {
            continue;
        }
        rust_files(&p, out);
    }
}

/// One declared item: its name (`fn name`, `test name`, `mod name`…), its lines, whether it
/// is a fn, and whether it is test code.
struct Item {
    label: String,
    start: usize,
    end: usize,
    is_fn: bool,
    test_code: bool,
}

/// The citations of one file, keyed (rule, kind, file, item) → first line.
fn scan(
    file: &str,
    text: &str,
    kind: &str,
    ids: &BTreeSet<String>,
    variants: &BTreeMap<String, String>,
    citations: &mut BTreeMap<(String, String, String, String), usize>,
) {
    let lines: Vec<&str> = text.lines().collect();
    let items = items(&lines);
    let whole_file_tests = file.ends_with("/tests.rs");
    for (i, line) in lines.iter().enumerate() {
        let found = rules_in(line, ids, variants);
        if found.is_empty() {
            continue;
        }
        let (label, test_code) = owner(&lines, &items, i);
        let kind = if whole_file_tests || test_code { "Test" } else { kind };
        let label = corpus_label(line).unwrap_or(label);
        for rule in found {
            citations.entry((rule, kind.to_string(), file.to_string(), label.clone())).or_insert(i + 1);
        }
    }
}

/// `program!("corpus", "g92_example", …)` lines of the corpus: the program's name.
fn corpus_label(line: &str) -> Option<String> {
    let rest = line.trim().strip_prefix("program!(")?;
    let name = rest.split('"').nth(3)?;
    Some(format!("corpus program {name}"))
}

/// The rule IDs a line cites.
fn rules_in(line: &str, ids: &BTreeSet<String>, variants: &BTreeMap<String, String>) -> BTreeSet<String> {
    let mut found = BTreeSet::new();
    let bytes = line.as_bytes();
    let ident = |b: u8| b.is_ascii_alphanumeric() || b == b'_';
    // Words: runs of identifier characters and dots between identifier characters.
    let mut i = 0;
    while i < bytes.len() {
        if !ident(bytes[i]) || (i > 0 && (ident(bytes[i - 1]) || bytes[i - 1] == b'.')) {
            i += 1;
            continue;
        }
        let mut j = i;
        while j < bytes.len() && (ident(bytes[j]) || (bytes[j] == b'.' && j + 1 < bytes.len() && ident(bytes[j + 1]))) {
            j += 1;
        }
        let word = &line[i..j];
        let after_rule = line[..i].ends_with("Rule::");
        if ids.contains(word) && word.contains('.') {
            found.insert(word.to_string());
        } else if let Some(id) = variants.get(word) {
            if after_rule || word != id {
                found.insert(id.clone());
            }
        } else if ids.contains(word) && after_rule {
            found.insert(word.to_string());
        }
        i = j;
    }
    found
}

/// The label of the item owning line `i` and whether it is test code: the item a doc comment
/// or attribute documents, else the innermost fn around the line, else the innermost item,
/// else the module.
fn owner(lines: &[&str], items: &[Item], i: usize) -> (String, bool) {
    let in_test = items.iter().any(|it| it.test_code && it.start <= i && i <= it.end);
    let t = lines[i].trim_start();
    if t.starts_with("///") || t.starts_with("#[") {
        if let Some(it) = items.iter().find(|it| it.start > i && documents(lines, i, it.start)) {
            return (it.label.clone(), in_test || it.test_code);
        }
    }
    let around = |fns_only: bool| {
        items
            .iter()
            .filter(|it| it.start <= i && i <= it.end && (!fns_only || it.is_fn))
            .min_by_key(|it| it.end - it.start)
    };
    match around(true).or_else(|| around(false)) {
        Some(it) => (it.label.clone(), in_test || it.test_code),
        None => ("module docs".to_string(), in_test),
    }
}

/// Whether only doc comments and attributes stand between line `i` and the item at `start`.
fn documents(lines: &[&str], i: usize, start: usize) -> bool {
    lines[i + 1..start].iter().all(|l| {
        let t = l.trim_start();
        t.starts_with("///") || t.starts_with("#[") || t.starts_with("//") || t.is_empty()
    })
}

/// The items of a file with their line spans (brace matching that skips comments, strings and
/// character literals).
fn items(lines: &[&str]) -> Vec<Item> {
    let mut items = Vec::new();
    for (i, line) in lines.iter().enumerate() {
        let Some((keyword, name)) = declaration(line) else { continue };
        let attrs = attributes_before(lines, i);
        let is_test = attrs.iter().any(|a| a.contains("#[test]") || a.contains("proptest") || a.contains("#[tokio::test]"));
        let is_proof = attrs.iter().any(|a| a.contains("kani::proof"));
        let cfg_test = attrs.iter().any(|a| a.contains("#[cfg(test)]"));
        let label = match keyword {
            "fn" if is_test => format!("test {name}"),
            "fn" if is_proof => format!("proof {name}"),
            "fn" => format!("fn {name}"),
            k => format!("{k} {name}"),
        };
        let end = span_end(lines, i);
        items.push(Item { label, start: i, end, is_fn: keyword == "fn", test_code: is_test || (cfg_test && keyword == "mod") });
    }
    items
}

/// The attribute lines directly above line `i` (skipping doc comments).
fn attributes_before<'a>(lines: &[&'a str], i: usize) -> Vec<&'a str> {
    let mut attrs = Vec::new();
    let mut k = i;
    while k > 0 {
        k -= 1;
        let t = lines[k].trim_start();
        if t.starts_with("#[") {
            attrs.push(t);
        } else if !t.starts_with("///") {
            break;
        }
    }
    attrs
}

/// `fn name`, `struct Name`, `mod name`, … when the line declares an item.
fn declaration(line: &str) -> Option<(&'static str, String)> {
    let mut t = line.trim_start();
    if t.starts_with("//") {
        return None;
    }
    // Visibility and qualifiers: `pub(crate) const unsafe fn` is a fn.
    loop {
        let stripped = ["pub(crate) ", "pub(super) ", "pub ", "async ", "unsafe ", "default "]
            .iter()
            .find_map(|p| t.strip_prefix(p))
            .or_else(|| t.strip_prefix("const ").filter(|r| r.starts_with("fn ") || r.starts_with("unsafe ")));
        match stripped {
            Some(rest) => t = rest,
            None => break,
        }
    }
    for keyword in ["fn", "struct", "enum", "mod", "trait", "const", "static", "impl", "macro_rules!", "type"] {
        let Some(rest) = t.strip_prefix(keyword) else { continue };
        let rest = if keyword == "macro_rules!" { rest } else { rest.strip_prefix(' ')? };
        let rest = rest.trim_start();
        let name: String = if keyword == "impl" {
            rest.split('{').next().unwrap_or("").trim().to_string()
        } else {
            rest.chars().take_while(|c| c.is_ascii_alphanumeric() || *c == '_').collect()
        };
        if name.is_empty() {
            return None;
        }
        return Some((keyword, name));
    }
    None
}

/// The last line of the item declared on line `start`: where its braces close, or the line
/// with its `;` when it has no body.
fn span_end(lines: &[&str], start: usize) -> usize {
    let mut depth = 0i64;
    let mut opened = false;
    for (k, line) in lines.iter().enumerate().skip(start) {
        let bytes = line.as_bytes();
        let mut j = 0;
        let mut in_str = false;
        while j < bytes.len() {
            let b = bytes[j];
            if in_str {
                match b {
                    b'\\' => j += 1,
                    b'"' => in_str = false,
                    _ => {}
                }
            } else {
                match b {
                    b'/' if bytes.get(j + 1) == Some(&b'/') => break,
                    b'"' => in_str = true,
                    b'\'' if bytes.get(j + 2) == Some(&b'\'') => j += 2,
                    b'\'' if bytes.get(j + 1) == Some(&b'\\') && bytes.get(j + 3) == Some(&b'\'') => j += 3,
                    b'{' => {
                        depth += 1;
                        opened = true;
                    }
                    b'}' => depth -= 1,
                    b';' if !opened && depth == 0 => return k,
                    _ => {}
                }
            }
            j += 1;
        }
        if opened && depth <= 0 {
            return k;
        }
    }
    lines.len().saturating_sub(1)
}

/// `$OUT_DIR/lemmas.rs`: the z3 lemma files of `smt/lemmas/` compiled in (stem, text), sorted,
/// for the evidence's proofs section (`certify/proofs.rs`).
fn lemmas(root: &std::path::Path) {
    let dir = root.join("smt/lemmas");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).filter(|p| p.extension().is_some_and(|x| x == "smt2")).collect())
        .unwrap_or_default();
    files.sort();
    if dir.exists() {
        println!("cargo:rerun-if-changed={}", dir.display());
    }
    let mut out = String::from("[\n");
    for f in &files {
        let stem = f.file_stem().map(|s| s.to_string_lossy().into_owned()).unwrap_or_default();
        out.push_str(&format!("    ({stem:?}, include_str!({:?})),\n", f.display().to_string()));
    }
    out.push(']');
    let dest = PathBuf::from(std::env::var("OUT_DIR").expect("cargo sets OUT_DIR")).join("lemmas.rs");
    std::fs::write(dest, out).expect("OUT_DIR is writable");
}
