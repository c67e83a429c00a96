//! Edges of the shared modules (`program`, `lex`, `words`, `operator/`, `sub`, …) that the
//! spec-alone mutation run of 2026-11-28 (sixth session, docs/MUTATION.md) found unpinned, each
//! worked by hand from docs/INTERPRETATION.md, the crate's documented API and the manuals.

use crate::expand_into;
use crate::tests::util::alarm_of;
use core::ops::ControlFlow;
use cycle_vocab::{AlarmCode, Config, Rule};

/// `expand_into` (the crate's API, `lib.rs`): "When `sink` answers `Break` it gets no further
/// event and the expansion stops after the block it is in (the result is then `None`, unless
/// that block itself ended in an alarm)". Block 2 would be `MISSING WORD F` (COM.LEAD: G01
/// moving with no feed set), but the sink broke at block 1's move: no alarm, one event.
#[test]
fn a_sink_that_breaks_ends_the_expansion_after_its_block() {
    let src = "G0 X10\nG1 X20\n";
    assert_eq!(alarm_of(src), (AlarmCode::MissingWord, Some('F'), Rule::ComLead, 2));
    let mut seen = 0;
    let alarm = expand_into(src.as_bytes(), &Config::default(), &mut |_| {
        seen += 1;
        ControlFlow::Break(())
    });
    assert_eq!((alarm, seen), (None, 1));
}
