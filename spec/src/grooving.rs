//! What G74 (face peck drilling / grooving) and G75 (OD grooving) share (M003): one cycle
//! written once over a **peck axis** p and a **step axis** q — G74: pecks along Z, columns
//! stepped in X; G75: "the other way round: the pecks go along X (Δi, a radius), the grooves
//! step in Z (Δk)" (docs/INTERPRETATION.md, "G74 … and G75"). Each code's family unit, formats
//! and kept first block are in [`crate::g74`] and [`crate::g75`].
//!
//! Check order: (4) no feed → `MISSING WORD F` (COM.LEAD); (5) no peck travel (GEOMETRY), no
//! peck (MISSING WORD), step travel without a step (MISSING WORD), then the pecks of all
//! columns against `max_passes` — all before any motion. Then the columns ([`emit`]).

use crate::contour::Point;
use crate::emit::Out;
use crate::family::{BlockIn, State, Words};
use crate::stock_removal::{counts_per_length, half_units};
use crate::words::{alarm, Read, F, N, U, W, X, Z};
use cycle_vocab::readings::G75Relief;
use cycle_vocab::{Alarm, AlarmCode, PassKind, Rule};

/// Which of the two cycles: its axes, words and rules.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Axes {
    G74,
    G75,
}

/// "Values. … P, Q: lengths 0 … N; e, Δd: lengths 0 … N (unsigned: a negative value is `OUT OF
/// RANGE`, COM.RANGES)"; G74.UNITS: "P (Δi) and Q (Δk) are ordinary lengths in every dialect".
const LENGTH: Read = Read::Length { lo: 0, hi: N };

/// G74.FORMAT, G75.FORMAT (M003, OPEN): the first block, "words R only: e".
pub const FIRST: Words = Words::of(&[(b'R', LENGTH)]);

/// G74.FORMAT, G75.FORMAT (M003, OPEN): "Second block words X U Z W P Q R F S T" (R = Δd).
pub const SECOND: Words = Words::of(&[F, (b'P', LENGTH), (b'Q', LENGTH), (b'R', LENGTH), U, W, X, Z]);

/// G74.FORMAT (M003, OPEN): "A block with any of X U Z W P Q is the second block (R = Δd
/// there), otherwise the first".
pub fn words(second: bool) -> Words {
    if second {
        SECOND
    } else {
        FIRST
    }
}

/// The rules of one code: (FORMAT, PECK, the return by e, COLUMN, RELIEF).
struct Rules {
    format: Rule,
    peck: Rule,
    back: Rule,
    column: Rule,
    relief: Rule,
}

impl Axes {
    /// The peck coordinate p of a point (G74 Z, G75 X).
    fn p(self, pt: Point) -> i128 {
        match self {
            Axes::G74 => pt.1,
            Axes::G75 => pt.0,
        }
    }
    /// The step coordinate q of a point (G74 X, G75 Z).
    fn q(self, pt: Point) -> i128 {
        match self {
            Axes::G74 => pt.0,
            Axes::G75 => pt.1,
        }
    }
    /// The point (X, Z) with peck coordinate `p` and step coordinate `q`.
    fn point(self, p: i128, q: i128) -> Point {
        match self {
            Axes::G74 => (q, p),
            Axes::G75 => (p, q),
        }
    }
    /// The address letters of the peck and the step axes.
    fn letters(self) -> (u8, u8) {
        match self {
            Axes::G74 => (b'Z', b'X'),
            Axes::G75 => (b'X', b'Z'),
        }
    }
    /// The words of the peck length and the step length: G74 Q (Δk) and P (Δi); G75 P (Δi)
    /// and Q (Δk).
    fn peck_and_step_words(self) -> (u8, u8) {
        match self {
            Axes::G74 => (b'Q', b'P'),
            Axes::G75 => (b'P', b'Q'),
        }
    }
    fn rules(self) -> Rules {
        match self {
            Axes::G74 => Rules {
                format: Rule::G74Format,
                peck: Rule::G74Peck,
                back: Rule::G74E,
                column: Rule::G74Column,
                relief: Rule::G74Relief,
            },
            Axes::G75 => Rules {
                format: Rule::G75Format,
                peck: Rule::G75Peck,
                back: Rule::G75Peck,
                column: Rule::G75Column,
                relief: Rule::G75Relief,
            },
        }
    }
}

