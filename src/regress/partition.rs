//! Shards of a suite for the machines of a CI matrix: `--partition K/N` renders the scenes
//! whose name hashes to K of N, as cargo-nextest's `--partition hash:K/N` does (deqp-runner's
//! `--fraction` deals tests out by position instead, which moves them when one is added).
//!
//! The hash is of the scene's name alone (its path below the folder given, without `.toml`,
//! with `/` between folders), never of its place in the suite, so adding or removing a scene
//! moves no other scene between shards. It is FNV-1a (64 bits) over the name's UTF-8 bytes,
//! then SplitMix64's finalizer (FNV's low bits alone spread similar names poorly), modulo N:
//! shard K holds the names whose value is K − 1. Any tool can recompute it.

use std::fmt;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

/// Shard `index` (1-based) of `count`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Partition {
    /// Which shard, 1..=count.
    pub index: u32,
    /// How many shards the suite is split into.
    pub count: u32,
}

/// A `--partition` value that is not `K/N` with 1 ≤ K ≤ N.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("--partition {given:?}: {problem}; expected K/N with whole numbers 1 <= K <= N, e.g. 2/4")]
pub struct PartitionError {
    /// The text given.
    pub given: String,
    /// What is wrong with it.
    pub problem: &'static str,
}

impl Partition {
    /// Whether the scene named `name` belongs to this shard.
    pub fn contains(&self, name: &str) -> bool {
        stable_hash(name) % u64::from(self.count) == u64::from(self.index - 1)
    }
}

impl fmt::Display for Partition {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Partition {
    type Err = PartitionError;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let refuse = |problem| PartitionError {
            given: s.to_owned(),
            problem,
        };
        let (k, n) = s.trim().split_once('/').ok_or_else(|| refuse("no '/'"))?;
        let index: u32 = k.trim().parse().map_err(|_| refuse("K is not a whole number"))?;
        let count: u32 = n.trim().parse().map_err(|_| refuse("N is not a whole number"))?;
        if count == 0 {
            return Err(refuse("N is 0"));
        }
        if index == 0 || index > count {
            return Err(refuse("K is outside 1..=N"));
        }
        Ok(Partition { index, count })
    }
}

/// The shard hash of a scene name (see the module's documentation).
pub fn stable_hash(name: &str) -> u64 {
    const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
    const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;
    let mut h = FNV_OFFSET;
    for byte in name.bytes() {
        h ^= u64::from(byte);
        h = h.wrapping_mul(FNV_PRIME);
    }
    // SplitMix64's finalizer.
    h ^= h >> 30;
    h = h.wrapping_mul(0xbf58_476d_1ce4_e5b9);
    h ^= h >> 27;
    h = h.wrapping_mul(0x94d0_49bb_1331_11eb);
    h ^ (h >> 31)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv_1a_of_known_inputs() {
        // FNV-1a 64's published values, before the finalizer: "" is the offset basis and
        // "a" is 0xaf63dc4c8601ec8c; the finalizer is a bijection, so equal inputs of it
        // give equal outputs and the shard depends on the name alone.
        fn fnv(name: &str) -> u64 {
            name.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
                (h ^ u64::from(b)).wrapping_mul(0x100_0000_01b3)
            })
        }
        assert_eq!(fnv(""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv("a"), 0xaf63_dc4c_8601_ec8c);
        assert_ne!(stable_hash("a"), stable_hash("b"));
        assert_eq!(stable_hash("dir/scene"), stable_hash("dir/scene"));
    }

    #[test]
    fn every_name_falls_in_exactly_one_shard() {
        for count in 1..=7 {
            let shards: Vec<Partition> = (1..=count).map(|index| Partition { index, count }).collect();
            for i in 0..500 {
                let name = format!("suite/scene_{i:03}");
                assert_eq!(
                    shards.iter().filter(|p| p.contains(&name)).count(),
                    1,
                    "{name} in {count}"
                );
            }
        }
    }

    #[test]
    fn shards_are_roughly_even() {
        let count = 4;
        let sizes: Vec<usize> = (1..=count)
            .map(|index| {
                (0..2000)
                    .filter(|i| Partition { index, count }.contains(&format!("s{i}")))
                    .count()
            })
            .collect();
        // 500 expected each; a binomial's standard deviation here is about 19.
        assert!(sizes.iter().all(|&n| (420..=580).contains(&n)), "{sizes:?}");
    }

    #[test]
    fn partitions_parse_and_refuse() {
        assert_eq!("2/4".parse(), Ok(Partition { index: 2, count: 4 }));
        assert_eq!(" 1 / 1 ".parse(), Ok(Partition { index: 1, count: 1 }));
        for (bad, problem) in [
            ("0/3", "outside"),
            ("4/3", "outside"),
            ("1/0", "N is 0"),
            ("1-3", "no '/'"),
            ("a/3", "K is not"),
            ("1/b", "N is not"),
        ] {
            let e = bad.parse::<Partition>().unwrap_err();
            assert!(e.to_string().contains(problem), "{bad}: {e}");
            assert!(e.to_string().contains(bad), "{bad}: {e}");
        }
    }
}
