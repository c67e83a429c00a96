use super::*;
use super::super::{CaseRecord, Options};
use cycle_kernel::engine::wrong::SpecWith;
use cycle_kernel::registry::CycleRun;
use std::collections::BTreeSet;

/// The spec with the X of every thread move one increment off: a wrong candidate.
const THREAD_X_OFF: SpecWith = SpecWith {
    name: "thread-x-off",
    fault: |_, m| m.x += i64::from(m.kind == cycle_vocab::MoveKind::Thread),
};

#[test]
fn a_wrong_candidate_is_found_grouped_and_minimized() {
    let o = Options { cycles: Options::parse_cycles("g92").unwrap(), cases: 10, ..Options::default() };
    let mut p = super::super::cases::Cases::new(&o, &super::super::readings_plan::Plan::drawn(o.readings.clone())).next().unwrap();
    let judged = judge(&SpecEngine, &THREAD_X_OFF, &p.program, &p.config);
    assert!(judged.reference.is_some());
    let result = judged.result;
    let CaseResult::Diverge(d) = &result else { panic!("{result:?}") };
    assert_eq!(d.field, Some("x"));
    let record = CaseRecord {
        name: p.name.clone(),
        origin: p.origin.clone(),
        cycle: CycleRun::Family(cycle_kernel::registry::find("g92").unwrap()),
        program: p.program.clone(),
        config: p.config,
        events: 0,
        rules: BTreeSet::new(),
        ending: String::new(),
        result: result.clone(),
        traces: None,
    };
    let m = minimize(&THREAD_X_OFF, &record, &mut p, signature(d)).unwrap();
    assert_eq!(m.method, "line deletion");
    assert!(m.program.len() < record.program.len(), "{}", String::from_utf8_lossy(&m.program));
    assert_eq!(signature(&m.divergence), signature(d));
}
