use cycle_vocab::Rule;

/// The generators mostly build legal cycles and reach every single-cycle alarm.
#[test]
fn single_cuts_reach_the_rules() {
    super::super::tests::assert_reaches(
        super::g90,
        &[Rule::G90Taper, Rule::G90Format, Rule::ComLead, Rule::PrjWord, Rule::ComRanges],
    );
    super::super::tests::assert_reaches(
        super::g94,
        &[Rule::G94Taper, Rule::G94Format, Rule::ComLead, Rule::PrjWord, Rule::PrjDialect],
    );
}
