//! The bodies of the cargo-fuzz targets (`fuzz/fuzz_targets/*.rs` are one line each), so the
//! same code runs under libFuzzer, in `cargo test` (which replays the committed seed corpus and
//! every committed regression case, `tests/tests/fuzz_replay.rs`) and in `cyclecheck fuzz`.
//!
//! Each body takes the fuzzer's raw bytes and returns `Err` with a report — the conformance
//! relation's rich divergence, or the broken property — when the case fails; the targets panic
//! with that report so libFuzzer prints it and saves the input.
//!
//! | target | input | checks |
//! |---|---|---|
//! | `parse_blocks` | any bytes as a program | the lexer ends, one alarm at most, on a line of the program; both engines expand it under two configurations without a panic, reject it with an alarm on a line of the program, and conform (a rejection is the same alarm in both) |
//! | `diff_spec_impl` | [`CycleInput`]: a generator family and its knobs | spec and impl conform ([`crate::conformance::check`]) |
//! | `impl_invariants` | draws of a proof harness ([`FuzzSource`]) | the `cycle-proofs` harness bodies (envelope, event bound, return to A, G92 pull-out table, depth schedule by induction and iteration, the G162 split and variable pitch) and the depth properties on the trace ([`trace_depths`]) |
//! | `gcode_roundtrip` | [`CycleInput`] | canonical expanded G-code of either engine reads back ([`crate::readback`]) as the same motions: kind, end point, feed or lead, angle, lead change |

mod input;
mod source;
pub mod trace_depths;

pub use input::CycleInput;
pub use source::FuzzSource;

use crate::campaign::{judge, Verdict};
use crate::engine::{Engine, ImplEngine, SpecEngine};
use crate::readback::{self, Motion};
use cycle_proofs::source::Stop;
use cycle_proofs::{depth_bounds, depth_step_monotone, expander_envelope, g162_pitch, g162_split, g92_pullout, schedule::Production};
use cycle_vocab::{Blocks, Config, Dialect, Grid, Increment, Rule, Units};

/// A fuzz target.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Target {
    ParseBlocks,
    DiffSpecImpl,
    ImplInvariants,
    GcodeRoundtrip,
}

impl Target {
    pub const ALL: [Target; 4] = [Target::ParseBlocks, Target::DiffSpecImpl, Target::ImplInvariants, Target::GcodeRoundtrip];

    /// The cargo-fuzz target name (also the corpus and regression folder name).
    pub const fn name(self) -> &'static str {
        match self {
            Target::ParseBlocks => "parse_blocks",
            Target::DiffSpecImpl => "diff_spec_impl",
            Target::ImplInvariants => "impl_invariants",
            Target::GcodeRoundtrip => "gcode_roundtrip",
        }
    }

    pub fn by_name(name: &str) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.name() == name)
    }

    /// Runs the target's body on one input.
    pub fn run(self, data: &[u8]) -> Result<(), String> {
        match self {
            Target::ParseBlocks => parse_blocks(data),
            Target::DiffSpecImpl => diff_spec_impl(data),
            Target::ImplInvariants => impl_invariants(data),
            Target::GcodeRoundtrip => gcode_roundtrip(data),
        }
    }
}

/// Runs `target` on `data` and panics with the report on a failure (for `fuzz_target!`).
pub fn fuzz(target: Target, data: &[u8]) {
    if let Err(report) = target.run(data) {
        panic!("{} failed:\n{report}", target.name());
    }
}

/// The configurations `parse_blocks` runs under: the default, and FANUC on the inch ISC grid.
fn parse_configs() -> [Config; 2] {
    let inch_isc = Grid { units: Units::Inch, increment: Increment::Isc };
    [Config::default(), Config { dialect: Dialect::Fanuc, grid: inch_isc, ..Config::default() }]
}

/// `parse_blocks`: arbitrary bytes as a program (PRJ.LEX, PRJ.WORD).
pub fn parse_blocks(data: &[u8]) -> Result<(), String> {
    let lines = data.iter().filter(|&&b| b == b'\n').count() + 1;
    let on_a_line = |line: u32| (1..=lines).contains(&(line as usize));
    // The lexer alone: it ends, each block on a line of the program, at most one alarm (a
    // lexical one, PRJ.LEX / PRJ.WORD, on a line of the program), then nothing.
    let mut blocks = Blocks::new(data);
    let mut count = 0usize;
    while let Some(block) = blocks.next() {
        count += 1;
        if count > data.len() + 1 {
            return Err("the lexer yields more blocks than the program has bytes".to_string());
        }
        match block {
            Ok(b) if !on_a_line(b.line) => return Err(format!("a block on line {} of {lines}", b.line)),
            Ok(_) => {}
            Err(a) => {
                if !matches!(a.rule, Rule::PrjLex | Rule::PrjWord) || !on_a_line(a.line) {
                    return Err(format!("lexical alarm {a:?} (rule or line wrong, {lines} lines)"));
                }
                if blocks.next().is_some() {
                    return Err("the lexer goes on after its alarm".to_string());
                }
            }
        }
    }
    // Both engines: no panic, a rejection is an alarm on a line of the program, and they agree.
    for config in parse_configs() {
        let (reference, verdict) = judge((&SpecEngine, &ImplEngine::default()), data, &config);
        if let Some(a) = reference.and_then(|t| t.alarm) {
            if !on_a_line(a.line) {
                return Err(format!("alarm {a:?} names line {} of a {lines}-line program", a.line));
            }
        }
        verdict_ok(verdict, data, &config)?;
    }
    Ok(())
}

