//! SMT lemmas about the G76/G78 rough-pass depth schedule (smt/lemmas/*.smt2, checked by z3 in
//! tests/lemmas.rs) and the driver that ties them to `cycle_impl::schedule` (tests/driver.rs):
//! [`model`] transcribes the lemmas' definitions; [`z3`] runs the solver. README.md.

pub mod model;
pub mod z3;
