use cycle_vocab::Rule;

/// The generator mostly builds legal programs and reaches the thread moves' checks.
#[test]
fn thread_moves_reach_the_rules() {
    super::super::tests::assert_reaches(super::build, &[Rule::G33, Rule::G34, Rule::ComLead, Rule::PrjDialect]);
}
