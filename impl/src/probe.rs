//! Test only: counts on this thread of calls that a fast path avoids, so that a test sees which
//! path ran where both give the same events (issue #33: no trace tells them apart) — a contour
//! cycle's `next_event` (G70's `finish::Cycle`, G73's `g73::Cycle`, G71/G72's
//! `rough::Roughing`: the events `fill` builds in place), and G71/G72's layer cuts computed
//! afresh (`rough`'s `new_layer_cut`: a line's cut is otherwise stepped from the layer before),
//! and G76.DEPTH.MIN's switch pass searched (`schedule`'s `switch_search`, not the closed form).
//! A test reads a count before and after its run.
extern crate std;
use core::cell::Cell;

std::thread_local! {
    static CALLS: Cell<usize> = const { Cell::new(0) };
    static CUTS: Cell<usize> = const { Cell::new(0) };
    static SEARCHES: Cell<usize> = const { Cell::new(0) };
}

/// One call of a `next_event` that counts itself.
pub fn count() {
    CALLS.with(|c| c.set(c.get() + 1));
}

/// The calls counted on this thread so far.
pub fn calls() -> usize {
    CALLS.with(Cell::get)
}

/// One G71/G72 layer cut computed afresh (not stepped from the layer before).
pub fn count_cut() {
    CUTS.with(|c| c.set(c.get() + 1));
}

/// The fresh layer cuts counted on this thread so far.
pub fn cuts() -> usize {
    CUTS.with(Cell::get)
}

/// One binary search for G76.DEPTH.MIN's switch pass.
pub fn count_search() {
    SEARCHES.with(|c| c.set(c.get() + 1));
}

/// The switch-pass searches counted on this thread so far.
pub fn searches() -> usize {
    SEARCHES.with(Cell::get)
}
