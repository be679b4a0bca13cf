//! Walks along a segment between two sample points through the full triangulation, every
//! side test the exact `orient`: does the segment cross a curve already found (peeling asks
//! it of a later pass's edges that are no edges of the full triangulation, see `peel.rs`,
//! [`crosses_a_curve`]), and which faces does it pass through (the medial axis blocks them,
//! [`faces_across`])?

use std::ops::ControlFlow;

use super::curves::Adjacency;
use crate::delaunay::{HalfEdge, NO_TWIN};
use crate::ids::{LocalPoint, VertexId};
use crate::kernel::{orient, Sign};
use crate::voronoi::Voronoi;

/// Does the segment from local point `a` to local point `b` of the full triangulation cross
/// an edge of `curve`, or pass through another sample point? An edge of the triangulation
/// crosses nothing. Otherwise every triangulation edge the open segment crosses is tested; a
/// point on the segment (collinear, strictly between `a` and `b`) counts as a crossing: a
/// curve never runs over a sample.
pub(super) fn crosses_a_curve(
    full: &Voronoi<'_>,
    curve: &Adjacency,
    a: LocalPoint,
    b: LocalPoint,
) -> bool {
    if a == b || full.is_delaunay_edge(a, b) {
        return false;
    }
    let tri = full.triangulation();
    let on_curve =
        |u: LocalPoint, v: LocalPoint| (curve.neighbours(u).iter()).any(|&(_, w)| w == v);
    let reached = walk(full, a, b, |x| {
        if on_curve(tri.org(x), tri.dest(x)) {
            ControlFlow::Break(())
        } else {
            ControlFlow::Continue(())
        }
    });
    !reached
}

/// The faces (Voronoi vertices, in order, a merged face once per triangle of it) that the
/// open segment from local point `a` to local point `b` passes through, when it is no edge of
/// the triangulation; `None` where it runs through another sample point.
pub(super) fn faces_across(
    full: &Voronoi<'_>,
    a: LocalPoint,
    b: LocalPoint,
) -> Option<Vec<VertexId>> {
    let twins = full.triangulation().halfedges();
    let mut faces = Vec::new();
    let reached = walk(full, a, b, |x| {
        if faces.is_empty() {
            faces.push(full.vertex_of_halfedge(x));
        }
        faces.push(full.vertex_of_halfedge(twins[x.index()]));
        ControlFlow::Continue(())
    });
    reached.then_some(faces)
}

