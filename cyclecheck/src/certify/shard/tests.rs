use super::*;

#[test]
fn parses_k_of_n_and_refuses_the_rest() {
    assert_eq!(Shard::parse("1/4"), Ok(Shard { index: 1, count: 4 }));
    assert_eq!(Shard::parse("4/4").map(|s| s.to_string()), Ok("4/4".to_string()));
    assert_eq!(Shard::parse("1/1"), Ok(Shard { index: 1, count: 1 }));
    for bad in ["0/4", "5/4", "a/b", "1/0", "0/0", "4", "", "1/4/2", "-1/4", "1/"] {
        let e = Shard::parse(bad).unwrap_err();
        assert!(e.starts_with("--shard takes K/N with 1 <= K <= N"), "{bad}: {e}");
    }
}

#[test]
fn every_case_is_in_exactly_one_shard() {
    for n in 1..=5u32 {
        for i in 0..50 {
            let owners = (1..=n).filter(|&k| Shard { index: k, count: n }.contains(i)).count();
            assert_eq!(owners, 1, "case {i} of {n} shards");
        }
    }
    assert!(Shard::includes(None, 7));
}
