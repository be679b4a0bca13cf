//! The Z order of many points on all threads (feature `parallel`): the keys, their sort, the
//! runs of equal keys and the duplicates in them, the copy of the points into key order, and
//! the input index of each item at the end.
//!
//! Every result is the sequential one: the keys, points and indices are maps, item by item;
//! the sort is a stable sort by key (the two halves radix-sorted at the same time, then
//! merged stably in independent pieces), which leaves one possible array; and runs of equal
//! keys, where all the settling and duplicate merging happens, never straddle two pieces.

use rayon::prelude::*;

use super::{radix_sort, settle_piece, Grid, Run};

/// Inputs of at least this many points are ordered on all threads (below, the fork and the
/// merge's extra pass cost more than they save).
const MIN_POINTS: usize = 1 << 16;

/// Items per piece when runs of equal keys are settled (a piece grows to the end of the run
/// its nominal end falls in).
const SETTLE_GRAIN: usize = 1 << 16;

/// Pieces of a merge at most this long are merged on one thread.
const MERGE_GRAIN: usize = 1 << 15;

/// Are `n` items worth ordering on all threads (more than one in the current pool)?
pub(super) fn pays(n: usize) -> bool {
    n >= MIN_POINTS && rayon::current_num_threads() > 1
}

/// [`super::keyed_items`] on all threads.
pub(super) fn keyed_items(points: &[[f64; 2]], grid: &Grid) -> Vec<u64> {
    points
        .par_iter()
        .enumerate()
        .map(|(i, &p)| grid.key(p) | i as u64)
        .collect()
}

/// [`super::settle_and_drop_duplicates`] on all threads: the sorted items and their points
/// cut into pieces at run boundaries, each settled on its own, the kept ones then moved
/// together.
pub(super) fn settle_and_drop_duplicates(
    items: &mut Vec<u64>,
    sorted: &mut Vec<[f64; 2]>,
    input: &[[f64; 2]],
    grid: &Grid,
) -> Vec<[u32; 2]> {
    let key_mask = !0u64 << grid.index_bits();
    let mut starts = vec![0];
    let mut end = SETTLE_GRAIN;
    while end < items.len() {
        while end < items.len() && (items[end - 1] ^ items[end]) & key_mask == 0 {
            end += 1;
        }
        if end < items.len() {
            starts.push(end);
        }
        end += SETTLE_GRAIN;
    }
    let mut pieces = Vec::with_capacity(starts.len());
    let (mut rest_items, mut rest_points) = (items.as_mut_slice(), sorted.as_mut_slice());
    for w in starts.windows(2) {
        let (piece_items, tail_items) = rest_items.split_at_mut(w[1] - w[0]);
        let (piece_points, tail_points) = rest_points.split_at_mut(w[1] - w[0]);
        pieces.push(Run {
            items: piece_items,
            points: piece_points,
        });
        (rest_items, rest_points) = (tail_items, tail_points);
    }
    pieces.push(Run {
        items: rest_items,
        points: rest_points,
    });
    let settled: Vec<(usize, Vec<[u32; 2]>)> = pieces
        .into_par_iter()
        .map(|piece| settle_piece(piece, input, grid))
        .collect();
    let mut kept = 0;
    let mut duplicates = Vec::new();
    for (&start, (count, piece_duplicates)) in starts.iter().zip(settled) {
        items.copy_within(start..start + count, kept);
        sorted.copy_within(start..start + count, kept);
        kept += count;
        duplicates.extend(piece_duplicates);
    }
    items.truncate(kept);
    sorted.truncate(kept);
    duplicates
}

/// [`super::points_in_order`] on all threads: a gather (one scattered read per item), which
/// the threads share; on one thread the sequential form's scatter is faster.
pub(super) fn points_in_order(points: &[[f64; 2]], items: &[u64], grid: &Grid) -> Vec<[f64; 2]> {
    items
        .par_iter()
        .map(|&item| points[grid.index(item) as usize])
        .collect()
}

/// [`super::input_indices`] on all threads.
pub(super) fn input_indices(items: &[u64], grid: &Grid) -> Vec<u32> {
    items.par_iter().map(|&item| grid.index(item)).collect()
}

/// Sorts `items` stably by the bits above `low`, as [`radix_sort`] does: the halves at the
/// same time, then a stable merge.
pub(super) fn sort_items(items: &mut [u64], low: u32) {
    let mut merged = vec![0; items.len()];
    let (first, second) = items.split_at_mut(items.len() / 2);
    rayon::join(|| radix_sort(first, low), || radix_sort(second, low));
    merge(first, second, &mut merged, low);
    items
        .par_chunks_mut(MERGE_GRAIN)
        .zip(merged.par_chunks(MERGE_GRAIN))
        .for_each(|(to, from)| to.copy_from_slice(from));
}

/// Merges `a` and `b` (each sorted by the bits above `low`) into `out` stably: of equal
/// keys, `a`'s come first. Large outputs are cut in two at their middle, each half merged
/// on its own.
fn merge(a: &[u64], b: &[u64], out: &mut [u64], low: u32) {
    if out.len() <= MERGE_GRAIN {
        return merge_sequentially(a, b, out, low);
    }
    let k = out.len() / 2;
    let i = taken_from_first(k, a, b, low);
    let (out_first, out_second) = out.split_at_mut(k);
    rayon::join(
        || merge(&a[..i], &b[..k - i], out_first, low),
        || merge(&a[i..], &b[k - i..], out_second, low),
    );
}

