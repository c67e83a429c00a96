//! G50 — setting the work coordinates (M003), under `gsk` and `fanuc`.
//!
//! `G50 [X] [Z] [S]` declares where the tool is: the current position becomes (X, Z), and the
//! trace's coordinates from then on are these work coordinates (G50.COORD). No motion and no
//! event. G50 is one-shot: the motion mode does not change and a G92/G90/G94 run goes on. `G50
//! S` (spindle limit) changes no geometry (G50.SMAX).

use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::words::{X, Z};
use cycle_vocab::{Alarm, Dialect};

/// G50 as a family of the interpreter: a one-shot code without moves.
#[derive(Debug, Default)]
pub struct G50;

/// G50.COORD (M003): X and Z, absolute only, |v| ≤ N (COM.RANGES); "U, W and every other word
/// but S are `WORD NOT ALLOWED`" (S, like G N O M T, every block takes).
const WORDS: Words = Words::of(&[X, Z]);

impl Family for G50 {
    fn words(&self, _: Kind, _: Dialect) -> Words {
        WORDS
    }

    /// G50.COORD (M003): "X and Z … make the current position (X, Z)"; an omitted axis keeps
    /// its coordinate.
    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        set_position(st, b.values.get(b'X'), b.values.get(b'Z'));
        Ok(())
    }
}

/// G50.COORD (M003): the current position becomes the written coordinates, without an event.
pub fn set_position(st: &mut State, x: Option<i64>, z: Option<i64>) {
    if let Some(x) = x {
        st.out.x = x;
    }
    if let Some(z) = z {
        st.out.z = z;
    }
}
