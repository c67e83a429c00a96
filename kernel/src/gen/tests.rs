//! The generators' tests, and their statistics (ignored: run by hand to tune the weights).

use super::*;
use crate::engine::{Engine, SpecEngine};
use proptest::strategy::ValueTree;
use proptest::test_runner::{Config as PtConfig, RngAlgorithm, TestRng, TestRunner};

/// `KNOBS` knobs from a xorshift state.
pub(super) fn random_knobs(s: &mut u64) -> Vec<u32> {
    (0..KNOBS)
        .map(|_| {
            *s ^= *s << 13;
            *s ^= *s >> 7;
            *s ^= *s << 17;
            *s as u32
        })
        .collect()
}

/// Over 3 000 cases of `builder`, more than half end without an alarm and every rule of
/// `rules` ends one.
pub(super) fn assert_reaches(builder: Builder, rules: &[cycle_vocab::Rule]) {
    let mut seen = std::collections::BTreeMap::new();
    let mut s = 0x2545_f491_4f6c_dd1du64;
    for _ in 0..3_000 {
        let case = build(builder, &random_knobs(&mut s));
        let t = SpecEngine.expand(&case.program, &case.config);
        let key = t.alarm.map_or("ok".to_string(), |a| a.rule.id().to_string());
        *seen.entry(key).or_insert(0) += 1;
    }
    assert!(seen.get("ok").is_some_and(|&n| n > 1_500), "{seen:?}");
    for rule in rules {
        assert!(seen.contains_key(rule.id()), "never reaches {rule}: {seen:?}");
    }
}

pub(super) fn sample(strategy: impl Strategy<Value = Case>, n: usize) -> Vec<Case> {
    let rng = TestRng::from_seed(RngAlgorithm::ChaCha, &[7; 32]);
    let mut runner = TestRunner::new_with_rng(PtConfig::default(), rng);
    (0..n).map(|_| strategy.new_tree(&mut runner).unwrap().current()).collect()
}

/// The plain program (every knob 0) of each family expands without an alarm and runs its
/// cycle (a pass header) or its thread moves.
#[test]
fn zero_knobs_give_plain_valid_programs() {
    let zero = vec![0u32; KNOBS];
    for family in FAMILIES {
        let case = build(family.build, &zero);
        let t = SpecEngine.expand(&case.program, &case.config);
        assert_eq!(t.alarm, None, "{case:?}");
        let pass = t.events.iter().any(|e| matches!(e, cycle_vocab::Event::Pass(_)));
        assert!(pass || t.moves().any(|m| m.kind == cycle_vocab::MoveKind::Thread), "{case:?}");
    }
}

/// The structured families mostly reach the cycles (not just alarms): at least 40 % of the
/// cases end without an alarm, and together they reach many different alarms.
#[test]
fn structured_families_reach_the_cycles_and_many_alarms() {
    for family in FAMILIES {
        let cases = sample(family.strategy(), 400);
        let mut clean = 0;
        let mut alarms = std::collections::BTreeSet::new();
        for c in &cases {
            let t = SpecEngine.expand(&c.program, &c.config);
            match t.alarm {
                None => clean += 1,
                Some(a) => {
                    alarms.insert((a.code.number(), a.rule));
                }
            }
        }
        assert!(clean * 5 >= cases.len() * 2, "{}: only {clean} of {} clean", family.name, cases.len());
        assert!(alarms.len() >= 10, "{}: only these alarms: {alarms:?}", family.name);
    }
}

/// Every mode, both sides, inch and ISC, fanuc and G78 occur.
#[test]
fn multipass_covers_the_input_space() {
    let cases = sample(strategy(multipass::any), 600);
    let fam: std::collections::BTreeSet<_> = cases.iter().map(|c| c.family).collect();
    assert_eq!(fam.into_iter().collect::<Vec<_>>(), vec!["f76", "g76", "g78"]);
    assert!(cases.iter().any(|c| c.config.grid.units == Units::Inch));
    assert!(cases.iter().any(|c| c.config.grid.increment == Increment::Isc));
    let text: String = cases.iter().map(Case::text).collect::<String>().to_ascii_uppercase();
    for needle in [" D0", " D1", " D2", " E", " J", " K", " L", "I"] {
        assert!(text.contains(needle), "no {needle:?}");
    }
}

