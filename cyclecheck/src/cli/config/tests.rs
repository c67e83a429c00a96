use super::grid_value;

#[test]
fn start_values_on_the_grid() {
    assert_eq!(grid_value("65", 3), Ok(65_000));
    assert_eq!(grid_value("-28.5", 3), Ok(-28_500));
    assert_eq!(grid_value("+.5", 4), Ok(5_000));
    assert_eq!(grid_value("1.2500", 3), Ok(1_250));
    assert_eq!(grid_value("999999.999", 3), Ok(999_999_999));
    assert!(grid_value("1000000", 3).is_err());
    assert!(grid_value("1.0001", 3).is_err());
    for bad in ["", ".", "-", "1e3", "1.2.3", "x", "99999999999999999999999"] {
        assert!(grid_value(bad, 3).is_err(), "{bad:?}");
    }
}
