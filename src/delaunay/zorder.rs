//! Z-order (Morton order) of the input: the recursion tree of the divide and conquer.
//!
//! Coordinates are quantized to 2^32 cells per axis of the bounding box, monotonically (a
//! smaller cell means a strictly smaller coordinate), and the cell indices are bit-interleaved
//! into a key whose bit `2j + 1` is bit `j` of the x cell and bit `2j` bit `j` of the y cell.
//! In key order, the points sharing a key prefix are contiguous, and the first bit below the
//! prefix splits them by a vertical (odd bit) or horizontal (even bit) line: Dwyer's
//! alternating cuts, found by a binary search instead of a median selection per level. The
//! order depends on coordinates only, never on input positions.

use std::cmp::Ordering;

#[cfg(feature = "parallel")]
mod parallel;

/// Radix digit: 2^11 counters stay in the L1/L2 caches while scattering.
const DIGIT_BITS: u32 = 11;

/// Monotone quantization of the bounding box.
///
/// Only the top bits of the key are sorted: the low `index_bits` carry the input index while
/// sorting, so an item is one `u64` (44 key bits for 10^6 points, 32 for 2^32). Points that
/// share a key anyway (a dense cluster far from outliers) are re-quantized on their own
/// bounding box.
#[derive(Debug, Clone, Copy)]
pub struct Grid {
    min: [f64; 2],
    /// 1, or for an extent below 2^-900 the power of two that makes `2^32 / extent` finite.
    pre: [f64; 2],
    scale: [f64; 2],
    index_bits: u32,
}

impl Grid {
    /// The grid of the bounding box of `points` (finite, not empty).
    pub fn new(points: &[[f64; 2]]) -> Grid {
        let index_bits = u64::BITS - (points.len() as u64 - 1).leading_zeros();
        Grid::of_box(points.iter().copied(), index_bits)
    }

    /// The grid of the bounding box of `points` (finite, not empty), for items whose low
    /// `index_bits` hold an index.
    pub fn of_box(points: impl Iterator<Item = [f64; 2]>, index_bits: u32) -> Grid {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        // Any finite coordinates: an extent that overflows is taken in halves, and a tiny
        // one (subnormal coordinates) is scaled up before 2^32 / extent is formed. A zero
        // extent puts everything in cell 0.
        let axis = |k: usize| -> (f64, f64) {
            const CELLS: f64 = 4_294_967_296.0; // 2^32
            const TINY: f64 = 1.1830521861667747e-271; // 2^-900
            const PRE: f64 = 4.149515568880993e180; // 2^600
            let extent = hi[k] - lo[k];
            if extent <= 0.0 {
                (1.0, 0.0)
            } else if extent == f64::INFINITY {
                (1.0, CELLS / 2.0 / (hi[k] * 0.5 - lo[k] * 0.5))
            } else if extent < TINY {
                (PRE, CELLS / (extent * PRE))
            } else {
                (1.0, CELLS / extent)
            }
        };
        let (x, y) = (axis(0), axis(1));
        Grid {
            min: lo,
            pre: [x.0, y.0],
            scale: [x.1, y.1],
            index_bits,
        }
    }

    /// Cell index along axis `k`. Rounding is monotone and the cast saturates, so
    /// `cell(a) < cell(b)` implies `a[k] < b[k]`.
    #[inline]
    pub fn cell(&self, p: [f64; 2], k: usize) -> u32 {
        ((p[k] - self.min[k]) * self.pre[k] * self.scale[k]) as u32
    }

    /// The sorted part of the Morton key (the low `index_bits` zero).
    #[inline]
    pub fn key(&self, p: [f64; 2]) -> u64 {
        let key = (spread(self.cell(p, 0)) << 1) | spread(self.cell(p, 1));
        key >> self.index_bits << self.index_bits
    }

    /// Input index of a sorted item.
    #[inline]
    pub fn index(&self, item: u64) -> u32 {
        (item & ((1 << self.index_bits) - 1)) as u32
    }

    /// Position of key bit `b` (`b ≥ index_bits`) in an item: items are keys with the low
    /// bits replaced by the index.
    #[inline]
    pub fn index_bits(&self) -> u32 {
        self.index_bits
    }
}

/// Spreads the 32 bits of `v` to the even bit positions of a `u64`.
#[inline]
fn spread(v: u32) -> u64 {
    let mut x = u64::from(v);
    x = (x | (x << 16)) & 0x0000_FFFF_0000_FFFF;
    x = (x | (x << 8)) & 0x00FF_00FF_00FF_00FF;
    x = (x | (x << 4)) & 0x0F0F_0F0F_0F0F_0F0F;
    x = (x | (x << 2)) & 0x3333_3333_3333_3333;
    (x | (x << 1)) & 0x5555_5555_5555_5555
}

