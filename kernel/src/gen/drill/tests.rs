use cycle_vocab::Rule;

/// The generators mostly build legal cycles and reach the drilling cycles' alarms.
#[test]
fn drilling_cycles_reach_the_rules() {
    super::super::tests::assert_reaches(super::g83, &[Rule::G83Format, Rule::ComRanges, Rule::PrjWord, Rule::PrjMaxPass]);
    super::super::tests::assert_reaches(super::g84, &[Rule::G84Format, Rule::ComLead, Rule::PrjDialect]);
}
