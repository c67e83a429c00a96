//! The structured input of `diff_spec_impl` and `gcode_roundtrip`: a cycle command built with
//! `arbitrary` from the fuzzer's bytes.
//!
//! Mostly a generator and the knobs of `crate::gen` (the proptest generators'
//! deterministic builders), so the fuzzer and the proptest campaigns share one description of
//! the input space: most programs legal, many on the edges the rules turn on (Δd against Δdmin
//! and k − d with exact ties, tapers, internal threads, inch and ISC grids, multi-start, every
//! infeed and depth mode, FANUC G76, words just outside their ranges). Each four bytes are one
//! knob; past the end of the input every knob is 0, the ordinary choice, so short inputs are
//! plain programs and a mutated byte changes one decision.
//!
//! Sometimes a literal program under a chosen configuration instead: the manuals' examples
//! enter the seed corpus this way, and libFuzzer's byte mutations of them reach programs no
//! builder writes.
//!
//! The declared readings (`crate::readings::from_bits`, one bit per reading, 0 the letter): a
//! built input's byte after its knobs, a literal input's byte after its configuration byte when
//! that has bit 5 set. Inputs written before the readings (shorter, bit 5 clear) run under the
//! letter, as they did.

use crate::gen::{self, Case, KNOBS};
use crate::registry::{self, Family, FAMILIES};
use arbitrary::{Arbitrary, Unstructured};
use cycle_vocab::{Config, Dialect, Grid, Increment, Units};

/// A cycle command: built from knobs, or literal.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CycleInput {
    /// `readings`: the bits of the declared readings (`crate::readings::from_bits`).
    Built { generator: Generator, knobs: Vec<u32>, readings: u8 },
    /// A program under the configuration of `literal_config` `config`, with the readings of
    /// `readings`.
    Literal { config: u8, readings: u8, program: Vec<u8> },
}

/// A knob-built generator of `crate::gen`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Generator {
    /// A registry family's.
    Family(&'static Family),
    /// G76, G78 or FANUC G76, the first knob choosing (`gen::multipass::any`).
    Multipass,
    /// Word soup.
    Soup,
    /// A corpus program with a few bytes changed.
    Mutant,
    /// A thread family's case with an operator script (`gen::operator::build`).
    Operator,
}

impl Generator {
    /// Its name in a committed case's provenance (`built.family`): the registry family's name,
    /// `multipass`, `soup` or `mutant`.
    pub fn name(self) -> &'static str {
        match self {
            Generator::Family(f) => f.name,
            Generator::Multipass => "multipass",
            Generator::Soup => "soup",
            Generator::Mutant => "mutant",
            Generator::Operator => "operator",
        }
    }

    pub(crate) fn builder(self) -> gen::Builder {
        match self {
            Generator::Family(f) => f.build,
            Generator::Multipass => gen::multipass::any,
            Generator::Soup => gen::garbage::soup,
            Generator::Mutant => gen::garbage::mutant,
            Generator::Operator => gen::operator::build,
        }
    }
}

/// The first byte, modulo 20 plus the families added since ([`added_families`]): 0–6
/// G76/G78/FANUC G76, 7–10 G92, 11 word soup, 12 corpus mutant, 13–15 literal, 16–17 G162 under
/// `nc201`, 18–19 G32/G33/G34, then one byte per added family in registry order, then the
/// `operator` generator (a thread case with an operator script). Bytes keep
/// their meaning as families are added (the committed seeds' first bytes are < 20; 16–19 came
/// after the first seeds, the same way).
const FIRST_BYTES: u8 = 20;
const LITERAL: u8 = 13;

/// Bit 5 of a literal input's configuration byte: a readings byte follows it.
const READINGS_FOLLOW: u8 = 32;
/// The bits of a readings byte that choose readings (one per reading).
const READING_BITS: u8 = (1 << cycle_vocab::Readings::NAMES.len()) - 1;

/// The families the first 20 bytes build as themselves (bytes 0–6 build G76, G78 and FANUC G76
/// through the multipass generator, so those three get bytes of their own after the 20).
const FIRST_FAMILIES: [&str; 3] = ["g92", "g162", "g32"];

/// The registry families past the first 20 bytes, in registry order.
fn added_families() -> Vec<&'static Family> {
    FAMILIES.iter().filter(|f| !FIRST_FAMILIES.contains(&f.name)).collect()
}

