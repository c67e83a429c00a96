//! The bodies of the program fuzz targets (`fuzz/fuzz_targets/*.rs` are a few lines each), so
//! the same code runs under libFuzzer, in `cargo test` (which replays the committed seeds and
//! regression cases, `tests/tests/fuzz_replay.rs`), in `cyclecheck gate` and in `cyclecheck
//! fuzz`. The fourth target, `impl_invariants`, runs the proof harness bodies
//! (`cycle_proofs::invariants`); its committed cases are read, written and replayed by
//! [`invariants`].
//!
//! Each body takes the fuzzer's raw bytes and returns `Err` with a report — the conformance
//! relation's rich divergence, or the broken property — when the case fails; the targets panic
//! with that report so libFuzzer prints it and saves the input.
//!
//! | target | input | checks |
//! |---|---|---|
//! | `parse_blocks` | any bytes as a program | the lexer ends, one alarm at most, on a line of the program; both engines expand it under two configurations without a panic, reject it with an alarm on a line of the program, and conform (a rejection is the same alarm in both) |
//! | `diff_spec_impl` | [`CycleInput`]: a generator family and its knobs | spec and impl conform ([`crate::conformance::check`]) |
//! | `gcode_roundtrip` | [`CycleInput`] | canonical expanded G-code of either engine reads back ([`crate::readback`]) as the same motions: kind, end point, feed or lead, angle, lead change |
//!
//! Committed cases are stored decoded ([`decoded`]): [`replay`] checks their verdicts,
//! [`seeds`] holds the built-in seeds and encodes them for libFuzzer.

pub mod committed;
pub mod decoded;
pub mod invariants;
mod input;
pub mod replay;
pub mod seeds;

pub use input::CycleInput;

use crate::campaign::{judge, Verdict};
use crate::engine::{Engine, ImplEngine, SpecEngine};
use crate::readback::{self, Printed};
use cycle_vocab::{Alarm, Config, Dialect, Grid, Increment, Rule, Units};

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

    /// The targets whose bodies are here (not `impl_invariants`).
    pub const PROGRAMS: [Target; 3] = [Target::ParseBlocks, Target::DiffSpecImpl, Target::GcodeRoundtrip];

    pub fn by_name(name: &str) -> Option<Target> {
        Target::ALL.into_iter().find(|t| t.name() == name)
    }

    /// Runs the target's body on one input; `impl_invariants` is not run here (its body is
    /// `cycle_proofs::invariants::fuzz`).
    pub fn run(self, data: &[u8]) -> Result<(), String> {
        match self {
            Target::ParseBlocks => parse_blocks(data),
            Target::DiffSpecImpl => diff_spec_impl(data),
            Target::GcodeRoundtrip => gcode_roundtrip(data),
            Target::ImplInvariants => Err("impl_invariants runs in cycle-proofs (cycle_proofs::invariants::fuzz)".to_string()),
        }
    }
}

/// The configurations `parse_blocks` runs under: the default, and FANUC on the inch ISC grid.
fn parse_configs() -> [Config; 2] {
    let inch_isc = Grid { units: Units::Inch, increment: Increment::Isc };
    [Config::default(), Config { dialect: Dialect::Fanuc, grid: inch_isc, ..Config::default() }]
}

/// A block as both lexers can state it: its line, and its words — the G words in the order
/// written, the others alphabetically — each as sign, significant digits, decimals and point.
type Read = Result<(u32, String), Alarm>;

fn block_text(line: u32, words: impl Iterator<Item = (u8, bool, String, u32, bool)>) -> (u32, String) {
    let mut s = String::new();
    for (letter, negative, digits, decimals, point) in words {
        let sign = if negative { "-" } else { "" };
        let point = if point { "." } else { "" };
        s.push_str(&format!(" {}{sign}{digits}e-{decimals}{point}", letter as char));
    }
    (line, s)
}

/// The reference lexer's reading of a program (`cycle_spec::lex`), block by block.
// The fuzz body that checks the lexers themselves: its subject is the reading.
#[allow(clippy::disallowed_methods)]
fn spec_reading(data: &[u8]) -> Vec<Read> {
    cycle_spec::lex::blocks(data)
        .map(|b| {
            b.map(|b| {
                let word = |l: u8, n: &cycle_spec::lex::Number| (l, n.negative, n.digits.clone(), n.decimals, n.point);
                let g = b.g_codes().map(|n| word(b'G', n)).collect::<Vec<_>>();
                let rest = b.letters().into_iter().filter_map(|l| b.get(l).map(|n| word(l, n))).collect::<Vec<_>>();
                block_text(b.line, g.into_iter().chain(rest))
            })
        })
        .collect()
}

