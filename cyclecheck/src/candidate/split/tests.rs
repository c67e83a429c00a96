use super::*;

#[test]
fn splits_like_a_shell_without_expansion() {
    let s = |l: &str| split_command(l).unwrap();
    assert_eq!(s("python3 examples/g92.py --plant-bug"), ["python3", "examples/g92.py", "--plant-bug"]);
    assert_eq!(s("  a\t 'b c'  \"d \\\" e\" f\\ g "), ["a", "b c", "d \" e", "f g"]);
    assert_eq!(s("echo $HOME * | > x; rm"), ["echo", "$HOME", "*", "|", ">", "x;", "rm"]);
    assert_eq!(s("'it''s' \"a\\nb\" ''"), ["its", "a\\nb", ""]);
    assert_eq!(s("x\\\ny"), ["xy"]);
    for bad in ["", "   ", "'open", "\"open", "trailing\\"] {
        assert!(split_command(bad).is_err(), "{bad:?}");
    }
}
