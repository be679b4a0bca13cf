//! Data-parallel loops: on rayon's pool with the `parallel` feature, plain loops without it.
//! Every function here returns what the plain loop returns, in the same order, so results never
//! depend on the number of threads.

use std::ops::Range;

/// Below this many items a loop runs on the calling thread: splitting it costs more than
/// it saves.
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
const MIN_PARALLEL: usize = 1 << 14;

/// Items per task of [`flat_map_chunks`]: large enough to amortise a task, small enough to
/// balance uneven work.
#[cfg_attr(not(feature = "parallel"), allow(dead_code))]
const CHUNK: usize = 1 << 12;

/// Whether a loop over `n` items runs on several threads (the `parallel` feature, more than
/// one thread in the current pool, and enough items): for callers whose sequential form can
/// do more in one pass than the parallel one.
pub(crate) fn pays(n: usize) -> bool {
    #[cfg(feature = "parallel")]
    if n >= MIN_PARALLEL && rayon::current_num_threads() > 1 {
        return true;
    }
    let _ = n;
    false
}

/// `(0..n).map(f).collect()`.
pub(crate) fn map_range<T, F>(n: usize, f: F) -> Vec<T>
where
    T: Send,
    F: Fn(usize) -> T + Sync + Send,
{
    #[cfg(feature = "parallel")]
    if pays(n) {
        use rayon::prelude::*;
        return (0..n).into_par_iter().map(f).collect();
    }
    (0..n).map(f).collect()
}

/// The concatenation of `f(chunk)` over consecutive chunks of `0..n`, in order: for small
/// outputs ([`flat_map_chunks_reserved`] with nothing reserved; the workers grow the chunks'
/// vectors).
pub(crate) fn flat_map_chunks<T, F>(n: usize, f: F) -> Vec<T>
where
    T: Send,
    F: Fn(Range<usize>, &mut Vec<T>) + Sync + Send,
{
    flat_map_chunks_reserved(n, 0, f)
}

/// [`flat_map_chunks`] for outputs large enough to matter at the memory peak, where each
/// item gives at most `most_per_item` outputs: every chunk's vector is reserved on the
/// calling thread at that bound (address space only: untouched pages take no memory), so
/// the workers fill it without allocating, and all of them are freed by the calling
/// thread. Vectors grown and freed by worker threads stay in those threads' allocators: at
/// 16 threads and 10^7 points they held 12 bytes a point of the reconstruction's memory
/// peak. An item with more outputs only costs that chunk a reallocation.
pub(crate) fn flat_map_chunks_reserved<T, F>(n: usize, most_per_item: usize, f: F) -> Vec<T>
where
    T: Send,
    F: Fn(Range<usize>, &mut Vec<T>) + Sync + Send,
{
    #[cfg(feature = "parallel")]
    if pays(n) {
        use rayon::prelude::*;
        let chunk = |c: usize| c * CHUNK..((c + 1) * CHUNK).min(n);
        let mut parts: Vec<Vec<T>> = (0..n.div_ceil(CHUNK))
            .map(|c| Vec::with_capacity(chunk(c).len() * most_per_item))
            .collect();
        parts
            .par_iter_mut()
            .enumerate()
            .for_each(|(c, part)| f(chunk(c), part));
        let mut all = Vec::with_capacity(parts.iter().map(Vec::len).sum());
        for part in parts {
            all.extend(part);
        }
        return all;
    }
    let _ = most_per_item;
    let mut all = Vec::new();
    f(0..n, &mut all);
    all
}

