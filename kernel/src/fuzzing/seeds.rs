//! The built-in seeds of the program targets, decoded (`fuzz/seeds/<target>/`, written by
//! `cyclecheck fuzz --write-seeds`), and their encoding as libFuzzer inputs
//! (`fuzz/corpus/<target>/`, not committed).
//!
//! The seeds: every program of the built-in corpus (the manuals' examples and one program per
//! feature) under its configuration and, for the structured targets, the plain case of each
//! generator family and a few built from fixed-seed random knobs and readings, so the fuzzer
//! starts from every family and every declared reading.

use super::decoded::{Origin, ProgramCase};
use super::replay::{built, case_for};
use super::{CycleInput, Target};
use super::input::{literal_bits, literal_config, Generator};
use crate::gen::{self, KNOBS};
use crate::registry::FAMILIES;

/// The generators seeded: every registry family's, then word soup, corpus mutants and thread
/// cases with operator scripts. A seed is named after its generator ([`Generator::name`]).
fn generators() -> Vec<Generator> {
    let families = FAMILIES.iter().map(Generator::Family);
    families.chain([Generator::Soup, Generator::Mutant, Generator::Operator]).collect()
}

fn origin(target: Target, what: String) -> Origin {
    Origin { target: target.name().to_string(), found_by: format!("built-in seed: {what}"), date: None }
}

/// The built-in seeds of a program target, decoded: (name, program, case). Empty for
/// `impl_invariants` (its seeds are `cycle_proofs::invariants::seeds`).
pub fn seeds(target: Target) -> Vec<(String, Vec<u8>, ProgramCase)> {
    let mut out = Vec::new();
    if target == Target::ImplInvariants {
        return out;
    }
    for p in crate::corpus::PROGRAMS {
        let config = (target != Target::ParseBlocks).then(|| p.config());
        if config.is_some_and(|c| c != literal_config(literal_bits(&c))) {
            continue; // no literal input carries its readings or parameters
        }
        let origin = origin(target, format!("corpus program {}", p.name));
        out.extend(case_for(target, p.text.as_bytes(), config, origin, None).map(|c| (p.name.to_string(), p.text.as_bytes().to_vec(), c)));
    }
    if target == Target::ParseBlocks {
        return out;
    }
    let mut rng = 0x5eed_f022_u64;
    for generator in generators() {
        let name = generator.name();
        let mut add = |seed: String, knobs: Vec<u32>, readings: u8| {
            let mut case = gen::build(generator.builder(), &knobs);
            case.config.readings = crate::readings::from_bits(readings);
            let origin = origin(target, format!("generator {name}, {seed}"));
            let c = case_for(target, &case.program, Some(case.config), origin, Some(built(generator, &knobs)));
            out.extend(c.map(|c| (format!("{name}_{seed}"), case.program, c)));
        };
        add("plain".to_string(), Vec::new(), 0);
        for i in 0..6 {
            let knobs = (0..KNOBS)
                .map(|_| {
                    rng ^= rng << 13;
                    rng ^= rng >> 7;
                    rng ^= rng << 17;
                    (rng >> 16) as u32
                })
                .collect();
            // Random seeds run under readings of their own: the fuzzer starts from each value.
            add(format!("random_{i}"), knobs, (rng >> 8) as u8 & 63);
        }
    }
    out
}

/// The libFuzzer input of a decoded program case: the program itself for `parse_blocks`; for
/// the structured targets the generator's input when its family and knobs still build exactly
/// this program and configuration, else a literal input when its configuration fits one.
pub fn encode(target: Target, program: &[u8], case: &ProgramCase) -> Result<Vec<u8>, String> {
    let config = match (target, case.config) {
        (Target::ParseBlocks, _) => return Ok(program.to_vec()),
        (Target::ImplInvariants, _) => return Err("impl_invariants cases are encoded by cycle-proofs".to_string()),
        (_, None) => return Err(format!("{} needs a configuration", target.name())),
        (_, Some(c)) => c,
    };
    let same = |bytes: &[u8]| {
        let c = CycleInput::from_bytes(bytes).case();
        c.program == program && c.config == config
    };
    if let Some(b) = &case.built {
        // The first byte that selects the family, then each knob as four bytes.
        let first = (0..=u8::MAX).find(|&x| {
            matches!(CycleInput::from_bytes(&[x]), CycleInput::Built { generator, .. } if generator.name() == b.family)
        });
        if let Some(first) = first {
            let mut bytes = vec![first];
            bytes.extend(b.knobs.iter().flat_map(|k| k.to_le_bytes()));
            // The readings byte follows every knob (the missing ones written as 0).
            let readings = crate::readings::bits(&config.readings);
            if readings != 0 {
                bytes.extend(std::iter::repeat_n(0u8, 4 * KNOBS.saturating_sub(b.knobs.len())));
                bytes.push(readings);
            }
            if same(&bytes) {
                return Ok(bytes);
            }
        }
    }
    let literal = CycleInput::literal_bytes(program, &config);
    if same(&literal) {
        return Ok(literal);
    }
    Err(format!(
        "no {} input encodes this case: its generator no longer builds it, and a literal input cannot carry its configuration {}",
        target.name(),
        serde_json::to_string(&config).unwrap_or_default()
    ))
}

#[cfg(test)]
mod tests;
