use super::*;

#[test]
fn sides_change_only_through_g40() {
    assert_eq!(switch(&[41], Side::Off, 1), Ok(Side::Left));
    assert_eq!(switch(&[41], Side::Left, 1), Ok(Side::Left));
    assert_eq!(switch(&[40, 42], Side::Left, 1), Ok(Side::Right));
    assert_eq!(switch(&[42, 40], Side::Left, 1), Err(alarm(AlarmCode::WordNotAllowed, b'G', Rule::TnrcSwitch, 1)));
    assert_eq!(switch(&[41, 42], Side::Off, 1), Err(alarm(AlarmCode::WordNotAllowed, b'G', Rule::TnrcSwitch, 1)));
    assert_eq!(switch(&[], Side::Right, 1), Ok(Side::Right));
}