/// Pass counts stay moderate: the reference trace of a generated case is short.
#[test]
fn cases_are_small() {
    let mut longest = 0;
    for c in sample(any_case(), 600) {
        let t = SpecEngine.expand(&c.program, &c.config);
        longest = longest.max(t.events.len());
    }
    assert!(longest < 20_000, "a case with {longest} events");
}

/// No builder draws the spelling knobs (nor the structure knobs after them): a case's
/// decisions, its spelling and its structure stay apart.
#[test]
fn builders_leave_the_spelling_knobs_alone() {
    let mut s = 0x9e37_79b9_7f4a_7c15u64;
    for family in FAMILIES {
        for _ in 0..300 {
            let knobs = random_knobs(&mut s);
            let mut d = Dice::new(&knobs);
            (family.build)(&mut d);
            assert!(d.at <= SPELLING_AT, "{} draws knob {}", family.name, d.at);
        }
    }
}

#[test]
fn garbage_never_panics_the_spec() {
    for c in sample(garbage::strategy(), 500) {
        let _ = SpecEngine.expand(&c.program, &c.config);
    }
}

#[test]
fn dice_zero_is_ordinary() {
    let zero = [0u32; 4];
    let mut d = Dice::new(&zero);
    assert!(!d.chance(99));
    assert_eq!(d.weighted(&[5, 5]), 0);
    assert_eq!(d.range(3, 9), 3);
}

/// Generator statistics, for tuning the weights: `cargo test -p cycle-kernel --lib
/// family_statistics -- --ignored --nocapture` prints, per generator, the time per case, the
/// event counts and how the reference trace ends; `SHOW=G92.TAPER` also prints three cases of
/// each ending that contains the text; `FAMILY=g71` runs only that generator.
mod stats {
    use super::*;

    #[test]
    #[ignore]
    fn family_statistics() {
        let show = std::env::var("SHOW").ok();
        let only = std::env::var("FAMILY").ok();
        let generators = FAMILIES.iter().map(|f| (f.name, f.strategy())).chain([("garbage", garbage::strategy())]);
        for (name, s) in generators.filter(|(name, _)| only.as_deref().is_none_or(|o| o == *name)) {
            let n = 2000;
            let t0 = std::time::Instant::now();
            let (mut events, mut longest) = (0, 0);
            let mut endings = std::collections::BTreeMap::new();
            for c in sample(s, n) {
                let t = SpecEngine.expand(&c.program, &c.config);
                events += t.events.len();
                longest = longest.max(t.events.len());
                let k = t.alarm.map_or_else(|| "clean".to_string(), |a| crate::conformance::alarm_short(&a));
                let seen = endings.entry(k.clone()).or_insert(0);
                if show.as_deref().is_some_and(|s| k.contains(s)) && *seen < 3 {
                    println!("{}\n{}", c.text(), t.to_gcode());
                }
                *seen += 1;
            }
            println!("{name}: {:?} per case, mean {} events, longest {longest}", t0.elapsed() / n as u32, events / n);
            for (k, v) in endings {
                println!("  {v:5} {k}");
            }
        }
    }
}

/// The fraction of each family's generated cases (its strategy, readings drawn) that end
/// without an alarm in the reference, printed (run by hand: `--ignored --nocapture`).
#[test]
#[ignore]
fn clean_fraction_per_family() {
    let generators = FAMILIES.iter().map(|f| (f.name, f.strategy())).chain([("garbage", garbage::strategy())]);
    for (name, strategy) in generators {
        let cases = sample(strategy, 2_000);
        let clean = cases.iter().filter(|c| SpecEngine.expand(&c.program, &c.config).alarm.is_none()).count();
        eprintln!("CLEAN {name} {clean}/{} = {:.1} %", cases.len(), 100.0 * clean as f64 / cases.len() as f64);
    }
}