/// A conforming verdict, or the report of the case.
fn verdict_ok(verdict: Verdict, program: &[u8], config: &Config) -> Result<(), String> {
    let report = match verdict {
        Verdict::Conform(_) => return Ok(()),
        Verdict::Diverge(d) => d.to_string(),
        Verdict::Panic { engine, message } => format!("PANIC in the {engine} engine: {message}"),
    };
    Err(format!("{report}\nconfig: {config:?}\nprogram:\n{}", String::from_utf8_lossy(program)))
}

/// `diff_spec_impl`: a structured cycle command through both engines, judged by the
/// conformance relation.
pub fn diff_spec_impl(data: &[u8]) -> Result<(), String> {
    let case = CycleInput::from_bytes(data).case();
    let (_, verdict) = judge((&SpecEngine, &ImplEngine::default()), &case.program, &case.config);
    verdict_ok(verdict, &case.program, &case.config).map_err(|e| format!("family {}\n{e}", case.family))
}

/// `impl_invariants`: the proof harness bodies of `cycle-proofs` on the production expander,
/// with the fuzzer choosing the harness and every draw.
pub fn impl_invariants(data: &[u8]) -> Result<(), String> {
    // Small lengths, where legal cycles have many passes (the proofs' `random_small` scope).
    const SMALL: expander_envelope::Scope =
        expander_envelope::Scope { max_start: 2000, max_len: 60, max_lead: 3000, max_passes: 60, max_program: 160, ..expander_envelope::WIDE };
    // Wider than the Kani scope: lengths to 1 mm·1000, any lead, the writer's whole buffer.
    const G92: g92_pullout::Scope = g92_pullout::Scope {
        max_len: 1_000_000,
        max_lead: 99_990_000,
        max_program: cycle_proofs::program::CAPACITY,
        ..g92_pullout::KANI
    };
    const SEQUENCE: depth_bounds::Scope = depth_bounds::Scope { max_passes: 64, ..depth_bounds::KANI };
    let mut src = FuzzSource::new(data);
    let (name, outcome) = match cycle_proofs::source::Source::choose(&mut src, 6) {
        0 => ("expander_never_panics (wide)", expander_envelope::body(&mut src, &expander_envelope::WIDE)),
        1 => ("expander_never_panics (small)", expander_envelope::body(&mut src, &SMALL)),
        2 => ("g92_pullout_total", g92_pullout::body(&mut src, &G92)),
        3 => ("depth_step_monotone", depth_step_monotone::body(&mut src, &Production, &depth_step_monotone::FULL)),
        4 => ("depth_bounds", depth_bounds::body(&mut src, &Production, &SEQUENCE)),
        // Index 5 is split three ways (the G162 harnesses came after the committed cases, whose
        // first choice keeps its meaning).
        _ => match cycle_proofs::source::Source::choose(&mut src, 3) {
            0 => ("trace_depths", trace_depths::body(&mut src)),
            1 => ("g162_split_exact", g162_split::body(&mut src, &g162_split::KANI)),
            _ => ("g162_variable_pitch", g162_pitch::body(&mut src, &g162_pitch::KANI)),
        },
    };
    match outcome {
        Err(Stop::Failed(msg)) => Err(format!("harness {name}: {msg}\ndraws: {:?}", src.draws)),
        Ok(()) | Err(Stop::Rejected) => Ok(()),
    }
}

/// `gcode_roundtrip`: canonical expanded G-code of each engine, read back, gives its motions.
pub fn gcode_roundtrip(data: &[u8]) -> Result<(), String> {
    let case = CycleInput::from_bytes(data).case();
    let engines: [&dyn Engine; 2] = [&SpecEngine, &ImplEngine::default()];
    for engine in engines {
        let trace = engine.expand(&case.program, &case.config);
        let text = trace.to_gcode();
        let context = || format!("engine {}, program:\n{}\nG-code:\n{text}", engine.name(), case.text());
        let (grid, motions) = readback::read(text.as_bytes()).map_err(|e| format!("{e}\n{}", context()))?;
        if grid != trace.grid {
            return Err(format!("grid {grid:?} read back as {:?}\n{}", trace.grid, context()));
        }
        let expected: Vec<Motion> = trace.moves().map(Motion::from).collect();
        if let Some(i) = (0..expected.len().max(motions.len())).find(|&i| expected.get(i) != motions.get(i)) {
            return Err(format!("motion {i}: {:?} read back as {:?}\n{}", expected.get(i), motions.get(i), context()));
        }
    }
    Ok(())
}

