use super::*;
use std::time::{Duration, UNIX_EPOCH};

#[test]
fn sha256_test_vectors() {
    // FIPS 180-2, appendix B.
    assert_eq!(sha256(b""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
    assert_eq!(sha256(b"abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
    let two_blocks = b"abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
    assert_eq!(sha256(two_blocks), "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

#[test]
fn utc_times() {
    assert_eq!(utc(UNIX_EPOCH), "1970-01-01T00:00:00Z");
    assert_eq!(utc(UNIX_EPOCH + Duration::from_secs(951_782_400)), "2000-02-29T00:00:00Z");
    assert_eq!(utc(UNIX_EPOCH + Duration::from_secs(1_798_761_599)), "2026-12-31T23:59:59Z");
}

#[test]
fn a_candidate_is_resolved_and_hashed() {
    let manifest = concat!(env!("CARGO_MANIFEST_DIR"), "/Cargo.toml");
    let c = candidate(&["sh".to_string(), manifest.to_string(), "--flag".to_string()]);
    assert!(c.executable.path.ends_with("sh"), "{c:?}");
    assert_eq!(c.executable.sha256.as_deref().map(str::len), Some(64), "{c:?}");
    let expected = sha256(&std::fs::read(manifest).unwrap());
    assert_eq!(c.files.iter().map(|f| f.sha256.clone().unwrap()).collect::<Vec<_>>(), [expected]);
    let missing = candidate(&["/nonexistent/candidate".to_string()]);
    assert_eq!(missing.executable.error.as_deref(), Some("not found"));
    assert!(BUILD.commit == "unknown" || BUILD.commit.len() == 40, "{}", BUILD.commit);
    assert!(["true", "false", "unknown"].contains(&BUILD.dirty));
}
