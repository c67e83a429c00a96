use super::{relief_direction, stops, Axes};
use cycle_vocab::readings::G75Relief;

/// G75.RELIEF: −Z under the letter whatever the step; against the step under
/// `against-step`; G74 against the step under either reading.
#[test]
fn relief_directions() {
    for sigma in [-1, 1] {
        assert_eq!(relief_direction(Axes::G75, sigma, G75Relief::MinusZ), -1);
        assert_eq!(relief_direction(Axes::G75, sigma, G75Relief::AgainstStep), -sigma);
        for reading in [G75Relief::MinusZ, G75Relief::AgainstStep] {
            assert_eq!(relief_direction(Axes::G74, sigma, reading), -sigma);
        }
    }
    assert_eq!(G75Relief::default(), G75Relief::MinusZ);
}

#[test]
fn stops_end_exactly_at_the_end() {
    assert_eq!(stops(2_000, -12_000, 5_000).collect::<Vec<_>>(), vec![-3_000, -8_000, -12_000]);
    assert_eq!(stops(0, 10, 5).collect::<Vec<_>>(), vec![5, 10]);
    assert_eq!(stops(0, 3, 10).collect::<Vec<_>>(), vec![3]);
    assert_eq!(stops(7, 7, 1).count(), 0);
}
