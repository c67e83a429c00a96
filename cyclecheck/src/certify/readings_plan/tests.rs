use super::*;

#[test]
fn plans_apply_name_and_read_back() {
    let pins = Pins::parse(&["g73.c=skip"]).unwrap();
    let drawn = Plan::drawn(pins.clone());
    let mut c = Config { readings: readings::from_bits(1), ..Config::default() };
    drawn.apply(&mut c);
    assert_eq!(readings::line(&c.readings), "g94.k=start-minus-end, g73.c=skip, others the letter");
    assert_eq!(drawn.line(), "readings: drawn per case, but g73.c=skip (--reading)");
    let d = Declared::parse(Some(&json!({"g94.k": "start-minus-end"}))).unwrap();
    let declared = Plan::declared(Some(d), pins).unwrap();
    let mut c = Config { readings: readings::from_bits(0b11_1111), ..Config::default() };
    declared.apply(&mut c);
    assert_eq!(declared.line(), "readings: g94.k=start-minus-end, g73.c=skip, others the letter");
    assert_eq!(declared.line(), format!("readings: {}", readings::line(&c.readings)));
    for p in [drawn, declared, Plan::drawn(Pins::default())] {
        assert_eq!(Plan::from_json(&p.json()), Ok(p.clone()));
    }
    assert!(Plan::declared(Some(d), Pins::parse(&["g94.k=end-minus-start"]).unwrap()).unwrap_err().contains("contradicts"));
    assert_eq!(Plan::from_json(&Value::Null), Ok(Plan::drawn(Pins::default())));
}