/// How many of the first `k` items of the stable merge of `a` and `b` come from `a`: the
/// first `i` for which `a[i]` does not go before `b[k − i − 1]` (a binary search).
fn taken_from_first(k: usize, a: &[u64], b: &[u64], low: u32) -> usize {
    let (mut lo, mut hi) = (k.saturating_sub(b.len()), k.min(a.len()));
    while lo < hi {
        let i = lo + (hi - lo) / 2;
        if a[i] >> low <= b[k - i - 1] >> low {
            lo = i + 1;
        } else {
            hi = i;
        }
    }
    lo
}

/// The stable merge of `a` and `b` by the bits above `low`, on this thread.
fn merge_sequentially(a: &[u64], b: &[u64], out: &mut [u64], low: u32) {
    let (mut i, mut j) = (0, 0);
    for slot in out.iter_mut() {
        let from_a = j == b.len() || (i < a.len() && a[i] >> low <= b[j] >> low);
        if from_a {
            *slot = a[i];
            i += 1;
        } else {
            *slot = b[j];
            j += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A stable sort by the bits above `low`, the reference.
    fn stable_by_key(items: &[u64], low: u32) -> Vec<u64> {
        let mut sorted = items.to_vec();
        sorted.sort_by_key(|&item| item >> low);
        sorted
    }

    #[test]
    fn the_parallel_sort_is_the_stable_sort() {
        let mut s = 3u64;
        for (n, low) in [(70_000, 17), (200_001, 18), (100_000, 40)] {
            // Few distinct keys (long runs of equal ones) and indices out of order.
            let items: Vec<u64> = (0..n)
                .map(|_| {
                    s = s
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    ((s >> 58) << 58) | ((s >> 30) % (1 << low))
                })
                .collect();
            for threads in [1, 2, 3] {
                let mut sorted = items.clone();
                rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap()
                    .install(|| sort_items(&mut sorted, low));
                assert_eq!(sorted, stable_by_key(&items, low), "{n} items, {threads}");
            }
        }
    }

    /// Runs of equal keys of every length (copies of one point, clusters finer than the
    /// grid, which are re-keyed: one of 75 000 points, sorted by radix, and one of 3 000,
    /// sorted as pairs) across many settling pieces: the same order, points and duplicates
    /// on any number of threads; each point beside its item, each first occurrence kept.
    #[test]
    fn the_order_is_the_same_on_any_thread_count() {
        let mut rng = wdm_crust_testkit::Rng::new(5);
        let mut next = move |below: usize| rng.below(below) as f64;
        let points: Vec<[f64; 2]> = (0..300_000)
            .map(|i| match i % 4 {
                // A coarse lattice: many exact duplicates.
                0 => [next(300), next(300)],
                // A cluster far finer than the grid, with its own duplicates.
                1 => [1.0 + next(5000) * 1e-12, 2.0 + next(7) * 1e-12],
                // A smaller one.
                _ if i % 100 == 2 => [3.0 + next(40) * 1e-13, 4.0 + next(40) * 1e-13],
                _ => [next(1_000_000) * 3e-4, next(1_000_000) * 3e-4],
            })
            .collect();
        let grid = Grid::new(&points);
        let in_pool = |threads: usize| {
            let o = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap()
                .install(|| super::super::order(&points, &grid));
            (o.points, o.items, o.duplicates)
        };
        let one = in_pool(1);
        assert!(one.2.len() > 50_000, "{} duplicates", one.2.len());
        let (kept, items, duplicates) = &one;
        assert_eq!(kept.len() + duplicates.len(), points.len());
        let mut first = std::collections::HashMap::new();
        for (i, p) in points.iter().enumerate() {
            first.entry(p.map(f64::to_bits)).or_insert(i as u32);
        }
        for (&p, &item) in kept.iter().zip(items) {
            let i = grid.index(item);
            assert_eq!(p, points[i as usize], "the point beside its item");
            assert_eq!(first[&p.map(f64::to_bits)], i, "the first occurrence kept");
        }
        for &[duplicate, kept] in duplicates {
            assert_eq!(first[&points[duplicate as usize].map(f64::to_bits)], kept);
        }
        for threads in [2, 3, 5] {
            assert!(in_pool(threads) == one, "{threads} threads");
        }
    }

    #[test]
    fn merge_pieces_cut_anywhere_are_the_stable_merge() {
        let a: Vec<u64> = [1, 1, 2, 5, 5, 5, 9].iter().map(|k| (k << 4) | 1).collect();
        let b: Vec<u64> = [0, 1, 5, 5, 7].iter().map(|k| (k << 4) | 2).collect();
        let mut whole = vec![0; a.len() + b.len()];
        merge_sequentially(&a, &b, &mut whole, 4);
        let expected = stable_by_key(&[a.clone(), b.clone()].concat(), 4);
        assert_eq!(whole, expected);
        for k in 0..=whole.len() {
            let i = taken_from_first(k, &a, &b, 4);
            let mut prefix = vec![0; k];
            merge_sequentially(&a[..i], &b[..k - i], &mut prefix, 4);
            assert_eq!(prefix, expected[..k], "first {k}");
        }
    }
}