/// The production lexer's reading of a program (`cycle_impl::lex`), block by block.
fn impl_reading(data: &[u8]) -> Vec<Read> {
    let mut blocks = cycle_impl::lex::Blocks::new(data);
    let mut out = Vec::new();
    let mut block = cycle_impl::lex::Block::new();
    loop {
        match blocks.read(&mut block) {
            Ok(false) => return out,
            Err(a) => {
                out.push(Err(a));
                return out;
            }
            Ok(true) => {
                let word = |l: u8, n: cycle_impl::number::Number| {
                    let digits = if n.mantissa == 0 { String::new() } else { n.mantissa.to_string() };
                    (l, n.negative, digits, u32::from(n.decimals), n.point)
                };
                let g = block.g_codes().iter().map(|n| word(b'G', *n)).collect::<Vec<_>>();
                let rest = block.letters().filter_map(|l| block.get(l).map(|n| word(l, n))).collect::<Vec<_>>();
                out.push(Ok(block_text(block.line, g.into_iter().chain(rest))));
            }
        }
    }
}

/// `parse_blocks`: arbitrary bytes as a program (PRJ.LEX, PRJ.WORD).
pub fn parse_blocks(data: &[u8]) -> Result<(), String> {
    let lines = data.iter().filter(|&&b| b == b'\n').count() + 1;
    let on_a_line = |line: u32| (1..=lines).contains(&(line as usize));
    // The two lexers read the same blocks, words and numbers, and stop at the same alarm.
    let (reference, production) = (spec_reading(data), impl_reading(data));
    if let Some(i) = (0..reference.len().max(production.len())).find(|&i| reference.get(i) != production.get(i)) {
        return Err(format!(
            "the lexers differ at block {}: reference {:?}, production {:?}\nprogram:\n{}",
            i + 1,
            reference.get(i),
            production.get(i),
            String::from_utf8_lossy(data)
        ));
    }
    // The reading itself: each block on a line of the program, at most one alarm (a lexical
    // one, PRJ.LEX / PRJ.WORD, on a line of the program), and it is last.
    if reference.len() > data.len() + 1 {
        return Err("the lexer yields more blocks than the program has bytes".to_string());
    }
    for (i, block) in reference.iter().enumerate() {
        match block {
            Ok((line, _)) if !on_a_line(*line) => return Err(format!("a block on line {line} of {lines}")),
            Ok(_) => {}
            Err(a) if !matches!(a.rule, Rule::PrjLex | Rule::PrjWord) || !on_a_line(a.line) => {
                return Err(format!("lexical alarm {a:?} (rule or line wrong, {lines} lines)"));
            }
            Err(_) if i + 1 != reference.len() => return Err("the lexer goes on after its alarm".to_string()),
            Err(_) => {}
        }
    }
    // Both engines: no panic, a rejection is an alarm on a line of the program, and they agree.
    for config in parse_configs() {
        let (reference, verdict, _) = judge((&SpecEngine, &ImplEngine), data, &config);
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
pub(crate) fn verdict_ok(verdict: Verdict, program: &[u8], config: &Config) -> Result<(), String> {
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
    let (_, verdict, _) = judge((&SpecEngine, &ImplEngine), &case.program, &case.config);
    verdict_ok(verdict, &case.program, &case.config).map_err(|e| format!("family {}\n{e}", case.family))
}

/// `gcode_roundtrip`: canonical expanded G-code of each engine, read back, gives its motions.
pub fn gcode_roundtrip(data: &[u8]) -> Result<(), String> {
    let case = CycleInput::from_bytes(data).case();
    gcode_roundtrip_case(&case.program, &case.config)
}

/// The round trip of `program` under `config`.
pub(crate) fn gcode_roundtrip_case(program: &[u8], config: &Config) -> Result<(), String> {
    let engines: [&dyn Engine; 2] = [&SpecEngine, &ImplEngine];
    for engine in engines {
        let trace = engine.expand(program, config);
        let text = trace.to_gcode();
        let context = || format!("engine {}, program:\n{}\nG-code:\n{text}", engine.name(), String::from_utf8_lossy(program));
        let (grid, motions) = readback::read(text.as_bytes()).map_err(|e| format!("{e}\n{}", context()))?;
        if grid != trace.grid {
            return Err(format!("grid {grid:?} read back as {:?}\n{}", trace.grid, context()));
        }
        let expected: Vec<Printed> = trace.events.iter().filter_map(Printed::of).collect();
        if let Some(i) = (0..expected.len().max(motions.len())).find(|&i| expected.get(i) != motions.get(i)) {
            return Err(format!("event {i}: {:?} read back as {:?}\n{}", expected.get(i), motions.get(i), context()));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
