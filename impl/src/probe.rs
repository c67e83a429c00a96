//! Test only: the calls of a contour cycle's `next_event` (G70's `finish::Cycle`, G73's
//! `g73::Cycle`) on this thread, so that a test sees which events `fill` builds in place and
//! which it takes from `next_event` (issue #33: the two paths give the same events, so no trace
//! tells them apart); likewise the calls of G162's `split::next`, which the cycle's own step
//! of a full pass does not make. A test reads the count before and after the cycle it runs.
extern crate std;
use core::cell::Cell;

std::thread_local! {
    static CALLS: Cell<usize> = const { Cell::new(0) };
}

/// One call of a `next_event` that counts itself.
pub fn count() {
    CALLS.with(|c| c.set(c.get() + 1));
}

/// The calls counted on this thread so far.
pub fn calls() -> usize {
    CALLS.with(Cell::get)
}
