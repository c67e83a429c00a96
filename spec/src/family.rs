//! One interface for every cycle family (PRJ.SUPPORTED, PRJ.DIALECT, PRJ.WORD, PRJ.MODAL).
//!
//! The shared interpreter ([`crate::program`]) knows the G codes, the modal state, the
//! conflicts, the check order, G00/G01, the position and the feed. Everything a family adds is
//! behind [`Family`]: which G codes select it under which dialects, which words each of its
//! blocks accepts and how each value is read, and the handler that executes a block. Adding a
//! family is its module and one row in the family table ([`FAMILIES`]).

use crate::config::{params, Params};
use crate::emit::Out;
use crate::lex::{Block, Blocks};
use crate::words::Read;
use cycle_vocab::{Alarm, Config, Dialect, Rule};
use std::rc::Rc;

mod table;
pub use table::{rows, select, Row, Selection, FAMILIES, NO_CYCLE};

/// The words a block accepts (besides G N O M S T) and how each is read; any other word is
/// `WORD NOT ALLOWED`, rule PRJ.WORD, except the letters of `refused` (a stricter format than
/// the GSK one), which name `refused.1`.
#[derive(Clone, Copy, Debug)]
pub struct Words {
    pub accepted: &'static [(u8, Read)],
    pub refused: (&'static [u8], Rule),
}

impl Words {
    /// A block that accepts `accepted`.
    pub const fn of(accepted: &'static [(u8, Read)]) -> Words {
        Words { accepted, refused: (&[], Rule::PrjWord) }
    }

    /// How `letter` is read, `None` when the block does not accept it.
    pub fn read(&self, letter: u8) -> Option<Read> {
        self.accepted.iter().find(|(l, _)| *l == letter).map(|(_, r)| *r)
    }

    /// The rule `WORD NOT ALLOWED` names for `letter`.
    pub fn refusal(&self, letter: u8) -> Rule {
        if self.refused.0.contains(&letter) {
            self.refused.1
        } else {
            Rule::PrjWord
        }
    }
}

/// A block as the interpreter hands it to a family.
#[derive(Clone, Copy, Debug)]
pub struct Kind {
    /// The family's code: written in the block, or the modal one.
    pub g: u32,
    /// Whether the block has an axis word X, U, Z or W.
    pub axes: bool,
    /// Whether the block has a P or a Q word (G71.UW: the second block of G71, G72).
    pub pq: bool,
    /// The letters the block writes, bit `letter − 'A'` (G73.FORMAT: I, K or D select format
    /// (b)).
    pub letters: u32,
}

impl Kind {
    /// Whether the block writes a word with this (upper-case) letter.
    pub fn has(&self, letter: u8) -> bool {
        letter.is_ascii_uppercase() && self.letters & (1 << (letter - b'A')) != 0
    }
}

/// What the handler of a block receives besides the machine state.
#[derive(Clone, Copy, Debug)]
pub struct BlockIn<'v> {
    pub kind: Kind,
    /// The motion mode before the block was another one (a modal family starts a new run).
    pub new_run: bool,
    pub values: &'v Values,
    pub line: u32,
}

/// One cycle family's handler; its G codes and dialects are its rows of [`FAMILIES`].
pub trait Family {
    /// Whether its codes are motion modes (PRJ.MODAL): a later block with no motion code runs
    /// the same code again. Otherwise (the default) they are one-shot and leave the motion mode
    /// unchanged (CYC.ONESHOT).
    fn modal(&self) -> bool {
        false
    }
    /// Whether I is threads per inch in its blocks, so that F with I is a `CONFLICT` (COM.LEAD);
    /// by default it is not.
    fn thread(&self) -> bool {
        false
    }
    /// The words a block of this kind accepts under `dialect` (PRJ.WORD, check steps 2 and 3).
    fn words(&self, kind: Kind, dialect: Dialect) -> Words;
    /// Executes a block whose words are allowed and read (check steps 4 and 5, then the moves).
    /// `src` is the program around the block: the contour cycles read their contour from it
    /// (CNT.FIND); every other family ignores it.
    fn execute(&mut self, st: &mut State, b: &BlockIn, src: &mut Source) -> Result<(), Alarm>;
}

/// The program a block stands in, as the interpreter reads it (CNT.FIND, CNT.FLOW, SUB.FIND):
/// the stream of blocks still to come, and the blocks before the one being executed. The main
/// program is its text, lexed as it is read (a cycle that needs the blocks before it lexes the
/// text again); a subprogram run is the subprogram area's blocks, read whole at the call, from
/// its O block on ("the contour blocks … are found in the program (main or subprogram) the cycle
/// block stands in").
pub struct Source<'p> {
    stream: Stream<'p>,
}

enum Stream<'p> {
    /// The main program: the whole text, from its start.
    Main {
        text: &'p [u8],
        blocks: Blocks<'p>,
        /// How many blocks have been handed out; the block being executed is the last of them.
        taken: u64,
    },
    /// One run of a subprogram: the area's blocks, the run starting at `start` (its O block);
    /// `next` is the index of the next block to hand out.
    Subprogram { area: Rc<[Block]>, start: usize, next: usize },
}

impl<'p> Source<'p> {
    /// The main program `text`.
    pub fn new(text: &'p [u8]) -> Source<'p> {
        Source { stream: Stream::Main { text, blocks: Blocks::new(text), taken: 0 } }
    }

    /// SUB.RETURN: a run of the subprogram whose O block is `area[start]`.
    pub fn subprogram(area: Rc<[Block]>, start: usize) -> Source<'p> {
        Source { stream: Stream::Subprogram { area, start, next: start } }
    }

