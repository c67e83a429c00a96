//! Operator scripts on thread-cycle cases (OP.SCRIPT; issue #22's campaigns).
//!
//! A case is a thread family's generated case (G92, G76, G78, FANUC G76, G162) with a script
//! placed on its **uninterrupted** trace U, which the reference expands once to see where the
//! moves are (placing needs U's indices; the judgement is still the two engines' traces). Holds
//! and resets land on thread moves, pull-outs (a cut's last thread move), rapids and feeds, at
//! the fractions that matter — 0, 1, the first and the last increment, halfway — or anywhere;
//! single block is switched on before a pass header or any event; No.0018 bit 6 is 0 or 1; now
//! and then a hold goes anywhere, a pass header or past the end (OP.AT, OP.REACH).

use super::{knobs, Case, Dice};
use crate::registry::Family;
use cycle_vocab::{Action, Along, Event, MoveKind, Script};
use proptest::prelude::*;

/// The thread families a script is placed on.
pub const FAMILIES: &[&str] = &["g92", "g76", "g78", "f76", "g162"];

/// Scripted cases drawn from `families` (those of [`FAMILIES`] among them; the caller passes at
/// least one).
pub fn strategy(families: Vec<&'static Family>) -> BoxedStrategy<Case> {
    let families: Vec<&'static Family> = families.into_iter().filter(|f| FAMILIES.contains(&f.name)).collect();
    super::drawn((knobs(), knobs()).prop_map(move |(base, script)| {
        let mut dice = Dice::new(&script);
        let family = dice.one_of(&families);
        scripted(super::build(family.build, &base), &mut dice)
    }))
}

/// A scripted case from one set of knobs (the fuzz input's `operator` generator): the first
/// knob picks the family, the next 128 build its case, the rest place the script.
pub fn build(dice: &mut Dice) -> Case {
    let name = dice.one_of(FAMILIES);
    let family = crate::registry::find(name).expect("the thread families are registered");
    let case = (family.build)(&mut dice.fork(128));
    scripted(case, dice)
}

/// `case` with a script placed on its uninterrupted trace, and No.0018 bit 6 drawn; its
/// generator is then `operator`.
pub fn scripted(mut case: Case, dice: &mut Dice) -> Case {
    case.family = "operator";
    case.config.params.no18_bit6_hold = Some(dice.below(2) as i64);
    let u = cycle_spec::expand(&case.program, &case.config);
    case.config.operator = place(&u.events, case.config.start_x, case.config.start_z, dice);
    case
}

/// A script of one to three episodes at increasing places of `events` (U).
pub fn place(events: &[Event], start_x: i64, start_z: i64, dice: &mut Dice) -> Script {
    let moves = spans(events, start_x, start_z);
    let mut script = Script::EMPTY;
    if moves.is_empty() {
        return script;
    }
    let mut from = 0;
    for _ in 0..1 + dice.below(3) {
        let mut d = dice.fork(8);
        let pick = moves.iter().filter(|m| m.index >= from).count();
        if pick == 0 {
            break;
        }
        let m = moves.iter().filter(|m| m.index >= from).nth(d.below(pick as u64) as usize).copied();
        let Some(m) = m else { break };
        let at = Along { event: m.index as u32, num: 0, den: 1 };
        let at = fraction(at, m.length, &mut d);
        let actions: Vec<Action> = match d.weighted(&[12, 2, 4, 1]) {
            0 => {
                let mut a = vec![Action::Hold(at)];
                if !d.chance(10) {
                    a.push(Action::Start);
                }
                a
            }
            1 => vec![Action::Reset(at)],
            2 => {
                let before = d.below(events.len() as u64) as u32;
                vec![Action::SingleBlock { on: !d.chance(20), before: before.max(from as u32) }]
            }
            // Anywhere, past the end included: a pass header (OP.AT) or never reached (OP.REACH).
            _ => vec![Action::Hold(Along { event: d.below(events.len() as u64 + 3) as u32, ..at })],
        };
        for a in actions {
            if script.push(a).is_err() {
                return script;
            }
        }
        from = m.index;
    }
    script
}

/// A move of U: its index, kind and length in increments along its longer axis.
#[derive(Clone, Copy, Debug)]
struct Span {
    index: usize,
    length: u64,
}

fn spans(events: &[Event], start_x: i64, start_z: i64) -> Vec<Span> {
    let (mut x, mut z) = (start_x, start_z);
    let mut out = Vec::new();
    for (index, e) in events.iter().enumerate() {
        if let Event::Move(m) = e {
            if matches!(m.kind, MoveKind::Rapid | MoveKind::Feed | MoveKind::Thread) {
                out.push(Span { index, length: m.x.abs_diff(x).max(m.z.abs_diff(z)) });
            }
            (x, z) = (m.x, m.z);
        }
    }
    out
}

/// A fraction of a move `length` increments long: 0, 1, the first or last increment, halfway,
/// or any.
fn fraction(at: Along, length: u64, d: &mut Dice) -> Along {
    let den = u32::try_from(length.clamp(1, u64::from(cycle_vocab::operator::ALONG_DEN_MAX))).unwrap_or(1);
    let (num, den) = match d.weighted(&[2, 2, 2, 2, 3, 5]) {
        0 => (0, 1),
        1 => (1, 1),
        2 => (1.min(den), den),
        3 => (den.saturating_sub(1), den),
        4 => (1, 2),
        _ => {
            let den = d.range(1, 1_000_000) as u32;
            (d.range(0, i64::from(den)) as u32, den)
        }
    };
    Along { num, den, ..at }
}
