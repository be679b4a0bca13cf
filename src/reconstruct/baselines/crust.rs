//! The crust of Amenta, Bern and Eppstein (1998), computed exactly.
//!
//! # Definition
//!
//! Let `S` be the samples and `V` the vertices of their Voronoi diagram (the circumcenters of
//! the merged Delaunay faces, see [`crate::voronoi`]). The crust is the set of edges of the
//! Delaunay triangulation of `S ∪ V` whose two ends are samples. Here "edge" means an edge of
//! the Delaunay *graph*: `pq` is an edge iff some circle through `p` and `q` has every other
//! point of `S ∪ V` strictly outside, i.e. the Voronoi cells of `p` and `q` in `Vor(S ∪ V)`
//! share a segment of positive length. (Edges that only some Delaunay triangulations have, the
//! diagonals of cocircular groups, are ambiguous and never belong to the crust; this is the
//! same convention as for the merged Voronoi faces of WDM_CRUST.) Such an edge is also an
//! edge of `Del(S)`, since a circle empty of `S ∪ V` is empty of `S`.
//!
//! # Why a local test on the dual Voronoi edge is not enough
//!
//! Parametrize the circles through `p` and `q` by their centre `c(t)` on the bisector of `pq`.
//! Each other point `x` excludes a half-line of `t` (it is inside `C(t)` for all `t` beyond the
//! centre of the circle through `p, q, x`, on `x`'s side of `pq`), so `pq` is a crust edge iff
//! these half-lines leave an open interval. The samples leave exactly the Voronoi edge `uv` of
//! `pq` in `Vor(S)`. A local test that looks only at the two ends `u`, `v` of that edge (as in
//! the "one-step crust" of Gold and Snoeyink) agrees with the crust on well-sampled curves, but
//! **not** on arbitrary input: other Voronoi vertices inside the two Delaunay circumdisks of
//! `pq` can cover the rest. For `S = {(1,2), (2,2), (4,5), (5,2), (5,6), (6,0), (6,1), (6,3)}`
//! the Delaunay edge `(2,2)–(5,2)` has `u = (3.5, 0)` and `v = (3.5, 19/6)`, which leave the
//! centre parameters `(−7/48, −8/63)` free, but the Voronoi vertex `(4.5, 0.5)` (circumcenter
//! of `(5,2), (6,1), (6,0)`) excludes all of them (test `one_step_test_is_not_the_crust`).
//! Which Voronoi vertices matter is not local in the Voronoi graph either, and enumerating the
//! vertices in the two circumdisks is quadratic on a noisy circle (every chord's circumdisks
//! hold the whole cluster of medial vertices).
//!
//! # The exact algorithm
//!
//! So the crust is computed by its definition. The Voronoi vertices are inserted into `Del(S)`
//! one by one by Bowyer–Watson insertion with ghost triangles (module `insertion`), in a
//! biased randomized order: random rounds that double in size, each along a Hilbert curve
//! refined where vertices crowd (`insertion_order`). A vertex whose Delaunay triangle is
//! still in the triangulation starts its cavity there (its circumcircle holds it); any other
//! is located by a walk from the vertex inserted before it. Expected `O(n log n)` work; on a
//! noisy curve about ten orientation and eighteen in-circle tests per vertex (10⁵ samples:
//! about three times the time of the default WDM reconstruction). Inserting in Hilbert order
//! alone, without the random rounds, is quadratic on curve samples: the vertices of the
//! medial axis, met in order along it, each conflict with the Delaunay triangles of all the
//! medial balls ahead of them. Every decision is exact: orientation and incircle tests on
//! points that are samples or exact rational circumcenters (the kernel's mixed predicates),
//! filtered on the rounded circumcenters with their proven error bounds and otherwise
//! decided by the sign of an integer determinant in homogeneous coordinates. Rounded
//! circumcenters are never used as points, and order the insertions only. The result is a
//! Delaunay triangulation of `S ∪ V` exactly, whatever the degeneracies and whatever the
//! order; a sample–sample edge of it is kept iff it is on the hull or the opposite corners of
//! its two triangles are not cocircular with it (exact incircle `≠ 0`), which is the
//! Delaunay-graph condition above and does not depend on which triangulation was built.

mod insertion;

