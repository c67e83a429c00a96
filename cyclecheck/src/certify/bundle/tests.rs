use super::*;

fn tmp(name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("cyclecheck-bundle-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&d);
    fs::create_dir_all(&d).unwrap();
    d
}

#[test]
fn writes_then_replaces_a_bundle_leaving_no_staging() {
    let root = tmp("replace");
    let out = root.join("evidence");
    let one = vec![("evidence.json".to_string(), b"1".to_vec()), ("plots/a.svg".to_string(), b"<svg/>".to_vec())];
    write(&out, &one).unwrap();
    assert_eq!(fs::read(out.join("plots/a.svg")).unwrap(), b"<svg/>");
    let two = vec![("evidence.json".to_string(), b"2".to_vec())];
    write(&out, &two).unwrap();
    assert_eq!(fs::read(out.join("evidence.json")).unwrap(), b"2");
    assert!(!out.join("plots").exists(), "the old bundle is replaced whole");
    let leftovers: Vec<_> = fs::read_dir(&root).unwrap().map(|e| e.unwrap().file_name()).collect();
    assert_eq!(leftovers, vec![std::ffi::OsString::from("evidence")]);
    fs::remove_dir_all(&root).unwrap();
}

#[test]
fn refuses_to_replace_a_directory_that_is_no_bundle() {
    let root = tmp("refuse");
    fs::write(root.join("precious.txt"), b"keep").unwrap();
    let e = write(&root, &[("evidence.json".to_string(), b"1".to_vec())]).unwrap_err();
    assert_eq!(e.kind(), io::ErrorKind::AlreadyExists);
    assert_eq!(fs::read(root.join("precious.txt")).unwrap(), b"keep");
    fs::remove_dir_all(&root).unwrap();
}

#[test]
fn a_staging_directory_dropped_uncommitted_is_removed() {
    let root = tmp("drop");
    let out = root.join("evidence");
    let staging = Staging::create(&out).unwrap();
    staging.write("cases.jsonl", b"{}\n").unwrap();
    assert_eq!(fs::read_dir(&root).unwrap().count(), 1);
    drop(staging);
    assert_eq!(fs::read_dir(&root).unwrap().count(), 0, "no staging left, no bundle written");
    assert!(Staging::create(Path::new("..")).is_err() && Staging::create(Path::new("/")).is_err());
    fs::remove_dir_all(&root).unwrap();
}
