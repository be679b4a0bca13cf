//! Assembly of reconstructed edges into curves: closed loops and open chains.

use std::cmp::Ordering;

use crate::delaunay::Triangulation;
use crate::ids::{ids, LocalPoint};
use crate::kernel::metric::{length_order, scaled_length_order};
use crate::kernel::{orient, Sign};
use crate::parallel;
use crate::reconstruct::thresholds::smooth::{FLAT, ZIGZAG_SHARE};

/// The loop `ring`'s longest edge and its next longest, by position (edge `i` runs from
/// `ring[i]` to `ring[i + 1]`, the last back to the first), when the longest is more than
/// `2^doublings` times every other edge: an edge alone in its length, as a chord across the
/// gap of an open curve is. Exact; ties have no lone edge.
pub(crate) fn lone_longest_edge(
    points: &[[f64; 2]],
    ring: &[LocalPoint],
    doublings: u32,
) -> Option<(usize, usize)> {
    let k = ring.len();
    let at = |i: usize| points[ring[i % k].index()];
    let order = |i: usize, j: usize| length_order(at(i), at(i + 1), at(j), at(j + 1));
    let (mut longest, mut second) = (0, None);
    for i in 1..k {
        if order(i, longest) == Ordering::Greater {
            (longest, second) = (i, Some(longest));
        } else if second.is_none_or(|s| order(i, s) == Ordering::Greater) {
            second = Some(i);
        }
    }
    let second = second?;
    let lone = scaled_length_order(
        at(longest),
        at(longest + 1),
        at(second),
        at(second + 1),
        doublings,
    ) == Ordering::Greater;
    lone.then_some((longest, second))
}

/// One reconstructed curve.
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Curve {
    /// True for a closed loop (the last point connects back to the first).
    pub closed: bool,
    /// Point indices along the curve. A closed loop lists each point once and runs
    /// counterclockwise, starting at its smallest index.
    pub points: Vec<u32>,
}

/// A curve while the reconstruction walks it: the points are the triangulation's local ones.
/// [`LocalCurve::named`] makes it a [`Curve`] in the caller's indices.
#[derive(Debug, Clone, PartialEq, Eq)]
pub(crate) struct LocalCurve {
    /// True for a closed loop (the last point connects back to the first).
    pub(crate) closed: bool,
    /// Local points along the curve.
    pub(crate) points: Vec<LocalPoint>,
}

impl LocalCurve {
    /// The same curve with every point renamed by `name` (in place: a local point is a
    /// `u32`).
    pub(crate) fn named(self, name: impl Fn(LocalPoint) -> u32) -> Curve {
        Curve {
            closed: self.closed,
            points: self.points.into_iter().map(name).collect(),
        }
    }

    /// `curve` (caller indices) with every point renamed by `local` into the
    /// triangulation's local points: the inverse of [`LocalCurve::named`].
    pub(crate) fn from_caller(curve: &Curve, local: impl Fn(u32) -> LocalPoint) -> LocalCurve {
        LocalCurve {
            closed: curve.closed,
            points: curve.points.iter().map(|&i| local(i)).collect(),
        }
    }
}

/// The point space an [`Adjacency`] is built over: the triangulation's local points
/// ([`LocalPoint`]), or a plain `u32` numbering (the caller's indices for
/// [`irregular_points`], the detour repair's positions among its candidates).
pub(crate) trait Point: Copy + Ord + From<u32> + Into<u32> + Send + Sync {}

impl Point for u32 {}

impl Point for LocalPoint {}

/// Splits the edge graph of distinct `edges` over points `0..point_count` into maximal paths
/// between points of degree ≠ 2 (open chains) and cycles of degree-2 points (closed loops),
/// given in the names `name(p)`. Every edge is in exactly one curve.
///
/// The result depends only on the edge set and the names (not on the order of `edges` nor
/// on the indices): open chains first, sorted by their first two points, each starting at
/// its smaller end (a chain from a junction back to itself runs towards its smaller
/// neighbour first); then closed loops by their smallest point, each starting there,
/// towards its smaller neighbour, reversed if that runs clockwise. That is the order in
/// which scanning the names upwards finds them.
///
/// The walks run over the triangulation's local points, so they stay local in memory while
/// the result is in the caller's indices.
pub(crate) fn assemble_named(
    point_count: usize,
    edges: &[[LocalPoint; 2]],
    points: &[[f64; 2]],
    name: impl Fn(LocalPoint) -> u32 + Sync,
) -> Vec<Curve> {
    let curves = assemble_unnamed(point_count, edges, points, &name);
    curves.into_iter().map(|c| c.named(&name)).collect()
}

