//! The modal interpreter (PRJ.MODAL, PRJ.WORD, PRJ.SUPPORTED, PRJ.DIALECT, COM.ABSINC,
//! COM.LEAD): blocks in, trace events out.
//!
//! Shared by every family: the position, the motion mode (G00, G01 or a modal family's code),
//! the modal feed/lead, and under `nc201` the G90/G91 mode (docs/INTERPRETATION.md, "Program
//! and modal state", "The `nc201` dialect"). Each cycle family keeps its own modal memory and
//! is reached through [`crate::family::Family`].
//!
//! Check order within a block (docs/INTERPRETATION.md): (1) lexing (done by the spec's own
//! reader, [`crate::lex`]); (2) G and M codes supported, then conflicts (two motion codes;
//! G90/G91; X/U, Z/W, F/I in thread blocks, none under `nc201`), then words allowed in
//! alphabetical order; (3) each word's value in alphabetical order; (4) missing words and
//! (5) the cycle's own checks, in the family's handler. M98 / M99 blocks ([`crate::sub`]) and
//! the spindle state ([`crate::spindle`]) are the interpreter's too.

use crate::emit::{Out, Sink};
use crate::family::{self, BlockIn, Family, Kind, Selection, Source, State, Values, Words};
use crate::lex::{Block, Number};
use crate::operator::note::{scope_of_cycle, Scope};
use crate::spindle;
use crate::step2::{conflicts, two_motion_codes, words_allowed, ALWAYS};
use crate::sub::{self, Call, SubCode};
use crate::tnrc::{self, Side};
use crate::words::{alarm, Read, F, U, W, X, Z};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Rule, Units};

/// The modal motion mode (PRJ.MODAL).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Motion {
    G00,
    G01,
    /// G02 (clockwise) or G03: ARC.DIR.
    Arc { cw: bool },
    /// A modal family's code: its row's index in [`family::rows`] and the code.
    Family(usize, u32),
}

/// A motion or cycle code written in a block.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Code {
    G00,
    G01,
    /// G02 (clockwise) or G03.
    Arc { cw: bool },
    /// A family's code: its row's index in [`family::rows`] and the code.
    Family(usize, u32),
}

/// What follows a block (PRJ.MODAL, SUB.*).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Flow {
    /// The next block of the same program.
    Next,
    /// M02 / M30: the program ends (in the main program or a subprogram).
    End,
    /// M98: a call, checked at steps 2–4 (the call's own checks are [`crate::sub`]'s).
    Call(Call),
    /// M99: the end of one run of the subprogram.
    Return,
}

/// The M code of a block, as it bears on the flow.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum MCode {
    /// None, or one without effect on the flow.
    Other,
    /// M02, M30.
    End,
    /// M98, M99.
    Sub(SubCode),
}

/// The machine between blocks.
pub struct Machine<'c> {
    pub st: State<'c>,
    motion: Motion,
    /// The handler of each row of [`family::rows`], by its index.
    families: Vec<Box<dyn Family>>,
    /// SUB.RETURN: a subprogram is running (M99 is its end, not `UNSUPPORTED`).
    pub in_subprogram: bool,
}

/// G00 / G01 words: X U Z W F; under `nc201` X Z F (NC201.ABSINC: U and W are no incremental
/// addresses).
const LINEAR: Words = Words::of(&[F, U, W, X, Z]);
const LINEAR_NC201: Words = Words::of(&[F, X, Z]);

