//! `Expander::fill` (the batch API of the production expander: events written straight into the
//! caller's buffer) gives exactly the stream of `Expander`'s iterator (PRJ.TRACE): the same
//! events in the same order, then the same alarm, for every buffer size — including sizes that
//! end a buffer in the middle of a pass, before an alarm, or at the end of the program.
//!
//! Programs: every generator family of `cycle_kernel::gen` (`CYCLECHECK_CASES`, default
//! 2 000, fixed seed `CYCLECHECK_SEED`) and the built-in corpus.

use cycle_impl::Expander;
use cycle_kernel::corpus;
use cycle_kernel::gen::{self, Case};
use cycle_vocab::{Alarm, Config, Event, Move, Rule};
use proptest::test_runner::{Config as ProptestConfig, RngAlgorithm, TestCaseError, TestRng, TestRunner};

/// Buffer sizes: single events, sizes around one start (a header and up to six moves), and a
/// large one.
const SIZES: [usize; 10] = [1, 2, 3, 5, 6, 7, 8, 13, 64, 4_096];

/// Events before the comparison stops (the generators stay far below it; a runaway would not).
const EVENT_LIMIT: usize = 2_000_000;

/// What the iterator yields: the events, then the alarm if any.
fn by_iterator(program: &[u8], config: Config) -> (Vec<Event>, Option<Alarm>) {
    let mut events = Vec::new();
    for item in Expander::new(program, config).take(EVENT_LIMIT) {
        match item {
            Ok(e) => events.push(e),
            Err(a) => return (events, Some(a)),
        }
    }
    (events, None)
}

/// What `fill` writes with a buffer of `size` events. Checks the API's contract on the way: a
/// short write is followed by the alarm or by the end (0 events), and after either every call
/// writes nothing.
fn by_fill(program: &[u8], config: Config, size: usize) -> Result<(Vec<Event>, Option<Alarm>), String> {
    let filler = Event::Move(Move::rapid(i64::MIN, i64::MIN, Rule::PrjTrace));
    let mut buffer = vec![filler; size];
    let mut expander = Expander::new(program, config);
    let mut events = Vec::new();
    let mut short = false;
    let alarm = loop {
        if events.len() >= EVENT_LIMIT {
            return Ok((events, None));
        }
        match expander.fill(&mut buffer) {
            Err(a) => break Some(a),
            Ok(0) => break None,
            Ok(n) if short => return Err(format!("{n} events after a short write of a {size}-event buffer")),
            Ok(n) => {
                let written = buffer.get(..n).ok_or_else(|| format!("fill says {n} events into {size} slots"))?;
                events.extend_from_slice(written);
                short = n < size;
            }
        }
    };
    for _ in 0..2 {
        let after = expander.fill(&mut buffer);
        if after != Ok(0) {
            return Err(format!("the stream went on after its end: {after:?}"));
        }
    }
    Ok((events, alarm))
}

/// Both ways agree for every buffer size; the message names the size and the first difference.
fn agree(program: &[u8], config: Config) -> Result<(), String> {
    let (events, alarm) = by_iterator(program, config);
    for size in SIZES {
        let (filled, filled_alarm) = by_fill(program, config, size).map_err(|e| format!("buffer of {size}: {e}"))?;
        if let Some(i) = (0..events.len().max(filled.len())).find(|&i| events.get(i) != filled.get(i)) {
            return Err(format!(
                "buffer of {size}: event {i} differs: iterator {:?}, fill {:?}",
                events.get(i),
                filled.get(i)
            ));
        }
        if alarm != filled_alarm {
            return Err(format!("buffer of {size}: alarm differs: iterator {alarm:?}, fill {filled_alarm:?}"));
        }
    }
    Ok(())
}

fn cases() -> u32 {
    std::env::var("CYCLECHECK_CASES").ok().and_then(|v| v.trim().parse().ok()).unwrap_or(2_000)
}

fn seed() -> [u8; 32] {
    let s: u64 = std::env::var("CYCLECHECK_SEED").ok().and_then(|v| v.trim().parse().ok()).unwrap_or(0xf111_0000_5eed);
    gen::seed_bytes(s)
}

#[test]
fn fill_gives_the_iterator_stream_on_generated_programs() {
    let config = ProptestConfig { cases: cases(), failure_persistence: None, ..ProptestConfig::default() };
    let mut runner = TestRunner::new_with_rng(config, TestRng::from_seed(RngAlgorithm::ChaCha, &seed()));
    let outcome = runner.run(&gen::any_case(), |case: Case| {
        agree(&case.program, case.config).map_err(|e| TestCaseError::fail(format!("{e}
{case:?}")))
    });
    if let Err(e) = outcome {
        panic!("fill and the iterator disagree (case shrunk): {e}");
    }
}

#[test]
fn fill_gives_the_iterator_stream_on_the_corpus() {
    let mut count = 0;
    for (name, program, config) in corpus::cases() {
        if let Err(e) = agree(&program, config) {
            panic!("{name}: {e}");
        }
        count += 1;
    }
    assert!(count >= 20, "the corpus has {count} programs");
}

/// An alarm after some events: the events come first, the alarm from the next call, then
/// nothing (the case of a buffer that the events do not fill).
#[test]
fn an_alarm_follows_the_events_before_it() {
    // (From X44: the default pull-out, J = one lead, ends at X42 — G92.PATH step ③ refuses X₃
    // beyond the start X.)
    let program = b"G0 X44 Z5\nG92 X38 Z-20 F2\nG0 X1 #\n";
    let mut expander = Expander::new(program, Config::default());
    let mut buffer = vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); 64];
    let n = expander.fill(&mut buffer).unwrap();
    let (events, alarm) = by_iterator(program, Config::default());
    assert_eq!(&buffer[..n], &events[..]);
    assert!(n >= 5, "{n} events");
    assert_eq!(expander.fill(&mut buffer), Err(alarm.unwrap()));
    assert_eq!(expander.fill(&mut buffer), Ok(0));
    assert_eq!(expander.fill(&mut []), Ok(0));
}