/// The program-structure wrappers: how the wrapped cases of each kind end today, printed (run
/// by hand: `--ignored --nocapture`).
#[test]
#[ignore]
fn wrapped_cases_endings() {
    let mut seen: std::collections::BTreeMap<(&str, String), usize> = std::collections::BTreeMap::new();
    for c in sample(any_case(), 4_000) {
        let text = c.text();
        let kind = if text.contains("M98") { "subprogram" } else if text.contains("G50 S") || text.contains("G96") { "spindle" } else { continue };
        let t = SpecEngine.expand(&c.program, &c.config);
        *seen.entry((kind, t.alarm.map_or("clean".to_string(), |a| a.rule.id().to_string()))).or_default() += 1;
    }
    for ((kind, ending), n) in &seen {
        eprintln!("WRAPPED {kind} {ending} {n}");
    }
}

/// The program structure and the words the declared readings turn on are generated: subprograms
/// (repeated, nested five deep), the spindle modes (G50 S before G96, G97 S), G84 with an rpm
/// from G97 S under G98 and with none behind `G50 S`, G78 blocks that leave J/K to the block
/// before, FANUC G76 with a = 40, G94 K of both signs.
#[test]
fn structure_and_reading_points_are_generated() {
    let text = |family: &str, n: usize| -> Vec<String> {
        let strategy = crate::registry::find(family).map_or_else(|| any_case().boxed(), |f| f.strategy());
        sample(strategy, n).iter().map(|c| c.text().to_ascii_uppercase().replace("\r\n", "\n")).collect()
    };
    // The digits right after each `letter` of a line.
    let words = |line: &str, letter: char| -> Vec<String> {
        line.match_indices(letter).map(|(i, _)| line[i + 1..].chars().take_while(|c| c.is_ascii_digit() || *c == '-').collect()).collect()
    };
    let any = text("any", 4_000);
    let has = |needle: &str| any.iter().any(|t| t.contains(needle));
    for needle in ["M98 P", "\nM99", "\nO", "G50 S", "G96 S", "G97 S"] {
        assert!(has(needle), "no case writes {needle:?}");
    }
    assert!(any.iter().any(|t| t.matches("\nO").count() >= 5), "no subprogram nested five deep");
    assert!(any.iter().any(|t| t.lines().any(|l| l.contains("M98 P2") && words(l, 'P')[0].len() >= 5)), "no repeated call");
    let g84 = text("g84", 1_500);
    assert!(g84.iter().any(|t| t.contains("G98") && t.contains("G97")), "no G84 under G98 with G97 S");
    let no_rpm = |t: &String| t.contains("G50") && t.lines().filter(|l| l.contains('S')).all(|l| l.contains("G50") || l.contains("G96"));
    assert!(g84.iter().any(no_rpm), "no G84 with only G50 S or G96 S before it");
    let g78 = text("g78", 1_500);
    let omits_jk = |t: &String| {
        let blocks: Vec<&str> = t.lines().filter(|l| l.contains("G78") && (l.contains('X') || l.contains('U'))).collect();
        blocks.len() >= 2 && (blocks[0].contains('J') || blocks[0].contains('K')) && !blocks[1].contains('J') && !blocks[1].contains('K')
    };
    assert!(g78.iter().any(omits_jk), "no G78 block leaving J/K to the one before");
    let a40 = |l: &str| l.contains("G76") && !l.contains('X') && !l.contains('U') && words(l, 'P').iter().any(|p| p.len() >= 5 && p.ends_with("40"));
    assert!(text("f76", 1_500).iter().any(|t| t.lines().any(a40)), "no FANUC G76 with a = 40");
    let g94 = text("g94", 2_000);
    let k = |neg: bool| g94.iter().any(|t| t.lines().any(|l| words(l, 'K').iter().any(|w| !w.is_empty() && w.starts_with('-') == neg && w != "-")));
    assert!(k(true) && k(false), "G94 K of one sign only");
}
