//! `--op` on the command line (OP.SCRIPT): the G92 example held halfway along its thread
//! cut, both No.0018 bit 6 values, `diff` under a script, and bad actions refused with exit 2.

use std::io::Write;
use std::process::{Command, Output, Stdio};

const G92: &str = "G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\nM30\n";

/// `cyclecheck ARGS -` with the example on standard input.
fn run(args: &[&str]) -> Output {
    let mut child = Command::new(env!("CARGO_BIN_EXE_cyclecheck"))
        .args(args)
        .arg("-")
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    // A refused option exits before reading standard input: the pipe may be closed by then.
    if let Err(e) = child.stdin.take().unwrap().write_all(G92.as_bytes()) {
        assert_eq!(e.kind(), std::io::ErrorKind::BrokenPipe, "{e}");
    }
    child.wait_with_output().unwrap()
}

fn lines(o: &Output) -> Vec<String> {
    String::from_utf8_lossy(&o.stdout).lines().map(str::to_string).collect()
}

#[test]
fn a_hold_halfway_both_ways() {
    let back = run(&["expand", "--op", "hold:3@1/2", "--op", "start"]);
    assert_eq!(back.status.code(), Some(0), "{}", String::from_utf8_lossy(&back.stderr));
    let l = lines(&back);
    let i = l.iter().position(|s| s == "(PRESS HOLD AT X58.700 Z-11.000)").expect("the press");
    assert_eq!(l[i + 2..i + 7], ["G32 X64.700 Z-12.000 F3.0000", "G00 X65.000 Z-12.000", "G00 X65.000 Z5.000", "(STOP FEED HOLD)", "(CYCLE START)"]);
    let on = run(&["expand", "--op", "hold:3@0.5", "--op", "start", "--param", "18=1"]);
    let l = lines(&on);
    let i = l.iter().position(|s| s.starts_with("(PRESS HOLD")).unwrap();
    assert_eq!(l[i + 3..], ["(STOP FEED HOLD)", "(CYCLE START)", "G00 X65.000 Z-28.000", "G00 X65.000 Z5.000"]);
}

#[test]
fn diff_under_a_script_conforms() {
    let o = run(&["diff", "--op", "single:on@0", "--op", "hold:4@1/3", "--op", "start"]);
    assert_eq!(o.status.code(), Some(0), "{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
}

#[test]
fn bad_actions_exit_2_naming_the_option() {
    for bad in ["hold:3@3/2", "hold:3", "pause:1@1", "single:maybe@0"] {
        let o = run(&["expand", "--op", bad]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(String::from_utf8_lossy(&o.stderr).contains("--op"), "{bad}: {}", String::from_utf8_lossy(&o.stderr));
    }
    // A hold on the pass header is the program's OPERATOR alarm (OP.AT), exit 2 as every alarm.
    let o = run(&["expand", "--op", "hold:1@1/2"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&o.stdout).contains("(ALARM 3005 LINE 2 RULE OP.AT)"), "{}", String::from_utf8_lossy(&o.stdout));
}