/// `f(range, &mut out[range])` over consecutive chunks of `out`, which together cover it:
/// one output array filled in place, without the per-chunk vectors of
/// [`flat_map_chunks`] (which worker threads' allocators keep after they are freed).
pub(crate) fn fill_chunks<T, F>(out: &mut [T], f: F)
where
    T: Send,
    F: Fn(Range<usize>, &mut [T]) + Sync + Send,
{
    #[cfg(feature = "parallel")]
    if pays(out.len()) {
        use rayon::prelude::*;
        let n = out.len();
        out.par_chunks_mut(CHUNK)
            .enumerate()
            .for_each(|(c, chunk)| f(c * CHUNK..((c + 1) * CHUNK).min(n), chunk));
        return;
    }
    let n = out.len();
    f(0..n, out)
}

/// `items.sort_unstable_by(compare)`, on the pool where it pays. `compare` must be a total
/// order in which only equal items compare equal: then there is one sorted order, whichever
/// algorithm finds it, and the result does not depend on the number of threads.
pub(crate) fn sort_unstable_by<T, F>(items: &mut [T], compare: F)
where
    T: Send,
    F: Fn(&T, &T) -> std::cmp::Ordering + Sync,
{
    #[cfg(feature = "parallel")]
    if pays(items.len()) {
        use rayon::prelude::*;
        return items.par_sort_unstable_by(compare);
    }
    items.sort_unstable_by(compare)
}

/// `items.sort_unstable()`, on the pool where it pays (items equal in `Ord` are identical:
/// integers, tuples and arrays of them).
pub(crate) fn sort_unstable<T: Ord + Send>(items: &mut [T]) {
    sort_unstable_by(items, T::cmp)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same items in the same order as the plain loops, on pools of any size.
    #[test]
    fn results_are_those_of_the_plain_loop() {
        for n in [
            0,
            1,
            5,
            MIN_PARALLEL - 1,
            MIN_PARALLEL,
            3 * CHUNK + 7 + MIN_PARALLEL,
        ] {
            let plain: Vec<u64> = (0..n as u64).map(|i| i * i % 97).collect();
            let evens: Vec<usize> = (0..n).filter(|i| i % 3 == 0).collect();
            let mut by_sequential_sort: Vec<u64> = (0..n as u64).map(|i| i * 7919 % 1009).collect();
            by_sequential_sort.sort();
            for threads in [1, 2, 5] {
                let run = || {
                    let mapped = map_range(n, |i| (i as u64) * (i as u64) % 97);
                    let chunked = flat_map_chunks(n, |range, out| {
                        out.extend(range.filter(|i| i % 3 == 0));
                    });
                    // One output reserved per item, while these items give 4/3 on
                    // average: chunks outgrow their reservation and lose nothing.
                    let reserved = flat_map_chunks_reserved(n, 1, |range, out| {
                        out.extend(
                            range.flat_map(|i| vec![i; usize::from(i % 3 == 0) * (1 + i % 7)]),
                        );
                    });
                    let expected: Vec<usize> = (0..n)
                        .flat_map(|i| vec![i; usize::from(i % 3 == 0) * (1 + i % 7)])
                        .collect();
                    assert_eq!(reserved, expected, "n {n}, {threads} threads");
                    let mut sorted: Vec<u64> = (0..n as u64).map(|i| i * 7919 % 1009).collect();
                    sort_unstable(&mut sorted);
                    let mut filled = vec![0u64; n];
                    fill_chunks(&mut filled, |range, out| {
                        assert_eq!(range.len(), out.len());
                        for (i, o) in range.zip(out) {
                            *o = (i as u64) * (i as u64) % 97;
                        }
                    });
                    assert_eq!(filled, plain, "n {n}, {threads} threads");
                    (mapped, chunked, sorted)
                };
                #[cfg(feature = "parallel")]
                let (mapped, chunked, sorted) = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap()
                    .install(run);
                #[cfg(not(feature = "parallel"))]
                let (mapped, chunked, sorted) = {
                    let _ = threads;
                    run()
                };
                assert_eq!(mapped, plain, "n {n}, {threads} threads");
                assert_eq!(chunked, evens, "n {n}, {threads} threads");
                assert_eq!(sorted, by_sequential_sort, "n {n}, {threads} threads");
            }
        }
    }
}
