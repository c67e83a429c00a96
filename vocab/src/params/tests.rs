use super::*;

#[test]
fn set_names_the_parameter_and_keeps_the_value() {
    let mut p = Params::default();
    assert_eq!(p.set("5140", 50), Ok(()));
    assert_eq!(p.p5140_min_cut, Some(50));
    assert_eq!(p.get("5140"), Some(50));
    // Any value is kept: its range is the engines' to check.
    assert_eq!(p.set("5144", 5), Ok(()));
    assert_eq!(p.set("9999", 1), Err(UnknownParam));
    assert_eq!(p.get("5130"), None);
    for name in Params::NAMES {
        let mut q = Params::default();
        q.set(name, 7).unwrap();
        assert_eq!(q.get(name), Some(7), "{name}");
    }
}