/// [`assemble_named`] with the points left local ([`LocalCurve`]): the same curves in the
/// same order, each point to be named still. (The pipeline reads the loops in the
/// triangulation's local indices first, which follow the points' locality, and names them
/// afterwards: looking the local index of every point up from the caller's, shuffled,
/// was a cache miss per point.)
pub(crate) fn assemble_unnamed(
    point_count: usize,
    edges: &[[LocalPoint; 2]],
    points: &[[f64; 2]],
    name: impl Fn(LocalPoint) -> u32 + Sync,
) -> Vec<LocalCurve> {
    let mut adjacency = Adjacency::new(point_count, edges);
    // Each row by the names of the neighbours: the order of the walks out of a point.
    adjacency.sort_rows_by_key(&name);
    let mut used = vec![false; edges.len()];
    let mut curves = Vec::new();
    // Open chains: start at every end or junction, along every unused edge.
    for start in ids::<LocalPoint>(point_count) {
        if adjacency.degree(start) == 2 || adjacency.degree(start) == 0 {
            continue;
        }
        for &(first_edge, _) in adjacency.neighbours(start) {
            if used[first_edge as usize] {
                continue;
            }
            let mut chain = walk(&adjacency, &mut used, start, first_edge, |p| {
                adjacency.degree(p) != 2
            });
            // From the smaller end; a chain from a junction back to itself towards its
            // smaller neighbour first.
            let (first, last) = (name(chain[0]), name(chain[chain.len() - 1]));
            let k = chain.len();
            if last < first || (last == first && k > 2 && name(chain[1]) > name(chain[k - 2])) {
                chain.reverse();
            }
            curves.push(LocalCurve {
                closed: false,
                points: chain,
            });
        }
    }
    // What remains are disjoint cycles of degree-2 points.
    for start in ids::<LocalPoint>(point_count) {
        if let Some(&(first_edge, _)) = adjacency
            .neighbours(start)
            .iter()
            .find(|&&(e, _)| !used[e as usize])
        {
            let mut cycle = walk(&adjacency, &mut used, start, first_edge, |p| p == start);
            cycle.pop(); // the walk ends back at the start
            orient_counterclockwise(&mut cycle, points, &name);
            curves.push(LocalCurve {
                closed: true,
                points: cycle,
            });
        }
    }
    // Stable, and already sorted when the names are the indices.
    curves.sort_by(|a, b| {
        let first_two = |c: &LocalCurve| [0, 1].map(|k| c.points.get(k).map(|&p| name(p)));
        a.closed
            .cmp(&b.closed)
            .then_with(|| first_two(a).cmp(&first_two(b)))
    });
    curves
}

/// The edges of `curves` as `[i, j]`, `i < j`, sorted: the edges they were assembled from
/// ([`assemble_named`] puts every edge in exactly one curve).
pub(crate) fn edges_of(curves: &[Curve]) -> Vec<[u32; 2]> {
    let mut edges = Vec::with_capacity(curves.iter().map(|c| c.points.len()).sum());
    for c in curves {
        let closing = c
            .closed
            .then(|| [c.points[c.points.len() - 1], c.points[0]]);
        let pairs = c.points.windows(2).map(|w| [w[0], w[1]]).chain(closing);
        edges.extend(pairs.map(|[a, b]| [a.min(b), a.max(b)]));
    }
    parallel::sort_unstable(&mut edges);
    edges
}

