use super::*;

/// The bound of the module doc: four frames and the counters, 248 bytes.
#[test]
fn size() {
    assert_eq!(core::mem::size_of::<Frame>(), 48);
    assert!(core::mem::size_of::<Calls>() <= 248, "{}", core::mem::size_of::<Calls>());
}

#[test]
fn area_and_find() {
    let src = b"G0 X1\nM30\nO1\nM99\nO2 (two)\nO2\nM99\n";
    let area = area_after(Blocks::new(src)).unwrap();
    let Area::At(from) = area else { panic!("{area:?}") };
    let (at, line, returns) = find(src, from, 1).unwrap().unwrap();
    assert_eq!((line, returns), (3, true));
    let mut b = Block::new();
    assert!(Blocks::resume(src, at).read(&mut b).unwrap());
    assert!(b.get(b'O').unwrap().is(1));
    // Two O2 blocks, no O3: not found.
    assert_eq!(find(src, from, 2), Ok(None));
    assert_eq!(find(src, from, 3), Ok(None));
    // SUB.RETURN: an O block with no M99 at or after it.
    let src = b"M30\nO1\nG0 X1\nO2 M99\n";
    let Ok(Area::At(from)) = area_after(Blocks::new(src)) else { panic!() };
    assert_eq!(find(src, from, 1).unwrap().map(|f| f.2), Some(true));
    assert_eq!(find(src, from, 2).unwrap().map(|f| f.2), Some(true));
    let src = b"M30\nO1\nG0 X1\n";
    let Ok(Area::At(from)) = area_after(Blocks::new(src)) else { panic!() };
    assert_eq!(find(src, from, 1).unwrap().map(|f| f.2), Some(false));
    assert_eq!(area_after(Blocks::new(b"G0 X1\nM3\n")), Ok(Area::Empty));
    // M30. and M-2 are no ends.
    assert_eq!(area_after(Blocks::new(b"M30.\nM-2\n")), Ok(Area::Empty));
    // A lexing alarm in the area is returned.
    let src = b"M30\nO1\nX1-2\n";
    let Ok(Area::At(from)) = area_after(Blocks::new(src)) else { panic!() };
    assert_eq!(find(src, from, 1).unwrap_err().code, AlarmCode::BadCharacter);
}

mod programs;
