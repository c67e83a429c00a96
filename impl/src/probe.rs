//! Test only: counts on this thread of what no trace shows (issue #33: two paths give the same
//! events, so no trace tells them apart). A test reads a count before and after what it runs.
//! - the calls of a contour cycle's `next_event` (G70's `finish::Cycle`, G73's `g73::Cycle`):
//!   which events `fill` builds in place and which it takes from `next_event`;
//! - the calls of G162's `split::next`, which the cycle's own step of a full pass does not make;
//! - the plain-block loops entered (`stream::runs`) and the blocks read (`Core::lex`): that a
//!   run of plain blocks is read in one loop, and no block before the buffer has room.
extern crate std;
use core::cell::Cell;

std::thread_local! {
    static CALLS: Cell<usize> = const { Cell::new(0) };
    static RUNS: Cell<usize> = const { Cell::new(0) };
    static READS: Cell<usize> = const { Cell::new(0) };
}

/// One call of a `next_event` that counts itself.
pub fn count() {
    CALLS.with(|c| c.set(c.get() + 1));
}

/// The calls counted on this thread so far.
pub fn calls() -> usize {
    CALLS.with(Cell::get)
}

/// A plain-block loop entered.
pub fn count_run() {
    RUNS.with(|c| c.set(c.get() + 1));
}

/// The plain-block loops entered on this thread so far.
pub fn runs() -> usize {
    RUNS.with(Cell::get)
}

/// A block read.
pub fn count_read() {
    READS.with(|c| c.set(c.get() + 1));
}

/// The blocks read on this thread so far.
pub fn reads() -> usize {
    READS.with(Cell::get)
}
