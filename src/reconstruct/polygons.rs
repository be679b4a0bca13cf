//! Closed curves as polygons with holes: which loop lies inside which, decided exactly.
//!
//! # The nesting rule
//!
//! The closed curves of a reconstruction never cross: they are cycles of edges of one planar
//! straight-line graph. So two loops are either nested or side by side, and the loops that
//! contain a given loop form a chain. The *depth* of a loop is the number of loops containing
//! it; a loop at even depth is the exterior of a polygon, a loop at odd depth is a hole of
//! its direct parent (the innermost loop containing it, at even depth), and a loop inside a
//! hole starts a new polygon.
//!
//! # Exactly
//!
//! Whether loop `A` lies inside loop `B` is the crossing parity of a horizontal ray from a
//! vertex `t` of `A` against `B`'s edges: which edges straddle the ray's line is decided by
//! comparing coordinates, and on which side of `t` an edge crosses is the exact orientation
//! of `t` against the edge (the kernel's `orient`). Both are exact, so the parity is.
//!
//! The test point must not lie on `B`. For reconstructed curves every vertex of `A` qualifies:
//! a closed loop consists of points of degree 2 in the edge graph, so two loops share no
//! point, and an edge of the triangulation holds no input point in its interior, so no
//! vertex of `A` lies on an edge of `B` either. For any other set of non-crossing loops the
//! first vertex of `A` that is not on `B` is used; if every vertex of `A` lies on `B`, the
//! loops touch all along `A` and `A` is taken as not inside `B` (such loops cannot come out
//! of a reconstruction).
//!
//! # Fast enough for thousands of loops
//!
//! `A` can only lie inside `B` when `B`'s bounding box contains `A`'s (an exact comparison of
//! coordinates); the loops are sorted by the left side of their boxes, so the candidates for
//! `A` are a prefix of that order, and only candidates are tested point by edge.

use super::curves::ring_orientation;
use super::{Curve, Reconstruction};
use crate::kernel::{orient, Sign};

/// A polygon made of reconstructed closed curves: an exterior ring with the rings of its
/// holes, as caller indices.
///
/// Rings are not closed: the first point is not repeated at the end (the GeoJSON writer and
/// the `geo-types` conversion close them). Each ring starts at its smallest index; the
/// exterior runs counterclockwise, each hole clockwise (the orientation is decided exactly).
/// A closed [`Curve`] is counterclockwise, so an exterior ring lists the same
/// points as its curve in the same order, and a hole ring lists its curve's points
/// backwards from the same first point.
#[derive(Debug, Clone, PartialEq, Eq)]
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[non_exhaustive]
pub struct Polygon {
    /// The outer ring, counterclockwise.
    pub exterior: Vec<u32>,
    /// The rings of the holes (the closed curves directly inside the exterior), clockwise.
    pub holes: Vec<Vec<u32>>,
}

impl Polygon {
    /// The coordinates of the exterior ring, in ring order (not closed), as the caller
    /// gave them to the reconstruction `rec` this polygon came from (the fitted ones with
    /// smoothing, [`Reconstruction::curve_vertex`]).
    ///
    /// ```
    /// // A square ring of 24 points around a square hole of 8, two spacings away.
    /// let mut points = Vec::new();
    /// for (r, k) in [(3.0, 6), (1.0, 2)] {
    ///     let corners = [[-r, -r], [r, -r], [r, r], [-r, r]];
    ///     for s in 0..4 {
    ///         let (a, b): ([f64; 2], [f64; 2]) = (corners[s], corners[(s + 1) % 4]);
    ///         for i in 0..k {
    ///             let t = i as f64 / k as f64;
    ///             points.push([a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])]);
    ///         }
    ///     }
    /// }
    /// let rec = wdm_crust::reconstruct(&points)?;
    /// let polygons = rec.polygons();
    /// assert_eq!(polygons.len(), 1);
    /// let outer = polygons[0].exterior_coords(&rec);
    /// assert_eq!(outer.len(), 24);
    /// assert_eq!(outer[0], points[polygons[0].exterior[0] as usize]);
    /// assert_eq!(polygons[0].hole_coords(&rec)[0].len(), 8);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn exterior_coords(&self, rec: &Reconstruction) -> Vec<[f64; 2]> {
        rec.ring_coords(&self.exterior)
    }

    /// The coordinates of every hole ring, in ring order (not closed).
    pub fn hole_coords(&self, rec: &Reconstruction) -> Vec<Vec<[f64; 2]>> {
        self.holes
            .iter()
            .map(|ring| rec.ring_coords(ring))
            .collect()
    }
}

