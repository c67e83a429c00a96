use super::*;
use cycle_kernel::registry::CycleRun;

fn runs(program: &[u8], config: &Config) -> CycleRun {
    registry::cycle_run(program, config, Some(&cycle_spec::expand(program, config)))
}

fn drain(o: &Options) -> (Vec<Pending>, Vec<FamilyRun>) {
    let mut cases = Cases::new(o, &Plan::drawn(o.readings.clone()));
    let list: Vec<Pending> = cases.by_ref().collect();
    assert_eq!(cases.drawn, cases.total);
    (list, cases.runs)
}

#[test]
fn cases_are_seeded_and_filtered() {
    let o = Options { cycles: Options::parse_cycles("g92").unwrap(), cases: 20, ..Options::default() };
    let (a, fa) = drain(&o);
    let (b, _) = drain(&o);
    assert_eq!(a.iter().map(|p| &p.program).collect::<Vec<_>>(), b.iter().map(|p| &p.program).collect::<Vec<_>>());
    let g92 = CycleRun::Family(registry::find("g92").unwrap());
    assert!(a.iter().all(|p| runs(&p.program, &p.config) == g92));
    assert_eq!(a.iter().filter(|p| matches!(p.origin, Origin::Corpus { .. })).count(), 9); // g92_5131, g92_step3 (its alarm is G92's) and sub_call run G92 too
    // The family's generator, then the operator generator over the covered thread families.
    assert_eq!((fa.len(), fa[0].family, fa[0].drawn), (2, "g92", 20));
    assert_eq!((fa[1].family, fa[1].drawn), ("operator", 5));
    assert!(a.iter().any(|p| !p.config.operator.is_empty()), "scripted cases are drawn");
    assert!(fa[0].kept >= 15, "{fa:?}");
    let other = Options { seed: 1, ..o.clone() };
    let (c, _) = drain(&other);
    assert_ne!(a.last().unwrap().program, c.last().unwrap().program);
    // A family draws the same cases alone as with the others.
    let (all, _) = drain(&Options { cases: 20, ..Options::default() });
    let generated = |l: &[Pending]| -> Vec<Vec<u8>> {
        l.iter().filter(|p| p.name.starts_with("g92#")).map(|p| p.program.clone()).collect()
    };
    let with_all = generated(&all);
    assert!(generated(&a).iter().all(|p| with_all.contains(p)));
}

#[test]
fn shards_split_the_cases_of_the_whole_run() {
    let whole = Options { cycles: Options::parse_cycles("g92,g90").unwrap(), cases: 13, ..Options::default() };
    let (all, runs) = drain(&whole);
    let mut joined: Vec<(String, Vec<u8>)> = Vec::new();
    for k in 1..=3 {
        let shard = Some(Shard::parse(&format!("{k}/3")).unwrap());
        let (part, part_runs) = drain(&Options { shard, ..whole.clone() });
        assert!(!part.is_empty() && part.len() < all.len(), "shard {k}/3: {} of {}", part.len(), all.len());
        assert!(part_runs.iter().zip(&runs).all(|(p, r)| p.drawn == r.drawn && p.seed == r.seed));
        joined.extend(part.into_iter().map(|p| (p.name, p.program)));
    }
    let mut expected: Vec<(String, Vec<u8>)> = all.into_iter().map(|p| (p.name, p.program)).collect();
    expected.sort();
    joined.sort();
    assert_eq!(joined, expected, "the shards hold the whole run's cases, each once");
}

#[test]
fn every_family_and_garbage_generate_with_all_cycles() {
    let (_, runs) = drain(&Options { cases: 5, ..Options::default() });
    let names: Vec<&str> = runs.iter().map(|r| r.family).collect();
    let mut expected: Vec<&str> = FAMILIES.iter().map(|f| f.name).collect();
    expected.extend(["operator", "garbage"]);
    assert_eq!(names, expected);
    assert!(runs.iter().all(|r| r.kept == r.drawn), "{runs:?}");
}

/// In process, the generated cases draw every value of every reading (the corpus programs
/// run under the readings their headers declare, with the pins); a candidate run's cases all
/// carry its readings, those told ahead too.
#[test]
fn campaigns_draw_every_reading_and_candidate_runs_fix_theirs() {
    let o = Options { cases: 8, ..Options::default() };
    let mut counts = cycle_kernel::readings::Counts::default();
    let (cases, _) = drain(&o);
    for p in &cases {
        match p.origin {
            Origin::Corpus { path } => {
                let own = corpus::PROGRAMS.iter().find(|c| c.path == path).unwrap().config().readings;
                assert_eq!(p.config.readings, own, "{}", p.name);
            }
            Origin::Generated { .. } => counts.add(&p.config.readings),
        }
    }
    for name in cycle_vocab::Readings::NAMES {
        for value in cycle_vocab::Readings::values(name).unwrap() {
            assert!(counts.get(name, value) > 0, "no case with {name}={value}: {counts:?}");
        }
    }
    let pins = cycle_kernel::readings::Pins::parse(&["g75.relief=against-step"]).unwrap();
    let pinned = Options { readings: pins.clone(), cycles: Options::parse_cycles("g75").unwrap(), ..o.clone() };
    let mut cases = Cases::new(&pinned, &Plan::drawn(pins.clone()));
    assert!(cases.by_ref().all(|p| p.config.readings.get("g75.relief") == Some("against-step")));
    let declared = cycle_kernel::readings::Declared::parse(Some(&serde_json::json!({"g94.k": "start-minus-end"}))).unwrap();
    let plan = Plan::declared(Some(declared), pins).unwrap();
    let Plan::Declared { readings, .. } = plan else { panic!() };
    let seen = std::sync::Mutex::new(Vec::new());
    struct Told<'a>(&'a std::sync::Mutex<Vec<cycle_vocab::Readings>>);
    impl Engine for Told<'_> {
        fn name(&self) -> &str {
            "told"
        }
        fn expand(&self, program: &[u8], config: &Config) -> cycle_vocab::text::Trace {
            SpecEngine.expand(program, config)
        }
        fn prefetch(&self, _: &[u8], config: &Config) {
            self.0.lock().unwrap().push(config.readings);
        }
    }
    let told = Told(&seen);
    let handed: Vec<Pending> = Ahead::new(Cases::new(&o, &plan), &told, 4).collect();
    assert!(handed.len() > 100 && handed.iter().all(|p| p.config.readings == readings));
    let seen = seen.into_inner().unwrap();
    assert!(seen.len() == handed.len() && seen.iter().all(|r| *r == readings));
}