impl<'c> Machine<'c> {
    /// PRJ.MODAL (PRJ): the machine starts at the configured start point, in G00, with no feed.
    pub fn new(config: &'c Config, sink: Sink<'c>) -> Machine<'c> {
        let out = Out::new(config.start_x, config.start_z, sink);
        let st = State {
            config,
            out,
            feed: None,
            incremental: false,
            side: Side::Off,
            tapping: Default::default(),
            spindle: Default::default(),
            deferred: None,
        };
        Machine { st, motion: Motion::G00, families: family::rows().map(|row| (row.handler)()).collect(), in_subprogram: false }
    }

    /// Whether the sink of the trace asked to stop (PRJ.TRACE).
    pub fn stopped(&self) -> bool {
        self.st.out.stopped()
    }

    /// Executes one block; `src` is the program around it (the contour cycles read from it).
    /// Returns what follows it: the next block, the program's end (M02, M30), a call (M98) or
    /// a return (M99).
    pub fn block(&mut self, b: &Block, src: &mut Source) -> Result<Flow, Alarm> {
        let dialect = self.st.config.dialect;
        let (codes, m) = self.codes(b)?;
        // The block's kind: its written code, else the modal motion mode.
        let code = codes.first().copied().unwrap_or(self.modal_code());
        self.st.out.note_block(b.line, scope(code));
        two_motion_codes(b, dialect, codes.len())?;
        let writes_arc = codes.iter().any(|c| matches!(c, Code::Arc { .. }));
        self.st.side = tnrc::check(b, writes_arc, self.st.side, self.st.params().nose_radius)?;
        conflicts(b, dialect, self.thread_block(code), matches!(code, Code::Arc { .. }))?;
        if let MCode::Sub(sub) = m {
            // SUB.CALL, SUB.RETURN: an M98 / M99 block runs no motion and sets no state.
            return sub::block(b, sub);
        }
        let words = self.words(b, code);
        words_allowed(b, &words)?;
        let values = self.values(b, &words)?;
        self.absolute_or_incremental(b);
        self.tapping_state(b);
        self.spindle_state(b, &values);
        match code {
            Code::Family(index, g) => {
                let new_run = self.motion != Motion::Family(index, g);
                let family = &mut self.families[index];
                // CYC.ONESHOT: a one-shot family (G70–G75, G83, G84) leaves the motion mode —
                // and so a G92/G90/G94 run — as it was before the block.
                if family.modal() {
                    self.motion = Motion::Family(index, g);
                }
                let kind = kind_of(b, g);
                family.execute(&mut self.st, &BlockIn { kind, new_run, values: &values, line: b.line }, src)?;
            }
            Code::G01 => self.linear(b, true, &values)?,
            Code::G00 => self.linear(b, false, &values)?,
            Code::Arc { cw } => {
                self.motion = Motion::Arc { cw };
                crate::arc::block(&mut self.st, &values, cw, has_axis(b), b.line)?;
            }
        }
        // A block whose handler has no missing-word check of its own ends step 4 here.
        self.st.missing_words_checked()?;
        Ok(if m == MCode::End { Flow::End } else { Flow::Next })
    }

    /// The modal motion mode as the code a block without one runs.
    fn modal_code(&self) -> Code {
        match self.motion {
            Motion::G00 => Code::G00,
            Motion::G01 => Code::G01,
            Motion::Arc { cw } => Code::Arc { cw },
            Motion::Family(index, g) => Code::Family(index, g),
        }
    }

    /// PRJ.SUPPORTED (PRJ), COM.UNITS (M000, M001), PRJ.DIALECT (PRJ): every G and M code of the
    /// block is supported. G00 and G01; under `nc201` G90 and G91 (NC201.ABSINC); each family's
    /// codes under its dialects (another dialect's code is refused under PRJ.DIALECT); the
    /// no-motion codes. G163 under `nc201` is refused by its own rule. Returns the motion/cycle
    /// codes written, in order, and the block's M code as it bears on the flow.
    fn codes(&self, b: &Block) -> Result<(Vec<Code>, MCode), Alarm> {
        let line = b.line;
        let config = self.st.config;
        let nc201 = config.dialect == Dialect::Nc201;
        let mut motion = Vec::new();
        for g in b.g_codes() {
            let unsupported = alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjSupported, line);
            // A G with a decimal point (G1.0, G92.1) or a sign is not a supported code.
            let Some(g) = code_value(g) else { return Err(unsupported) };
            let code = match g {
                0 => Some(Code::G00),
                1 => Some(Code::G01),
                // ARC.FORMAT (M003): arcs are codes of `gsk` and `fanuc`.
                2 | 3 if nc201 => return Err(alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, line)),
                2 | 3 => Some(Code::Arc { cw: g == 2 }),
                90 | 91 if nc201 => None,
                g => match family::select(g, config.dialect) {
                    // A row's code is a u32.
                    Selection::Row(index) => Some(Code::Family(index, g as u32)),
                    Selection::OtherDialect => return Err(alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, line)),
                    Selection::None => match g {
                        18 | 40 | 97 | 99 => None,
                        // G50.SMAX, TNRC.CODES (M003): no-motion codes of `gsk` and `fanuc`.
                        41 | 42 | 96 | 98 if nc201 => {
                            return Err(alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, line));
                        }
                        41 | 42 | 96 | 98 => None,
                        // G80 (M003): a no-motion code of `gsk` and `fanuc` ("every code of this
                        // section is `UNSUPPORTED CODE`" under `nc201`).
                        80 if nc201 => return Err(alarm(AlarmCode::UnsupportedCode, b'G', Rule::PrjDialect, line)),
                        80 => None,
                        // G163 (M004, `004_…` lines 79–89): the seed names the tapping / die cycle
                        // but not its table or motion; under `nc201` it is refused by rule G163.
                        163 if nc201 => return Err(alarm(AlarmCode::UnsupportedCode, b'G', Rule::G163, line)),
                        20 | 21 => {
                            // COM.UNITS: the grid of a trace is fixed for the whole program.
                            let wanted = if g == 20 { Units::Inch } else { Units::Metric };
                            if wanted != config.grid.units {
                                return Err(alarm(AlarmCode::Unsupported, b'G', Rule::ComUnits, line));
                            }
                            None
                        }
                        _ => return Err(unsupported),
                    },
                },
            };
            motion.extend(code);
        }
        let mut flow = MCode::Other;
        if let Some(m) = b.get(b'M') {
            if m.point {
                return Err(alarm(AlarmCode::NotInteger, b'M', Rule::ComRanges, line));
            }
            let Some(m) = code_value(m).filter(|&m| m <= 99) else {
                return Err(alarm(AlarmCode::UnsupportedCode, b'M', Rule::PrjSupported, line));
            };
            flow = match m {
                // PRJ.MODAL: M02 and M30 end the program.
                2 | 30 => MCode::End,
                98 => MCode::Sub(SubCode::Call),
                // SUB.RETURN: "M99 in the main program is `UNSUPPORTED` on M (FANUC restarts the
                // main program endlessly: no finite trace)".
                99 if !self.in_subprogram => return Err(alarm(AlarmCode::Unsupported, b'M', Rule::SubReturn, line)),
                99 => MCode::Sub(SubCode::Return),
                _ => MCode::Other,
            };
        }
        Ok((motion, flow))
    }

    /// COM.LEAD: whether the block, by its written or modal code, is a thread block.
    fn thread_block(&self, code: Code) -> bool {
        match code {
            Code::Family(index, _) => self.families[index].thread(),
            Code::G00 | Code::G01 | Code::Arc { .. } => false,
        }
    }

    /// PRJ.WORD (PRJ): the words the block's kind accepts.
    fn words(&self, b: &Block, code: Code) -> Words {
        let dialect = self.st.config.dialect;
        match code {
            Code::Family(index, g) => self.families[index].words(kind_of(b, g), dialect),
            Code::Arc { .. } => crate::arc::WORDS,
            _ if dialect == Dialect::Nc201 => LINEAR_NC201,
            _ => LINEAR,
        }
    }

    /// COM.UNITS, COM.RANGES, COM.LEAD (M000, M001, M002), PRJ.DIALECT (PRJ): each word's
    /// value, in alphabetical order, read as the block's word table says; under `gsk` and
    /// `fanuc` S as the spindle section says (G50.SMAX: an integer, the maximum's range).
    fn values(&self, b: &Block, words: &Words) -> Result<Values, Alarm> {
        let mut v = Values::default();
        for letter in b.letters() {
            if let (b'S', Some(n)) = (letter, b.get(b'S')) {
                if self.st.config.dialect != Dialect::Nc201 {
                    v.set(b'S', spindle::s_value(n, spindle::writes_g50(b), b.line)?);
                }
                continue;
            }
            if ALWAYS.contains(&letter) {
                continue;
            }
            let (Some(n), Some(read)) = (b.get(letter), words.read(letter)) else {
                // Not reachable: words_allowed refused every other letter.
                return Err(alarm(AlarmCode::WordNotAllowed, letter, Rule::PrjWord, b.line));
            };
            v.set(letter, Read::value(read, n, letter, self.st.config, b.line)?);
        }
        Ok(v)
    }

    /// NC201.ABSINC (M004): G90 / G91 written in the block set the mode, for this block on.
    fn absolute_or_incremental(&mut self, b: &Block) {
        if self.st.config.dialect != Dialect::Nc201 {
            return;
        }
        for g in b.g_codes() {
            match code_value(g) {
                Some(90) => self.st.incremental = false,
                Some(91) => self.st.incremental = true,
                _ => {}
            }
        }
    }

    /// G84.FORMAT, G80 (`Rule::G80`), G50.SMAX (M003): what rigid tapping reads from the blocks before it —
    /// G98 / G99 written set the feed mode ("the project keeps which one is in force (G99 at
    /// the start) only for G84's lead"); G80 "ends an M29 not followed by G84"; M29 "arms rigid
    /// tapping" (an M29 written with G80 arms: the G80 ends only an earlier one). The speed is
    /// the spindle state's ([`Machine::spindle_state`]). Contour blocks never come here
    /// (CNT.MODAL: they change no machine state).
    fn tapping_state(&mut self, b: &Block) {
        let t = &mut self.st.tapping;
        for g in b.g_codes() {
            match code_value(g) {
                Some(98) => t.per_minute = true,
                Some(99) => t.per_minute = false,
                Some(80) => t.rigid = false,
                _ => {}
            }
        }
        if b.get(b'M').and_then(code_value) == Some(29) {
            t.rigid = true;
        }
    }

    /// G96.SMAX, G96.SPEED, G50.SMAX (M003), under `gsk` and `fanuc`: whether the block writes
    /// G96 with no maximum from an earlier block (deferred to the end of check step 4), then the
    /// block's G96 / G97 and S. Contour blocks never come here (CNT.MODAL).
    fn spindle_state(&mut self, b: &Block, v: &Values) {
        if self.st.config.dialect == Dialect::Nc201 {
            return;
        }
        self.st.deferred = self.st.spindle.smax_missing(b);
        self.st.spindle.take(b, v.get(b'S'));
    }

    /// G00 / G01 (PRJ.MODAL, PRJ): one move to the end point, both axes together; G01 at the modal
    /// feed (COM.LEAD: `MISSING WORD F` when a G01 block moves with no feed set). Then G96.SMAX
    /// (the end of step 4) and, for a G00 block with axis words, G96.RAPID.
    fn linear(&mut self, b: &Block, feed: bool, v: &Values) -> Result<(), Alarm> {
        self.st.take_lead(v);
        let moving = has_axis(b);
        if feed && moving && self.st.feed.is_none() {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, b.line));
        }
        self.st.missing_words_checked()?;
        if !feed && moving {
            self.st.spindle.rapid(self.st.config.readings.g96_rapid, b.line)?;
        }
        self.motion = if feed { Motion::G01 } else { Motion::G00 };
        if !moving {
            return Ok(());
        }
        let (x, z) = self.st.end_point(v);
        let (px, pz) = self.st.position();
        let (x, z) = (x.unwrap_or(px), z.unwrap_or(pz));
        match (feed, self.st.feed) {
            (true, Some(f)) => self.st.out.feed(x, z, f, Rule::PrjModal, b.line),
            _ => self.st.out.rapid(x, z, Rule::PrjModal, b.line),
        }
    }
}

