use super::*;
use crate::fuzzing::decoded::Origin;

fn origin(target: Target) -> Origin {
    Origin { target: target.name().to_string(), found_by: "a test".into(), date: None }
}

#[test]
fn a_case_replays_until_its_reference_ends_differently() {
    if crate::spec_alone::skip("a diff_spec_impl replay") {
        return;
    }
    let data = CycleInput::literal_bytes(b"G0 X65 Z5\nG92 X58.7 Z-28 F3\n", &Config::default());
    let (program, mut case) = regression(Target::DiffSpecImpl, &data, origin(Target::DiffSpecImpl)).unwrap();
    assert_eq!(case.expect, Expect { conform: Some(true), reference_ends: Some(Ending::Clean), ..Expect::default() });
    assert_eq!(replay(Target::DiffSpecImpl, &program, &case), Ok(()));
    let alarm = cycle_vocab::Alarm::new(cycle_vocab::AlarmCode::MissingWord, Some(b'P'), cycle_vocab::Rule::G76Required, 2);
    case.expect.reference_ends = Some(Ending::Alarm(alarm));
    let e = replay(Target::DiffSpecImpl, &program, &case).unwrap_err();
    assert!(e.starts_with("the reference now ends clean; the case expects it to end with ALARM 2001 line 2"), "{e}");
}

#[test]
fn lexer_outcomes_and_failed_checks_are_named() {
    if crate::spec_alone::skip("a parse_blocks replay (the two lexers side by side)") {
        return;
    }
    let (program, mut case) = regression(Target::ParseBlocks, b"G0 X1\nG92 X#\n", origin(Target::ParseBlocks)).unwrap();
    let lexed = case.expect.lexer.unwrap();
    assert!(lexed.blocks == 1 && matches!(lexed.ends, Ending::Alarm(a) if a.line == 2), "{lexed:?}");
    assert_eq!(replay(Target::ParseBlocks, &program, &case), Ok(()));
    case.expect.lexer = Some(Lexed { blocks: 2, ends: Ending::Clean });
    case.expect.passes = Some(false);
    let e = replay(Target::ParseBlocks, &program, &case).unwrap_err();
    assert!(e.contains("the lexer now yields 1 blocks, ending with ALARM") && e.contains("the checks pass; the case expects: the checks fail"), "{e}");
}

#[test]
fn knob_built_inputs_keep_their_generator() {
    let data = [7, 9, 0, 0, 0];
    let CycleInput::Built { generator, .. } = CycleInput::from_bytes(&data) else { panic!("a knob-built input") };
    let (_, case) = regression(Target::GcodeRoundtrip, &data, origin(Target::GcodeRoundtrip)).unwrap();
    assert_eq!(case.built, Some(built(generator, &[9, 0, 0])));
    assert_eq!(case.built.unwrap().knobs, vec![9]);
    assert_eq!(case.expect, Expect { round_trips: Some(true), ..Expect::default() });
    assert!(regression(Target::ImplInvariants, &[], origin(Target::ImplInvariants)).is_none());
}