/// Walks from local point `a` to local point `b` (distinct, no edge of the triangulation)
/// through the triangles the open segment meets, handing `crossing` every triangulation edge
/// it crosses, in order, as the half-edge running from the segment's right to its left
/// (whose twin exists: the segment stays inside the hull). True when the walk reaches `b`;
/// false when `crossing` stops it or the segment runs through another sample point.
fn walk(
    full: &Voronoi<'_>,
    a: LocalPoint,
    b: LocalPoint,
    mut crossing: impl FnMut(HalfEdge) -> ControlFlow<()>,
) -> bool {
    let tri = full.triangulation();
    let at = |p: LocalPoint| tri.position(p);
    let (pa, pb) = (at(a), at(b));
    let side = |p: LocalPoint| orient(pa, pb, at(p));
    let twin = |e: HalfEdge| tri.halfedges()[e.index()];
    // A point collinear with the segment lies on it when it lies on the side of `a` towards
    // `b` (for collinear points, comparing coordinates is exact); such a point blocks.
    let ahead = |p: LocalPoint| {
        let q = at(p);
        let same = |x: f64, y: f64, z: f64| (y - x).signum() == (z - x).signum() || y == x;
        same(pa[0], q[0], pb[0]) && same(pa[1], q[1], pb[1])
    };
    // The triangle around `a` that the segment leaves `a` through: the half-edge `x` of
    // it opposite `a`, whose ends lie left and right of the segment.
    let Some(first) = full
        .delaunay_neighbours(a)
        .next()
        .and_then(|q| full.delaunay_halfedge(a, q))
        .filter(|&e| tri.org(e) == a)
    else {
        return false;
    };
    let mut e = first;
    let mut crossed = None;
    loop {
        let (d, c) = (tri.dest(e), tri.org(e.prev()));
        let (sd, sc) = (side(d), side(c));
        if (sd == Sign::Zero && ahead(d)) || (sc == Sign::Zero && ahead(c)) {
            return false;
        }
        // Triangle `a, d, c` is counterclockwise: the segment runs between `d` (right) and
        // `c` (left).
        if sd == Sign::Negative && sc == Sign::Positive {
            crossed = Some(e.next());
            break;
        }
        let incoming = twin(e.prev());
        if incoming == NO_TWIN || incoming == first {
            break;
        }
        e = incoming;
    }
    let Some(mut x) = crossed else {
        return false;
    };
    // `x` runs from the right of the segment to its left.
    for _ in 0..tri.halfedges().len() {
        let y = twin(x);
        if y == NO_TWIN || crossing(x).is_break() {
            return false;
        }
        // `y` runs from left to right; the third point of its triangle is `w`.
        let w = tri.dest(y.next());
        if w == b {
            return true;
        }
        x = match side(w) {
            Sign::Zero => return false,
            // `w` left: the segment leaves through `right → w`, the edge after `y`.
            Sign::Positive => y.next(),
            // `w` right: it leaves through `w → left`, the edge before `y`.
            Sign::Negative => y.prev(),
        };
    }
    false
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::delaunay::{triangulate, Triangulation};
    use wdm_crust_testkit::Rng;

    fn opposite(s: Sign, t: Sign) -> bool {
        matches!(
            (s, t),
            (Sign::Positive, Sign::Negative) | (Sign::Negative, Sign::Positive)
        )
    }

    /// 4 to 63 random points in even rounds; in odd ones points of a small lattice (segments
    /// through points, collinear runs).
    /// The triangulation of 4 to 63 random points, uniform in even rounds and on a 7 × 7
    /// lattice in odd ones (cocircular faces, collinear runs); `None` when degenerate.
    fn random_triangulation(rng: &mut Rng, round: usize) -> Option<Triangulation> {
        let n = 4 + rng.below(60);
        let points: Vec<[f64; 2]> = (0..n)
            .map(|_| {
                if round % 2 == 0 {
                    [rng.f64(), rng.f64()]
                } else {
                    [rng.below(7) as f64, rng.below(7) as f64]
                }
            })
            .collect();
        let tri = triangulate(&points).unwrap();
        (!tri.is_degenerate()).then_some(tri)
    }

    /// The reference: every curve edge and every point, tested against the segment.
    fn crosses_by_brute_force(
        points: &[[f64; 2]],
        curve: &[[LocalPoint; 2]],
        a: LocalPoint,
        b: LocalPoint,
    ) -> bool {
        let (pa, pb) = (points[a.index()], points[b.index()]);
        let strictly_between = |q: [f64; 2]| {
            let inside = |x: f64, y: f64, z: f64| x.min(z) <= y && y <= x.max(z);
            orient(pa, pb, q) == Sign::Zero
                && inside(pa[0], q[0], pb[0])
                && inside(pa[1], q[1], pb[1])
                && q != pa
                && q != pb
        };
        let on_segment = points.iter().any(|&q| strictly_between(q));
        let crossing = curve.iter().any(|&[u, v]| {
            let (pu, pv) = (points[u.index()], points[v.index()]);
            [u, v].iter().all(|&w| w != a && w != b)
                && opposite(orient(pa, pb, pu), orient(pa, pb, pv))
                && opposite(orient(pu, pv, pa), orient(pu, pv, pb))
        });
        on_segment || crossing
    }

    /// The faces across a segment are those of the triangles whose interior the open
    /// segment meets (no separating line among the triangle's sides and the segment's),
    /// tested triangle by triangle.
    #[test]
    fn the_faces_across_are_the_triangles_the_segment_meets() {
        let mut rng = Rng::new(43);
        let mut walked = 0;
        for round in 0..200 {
            let Some(tri) = random_triangulation(&mut rng, round) else {
                continue;
            };
            let vor = tri.voronoi();
            let local = &tri.points;
            for _ in 0..30 {
                let m = local.len();
                let (a, b) = (rng.below(m) as u32, rng.below(m) as u32);
                let (a, b) = (LocalPoint::new(a), LocalPoint::new(b));
                if a == b || vor.is_delaunay_edge(a, b) {
                    continue;
                }
                let Some(mut faces) = faces_across(&vor, a, b) else {
                    continue;
                };
                walked += 1;
                let (pa, pb) = (local[a.index()], local[b.index()]);
                let mut expected: Vec<VertexId> = (tri.triangle_ids())
                    .filter(|&t| {
                        let corners = tri.triangle_points(t);
                        let sides = corners.map(|q| orient(pa, pb, q));
                        let apart = sides.iter().all(|&s| s != Sign::Positive)
                            || sides.iter().all(|&s| s != Sign::Negative);
                        let outside_a_side = (0..3).any(|k| {
                            let (p, q) = (corners[k], corners[(k + 1) % 3]);
                            orient(p, q, pa) != Sign::Positive && orient(p, q, pb) != Sign::Positive
                        });
                        !apart && !outside_a_side
                    })
                    .map(|t| vor.vertex_of_triangle(t))
                    .collect();
                for list in [&mut faces, &mut expected] {
                    list.sort_unstable();
                    list.dedup();
                }
                assert_eq!(faces, expected, "round {round}: {a} → {b}");
            }
        }
        assert!(walked > 1000, "only {walked} walks");
    }

    #[test]
    fn the_walk_agrees_with_testing_every_edge_and_point() {
        let mut rng = Rng::new(41);
        let mut crossings = 0;
        for round in 0..200 {
            let Some(tri) = random_triangulation(&mut rng, round) else {
                continue;
            };
            let vor = tri.voronoi();
            let local = &tri.points;
            let m = local.len() as u32;
            // A random third of the triangulation's edges is the "curve".
            let mut curve: Vec<[LocalPoint; 2]> = tri
                .halfedge_ids()
                .map(|e| {
                    let (u, v) = (tri.org(e), tri.dest(e));
                    [u.min(v), u.max(v)]
                })
                .filter(|_| rng.below(3) == 0)
                .collect();
            curve.sort_unstable();
            curve.dedup();
            let adjacency = Adjacency::new(local.len(), &curve);
            for _ in 0..30 {
                let (a, b) = (rng.below(m as usize) as u32, rng.below(m as usize) as u32);
                let (a, b) = (LocalPoint::new(a), LocalPoint::new(b));
                let expected =
                    !vor.is_delaunay_edge(a, b) && crosses_by_brute_force(local, &curve, a, b);
                let got = crosses_a_curve(&vor, &adjacency, a, b);
                assert_eq!(got, expected && a != b, "round {round}: {a} → {b}");
                crossings += usize::from(got);
            }
        }
        assert!(crossings > 500, "only {crossings} crossings");
    }
}
