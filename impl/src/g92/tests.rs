//! G92's cycle at the edges of i64 (lib.rs "Magnitudes": beyond 2^62 the arithmetic saturates,
//! never wraps): C.x = D.x + 2R past i64 (saturated, the side taken from the exact value), W
//! past i64 (saturated), and step ③'s X past i64 (G92.PATH). The expected values are worked from
//! the register's formulas (COM.SIDE, G92.FORMAT, G92.PULLOUT, G92.PATH) in exact arithmetic.
extern crate std;

use super::*;
use crate::config::DEFAULTS;
use cycle_vocab::{Event, Move};
use std::vec::Vec;

/// 0.1 mm: No.19 = 10 tenths of it is c = 100 increments, so JK.1 gives K = 100 and
/// J = round(100·tan 45°) = 100 (No.5131 = 45).
const LEAD: i64 = 1_000;
const LINE: u32 = 7;

/// The events of one G92 cycle from `a` to `end` with taper `r`, no J or K (JK.1).
fn run(a: (i64, i64), end: (i64, i64), r: i64) -> Result<Vec<Event>, Alarm> {
    let st = G92State { end, r, index: 1, ..G92State::new() };
    let mut c = cycle(&Config::default(), &DEFAULTS, &st, &mut PullMemo::default(), a, LEAD, LINE)?;
    let mut pos = a;
    Ok(core::iter::from_fn(|| c.next_event(&mut pos)).collect())
}

fn header(depth: i64) -> Event {
    Event::Pass(Pass { index: 1, kind: PassKind::Rough, diameter_depth: depth, rule: Rule::G92Path })
}

fn rapid(x: i64, z: i64) -> Event {
    Event::Move(Move::rapid(x, z, Rule::G92Path))
}

fn thread(x: i64, z: i64, rule: Rule) -> Event {
    Event::Move(Move::thread(x, z, LEAD, 0, rule))
}

/// C.x = D.x + 2R beyond i64 on either side: C.x saturates, the side is the exact one, and the
/// depth |A.x − C.x| saturates. Z is the long axis (|W| = 1 000 > |R| = 100): the pull-out
/// starts K = 100 before the end on Z at X = end + 2·round(R·K/|W|) = end ± 20 and ends at
/// X = end + 2·s·J = end ∓ 200.
#[test]
fn c_x_beyond_i64_saturates_with_the_exact_side() {
    // D.x + 2R = i64::MAX + 50: s = sign(0 − C.x) = −1.
    let d = (i64::MAX - 150, -1_000);
    let want = [
        header(i64::MAX),
        rapid(i64::MAX, 0),
        thread(d.0 + 20, -900, Rule::G92Path),
        thread(d.0 - 200, -1_000, Rule::G92Pullout),
        rapid(0, -1_000),
        rapid(0, 0),
    ];
    assert_eq!(run((0, 0), d, 100), Ok(want.to_vec()));
    // D.x + 2R = i64::MIN − 50: s = +1; |0 − C.x| = 2^63 saturates to i64::MAX.
    let d = (i64::MIN + 150, -1_000);
    let want = [
        header(i64::MAX),
        rapid(i64::MIN, 0),
        thread(d.0 - 20, -900, Rule::G92Path),
        thread(d.0 + 200, -1_000, Rule::G92Pullout),
        rapid(0, -1_000),
        rapid(0, 0),
    ];
    assert_eq!(run((0, 0), d, -100), Ok(want.to_vec()));
}

/// W = D.z − A.z beyond i64 saturates to i64::MAX: not 0 (no G92.FORMAT alarm), and K = 100
/// stays below that travel (no G92.PULLOUT alarm); the pull-out is Z-long with R = 0.
#[test]
fn w_beyond_i64_saturates() {
    let a = (10_000, i64::MIN + 500);
    let want = [
        header(5_000),
        rapid(5_000, a.1),
        thread(5_000, 900, Rule::G92Path),
        thread(5_200, 1_000, Rule::G92Pullout),
        rapid(10_000, 1_000),
        rapid(10_000, a.1),
    ];
    assert_eq!(run(a, (5_000, 1_000), 0), Ok(want.to_vec()));
}

/// Step ③'s X₃ = D.x + 2·s·J beyond i64: it lies past A.x on the side s (G92.PATH, on J: D.x
/// itself is on A's side), on either side.
#[test]
fn x3_beyond_i64_departs() {
    let departs = Err(Alarm::new(AlarmCode::Geometry, Some(b'J'), Rule::G92Path, LINE));
    assert_eq!(run((i64::MAX, 0), (i64::MAX - 100, -1_000), 0), departs);
    assert_eq!(run((i64::MIN, 0), (i64::MIN + 100, -1_000), 0), departs);
    // Near the edge, X₃ = A.x ± 1 fits: beyond A.x all the same; X₃ = A.x is not.
    assert_eq!(run((i64::MAX - 99, 0), (i64::MAX - 298, -1_000), 0), departs);
    assert_eq!(run((i64::MIN + 99, 0), (i64::MIN + 298, -1_000), 0), departs);
    assert!(run((i64::MAX - 99, 0), (i64::MAX - 299, -1_000), 0).is_ok());
    assert!(run((i64::MIN + 99, 0), (i64::MIN + 299, -1_000), 0).is_ok());
}
