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

/// Key bits the radix sort orders by (the top ones, 22 per axis); lower bits only refine
/// cells of 2^-22 of the bounding box, where the recursion switches to lexicographic order.
const SORTED_KEY_BITS: u32 = 44;
const KEY_MASK: u64 = !0 << (64 - SORTED_KEY_BITS);
/// Radix digit: 2^11 counters stay in the L1/L2 caches while scattering.
const DIGIT_BITS: u32 = 11;

/// Monotone quantization of the bounding box.
#[derive(Debug, Clone, Copy)]
pub struct Grid {
    min: [f64; 2],
    scale: [f64; 2],
}

impl Grid {
    /// The grid of the bounding box of `points` (finite, not empty).
    pub fn new(points: &[[f64; 2]]) -> Grid {
        let mut lo = points[0];
        let mut hi = points[0];
        for p in points {
            for k in 0..2 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        // 2^32 / extent cannot overflow: the extent is 0 or at least 2^-194 (coordinates are
        // 0 or at least 2^-142 in magnitude). A zero extent puts everything in cell 0.
        let scale = |k: usize| {
            let extent = hi[k] - lo[k];
            if extent > 0.0 {
                4_294_967_296.0 / extent
            } else {
                0.0
            }
        };
        Grid {
            min: lo,
            scale: [scale(0), scale(1)],
        }
    }

    /// Cell index along axis `k`. Rounding is monotone and the cast saturates, so
    /// `cell(a) < cell(b)` implies `a[k] < b[k]`.
    #[inline]
    pub fn cell(&self, p: [f64; 2], k: usize) -> u32 {
        ((p[k] - self.min[k]) * self.scale[k]) as u32
    }

    /// The sorted part of the Morton key (lower bits zero).
    #[inline]
    pub fn key(&self, p: [f64; 2]) -> u64 {
        ((spread(self.cell(p, 0)) << 1) | spread(self.cell(p, 1))) & KEY_MASK
    }

    /// Is bit `b` of the key of `p` set?
    #[inline]
    pub fn key_bit(&self, p: [f64; 2], b: u32) -> bool {
        let axis = if b % 2 == 1 { 0 } else { 1 };
        (self.cell(p, axis) >> (b / 2)) & 1 == 1
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

/// The distinct points in key order (points with equal keys lexicographically), their input
/// indices, and the `[duplicate, kept]` pairs sorted by duplicate.
pub struct Ordered {
    pub points: Vec<[f64; 2]>,
    pub ids: Vec<u32>,
    pub duplicates: Vec<[u32; 2]>,
}

/// Orders `points` (finite, not empty) along the Z curve of `grid` and merges exact
/// duplicates into their first occurrence.
pub fn order(points: &[[f64; 2]], grid: &Grid) -> Ordered {
    let mut items: Vec<(u64, u32)> = points
        .iter()
        .enumerate()
        .map(|(i, &p)| (grid.key(p), i as u32))
        .collect();
    radix_sort(&mut items);
    // Equal keys: order by coordinates, then index, so duplicates are adjacent and the first
    // occurrence leads. Rare (cells are 2^-24 of the box), so a comparison sort is fine.
    let mut start = 0;
    while start < items.len() {
        let key = items[start].0;
        let mut end = start + 1;
        while end < items.len() && items[end].0 == key {
            end += 1;
        }
        if end - start > 1 {
            items[start..end].sort_unstable_by(|a, b| {
                lexicographic(points[a.1 as usize], points[b.1 as usize]).then(a.1.cmp(&b.1))
            });
        }
        start = end;
    }
    let mut ordered = Ordered {
        points: Vec::with_capacity(items.len()),
        ids: Vec::with_capacity(items.len()),
        duplicates: Vec::new(),
    };
    for (k, &(key, i)) in items.iter().enumerate() {
        let p = points[i as usize];
        if k > 0 && items[k - 1].0 == key {
            let kept = *ordered.ids.last().expect("a point precedes");
            if lexicographic(points[kept as usize], p).is_eq() {
                ordered.duplicates.push([i, kept]);
                continue;
            }
        }
        ordered.points.push(p);
        ordered.ids.push(i);
    }
    ordered.duplicates.sort_unstable();
    ordered
}

/// Stable least-significant-digit radix sort by the sorted key bits, [`DIGIT_BITS`] per
/// pass; passes whose digit is the same for every item are skipped.
fn radix_sort(items: &mut Vec<(u64, u32)>) {
    const PASSES: usize = (SORTED_KEY_BITS / DIGIT_BITS) as usize;
    const LOW: u32 = 64 - SORTED_KEY_BITS;
    const MASK: u64 = (1 << DIGIT_BITS) - 1;
    let n = items.len();
    let mut counts = vec![[0usize; 1 << DIGIT_BITS]; PASSES];
    for &(key, _) in items.iter() {
        for (d, count) in counts.iter_mut().enumerate() {
            count[((key >> (LOW + DIGIT_BITS * d as u32)) & MASK) as usize] += 1;
        }
    }
    let mut buffer: Vec<(u64, u32)> = Vec::new();
    for (d, count) in counts.iter_mut().enumerate() {
        if count.contains(&n) {
            continue;
        }
        if buffer.is_empty() {
            buffer = vec![(0, 0); n];
        }
        // Counts become start offsets.
        let mut sum = 0;
        for c in count.iter_mut() {
            (*c, sum) = (sum, sum + *c);
        }
        let shift = LOW + DIGIT_BITS * d as u32;
        for &item in items.iter() {
            let digit = ((item.0 >> shift) & MASK) as usize;
            buffer[count[digit]] = item;
            count[digit] += 1;
        }
        std::mem::swap(items, &mut buffer);
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
                s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
                [((s >> 40) % 16) as f64, ((s >> 20) % 16) as f64]
            })
            .collect();
        pts.push([1e-30, 1e-30]);
        pts.push([0.0, 0.0]);
        let g = Grid::new(&pts);
        let o = order(&pts, &g);
        assert!(o.points.windows(2).all(|w| g.key(w[0]) <= g.key(w[1])));
        assert_eq!(o.points.len() + o.duplicates.len(), pts.len());
        for &[dup, kept] in &o.duplicates {
            assert!(kept < dup);
            assert_eq!(pts[dup as usize], pts[kept as usize]);
            assert!(o.ids.contains(&kept));
        }
        for (k, &i) in o.ids.iter().enumerate() {
            assert_eq!(o.points[k], pts[i as usize]);
            assert!(pts[..i as usize].iter().all(|&p| p != pts[i as usize]), "first kept");
        }
    }
}
