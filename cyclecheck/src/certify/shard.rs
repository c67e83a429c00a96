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
mod tests;
