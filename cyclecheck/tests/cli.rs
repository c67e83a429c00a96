//! The `cyclecheck` binary, run as a user runs it: exit codes, stdout, stderr (README, "The CLI").
//! Expected results of `diff` and `corpus` are computed in-process with the same engines, so the
//! tests hold before and after the production expander conforms.

use cycle_kernel::engine::{Engine, ImplEngine, SpecEngine};
use cycle_kernel::{conformance, corpus};
use cycle_vocab::text::Trace;
use cycle_vocab::Config;
use std::path::PathBuf;
use std::process::{Command, Output};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("..")
}

fn corpus_file(name: &str) -> String {
    root().join("corpus").join(name).to_string_lossy().into_owned()
}

fn run(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cyclecheck")).args(args).output().expect("the binary runs")
}

fn code(o: &Output) -> i32 {
    o.status.code().expect("exited, not killed by a signal")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// A program file in the temporary directory, removed when dropped.
struct TempFile(PathBuf);

impl TempFile {
    fn new(name: &str, bytes: &[u8]) -> TempFile {
        let path = std::env::temp_dir().join(format!("cyclecheck-cli-{}-{name}", std::process::id()));
        std::fs::write(&path, bytes).unwrap();
        TempFile(path)
    }

    fn path(&self) -> &str {
        self.0.to_str().unwrap()
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

#[test]
fn expand_g92_example_prints_canonical_gcode() {
    let o = run(&["expand", &corpus_file("g92_example.nc")]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.starts_with("(CYCLECHECK TRACE MM GRID 0.001)\n"), "{out}");
    assert!(out.contains("(PASS 1 ROUGH DEPTH 3.150)\n"), "{out}");
    assert!(out.contains("G32 X58.700 Z-27.000 F3.0000\n"), "{out}");
    assert!(out.contains("G32 X64.700 Z-28.000 F3.0000\n"), "{out}");
    // Exactly the spec's trace.
    let program = std::fs::read(corpus_file("g92_example.nc")).unwrap();
    assert_eq!(out, SpecEngine.expand(&program, &Config::default()).to_gcode());
    assert!(stderr(&o).is_empty(), "{}", stderr(&o));
}

#[test]
fn expand_json_parses_back() {
    for engine in ["spec", "impl"] {
        let o = run(&["expand", &corpus_file("g92_example.nc"), "--engine", engine, "--format", "json"]);
        let trace = Trace::from_json(&stdout(&o)).expect("the JSON output is a trace");
        let program = std::fs::read(corpus_file("g92_example.nc")).unwrap();
        let direct = match engine {
            "spec" => SpecEngine.expand(&program, &Config::default()),
            _ => ImplEngine.expand(&program, &Config::default()),
        };
        assert_eq!(trace, direct, "{engine}");
        assert_eq!(code(&o), if direct.alarm.is_some() { 2 } else { 0 }, "{engine}");
    }
}

#[test]
fn expand_under_fanuc_dialect_and_inch_units() {
    let o = run(&["expand", &corpus_file("f76_ex1_microns.nc"), "--dialect", "fanuc"]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    let gsk = run(&["expand", &corpus_file("f76_ex1.nc")]);
    assert_eq!(stdout(&o), stdout(&gsk), "the micron form is the same thread");

    let inch = root().join("tests/programs/g92_inch.nc");
    let o = run(&["expand", inch.to_str().unwrap(), "--units", "inch"]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stdout(&o).starts_with("(CYCLECHECK TRACE INCH GRID 0.0001)\n"), "{}", stdout(&o));
    // Without --units inch, its G20 is refused.
    let o = run(&["expand", inch.to_str().unwrap()]);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("rule COM.UNITS"), "{}", stderr(&o));
    // …with a hint naming the option.
    assert!(stderr(&o).contains("hint: G20 selects inch") && stderr(&o).contains("run with --units inch"), "{}", stderr(&o));
    let g162 = corpus_file("g162_cone.nc");
    let o = run(&["diff", &g162]);
    assert_eq!(code(&o), 0, "both engines raise the same alarm: they conform");
    assert!(stderr(&o).contains("run with --dialect nc201"), "{}", stderr(&o));
}

#[test]
fn options_change_the_configuration() {
    let file = corpus_file("g92_example.nc");
    let o = run(&["expand", &file, "--increment", "isc"]);
    assert!(stdout(&o).contains("G32 X58.7000 Z-27.0000 F3.0000"), "{}", stdout(&o));
    // Start point: the first move leaves from there, so it is printed as given by the program.
    let p = TempFile::new("x_only.nc", b"G0 X10\n");
    let o = run(&["expand", p.path(), "--start-x", "5", "--start-z=-2.5"]);
    assert_eq!(code(&o), 0, "{}", stderr(&o));
    assert!(stdout(&o).contains("G00 X10.000 Z-2.500"), "{}", stdout(&o));
    // --param reaches the engine: No.107 ≠ 0 is refused on the first G92 cycle.
    let o = run(&["expand", &file, "--param", "107=1"]);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).contains("rule G92.JK.8"), "{}", stderr(&o));
}

#[test]
fn missing_lead_is_an_alarm_naming_word_and_rule() {
    let p = TempFile::new("no_lead.nc", b"G0 X65 Z5\nG92 X58.7 Z-28 J3 K1\n");
    let o = run(&["expand", p.path()]);
    assert_eq!(code(&o), 2);
    let err = stderr(&o);
    assert_eq!(err.trim_end(), "ALARM 2001 MISSING WORD: word F, rule COM.LEAD, line 2");
    assert!(stdout(&o).ends_with("(ALARM 2001 LINE 2 WORD F RULE COM.LEAD)\n"), "{}", stdout(&o));
}

#[test]
fn g78_example_ends_in_its_alarm() {
    let o = run(&["expand", &corpus_file("g78_example.nc")]);
    assert_eq!(code(&o), 2);
    assert_eq!(stderr(&o).trim_end(), "ALARM 2002 OUT OF RANGE: word P, rule G78.MODE, line 3");
}

#[test]
fn garbage_is_an_alarm_not_a_panic() {
    // Deterministic pseudo-random bytes, including NUL and bytes above 0x7F.
    let mut state = 0x9e37_79b9_7f4a_7c15u64;
    let bytes: Vec<u8> = (0..512)
        .map(|_| {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 32) as u8
        })
        .collect();
    let p = TempFile::new("random.nc", &bytes);
    for args in [vec!["expand", p.path()], vec!["expand", p.path(), "--engine", "impl"], vec!["diff", p.path()]] {
        let o = run(&args);
        let c = code(&o);
        // expand: 2, the program ends in an alarm; diff: 0, both engines raise it (or 1).
        let expected: &[i32] = if args[0] == "diff" { &[0, 1] } else { &[2] };
        assert!(expected.contains(&c), "{args:?}: exit {c}\n{}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"), "{args:?}: {}", stderr(&o));
    }
    let o = run(&["expand", p.path()]);
    assert_eq!(code(&o), 2);
    assert!(stderr(&o).starts_with("ALARM 1001 BAD CHARACTER: word 0x"), "{}", stderr(&o));
}

