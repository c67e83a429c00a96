use super::*;

const GOOD: &str = "[[deviation]]\nrule = \"G92.PULLOUT\"\nfamily = \"g92\"\ndialect = \"fanuc\"\nfield = \"z\"\nreason = \"no pull-out\"\n\n[[deviation]]\nrule = \"G76.INFEED.Z\"\nreason = \"r\"\n";

#[test]
fn declarations_parse_with_their_lines() {
    let list = parse(GOOD, "d.toml").unwrap();
    assert_eq!(list.len(), 2);
    assert_eq!((list[0].rule, list[0].family, list[0].dialect, list[0].line), (Rule::G92Pullout, Some("g92"), Some(Dialect::Fanuc), 1));
    assert_eq!((list[1].field.as_deref(), list[1].line), (None, 8));
    assert_eq!(list[0].label(), "G92.PULLOUT (family g92, dialect fanuc, field z)");
    for d in &list {
        assert_eq!(&Deviation::from_json(&d.json()).unwrap(), d);
    }
    assert!(parse("", "e").unwrap().is_empty());
}

#[test]
fn bad_files_name_the_key_and_the_line() {
    let err = |text: &str| parse(text, "d.toml").unwrap_err();
    let e = err("[[deviation]]\nrule = \"G92.PULLOUT\"\n");
    assert!(e.contains("reason") && e.contains("line 1"), "{e}");
    let e = err("[[deviation]]\nreason = \"r\"\n");
    assert!(e.contains("rule") && e.contains("line 1"), "{e}");
    let e = err("\n[[deviation]]\nrule = \"NO.SUCH\"\nreason = \"r\"\n");
    assert!(e.contains("line 3: rule") && e.contains("NO.SUCH"), "{e}");
    let e = err("[[deviation]]\nrule = \"G92.PULLOUT\"\nreason = \"r\"\nfamily = \"g999\"\n");
    assert!(e.contains("line 4: family"), "{e}");
    let e = err("[[deviation]]\nrule = \"G92.PULLOUT\"\nreason = \"r\"\ncolour = 1\n");
    assert!(e.contains("colour") && e.contains("line 4"), "{e}");
    let e = err("[[deviation]\n");
    assert!(e.contains("line 1"), "{e}");
}