impl Reconstruction {
    /// The closed curves nested into polygons with holes (see [`polygons`](crate::reconstruct::polygons)
    /// for the rule, decided exactly): a closed curve at even depth is the exterior of a polygon,
    /// one at odd depth a hole of the curve directly around it. Polygons come in the order
    /// of their exterior curves in [`curves`](Self::curves). Computed on each call.
    ///
    /// ```
    /// // Two concentric circles: one polygon with one hole.
    /// let mut points = Vec::new();
    /// for (r, n) in [(2.0, 40), (1.0, 20)] {
    ///     for k in 0..n {
    ///         let t = k as f64 * std::f64::consts::TAU / n as f64;
    ///         points.push([r * t.cos(), r * t.sin()]);
    ///     }
    /// }
    /// let rec = wdm_crust::reconstruct(&points)?;
    /// let polygons = rec.polygons();
    /// assert_eq!(polygons.len(), 1);
    /// assert_eq!(polygons[0].exterior.len(), 40);
    /// assert_eq!(polygons[0].holes.len(), 1);
    /// assert_eq!(polygons[0].holes[0].len(), 20);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn polygons(&self) -> Vec<Polygon> {
        let loops: Vec<&[u32]> = self
            .curves
            .iter()
            .filter(|c| c.closed)
            .map(|c| c.points.as_slice())
            .collect();
        // With smoothing the fitted rings (simple and apart, decided exactly) are nested.
        nest_into_polygons(&loops, |i| {
            self.curve_vertex(i)
                .unwrap_or_else(|| self.triangulation.point(i))
        })
    }

    /// The coordinates of the points of `curve` (a curve of this reconstruction), in curve
    /// order; a closed curve's first point is not repeated at the end. With smoothing
    /// ([`Options::with_smoothing`](crate::reconstruct::Options::with_smoothing)) the fitted
    /// positions, otherwise the input points ([`curve_vertex`](Self::curve_vertex)).
    ///
    /// ```
    /// let points = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
    /// let rec = wdm_crust::reconstruct(&points)?;
    /// let chain = &rec.curves()[0];
    /// assert_eq!(rec.curve_coords(chain), vec![[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]]);
    /// # Ok::<(), wdm_crust::Error>(())
    /// ```
    pub fn curve_coords(&self, curve: &Curve) -> Vec<[f64; 2]> {
        self.ring_coords(&curve.points)
    }

    /// The curve-vertex coordinates of caller indices (indices beyond the input are
    /// skipped).
    fn ring_coords(&self, indices: &[u32]) -> Vec<[f64; 2]> {
        indices
            .iter()
            .filter_map(|&i| self.curve_vertex(i))
            .collect()
    }
}

/// Groups the closed `loops` (caller indices; each at least three distinct points, no two
/// crossing) into polygons, with `point(i)` the coordinates of point `i`.
///
/// Polygons come in the order of their exterior loops in `loops`, holes in the order of
/// theirs.
pub(crate) fn nest_into_polygons(
    loops: &[&[u32]],
    point: impl Fn(u32) -> [f64; 2],
) -> Vec<Polygon> {
    let rings: Vec<Ring> = loops
        .iter()
        .map(|indices| Ring::new(indices.iter().map(|&i| point(i)).collect()))
        .collect();
    let nesting = Nesting::of(&rings);
    let mut polygon_of = vec![usize::MAX; loops.len()];
    let mut polygons = Vec::new();
    for (k, indices) in loops.iter().enumerate() {
        if nesting.depth[k] % 2 == 0 {
            polygon_of[k] = polygons.len();
            polygons.push(Polygon {
                exterior: oriented(indices, &rings[k], Sign::Positive),
                holes: Vec::new(),
            });
        }
    }
    for (k, indices) in loops.iter().enumerate() {
        if nesting.depth[k] % 2 == 1 {
            // An odd depth has a parent, at even depth.
            if let Some(&p) = nesting.parent[k].and_then(|p| polygon_of.get(p)) {
                if let Some(polygon) = polygons.get_mut(p) {
                    polygon
                        .holes
                        .push(oriented(indices, &rings[k], Sign::Negative));
                }
            }
        }
    }
    polygons
}

