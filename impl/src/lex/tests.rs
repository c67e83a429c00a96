//! Unit tests of the production lexer (PRJ.LEX, PRJ.WORD).

extern crate std;

use super::*;
use crate::tests::xorshift;
use std::vec::Vec;

fn blocks(src: &str) -> Vec<Result<Block, Alarm>> {
    Blocks::new(src.as_bytes()).collect()
}

#[test]
fn reads_the_g92_example() {
    let src = "%\nO0012;\nM3 S300 G0 X150 Z50 T0101; (thread tool)\nG0X65Z5\ng92 x58.7 z-28 f3 j3 k1;\nX57.7;\nM30;\n%\n";
    let b: Vec<Block> = blocks(src).into_iter().map(Result::unwrap).collect();
    assert_eq!(b.len(), 6);
    assert_eq!(b[0].get(b'O').unwrap().mantissa, 12);
    assert_eq!(b[1].line, 3);
    assert_eq!(b[1].g_codes().len(), 1);
    let g92 = &b[3];
    assert_eq!(g92.line, 5);
    assert_eq!(g92.g_codes()[0].mantissa, 92);
    let z = g92.get(b'Z').unwrap();
    assert!(z.negative && z.mantissa == 28 && !z.point);
    let x = g92.get(b'X').unwrap();
    assert_eq!((x.mantissa, x.decimals, x.point), (587, 1, true));
    assert_eq!(g92.letters().collect::<Vec<_>>(), b"FJKXZ".to_vec());
}

#[test]
fn alarms_name_byte_and_line() {
    let r = blocks("G0 X1\nG0 X2 #\n");
    assert!(r[0].is_ok());
    assert_eq!(r[1], Err(Alarm::new(AlarmCode::BadCharacter, Some(b'#'), Rule::PrjLex, 2)));
    assert_eq!(r.len(), 2);
    assert_eq!(
        blocks("X1 X2")[0],
        Err(Alarm::new(AlarmCode::DuplicateWord, Some(b'X'), Rule::PrjWord, 1))
    );
    assert_eq!(blocks("G0 X")[0], Err(Alarm::new(AlarmCode::BadNumber, Some(b'X'), Rule::PrjLex, 1)));
    assert_eq!(blocks("X-.")[0], Err(Alarm::new(AlarmCode::BadNumber, Some(b'X'), Rule::PrjLex, 1)));
    assert_eq!(
        blocks("\n(open\nX1")[0],
        Err(Alarm::new(AlarmCode::UnclosedComment, Some(b'('), Rule::PrjLex, 2))
    );
    assert_eq!(
        blocks("X1234567890123456789")[0],
        Err(Alarm::new(AlarmCode::BadNumber, Some(b'X'), Rule::PrjLex, 1))
    );
}

/// A block read in place holds only its own words: the previous block's are gone, and the
/// block reads as the iterator's fresh one.
#[test]
fn reading_in_place_keeps_only_the_blocks_words() {
    let src = "G0 X1 Z2 M3\n(c)\nG92 U3 F1.5\n\nW-4\nX1 X2";
    let mut reader = Blocks::new(src.as_bytes());
    let mut block = Block::new();
    for fresh in Blocks::new(src.as_bytes()) {
        assert_eq!(reader.read(&mut block).map(|more| more.then_some(block)), fresh.map(Some));
    }
    assert_eq!(reader.read(&mut block), Ok(false), "ends after the alarm");
    let mut reader = Blocks::new(b"G0 X1 Z2\n\nW-4");
    assert_eq!((reader.read(&mut block), reader.read(&mut block)), (Ok(true), Ok(true)));
    assert_eq!(block.letters().collect::<Vec<_>>(), b"W".to_vec());
    assert_eq!((block.g_codes(), block.line, block.has(b'X')), (&[][..], 3, false));
    assert_eq!(reader.read(&mut block), Ok(false));
}

#[test]
fn numbers_forms() {
    let b = blocks("X.5 Z-0 U+3. W000123.4500")[0].unwrap();
    assert_eq!(b.get(b'X').unwrap(), Number { negative: false, mantissa: 5, decimals: 1, point: true });
    assert_eq!(b.get(b'Z').unwrap(), Number { negative: false, mantissa: 0, decimals: 0, point: false });
    assert_eq!(b.get(b'U').unwrap(), Number { negative: false, mantissa: 3, decimals: 0, point: true });
    assert_eq!(b.get(b'W').unwrap(), Number { negative: false, mantissa: 1234500, decimals: 4, point: true });
}

