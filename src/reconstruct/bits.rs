//! A set of indices below a fixed bound, one bit each: the loops' half-edges and the leaves
//! waiting to be tested (medial axis), the points a repair's removed edges touch.

pub(super) struct Bits(Vec<u64>);

impl Bits {
    pub(super) fn new(count: usize) -> Bits {
        Bits(vec![0; count.div_ceil(64)])
    }

    pub(super) fn set(&mut self, i: usize) {
        self.0[i / 64] |= 1 << (i % 64);
    }

    pub(super) fn get(&self, i: usize) -> bool {
        self.0[i / 64] >> (i % 64) & 1 == 1
    }

    /// The smallest index in the set within `from..to`, reading a word at a time.
    pub(super) fn first_in(&self, from: usize, to: usize) -> Option<usize> {
        let end = to.min(self.0.len() * 64);
        let mut word = from / 64;
        if from >= end {
            return None;
        }
        // The bits below `from` in its word are masked off.
        let mut bits = self.0[word] & (u64::MAX << (from % 64));
        while bits == 0 {
            word += 1;
            if word * 64 >= end {
                return None;
            }
            bits = self.0[word];
        }
        Some(word * 64 + bits.trailing_zeros() as usize).filter(|&i| i < end)
    }

    /// Removes and returns the smallest index at least `from`.
    pub(super) fn take_first_from(&mut self, from: usize) -> Option<usize> {
        let i = self.first_in(from, usize::MAX)?;
        self.0[i / 64] &= !(1 << (i % 64));
        Some(i)
    }
}

/// A [`Bits`] that also answers how many of its members are smaller than an index: the
/// position of a member among them, in O(1) from a count per word (4 bytes per 64 indices).
pub(super) struct RankedBits {
    bits: Bits,
    /// Members in the words before each word.
    before: Vec<u32>,
}

impl RankedBits {
    /// `bits` must have fewer than `u32::MAX` members.
    pub(super) fn new(bits: Bits) -> RankedBits {
        let mut count = 0u32;
        let before = (bits.0.iter())
            .map(|word| {
                let here = count;
                count += word.count_ones();
                here
            })
            .collect();
        RankedBits { bits, before }
    }

    /// The number of members.
    pub(super) fn len(&self) -> usize {
        self.before.last().map_or(0, |&b| b as usize)
            + self.bits.0.last().map_or(0, |w| w.count_ones() as usize)
    }

    /// The position of `i` among the members, in increasing order, when it is one.
    pub(super) fn rank(&self, i: usize) -> Option<u32> {
        let word = self.bits.0[i / 64];
        (word >> (i % 64) & 1 == 1)
            .then(|| self.before[i / 64] + (word & ((1u64 << (i % 64)) - 1)).count_ones())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use wdm_crust_testkit::Rng;

    /// `first_in`, `take_first_from` and the ranks against a scan of a plain array, at every
    /// window edge of sparse and dense sets.
    #[test]
    fn searches_and_ranks_agree_with_a_plain_scan() {
        let mut rng = Rng::new(21);
        for round in 0..100 {
            let count = 1 + rng.below(400);
            let density = [0.01, 0.2, 0.9][round % 3];
            let plain: Vec<bool> = (0..count).map(|_| rng.f64() < density).collect();
            let mut bits = Bits::new(count);
            for i in (0..count).filter(|&i| plain[i]) {
                bits.set(i);
            }
            for from in 0..=count + 1 {
                for to in [from, from + 1, from + 63, from + 64, from + 200, usize::MAX] {
                    let expected = (from..to.min(count)).find(|&i| plain[i]);
                    assert_eq!(bits.first_in(from, to), expected, "{from}..{to}");
                }
            }
            let ranked = RankedBits::new(Bits(bits.0.clone()));
            let members: Vec<usize> = (0..count).filter(|&i| plain[i]).collect();
            assert_eq!(ranked.len(), members.len());
            for i in 0..count {
                let expected = members.iter().position(|&m| m == i).map(|k| k as u32);
                assert_eq!(ranked.rank(i), expected, "rank of {i}");
            }
            let mut taken = Vec::new();
            while let Some(i) = bits.take_first_from(0) {
                assert!(!bits.get(i));
                taken.push(i);
            }
            assert_eq!(taken, (0..count).filter(|&i| plain[i]).collect::<Vec<_>>());
        }
    }
}