/// `indices` turned to run with orientation `want` (Positive: counterclockwise), from its
/// smallest index.
fn oriented(indices: &[u32], ring: &Ring, want: Sign) -> Vec<u32> {
    let mut out = indices.to_vec();
    if let Some(min_at) = (0..out.len()).min_by_key(|&i| out[i]) {
        out.rotate_left(min_at);
    }
    if ring.orientation() != want && ring.orientation() != Sign::Zero {
        out[1..].reverse();
    }
    out
}

/// Where a point lies relative to a closed ring.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum RingSide {
    Inside,
    Outside,
    /// On an edge or a vertex of the ring.
    Boundary,
}

/// A loop's coordinates with its bounding box.
pub(crate) struct Ring {
    coords: Vec<[f64; 2]>,
    /// `[xmin, ymin, xmax, ymax]`.
    bbox: [f64; 4],
}

impl Ring {
    pub(crate) fn new(coords: Vec<[f64; 2]>) -> Ring {
        let mut bbox = [
            f64::INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NEG_INFINITY,
        ];
        for p in &coords {
            bbox = [
                bbox[0].min(p[0]),
                bbox[1].min(p[1]),
                bbox[2].max(p[0]),
                bbox[3].max(p[1]),
            ];
        }
        Ring { coords, bbox }
    }

    pub(crate) fn orientation(&self) -> Sign {
        ring_orientation(&self.coords)
    }

    /// Does this ring's box contain `other`'s (closed boxes)?
    fn box_contains(&self, other: &Ring) -> bool {
        self.bbox[0] <= other.bbox[0]
            && self.bbox[1] <= other.bbox[1]
            && self.bbox[2] >= other.bbox[2]
            && self.bbox[3] >= other.bbox[3]
    }

    /// Exact point-in-ring test by the crossing parity of the ray from `t` towards +x.
    ///
    /// An edge straddles the ray's line when one end is strictly above `t` and the other at or
    /// below (so a vertex on the line is counted once, or not at all, consistently); it
    /// crosses right of `t` when `t` lies left of the edge directed upwards.
    pub(crate) fn side_of(&self, t: [f64; 2]) -> RingSide {
        let [x0, y0, x1, y1] = self.bbox;
        if t[0] < x0 || t[0] > x1 || t[1] < y0 || t[1] > y1 {
            return RingSide::Outside;
        }
        let n = self.coords.len();
        let mut inside = false;
        for i in 0..n {
            let (p, q) = (self.coords[i], self.coords[(i + 1) % n]);
            let in_edge_box = p[0].min(q[0]) <= t[0]
                && t[0] <= p[0].max(q[0])
                && p[1].min(q[1]) <= t[1]
                && t[1] <= p[1].max(q[1]);
            let straddles = (p[1] > t[1]) != (q[1] > t[1]);
            if !in_edge_box && !straddles {
                continue;
            }
            let side = orient(p, q, t);
            if side == Sign::Zero && in_edge_box {
                return RingSide::Boundary;
            }
            if straddles {
                let upward = q[1] > t[1];
                let left_of_upward = if upward {
                    side == Sign::Positive
                } else {
                    side == Sign::Negative
                };
                if left_of_upward {
                    inside = !inside;
                }
            }
        }
        if inside {
            RingSide::Inside
        } else {
            RingSide::Outside
        }
    }

    /// Does this ring lie inside `outer`? Decided at the first vertex not on `outer` (see
    /// the module docs for why there is one); `false` if every vertex is on it.
    fn inside(&self, outer: &Ring) -> bool {
        for &t in &self.coords {
            match outer.side_of(t) {
                RingSide::Inside => return true,
                RingSide::Outside => return false,
                RingSide::Boundary => {}
            }
        }
        false
    }
}

