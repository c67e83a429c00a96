//! The batch path of a running cycle ([`crate::Expander::fill`]): a cycle whose events come in
//! units of a fixed most (a pass, a start) writes whole units straight into the caller's
//! buffer, each event built in place, and falls back to its one-event state machine only for a
//! unit begun by `next_event` or where less room than a unit is left. The events are those of
//! `next_event`, in the same order.

use cycle_vocab::Event;

/// The events of one unit, each written in place into the next of the caller's slots; an event
/// past the last slot is not written (the units' sizes are their most events).
pub(crate) struct Unit<'a> {
    slots: &'a mut [Event],
    n: usize,
}

impl<'a> Unit<'a> {
    #[inline(always)]
    pub(crate) fn new(slots: &'a mut [Event]) -> Self {
        Unit { slots, n: 0 }
    }

    /// Writes `e` into the next slot.
    #[inline(always)]
    pub(crate) fn put(&mut self, e: Event) {
        if let Some(slot) = self.slots.get_mut(self.n) {
            *slot = e;
            self.n += 1;
        }
    }

    /// Writes `e` if there is one (a move that does not move is none: PRJ.NOOP).
    #[inline(always)]
    pub(crate) fn put_some(&mut self, e: Option<Event>) {
        if let Some(e) = e {
            self.put(e);
        }
    }

    /// How many events were written.
    #[inline(always)]
    pub(crate) fn written(&self) -> usize {
        self.n
    }
}

/// A cycle that writes its events in units of at most `N` events.
pub(crate) trait Batch<const N: usize> {
    /// The cycle's one-event state machine.
    fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event>;
    /// A unit was begun by `next_event` and is not finished.
    fn begun(&self) -> bool;
    /// Makes the next unit current when the current one is finished; `false` when the cycle is
    /// done. Called only when no unit is begun.
    fn ready(&mut self) -> bool;
    /// Writes the whole current unit into `slots` (its events as `next_event` would give
    /// them), leaving it finished; returns how many were written.
    fn write_unit(&mut self, pos: &mut (i64, i64), slots: &mut [Event; N]) -> usize;
}

/// Writes the next events of `c` into `out`: a begun unit one event at a time, then whole
/// units while one fits, then one event at a time. Returns how many were written and whether
/// the cycle is done. Bounded work: `out.len()` events, one unit change per unit.
#[inline]
pub(crate) fn fill<const N: usize, C: Batch<N>>(c: &mut C, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
    let mut n = 0;
    while c.begun() {
        let Some(slot) = out.get_mut(n) else {
            return (n, false);
        };
        match c.next_event(pos) {
            Some(e) => {
                *slot = e;
                n += 1;
            }
            None => return (n, true),
        }
    }
    // Whole units, the position kept in a local.
    let mut at = *pos;
    while let Some(slots) = out.get_mut(n..).and_then(|r| r.first_chunk_mut::<N>()) {
        if !c.ready() {
            *pos = at;
            return (n, true);
        }
        n += c.write_unit(&mut at, slots);
    }
    *pos = at;
    // Less room than a unit: one event at a time.
    while let Some(slot) = out.get_mut(n) {
        match c.next_event(pos) {
            Some(e) => {
                *slot = e;
                n += 1;
            }
            None => return (n, true),
        }
    }
    (n, false)
}

/// A cycle whose bulk (a run of like events: pecks and their returns) a loop of its own writes
/// in place, every other event through `next_event`.
pub(crate) trait Bulk {
    /// The cycle's one-event state machine.
    fn next_event(&mut self, pos: &mut (i64, i64)) -> Option<Event>;
    /// The cycle is in its bulk.
    fn in_bulk(&self) -> bool;
    /// Writes as much of the bulk as fits into `out` (its events as `next_event` would give
    /// them); returns how many were written.
    fn write_bulk(&mut self, pos: &mut (i64, i64), out: &mut [Event]) -> usize;
}

/// Writes the next events of `c` into `out`: its bulk through [`Bulk::write_bulk`], every
/// other event through `next_event`. Returns how many were written and whether the cycle is
/// done. Bounded work: `out.len()` events.
#[inline]
pub(crate) fn fill_bulk<C: Bulk>(c: &mut C, pos: &mut (i64, i64), out: &mut [Event]) -> (usize, bool) {
    let mut n = 0;
    loop {
        if c.in_bulk() {
            n += c.write_bulk(pos, out.get_mut(n..).unwrap_or_default());
        }
        let Some(slot) = out.get_mut(n) else {
            return (n, false);
        };
        match c.next_event(pos) {
            Some(e) => {
                *slot = e;
                n += 1;
            }
            None => return (n, true),
        }
    }
}