/// [`assemble_named`] with the indices as names.
/// The exact orientation of the simple polygon `ring`: `Positive` when counterclockwise.
///
/// At the lexicographically smallest vertex the polygon is convex, so the turn there is the
/// polygon's orientation. Its two neighbours are both lexicographically larger; they are
/// collinear with it only if they lie on one ray from it, where the two edges would overlap,
/// which a simple polygon rules out. `Zero` therefore only for degenerate rings (fewer than
/// three points, or not simple).
pub(crate) fn ring_orientation(ring: &[[f64; 2]]) -> Sign {
    ring_orientation_by(ring.len(), |i| ring[i])
}

/// [`ring_orientation`] of the ring whose `i`-th of `n` points is `at(i)`.
pub(crate) fn ring_orientation_by(n: usize, at: impl Fn(usize) -> [f64; 2]) -> Sign {
    if n < 3 {
        return Sign::Zero;
    }
    let lowest = (0..n)
        .min_by(|&i, &j| lexicographic(at(i), at(j)))
        .unwrap_or(0);
    orient(at((lowest + n - 1) % n), at(lowest), at((lowest + 1) % n))
}

/// By value (`-0.0` equals `0.0`, which `total_cmp` would not say); coordinates are finite.
pub(crate) fn lexicographic(a: [f64; 2], b: [f64; 2]) -> Ordering {
    let by = |x: f64, y: f64| x.partial_cmp(&y).unwrap_or(Ordering::Equal);
    by(a[0], b[0]).then(by(a[1], b[1]))
}

/// Collinear or tiny input: the chain along the line is the reconstruction.
pub(crate) fn chain_edges(tri: &Triangulation) -> Vec<[LocalPoint; 2]> {
    tri.hull
        .windows(2)
        .map(|w| [w[0].min(w[1]), w[0].max(w[1])])
        .collect()
}

/// [`assemble_named`] of `edges` over the points `0..point_count` with the indices as names
/// (taken as local points: a test's edges name no triangulation).
#[cfg(test)]
pub fn assemble(point_count: usize, edges: &[[u32; 2]], points: &[[f64; 2]]) -> Vec<Curve> {
    let edges: Vec<[LocalPoint; 2]> = edges.iter().map(|e| e.map(LocalPoint::new)).collect();
    assemble_named(point_count, &edges, points, LocalPoint::get)
}

/// Points with at least one edge and a degree other than 2: curve ends and junctions.
/// (Points without any edge are not listed: the caller decides what those mean.) In the
/// caller's indices, as the result holds its edges.
pub fn irregular_points(point_count: usize, edges: &[[u32; 2]]) -> Vec<u32> {
    let adjacency = Adjacency::new(point_count, edges);
    (0..point_count as u32)
        .filter(|&p| {
            let d = adjacency.degree(p);
            d != 0 && d != 2
        })
        .collect()
}

/// Follows unused edges from `start` until `stop` says so; returns the visited points.
///
/// Through a point of degree 2 the way on is the entry not arrived by, without consulting
/// `used`: the chain phase stops at every other point, and the cycle phase meets only points
/// of degree 2, so that entry is unused. This saves a cache miss per point on large, shuffled
/// input, where the walk jumps around memory.
fn walk(
    adjacency: &Adjacency,
    used: &mut [bool],
    start: LocalPoint,
    first_edge: u32,
    stop: impl Fn(LocalPoint) -> bool,
) -> Vec<LocalPoint> {
    let mut chain = vec![start];
    let mut at = start;
    let mut edge = first_edge;
    loop {
        used[edge as usize] = true;
        let next = adjacency
            .neighbours(at)
            .iter()
            .find(|&&(e, _)| e == edge)
            .map(|&(_, q)| q)
            .unwrap_or(at);
        chain.push(next);
        at = next;
        if stop(at) {
            break;
        }
        let way_on = match adjacency.neighbours(at) {
            &[(e0, _), (e1, _)] => Some(if e0 == edge { e1 } else { e0 }),
            entries => entries
                .iter()
                .find(|&&(e, _)| !used[e as usize])
                .map(|&(e, _)| e),
        };
        match way_on {
            Some(e) => edge = e,
            None => break,
        }
    }
    chain
}

