//! The spec's own reader (PRJ.LEX, PRJ.WORD): every rule of the register's "Program text"
//! section with its alarm, every spelling a program may use, and the value rules of "Values
//! (check step 3)" that the reader's exact numbers make possible.

use crate::expand;
use crate::lex::{blocks, Block, Number};
use cycle_vocab::text::Trace;
use cycle_vocab::{Alarm, AlarmCode, Config, Dialect, Rule};

/// An alarm as (code, word, rule, line).
type Expect = (AlarmCode, Option<u8>, Rule, u32);

fn lex_alarm(code: AlarmCode, byte: u8, line: u32) -> Expect {
    (code, Some(byte), Rule::PrjLex, line)
}

/// The blocks of `src` up to the first alarm, and that alarm.
fn read(src: &[u8]) -> (Vec<Block>, Option<Expect>) {
    let mut out = Vec::new();
    for b in blocks(src) {
        match b {
            Ok(b) => out.push(b),
            Err(a) => return (out, Some((a.code, a.word, a.rule, a.line))),
        }
    }
    (out, None)
}

fn alarm_of(src: &[u8]) -> Option<Expect> {
    read(src).1
}

/// Each block as its words `LETTER=number` and its line.
fn words(src: &[u8]) -> Vec<(u32, String)> {
    let (bs, alarm) = read(src);
    assert_eq!(alarm, None, "{:?}", String::from_utf8_lossy(src));
    bs.iter()
        .map(|b| (b.line, b.words.iter().map(|w| format!("{}={}", w.letter as char, w.number)).collect::<Vec<_>>().join(" ")))
        .collect()
}

fn run(src: &[u8], config: &Config) -> Trace {
    expand(src, config)
}

fn trace_alarm(src: &str, config: &Config) -> Option<Expect> {
    run(src.as_bytes(), config).alarm.map(|a: Alarm| (a.code, a.word, a.rule, a.line))
}

/// Numbers as written: sign, digits, decimals, point; leading zeros dropped; `-0` is zero.
#[test]
fn numbers_as_written() {
    let n = |s: &str| Number::parse(s).unwrap_or_else(|| panic!("{s}"));
    let parts = |s: &str| {
        let v = n(s);
        (v.negative, v.digits, v.decimals, v.point)
    };
    assert_eq!(parts("5"), (false, "5".into(), 0, false));
    assert_eq!(parts("5."), (false, "5".into(), 0, true));
    assert_eq!(parts("5.25"), (false, "525".into(), 2, true));
    assert_eq!(parts(".5"), (false, "5".into(), 1, true));
    assert_eq!(parts("+.5"), (false, "5".into(), 1, true));
    assert_eq!(parts("-.5"), (true, "5".into(), 1, true));
    assert_eq!(parts("007.50"), (false, "750".into(), 2, true));
    assert_eq!(parts("-0"), (false, "".into(), 0, false));
    assert_eq!(parts("-0.0"), (false, "".into(), 1, true));
    assert_eq!(parts("0.000000000000000001"), (false, "1".into(), 18, true));
    assert_eq!(n("-0.0"), n("0.0"));
    // The canonical form.
    for (s, shown) in [("5", "5"), ("5.", "5."), ("+.5", "0.5"), ("-007.50", "-7.50"), ("-0", "0"), (".000", "0.000")] {
        assert_eq!(n(s).to_string(), shown);
    }
    // Not one number.
    for s in ["", "+", "-", ".", "-.", "+-1", "1.2.3", "- 1", "1 ", "1e3"] {
        assert_eq!(Number::parse(s), None, "{s}");
    }
}

/// At most 18 significant digits (from the first nonzero digit, trailing zeros included) and
/// at most 18 decimals; more is `BAD NUMBER` on the letter.
#[test]
fn eighteen_digit_edges() {
    let ok = |s: &str| assert_eq!(alarm_of(format!("X{s}").as_bytes()), None, "{s}");
    let bad = |s: &str| assert_eq!(alarm_of(format!("X{s}").as_bytes()), Some(lex_alarm(AlarmCode::BadNumber, b'X', 1)), "{s}");
    ok("123456789012345678");
    bad("1234567890123456789");
    ok("-12345678901234567.8");
    bad("-12345678901234567.89");
    ok("1.00000000000000000"); // 18 significant digits, 17 decimals
    bad("10.00000000000000000"); // 19 significant digits
    ok("0.000000000000000001"); // 1 significant digit, 18 decimals
    bad("0.0000000000000000001"); // 19 decimals
    ok("0.000000000000000000");
    bad("0.0000000000000000000");
    ok("000000000000000000000000000000000000001"); // leading zeros are not significant
    ok("000000000000000000000000000000000000000.");
    bad(&"9".repeat(100_000)); // read to its end, kept to 18 digits
}

