//! The nearest-neighbour crust of Dey and Kumar (1999), decided exactly.
//!
//! For every sample `p`:
//! 1. the edge to its nearest neighbour `q`;
//! 2. the edge to its *half neighbour* `s`: the nearest among the neighbours with
//!    `(s − p)·(q − p) < 0` (strictly more than 90° away from `pq`), if there is one.
//!
//! Candidates are the neighbours of `p` in the Delaunay graph (the edges with a dual Voronoi
//! edge: hull edges, and interior edges whose two triangles are not cocircular). The nearest
//! neighbour is always such a neighbour (its diametral disk holds no other point, not even on
//! the boundary); restricting the half neighbour to Delaunay edges is Dey and Kumar's
//! algorithm, and leaving out the diagonals of cocircular groups makes the result independent
//! of how the triangulation split them.
//!
//! # Exactness and determinism
//!
//! Both tests are polynomials in the input coordinates, decided exactly by the kernel
//! (a floating-point filter with a proven bound, then exact arithmetic):
//! * `|p − a|² − |p − b|² = (a − b)·((a − p) + (b − p))` (degree 2) compares two distances;
//! * `(s − p)·(q − p)` (degree 2) is the half-plane test.
//!
//! Equal distances are broken by the coordinates of the candidates (smaller `x`, then smaller
//! `y`), never by input index, so the result does not depend on the order of the input.
//!
//! # Cost
//!
//! Linear after the triangulation: every point scans its Delaunay neighbours once (10⁵
//! samples of a noisy curve: about half the time of the default WDM reconstruction).

use crate::delaunay::Triangulation;
use crate::ids::{ids, LocalPoint};
use crate::reconstruct::curves::chain_edges;
use crate::reconstruct::proximity::DelaunayGraph;

/// NN-crust edges of the distinct points of `tri`, `[i, j]` with `i < j`, sorted.
///
/// Collinear input gives the chain along the line.
///
/// ```
/// use wdm_crust::reconstruct::nn_crust::nn_crust_edges;
/// // Pairs of close points on a circle: the nearest neighbours only pair them up; the half
/// // neighbours close the polygon.
/// let pts: Vec<[f64; 2]> = (0..8)
///     .map(|i| {
///         let t = (i / 2) as f64 * std::f64::consts::FRAC_PI_2 + (i % 2) as f64 * 0.2;
///         [t.cos(), t.sin()]
///     })
///     .collect();
/// let tri = wdm_crust::triangulate(&pts)?;
/// assert_eq!(nn_crust_edges(&tri).len(), 8);
/// # Ok::<(), wdm_crust::Error>(())
/// ```
pub fn nn_crust_edges(tri: &Triangulation) -> Vec<[u32; 2]> {
    tri.to_input_edges(edges_of(tri))
}

