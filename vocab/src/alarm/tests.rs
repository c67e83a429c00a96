use super::*;

#[test]
fn display_names_code_word_rule_and_line() {
    let a = Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3);
    assert_eq!(a.to_string(), "ALARM 2001 line 3: required address missing (P) [rule G76.REQUIRED]");
    let b = Alarm::new(AlarmCode::BadCharacter, Some(0xFF), Rule::PrjLex, 1);
    assert!(b.to_string().contains("(0xFF)"));
}

#[test]
fn json_round_trip() {
    for a in [
        Alarm::new(AlarmCode::MissingWord, Some(b'P'), Rule::G76Required, 3),
        Alarm::new(AlarmCode::BadCharacter, Some(0x80), Rule::PrjLex, 9),
        Alarm::new(AlarmCode::TooManyPasses, None, Rule::PrjMaxPass, 2),
    ] {
        let j = serde_json::to_string(&a).unwrap();
        assert_eq!(serde_json::from_str::<Alarm>(&j).unwrap(), a, "{j}");
    }
}