/// Every spelling of one program gives the same blocks and the same trace.
#[test]
fn spellings() {
    let plain = "G0 X5 Z2\nG1 X4.5 Z-1 F0.25\n";
    let spellings: [&[u8]; 11] = [
        b"g0 x5 z2\ng1 x4.5 z-1 f0.25\n",
        b"G0X5Z2\nG1X4.5Z-1F.25\n",
        b"G00 X005. Z+2.000\nG01 X4.50 Z-1. F0.250\n",
        b"G0 X 5 Z 2\nG1 X\t4.5 Z -1 F 0.25\n",
        b"G0 X5(rapid)Z2\nG1(feed)X4.5 (a) Z-1 F0.25 (end)\n",
        b"G0 X5 Z2\r\nG1 X4.5 Z-1 F0.25\r\n",
        b"%\nG0 X5 Z2;G1 X4.5 Z-1 F0.25;\n%",
        b"\xEF\xBB\xBFG0 X5 Z2\nG1 X4.5 Z-1 F0.25",
        b";;\n(only a comment)\n  \n%\nG0 X5 Z2\nG1 X4.5 Z-1 F0.25\n",
        b"N10 G0 X5 Z2 ( \xff any byte ( )\nN20 G1 X4.5 Z-1 F0.25 S300 T0101\n",
        b"G-0 X5 Z2\nG1 X4.5 Z-1 F0.25 M-0\n",
    ];
    let reference = run(plain.as_bytes(), &Config::default());
    assert_eq!(reference.alarm, None);
    assert_eq!(reference.moves().count(), 2);
    for s in spellings {
        assert_eq!(run(s, &Config::default()), reference, "{:?}", String::from_utf8_lossy(s));
    }
    // Blocks, their lines and words as read.
    assert_eq!(words(b"G0X1;z-2.5\n\n(c)\nx.5 ;;"), vec![(1, "G=0 X=1".into()), (1, "Z=-2.5".into()), (4, "X=0.5".into())]);
    assert_eq!(words(b"\xEF\xBB\xBF\r\nG1"), vec![(2, "G=1".into())]);
    assert_eq!(words(b"G0 G1 G2 G3 X1"), vec![(1, "G=0 G=1 G=2 G=3 X=1".into())]);
}

/// `BAD CHARACTER` names the byte where a word may start, at its line; the blocks before it
/// are executed first.
#[test]
fn bad_characters() {
    let bad = |src: &[u8], byte: u8, line: u32| {
        assert_eq!(alarm_of(src), Some(lex_alarm(AlarmCode::BadCharacter, byte, line)), "{:?}", String::from_utf8_lossy(src));
    };
    bad(b"X1-2", b'-', 1);
    bad(b"X1.2.3", b'.', 1);
    bad(b"G0\nX1 2", b'2', 2);
    bad(b"5", b'5', 1);
    bad(b"+X1", b'+', 1);
    bad(b"X1)", b')', 1);
    bad(b"#1=2", b'#', 1);
    bad(b"/N10", b'/', 1);
    bad(b"X1 =", b'=', 1);
    bad(b"G0 \xC3\xA9", 0xC3, 1); // 'é' where a word may start
    bad(b"G0\n\n\xC3\xA9", 0xC3, 3);
    bad(b"\0", 0, 1);
    // A byte-order mark anywhere but at the very start is a bad character.
    bad(b"G0\n\xEF\xBB\xBFX1", 0xEF, 2);
    bad(b"\xEF\xBB\xBF\xEF\xBB\xBFG0", 0xEF, 1);
    bad(b" \xEF\xBB\xBFG0", 0xEF, 1);
    // The blocks before the alarm are executed; the broken block is not.
    let t = run(b"G0 X1\nG0 X2 #\n", &Config::default());
    assert_eq!(t.moves().map(|m| m.x).collect::<Vec<_>>(), vec![1_000]);
    assert_eq!(t.alarm, Some(Alarm::new(AlarmCode::BadCharacter, Some(b'#'), Rule::PrjLex, 2)));
}