/// One checked cycle, every length in counts of its axis (X on the diameter count).
#[derive(Clone, Copy, Debug)]
struct Cycle {
    ax: Axes,
    /// A, the start; E, the end point ("an omitted axis = A's").
    a: Point,
    e: Point,
    /// One peck along p: G74 Δk, G75 2Δi ("G75 likewise along X with diameter steps 2Δi").
    peck: i128,
    /// One step along q: G74 2Δi, G75 Δk.
    step: i128,
    /// The return after a peck along p: G74 e, G75 2e.
    back: i128,
    /// The relief along q at a column's bottom: G74 2Δd, G75 Δd (magnitude).
    relief: i128,
    /// Its direction on q (−1, +1; 0 with no step travel): [`relief_direction`].
    relief_dir: i128,
    feed: i64,
    line: u32,
}

/// The second block (M003): "No feed at all → `MISSING WORD F` (COM.LEAD, step 4)"; then the
/// checks of step 5 in order; then the columns. `e` is the code's kept return (else 5139).
pub fn second_block(ax: Axes, e: Option<i64>, st: &mut State, b: &BlockIn) -> Result<(), Alarm> {
    let (v, line) = (b.values, b.line);
    st.take_feed(v);
    let Some(feed) = st.feed else {
        return Err(alarm(AlarmCode::MissingWord, b'F', Rule::ComLead, line));
    };
    st.missing_words_checked()?;
    let params = st.params();
    let a = st.position();
    let (ex, ez) = st.end_point(v);
    let end = (ex.unwrap_or(a.0), ez.unwrap_or(a.1));
    let (p_letter, q_letter) = ax.letters();
    let (peck_word, step_word) = ax.peck_and_step_words();
    let length = |w: u8, letter: u8| i128::from(v.get(w).unwrap_or(0)) * counts_per_length(letter);
    let cy = Cycle {
        ax,
        a,
        e: end,
        peck: length(peck_word, p_letter),
        step: length(step_word, q_letter),
        back: i128::from(e.unwrap_or(params.p5139_peck_return)) * counts_per_length(p_letter),
        relief: length(b'R', q_letter),
        relief_dir: relief_direction(ax, (ax.q(end) - ax.q(a)).signum(), st.config.readings.g75_relief),
        feed,
        line,
    };
    check(&cy)?;
    // PRJ.MAXPASS: "the pecks of all columns together > `max_passes` is `TOO MANY PASSES` on Q
    // (G74) / P (G75) — before any motion".
    if pecks(&cy) * columns(&cy) > i128::from(params.max_passes) {
        return Err(alarm(AlarmCode::TooManyPasses, peck_word, Rule::PrjMaxPass, line));
    }
    emit(&cy, &mut st.out)
}

/// "Checks (step 5), in order. G74: no Z travel (E.z = A.z) is `GEOMETRY` on Z, rule
/// G74.FORMAT; Δk = 0 (Q omitted or 0) is `MISSING WORD Q`, rule G74.PECK; X travel with Δi = 0
/// is `MISSING WORD P`, rule G74.COLUMN. G75: no X travel is `GEOMETRY` on X, rule G75.FORMAT;
/// Δi = 0 is `MISSING WORD P`, rule G75.PECK; Z travel with Δk = 0 is `MISSING WORD Q`, rule
/// G75.COLUMN."
fn check(cy: &Cycle) -> Result<(), Alarm> {
    let (ax, r, line) = (cy.ax, cy.ax.rules(), cy.line);
    let (p_letter, _) = ax.letters();
    let (peck_word, step_word) = ax.peck_and_step_words();
    if ax.p(cy.e) == ax.p(cy.a) {
        return Err(alarm(AlarmCode::Geometry, p_letter, r.format, line));
    }
    if cy.peck == 0 {
        return Err(alarm(AlarmCode::MissingWord, peck_word, r.peck, line));
    }
    if ax.q(cy.e) != ax.q(cy.a) && cy.step == 0 {
        return Err(alarm(AlarmCode::MissingWord, step_word, r.column, line));
    }
    Ok(())
}

/// The direction of the relief on the step axis, σ being the step direction (sign of E.q − A.q).
/// G74.RELIEF (OPEN): "against the step (−σ·2Δd …)". G75.RELIEF (declared reading `g75.relief`;
/// `003_…` line 143: "在槽底沿-Z方向的退刀量"): the letter `minus-z`, toward −Z whatever σ;
/// `against-step`, −σ as FANUC/ADTECH draw it.
pub fn relief_direction(ax: Axes, sigma: i128, reading: G75Relief) -> i128 {
    match (ax, reading) {
        (Axes::G75, G75Relief::MinusZ) => -1,
        (Axes::G74, _) | (Axes::G75, G75Relief::AgainstStep) => -sigma,
    }
}

