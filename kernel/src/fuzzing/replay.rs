//! The verdicts of the program targets on a decoded case: observing them, checking them
//! against what a committed case expects, and turning a fuzz input into a committed case.

use super::decoded::{Built, Ending, Expect, Lexed, Origin, ProgramCase};
use super::input::Generator;
use super::{gcode_roundtrip_case, parse_blocks, verdict_ok, CycleInput, Target};
use crate::campaign::judge;
use crate::engine::{ImplEngine, SpecEngine};
use cycle_vocab::Config;

/// What the reference's lexer makes of `program` (`parse_blocks` checks the production lexer
/// reads the same).
// Part of a fuzz case's verdict (`parse_blocks`): the lexer is the subject.
#[allow(clippy::disallowed_methods)]
pub fn lexed(program: &[u8]) -> Lexed {
    let mut blocks = 0;
    for block in cycle_spec::lex::blocks(program) {
        match block {
            Ok(_) => blocks += 1,
            Err(a) => return Lexed { blocks, ends: Ending::Alarm(a) },
        }
    }
    Lexed { blocks, ends: Ending::Clean }
}

/// The verdict of `target` on `program` under `config` (the fields the target sets), and the
/// body's report. `None` for `impl_invariants` (it runs in `cycle-proofs`).
pub fn observe(target: Target, program: &[u8], config: &Config) -> Option<(Expect, Result<(), String>)> {
    Some(match target {
        Target::ParseBlocks => {
            let report = parse_blocks(program);
            let expect = Expect { lexer: Some(lexed(program)), passes: Some(report.is_ok()), ..Expect::default() };
            (expect, report)
        }
        Target::DiffSpecImpl => {
            let (reference, verdict, _) = judge((&SpecEngine, &ImplEngine), program, config);
            let report = verdict_ok(verdict, program, config);
            let ends = reference.map(|t| t.alarm.map_or(Ending::Clean, Ending::Alarm));
            (Expect { conform: Some(report.is_ok()), reference_ends: ends, ..Expect::default() }, report)
        }
        Target::GcodeRoundtrip => {
            let report = gcode_roundtrip_case(program, config);
            (Expect { round_trips: Some(report.is_ok()), ..Expect::default() }, report)
        }
        Target::ImplInvariants => return None,
    })
}

fn ending(e: Option<Ending>) -> String {
    e.map_or_else(|| "(no trace: the reference panicked)".to_string(), |e| e.to_string())
}

/// Runs a committed program case and checks its verdict: `Err` names what differs.
pub fn replay(target: Target, program: &[u8], case: &ProgramCase) -> Result<(), String> {
    let config = match (target, case.config) {
        (Target::ParseBlocks, _) => Config::default(),
        (_, Some(c)) => c,
        (_, None) => return Err(format!("{} needs a configuration", target.name())),
    };
    let (seen, report) = observe(target, program, &config).ok_or("impl_invariants cases run in cycle-proofs")?;
    let want = &case.expect;
    if seen == *want {
        return Ok(());
    }
    let mut why = Vec::new();
    if seen.reference_ends != want.reference_ends {
        why.push(format!("the reference now ends {}; the case expects it to end {}", ending(seen.reference_ends), ending(want.reference_ends)));
    }
    if seen.lexer != want.lexer {
        let show = |l: Option<Lexed>| l.map_or("nothing".to_string(), |l| format!("{} blocks, ending {}", l.blocks, l.ends));
        why.push(format!("the lexer now yields {}; the case expects {}", show(seen.lexer), show(want.lexer)));
    }
    let flags = [
        (seen.conform, want.conform, "the engines conform", "the engines diverge"),
        (seen.round_trips, want.round_trips, "the G-code round-trips", "the G-code does not round-trip"),
        (seen.passes, want.passes, "the checks pass", "the checks fail"),
    ];
    for (s, w, yes, no) in flags {
        let say = |b: Option<bool>| b.map_or("(not observed)", |b| if b { yes } else { no });
        if s != w {
            why.push(format!("{}; the case expects: {}", say(s), say(w)));
        }
    }
    let report = report.err().map(|r| format!("\n{r}")).unwrap_or_default();
    Err(format!("{}{report}", why.join("\n")))
}

/// The committed case of a fuzz input of a program target: its program, configuration and
/// generator, with the verdict of [`case_for`]. `None` for `impl_invariants`.
pub fn regression(target: Target, data: &[u8], origin: Origin) -> Option<(Vec<u8>, ProgramCase)> {
    let (program, config, built) = match target {
        Target::ParseBlocks => (data.to_vec(), None, None),
        Target::ImplInvariants => return None,
        Target::DiffSpecImpl | Target::GcodeRoundtrip => {
            let input = CycleInput::from_bytes(data);
            let case = input.case();
            let built = match input {
                CycleInput::Built { generator, knobs, .. } => Some(built(generator, &knobs)),
                CycleInput::Literal { .. } => None,
            };
            (case.program, Some(case.config), built)
        }
    };
    let case = case_for(target, &program, config, origin, built)?;
    Some((program, case))
}

/// A committed case of `program`, expecting what it must: the target's checks pass, and the
/// reference's ending and the lexer's outcome are as observed in this build. `None` for
/// `impl_invariants`.
pub fn case_for(target: Target, program: &[u8], config: Option<Config>, origin: Origin, built: Option<Built>) -> Option<ProgramCase> {
    let (mut expect, _) = observe(target, program, &config.unwrap_or_default())?;
    for pass in [&mut expect.conform, &mut expect.round_trips, &mut expect.passes] {
        if pass.is_some() {
            *pass = Some(true);
        }
    }
    Some(ProgramCase { config, expect, origin, built })
}

/// The provenance of a knob-built program, trailing zero knobs left out.
pub fn built(generator: Generator, knobs: &[u32]) -> Built {
    let len = knobs.iter().rposition(|&k| k != 0).map_or(0, |i| i + 1);
    Built { family: generator.name().to_string(), knobs: knobs[..len].to_vec() }
}

#[cfg(test)]
mod tests;