/// `BAD NUMBER` on the (upper-case) letter without a legal number, at its line.
#[test]
fn bad_numbers() {
    for src in ["X", "X-", "X.", "X+-1", "X-.", "X;", "X\n", "X(1)", "X- 1", "XZ1", "x", "X--1", "X.-1"] {
        assert_eq!(alarm_of(src.as_bytes()), Some(lex_alarm(AlarmCode::BadNumber, b'X', 1)), "{src:?}");
    }
    assert_eq!(alarm_of(b"G0\n\nz"), Some(lex_alarm(AlarmCode::BadNumber, b'Z', 3)));
    assert_eq!(alarm_of(b"N1234567890123456789"), Some(lex_alarm(AlarmCode::BadNumber, b'N', 1)));
    assert_eq!(alarm_of(b"N123456789012345678 O1 S1.5 T-2"), None);
}

/// `UNCLOSED COMMENT` on `(` at the comment's line: a comment closes on its own line.
#[test]
fn comments() {
    let unclosed = |line| Some(lex_alarm(AlarmCode::UnclosedComment, b'(', line));
    assert_eq!(alarm_of(b"G0 (abc\nX1)"), unclosed(1));
    assert_eq!(alarm_of(b"G0\nX1 (abc"), unclosed(2));
    assert_eq!(alarm_of(b"G0\r\n\r\n(abc\r\n)"), unclosed(3));
    assert_eq!(alarm_of(b"((nested)"), None); // the first ')' closes
    assert_eq!(alarm_of(b"X1((x))"), Some(lex_alarm(AlarmCode::BadCharacter, b')', 1)));
}

/// `DUPLICATE WORD` (PRJ.WORD) at the block's line: a letter twice (either case), a fifth G.
#[test]
fn duplicate_words() {
    let dup = |byte, line| Some((AlarmCode::DuplicateWord, Some(byte), Rule::PrjWord, line));
    assert_eq!(alarm_of(b"X1 X2"), dup(b'X', 1));
    assert_eq!(alarm_of(b"G0\n\nx1 Z2 X1"), dup(b'X', 3));
    assert_eq!(alarm_of(b"G0 G0 G0 G0 G0"), dup(b'G', 1));
    assert_eq!(alarm_of(b"N1 n2"), dup(b'N', 1));
    assert_eq!(alarm_of(b"X1;X2"), None); // two blocks
    // The word is read before it is counted: a second X without a number is BAD NUMBER.
    assert_eq!(alarm_of(b"X1 X"), Some(lex_alarm(AlarmCode::BadNumber, b'X', 1)));
}

/// The reader streams: blocks are handed out before the rest of the program is read, and a
/// long program is read block by block.
#[test]
fn streams() {
    let mut text = b"G0 X1\n".to_vec();
    text.extend(vec![b'#'; 1_000_000]);
    let mut it = blocks(&text);
    assert!(matches!(it.next(), Some(Ok(_))));
    assert!(matches!(it.next(), Some(Err(_))));
    assert!(it.next().is_none());
    let long = "G1 X1 F1\nX2\n".repeat(50_000);
    assert_eq!(blocks(long.as_bytes()).count(), 100_000);
    assert_eq!(run(long.as_bytes(), &Config::default()).moves().count(), 100_000);
}