/// Lexicographic order of coordinates; `-0.0 == 0.0`, inputs are finite.
#[inline]
pub fn lexicographic(a: [f64; 2], b: [f64; 2]) -> Ordering {
    a[0].partial_cmp(&b[0])
        .unwrap_or(Ordering::Equal)
        .then(a[1].partial_cmp(&b[1]).unwrap_or(Ordering::Equal))
}

/// The distinct points in key order (points with equal keys lexicographically), their
/// items (key in the high bits, input index in the low [`Grid::index_bits`]), and the
/// `[duplicate, kept]` pairs sorted by duplicate.
pub struct Ordered {
    pub points: Vec<[f64; 2]>,
    pub items: Vec<u64>,
    pub duplicates: Vec<[u32; 2]>,
}

/// Orders `points` (finite, not empty) along the Z curve of `grid` and merges exact
/// duplicates into their first occurrence.
pub fn order(points: &[[f64; 2]], grid: &Grid) -> Ordered {
    let mut items = keyed_items(points, grid);
    sort_items(&mut items, grid.index_bits);
    // The points are copied into key order before the runs of equal keys are settled, so
    // that settling and the duplicate test read them in order beside their items. Read
    // through the input indices instead, every point of a run is a cache miss: a tenth of
    // the triangulation of 10^7 random samples of a curve, whose keys of 40 bits put a few
    // points in many cells.
    let mut sorted = points_in_order(points, &items, grid);
    let mut duplicates = settle_and_drop_duplicates(&mut items, &mut sorted, points, grid);
    if !duplicates.is_empty() {
        // The points are kept with the triangulation: not the room of the copies.
        sorted.shrink_to_fit();
    }
    duplicates.sort_unstable();
    Ordered {
        points: sorted,
        items,
        duplicates,
    }
}

/// Settles the runs of equal keys of the sorted `items` and of their points `sorted` (item
/// by item), and drops the duplicates from both, keeping each point's first occurrence;
/// returns the `[duplicate, kept]` pairs, unsorted. `input` is the caller's points.
fn settle_and_drop_duplicates(
    items: &mut Vec<u64>,
    sorted: &mut Vec<[f64; 2]>,
    input: &[[f64; 2]],
    grid: &Grid,
) -> Vec<[u32; 2]> {
    #[cfg(feature = "parallel")]
    if parallel::pays(items.len()) {
        return parallel::settle_and_drop_duplicates(items, sorted, input, grid);
    }
    let piece = Run {
        items,
        points: sorted,
    };
    let (kept, duplicates) = settle_piece(piece, input, grid);
    items.truncate(kept);
    sorted.truncate(kept);
    duplicates
}

/// Items and their points, item by item: a piece of the sorted order.
struct Run<'a> {
    items: &'a mut [u64],
    points: &'a mut [[f64; 2]],
}

impl Run<'_> {
    fn len(&self) -> usize {
        self.items.len()
    }

    /// The sub-run `range`.
    fn at(&mut self, range: std::ops::Range<usize>) -> Run<'_> {
        Run {
            items: &mut self.items[range.clone()],
            points: &mut self.points[range],
        }
    }

    /// Sorts the items and their points together as `(item, point)` pairs by `order`, in
    /// the working space `scratch`.
    fn sort_pairs_by(
        &mut self,
        scratch: &mut Vec<(u64, [f64; 2])>,
        order: impl FnMut(&(u64, [f64; 2]), &(u64, [f64; 2])) -> Ordering,
    ) {
        scratch.clear();
        scratch.extend(self.items.iter().copied().zip(self.points.iter().copied()));
        scratch.sort_unstable_by(order);
        for (k, &(item, p)) in scratch.iter().enumerate() {
            (self.items[k], self.points[k]) = (item, p);
        }
    }
}

/// [`settle_runs`] on `piece`, a whole number of runs of equal keys, then the duplicates
/// dropped in place (only equal keys need coordinates, and they are in one run): returns how
/// many items are kept, at the front of `piece`, and the `[duplicate, kept]` pairs.
fn settle_piece(mut piece: Run, input: &[[f64; 2]], grid: &Grid) -> (usize, Vec<[u32; 2]>) {
    settle_runs(
        piece.at(0..piece.len()),
        input,
        grid.index_bits,
        &mut Vec::new(),
    );
    let key_mask = !0u64 << grid.index_bits;
    let Run { items, points } = piece;
    let mut duplicates = Vec::new();
    let mut w = 0;
    for k in 0..items.len() {
        let (item, p) = (items[k], points[k]);
        let same_key = w > 0 && (items[w - 1] ^ item) & key_mask == 0;
        if same_key && lexicographic(points[w - 1], p).is_eq() {
            duplicates.push([grid.index(item), grid.index(items[w - 1])]);
            continue;
        }
        items[w] = item;
        points[w] = p;
        w += 1;
    }
    (w, duplicates)
}

