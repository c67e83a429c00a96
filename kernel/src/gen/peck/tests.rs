use cycle_vocab::Rule;

/// The generators mostly build legal cycles and reach the peck cycles' alarms.
#[test]
fn peck_cycles_reach_the_rules() {
    super::super::tests::assert_reaches(super::g74, &[Rule::G74Format, Rule::G74Peck, Rule::G74Column, Rule::ComLead, Rule::PrjWord, Rule::PrjMaxPass]);
    super::super::tests::assert_reaches(super::g75, &[Rule::G75Format, Rule::G75Peck, Rule::G75Column, Rule::ComRanges, Rule::PrjDialect]);
}
