use super::*;

#[test]
fn names_parse_back_and_order_weakest_first() {
    for l in Level::ALL {
        assert_eq!(Level::parse(l.name()), Ok(l));
    }
    assert!(Level::parse("moves").unwrap_err().contains("motion-alarm-presence"));
    assert!(Level::MotionAlarmPresence < Level::Motion && Level::Motion < Level::Full);
    assert_eq!(Level::default(), Level::Full);
}
