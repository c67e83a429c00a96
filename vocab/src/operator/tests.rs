use super::*;

#[test]
fn push_keeps_order_and_refuses_the_seventeenth() {
    let mut s = Script::EMPTY;
    assert!(s.is_empty());
    let hold = Action::Hold(Along { event: 3, num: 1, den: 2 });
    s.push(hold).unwrap();
    s.push(Action::Start).unwrap();
    assert_eq!(s.actions(), &[hold, Action::Start]);
    for _ in 2..SCRIPT_MAX {
        s.push(Action::Start).unwrap();
    }
    assert_eq!(s.push(Action::Start), Err(ScriptFull));
    assert_eq!(s.actions().len(), SCRIPT_MAX);
}

#[test]
fn along_legality() {
    assert!(Along { event: 0, num: 0, den: 1 }.is_legal());
    assert!(Along { event: 0, num: 7, den: 7 }.is_legal());
    assert!(!Along { event: 0, num: 8, den: 7 }.is_legal());
    assert!(!Along { event: 0, num: 0, den: 0 }.is_legal());
    assert!(!Along { event: 0, num: 1, den: ALONG_DEN_MAX + 1 }.is_legal());
}

#[cfg(feature = "std")]
#[test]
fn json_is_a_list_and_an_empty_script_is_the_default() {
    let s = Script::of(&[
        Action::Hold(Along { event: 4, num: 1, den: 2 }),
        Action::Start,
        Action::SingleBlock { on: true, before: 0 },
    ])
    .unwrap();
    let text = serde_json::to_string(&s).unwrap();
    assert_eq!(text, r#"[{"hold":{"event":4,"num":1,"den":2}},"start",{"single_block":{"on":true,"before":0}}]"#);
    assert_eq!(serde_json::from_str::<Script>(&text).unwrap(), s);
    let too_long = format!("[{}]", vec!["\"start\""; SCRIPT_MAX + 1].join(","));
    assert!(serde_json::from_str::<Script>(&too_long).is_err());
}
