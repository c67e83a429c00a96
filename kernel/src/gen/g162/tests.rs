use cycle_vocab::Rule;

/// The generator mostly builds legal programs and reaches every check of the register.
#[test]
fn g162_reaches_the_rules() {
    super::super::tests::assert_reaches(
        super::build,
        &[
            Rule::G162A, Rule::G162B, Rule::G162H, Rule::G162I, Rule::G162J, Rule::G162Pq, Rule::G162F,
            Rule::PrjMaxPass, Rule::PrjWord, Rule::PrjDialect, Rule::Nc201AbsInc,
        ],
    );
}
