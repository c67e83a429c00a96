use super::*;

#[test]
fn angles() {
    assert_eq!(start_angle(0, 3), 0);
    assert_eq!(start_angle(1, 3), 120_000);
    assert_eq!(start_angle(1, 7), 51_429); // 51428.57
    assert_eq!(start_angle(1, 2), 180_000);
}

#[test]
fn noop_moves_are_dropped() {
    let mut events = Vec::new();
    let mut sink = |e| {
        events.push(e);
        ControlFlow::Continue(())
    };
    let mut o = Out::new(10, 20, &mut sink);
    o.rapid(10, 20, Rule::PrjModal, 1).unwrap();
    o.rapid(11, 20, Rule::PrjModal, 1).unwrap();
    assert_eq!(events.len(), 1);
}

#[test]
fn a_sink_that_breaks_gets_no_more_events_while_the_position_moves_on() {
    let mut seen = 0;
    let mut sink = |_| {
        seen += 1;
        ControlFlow::Break(())
    };
    let mut o = Out::new(0, 0, &mut sink);
    o.rapid(1, 0, Rule::PrjModal, 1).unwrap();
    o.rapid(2, 0, Rule::PrjModal, 1).unwrap();
    assert!(o.stopped());
    assert_eq!((o.x, o.z), (2, 0));
    assert_eq!(seen, 1);
}
