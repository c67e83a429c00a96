//! G76 (M001, and FANUC-style under `fanuc`, M003) and G78 (M000) as a family of the
//! interpreter: one-shot codes whose first block is kept per code (G76.FORMAT).

use super::{check_p_digits, expand, Cycle, FirstBlock, SecondBlock};
use crate::family::{BlockIn, Family, Kind, Source, State, Words};
use crate::lex::Number;
use crate::words::{alarm, integer, Read, F, I_TPI, N, U, W, X, Z};
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Rule};

/// The first-block memory of G76 and of G78 (kept separately), and G78's modal J and K.
#[derive(Debug, Default)]
pub struct Multipass {
    first76: FirstBlock,
    first78: FirstBlock,
    pull78: KeptPullout,
}

/// G78.PULLOUT (M000, `000_…` lines 59 and 61: J and K "模态指令", modal): the J and the K of the
/// last G78 second block that wrote each, kept for the whole program, apart from G92's. G76's J
/// and K are not kept (OPEN: M001 does not call them modal).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct KeptPullout {
    pub j: Option<i64>,
    pub k: Option<i64>,
}

impl KeptPullout {
    /// A G78 second block's J and K: each word written replaces the kept one; the values the
    /// block uses are the kept ones after that.
    pub fn take(&mut self, j: Option<i64>, k: Option<i64>) -> (Option<i64>, Option<i64>) {
        self.j = j.or(self.j);
        self.k = k.or(self.k);
        (self.j, self.k)
    }
}

/// G76.FORMAT / G78.MODE / F76.FORMAT: P(m)(r)(a) of a first block, six digits without a
/// point, then its digits checked.
fn p_digits_of(cycle: Cycle, n: &Number, letter: u8, config: &Config, line: u32) -> Result<i64, Alarm> {
    let p = integer(n, letter, 0, 999_999, Rule::ComRanges, line)?;
    check_p_digits(cycle, p, config.dialect, line)?;
    Ok(p)
}

const P76: Read = Read::Own(|n, letter, config, line| p_digits_of(Cycle::G76, n, letter, config, line));
const P78: Read = Read::Own(|n, letter, config, line| p_digits_of(Cycle::G78, n, letter, config, line));
/// Q(Δdmin), unsigned (F76.MICRONS under `fanuc`); R(d), E unsigned lengths; L 1…999.
const Q_MIN: (u8, Read) = (b'Q', Read::Microns { lo: 0, hi: N });
const R_D: (u8, Read) = (b'R', Read::Length { lo: 0, hi: N });
const E: (u8, Read) = (b'E', Read::Length { lo: 0, hi: N });
const L: (u8, Read) = (b'L', Read::Integer { lo: 1, hi: 999, rule: Rule::ComRanges });

/// First blocks: `G76 P Q R D L E`, D = e 0…2 (G76.MODE); `G78 P Q R D L E`, D = depth mode
/// 0…1 (G78.DEPTHMODE); FANUC G76: P Q R only, D L E refused under F76.FORMAT.
const FIRST76: Words = Words::of(&[(b'D', Read::Integer { lo: 0, hi: 2, rule: Rule::G76Mode }), E, L, (b'P', P76), Q_MIN, R_D]);
const FIRST78: Words =
    Words::of(&[(b'D', Read::Integer { lo: 0, hi: 1, rule: Rule::G78DepthMode }), E, L, (b'P', P78), Q_MIN, R_D]);
const FIRST_F76: Words = Words { accepted: &[(b'P', P76), Q_MIN, R_D], refused: (b"DLE", Rule::F76Format) };

