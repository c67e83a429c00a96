//! The body of the `impl_invariants` fuzz target: the harness bodies of this crate on the
//! production expander, with the fuzzer choosing the harness and every draw — the same bodies
//! Kani proves and the drivers run under `cargo test`.
//!
//! A fuzz input is read by a [`FuzzSource`]: its first draw is an index into [`HARNESSES`], the
//! rest are the body's. A committed case (seed or regression) is stored decoded — the harness's
//! name and the values its body drew — and replayed by a [`ReplaySource`], so it keeps its
//! meaning whatever the byte encoding; [`encode`] turns it back into fuzz bytes for libFuzzer's
//! corpus.

use crate::source::{Outcome, Source, Stop};
use crate::{depth_bounds, depth_step_monotone, expander_envelope, g162_pitch, g162_split, g92_pullout, trace_depths};
use crate::{program::CAPACITY, schedule::Production};
use cycle_harness::{FuzzSource, ReplaySource};

/// The harnesses by the name a committed case records; the fuzz input's first draw indexes it.
pub const HARNESSES: [&str; 8] = [
    "expander_never_panics_wide",
    "expander_never_panics_small",
    "g92_pullout_total",
    "depth_step_monotone",
    "depth_bounds",
    "trace_depths",
    "g162_split_exact",
    "g162_variable_pitch",
];

/// Small lengths, where legal cycles have many passes (the proofs' `random_small` scope).
const SMALL: expander_envelope::Scope = expander_envelope::Scope {
    max_start: 2000,
    max_len: 60,
    max_lead: 3000,
    max_passes: 60,
    max_program: 160,
    ..expander_envelope::WIDE
};

/// Wider than the Kani scope: lengths to 1 mm·1000, any lead, the writer's whole buffer.
const G92: g92_pullout::Scope =
    g92_pullout::Scope { max_len: 1_000_000, max_lead: 99_990_000, max_program: CAPACITY, ..g92_pullout::KANI };

const SEQUENCE: depth_bounds::Scope = depth_bounds::Scope { max_passes: 64, ..depth_bounds::KANI };

/// Runs the harness `name` on `src`; `None` for a name not in [`HARNESSES`].
pub fn run<S: Source>(name: &str, src: &mut S) -> Option<Outcome> {
    Some(match name {
        "expander_never_panics_wide" => expander_envelope::body(src, &expander_envelope::WIDE),
        "expander_never_panics_small" => expander_envelope::body(src, &SMALL),
        "g92_pullout_total" => g92_pullout::body(src, &G92),
        "depth_step_monotone" => depth_step_monotone::body(src, &Production, &depth_step_monotone::FULL),
        "depth_bounds" => depth_bounds::body(src, &Production, &SEQUENCE),
        "trace_depths" => trace_depths::body(src),
        "g162_split_exact" => g162_split::body(src, &g162_split::FULL),
        "g162_variable_pitch" => g162_pitch::body(src, &g162_pitch::KANI),
        _ => return None,
    })
}

/// A fuzz input, decoded: the harness, the values its body drew, what it returned, and the
/// program it built (if it built one).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Decoded {
    pub harness: &'static str,
    pub draws: Vec<i128>,
    pub outcome: Outcome,
    pub program: Option<Vec<u8>>,
}

/// Runs the body on fuzz bytes and records what it drew.
pub fn decode(data: &[u8]) -> Decoded {
    let mut src = FuzzSource::new(data);
    let harness = HARNESSES[src.choose(HARNESSES.len() as u32) as usize];
    let outcome = run(harness, &mut src).unwrap_or(Ok(()));
    let draws = src.draws.get(1..).unwrap_or_default().to_vec();
    Decoded { harness, draws, outcome, program: src.program }
}

/// The failure report of a case, or `Ok` when every property held (or it was rejected).
pub fn report(harness: &str, draws: &[i128], outcome: Outcome, program: Option<&[u8]>) -> Result<(), String> {
    match outcome {
        Err(Stop::Failed(msg)) => {
            let text = program.map(|p| format!("\nprogram:\n{}", String::from_utf8_lossy(p))).unwrap_or_default();
            Err(format!("harness {harness}: {msg}\ndraws: {draws:?}{text}"))
        }
        Ok(()) | Err(Stop::Rejected) => Ok(()),
    }
}

/// The target's body: `Err` with the report when a property fails.
pub fn fuzz(data: &[u8]) -> Result<(), String> {
    let d = decode(data);
    report(d.harness, &d.draws, d.outcome, d.program.as_deref())
}

/// Fuzz bytes that [`decode`] to `harness` with `draws`; `None` for an unknown harness.
pub fn encode(harness: &str, draws: &[i128]) -> Option<Vec<u8>> {
    let index = HARNESSES.iter().position(|&h| h == harness)?;
    let mut all = vec![index as i128];
    all.extend_from_slice(draws);
    Some(FuzzSource::encode(&all))
}

/// Replays a decoded case: its outcome and program, or why its draws no longer fit the harness.
pub fn replay(harness: &str, draws: &[i128]) -> Result<(Outcome, Option<Vec<u8>>), String> {
    let mut src = ReplaySource::new(draws.to_vec());
    let outcome = run(harness, &mut src).ok_or_else(|| format!("no harness {harness:?} (known: {HARNESSES:?})"))?;
    src.finish()?;
    Ok((outcome, src.program))
}

/// The built-in seeds, by name: per harness, the plain case (every draw its range's low end)
/// and four decoded from fixed-seed random bytes.
pub fn seeds() -> Vec<(String, Decoded)> {
    let mut rng = 0x5eed_f022_u64;
    let mut out = Vec::new();
    for (i, harness) in HARNESSES.iter().enumerate() {
        let head = FuzzSource::encode(&[i as i128]);
        out.push((format!("{harness}_plain"), decode(&head)));
        for r in 0..4 {
            let mut bytes = head.clone();
            bytes.extend((0..17 * 40).map(|_| {
                rng ^= rng << 13;
                rng ^= rng >> 7;
                rng ^= rng << 17;
                (rng >> 24) as u8
            }));
            out.push((format!("{harness}_random_{r}"), decode(&bytes)));
        }
    }
    out
}

#[cfg(test)]
mod tests;
