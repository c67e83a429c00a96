//! The plain-block loops read a run of plain blocks in one entry, and read no block before the
//! caller's buffer has room for what it runs. Neither shows in a trace (the events are the
//! same either way), so the tests count with `crate::probe`: the loops entered and the blocks
//! read, against the events `fill` writes.
extern crate std;

use crate::probe;
use crate::Expander;
use cycle_vocab::{Config, Event, Move, Rule};
use std::format;
use std::string::String;
use std::vec;

/// The program `head` followed by `n` plain blocks of axis word `letter`, values `from`,
/// `from − 0.1`, … (mm).
fn program(head: &str, letter: char, from: i64, n: i64) -> String {
    let mut p = String::from(head);
    for i in 0..n {
        let v = from - 100 * i;
        p.push_str(&format!("{letter}{}.{:03}\n", v / 1000, v % 1000));
    }
    p
}

/// Each plain kind: G92 passes (six events a block), G90 passes (five), G32 moves (one).
fn kinds() -> [(&'static str, String); 3] {
    [
        ("g92", program("G0 X65 Z5\nG92 X58.7 Z-28 F3\n", 'X', 58_600, 20)),
        ("g90", program("G0 X100 Z2\nG90 X99 Z-20 F0.2\n", 'X', 98_000, 20)),
        ("g32", program("G0 X30 Z5\nG32 Z4 F2\n", 'Z', 3_000, 20)),
    ]
}

/// `fill` calls with buffers of `size` until the program is over: the events written, the
/// plain-block loops entered and the blocks read.
fn fill_all(p: &str, size: usize) -> (usize, usize, usize) {
    let mut ex = Expander::new(p.as_bytes(), Config::default());
    let mut buf = vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); size];
    let (runs, reads) = (probe::runs(), probe::reads());
    let mut events = 0;
    loop {
        match ex.fill(&mut buf) {
            Ok(0) => break,
            Ok(w) => events += w,
            Err(a) => panic!("{a:?}"),
        }
    }
    (events, probe::runs() - runs, probe::reads() - reads)
}

/// With room for the whole trace, the 20 plain blocks after each cycle's coded block are read
/// in one loop: one entry, every block read once (the program's 22 blocks, and the end).
#[test]
fn a_run_of_plain_blocks_is_one_loop() {
    for (kind, p) in kinds() {
        let per_block = match kind {
            "g92" => 6,
            "g90" => 5,
            _ => 1,
        };
        let (events, runs, reads) = fill_all(&p, 4096);
        assert_eq!(events, 1 + 21 * per_block, "{kind}: the rapid and 21 blocks' events");
        assert_eq!((runs, reads), (1, 23), "{kind}: one loop; 22 blocks and the end read");
    }
}

/// A buffer that a G90 pass or a G32 move fills exactly: the call that fills it reads no block
/// after the one whose events fill it (the next block is read by the next call). G92's pass
/// is written whole only with room for seven events and has six, so its loop never fills the
/// buffer exactly.
#[test]
fn no_block_is_read_before_there_is_room() {
    for (kind, p) in kinds() {
        let first = match kind {
            "g92" => continue,
            // The rapid, the coded block's pass, the first plain block's pass.
            "g90" => 1 + 5 + 5,
            _ => 1 + 1 + 1,
        };
        let mut ex = Expander::new(p.as_bytes(), Config::default());
        let mut buf = vec![Event::Move(Move::rapid(0, 0, Rule::PrjTrace)); first];
        let reads = probe::reads();
        assert_eq!(ex.fill(&mut buf), Ok(first), "{kind}");
        assert_eq!(probe::reads() - reads, 3, "{kind}: G0, the coded block and one plain block read");
    }
}
