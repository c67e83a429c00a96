use super::*;

#[test]
fn a_campaign_counts_its_cases_and_failures() {
    let options = certify::Options { cycles: certify::Options::parse_cycles("g92").unwrap(), cases: 10, ..certify::Options::default() };
    let n = Cases::new(&options, &certify::readings_plan::Plan::drawn(options.readings.clone())).count() as u64;
    let r = campaign(&ImplEngine, &options, 4);
    assert_eq!((r.cases, r.bad), (n, 0));
    let wrong = cycle_kernel::engine::wrong::Panics;
    assert_eq!(campaign(&wrong, &options, 0).bad, n);
    assert_eq!(drawing(&options).cases, n);
}
