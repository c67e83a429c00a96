use super::*;

fn hint_for(program: &str, config: &Config) -> Option<String> {
    let t = cycle_spec::expand(program.as_bytes(), config);
    let alarm = t.alarm.expect("an alarm");
    hint(config, &alarm, &crate::registry::sight(program.as_bytes(), config, Some(&alarm)))
}

#[test]
fn units_and_dialects_are_hinted() {
    let metric = Config::default();
    assert_eq!(hint_for("G20\nG0 X1\n", &metric).unwrap(), "hint: G20 selects inch and a trace's units are fixed by the configuration: run with --units inch");
    let inch = Config { grid: cycle_vocab::Grid { units: Units::Inch, ..metric.grid }, ..metric };
    assert!(hint_for("G0 X1\nG21\n", &inch).unwrap().ends_with("run with --units metric"));
    assert_eq!(hint_for("G0 X1\nG162 X1\n", &metric).unwrap(), "hint: G162 is a code of the nc201 dialect: run with --dialect nc201");
    assert!(hint_for("G91 G0 X1\n", &metric).unwrap().ends_with("run with --dialect nc201"));
    // An alarm of the program itself gets none.
    assert_eq!(hint_for("G0 X65 Z5\nG92 X58.7 Z-28\n", &metric), None);
}
