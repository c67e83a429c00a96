use super::*;

#[test]
fn every_reading_sets_and_reads_back_every_value() {
    for name in Readings::NAMES {
        let values = Readings::values(name).unwrap();
        assert!(values.len() >= 2, "{name}");
        for v in values {
            let mut r = Readings::default();
            r.set(name, v).unwrap();
            assert_eq!(r.get(name), Some(*v));
            assert_eq!(r.is_letter(), v == &values[0], "{name}={v}");
        }
        assert_eq!(Readings::default().set(name, "nonsense"), Err(BadReading::Value));
    }
    assert_eq!(Readings::default().set("g95.k", "x"), Err(BadReading::Name));
    assert_eq!(Readings::default().pairs().len(), Readings::NAMES.len());
}