/// Puts a loop in its canonical form by names: from its smallest name towards the smaller
/// neighbour, reversed if it runs clockwise (decided exactly, see
/// [`ring_orientation_by`]), then from its smallest name again.
fn orient_counterclockwise(
    cycle: &mut [LocalPoint],
    points: &[[f64; 2]],
    name: impl Fn(LocalPoint) -> u32,
) {
    let n = cycle.len();
    let start_at_smallest = |cycle: &mut [LocalPoint]| {
        if let Some(min_at) = (0..n).min_by_key(|&i| name(cycle[i])) {
            cycle.rotate_left(min_at);
        }
    };
    start_at_smallest(cycle);
    if n > 2 && name(cycle[1]) > name(cycle[n - 1]) {
        cycle[1..].reverse();
    }
    // Exactly (the float shoelace sum can get a thin loop far from the origin wrong).
    if ring_orientation_by(n, |i| points[cycle[i].index()]) == Sign::Negative {
        cycle.reverse();
        start_at_smallest(cycle);
    }
}

/// Compressed adjacency lists: for each point, `(edge index, other end)`; the points are
/// local ones unless said otherwise.
pub(crate) struct Adjacency<P = LocalPoint> {
    start: Vec<u32>,
    entries: Vec<(u32, P)>,
}

impl<P: Point> Adjacency<P> {
    pub(crate) fn new(point_count: usize, edges: &[[P; 2]]) -> Self {
        #[cfg(feature = "parallel")]
        if parallel::pays(edges.len()) {
            return Adjacency::by_point_ranges(point_count, edges);
        }
        Adjacency::in_slots(point_count, edges, |p| p.into() as usize)
    }

    /// [`Adjacency::new`] on all threads, the same arrays: each thread owns a range of
    /// points, counts and fills their rows (a part of the entries of its own) reading all
    /// the edges in order, so each row lists its edges in their order, and no two threads
    /// write the same place. Every thread reads every edge, twice, in order; the scattered
    /// writes, the cost of the sequential form, are shared out.
    #[cfg(feature = "parallel")]
    fn by_point_ranges(point_count: usize, edges: &[[P; 2]]) -> Self {
        use rayon::prelude::*;
        let per_range = point_count.div_ceil(rayon::current_num_threads()).max(1);
        let mut start = vec![0u32; point_count + 1];
        start[1..]
            .par_chunks_mut(per_range)
            .enumerate()
            .for_each(|(k, counts)| {
                let first = k * per_range;
                let ours = first as u32..(first + counts.len()) as u32;
                for &[a, b] in edges {
                    let ends = [a, b].map(Into::<u32>::into);
                    for p in ends.into_iter().filter(|p| ours.contains(p)) {
                        counts[p as usize - first] += 1;
                    }
                }
            });
        for i in 0..point_count {
            start[i + 1] += start[i];
        }
        // Filled from the end of each row, the edges read backwards (so that each row
        // still lists its edges in their order), with the thread's own part of `start` as
        // the cursors: afterwards `start[p + 1]` holds the row start of `p`, and one shift
        // puts them back. (Cursors of their own, 4 bytes a point in all, were allocated
        // and freed by the worker threads, whose allocators kept them.)
        let mut entries = vec![(0, P::from(0)); 2 * edges.len()];
        let firsts: Vec<usize> = (0..point_count).step_by(per_range).collect();
        let bases: Vec<u32> = firsts.iter().map(|&first| start[first]).collect();
        let total = start[point_count];
        let rows = rows_in_ranges(&start, &mut entries, per_range);
        rows.into_par_iter()
            .zip(start[1..].par_chunks_mut(per_range))
            .enumerate()
            .for_each(|(k, ((first, last, ours), ends))| {
                let base = bases[k];
                let ours_range = first as u32..last as u32;
                for (i, &[a, b]) in edges.iter().enumerate().rev() {
                    for (p, q) in [(b, a), (a, b)] {
                        let p: u32 = p.into();
                        if ours_range.contains(&p) {
                            let end = &mut ends[p as usize - first];
                            *end -= 1;
                            ours[(*end - base) as usize] = (i as u32, q);
                        }
                    }
                }
                // `ends[j]` is now the row start of point `first + j`; the row end is the
                // next one's start.
                ends.copy_within(1.., 0);
                if let Some(end) = ends.last_mut() {
                    *end = bases.get(k + 1).copied().unwrap_or(total);
                }
            });
        Adjacency { start, entries }
    }

