use super::*;

#[test]
fn pins_name_what_is_wrong() {
    let p = Pins::parse(&["g94.k=start-minus-end", " g96.rapid = allow "]).unwrap();
    assert_eq!(p.0, vec![("g94.k", "start-minus-end"), ("g96.rapid", "allow")]);
    let r = p.apply(Readings::default());
    assert_eq!((r.get("g94.k"), r.get("g96.rapid"), r.get("g73.c")), (Some("start-minus-end"), Some("allow"), Some("visit")));
    let e = Pins::parse(&["g95.k=x"]).unwrap_err();
    assert!(e.contains("g95.k") && e.contains("g94.k, g73.c, g75.relief, g162.lead, thread.zref, g96.rapid"), "{e}");
    let e = Pins::parse(&["g73.c=maybe"]).unwrap_err();
    assert!(e.contains("maybe") && e.contains("visit (the letter), skip"), "{e}");
    assert!(Pins::parse(&["g73.c"]).unwrap_err().contains("NAME=VALUE"));
    assert!(Pins::parse(&["g73.c=skip", "g73.c=visit"]).unwrap_err().contains("twice"));
}

#[test]
fn bits_choose_values_and_read_back() {
    assert_eq!(LETTER, Readings::default());
    assert!(from_bits(0).is_letter());
    for b in 0..64u8 {
        assert_eq!(bits(&from_bits(b)), b);
    }
    assert_eq!(from_bits(1).get("g94.k"), Some("start-minus-end"));
    assert_eq!(from_bits(0b10_0000).get("g96.rapid"), Some("allow"));
    assert_eq!(line(&from_bits(1)), "g94.k=start-minus-end, others the letter");
    assert_eq!(line(&Readings::default()), "the letter throughout");
}

#[test]
fn flags_merge_with_the_declaration_unless_they_contradict_it() {
    let d = Declared::parse(Some(&serde_json::json!({"g94.k": "start-minus-end"}))).unwrap();
    assert_eq!(d.pairs(), vec![("g94.k", "start-minus-end")]);
    let merged = settle(&d, &Pins::parse(&["g73.c=skip", "g94.k=start-minus-end"]).unwrap()).unwrap();
    assert_eq!(line(&merged), "g94.k=start-minus-end, g73.c=skip, others the letter");
    let e = settle(&d, &Pins::parse(&["g94.k=end-minus-start"]).unwrap()).unwrap_err();
    assert!(e.contains("contradicts") && e.contains("g94.k=start-minus-end"), "{e}");
    assert_eq!(Declared::parse(None).unwrap(), Declared::default());
    for bad in [serde_json::json!(["g94.k"]), serde_json::json!({"g95.k": "x"}), serde_json::json!({"g94.k": 1}), serde_json::json!({"g94.k": "up"})] {
        assert!(Declared::parse(Some(&bad)).is_err(), "{bad}");
    }
}

#[test]
fn counts_add_and_merge() {
    let mut c = Counts::default();
    c.add(&Readings::default());
    c.add(&from_bits(1));
    assert_eq!((c.get("g94.k", "end-minus-start"), c.get("g94.k", "start-minus-end"), c.get("g73.c", "visit")), (1, 1, 2));
    let mut m = Counts::default();
    m.add_json(&c.json());
    m.add_json(&c.json());
    assert_eq!(m.get("g73.c", "visit"), 4);
    assert_eq!(c.lines()[0], "g94.k: end-minus-start 1, start-minus-end 1");
}
