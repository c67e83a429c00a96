//! Unit tests of the stand-in.

#[test]
fn stub_api_shapes() {
    let x: u32 = crate::any();
    let y: i64 = crate::any_where(|v: &i64| *v == 0);
    crate::assume(x == 0);
    crate::assert(y == 0, "zero");
    crate::cover!(x == 0, "covered");
    crate::cover!(x == 0);
    let a: [u8; 4] = crate::any();
    assert_eq!(a, [0; 4]);
}