    /// The entries of point `p` in slot `slot(p)` (below `slot_count`), naming the edge and
    /// the neighbour as given.
    fn in_slots(slot_count: usize, edges: &[[P; 2]], slot: impl Fn(P) -> usize) -> Self {
        let mut start = vec![0u32; slot_count + 1];
        for &[a, b] in edges {
            start[slot(a) + 1] += 1;
            start[slot(b) + 1] += 1;
        }
        for i in 0..slot_count {
            start[i + 1] += start[i];
        }
        let mut fill = start.clone();
        let mut entries = vec![(0, P::from(0)); 2 * edges.len()];
        for (i, &[a, b]) in edges.iter().enumerate() {
            let (sa, sb) = (slot(a), slot(b));
            entries[fill[sa] as usize] = (i as u32, b);
            fill[sa] += 1;
            entries[fill[sb] as usize] = (i as u32, a);
            fill[sb] += 1;
        }
        Adjacency { start, entries }
    }

    /// Sorts every row by `key` of the neighbours (distinct in a row, so one order), on all
    /// threads where that pays, a range of rows each.
    fn sort_rows_by_key(&mut self, key: impl Fn(P) -> u32 + Sync) {
        let Adjacency { start, entries } = self;
        let sort_rows = |first: usize, last: usize, rows: &mut [(u32, P)]| {
            let base = start[first];
            for p in first..last {
                let (lo, hi) = ((start[p] - base) as usize, (start[p + 1] - base) as usize);
                rows[lo..hi].sort_unstable_by_key(|&(_, q)| key(q));
            }
        };
        let point_count = start.len() - 1;
        #[cfg(feature = "parallel")]
        if parallel::pays(entries.len()) {
            use rayon::prelude::*;
            rows_in_ranges(start, entries, 1 << 14)
                .into_par_iter()
                .for_each(|(first, last, rows)| sort_rows(first, last, rows));
            return;
        }
        sort_rows(0, point_count, entries);
    }

    /// `(edge, neighbour)` for every edge at `p`, in the order of the edges.
    pub(crate) fn neighbours(&self, p: P) -> &[(u32, P)] {
        self.in_slot(p.into() as usize)
    }

    fn in_slot(&self, slot: usize) -> &[(u32, P)] {
        &self.entries[self.start[slot] as usize..self.start[slot + 1] as usize]
    }

    fn degree(&self, p: P) -> usize {
        self.neighbours(p).len()
    }
}

/// The rows of the points `first..last`: `(first, last, their entries)`.
#[cfg(feature = "parallel")]
type RowRange<'e, P> = (usize, usize, &'e mut [(u32, P)]);

/// The rows of `entries` (laid out by `start`, as in [`Adjacency`]) for consecutive ranges
/// of `per_range` points: disjoint slices that threads can fill or sort on their own.
#[cfg(feature = "parallel")]
fn rows_in_ranges<'e, P>(
    start: &[u32],
    entries: &'e mut [(u32, P)],
    per_range: usize,
) -> Vec<RowRange<'e, P>> {
    let point_count = start.len() - 1;
    let mut ranges = Vec::new();
    let mut rest = entries;
    for first in (0..point_count).step_by(per_range) {
        let last = (first + per_range).min(point_count);
        let (ours, tail) = rest.split_at_mut((start[last] - start[first]) as usize);
        ranges.push((first, last, ours));
        rest = tail;
    }
    ranges
}

/// An [`Adjacency`] of a few edges, with slots for their points alone (found by a binary
/// search): nothing is built over all the points. It knows every edge at a point only where
/// every edge at that point is among those given.
pub(crate) struct SomeAdjacency<P = LocalPoint> {
    /// The points of the edges, sorted: the slot of a point is its position here.
    members: Vec<P>,
    adjacency: Adjacency<P>,
}

