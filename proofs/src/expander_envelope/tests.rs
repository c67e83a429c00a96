//! The unit tests of `expander_envelope` that are not its harness drivers.

use super::*;
use crate::program::Program;

/// The longest program of the Kani scope, written out (inch ISC, 5 decimals, every optional
/// word, negative U, W, R): 110 bytes.
#[test]
fn longest_kani_program_is_110_bytes() {
    let mut p = Program::new();
    p.text(b"G78P029999Q0.00009R0.00009D1L2E0.00009\n");
    p.text(b"G78U-0.00036W-0.00009R-0.00009P0.00009Q0.00009F0.00009J0.00009K0.00009\n");
    assert_eq!(p.len(), KANI_PROGRAM);
}
