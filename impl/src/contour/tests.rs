use super::*;

/// The bound and what it costs, as documented: 48-byte elements, 48 000 bytes.
#[test]
fn buffer_size() {
    assert_eq!(core::mem::size_of::<Element>(), 48);
    assert_eq!(core::mem::size_of::<[Element; MAX_BLOCKS]>(), 48_000);
    assert!(core::mem::size_of::<Contour>() <= 48_016);
    // The uninterrupted expander; its configuration carries the operator script (16
    // actions, ~260 bytes) and it holds the subprogram call stack (`sub::Calls`, 248
    // bytes), hence the bound over 50 000.
    assert!(core::mem::size_of::<crate::stream::Core<'_>>() < 50_500);
    // The operator layer (OP.SCRIPT): script, one cut, look-ahead, output queue.
    assert!(core::mem::size_of::<crate::operator::Layer>() <= 2_400);
    assert!(core::mem::size_of::<crate::expander::Expander<'_>>() < 52_800);
    let mut c = Contour::new();
    assert!(c.is_empty() && c.elements.is_none());
    for i in 0..MAX_BLOCKS {
        assert!(c.push(Element { line: i as u32, ..Element::ZERO }));
    }
    assert!(!c.push(Element::ZERO));
    assert_eq!((c.len(), c.last().line, c.get(MAX_BLOCKS)), (MAX_BLOCKS, 999, Element::ZERO));
}

/// `clear` empties the contour for the next cycle; an element of an earlier, longer contour left
/// in the buffer is never read: `get` beyond the end is `Element::ZERO`, `elements` and `last`
/// stop at the end (the contour of a later cycle is its own blocks only).
#[test]
fn a_cleared_contour_reads_only_its_own_elements() {
    let mut c = Contour::new();
    let e = |line: u32| Element { x: i64::from(line), line, kind: Kind::Feed, ..Element::ZERO };
    assert!(c.push(e(1)) && c.push(e(2)) && c.push(e(3)));
    assert!(!c.is_empty());
    c.clear();
    assert!(c.is_empty());
    assert_eq!((c.len(), c.get(0), c.elements()), (0, Element::ZERO, &[][..]));
    assert!(c.push(e(7)));
    assert!(!c.is_empty());
    assert_eq!((c.len(), c.get(0), c.get(1), c.last()), (1, e(7), Element::ZERO, e(7)));
    assert_eq!(c.elements(), &[e(7)][..]);
}
