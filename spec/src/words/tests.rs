use super::*;

fn num(s: &str) -> Number {
    Number::parse(s).unwrap_or_else(|| panic!("bad test number {s}"))
}

#[test]
fn lengths_and_leads() {
    let g = Grid::METRIC_ISB;
    assert_eq!(length(&num("58.7"), b'X', g, -N, N, 1), Ok(58_700));
    assert_eq!(length(&num("60"), b'X', g, -N, N, 1), Ok(60_000));
    assert_eq!(length(&num("58.7000"), b'X', g, -N, N, 1), Ok(58_700));
    assert_eq!(length(&num("-0.000000000000000000"), b'X', g, -N, N, 1), Ok(0));
    assert_eq!(
        length(&num("58.7001"), b'X', g, -N, N, 1),
        Err(alarm(AlarmCode::Precision, b'X', Rule::ComUnits, 1))
    );
    assert_eq!(
        length(&num("1000000"), b'X', g, -N, N, 1),
        Err(alarm(AlarmCode::OutOfRange, b'X', Rule::ComRanges, 1))
    );
    assert_eq!(lead_from_f(&num("3"), g, 1), Ok(30_000));
    assert_eq!(lead_from_i(&num("24"), g, 1), Ok(10_583)); // 25.4/24 = 1.05833
    assert_eq!(lead_from_i(&num("254"), g, 1), Ok(1_000));
    let fanuc = Config { dialect: Dialect::Fanuc, ..Config::default() };
    assert_eq!(micron_length(&num("2400"), b'P', &fanuc, 1, N, 1), Ok(2_400));
    assert_eq!(micron_length(&num("2.4"), b'P', &fanuc, 1, N, 1), Ok(2_400));
    assert_eq!(micron_length(&num("2400"), b'P', &Config::default(), 1, N, 1), Ok(2_400_000));
}

/// "Values (check step 3)": precision first, then the range under the word's own rule,
/// however large the value (18 digits, beyond any machine word once scaled).
#[test]
fn huge_values_are_out_of_range_under_their_rule() {
    let g = Grid::METRIC_ISB;
    let big = "999999999999999999";
    let out = |w: u8, r: Rule| Err(alarm(AlarmCode::OutOfRange, w, r, 1));
    assert_eq!(length(&num(big), b'X', g, -N, N, 1), out(b'X', Rule::ComRanges));
    assert_eq!(length(&num(&format!("-{big}")), b'X', g, -N, N, 1), out(b'X', Rule::ComRanges));
    assert_eq!(feed(&num(big), b'H', g, N, Rule::G162H, 1), out(b'H', Rule::G162H));
    assert_eq!(signed_lead(&num(big), b'I', g, lead_max(g), Rule::G162I, 1), out(b'I', Rule::G162I));
    assert_eq!(millidegrees(&num(big), b'J', 1, N, Rule::G162J, 1), out(b'J', Rule::G162J));
    assert_eq!(tenths_of_degree(&num("99999999999999999.5"), b'A', 1), out(b'A', Rule::G162A));
    assert_eq!(integer(&num(big), b'D', 0, 2, Rule::G76Mode, 1), out(b'D', Rule::G76Mode));
    assert_eq!(lead_from_i(&num(big), g, 1), out(b'I', Rule::ComRanges));
    // Precision is decided before the range.
    assert_eq!(
        feed(&num("9999999999999.99999"), b'H', g, N, Rule::G162H, 1),
        Err(alarm(AlarmCode::Precision, b'H', Rule::ComUnits, 1))
    );
    assert_eq!(
        integer(&num("999999999999999999."), b'L', 1, 99, Rule::ComRanges, 1),
        Err(alarm(AlarmCode::NotInteger, b'L', Rule::ComRanges, 1))
    );
}

#[test]
fn g162_angles_feeds_and_signed_leads() {
    let g = Grid::METRIC_ISB;
    assert_eq!(tenths_of_degree(&num("27.5"), b'A', 1), Ok(275));
    assert_eq!(tenths_of_degree(&num("-30"), b'A', 1), Ok(-300));
    assert_eq!(tenths_of_degree(&num("30.00"), b'A', 1), Ok(300));
    // Any tenth is legal (G162.A, "A27.3 included").
    assert_eq!(tenths_of_degree(&num("27.3"), b'A', 1), Ok(273));
    assert_eq!(tenths_of_degree(&num("-89"), b'A', 1), Ok(-890));
    assert_eq!(tenths_of_degree(&num("27.35"), b'A', 1), Err(alarm(AlarmCode::Precision, b'A', Rule::G162A, 1)));
    assert_eq!(tenths_of_degree(&num("27.25"), b'A', 1), Err(alarm(AlarmCode::Precision, b'A', Rule::G162A, 1)));
    assert_eq!(tenths_of_degree(&num("89.1"), b'A', 1), Err(alarm(AlarmCode::OutOfRange, b'A', Rule::G162A, 1)));
    assert_eq!(tenths_of_degree(&num("89.5"), b'A', 1), Err(alarm(AlarmCode::OutOfRange, b'A', Rule::G162A, 1)));
    assert_eq!(millidegrees(&num("90.5"), b'B', 0, 360_000, Rule::G162B, 1), Ok(90_500));
    assert_eq!(
        millidegrees(&num("360.001"), b'B', 0, 360_000, Rule::G162B, 1),
        Err(alarm(AlarmCode::OutOfRange, b'B', Rule::G162B, 1))
    );
    assert_eq!(signed_lead(&num("-0.5"), b'I', g, lead_max(g), Rule::G162I, 1), Ok(-5_000));
    assert_eq!(
        signed_lead(&num("10000"), b'K', g, lead_max(g), Rule::G34, 1),
        Err(alarm(AlarmCode::OutOfRange, b'K', Rule::G34, 1))
    );
    assert_eq!(feed(&num("500"), b'H', g, N, Rule::G162H, 1), Ok(5_000_000));
    assert_eq!(feed(&num("0"), b'H', g, N, Rule::G162H, 1), Err(alarm(AlarmCode::OutOfRange, b'H', Rule::G162H, 1)));
}
