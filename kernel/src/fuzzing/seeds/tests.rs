use super::*;
use crate::fuzzing::replay::replay;
use cycle_vocab::Config;

#[test]
fn seeds_pass_encode_to_themselves_and_reach_every_family() {
    // The parse_blocks and diff_spec_impl seeds compare the two lexers, the two engines.
    let differential = crate::spec_alone::skip("the replay of the parse_blocks and diff_spec_impl seeds");
    for t in [Target::ParseBlocks, Target::DiffSpecImpl, Target::GcodeRoundtrip] {
        if differential && t != Target::GcodeRoundtrip {
            continue;
        }
        let seeds = seeds(t);
        assert!(seeds.len() >= 20, "{}: {} seeds", t.name(), seeds.len());
        for (name, program, case) in &seeds {
            replay(t, program, case).unwrap_or_else(|e| panic!("{} seed {name}: {e}", t.name()));
            let bytes = encode(t, program, case).unwrap_or_else(|e| panic!("{} seed {name}: {e}", t.name()));
            if t != Target::ParseBlocks {
                let c = CycleInput::from_bytes(&bytes).case();
                assert_eq!((&c.program, Some(c.config)), (program, case.config), "{name}");
                // Family seeds keep their structure: mutating a knob changes one decision.
                assert_eq!(case.built.is_some(), matches!(CycleInput::from_bytes(&bytes), CycleInput::Built { .. }), "{name}");
            }
        }
    }
    let families: std::collections::BTreeSet<_> = seeds(Target::DiffSpecImpl)
        .iter()
        .map(|(_, p, c)| if c.built.is_some() { CycleInput::from_bytes(&encode(Target::DiffSpecImpl, p, c).unwrap()).case().family } else { "literal" })
        .collect();
    // Every registered family, the corpus's literal programs, the garbage generator's kinds.
    let mut expected: std::collections::BTreeSet<&str> = crate::registry::FAMILIES.iter().map(|f| f.name).collect();
    expected.extend(["literal", "mutant", "operator", "soup"]);
    assert_eq!(families, expected);
}

#[test]
fn a_configuration_no_input_carries_is_refused() {
    let mut config = Config::default();
    config.params.max_passes = Some(3);
    let (_, _, mut case) = seeds(Target::DiffSpecImpl).remove(0);
    case.config = Some(config);
    case.built = None;
    assert!(encode(Target::DiffSpecImpl, b"G0 X1\n", &case).unwrap_err().contains("\"max_passes\":3"));
}