#[test]
fn bad_input_exits_2_naming_the_problem() {
    let file = corpus_file("g92_example.nc");
    for (args, names) in [
        (vec![], "Usage"),
        (vec!["frobnicate"], "frobnicate"),
        (vec!["expand"], "FILE"),
        (vec!["expand", "/nonexistent/program.nc"], "/nonexistent/program.nc"),
        (vec!["expand", &file, "--bogus"], "--bogus"),
        (vec!["expand", &file, "--engine", "other"], "--engine"),
        (vec!["expand", &file, "--format", "xml"], "--format"),
        (vec!["expand", &file, "--dialect", "heidenhain"], "--dialect"),
        (vec!["expand", &file, "--units", "furlong"], "--units"),
        (vec!["expand", &file, "--increment", "isd"], "--increment"),
        (vec!["expand", &file, "--param", "5144=5"], "configuration"),
        (vec!["expand", &file, "--param", "9999=1"], "--param 9999"),
        (vec!["expand", &file, "--param", "19"], "--param"),
        (vec!["expand", &file, "--start-x", "1.0001"], "--start-x"),
        (vec!["expand", &file, "--start-z", "abc"], "--start-z"),
        (vec!["expand", &file, "--start-x", "1000000"], "--start-x"),
        (vec!["expand", &file, "--start-x"], "--start-x"),
        (vec!["expand", &file, &file], "unexpected argument"),
        (vec!["expand", &file, "--candidate", "x"], "--candidate"),
        (vec!["diff", &file, "--engine", "spec"], "--engine"),
        (vec!["diff", &file, "/nonexistent/other.nc"], "/nonexistent/other.nc"),
        (vec!["diff", "-", "-"], "standard input"),
        (vec!["diff", &file, "--timeout-ms", "0"], "--timeout-ms"),
        (vec!["corpus", "--format", "gcode"], "--format"),
        (vec!["corpus", "extra"], "extra"),
        (vec!["certify", "--cases", "many"], "--cases"),
        (vec!["certify", "--cycles", "g93"], "g93"),
        (vec!["certify", "--candidate", "'unterminated"], "--candidate"),
        (vec!["gate", "--cases", "-1"], "-1"),
        (vec!["gate", "--cases", "many"], "--cases"),
        (vec!["fuzz", "--targets", "nope"], "nope"),
        (vec!["fuzz", "--budget", "0"], "--budget"),
    ] {
        let o = run(&args);
        assert_eq!(code(&o), 2, "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(names), "{args:?} should name {names:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"), "{args:?}: {}", stderr(&o));
        assert!(stdout(&o).is_empty(), "{args:?}: {}", stdout(&o));
    }
}

/// `--help` of the tool and of every subcommand exits 0; `--version` names the build's commit.
#[test]
fn every_command_answers_help_and_version() {
    for command in ["", "expand", "diff", "corpus", "certify", "gate", "fuzz"] {
        let args: Vec<&str> = [command, "--help"].into_iter().filter(|a| !a.is_empty()).collect();
        let o = run(&args);
        assert_eq!(code(&o), 0, "{args:?}: {}", stderr(&o));
        assert!(stdout(&o).contains("Usage: cyclecheck"), "{args:?}: {}", stdout(&o));
    }
    let o = run(&["help", "certify"]);
    assert_eq!(code(&o), 0);
    assert!(stdout(&o).contains("--max-failures"), "{}", stdout(&o));
    let o = run(&["--version"]);
    assert_eq!(code(&o), 0);
    let version = stdout(&o);
    let commit = cyclecheck::certify::identity::BUILD.commit;
    let short = &commit[..commit.len().min(12)];
    assert!(version.starts_with("cyclecheck 0.") && version.contains(&format!("commit {short}")), "{version}");
}

/// The defaults `--help` states are the constants the code uses.
#[test]
fn help_states_the_true_defaults() {
    use cyclecheck::candidate::Limits;
    use cyclecheck::{certify, gate, nightly};
    let help = |c: &str| stdout(&run(&[c, "--help"])).split_whitespace().collect::<Vec<_>>().join(" ");
    // The default `--help` states for `option`.
    let stated = |help: &str, option: &str| -> Option<String> {
        let after = help.split(option).nth(1).unwrap_or_else(|| panic!("{option} missing: {help}"));
        after.split("[default: ").nth(1).and_then(|d| d.split(']').next()).map(str::to_string)
    };
    let (certify_help, gate_help) = (help("certify"), help("gate"));
    for (help, option, default) in [
        (&certify_help, "--out <DIR>", certify::DEFAULT_OUT.to_string()),
        (&certify_help, "--timeout-ms <MS>", Limits::DEFAULT_TIMEOUT_MS.to_string()),
        (&certify_help, "--max-output <BYTES>", Limits::DEFAULT_MAX_OUTPUT.to_string()),
        (&certify_help, "--max-failures <N>", certify::DEFAULT_MAX_FAILURES.to_string()),
        (&certify_help, "--cases <N>", certify::DEFAULT_CASES.to_string()),
        (&certify_help, "--seed <S>", certify::DEFAULT_SEED.to_string()),
        (&gate_help, "--cases <N>", gate::DEFAULT_CASES.to_string()),
        (&gate_help, "--seed <S>", gate::DEFAULT_SEED.to_string()),
        (&gate_help, "--test-cases <N>", gate::DEFAULT_TEST_CASES.to_string()),
        (&gate_help, "--proof-cases <N>", gate::DEFAULT_PROOF_CASES.to_string()),
    ] {
        assert_eq!(stated(help, option), Some(default), "{option} in\n{help}");
    }
    let fuzz_help = help("fuzz");
    assert!(fuzz_help.contains(&format!("[default: {}]", nightly::DEFAULT_BUDGET)), "{fuzz_help}");
    assert!(fuzz_help.contains(&format!("[default: {}]", nightly::DEFAULT_OUT)), "{fuzz_help}");
    let expand_help = help("expand");
    for default in ["[default: gsk]", "[default: metric]", "[default: isb]", "[default: spec]", "[default: gcode]"] {
        assert!(expand_help.contains(default), "{default}: {expand_help}");
    }
    assert_eq!(cycle_vocab::Config::default().dialect, cycle_vocab::Dialect::Gsk);
}

/// `-` reads the program from standard input.
#[test]
fn a_dash_reads_standard_input() {
    use std::io::Write as _;
    let program = std::fs::read(corpus_file("g92_example.nc")).unwrap();
    for args in [vec!["expand", "-"], vec!["diff", "-"]] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_cyclecheck"))
            .args(&args)
            .stdin(std::process::Stdio::piped())
            .stdout(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        child.stdin.take().unwrap().write_all(&program).unwrap();
        let o = child.wait_with_output().unwrap();
        assert_eq!(code(&o), 0, "{args:?}: {}", stderr(&o));
        let expected = match args[0] {
            "expand" => SpecEngine.expand(&program, &Config::default()).to_gcode(),
            _ => format!("conform: {} events\n", SpecEngine.expand(&program, &Config::default()).events.len()),
        };
        assert_eq!(stdout(&o), expected, "{args:?}");
    }
}

/// `diff` exits 1 on a divergence (printing it), else 0 — an alarm both engines raise is
/// conformance; the alarm is named on stderr.
#[test]
fn diff_exit_codes_follow_the_relation() {
    for p in corpus::PROGRAMS {
        let file = root().join(p.path);
        let params: Vec<String> = p.params.iter().map(|(n, v)| format!("{n}={v}")).collect();
        let mut args = vec!["diff", file.to_str().unwrap()];
        for v in &params {
            args.extend(["--param", v.as_str()]);
        }
        match p.config().dialect {
            cycle_vocab::Dialect::Gsk => {}
            cycle_vocab::Dialect::Fanuc => args.extend(["--dialect", "fanuc"]),
            cycle_vocab::Dialect::Nc201 => args.extend(["--dialect", "nc201"]),
        }
        if p.config().grid.units == cycle_vocab::Units::Inch {
            args.extend(["--units", "inch"]);
        }
        if p.config().grid.increment == cycle_vocab::Increment::Isc {
            args.extend(["--increment", "isc"]);
        }
        // The readings its header declares (`--reading` on the CLI since wp-oracle-readings).
        let readings: Vec<String> = p.readings.iter().map(|(n, v)| format!("--reading={n}={v}")).collect();
        args.extend(readings.iter().map(String::as_str));
        let o = run(&args);
        let reference = SpecEngine.expand(p.text.as_bytes(), &p.config());
        let candidate = ImplEngine.expand(p.text.as_bytes(), &p.config());
        match conformance::check(&reference, &candidate) {
            Err(d) => {
                assert_eq!(code(&o), 1, "{}", p.name);
                assert_eq!(stdout(&o).trim_end(), d.to_string(), "{}", p.name);
            }
            Ok(()) => {
                assert!(stdout(&o).starts_with(&format!("conform: {} events", reference.events.len())), "{}", p.name);
                assert_eq!(code(&o), 0, "{}", p.name);
                match reference.alarm {
                    Some(a) => assert_eq!(stderr(&o).trim_end(), conformance::alarm_summary(&a)),
                    None => assert!(stderr(&o).is_empty(), "{}", p.name),
                }
            }
        }
    }
}

/// `corpus` prints one line per program and a summary; exit 0 only when all conform.
#[test]
fn corpus_command_reports_every_program() {
    let all_conform = corpus::PROGRAMS.iter().all(|p| {
        let r = SpecEngine.expand(p.text.as_bytes(), &p.config());
        let c = ImplEngine.expand(p.text.as_bytes(), &p.config());
        conformance::check(&r, &c).is_ok()
    });
    let o = run(&["corpus"]);
    assert_eq!(code(&o), if all_conform { 0 } else { 1 }, "{}", stdout(&o));
    let out = stdout(&o);
    for p in corpus::PROGRAMS {
        let line = out.lines().find(|l| l.split_whitespace().next() == Some(p.name));
        let line = line.unwrap_or_else(|| panic!("no line for {}\n{out}", p.name));
        let t = SpecEngine.expand(p.text.as_bytes(), &p.config());
        assert!(line.contains(&format!("{} events", t.events.len())), "{line}");
        if all_conform && p.name == "g78_example" {
            assert!(line.ends_with("conform (alarm 2002 P G78.MODE)"), "{line}");
        }
    }
    let n = corpus::PROGRAMS.len();
    assert!(out.contains(&format!("{n} programs: ")), "{out}");

    let o = run(&["corpus", "--format", "json"]);
    assert_eq!(code(&o), if all_conform { 0 } else { 1 });
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).expect("JSON");
    assert_eq!(v["programs"].as_array().map(Vec::len), Some(n));
    assert_eq!(v["summary"]["programs"], n);
    assert_eq!(v["programs"][0]["name"], "g92_example");
    assert_eq!(v["programs"][0]["rules"][0], "G92.EXAMPLE");
}

/// No silent limit: a program of 700 000 modal G92 repeats — 4 200 007 events, past the 4 000 000
/// at which the production expander's trace used to be cut — expands whole with the production
/// expander (every pass printed), and `diff` finds both engines agree (exit 0).
#[test]
fn a_trace_of_millions_of_events_is_never_cut() {
    use std::io::Read as _;
    let repeats = 700_000;
    let mut program = b"G0 X65 Z5\nG92 X58.7 Z-28 F3 J3 K1\n".to_vec();
    program.extend(b"X58.7\n".repeat(repeats));
    let p = TempFile::new("g92_repeats.nc", &program);
    let o = run(&["diff", p.path()]);
    assert_eq!(code(&o), 0, "{}{}", stdout(&o), stderr(&o));
    assert_eq!(stdout(&o), format!("conform: {} events\n", 6 * (repeats + 1) + 1));
    let mut child = Command::new(env!("CARGO_BIN_EXE_cyclecheck"))
        .args(["expand", p.path(), "--engine", "impl"])
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let (mut passes, mut buf, mut carry) = (0usize, vec![0u8; 1 << 16], Vec::new());
    loop {
        let n = stdout.read(&mut buf).unwrap();
        if n == 0 {
            break;
        }
        carry.extend_from_slice(&buf[..n]);
        let end = carry.iter().rposition(|&b| b == b'\n').map_or(0, |i| i + 1);
        passes += carry[..end].split(|&b| b == b'\n').filter(|l| l.starts_with(b"(PASS ")).count();
        carry.drain(..end);
    }
    assert_eq!(child.wait().unwrap().code(), Some(0));
    assert_eq!(passes, repeats + 1, "every pass of every cycle is printed");
}
