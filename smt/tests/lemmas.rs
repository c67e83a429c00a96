//! The lemmas' soundness checks (the proofs themselves are tests/prove.rs): the assumptions of
//! every lemma satisfiable (none is `unsat` vacuously), the shared definitions identical in
//! every file, and the negative controls: deliberately wrong models for which a lemma is `sat`.

use cycle_smt::z3;
use std::collections::BTreeMap;

/// The assumptions alone (the negated property cut off) have a model: no lemma holds only
/// because its hypotheses contradict each other.
#[test]
fn every_lemmas_assumptions_are_satisfiable() {
    for path in z3::lemma_files() {
        let (name, text) = z3::lemma(path.as_path());
        let run = z3::check(&z3::assumptions_only(&text));
        assert_eq!(run.result, "sat", "{name}: assumptions alone");
    }
}

/// The `(define-fun NAME …)` blocks of a lemma file (a block: its first line and the indented
/// lines after it), trailing comments and spacing normalized.
fn definitions(text: &str) -> BTreeMap<String, String> {
    let mut defs = BTreeMap::new();
    let mut current: Option<(String, String)> = None;
    for line in text.lines() {
        let code = line.split(';').next().unwrap_or("").trim_end();
        if let Some(rest) = line.strip_prefix("(define-fun ") {
            if let Some((name, body)) = current.take() {
                defs.insert(name, body);
            }
            let name = rest.split_whitespace().next().unwrap_or("").to_string();
            current = Some((name, code.split_whitespace().collect::<Vec<_>>().join(" ")));
        } else if let (true, Some((_, body))) = (line.starts_with(' '), current.as_mut()) {
            *body += " ";
            *body += &code.split_whitespace().collect::<Vec<_>>().join(" ");
        } else if let Some((name, body)) = current.take() {
            defs.insert(name, body);
        }
    }
    if let Some((name, body)) = current {
        defs.insert(name, body);
    }
    defs
}

/// A definition used by several lemmas is the same text in each: one model (the one
/// src/model.rs transcribes), not a variant per file.
#[test]
fn shared_definitions_are_identical() {
    let mut seen: BTreeMap<String, (String, String)> = BTreeMap::new();
    let mut shared = 0;
    for path in z3::lemma_files() {
        let (name, text) = z3::lemma(&path);
        for (def, body) in definitions(&text) {
            match seen.get(&def) {
                Some((first, b)) => {
                    assert_eq!(b, &body, "`{def}` differs between {first} and {name}");
                    shared += 1;
                }
                None => {
                    seen.insert(def, (name.clone(), body));
                }
            }
        }
    }
    assert!(seen.contains_key("is_root") && seen.contains_key("depth_u") && shared >= 15, "{shared}");
}

/// The lemma `name` with the definition block `def` replaced by `block` (which must occur).
fn mutate(name: &str, def: &str, block: &str) -> String {
    let text = z3::lemma_named(name);
    let start = text.find(&format!("(define-fun {def} ")).unwrap_or_else(|| panic!("{name}: no {def}"));
    let len = text[start..].lines().take_while({
        let mut first = true;
        move |l| std::mem::replace(&mut first, false) || l.starts_with(' ')
    });
    let end = start + len.map(|l| l.len() + 1).sum::<usize>();
    format!("{}{block}\n{}", &text[..start], &text[end..])
}

/// The lemma `name` with the text `from` replaced by `to` (which must occur exactly once).
fn edit(name: &str, from: &str, to: &str) -> String {
    let text = z3::lemma_named(name);
    assert_eq!(text.matches(from).count(), 1, "{name}: `{from}`");
    text.replace(from, to)
}

/// Checks a mutated lemma is `sat` and prints z3's counterexample.
fn expect_sat(what: &str, text: &str) {
    let run = z3::check(text);
    let model = z3::check(&text.replace("(check-sat)", "(check-sat)\n(get-model)"));
    println!("negative control, {what}: {} in {:.2} s\n{}", run.result, run.seconds, model.output);
    assert_eq!(run.result, "sat", "{what}: the wrong model must violate the lemma");
}

/// The model mutant of the impl's `planted-depth-bug`: v = r² + r rounds to r + 1.
const IS_ROOT_TIES_UP: &str = "(define-fun is_root ((v Int) (r Int)) Bool
  (or (and (= r 0) (<= v 0))
      (and (>= r 1) (>= v 1) (<= (- (* r r) r) v) (< v (+ (* r r) r)))))";

/// Rounding one increment too high at v = r² + r: the threshold where the rounded depth
/// reaches T moves (lemma 05 `sat`: v = T(T − 1) already rounds to T).
#[test]
fn negative_control_ties_up_rounding() {
    expect_sat("rounding r² + r up, lemma 05", &mutate("05_root_threshold", "is_root", IS_ROOT_TIES_UP));
    expect_sat("rounding r² + r up, lemma 01", &mutate("01_root_is_rounding", "is_root", IS_ROOT_TIES_UP));
}

/// The switch one pass late (⌊a²/c²⌋ + 3): lemma 07 `sat` (the rule already holds at s − 1).
#[test]
fn negative_control_switch_one_pass_late() {
    let late = edit("07_switch_pass", "(+ (div (* a a) (* 4 dd dd dm dm)) 2)", "(+ (div (* a a) (* 4 dd dd dm dm)) 3)");
    expect_sat("switch pass ⌊a²/c²⌋ + 3, lemma 07", &late);
}

/// The switch rule non-strict (a² ≤ c²(n − 1), a switch at the tie): lemma 07 `sat` (the
/// closed form is no longer its first pass: Δd = Δdmin switches at pass 1).
#[test]
fn negative_control_switch_at_the_tie() {
    let tie = edit("07_switch_pass", "(or (< a 0) (< (* a a)", "(or (< a 0) (<= (* a a)");
    expect_sat("switch rule with ≤, lemma 07", &tie);
}

/// The count with a floor instead of a ceiling: lemma 11 `sat`.
#[test]
fn negative_control_count_floor() {
    let floor = mutate("11_rough_count", "ceil_div", "(define-fun ceil_div ((x Int) (m Int)) Int (div x m))");
    expect_sat("count with ⌊(T − b)/Δdmin⌋, lemma 11", &floor);
}

/// The peck count one too many (K = t div l + 1, the ceiling's tie at t mod l = 0 lost): lemma
/// 16 `sat` (a multiple of the peck gets an extra peck of no depth).
#[test]
fn negative_control_peck_count_one_too_many() {
    let more = edit("16_peck_count", "(ite (= (mod t l) 0) 0 1)", "1");
    expect_sat("peck count t div l + 1, lemma 16", &more);
}

/// Full pass k taken as last even with a remainder (the split forgotten): lemma 17 `sat`.
#[test]
fn negative_control_full_pass_last_with_remainder() {
    let wrong = edit("17_g162_full_pass", "(and (= m k) (= d 0))", "(= m k)");
    expect_sat("full pass k last whatever D, lemma 17", &wrong);
}
