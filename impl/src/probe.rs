//! Test only: counts on this thread of what no trace shows (issue #33: two paths give the same
//! events, so no trace tells them apart). A test reads a count before and after what it runs.
//! - the calls of a contour cycle's `next_event` (G70's `finish::Cycle`, G73's `g73::Cycle`,
//!   G71/G72's `rough::Roughing`): which events `fill` builds in place;
//! - the calls of G162's `split::next`, which the cycle's own step of a full pass does not make;
//! - G71/G72's layer cuts computed afresh (`rough`'s `new_layer_cut`: a line's cut is otherwise
//!   stepped from the layer before);
//! - G76.DEPTH.MIN's switch pass searched (`schedule`'s `switch_search`, not the closed form),
//!   and G76.DEPTH.1's square roots taken (`schedule`'s `root`, where its walk from the guess
//!   does not find the root);
//! - the plain-block loops entered (`stream::runs`) and the blocks read (`Core::lex`): that a
//!   run of plain blocks is read in one loop, and no block before the buffer has room;
//! - the G92 passes of X alone read by their short path (`Machine::plain_g92`).
extern crate std;
use core::cell::Cell;

/// One thread-local counter: `$count` adds one, `$read` gives the count so far.
macro_rules! counter {
    ($cell:ident, $count:ident, $read:ident, $what:literal) => {
        std::thread_local! {
            static $cell: Cell<usize> = const { Cell::new(0) };
        }
        #[doc = concat!("One more: ", $what, ".")]
        pub fn $count() {
            $cell.with(|c| c.set(c.get() + 1));
        }
        #[doc = concat!("How many so far on this thread: ", $what, ".")]
        pub fn $read() -> usize {
            $cell.with(Cell::get)
        }
    };
}

counter!(CALLS, count, calls, "calls of a `next_event` that counts itself");
counter!(CUTS, count_cut, cuts, "G71/G72 layer cuts computed afresh");
counter!(SEARCHES, count_search, searches, "G76.DEPTH.MIN switch-pass searches");
counter!(ROOTS, count_root, roots, "G76.DEPTH.1 square roots taken");
counter!(RUNS, count_run, runs, "plain-block loops entered");
counter!(READS, count_read, reads, "blocks read");
counter!(SHORT, count_short, shorts, "G92 passes of X alone read by their short path");