/// The number of pecks in one column: ⌈|E.p − A.p| / peck⌉.
fn pecks(cy: &Cycle) -> i128 {
    let travel = (cy.ax.p(cy.e) - cy.ax.p(cy.a)).abs();
    (travel + cy.peck - 1) / cy.peck
}

/// The number of columns: "without X travel one column at A.x (P has no effect)"; else one at
/// A and one per step, the last exactly at E: 1 + ⌈|E.q − A.q| / step⌉.
fn columns(cy: &Cycle) -> i128 {
    let travel = (cy.ax.q(cy.e) - cy.ax.q(cy.a)).abs();
    if travel == 0 {
        1
    } else {
        1 + (travel + cy.step - 1) / cy.step
    }
}

/// The stops from `from` toward `to` by `step` (> 0), `from` excluded: from + σ·k·step for
/// k = 1, 2, … while short of `to`, then `to` itself ("the last exactly at E"). Empty when
/// `from` = `to`.
pub(crate) fn stops(from: i128, to: i128, step: i128) -> impl Iterator<Item = i128> {
    let sigma = (to - from).signum();
    let inner = (1..).map(move |k| from + sigma * k * step).take_while(move |&v| sigma * (to - v) > 0);
    inner.chain((from != to).then_some(to))
}

/// G74.COLUMN, G74.PECK, G74.RELIEF (M003, OPEN; G75 mirrored): for each column j, "Pass
/// headers. One per column: index j + 1, kind ROUGH, diameter_depth = the depth of the pecks
/// (G74: 2·|E.z − A.z| …; G75: |E.x − A.x|)"; the pecks; "At the bottom of every column but
/// the first" the relief; "a rapid along the peck axis back to A's …; then a rapid along the
/// step axis to the next column …; after the last column, a rapid along the step axis back to
/// A. The tool ends at A."
fn emit(cy: &Cycle, out: &mut Out) -> Result<(), Alarm> {
    let (ax, a, line, r) = (cy.ax, cy.a, cy.line, cy.ax.rules());
    let (p_letter, _) = ax.letters();
    let depth = (ax.p(cy.e) - ax.p(a)).abs() * half_units(p_letter);
    let columns = core::iter::once(ax.q(a)).chain(stops(ax.q(a), ax.q(cy.e), cy.step));
    let mut j: u32 = 0;
    for q in columns {
        j += 1;
        out.pass(j, PassKind::Rough, depth, r.column, line)?;
        if j > 1 {
            // "then a rapid along the step axis to the next column" — after its header, as every
            // cycle's pass header comes before the pass's first move.
            let to = ax.point(ax.p(a), q);
            out.rapid(to.0, to.1, r.column, line)?;
        }
        pecks_of_column(cy, q, out)?;
        let mut at_q = q;
        if j > 1 {
            // G74.RELIEF: "a rapid by Δd in X against the step (−σ·2Δd …)"; G75.RELIEF by Δd in Z,
            // the way `relief_direction` says.
            at_q = q + cy.relief_dir * cy.relief;
            let bottom = ax.point(ax.p(cy.e), at_q);
            out.rapid(bottom.0, bottom.1, r.relief, line)?;
        }
        let up = ax.point(ax.p(a), at_q);
        out.rapid(up.0, up.1, r.column, line)?;
    }
    // "after the last column, a rapid along the step axis back to A."
    out.rapid(a.0, a.1, r.column, line)?;
    Ok(())
}

/// G74.PECK (M003, OPEN): "In a column, from A.z toward E.z (direction c): peck i ends at
/// A.z + c·i·Δk, the last exactly at E.z. Each peck is one feed (at F) from where the tool
/// stands to its end; after every peck but the last, a rapid back by e (to the peck's end −
/// c·e)." G75: along X, pecks of 2Δi, returns of 2e.
fn pecks_of_column(cy: &Cycle, q: i128, out: &mut Out) -> Result<(), Alarm> {
    let (ax, a, line, r) = (cy.ax, cy.a, cy.line, cy.ax.rules());
    let (from, to) = (ax.p(a), ax.p(cy.e));
    let c = (to - from).signum();
    for p in stops(from, to, cy.peck) {
        let end = ax.point(p, q);
        out.feed(end.0, end.1, cy.feed, r.peck, line)?;
        if p != to {
            let back = ax.point(p - c * cy.back, q);
            out.rapid(back.0, back.1, r.back, line)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests;