/// The items of `points` in input order: key in the high bits, input index in the low ones.
fn keyed_items(points: &[[f64; 2]], grid: &Grid) -> Vec<u64> {
    #[cfg(feature = "parallel")]
    if parallel::pays(points.len()) {
        return parallel::keyed_items(points, grid);
    }
    points
        .iter()
        .enumerate()
        .map(|(i, &p)| grid.key(p) | i as u64)
        .collect()
}

/// The points of `items` (one item per input point), in their order.
fn points_in_order(points: &[[f64; 2]], items: &[u64], grid: &Grid) -> Vec<[f64; 2]> {
    #[cfg(feature = "parallel")]
    if parallel::pays(items.len()) {
        return parallel::points_in_order(points, items, grid);
    }
    // Scatter the ranks, then read the input in order and write each point to its rank:
    // scattered writes do not stall the way scattered reads (a gather) do. (A gather on two
    // threads took as long as this on one: 5.2 against 5.4 ms at 10^6 points.)
    let mut rank = vec![0u32; points.len()];
    for (k, &item) in items.iter().enumerate() {
        rank[grid.index(item) as usize] = k as u32;
    }
    let mut sorted = vec![[0.0; 2]; items.len()];
    for (&p, &r) in points.iter().zip(&rank) {
        sorted[r as usize] = p;
    }
    sorted
}

/// The input index of every item.
pub fn input_indices(items: &[u64], grid: &Grid) -> Vec<u32> {
    #[cfg(feature = "parallel")]
    if parallel::pays(items.len()) {
        return parallel::input_indices(items, grid);
    }
    items.iter().map(|&item| grid.index(item)).collect()
}

/// Orders every run of items with equal keys, their points along, so that exact duplicates
/// are adjacent, the first occurrence first: short runs lexicographically (then by index);
/// long runs (a wide spread of scales, or many samples in little room) along the Z curve of
/// their own bounding box first, recursively, so that no long run is comparison-sorted by
/// coordinates. The keys of a run stay equal, so the divide and conquer re-keys it the same
/// way when it gets there. `scratch` is working space for the sorts.
fn settle_runs(
    mut run: Run,
    input: &[[f64; 2]],
    index_bits: u32,
    scratch: &mut Vec<(u64, [f64; 2])>,
) {
    const SHORT: usize = 64;
    let key_mask = !0u64 << index_bits;
    let index = |item: u64| item & !key_mask;
    let mut start = 0;
    while start < run.len() {
        let key = run.items[start] & key_mask;
        let mut end = start + 1;
        while end < run.len() && run.items[end] & key_mask == key {
            end += 1;
        }
        let mut equal = run.at(start..end);
        let n = equal.len();
        let mut sorted = false;
        if n > SHORT {
            let local = Grid::of_box(equal.points.iter().copied(), index_bits);
            for (item, &p) in equal.items.iter_mut().zip(equal.points.iter()) {
                *item = local.key(p) | index(*item);
            }
            sort_by_items(equal.at(0..n), input, index_bits, scratch);
            // Distinct points in the run split it; copies of one point do not.
            if (equal.items[0] ^ equal.items[n - 1]) & key_mask != 0 {
                settle_runs(equal.at(0..n), input, index_bits, scratch);
                sorted = true;
            }
            for item in equal.items.iter_mut() {
                *item = key | index(*item);
            }
        }
        if !sorted && n > 1 {
            equal.sort_pairs_by(scratch, |a, b| {
                lexicographic(a.1, b.1).then(index(a.0).cmp(&index(b.0)))
            });
        }
        start = end;
    }
}

/// Sorts a run by its items (key, then index), its points along: as pairs where a
/// comparison sort is the faster, else the items alone by radix and then the points read
/// again from the `input`.
fn sort_by_items(
    mut run: Run,
    input: &[[f64; 2]],
    index_bits: u32,
    scratch: &mut Vec<(u64, [f64; 2])>,
) {
    if run.len() > 1 << 12 {
        sort_items(run.items, index_bits);
        let index_mask = (1u64 << index_bits) - 1;
        for (p, &item) in run.points.iter_mut().zip(run.items.iter()) {
            *p = input[(item & index_mask) as usize];
        }
        return;
    }
    run.sort_pairs_by(scratch, |a, b| a.0.cmp(&b.0));
}

