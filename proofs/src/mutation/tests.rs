//! Unit tests of `mutation`.

use super::*;
use crate::schedule::mutants::{ClampToK, CountOffByOne, LastPlusOne, NoMinimum};
use crate::schedule::Production;

#[test]
fn production_passes_the_mutation_scopes() {
    assert_eq!(failing(&Production), vec![]);
}

#[test]
fn mutant_schedule_is_caught() {
    let mutants = [
        ("clamp to k (d = 1)", failing(&ClampToK { finish_allowance: 1 })),
        ("clamp to k (d = 100)", failing(&ClampToK { finish_allowance: 100 })),
        ("last pass at k − d + 1", failing(&LastPlusOne)),
        ("minimum cut ignored", failing(&NoMinimum)),
        ("pass count off by one", failing(&CountOffByOne)),
    ];
    for (name, caught) in mutants {
        assert!(!caught.is_empty(), "mutant {name:?} passed every schedule harness");
        for (harness, why) in &caught {
            println!("mutant {name:?} caught by {harness}: {why}");
        }
    }
}
