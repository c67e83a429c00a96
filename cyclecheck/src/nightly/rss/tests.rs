use super::*;

#[test]
fn reads_proc_stat() {
    assert_eq!(parse_stat("4242 (diff_spec_impl) S 4200 4242 1 0"), Some(("diff_spec_impl", 4200)));
    assert_eq!(parse_stat("7 (a (b) c) R 1 7"), Some(("a (b) c", 1)));
    assert_eq!(parse_stat("garbage"), None);
}

#[cfg(target_os = "linux")]
#[test]
fn sees_a_child_process() {
    let Ok(mut child) = std::process::Command::new("sleep").arg("1").spawn() else { return };
    let peak = sample(std::process::id(), "sleep");
    let _ = child.wait();
    assert!(peak.is_some_and(|kb| kb > 0), "{peak:?}");
}