impl<P: Point> SomeAdjacency<P> {
    pub(crate) fn new(edges: &[[P; 2]]) -> Self {
        let mut members: Vec<P> = edges.iter().flatten().copied().collect();
        members.sort_unstable();
        members.dedup();
        let slot = |p: P| members.binary_search(&p).unwrap_or_default();
        let adjacency = Adjacency::in_slots(members.len(), edges, slot);
        SomeAdjacency { members, adjacency }
    }

    /// As [`Adjacency::neighbours`]; nothing for a point of none of the edges.
    pub(crate) fn neighbours(&self, p: P) -> &[(u32, P)] {
        match self.members.binary_search(&p) {
            Ok(slot) => self.adjacency.in_slot(slot),
            Err(_) => &[],
        }
    }
}

/// Whether `curve` is noisy: more than [`ZIGZAG_SHARE`] of its vertices turn the other way
/// than both their neighbours (exact orientations). Noise that is not small against the
/// curve's own turn per step makes the turns' signs about random, and a quarter of the
/// vertices then zigzag; an ε-sample of a smooth curve or a polygon turns one way along
/// every run between inflections, which it samples with several vertices, so none do.
/// Smoothing fits only curves that zigzag (a fit could only trade clean samples' exact
/// positions for its bias); the loops beside curves (`repairs/beside.rs`) are kept only
/// when they do not.
pub(crate) fn zigzags(points: &[[f64; 2]], curve: &LocalCurve) -> bool {
    let k = curve.points.len();
    if k < 5 {
        return false;
    }
    let at = |i: usize| points[curve.points[i % k].index()];
    // The turn at `b`, `Zero` where it is below [`FLAT`] (a straight run of clean samples
    // that rounding put a hair off its line).
    let turn = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        let sign = orient(a, b, c);
        let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
        let sine = (u[0] * v[1] - u[1] * v[0]) / (u[0].hypot(u[1]) * v[0].hypot(v[1]));
        if sine.abs() <= FLAT {
            Sign::Zero
        } else {
            sign
        }
    };
    let turns: Vec<Sign> = if curve.closed {
        (0..k)
            .map(|i| turn(at(i + k - 1), at(i), at(i + 1)))
            .collect()
    } else {
        (1..k - 1)
            .map(|i| turn(at(i - 1), at(i), at(i + 1)))
            .collect()
    };
    let m = turns.len();
    let middle = if curve.closed { 0..m } else { 1..m - 1 };
    let flips = middle
        .clone()
        .filter(|&i| {
            let (before, here, after) = (turns[(i + m - 1) % m], turns[i], turns[(i + 1) % m]);
            here != Sign::Zero && before == after && before != here && before != Sign::Zero
        })
        .count();
    flips as f64 > ZIGZAG_SHARE * middle.len() as f64
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `edges` between the local points with these numbers.
    fn local(edges: &[[u32; 2]]) -> Vec<[LocalPoint; 2]> {
        edges.iter().map(|e| e.map(LocalPoint::new)).collect()
    }

    fn square() -> Vec<[f64; 2]> {
        vec![
            [0.0, 0.0],
            [1.0, 0.0],
            [1.0, 1.0],
            [0.0, 1.0],
            [5.0, 5.0],
            [6.0, 5.0],
        ]
    }

    #[test]
    fn a_loop_and_a_chain() {
        let edges = [[0, 3], [2, 3], [1, 2], [0, 1], [4, 5]];
        let curves = assemble(6, &edges, &square());
        assert_eq!(curves.len(), 2);
        assert_eq!(
            curves[0],
            Curve {
                closed: false,
                points: vec![4, 5]
            }
        );
        assert_eq!(
            curves[1],
            Curve {
                closed: true,
                points: vec![0, 1, 2, 3]
            }
        );
        assert!(irregular_points(6, &edges) == vec![4, 5]);
    }

    #[test]
    fn clockwise_loop_is_turned() {
        let edges = [[0, 1], [1, 3], [3, 2], [0, 2]];
        // 0-1-3-2 with these coordinates is a bow-tie; use a real clockwise square instead.
        let pts = vec![[0.0, 0.0], [0.0, 1.0], [1.0, 0.0], [1.0, 1.0]];
        let curves = assemble(4, &edges, &pts);
        assert_eq!(
            curves,
            vec![Curve {
                closed: true,
                points: vec![0, 2, 3, 1]
            }]
        );
    }

    #[test]
    fn curves_come_in_the_canonical_order() {
        use wdm_crust_testkit::Rng;
        let mut rng = Rng::new(17);
        for round in 0..300 {
            // A random graph of small degree on up to 40 points: loops, chains, junctions,
            // loops through junctions, isolated points.
            let n = 3 + rng.below(38);
            let points: Vec<[f64; 2]> = (0..n).map(|_| [rng.f64(), rng.f64()]).collect();
            let mut edges: Vec<[u32; 2]> = Vec::new();
            for _ in 0..rng.below(2 * n) {
                let (a, b) = (rng.below(n) as u32, rng.below(n) as u32);
                if a != b {
                    edges.push([a.min(b), a.max(b)]);
                }
            }
            if round % 3 == 0 {
                // Add a long cycle so that closed loops are common.
                for i in 0..n as u32 / 2 {
                    let j = (i + 1) % (n as u32 / 2);
                    edges.push([i.min(j), i.max(j)]);
                }
            }
            edges.sort_unstable();
            edges.dedup();
            let curves = assemble(n, &edges, &points);
            // Walking over other indices and naming the points gives what assembling on the
            // names gives.
            let name: Vec<u32> = rng.permutation(n).iter().map(|&k| k as u32).collect();
            let mut named_points = vec![[0.0; 2]; n];
            for (p, &q) in name.iter().enumerate() {
                named_points[q as usize] = points[p];
            }
            let mut named_edges: Vec<[u32; 2]> = edges
                .iter()
                .map(|&[a, b]| {
                    let (a, b) = (name[a as usize], name[b as usize]);
                    [a.min(b), a.max(b)]
                })
                .collect();
            named_edges.sort_unstable();
            let mut shuffled = edges.clone();
            rng.shuffle(&mut shuffled);
            assert_eq!(
                assemble_named(n, &local(&shuffled), &points, |p| name[p.index()]),
                assemble(n, &named_edges, &named_points),
                "round {round}"
            );
            let key = |c: &Curve| {
                (
                    c.closed,
                    c.points.iter().take(2).copied().collect::<Vec<_>>(),
                )
            };
            assert!(
                curves.windows(2).all(|w| key(&w[0]) <= key(&w[1])),
                "round {round}: order"
            );
            for c in &curves {
                let (first, last) = (c.points[0], c.points[c.points.len() - 1]);
                if c.closed {
                    assert_eq!(Some(&first), c.points.iter().min(), "round {round}");
                } else {
                    assert!(first <= last, "round {round}: chain from its smaller end");
                }
            }
        }
    }

    #[test]
    fn junction_splits_chains() {
        // A "T": 0-1-2 and 1-3.
        let edges = [[0, 1], [1, 2], [1, 3]];
        let pts = vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0], [1.0, 1.0]];
        let curves = assemble(4, &edges, &pts);
        assert_eq!(curves.len(), 3);
        assert!(curves.iter().all(|c| !c.closed && c.points.len() == 2));
        assert_eq!(irregular_points(4, &edges), vec![0, 1, 2, 3]);
    }

    /// Every edge is in exactly one curve: the curves' edges are the edges assembled, on
    /// Up to `2n` distinct random edges `[min, max]` between `n` points, sorted: points of
    /// every degree (loops, chains, junctions, isolated points).
    fn random_graph(rng: &mut wdm_crust_testkit::Rng, n: usize) -> Vec<[u32; 2]> {
        let mut edges = Vec::new();
        for _ in 0..rng.below(2 * n) {
            let (a, b) = (rng.below(n) as u32, rng.below(n) as u32);
            if a != b {
                edges.push([a.min(b), a.max(b)]);
            }
        }
        edges.sort_unstable();
        edges.dedup();
        edges
    }

    /// random graphs of every degree (loops, chains, junctions, isolated points), under
    /// random names.
    #[test]
    fn the_curves_edges_are_the_edges() {
        let mut rng = wdm_crust_testkit::Rng::new(21);
        for round in 0..300 {
            let n = 2 + rng.below(40);
            let points: Vec<[f64; 2]> = (0..n).map(|_| [rng.f64(), rng.f64()]).collect();
            let edges = random_graph(&mut rng, n);
            // Names: a permutation, so that the curves come in caller order.
            let mut names: Vec<u32> = (0..n as u32).collect();
            for i in (1..n).rev() {
                names.swap(i, rng.below(i + 1));
            }
            let curves = assemble_named(n, &local(&edges), &points, |p| names[p.index()]);
            let mut named: Vec<[u32; 2]> = edges
                .iter()
                .map(|e| e.map(|p| names[p as usize]))
                .map(|[a, b]| [a.min(b), a.max(b)])
                .collect();
            named.sort_unstable();
            assert_eq!(edges_of(&curves), named, "round {round}");
        }
    }

    /// The edges at a few points of a random graph: at every point the entries of
    /// [`Adjacency`] over all points, so every edge at the points asked for.
    #[test]
    fn some_adjacency_answers_at_the_points_it_holds_whole() {
        let mut rng = wdm_crust_testkit::Rng::new(5);
        for round in 0..200 {
            let n = 2 + rng.below(60);
            let edges = random_graph(&mut rng, n);
            let asked: Vec<bool> = (0..n).map(|_| rng.below(4) == 0).collect();
            let picked: Vec<[u32; 2]> = edges
                .iter()
                .copied()
                .filter(|&[a, b]| asked[a as usize] || asked[b as usize])
                .collect();
            let whole = Adjacency::new(n, &picked);
            let some = SomeAdjacency::new(&picked);
            for p in 0..n as u32 {
                assert_eq!(
                    some.neighbours(p),
                    whole.neighbours(p),
                    "round {round}, {p}"
                );
                if asked[p as usize] {
                    let all = edges.iter().filter(|e| e.contains(&p)).count();
                    assert_eq!(some.neighbours(p).len(), all, "round {round}, {p}");
                }
            }
        }
    }

    /// The adjacency built on several threads is the one built on one: the same rows, each
    /// in the order of the edges, for graphs of every degree and some points of none; and
    /// so are its rows sorted by a key.
    #[cfg(feature = "parallel")]
    #[test]
    fn the_adjacency_is_the_same_on_any_thread_count() {
        let mut rng = wdm_crust_testkit::Rng::new(13);
        for (n, edges) in [(1, 0), (7, 20), (1000, 3000), (40_000, 50_000)] {
            let mut graph: Vec<[u32; 2]> = (0..edges)
                .map(|_| (rng.below(n) as u32, rng.below(n) as u32))
                .filter(|&(a, b)| a != b)
                .map(|(a, b)| [a.min(b), a.max(b)])
                .collect();
            graph.sort_unstable();
            graph.dedup();
            rng.shuffle(&mut graph);
            let one = Adjacency::in_slots(n, &graph, |p| p as usize);
            // Rows by a key that is no order of the indices.
            let key = |q: u32| q.wrapping_mul(2_654_435_761);
            let mut one_sorted = Adjacency::in_slots(n, &graph, |p| p as usize);
            one_sorted.sort_rows_by_key(key);
            for threads in [1, 2, 3, 4] {
                let pool = rayon::ThreadPoolBuilder::new()
                    .num_threads(threads)
                    .build()
                    .unwrap();
                let mut many = pool.install(|| Adjacency::by_point_ranges(n, &graph));
                assert!(many.start == one.start, "{n} points, {threads} threads");
                assert!(many.entries == one.entries, "{n} points, {threads} threads");
                pool.install(|| many.sort_rows_by_key(key));
                assert!(
                    many.entries == one_sorted.entries,
                    "sorted, {threads} threads"
                );
            }
        }
    }
}
