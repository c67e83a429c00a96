use super::*;

fn writer(spelling: Spelling) -> Writer {
    Writer { out: String::new(), style: 0, spelling }
}

#[test]
fn the_plain_writer_writes_plain_words() {
    let mut w = writer(Spelling::default());
    assert_eq!(w.length(60_000, 3), "60");
    assert_eq!(w.length(58_700, 3), "58.7");
    assert_eq!(w.length(-28_000, 3), "-28");
    assert_eq!(w.micron(2_400, 3, true), "2400");
    assert_eq!(w.micron(2_400, 3, false), "2.4");
    w.block(&[('G', "92".into()), ('X', "58.7".into())]);
    assert_eq!(w.finish(), b"G92 X58.7\n");
}

/// Each spelling of the lexer's promise, alone.
#[test]
fn each_spelling_writes_its_form() {
    let words = [('G', "0".to_string()), ('X', "-.5".to_string())];
    for (spelling, length, block) in [
        (Spelling { leading_zeros: true, ..Spelling::default() }, "7.5", "G000 X-00.5\n"),
        (Spelling { trailing_point: true, ..Spelling::default() }, "5.", "G0 X-.5\n"),
        (Spelling { trailing_zeros: true, ..Spelling::default() }, "7.5000000", "G0 X-.5\n"),
        (Spelling { plus_point: true, ..Spelling::default() }, "+.5", "G0 X-.5\n"),
        (Spelling { minus_zero: true, ..Spelling::default() }, "-0", "G0 X-.5\n"),
        (Spelling { lower_case: true, ..Spelling::default() }, "7.5", "g0 x-.5\n"),
        (Spelling { no_spaces: true, ..Spelling::default() }, "7.5", "G0X-.5\n"),
        (Spelling { comments: true, ..Spelling::default() }, "7.5", "G0 (c)X-.5\n"),
        (Spelling { crlf: true, ..Spelling::default() }, "7.5", "G0 X-.5\r\n"),
        (Spelling { bom: true, ..Spelling::default() }, "7.5", "\u{feff}G0 X-.5\n"),
    ] {
        let mut w = writer(spelling);
        let count = match length {
            "5." => 5_000,
            "+.5" => 500,
            "-0" => 0,
            _ => 7_500,
        };
        assert_eq!(w.length(count, 3), length, "{spelling:?}");
        w.block(&words);
        assert_eq!(String::from_utf8(w.finish()).unwrap(), block, "{spelling:?}");
    }
}

/// The spelling knobs at 0 are the plain spelling; each knob turns on its form.
#[test]
fn zero_knobs_spell_plainly() {
    assert_eq!(Spelling::draw(&mut Dice::new(&[0; 9])), Spelling::default());
    assert!(Spelling::draw(&mut Dice::new(&[99, 0, 0, 0, 0, 0, 0, 0, 0])).leading_zeros);
    assert!(Spelling::draw(&mut Dice::new(&[0, 0, 0, 0, 0, 0, 0, 0, 99])).bom);
}
