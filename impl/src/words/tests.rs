use super::*;
use cycle_vocab::Increment;

fn num(negative: bool, mantissa: u64, decimals: u8, point: bool) -> Number {
    Number { negative, mantissa, decimals, point }
}

const AT: At = At { letter: b'X', line: 7 };

#[test]
fn lengths() {
    let g = Grid::METRIC_ISB;
    assert_eq!(length(num(false, 587, 1, true), g, false, AT), Ok(58_700));
    assert_eq!(
        length(num(false, 587_001, 4, true), g, false, AT),
        Err(Alarm::new(AlarmCode::Precision, Some(b'X'), Rule::ComUnits, 7))
    );
    assert_eq!(length(num(false, 2400, 0, false), g, true, AT), Ok(2400));
    assert_eq!(length(num(false, 24, 1, true), g, true, AT), Ok(2400));
    assert_eq!(signed_length(num(true, 999_999_999, 3, true), g, AT), Ok(-999_999_999));
    assert_eq!(signed_length(num(false, 1_000_000, 0, false), g, AT), Err(AT.out_of_range()));
    let isc = Grid { units: Units::Metric, increment: Increment::Isc };
    assert_eq!(length(num(false, 587_001, 4, true), isc, false, AT), Ok(587_001));
}

#[test]
fn leads() {
    let g = Grid::METRIC_ISB;
    assert_eq!(lead_f(num(false, 3, 0, false), g, AT), Ok(30_000));
    assert_eq!(lead_f(num(false, 0, 0, false), g, AT), Err(AT.out_of_range()));
    assert_eq!(lead_f(num(false, 9999, 0, false), g, AT), Ok(99_990_000));
    assert_eq!(lead_f(num(false, 99_991, 1, true), g, AT), Err(AT.out_of_range()));
    // 16 TPI metric: 25.4/16 = 1.5875 mm.
    assert_eq!(lead_i(num(false, 16, 0, false), g, AT), Ok(15_875));
    // 20 TPI inch: 0.05 in = 5000 counts of 0.00001 in.
    let inch = Grid { units: Units::Inch, increment: Increment::Isb };
    assert_eq!(lead_i(num(false, 20, 0, false), inch, AT), Ok(5_000));
    // 7 TPI inch: 0.142857… in → 14286.
    assert_eq!(lead_i(num(false, 7, 0, false), inch, AT), Ok(14_286));
    assert_eq!(lead_i(num(false, 101, 0, false), inch, AT), Err(AT.out_of_range()));
    assert_eq!(lead_i(num(false, 254, 0, false), g, AT), Ok(1_000));
    assert_eq!(
        lead_i(num(false, 100_001, 5, true), g, AT),
        Err(Alarm::new(AlarmCode::Precision, Some(b'X'), Rule::ComUnits, 7))
    );
}

#[test]
fn g162_words() {
    let g = Grid::METRIC_ISB;
    let at = At { letter: b'A', line: 2 };
    // G162.A: tenths of a degree, any tenth; a second decimal is PRECISION under G162.A.
    assert_eq!(infeed_angle(num(false, 275, 1, true), at), Ok(275));
    assert_eq!(infeed_angle(num(true, 30, 0, false), at), Ok(-300));
    assert_eq!(infeed_angle(num(false, 89, 0, false), at), Ok(890));
    assert_eq!(infeed_angle(num(false, 273, 1, true), at), Ok(273));
    assert_eq!(infeed_angle(num(true, 889, 1, true), at), Ok(-889));
    assert_eq!(infeed_angle(num(false, 891, 1, true), at), Err(Alarm::new(AlarmCode::OutOfRange, Some(b'A'), Rule::G162A, 2)));
    assert_eq!(infeed_angle(num(false, 2735, 2, true), at), Err(Alarm::new(AlarmCode::Precision, Some(b'A'), Rule::G162A, 2)));
    assert_eq!(signed_lead(num(true, 5, 1, true), g, 99_990_000, Rule::G162I, at), Ok(-5_000));
    assert_eq!(
        signed_lead(num(false, 10_000, 0, false), g, 99_990_000, Rule::G162I, at),
        Err(Alarm::new(AlarmCode::OutOfRange, Some(b'A'), Rule::G162I, 2))
    );
    assert_eq!(scaled_in(num(false, 360, 0, false), 3, 0, 360_000, Rule::G162B, at), Ok(360_000));
    assert_eq!(
        scaled_in(num(false, 360_001, 3, true), 3, 0, 360_000, Rule::G162B, at),
        Err(Alarm::new(AlarmCode::OutOfRange, Some(b'A'), Rule::G162B, 2))
    );
}

#[test]
fn integers() {
    assert_eq!(integer_in(num(false, 20545, 0, false), 0, 999_999, Rule::ComRanges, AT), Ok(20545));
    assert_eq!(
        integer_in(num(false, 2, 0, true), 0, 9, Rule::ComRanges, AT),
        Err(Alarm::new(AlarmCode::NotInteger, Some(b'X'), Rule::ComRanges, 7))
    );
    assert_eq!(
        integer_in(num(true, 2, 0, false), 0, 9, Rule::G76Mode, AT),
        Err(Alarm::new(AlarmCode::OutOfRange, Some(b'X'), Rule::G76Mode, 7))
    );
}