/// The kind of a family's block: its code, whether it has axis words, and whether P or Q.
fn kind_of(b: &Block, g: u32) -> Kind {
    let letters = b.letters().iter().filter(|l| l.is_ascii_uppercase()).fold(0u32, |m, &l| m | 1 << (l - b'A'));
    Kind { g, axes: has_axis(b), pq: b.has(b'P') || b.has(b'Q'), letters }
}

/// OP.SCOPE (PRJ): the operator scope of a block by its code — plain `G00`/`G01`, a thread
/// cycle G92, G76, G78, G162, or any other block.
fn scope(code: Code) -> Scope {
    match code {
        Code::G00 | Code::G01 => Scope::Plain,
        Code::Arc { .. } => Scope::Other,
        Code::Family(_, g) => scope_of_cycle(g),
    }
}

/// Whether the block has an axis word X, U, Z or W.
fn has_axis(b: &Block) -> bool {
    b.has(b'X') || b.has(b'U') || b.has(b'Z') || b.has(b'W')
}

/// PRJ.SUPPORTED: the value of a G or M code, `None` when it has a decimal point or a sign (no
/// code) or more digits than any code.
pub fn code_value(n: &Number) -> Option<u64> {
    if n.point || n.negative {
        return None;
    }
    if n.digits.is_empty() {
        return Some(0);
    }
    n.digits.parse().ok()
}