/// Second blocks: X(U) Z(W) R(i) P(k) Q(Δd) J K F(I); R signed; P, Q 1…N (F76.MICRONS); J, K
/// unsigned. FANUC G76: J and K refused under F76.FORMAT.
const R_I: (u8, Read) = (b'R', Read::Length { lo: -N, hi: N });
const P_K: (u8, Read) = (b'P', Read::Microns { lo: 1, hi: N });
const Q_DD: (u8, Read) = (b'Q', Read::Microns { lo: 1, hi: N });
const PULL: Read = Read::Length { lo: 0, hi: N };
const SECOND: Words = Words::of(&[F, I_TPI, (b'J', PULL), (b'K', PULL), P_K, Q_DD, R_I, U, W, X, Z]);
const SECOND_F76: Words = Words { accepted: &[F, I_TPI, P_K, Q_DD, R_I, U, W, X, Z], refused: (b"JK", Rule::F76Format) };

fn cycle_of(g: u32) -> Cycle {
    if g == 78 {
        Cycle::G78
    } else {
        Cycle::G76
    }
}

impl Family for Multipass {
    fn thread(&self) -> bool {
        true
    }

    /// G76.FORMAT (M001): a block without X, U, Z, W is the first block, with any of them the
    /// second.
    fn words(&self, kind: Kind, dialect: Dialect) -> Words {
        let fanuc = dialect == Dialect::Fanuc;
        match (cycle_of(kind.g), kind.axes) {
            (Cycle::G76, false) if fanuc => FIRST_F76,
            (Cycle::G76, false) => FIRST76,
            (Cycle::G78, false) => FIRST78,
            (Cycle::G76, true) if fanuc => SECOND_F76,
            (_, true) => SECOND,
        }
    }

    fn execute(&mut self, st: &mut State, b: &BlockIn, _: &mut Source) -> Result<(), Alarm> {
        let cycle = cycle_of(b.kind.g);
        if b.kind.axes {
            self.second_block(st, cycle, b)
        } else {
            self.first_block(cycle, b);
            Ok(())
        }
    }
}

impl Multipass {
    /// G76.FORMAT (M001) / G78.FORMAT (M000): a first block replaces that code's memory;
    /// omitted words fall back to their defaults again.
    fn first_block(&mut self, cycle: Cycle, b: &BlockIn) {
        let v = b.values;
        let mem = FirstBlock {
            p: v.get(b'P'),
            q_min: v.get(b'Q'),
            r_finish: v.get(b'R'),
            d_mode: v.get(b'D'),
            l_starts: v.get(b'L'),
            e_leadin: v.get(b'E'),
        };
        match cycle {
            Cycle::G76 => self.first76 = mem,
            Cycle::G78 => self.first78 = mem,
        }
    }

    /// G76.FORMAT (M001) / G78.FORMAT (M000) second block, G76.REQUIRED (M001): missing words
    /// (lead F, then P, then Q), then the cycle.
    fn second_block(&mut self, st: &mut State, cycle: Cycle, b: &BlockIn) -> Result<(), Alarm> {
        let (v, line) = (b.values, b.line);
        st.take_lead(v);
        let Some(lead) = st.feed else {
            return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
        };
        let Some(k) = v.get(b'P') else {
            return Err(alarm(AlarmCode::MissingWord, b'P', Rule::G76Required, line));
        };
        let Some(dd) = v.get(b'Q') else {
            return Err(alarm(AlarmCode::MissingWord, b'Q', Rule::G76Required, line));
        };
        st.missing_words_checked()?;
        let (j, k_pull) = match cycle {
            Cycle::G76 => (v.get(b'J'), v.get(b'K')),
            Cycle::G78 => self.pull78.take(v.get(b'J'), v.get(b'K')),
        };
        let a = st.position();
        let (x, z) = st.end_point(v);
        let second = SecondBlock {
            a,
            d: (x.unwrap_or(a.0), z.unwrap_or(a.1)),
            i: v.get(b'R').unwrap_or(0) as i128,
            k,
            dd,
            j,
            k_pull,
            lead,
            line,
        };
        let first = match cycle {
            Cycle::G76 => self.first76,
            Cycle::G78 => self.first78,
        };
        expand(cycle, &first, &second, st.config, &mut st.out)
    }
}
