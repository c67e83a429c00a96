use super::*;

#[test]
fn actions_read_and_print_back() {
    let cases = [
        ("hold:12@1/2", Action::Hold(Along { event: 12, num: 1, den: 2 })),
        ("hold:3@0.5", Action::Hold(Along { event: 3, num: 5, den: 10 })),
        ("hold:3@1", Action::Hold(Along { event: 3, num: 1, den: 1 })),
        ("hold:3@0", Action::Hold(Along { event: 3, num: 0, den: 1 })),
        ("reset:7@.125", Action::Reset(Along { event: 7, num: 125, den: 1000 })),
        ("start", Action::Start),
        ("single:on@0", Action::SingleBlock { on: true, before: 0 }),
        ("single:off@9", Action::SingleBlock { on: false, before: 9 }),
    ];
    for (text, action) in cases {
        assert_eq!(parse_action(text), Ok(action), "{text}");
        assert_eq!(parse_action(&action_text(&action)), Ok(action), "{text}");
    }
}

#[test]
fn bad_actions_say_why() {
    for bad in ["hold:3", "hold:x@1/2", "hold:3@3/2", "hold:3@1/0", "hold:3@1.5", "hold:3@0.1234567", "pause:1@1", "single:maybe@1", "single:on", "hold:3@-1/2", "hold:3@1/1000001"] {
        assert!(parse_action(bad).is_err(), "{bad}");
    }
    let seventeen = vec!["start"; 17];
    assert!(parse_script(&seventeen).unwrap_err().contains("at most 16"));
    assert_eq!(parse_script(&["hold:1@1/2", "start"]).unwrap().actions().len(), 2);
}
