//! The harnesses as Kani compiles them (`cfg(kani)`), type-checked against the local stand-in
//! for the `kani` crate (`harness/kani-stub`), so a change that breaks a Kani harness fails CI
//! even though Kani itself is not installed here.
//!
//! Runs `cargo check -p cycle-proofs` with `RUSTFLAGS="--cfg kani --cfg kani_stub"` in its own
//! target directory (`target/kani-check`), without and with the feature `kani-attempts` (the
//! TESTs' harnesses as proof harnesses), as documented in `proofs/README.md`.

use std::path::Path;
use std::process::Command;

#[test]
fn harnesses_type_check_under_cfg_kani() {
    let cargo = std::env::var("CARGO").unwrap_or_else(|_| "cargo".to_string());
    let workspace = Path::new(env!("CARGO_MANIFEST_DIR")).parent().expect("proofs/ has a parent");
    for features in [&[][..], &["--features", "kani-attempts"]] {
        let out = Command::new(&cargo)
            .current_dir(workspace)
            .env("RUSTFLAGS", "--cfg kani --cfg kani_stub")
            .env_remove("CARGO_TARGET_DIR")
            .args(["check", "--quiet", "-p", "cycle-proofs", "--target-dir", "target/kani-check"])
            .args(features)
            .output()
            .expect("cargo runs");
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "cargo check {features:?} under --cfg kani --cfg kani_stub failed:\n{stderr}");
        // Warnings of other crates are theirs; the harness crates compile cleanly under cfg(kani).
        for ours in ["proofs/src", "harness/src", "harness/kani-stub"] {
            assert!(!stderr.contains(ours), "warnings {features:?} under cfg(kani):\n{stderr}");
        }
    }
}