use crate::delaunay::Triangulation;
use crate::ids::{LocalPoint, VertexId};
use crate::kernel::Sign;
use crate::parallel;
use crate::reconstruct::curves::chain_edges;

use self::insertion::Dt;
use crate::kernel::mixed::MixedPoints;

/// Crust edges of the distinct points of `tri`, `[i, j]` with `i < j`, sorted.
///
/// Collinear input (no triangles, no Voronoi vertices) gives the chain along the line.
///
/// ```
/// use wdm_crust::reconstruct::crust::crust_edges;
/// // A square and a point near one side: the crust is the pentagon.
/// let pts = [[0.0, 0.0], [4.0, 0.0], [4.0, 4.0], [0.0, 4.0], [2.0, 4.5]];
/// let tri = wdm_crust::triangulate(&pts)?;
/// assert_eq!(crust_edges(&tri), vec![[0, 1], [0, 3], [1, 2], [2, 4], [3, 4]]);
/// # Ok::<(), wdm_crust::Error>(())
/// ```
pub fn crust_edges(tri: &Triangulation) -> Vec<[u32; 2]> {
    tri.to_input_edges(edges_of(tri))
}

/// The edges of [`crust_edges`], between the triangulation's own points.
pub(crate) fn edges_of(tri: &Triangulation) -> Vec<[LocalPoint; 2]> {
    edges_in_order(tri, insertion_order)
}

/// [`edges_of`], inserting the Voronoi vertices in the order `order` gives for their rounded
/// positions (a permutation; the result does not depend on it).
fn edges_in_order(
    tri: &Triangulation,
    order: impl FnOnce(&[[f64; 2]]) -> Vec<u32>,
) -> Vec<[LocalPoint; 2]> {
    if tri.is_degenerate() {
        let mut chain = chain_edges(tri);
        chain.sort_unstable();
        return chain;
    }
    let vor = tri.voronoi();
    let n = tri.points.len();
    let m = vor.vertex_count();
    let triangles = vor.vertex_ids().map(|v| vor.vertex_triangle(v)).collect();
    let positions = vor.vertex_positions();
    let points = MixedPoints::with_centres(&tri.points, triangles, positions);
    let mut dt = Dt::new(tri, &points, n + m);
    let order = order(positions);
    let mut near = order
        .first()
        .and_then(|&v| vor.face_corners(VertexId::new(v)).next())
        .map_or(0, LocalPoint::get);
    for v in order {
        let w = (n + v as usize) as u32;
        let t = vor.vertex_triangle_id(VertexId::new(v));
        let seed = (t.get(), tri.triangles[t.index()].map(LocalPoint::get));
        if dt.insert(w, near, seed) {
            near = w;
        }
    }
    let mut edges = dt.sample_edges(|a, b, c, across| match across {
        None => true,
        Some(d) => points.incircle(a, b, c, d) != Sign::Zero,
    });
    parallel::sort_unstable(&mut edges);
    edges.dedup();
    // The insertion store's samples are the local points `0..n`.
    edges.into_iter().map(|e| e.map(LocalPoint::new)).collect()
}

/// The order in which the Voronoi vertices at `positions` are inserted: a biased randomized
/// insertion order (Amenta, Choi and Rote). Each vertex is given a round by a fixed hash of
/// its index, the last round with probability 1/2, the one before with 1/4, and so on down
/// to a first round of about [`FIRST_ROUND`] vertices; the rounds are inserted one after the
/// other, each along a Hilbert curve, in alternate directions so that a round starts where
/// the last one ended. Inserting in Hilbert order alone made the cavities grow with `n` on
/// curve samples (each vertex of the medial axis, met in order along it, conflicted with
/// the Delaunay triangles of every medial ball still ahead of it: 46 s at 10^5 samples of a
/// clean curve); the random rounds keep the expected work at `O(n log n)`, and the Hilbert
/// order within a round keeps the walks that locate each vertex short.
fn insertion_order(positions: &[[f64; 2]]) -> Vec<u32> {
    let m = positions.len();
    let mut rounds = 1;
    while (m >> rounds) > FIRST_ROUND {
        rounds += 1;
    }
    let mut by_round: Vec<Vec<u32>> = vec![Vec::new(); rounds];
    for v in hilbert_order(positions) {
        // A vertex lands in round `rounds − 1 − z` with `z` the trailing zeros of its hash:
        // probability 2^-(z + 1).
        let z = splitmix(u64::from(v)).trailing_zeros() as usize;
        by_round[rounds - 1 - z.min(rounds - 1)].push(v);
    }
    let mut order = Vec::with_capacity(m);
    for (round, mut vertices) in by_round.into_iter().enumerate() {
        if round % 2 == 1 {
            vertices.reverse();
        }
        order.extend(vertices);
    }
    order
}

