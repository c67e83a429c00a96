//! The macro on a toy property: its entry, its generated tests (run as this module's tests, one
//! of them expected to fail), and the registry check.

use crate::{check, cover, CheckedBy, Outcome, Property, Source};

/// x + y never overflows for x, y ≤ `max` (and a wrong claim about it, for the failing test).
fn sum_body<S: Source>(src: &mut S, max: u32, claim_below: u64) -> Outcome {
    let (x, y) = (src.bounded_u32(0, max), src.bounded_u32(0, max));
    let sum = u64::from(x) + u64::from(y);
    check!(src, sum <= 2 * u64::from(max), "the sum is at most 2·max");
    check!(src, sum < claim_below, "the sum is below the claim");
    cover!(src, x == max && y == max, "both at the top");
    Ok(())
}

const PROPERTIES: &[Property] = &[SUM, WRONG];

crate::property! {
    /// A true property, proved.
    const SUM = toy_sum in PROPERTIES {
        rules: ["COM.RANGES"],
        states: "x + y ≤ 2·max.",
        body: |src, max| sum_body(src, max, u64::MAX),
        /// The Kani harness.
        kani: proof(u32::MAX) { unwind: 3, solver: kissat, stubs: [core::cmp::max => core::cmp::min], measured: "SUCCESSFUL, 1 s" },
        tests {
            /// Every pair below 5.
            fn toy_sum_exhaustive = exhaustive(8, 1000) on 4;
            fn toy_sum_random = random(1, 100_000) on u32::MAX, random(2, 100_000) on 7;
        }
    }
}

crate::property! {
    const WRONG = toy_wrong in PROPERTIES {
        rules: ["COM.RANGES", "PRJ.MAXPASS"],
        states: "x + y < 8 (false).",
        body: |src, max| sum_body(src, max, 8),
        kani: test(u32::MAX) { why: "a toy" },
        tests {
            #[should_panic(expected = "the sum is below the claim")]
            fn toy_wrong_exhaustive = exhaustive(8, 1000) on 4;
        }
    }
}

/// A property the registry does not list: its test fails before running any driver.
const UNLISTED: &[Property] = &[SUM];

crate::property! {
    const NOT_LISTED = toy_unlisted in UNLISTED {
        rules: ["COM.RANGES"],
        states: "x + y ≤ 2·max.",
        body: |src, max| sum_body(src, max, u64::MAX),
        kani: none { why: "not a Kani target" },
        tests {
            #[should_panic(expected = "toy_unlisted is not in the crate's list")]
            fn toy_unlisted_exhaustive = exhaustive(8, 1000) on 4;
        }
    }
}

#[test]
fn entries_say_what_the_macro_was_given() {
    assert_eq!(SUM.harness, "toy_sum");
    assert_eq!(
        (SUM.rules, SUM.statement, SUM.checked_by),
        (&["COM.RANGES"][..], "x + y ≤ 2·max.", CheckedBy::Kani)
    );
    assert_eq!(
        (SUM.kani, SUM.unwind, SUM.solver),
        ("SUCCESSFUL, 1 s", Some(3), Some("kissat"))
    );
    assert_eq!(SUM.stubs, ["core::cmp::max"]);
    assert_eq!(SUM.tests, ["toy_sum_exhaustive", "toy_sum_random"]);
    assert_eq!(
        (WRONG.checked_by, WRONG.kani, WRONG.unwind, WRONG.solver),
        (CheckedBy::Drivers, "a toy", None, None)
    );
    assert!(WRONG.stubs.is_empty());
    assert_eq!(
        (NOT_LISTED.checked_by, NOT_LISTED.kani),
        (CheckedBy::Drivers, "not a Kani target")
    );
}