/// The built-in seed corpus of `target` (file name, bytes), committed under
/// `fuzz/corpus/<target>/` (`cyclecheck fuzz --write-seeds`): every program of the built-in
/// corpus (the manuals' examples and one program per feature) — as raw bytes for
/// `parse_blocks`, as literal [`CycleInput`]s under its configuration for the structured
/// targets — and, for the structured targets, the plain input of each family and a few
/// fixed-seed random ones, so the fuzzer starts from every family and harness.
pub fn seeds(target: Target) -> Vec<(String, Vec<u8>)> {
    let mut out = Vec::new();
    let mut rng = 0x5eed_f022_u64;
    let mut random_bytes = |n: usize| -> Vec<u8> {
        (0..n)
            .map(|_| {
                rng ^= rng << 13;
                rng ^= rng >> 7;
                rng ^= rng << 17;
                (rng >> 24) as u8
            })
            .collect()
    };
    for p in crate::corpus::PROGRAMS {
        let bytes = match target {
            Target::ParseBlocks => p.text.as_bytes().to_vec(),
            Target::DiffSpecImpl | Target::GcodeRoundtrip => CycleInput::literal_bytes(p.text.as_bytes(), &p.config()),
            Target::ImplInvariants => continue,
        };
        out.push((format!("{}.nc", p.name), bytes));
    }
    match target {
        Target::ParseBlocks => {}
        Target::DiffSpecImpl | Target::GcodeRoundtrip => {
            for (name, first) in [("g76_g78_f76", 0u8), ("g92", 7), ("soup", 11), ("mutant", 12), ("g162", 16), ("g32_g33_g34", 18)] {
                out.push((format!("{name}_plain"), vec![first]));
                for i in 0..6 {
                    let mut bytes = vec![first];
                    bytes.extend(random_bytes(4 * crate::gen::KNOBS));
                    out.push((format!("{name}_random_{i}"), bytes));
                }
            }
        }
        Target::ImplInvariants => {
            // The first draw picks the harness: mode byte 0 (uniform), then the index.
            // Harness 5 has a second draw: 0 trace depths, 1 and 2 the G162 harnesses.
            for (name, head) in [("harness_0", &[0u8, 0][..]), ("harness_1", &[0, 1]), ("harness_2", &[0, 2]), ("harness_3", &[0, 3]),
                ("harness_4", &[0, 4]), ("harness_5", &[0, 5]), ("g162_split", &[0, 5, 0, 1]), ("g162_pitch", &[0, 5, 0, 2])]
            {
                out.push((format!("{name}_plain"), head.to_vec()));
                for i in 0..4 {
                    let mut bytes = head.to_vec();
                    bytes.extend(random_bytes(400));
                    out.push((format!("{name}_random_{i}"), bytes));
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn seeds_pass_and_reach_every_harness_and_family() {
        for t in Target::ALL {
            let seeds = seeds(t);
            assert!(seeds.len() >= 20, "{}: {} seeds", t.name(), seeds.len());
            for (name, bytes) in &seeds {
                t.run(bytes).unwrap_or_else(|e| panic!("{} seed {name}: {e}", t.name()));
            }
        }
        let families: std::collections::BTreeSet<_> =
            seeds(Target::DiffSpecImpl).iter().map(|(_, b)| CycleInput::from_bytes(b).case().family).collect();
        let expected = ["f76", "g162", "g32", "g76", "g78", "g92", "literal", "mutant", "soup"];
        assert_eq!(families.into_iter().collect::<Vec<_>>(), expected);
    }

    #[test]
    fn names_round_trip() {
        for t in Target::ALL {
            assert_eq!(Target::by_name(t.name()), Some(t));
        }
        assert_eq!(Target::by_name("nope"), None);
    }

    #[test]
    fn every_target_passes_on_empty_and_small_inputs() {
        for t in Target::ALL {
            for data in [&b""[..], b"G0 X65 Z5\nG92 X58.7 Z-28 F3\n", &[0xff; 64], &[7; 300]] {
                t.run(data).unwrap_or_else(|e| panic!("{}: {e}", t.name()));
            }
        }
    }

    #[test]
    fn parse_blocks_rejects_with_an_alarm_on_a_line() {
        assert_eq!(parse_blocks(b"G0 X1 Z1\nG92 X#\n"), Ok(()));
    }

    /// A report names the divergence and the program.
    #[test]
    fn a_divergence_report_names_program_and_config() {
        let e = verdict_ok(
            Verdict::Panic { engine: "impl".to_string(), message: "boom".to_string() },
            b"G0 X1",
            &Config::default(),
        )
        .unwrap_err();
        assert!(e.contains("PANIC in the impl engine: boom") && e.contains("program:\nG0 X1"), "{e}");
    }
}
