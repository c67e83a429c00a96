//! `--shard K/N`: one of N slices of a run. Each source of cases — the corpus, and each
//! family's generator — numbers its cases from 0; case `i` belongs to shard `i mod N + 1`. A
//! shard draws every generated case (the generators' random streams stay those of the whole
//! run) and judges only its own, so shards 1/N … N/N judge exactly the cases of the unsharded
//! run, each once; `cyclecheck merge` ([`super::merge`]) joins their bundles.

use serde::Serialize;
use std::fmt;

/// Shard `index` (1-based) of `count`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub struct Shard {
    pub index: u32,
    pub count: u32,
}

impl Shard {
    /// Parses `K/N` with 1 ≤ K ≤ N.
    pub fn parse(text: &str) -> Result<Shard, String> {
        let usage = || format!("--shard takes K/N with 1 <= K <= N (e.g. 1/4), not {text:?}");
        let (k, n) = text.split_once('/').ok_or_else(usage)?;
        let number = |s: &str| s.trim().parse::<u32>().map_err(|_| usage());
        let (index, count) = (number(k)?, number(n)?);
        if index == 0 || count == 0 || index > count {
            return Err(usage());
        }
        Ok(Shard { index, count })
    }

    /// Whether the case numbered `i` in its source is this shard's.
    pub fn contains(self, i: usize) -> bool {
        i % self.count as usize == (self.index - 1) as usize
    }

    /// Whether case `i` is in a run sharded by `shard` (every case when unsharded).
    pub fn includes(shard: Option<Shard>, i: usize) -> bool {
        shard.is_none_or(|s| s.contains(i))
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

/// A shard as a merged bundle lists it: where and when it ran, how long, how many cases.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ShardRun {
    /// `K/N`.
    pub shard: String,
    /// The shard's bundle directory as given to `merge`.
    pub bundle: String,
    pub started_utc: String,
    pub host: String,
    pub duration_s: f64,
    pub cases: usize,
}

#[cfg(test)]
mod tests {
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
}