/// Depth and direct parent of every ring.
struct Nesting {
    depth: Vec<usize>,
    parent: Vec<Option<usize>>,
}

impl Nesting {
    fn of(rings: &[Ring]) -> Nesting {
        let k = rings.len();
        // Candidates for containing ring `a` have a box whose left side is at or left of
        // `a`'s: a prefix of this order.
        let mut by_left: Vec<usize> = (0..k).collect();
        by_left.sort_by(|&a, &b| rings[a].bbox[0].total_cmp(&rings[b].bbox[0]));
        let containers: Vec<Vec<usize>> = (0..k)
            .map(|a| {
                let left = rings[a].bbox[0];
                by_left
                    .iter()
                    .take_while(|&&b| rings[b].bbox[0] <= left)
                    .filter(|&&b| b != a && rings[b].box_contains(&rings[a]))
                    .filter(|&&b| rings[a].inside(&rings[b]))
                    .copied()
                    .collect()
            })
            .collect();
        let depth: Vec<usize> = containers.iter().map(Vec::len).collect();
        // The containers of a ring form a chain; the innermost one is contained in all the
        // others, so it has the most containers itself.
        let parent = containers
            .iter()
            .map(|list| list.iter().copied().max_by_key(|&b| depth[b]))
            .collect();
        Nesting { depth, parent }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A square ring of side `2r` around `c`, counterclockwise, `k` points per side.
    fn square(c: [f64; 2], r: f64, k: usize) -> Vec<[f64; 2]> {
        let mut out = Vec::new();
        let corners = [[-r, -r], [r, -r], [r, r], [-r, r]];
        for s in 0..4 {
            let (a, b) = (corners[s], corners[(s + 1) % 4]);
            for i in 0..k {
                let t = i as f64 / k as f64;
                out.push([
                    c[0] + a[0] + t * (b[0] - a[0]),
                    c[1] + a[1] + t * (b[1] - a[1]),
                ]);
            }
        }
        out
    }

    /// Points and index loops from coordinate loops.
    fn index_loops(rings: &[Vec<[f64; 2]>]) -> (Vec<[f64; 2]>, Vec<Vec<u32>>) {
        let mut points = Vec::new();
        let mut loops = Vec::new();
        for ring in rings {
            let start = points.len() as u32;
            points.extend_from_slice(ring);
            loops.push((start..points.len() as u32).collect());
        }
        (points, loops)
    }

    fn nest(points: &[[f64; 2]], loops: &[Vec<u32>]) -> Vec<Polygon> {
        let refs: Vec<&[u32]> = loops.iter().map(Vec::as_slice).collect();
        nest_into_polygons(&refs, |i| points[i as usize])
    }

    #[test]
    fn three_levels_and_a_neighbour() {
        // 0 contains 1 contains 2; 3 beside 0; the hole 1 is given clockwise.
        let mut hole = square([0.0, 0.0], 6.0, 3);
        hole.reverse();
        let rings = vec![
            square([0.0, 0.0], 10.0, 2),
            hole,
            square([0.0, 0.0], 2.0, 1),
            square([30.0, 0.0], 1.0, 1),
        ];
        let (points, loops) = index_loops(&rings);
        let polygons = nest(&points, &loops);
        assert_eq!(polygons.len(), 3);
        assert_eq!(polygons[0].exterior, loops[0]);
        assert_eq!(polygons[0].holes.len(), 1);
        // The hole, clockwise from its smallest index: as given (it was clockwise).
        assert_eq!(polygons[0].holes[0], loops[1]);
        assert_eq!(polygons[1].exterior, loops[2]);
        assert!(polygons[1].holes.is_empty());
        assert_eq!(polygons[2].exterior, loops[3]);
        for p in &polygons {
            let coords = |ring: &[u32]| ring.iter().map(|&i| points[i as usize]).collect();
            assert_eq!(Ring::new(coords(&p.exterior)).orientation(), Sign::Positive);
            for h in &p.holes {
                assert_eq!(Ring::new(coords(h)).orientation(), Sign::Negative);
            }
        }
    }

    #[test]
    fn side_of_is_exact_on_edges_vertices_and_the_ray_line() {
        let ring = Ring::new(vec![
            [0.0, 0.0],
            [2.0, 0.0],
            [2.0, 2.0],
            [1.0, 1.0],
            [0.0, 2.0],
        ]);
        assert_eq!(ring.side_of([1.0, 0.5]), RingSide::Inside);
        assert_eq!(ring.side_of([1.0, 1.5]), RingSide::Outside); // in the notch
        assert_eq!(ring.side_of([1.0, 1.0]), RingSide::Boundary); // the notch vertex
        assert_eq!(ring.side_of([0.5, 1.5]), RingSide::Boundary); // on an edge
        assert_eq!(ring.side_of([2.0, 1.0]), RingSide::Boundary);
        assert_eq!(ring.side_of([-1.0, 1.0]), RingSide::Outside); // ray through the notch vertex
        assert_eq!(ring.side_of([0.5, 1.0]), RingSide::Inside);
        assert_eq!(ring.side_of([-1.0, 0.0]), RingSide::Outside); // ray along the bottom edge
        assert_eq!(ring.side_of([-1.0, 2.0]), RingSide::Outside); // ray through both tips
                                                                  // A point one ulp off an edge of slope 1.
        let tri = Ring::new(vec![[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        let x: f64 = 0.3;
        let above = f64::from_bits(x.to_bits() + 1);
        assert_eq!(tri.side_of([x, above]), RingSide::Inside);
        assert_eq!(tri.side_of([above, x]), RingSide::Outside);
        assert_eq!(tri.side_of([x, x]), RingSide::Boundary);
    }

    #[test]
    fn orientation_of_thin_rings_is_exact() {
        // A sliver far from the origin: the float shoelace sum is all rounding.
        let base = 1e15;
        // The third point is one ulp above the line y = x: counterclockwise.
        let ring = vec![
            [base, base],
            [base + 2.0, base + 2.0],
            [base + 1.0, base + 1.125],
        ];
        let shoelace: f64 = (0..3)
            .map(|i| {
                let (a, b) = (ring[i], ring[(i + 1) % 3]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum();
        assert!(shoelace <= 0.0, "the float sum gets it wrong: {shoelace}");
        assert_eq!(ring_orientation(&ring), Sign::Positive);
        let mut cw = ring.clone();
        cw.reverse();
        assert_eq!(ring_orientation(&cw), Sign::Negative);
        // -0.0 is 0.0: the lowest vertex is (0, 0), not (-0, 2.5), where the turn is flat.
        let ring = vec![[0.0, 0.0], [4.0, 0.0], [4.0, 5.0], [-0.0, 5.0], [-0.0, 2.5]];
        assert_eq!(ring_orientation(&ring), Sign::Positive);
    }

    #[test]
    fn many_rings_agree_with_brute_force() {
        // A grid of nested squares, given in a scrambled order.
        use wdm_crust_testkit::Rng;
        let mut rng = Rng::new(5);
        let mut rings = Vec::new();
        let mut truth_depth = Vec::new();
        for gx in 0..12 {
            for gy in 0..12 {
                let levels = 1 + (gx + gy) % 4;
                for l in 0..levels {
                    let r = 4.0 - l as f64;
                    rings.push(square([gx as f64 * 10.0, gy as f64 * 10.0], r, 1 + l));
                    truth_depth.push(l);
                }
            }
        }
        let order = rng.permutation(rings.len());
        let rings: Vec<_> = order.iter().map(|&k| rings[k].clone()).collect();
        let truth_depth: Vec<usize> = order.iter().map(|&k| truth_depth[k]).collect();
        let built: Vec<Ring> = rings.iter().map(|r| Ring::new(r.clone())).collect();
        let nesting = Nesting::of(&built);
        assert_eq!(nesting.depth, truth_depth);
        let (points, loops) = index_loops(&rings);
        let polygons = nest(&points, &loops);
        let exteriors = truth_depth.iter().filter(|&&d| d % 2 == 0).count();
        assert_eq!(polygons.len(), exteriors);
        let holes: usize = polygons.iter().map(|p| p.holes.len()).sum();
        assert_eq!(holes, rings.len() - exteriors);
    }
}