/// "Values (check step 3)": a value too large for any machine word is `OUT OF RANGE` under the
/// word's own rule; G and M codes of any size are unsupported codes.
#[test]
fn huge_values() {
    let nc201 = Config { dialect: Dialect::Nc201, ..Config::default() };
    let gsk = Config::default();
    let big = "999999999999999999";
    let out = |w: u8, rule, line| Some((AlarmCode::OutOfRange, Some(w), rule, line));
    assert_eq!(trace_alarm(&format!("G0 X30 Z5\nG162 X24 Z-20 H{big} F1.5\n"), &nc201), out(b'H', Rule::G162H, 2));
    assert_eq!(trace_alarm(&format!("G162 X24 Z-20 H1 F1.5 I-{big}\n"), &nc201), out(b'I', Rule::G162I, 1));
    assert_eq!(trace_alarm(&format!("G162 X24 Z-20 H1 F1.5 J{big}\n"), &nc201), out(b'J', Rule::G162J, 1));
    assert_eq!(trace_alarm(&format!("G162 X24 Z-20 H1 F1.5 B{big}\n"), &nc201), out(b'B', Rule::G162B, 1));
    assert_eq!(trace_alarm(&format!("G162 X24 Z-20 H1 F1.5 A{big}\n"), &nc201), out(b'A', Rule::G162A, 1));
    assert_eq!(trace_alarm(&format!("G33 Z-5 F1 P{big}\n"), &gsk), out(b'P', Rule::G33, 1));
    assert_eq!(trace_alarm(&format!("G34 Z-5 F1 K-{big}\n"), &gsk), out(b'K', Rule::G34, 1));
    assert_eq!(trace_alarm(&format!("G76 P010060 D{big}\n"), &gsk), out(b'D', Rule::G76Mode, 1));
    assert_eq!(trace_alarm(&format!("G78 P010060 D{big}\n"), &gsk), out(b'D', Rule::G78DepthMode, 1));
    assert_eq!(trace_alarm(&format!("G0 X{big}\n"), &gsk), out(b'X', Rule::ComRanges, 1));
    assert_eq!(trace_alarm(&format!("G0 X0.{big}\n"), &gsk), Some((AlarmCode::Precision, Some(b'X'), Rule::ComUnits, 1)));
    assert_eq!(trace_alarm(&format!("G92 X1 Z-1 F1 L{big}\n"), &gsk), out(b'L', Rule::ComRanges, 1));
    assert_eq!(trace_alarm(&format!("G{big} X1\n"), &gsk), Some((AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1)));
    assert_eq!(trace_alarm(&format!("M{big}\n"), &gsk), Some((AlarmCode::UnsupportedCode, Some(b'M'), Rule::PrjSupported, 1)));
    assert_eq!(trace_alarm("G1.0 X1\n", &gsk), Some((AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1)));
    assert_eq!(trace_alarm("G-1 X1\n", &gsk), Some((AlarmCode::UnsupportedCode, Some(b'G'), Rule::PrjSupported, 1)));
    assert_eq!(trace_alarm("M-1\n", &gsk), Some((AlarmCode::UnsupportedCode, Some(b'M'), Rule::PrjSupported, 1)));
}

/// COM.LEAD: F with I is a `CONFLICT` only in thread blocks; elsewhere I is not allowed.
#[test]
fn f_with_i_only_in_thread_blocks() {
    let c = Config::default();
    let conflict = |line| Some((AlarmCode::Conflict, Some(b'I'), Rule::ComLead, line));
    let not_allowed = |line| Some((AlarmCode::WordNotAllowed, Some(b'I'), Rule::PrjWord, line));
    assert_eq!(trace_alarm("G01 F1 I1\n", &c), not_allowed(1));
    assert_eq!(trace_alarm("G0 X1 F1 I1\n", &c), not_allowed(1));
    assert_eq!(trace_alarm("G1 X1 F1\nF1 I1\n", &c), not_allowed(2));
    assert_eq!(trace_alarm("G1 X1 F1\nI1\n", &c), not_allowed(2));
    assert_eq!(trace_alarm("G92 X1 Z-1 F1 I1\n", &c), conflict(1));
    assert_eq!(trace_alarm("G0 X5 Z5\nG92 X1 Z-1 F1\nF1 I1\n", &c), conflict(3));
    assert_eq!(trace_alarm("G76 P010060 F1 I1\n", &c), conflict(1));
    assert_eq!(trace_alarm("G78 X1 Z-1 F1 I1\n", &c), conflict(1));
    for g in ["G32", "G33", "G34 K0"] {
        assert_eq!(trace_alarm(&format!("{g} Z-5 F1 I1\n"), &c), conflict(1));
        assert_eq!(trace_alarm(&format!("{g} Z-5 F1\nW-1 F1 I1\n"), &c), conflict(2));
    }
    // X with U and Z with W stay conflicts everywhere (before the F/I check).
    assert_eq!(trace_alarm("G1 X1 U1 F1 I1\n", &c), Some((AlarmCode::Conflict, Some(b'U'), Rule::ComAbsInc, 1)));
}