    /// The next block of the program (PRJ.LEX); `None` at its end or after a lexing alarm.
    /// Blocks a cycle takes from here (its contour) are not read again by the interpreter.
    pub fn next_block(&mut self) -> Option<Result<Block, Alarm>> {
        match &mut self.stream {
            Stream::Main { blocks, taken, .. } => {
                let next = blocks.next();
                if matches!(next, Some(Ok(_))) {
                    *taken = taken.saturating_add(1);
                }
                next
            }
            Stream::Subprogram { area, next, .. } => {
                let block = area.get(*next).cloned()?;
                *next += 1;
                Some(Ok(block))
            }
        }
    }

    /// The blocks that stand before the last one handed out, in program order: in the main
    /// program from its start, read again from the text (they were read once without an alarm,
    /// so they read again alike); in a subprogram from its O block.
    pub fn before(&self) -> Box<dyn Iterator<Item = Block> + '_> {
        match &self.stream {
            Stream::Main { text, taken, .. } => {
                let n = usize::try_from(taken.saturating_sub(1)).unwrap_or(usize::MAX);
                Box::new(Blocks::new(text).take(n).map_while(Result::ok))
            }
            Stream::Subprogram { area, start, next } => {
                let end = next.saturating_sub(1).max(*start);
                Box::new(area[*start..end].iter().cloned())
            }
        }
    }
}

/// The values of one block's words, by letter (lengths in increments, leads in lead counts).
#[derive(Clone, Copy, Debug, Default)]
pub struct Values([Option<i64>; 26]);

impl Values {
    fn index(letter: u8) -> Option<usize> {
        letter.is_ascii_uppercase().then(|| (letter - b'A') as usize)
    }
    /// The value of `letter` (upper case), `None` when the block does not write it.
    pub fn get(&self, letter: u8) -> Option<i64> {
        Values::index(letter).and_then(|i| self.0[i])
    }
    pub fn set(&mut self, letter: u8, v: i64) {
        if let Some(i) = Values::index(letter) {
            self.0[i] = Some(v);
        }
    }
}

/// The machine state a family works on (PRJ.MODAL): the trace and position, the modal feed.
pub struct State<'c> {
    pub config: &'c Config,
    pub out: Out<'c>,
    /// The one modal feed / lead value, lead counts (COM.LEAD).
    pub feed: Option<i64>,
    /// NC201.ABSINC: G91 (X and Z are distances from the position before the block).
    pub incremental: bool,
    /// TNRC.CODES: the nose-radius compensation in force.
    pub side: crate::tnrc::Side,
    /// G84.FORMAT: what rigid tapping needs from the blocks before it.
    pub tapping: Tapping,
    /// G50.SMAX, G96.*: the spindle state (docs/INTERPRETATION.md, "Spindle speed").
    pub spindle: crate::spindle::Spindle,
    /// A check the interpreter defers to the end of the block's check step 4 (G96.SMAX: "after
    /// the block's own missing words; before any motion of the block"), raised by
    /// [`State::missing_words_checked`].
    pub deferred: Option<Alarm>,
}

/// The state G84 reads (docs/INTERPRETATION.md, "G83 and G84"): "M29 must have been written in
/// this block or since the last G80/G84 cycle"; "G98, G99 … the project keeps which one is in
/// force (G99 at the start) only for G84's lead". The speed is the spindle state's
/// ([`crate::spindle::Spindle`]).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Tapping {
    /// M29 armed rigid tapping (until G80 or a G84 cycle).
    pub rigid: bool,
    /// G98 (feed per minute) is in force; `false`: G99 (feed per revolution), the start.
    pub per_minute: bool,
}

impl State<'_> {
    /// The parameters of the configuration, each set value or its default.
    pub fn params(&self) -> Params {
        params(self.config)
    }

    /// The current position (X diameter, Z), increments.
    pub fn position(&self) -> (i128, i128) {
        (self.out.x as i128, self.out.z as i128)
    }

    /// Check step 4 ends here: every family calls this right after its own missing-word checks,
    /// before the checks of step 5 and any motion; the interpreter calls it after the block for
    /// blocks that have none. Raises the deferred check (G96.SMAX), once.
    pub fn missing_words_checked(&mut self) -> Result<(), Alarm> {
        match self.deferred.take() {
            Some(a) => Err(a),
            None => Ok(()),
        }
    }

    /// COM.LEAD (M001, M002): F and I set one modal feed value (never both in a thread block:
    /// conflicts).
    pub fn take_lead(&mut self, v: &Values) {
        if let Some(f) = v.get(b'F').or(v.get(b'I')) {
            self.feed = Some(f);
        }
    }

    /// COM.LEAD: F alone sets the modal feed (blocks where I is no lead: G90, G94, G162).
    pub fn take_feed(&mut self, v: &Values) {
        if let Some(f) = v.get(b'F') {
            self.feed = Some(f);
        }
    }

    /// COM.ABSINC (M001, M002): the end point of X(U) and Z(W), `None` for an omitted axis.
    /// NC201.ABSINC (M004): under `nc201`, X and Z are positions (G90) or distances from the
    /// current position (G91).
    pub fn end_point(&self, v: &Values) -> (Option<i128>, Option<i128>) {
        let (px, pz) = self.position();
        if self.config.dialect == Dialect::Nc201 {
            let (bx, bz) = if self.incremental { (px, pz) } else { (0, 0) };
            return (v.get(b'X').map(|x| bx + x as i128), v.get(b'Z').map(|z| bz + z as i128));
        }
        let x = v.get(b'X').map(i128::from).or(v.get(b'U').map(|u| px + u as i128));
        let z = v.get(b'Z').map(i128::from).or(v.get(b'W').map(|w| pz + w as i128));
        (x, z)
    }
}

#[cfg(test)]
mod tests;
