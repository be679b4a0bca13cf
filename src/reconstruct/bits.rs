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

    /// Removes and returns the smallest index at least `from`, reading a word at a time.
    pub(super) fn take_first_from(&mut self, from: usize) -> Option<usize> {
        let mut word = from / 64;
        // The bits below `from` in its word are masked off.
        let mut bits = *self.0.get(word)? & (u64::MAX << (from % 64));
        while bits == 0 {
            word += 1;
            bits = *self.0.get(word)?;
        }
        let i = word * 64 + bits.trailing_zeros() as usize;
        self.0[word] &= !(1 << (i % 64));
        Some(i)
    }
}