/// The number reader as first written, one digit at a time with every check per digit:
/// the reference for the run-based reader. `Ok` with the bytes read, or `Err` (BadNumber).
fn number_by_digit(src: &[u8]) -> Result<(Number, usize), ()> {
    let mut pos = src.iter().take_while(|&&b| matches!(b, b' ' | b'\t' | b'\r' | b'%')).count();
    let mut n = Number { negative: false, mantissa: 0, decimals: 0, point: false };
    if let Some(&sign @ (b'+' | b'-')) = src.get(pos) {
        n.negative = sign == b'-';
        pos += 1;
    }
    let (mut digits, mut significant) = (0u32, 0u32);
    while let Some(&b) = src.get(pos) {
        match b {
            b'0'..=b'9' => {
                digits += 1;
                if significant > 0 || b != b'0' {
                    significant += 1;
                }
                if significant > MAX_DIGITS || (n.point && n.decimals as u32 >= MAX_DIGITS) {
                    return Err(());
                }
                n.mantissa = n.mantissa * 10 + u64::from(b - b'0');
                if n.point {
                    n.decimals += 1;
                }
            }
            b'.' if !n.point => n.point = true,
            _ => break,
        }
        pos += 1;
    }
    if digits == 0 {
        return Err(());
    }
    if n.mantissa == 0 {
        n.negative = false;
    }
    Ok((n, pos))
}

/// PRJ.LEX: the run-based number reader reads what the digit-by-digit one reads — the same
/// number and the same bytes, or BadNumber — over random strings of signs, points, blanks
/// and digits (runs of zeros and of 18–20 significant digits, up to 44 characters).
#[test]
fn numbers_read_as_digit_by_digit() {
    let mut state = 0x0000_ddb1_a5e5_u64;
    let mut next = || xorshift(&mut state);
    let pieces: [&[u8]; 12] =
        [b"0", b"00000000", b"1", b"9", b"123456789", b"999999999", b".", b"-", b"+", b" ", b"5", b"X"];
    for _ in 0..200_000 {
        let mut text = [0u8; 48];
        let mut len = 0;
        for _ in 0..next() % 7 {
            let piece = pieces[(next() % 12) as usize];
            if len + piece.len() > 44 {
                break;
            }
            text[len..len + piece.len()].copy_from_slice(piece);
            len += piece.len();
        }
        let src = &text[..len];
        let mut reader = Blocks::new(src);
        let read = reader.number(b'X').map(|n| (n, reader.pos));
        let want = number_by_digit(src)
            .map_err(|()| Alarm::new(AlarmCode::BadNumber, Some(b'X'), Rule::PrjLex, 1));
        assert_eq!(read, want, "{:?}", core::str::from_utf8(src));
    }
    for (text, mantissa, decimals) in
        [("0.000000000000000001", 1, 18), ("000123456789012345678", 123_456_789_012_345_678, 0)]
    {
        let n = Blocks::new(text.as_bytes()).number(b'X').unwrap();
        assert_eq!((n.mantissa, n.decimals), (mantissa, decimals));
    }
    for text in ["0.0000000000000000001", "1234567890123456789", "1.234567890123456789", "."] {
        assert!(Blocks::new(text.as_bytes()).number(b'X').is_err(), "{text}");
    }
}

#[test]
fn random_bytes_never_panic() {
    let mut state = 0x1234_5678_9abc_def0u64;
    for _ in 0..2000 {
        let mut buf = [0u8; 64];
        for b in buf.iter_mut() {
            *b = (xorshift(&mut state) >> 24) as u8;
        }
        for r in Blocks::new(&buf) {
            let _ = r;
        }
    }
}

/// PRJ.LEX: a byte-order mark as the first three bytes is skipped, anywhere else (or cut
/// short) its first byte is a bad character.
#[test]
fn byte_order_mark_only_at_the_start() {
    let b = blocks("\u{feff}G0 X1\nZ2");
    assert_eq!(b.len(), 2);
    assert_eq!((b[0].unwrap().line, b[1].unwrap().line), (1, 2));
    assert!(blocks("\u{feff}").is_empty());
    let bad = |line| Err(Alarm::new(AlarmCode::BadCharacter, Some(0xEF), Rule::PrjLex, line));
    assert_eq!(blocks("\u{feff}\u{feff}X1")[0], bad(1));
    assert_eq!(blocks("X1\n\u{feff}X1")[1], bad(2));
    assert_eq!(Blocks::new(b"\xef\xbb").next(), Some(bad(1)));
    assert_eq!(Blocks::new(b"\xef").next(), Some(bad(1)));
}