/// The edges of [`nn_crust_edges`], between the triangulation's own points.
pub(crate) fn edges_of(tri: &Triangulation) -> Vec<[LocalPoint; 2]> {
    if tri.is_degenerate() {
        let mut chain = chain_edges(tri);
        chain.sort_unstable();
        return chain;
    }
    let graph = DelaunayGraph::of(tri);
    let mut edges = Vec::new();
    for p in ids::<LocalPoint>(tri.points.len()) {
        let proposal = graph.proposal(&tri.points, p, |_| true);
        for q in proposal.iter() {
            edges.push([p.min(q), p.max(q)]);
        }
    }
    edges.sort_unstable();
    edges.dedup();
    edges
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::metric::{distance_order, dot_sign};
    use crate::kernel::Sign;
    use crate::reconstruct::baselines::reference::{self, d2, Q};
    use crate::reconstruct::proximity::closer;
    use num_rational::BigRational;
    use std::cmp::Ordering;

    fn rational(x: f64) -> BigRational {
        BigRational::from_float(x).unwrap_or_default()
    }
    use crate::triangulate;

    fn nn_crust_of(points: &[[f64; 2]]) -> Vec<[u32; 2]> {
        nn_crust_edges(&triangulate(points).unwrap())
    }

    fn polygon_edges(order: &[usize]) -> Vec<[u32; 2]> {
        let n = order.len();
        let mut edges: Vec<[u32; 2]> = (0..n)
            .map(|i| {
                let (a, b) = (order[i] as u32, order[(i + 1) % n] as u32);
                [a.min(b), a.max(b)]
            })
            .collect();
        edges.sort_unstable();
        edges
    }

    #[test]
    fn dense_circle_sample_gives_the_polygon() {
        let n = 50;
        // Scrambled input order; point k of the circle is input index perm[k].
        let perm: Vec<usize> = (0..n).map(|i| (i * 17 + 5) % n).collect();
        let mut pts = vec![[0.0; 2]; n];
        for (k, &i) in perm.iter().enumerate() {
            let t =
                (k as f64 + 0.3 * ((k * 7) % 5) as f64 / 5.0) * std::f64::consts::TAU / n as f64;
            pts[i] = [2.0 * t.cos() - 1.0, 2.0 * t.sin() + 3.0];
        }
        assert_eq!(nn_crust_of(&pts), polygon_edges(&perm));
    }

    #[test]
    fn half_neighbours_close_the_gaps_between_pairs() {
        // Close pairs on a circle: every point's nearest neighbour is its partner, so the
        // edges between pairs come only from half neighbours.
        let pairs = 9;
        let pts: Vec<[f64; 2]> = (0..2 * pairs)
            .map(|i| {
                let t =
                    (i / 2) as f64 * std::f64::consts::TAU / pairs as f64 + (i % 2) as f64 * 0.1;
                [t.cos(), t.sin()]
            })
            .collect();
        let edges = nn_crust_of(&pts);
        let order: Vec<usize> = (0..2 * pairs).collect();
        assert_eq!(edges, polygon_edges(&order));
        // Without half neighbours there would be only the pairs.
        let pair_edges = edges.iter().filter(|e| e[0] / 2 == e[1] / 2).count();
        assert_eq!(pair_edges, pairs);
    }

    /// The output as pairs of points (not indices), sorted.
    fn edges_by_coordinates(pts: &[[f64; 2]]) -> Vec<[[u64; 2]; 2]> {
        let key = |i: u32| pts[i as usize].map(f64::to_bits);
        let mut e: Vec<[[u64; 2]; 2]> = nn_crust_of(pts)
            .iter()
            .map(|&[a, b]| {
                let (ka, kb) = (key(a), key(b));
                [ka.min(kb), ka.max(kb)]
            })
            .collect();
        e.sort_unstable();
        e
    }

    #[test]
    fn ties_are_broken_by_coordinates_not_by_index() {
        // Equal distances: smaller x first, then smaller y, whatever the argument order.
        let p = [0.0, 0.0];
        let (a, b, c) = ([1.0, 0.0], [0.0, 1.0], [0.0, -1.0]);
        assert_eq!(closer(p, b, a), Ordering::Less);
        assert_eq!(closer(p, a, b), Ordering::Greater);
        assert_eq!(closer(p, c, b), Ordering::Less);
        assert_eq!(closer(p, [0.5, 0.0], b), Ordering::Less);
        // Inputs full of ties (a grid, a plus sign, a regular hexagon with its centre): every
        // order of the input gives the same edges between the same points.
        let mut grid = Vec::new();
        for y in 0..4 {
            for x in 0..4 {
                grid.push([f64::from(x) * 0.1, f64::from(y) * 0.1]);
            }
        }
        let plus = vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]];
        let mut hexagon = vec![[0.0, 0.0]];
        hexagon.extend([
            [2.0, 0.0],
            [1.0, 2.0],
            [-1.0, 2.0],
            [-2.0, 0.0],
            [-1.0, -2.0],
            [1.0, -2.0],
        ]);
        for base in [grid, plus, hexagon] {
            let reference = edges_by_coordinates(&base);
            let n = base.len();
            for step in [1, 3, 5, 7] {
                for offset in 0..n {
                    if step % n == 0 || gcd(step, n) != 1 {
                        continue;
                    }
                    let pts: Vec<[f64; 2]> =
                        (0..n).map(|i| base[(i * step + offset) % n]).collect();
                    assert_eq!(edges_by_coordinates(&pts), reference);
                    let reversed: Vec<[f64; 2]> = pts.iter().rev().copied().collect();
                    assert_eq!(edges_by_coordinates(&reversed), reference);
                }
            }
        }
    }

    fn gcd(a: usize, b: usize) -> usize {
        if b == 0 {
            a
        } else {
            gcd(b, a % b)
        }
    }

    #[test]
    fn exact_distance_comparison_beyond_f64() {
        // |p − a|² and |p − b|² differ by far less than their rounding error.
        let p = [0.1, 0.2];
        let a = [0.1 + 1e-9, 0.2 + 3e-9];
        let b = [0.1 - 3e-9, 0.2 + 1e-9];
        let exact = |x: [f64; 2]| {
            let (dx, dy) = (
                rational(x[0]) - rational(p[0]),
                rational(x[1]) - rational(p[1]),
            );
            &dx * &dx + &dy * &dy
        };
        assert_eq!(
            Ordering::from(distance_order(p, a, b)),
            exact(a).cmp(&exact(b))
        );
        assert_eq!(distance_order(p, a, a), Sign::Zero);
        // A right angle exactly: not a half neighbour.
        assert_eq!(dot_sign([0.0, 0.0], [0.0, 0.3], [0.7, 0.0]), Sign::Zero);
        assert_eq!(dot_sign([0.1, 0.1], [0.1, 0.4], [0.7, 0.1]), Sign::Zero);
    }

    /// Brute-force exact reference: the strict Delaunay graph from the interval of circle
    /// centres on each pair's bisector that keeps all other points strictly outside, then
    /// nearest and half neighbours by exact squared distances, ties by coordinates.
    fn reference_nn_crust(points: &[[f64; 2]]) -> Vec<[u32; 2]> {
        let (ids, s) = reference::distinct(points);
        let delaunay = |i: usize, j: usize| reference::strictly_delaunay(&s[i], &s[j], &s);
        let mut edges = Vec::new();
        for p in 0..s.len() {
            let nbrs: Vec<usize> = (0..s.len()).filter(|&a| a != p && delaunay(p, a)).collect();
            let better = |a: usize, b: usize| {
                let (da, db) = (d2(&s[p], &s[a]), d2(&s[p], &s[b]));
                da < db
                    || (da == db
                        && (points[ids[a]][0], points[ids[a]][1])
                            < (points[ids[b]][0], points[ids[b]][1]))
            };
            let pick = |cands: &mut dyn Iterator<Item = usize>| {
                cands.fold(None, |best: Option<usize>, a| match best {
                    Some(b) if !better(a, b) => Some(b),
                    _ => Some(a),
                })
            };
            let Some(q) = pick(&mut nbrs.iter().copied()) else {
                continue;
            };
            let zero = Q::from_integer(0.into());
            let half = pick(&mut nbrs.iter().copied().filter(|&a| {
                let dot = (&s[a][0] - &s[p][0]) * (&s[q][0] - &s[p][0])
                    + (&s[a][1] - &s[p][1]) * (&s[q][1] - &s[p][1]);
                dot < zero
            }));
            for o in std::iter::once(q).chain(half) {
                let (a, b) = (ids[p] as u32, ids[o] as u32);
                edges.push([a.min(b), a.max(b)]);
            }
        }
        edges.sort_unstable();
        edges.dedup();
        edges
    }

    #[test]
    fn matches_brute_force_reference() {
        let mut state = 12345u64;
        let mut next = move || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for case in 0..200 {
            let n = 3 + case % 14;
            let pts: Vec<[f64; 2]> = (0..n)
                .map(|_| match case % 3 {
                    0 => [(next() * 5.0).floor() * 0.1, (next() * 5.0).floor() * 0.1],
                    1 => [next() * 3.0, next() - 0.5],
                    _ => {
                        let t = next() * std::f64::consts::TAU;
                        let r = 1.0 + 0.1 * next();
                        [r * t.cos(), r * t.sin()]
                    }
                })
                .collect();
            let tri = triangulate(&pts).unwrap();
            if tri.is_degenerate() {
                continue;
            }
            assert_eq!(
                nn_crust_edges(&tri),
                reference_nn_crust(&pts),
                "case {case}: {pts:?}"
            );
        }
    }

    #[test]
    fn exact_under_extreme_scaling() {
        let base: Vec<[f64; 2]> = (0..40)
            .map(|i| {
                let t = i as f64 * 0.157 + 0.01 * ((i * 7) % 3) as f64;
                [(1.0 + 0.2 * (2.0 * t).sin()) * t.cos(), t.sin() + 2.0]
            })
            .collect();
        let expected = nn_crust_of(&base);
        for k in [-130, 190] {
            let f = 2f64.powi(k);
            let scaled: Vec<[f64; 2]> = base.iter().map(|p| [p[0] * f, p[1] * f]).collect();
            assert_eq!(nn_crust_of(&scaled), expected, "scale 2^{k}");
        }
    }

    #[test]
    fn collinear_input_is_the_chain() {
        assert_eq!(
            nn_crust_of(&[[0.0, 0.0], [3.0, 3.0], [1.0, 1.0]]),
            vec![[0, 2], [1, 2]]
        );
    }
}