/// The expected size of the first round of [`insertion_order`].
const FIRST_ROUND: usize = 64;

/// SplitMix64's output function on `x`: a fixed hash with well-mixed low bits.
fn splitmix(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

/// Indices of `positions` along a Hilbert curve, refined where points crowd: the points are
/// ordered on a grid of [`SIDE`] cells a side over their bounding box, and every run of more
/// than [`CROWD`] points in one cell is ordered again on a grid over its own bounding box.
/// Nearly coincident Voronoi vertices (the medial cluster of a circle) would otherwise share
/// a cell and be met in index order, each walk crossing the whole cluster. Non-finite
/// coordinates are clamped; only the order, never the result, depends on it.
fn hilbert_order(positions: &[[f64; 2]]) -> Vec<u32> {
    let mut order: Vec<u32> = (0..positions.len() as u32).collect();
    let mut keyed = Vec::new();
    hilbert_sort(&mut order, positions, &mut keyed);
    order
}

/// Grid cells a side of one level of [`hilbert_order`].
const SIDE: u32 = 1 << 16;
/// Runs of more points than this in one cell are ordered again.
const CROWD: usize = 32;

/// Sorts `items` (indices of `positions`) along a Hilbert curve over their bounding box, and
/// then every crowded cell over its own; `keyed` is scratch space.
fn hilbert_sort(items: &mut [u32], positions: &[[f64; 2]], keyed: &mut Vec<(u64, u32)>) {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for &i in items.iter() {
        let p = positions[i as usize];
        for k in 0..2 {
            if p[k].is_finite() {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
    }
    let span = [hi[0] - lo[0], hi[1] - lo[1]];
    if !(span[0] > 0.0 || span[1] > 0.0) {
        return; // one point, repeated (or nothing finite): any order
    }
    let cell = |x: f64, k: usize| -> u32 {
        if !(span[k] > 0.0 && span[k] < f64::INFINITY) {
            return 0;
        }
        let f = ((x - lo[k]) / span[k] * f64::from(SIDE - 1)).clamp(0.0, f64::from(SIDE - 1));
        if f.is_nan() {
            0
        } else {
            f as u32
        }
    };
    keyed.clear();
    keyed.extend(items.iter().map(|&i| {
        let p = positions[i as usize];
        (hilbert_index(SIDE, cell(p[0], 0), cell(p[1], 1)), i)
    }));
    parallel::sort_unstable(keyed);
    for (item, &(_, i)) in items.iter_mut().zip(keyed.iter()) {
        *item = i;
    }
    let keys: Vec<u64> = keyed.iter().map(|&(key, _)| key).collect();
    let mut start = 0;
    while start < keys.len() {
        let mut end = start + 1;
        while end < keys.len() && keys[end] == keys[start] {
            end += 1;
        }
        if end - start > CROWD {
            hilbert_sort(&mut items[start..end], positions, keyed);
        }
        start = end;
    }
}

/// Position of cell `(x, y)` along the Hilbert curve filling a `side × side` grid (`side` a
/// power of two).
fn hilbert_index(side: u32, mut x: u32, mut y: u32) -> u64 {
    let mut d = 0u64;
    let mut s = side / 2;
    while s > 0 {
        let rx = u32::from(x & s != 0);
        let ry = u32::from(y & s != 0);
        d += u64::from(s) * u64::from(s) * u64::from((3 * rx) ^ ry);
        if ry == 0 {
            if rx == 1 {
                x = side - 1 - x;
                y = side - 1 - y;
            }
            std::mem::swap(&mut x, &mut y);
        }
        s /= 2;
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reconstruct::baselines::reference::{self, d2, Q};
    use crate::triangulate;
    use num_traits::Zero;

    /// Brute-force exact reference, independent of the triangulation code: `V` from all triples
    /// with an empty circumcircle, then for every pair the interval of circle centres on its
    /// bisector that keeps every other point of `S ∪ V` strictly outside.
    fn reference_crust(points: &[[f64; 2]]) -> Vec<[u32; 2]> {
        let (distinct, s) = reference::distinct(points);
        let mut v: Vec<[Q; 2]> = Vec::new();
        for i in 0..s.len() {
            for j in i + 1..s.len() {
                for k in j + 1..s.len() {
                    let (a, b, c) = (&s[i], &s[j], &s[k]);
                    let (bx, by) = (&b[0] - &a[0], &b[1] - &a[1]);
                    let (cx, cy) = (&c[0] - &a[0], &c[1] - &a[1]);
                    let d = (&bx * &cy - &by * &cx) * Q::from_integer(2.into());
                    if d.is_zero() {
                        continue;
                    }
                    let b2 = &bx * &bx + &by * &by;
                    let c2 = &cx * &cx + &cy * &cy;
                    let o = [
                        &a[0] + (&cy * &b2 - &by * &c2) / &d,
                        &a[1] + (&bx * &c2 - &cx * &b2) / &d,
                    ];
                    let r = d2(&o, a);
                    if s.iter().all(|x| d2(&o, x) >= r) && !v.contains(&o) {
                        v.push(o);
                    }
                }
            }
        }
        let mut edges = Vec::new();
        for i in 0..s.len() {
            for j in i + 1..s.len() {
                if reference::strictly_delaunay(&s[i], &s[j], s.iter().chain(v.iter())) {
                    let (a, b) = (distinct[i] as u32, distinct[j] as u32);
                    edges.push([a.min(b), a.max(b)]);
                }
            }
        }
        edges.sort_unstable();
        edges
    }

    fn crust_of(points: &[[f64; 2]]) -> Vec<[u32; 2]> {
        crust_edges(&triangulate(points).unwrap())
    }

    struct Lcg(u64);
    impl Lcg {
        fn next(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (self.0 >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    #[test]
    fn dense_circle_sample_gives_the_polygon() {
        for &(n, jitter) in &[(12usize, 0.0), (40, 0.0), (64, 0.2), (200, 0.3)] {
            let mut rng = Lcg(n as u64);
            let order: Vec<usize> = (0..n).map(|i| (i * 7 + 3) % n).collect();
            let pts: Vec<[f64; 2]> = order
                .iter()
                .map(|&k| {
                    let t =
                        (k as f64 + jitter * (rng.next() - 0.5)) * std::f64::consts::TAU / n as f64;
                    [3.0 * t.cos() + 1.0, 3.0 * t.sin() - 2.0]
                })
                .collect();
            let mut expected: Vec<[u32; 2]> = (0..n)
                .map(|i| {
                    let a = order.iter().position(|&k| k == i).unwrap() as u32;
                    let b = order.iter().position(|&k| k == (i + 1) % n).unwrap() as u32;
                    [a.min(b), a.max(b)]
                })
                .collect();
            expected.sort_unstable();
            assert_eq!(crust_of(&pts), expected, "n = {n}");
        }
    }

    #[test]
    fn one_step_test_is_not_the_crust() {
        let pts = [
            [1.0, 2.0],
            [6.0, 0.0],
            [6.0, 1.0],
            [4.0, 5.0],
            [5.0, 6.0],
            [2.0, 2.0],
            [6.0, 3.0],
            [5.0, 2.0],
        ];
        let crust = crust_of(&pts);
        assert_eq!(crust, reference_crust(&pts));
        // (2,2)–(5,2) is a Delaunay edge that the Voronoi vertex (4.5, 0.5) blocks.
        let tri = triangulate(&pts).unwrap();
        let is_delaunay = tri.halfedge_ids().any(|e| {
            let (a, b) = (tri.halfedge_origin(e), tri.halfedge_destination(e));
            [a.min(b), a.max(b)] == [5, 7]
        });
        assert!(is_delaunay);
        assert!(!crust.contains(&[5, 7]));
    }

    /// `CRUST_CASES` and `CRUST_MAXN` (environment) enlarge the run; it passed with 3000
    /// cases of up to 19 points.
    #[test]
    fn matches_brute_force_reference_on_random_and_degenerate_sets() {
        let env = |name: &str, default: usize| {
            std::env::var(name)
                .ok()
                .and_then(|v| v.parse().ok())
                .unwrap_or(default)
        };
        let (cases, spread) = (env("CRUST_CASES", 60), env("CRUST_MAXN", 9));
        let mut rng = Lcg(7);
        for case in 0..cases {
            let n = 4 + case % spread;
            let pts: Vec<[f64; 2]> = (0..n)
                .map(|_| match case % 3 {
                    // Small integer grid: duplicates, collinear and cocircular groups.
                    0 => [(rng.next() * 6.0).floor(), (rng.next() * 6.0).floor()],
                    // Generic points.
                    1 => [rng.next() * 10.0 - 5.0, rng.next() * 7.0],
                    // Noisy circle.
                    _ => {
                        let t = rng.next() * std::f64::consts::TAU;
                        let r = 1.0 + 0.2 * rng.next();
                        [r * t.cos(), r * t.sin()]
                    }
                })
                .collect();
            let tri = triangulate(&pts).unwrap();
            if tri.is_degenerate() {
                continue;
            }
            assert_eq!(
                crust_edges(&tri),
                reference_crust(&pts),
                "case {case}: {pts:?}"
            );
        }
    }

    /// Points on a circle, whose Voronoi vertices all crowd near its centre (cells of the
    /// insertion order's Hilbert curve ordered again), a noisy curve and two clusters. (The
    /// rounds of the insertion order are checked against other orders below.)
    #[test]
    fn matches_brute_force_reference_on_crowded_vertices() {
        let mut rng = Lcg(11);
        for case in 0..3 {
            let n = 24 + case;
            let pts: Vec<[f64; 2]> = (0..n)
                .map(|_| {
                    let t = rng.next() * std::f64::consts::TAU;
                    match case % 3 {
                        // On a circle: every medial vertex near the centre.
                        0 => [t.cos(), t.sin()],
                        // A noisy closed curve.
                        1 => {
                            let r = 1.0 + 0.3 * (3.0 * t).cos() + 0.02 * rng.next();
                            [r * t.cos(), r * t.sin()]
                        }
                        // Two clusters.
                        _ => {
                            let c = if rng.next() < 0.5 { 0.0 } else { 3.0 };
                            [c + 0.3 * rng.next(), 0.3 * rng.next() - c]
                        }
                    }
                })
                .collect();
            let tri = triangulate(&pts).unwrap();
            assert_eq!(
                crust_edges(&tri),
                reference_crust(&pts),
                "case {case}: {pts:?}"
            );
        }
    }

    /// The crust is a property of the points: inserting the Voronoi vertices in index order,
    /// in reverse, or in the biased randomized order gives the same edges.
    #[test]
    fn insertion_order_does_not_change_the_crust() {
        let mut rng = Lcg(5);
        let noisy_circle: Vec<[f64; 2]> = (0..600)
            .map(|_| {
                let t = rng.next() * std::f64::consts::TAU;
                let r = 1.0 + 0.01 * rng.next();
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let mut grid = Vec::new();
        for y in 0..20 {
            for x in 0..20 {
                grid.push([f64::from(x) * 0.1, f64::from(y) * 0.1]);
            }
        }
        for pts in [noisy_circle, grid] {
            let tri = triangulate(&pts).unwrap();
            let expected = edges_of(&tri);
            let forward = edges_in_order(&tri, |p| (0..p.len() as u32).collect());
            let backward = edges_in_order(&tri, |p| (0..p.len() as u32).rev().collect());
            assert_eq!(forward, expected);
            assert_eq!(backward, expected);
        }
    }

    #[test]
    fn insertion_order_is_a_permutation() {
        let mut rng = Lcg(9);
        // A wide spread, a tight cluster (crowded cells, ordered again) and repeated points.
        let mut positions: Vec<[f64; 2]> = (0..3000)
            .map(|i| match i % 3 {
                0 => [rng.next() * 1e6, rng.next()],
                1 => [1.0 + rng.next() * 1e-12, 2.0 + rng.next() * 1e-12],
                _ => [5.0, 5.0],
            })
            .collect();
        positions.push([f64::INFINITY, f64::NAN]);
        let mut order = insertion_order(&positions);
        order.sort_unstable();
        assert_eq!(order, (0..positions.len() as u32).collect::<Vec<_>>());
    }

    #[test]
    fn grids_and_regular_polygons() {
        // 3 × 3 grid: the boundary square only (interior edges are blocked by the centres).
        let mut grid = Vec::new();
        for y in 0..3 {
            for x in 0..3 {
                grid.push([f64::from(x), f64::from(y)]);
            }
        }
        let crust = crust_of(&grid);
        assert_eq!(crust, reference_crust(&grid));
        assert_eq!(crust.len(), 8);
        // A larger grid against the reference.
        let mut grid = Vec::new();
        for y in 0..4 {
            for x in 0..5 {
                grid.push([f64::from(x) * 0.5, f64::from(y) * 0.5]);
            }
        }
        assert_eq!(crust_of(&grid), reference_crust(&grid));
        // An exactly cocircular octagon (coordinates 0, ±1, ±3 on a circle of radius² 10).
        let oct = [
            [3.0, 1.0],
            [1.0, 3.0],
            [-1.0, 3.0],
            [-3.0, 1.0],
            [-3.0, -1.0],
            [-1.0, -3.0],
            [1.0, -3.0],
            [3.0, -1.0],
        ];
        let crust = crust_of(&oct);
        assert_eq!(crust.len(), 8);
        assert_eq!(crust, reference_crust(&oct));
    }

    #[test]
    fn duplicates_map_to_the_kept_point() {
        let pts = [
            [0.0, 0.0],
            [4.0, 0.0],
            [4.0, 4.0],
            [0.0, 4.0],
            [4.0, 0.0],
            [2.0, 4.5],
        ];
        assert_eq!(crust_of(&pts), vec![[0, 1], [0, 3], [1, 2], [2, 5], [3, 5]]);
    }

    #[test]
    fn collinear_input_is_the_chain() {
        let pts = [[2.0, 2.0], [0.0, 0.0], [1.0, 1.0]];
        assert_eq!(crust_of(&pts), vec![[0, 2], [1, 2]]);
    }

    #[test]
    fn agrees_with_rounded_cross_check_on_a_generic_set() {
        // Triangulating S plus the rounded circumcenters is not exact in general, but on a
        // generic random set it must give the same sample–sample Delaunay edges.
        let mut rng = Lcg(99);
        let pts: Vec<[f64; 2]> = (0..400)
            .map(|_| {
                let t = rng.next() * std::f64::consts::TAU;
                let r = 1.0 + 0.05 * (5.0 * t).sin() + 0.01 * rng.next();
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let tri = triangulate(&pts).unwrap();
        let vor = tri.voronoi();
        let mut all = pts.clone();
        all.extend_from_slice(vor.vertex_positions());
        let big = triangulate(&all).unwrap();
        let mut expected = Vec::new();
        for e in big.halfedge_ids() {
            let (a, b) = (big.halfedge_origin(e), big.halfedge_destination(e));
            if (a as usize) < pts.len() && (b as usize) < pts.len() {
                expected.push([a.min(b), a.max(b)]);
            }
        }
        expected.sort_unstable();
        expected.dedup();
        assert_eq!(crust_edges(&tri), expected);
    }

    #[test]
    fn exact_under_extreme_scaling() {
        // Scaling by a power of two is exact and changes no predicate, so the crust must not
        // change, even where the interval filter overflows or the coordinates are tiny.
        let mut rng = Lcg(3);
        let base: Vec<[f64; 2]> = (0..60)
            .map(|i| {
                let t = i as f64 * std::f64::consts::TAU / 60.0 + 0.02 * rng.next();
                let r = 1.0 + 0.3 * (3.0 * t).cos() + 0.01 * rng.next();
                [r * t.cos() + 2.0, r * t.sin() + 1.5]
            })
            .chain([[1.0, 1.0], [1.5, 1.0], [1.0, 1.5], [1.5, 1.5]])
            .collect();
        let expected = crust_of(&base);
        for k in [-130, -60, 60, 190] {
            let f = 2f64.powi(k);
            let scaled: Vec<[f64; 2]> = base.iter().map(|p| [p[0] * f, p[1] * f]).collect();
            assert_eq!(crust_of(&scaled), expected, "scale 2^{k}");
        }
    }

    #[test]
    fn hilbert_index_is_a_bijection_on_a_small_grid() {
        let mut seen = [false; 64];
        for x in 0..8 {
            for y in 0..8 {
                let d = hilbert_index(8, x, y) as usize;
                assert!(!seen[d]);
                seen[d] = true;
            }
        }
    }
}
