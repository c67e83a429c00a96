use super::*;

#[test]
fn manifests_are_checked() {
    let dir = std::env::temp_dir().join(format!("cyclecheck-manifest-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("candidate.toml");
    let good = "name = \"x\"\nexpander = \"x 1.0\"\ncommand = \"x --serve\"\nsetup = \"make\"\n[[campaign]]\ncycles = \"g92\"\ncases = 5\nseed = 1\ndialect = \"fanuc\"\nparams = { 5143 = 60 }\n[notes]\n\"G92.PULLOUT\" = \"n\"\n";
    std::fs::write(&path, good).unwrap();
    let m = Manifest::read(&path).unwrap();
    assert_eq!((m.name.as_str(), m.campaigns.len(), m.ci), ("x", 1, false));
    assert_eq!(m.campaigns[0].label(), "cycles g92; 5 cases per family; seed 1; dialect fanuc; params 5143 = 60");
    assert_eq!(m.campaigns[0].options("x").unwrap().params.p5143_tool_angle, Some(60));
    for (bad, says) in [
        (good.replace("cycles = \"g92\"", "cycles = \"g999\""), "campaign 1"),
        (good.replace("dialect = \"fanuc\"", "dialect = \"haas\""), "haas"),
        (good.replace("5143", "9999"), "9999"),
        (good.replace("\"G92.PULLOUT\"", "\"NO.RULE\""), "NO.RULE"),
        (good.replace("setup = \"make\"\n", ""), "setup"),
        (good.replace("[[campaign]]", "[[campain]]"), "campain"),
    ] {
        std::fs::write(&path, &bad).unwrap();
        let e = Manifest::read(&path).unwrap_err();
        assert!(e.contains(says), "{e}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}