/// Sorts items by key, then index (as a stable sort by key would): a radix sort, or for few
/// items, where its fixed cost (2^11 counters per pass) dominates, a comparison sort. The
/// items are distinct (each holds its index), so every way of sorting them gives the same
/// array: many items are sorted on all threads.
fn sort_items(items: &mut [u64], low: u32) {
    if items.len() <= 1 << 12 {
        items.sort_unstable();
        return;
    }
    #[cfg(feature = "parallel")]
    if parallel::pays(items.len()) {
        return parallel::sort_items(items, low);
    }
    radix_sort(items, low);
}

/// Stable least-significant-digit radix sort by the bits above `low`, [`DIGIT_BITS`] per
/// pass; passes whose digit is the same for every item are skipped.
fn radix_sort(items: &mut [u64], low: u32) {
    const MASK: u64 = (1 << DIGIT_BITS) - 1;
    let passes = (u64::BITS - low).div_ceil(DIGIT_BITS) as usize;
    let n = items.len();
    let mut counts = vec![[0usize; 1 << DIGIT_BITS]; passes];
    for &key in items.iter() {
        for (d, count) in counts.iter_mut().enumerate() {
            count[((key >> (low + DIGIT_BITS * d as u32)) & MASK) as usize] += 1;
        }
    }
    let mut buffer: Vec<u64> = Vec::new();
    // Passes alternate between `items` and `buffer`; true when the latest order is in `buffer`.
    let mut in_buffer = false;
    for (d, count) in counts.iter_mut().enumerate() {
        if count.contains(&n) {
            continue;
        }
        if buffer.is_empty() {
            buffer = vec![0; n];
        }
        // Counts become start offsets.
        let mut sum = 0;
        for c in count.iter_mut() {
            (*c, sum) = (sum, sum + *c);
        }
        let shift = low + DIGIT_BITS * d as u32;
        if in_buffer {
            scatter(&buffer, items, count, shift);
        } else {
            scatter(items, &mut buffer, count, shift);
        }
        in_buffer = !in_buffer;
    }
    if in_buffer {
        items.copy_from_slice(&buffer);
    }
}

/// One radix pass: `src` into `dst` by the digit at `shift`, `offset` the start of each digit.
#[inline]
fn scatter(src: &[u64], dst: &mut [u64], offset: &mut [usize], shift: u32) {
    for &item in src {
        let digit = ((item >> shift) & ((1 << DIGIT_BITS) - 1)) as usize;
        dst[offset[digit]] = item;
        offset[digit] += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_interleaves() {
        assert_eq!(spread(0b1011), 0b100_0101);
        assert_eq!(spread(u32::MAX), 0x5555_5555_5555_5555);
    }

    #[test]
    fn radix_sort_equals_a_comparison_sort() {
        let mut s = 11u64;
        for (n, low) in [(1, 0), (5000, 13), (20_000, 15), (3000, 32)] {
            let mut items: Vec<u64> = (0..n)
                .map(|i| {
                    s = s
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    // Few distinct keys in the high bits (equal keys keep the index order).
                    ((s >> 60) << 60) | ((s >> 20) & 0xFFFF) << low | i as u64
                })
                .collect();
            let mut expected = items.clone();
            expected.sort_unstable();
            radix_sort(&mut items, low);
            assert_eq!(items, expected);
        }
    }

    #[test]
    fn cells_are_monotone_and_cover_the_box() {
        let pts = [[-3.0, 1.0], [5.0, 1.0], [1.0, 1.0]];
        let g = Grid::new(&pts);
        assert_eq!(g.cell(pts[0], 0), 0);
        assert_eq!(g.cell(pts[1], 0), u32::MAX);
        assert_eq!(g.cell(pts[2], 0), 1 << 31);
        assert_eq!(g.cell(pts[2], 1), 0, "zero extent: one cell");
    }

    #[test]
    fn order_sorts_by_key_and_merges_duplicates() {
        let mut s = 7u64;
        let mut pts: Vec<[f64; 2]> = (0..500)
            .map(|_| {
                s = s
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                [((s >> 40) % 16) as f64, ((s >> 20) % 16) as f64]
            })
            .collect();
        pts.push([1e-30, 1e-30]);
        pts.push([0.0, 0.0]);
        let g = Grid::new(&pts);
        let o = order(&pts, &g);
        assert!(o.points.windows(2).all(|w| g.key(w[0]) <= g.key(w[1])));
        assert_eq!(o.points.len() + o.duplicates.len(), pts.len());
        let ids: Vec<u32> = o.items.iter().map(|&item| g.index(item)).collect();
        for &[dup, kept] in &o.duplicates {
            assert!(kept < dup);
            assert_eq!(pts[dup as usize], pts[kept as usize]);
            assert!(ids.contains(&kept));
        }
        for (k, &i) in ids.iter().enumerate() {
            assert_eq!(o.points[k], pts[i as usize]);
            assert!(
                pts[..i as usize].iter().all(|&p| p != pts[i as usize]),
                "first kept"
            );
        }
    }
}
