use super::*;

#[test]
fn fingerprints_differ_and_are_stable() {
    assert_eq!(fingerprint(""), "fnv1a64:cbf29ce484222325");
    assert_ne!(fingerprint(RULES_MD), fingerprint(INTERPRETATION_MD));
}