/// The family named `name` (one of [`FIRST_FAMILIES`]).
fn family(name: &str) -> Generator {
    Generator::Family(registry::find(name).expect("the first bytes' families are registered"))
}

/// The configuration of a literal program: bit 0 FANUC, bit 1 inch, bit 2 ISC, bit 3 `nc201`
/// (before bit 0), bit 4 `x_radius` = 1 (NC201.XMODE; other dialects alarm on it). Bits 5–7 are
/// ignored here (bit 5 of the input's byte says a readings byte follows).
pub fn literal_config(bits: u8) -> Config {
    let units = if bits & 2 != 0 { Units::Inch } else { Units::Metric };
    let increment = if bits & 4 != 0 { Increment::Isc } else { Increment::Isb };
    let dialect = match (bits & 8 != 0, bits & 1 != 0) {
        (true, _) => Dialect::Nc201,
        (false, true) => Dialect::Fanuc,
        (false, false) => Dialect::Gsk,
    };
    let mut config = Config { dialect, grid: Grid { units, increment }, ..Config::default() };
    if bits & 16 != 0 {
        config.params.x_radius = Some(1);
    }
    config
}

/// The bits of [`literal_config`] for a configuration with default parameters (but `x_radius`).
pub fn literal_bits(config: &Config) -> u8 {
    u8::from(config.dialect == Dialect::Fanuc)
        | if config.grid.units == Units::Inch { 2 } else { 0 }
        | if config.grid.increment == Increment::Isc { 4 } else { 0 }
        | if config.dialect == Dialect::Nc201 { 8 } else { 0 }
        | if config.params.x_radius == Some(1) { 16 } else { 0 }
}

impl<'a> Arbitrary<'a> for CycleInput {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<CycleInput> {
        let added = added_families();
        let operator = FIRST_BYTES + u8::try_from(added.len()).unwrap_or(0);
        let generator = match u.int_in_range(0..=operator)? {
            0..=6 => Generator::Multipass,
            7..=10 => family("g92"),
            11 => Generator::Soup,
            12 => Generator::Mutant,
            13..=15 => {
                let byte = u.arbitrary::<u8>()?;
                let readings = if byte & READINGS_FOLLOW != 0 { u.arbitrary::<u8>()? & READING_BITS } else { 0 };
                let program = u.bytes(u.len())?.to_vec();
                return Ok(CycleInput::Literal { config: byte & 31, readings, program });
            }
            16 | 17 => family("g162"),
            18 | 19 => family("g32"),
            n if n == operator => Generator::Operator,
            n => Generator::Family(added[usize::from(n - FIRST_BYTES)]),
        };
        let knobs = (0..KNOBS).map(|_| u.arbitrary::<u32>()).collect::<arbitrary::Result<Vec<u32>>>()?;
        let readings = u.arbitrary::<u8>()? & READING_BITS;
        Ok(CycleInput::Built { generator, knobs, readings })
    }
}

impl CycleInput {
    /// Reads the input from fuzz bytes (any bytes make an input).
    pub fn from_bytes(data: &[u8]) -> CycleInput {
        CycleInput::arbitrary_take_rest(Unstructured::new(data))
            .unwrap_or(CycleInput::Built { generator: Generator::Multipass, knobs: vec![0; KNOBS], readings: 0 })
    }

    /// The fuzz bytes of a literal program under `config` (dialect, grid, readings; the seed
    /// corpus).
    pub fn literal_bytes(program: &[u8], config: &Config) -> Vec<u8> {
        let readings = crate::readings::bits(&config.readings);
        let mut out = vec![LITERAL, literal_bits(config)];
        if readings != 0 {
            out[1] |= READINGS_FOLLOW;
            out.push(readings);
        }
        out.extend_from_slice(program);
        out
    }

    /// The program and configuration the input describes.
    pub fn case(&self) -> Case {
        match self {
            CycleInput::Built { generator, knobs, readings } => {
                let mut case = gen::build(generator.builder(), knobs);
                case.config.readings = crate::readings::from_bits(*readings);
                case
            }
            CycleInput::Literal { config, readings, program } => {
                let config = Config { readings: crate::readings::from_bits(*readings), ..literal_config(*config) };
                Case { family: "literal", program: program.clone(), config }
            }
        }
    }
}

#[cfg(test)]
mod tests;
