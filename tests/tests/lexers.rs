//! The two lexers — the reference's (`cycle_spec::lex`, written for clarity over decimal strings)
//! and the production expander's (`cycle_impl::lex`, written for speed) — read the same blocks,
//! words and numbers and stop at the same alarm (PRJ.LEX, PRJ.WORD), on the edges of the
//! register's "Program text" rules that generated programs reach rarely: 17, 18 and 19
//! significant digits and decimals, zeros that do or do not count, signs, points, blanks
//! between a letter and its number, comments, CR LF, the byte-order mark, four and five G
//! words, repeated letters, bytes that are no part of a program. The comparison is the
//! `parse_blocks` fuzz target's body (`cycle_kernel::fuzzing::parse_blocks`), which also runs
//! both engines on the program and requires them to conform.

use cycle_kernel::fuzzing::parse_blocks;

/// Numbers around the digit limits: `digits` significant digits, `decimals` after the point,
/// `zeros` zeros before the first significant digit.
fn number(zeros: usize, digits: usize, decimals: usize) -> String {
    let body: String = "0".repeat(zeros) + &"7".repeat(digits);
    if decimals == 0 {
        return body;
    }
    let padded = format!("{body:0>width$}", width = decimals + 1);
    let (int, frac) = padded.split_at(padded.len() - decimals);
    format!("{int}.{frac}")
}

#[test]
fn lexers_agree_on_the_number_edges() {
    let mut programs = Vec::new();
    for zeros in [0, 1, 5, 20] {
        for digits in [0, 1, 17, 18, 19] {
            for decimals in [0, 1, 17, 18, 19, 20] {
                let n = number(zeros, digits, decimals);
                for letter in ["X", "N", "G", "F", "m"] {
                    for sign in ["", "-", "+"] {
                        programs.push(format!("G0 {letter}{sign}{n}\n"));
                    }
                }
                programs.push(format!("G0 X {n}.\n"));
                programs.push(format!("G0 X-.{n}\n"));
            }
        }
    }
    for p in programs {
        if let Err(e) = parse_blocks(p.as_bytes()) {
            panic!("{p:?}:\n{e}");
        }
    }
}

/// Values with zeros after the grid's last decimal place read the same in both engines (the
/// number reader scales by the digits beyond the grid; `parse_blocks` runs both engines, on the
/// metric ISB grid and the inch ISC grid, and requires them to conform).
#[test]
fn engines_agree_on_trailing_zeros() {
    for zeros in 0..=17 {
        let z = "0".repeat(zeros);
        for value in [format!("1.5{z}"), format!("-20.125{z}"), format!("0.0001{z}"), format!("7.{z}")] {
            let p = format!("G0 X{value} Z{value}\nG1 W-{value} F0.2{z}\n");
            if let Err(e) = parse_blocks(p.as_bytes()) {
                panic!("{p:?}:\n{e}");
            }
        }
    }
}

#[test]
fn lexers_agree_on_blocks_comments_and_bytes() {
    let programs: &[&[u8]] = &[
        b"\xef\xbb\xbfG0 X1\n",
        b"G0 X1\n\xef\xbb\xbfZ2\n",
        b"\xef\xbbG0\n",
        b"G0 X1\r\nZ2\r\n",
        b"G0X1(c)Z2\n",
        b"G0 X(c)1\n",
        b"G0 X1 (open\nZ2\n",
        b"G0 X1 X2\n",
        b"G1 G0 G1 G0 X1\n",
        b"G1 G0 G1 G0 G1 X1\n",
        b"G0 X1 ;; Z2 ;\n;\n",
        b"% \n%G0 %X1%\n",
        b"g0 x1 z-.5\n",
        b"G0 X1-2\n",
        b"G0 X1.2.3\n",
        b"G0 X+-1\n",
        b"G0 X-\n",
        b"G0 X.\n",
        b"G0 X\t5\n",
        b"G0 X1 # comment\n",
        b"G0 X1 / Z2\n",
        b")G0\n",
        b"G0 X1\x00\n",
        b"M30\nG0 X#\n",
        b"G0 X1 Z2 M02\n(unclosed\n",
        b"N10.5 O20.5 S-3 T01.01 G0 X1\n",
        // S is an integer under gsk and fanuc (G50.SMAX, "Spindle speed"): NOT INTEGER on S.
        b"N10 O20 S-3.5 T0101 G0 X1\n",
    ];
    for p in programs {
        if let Err(e) = parse_blocks(p) {
            panic!("{:?}:\n{e}", String::from_utf8_lossy(p));
        }
    }
}
