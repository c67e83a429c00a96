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
