//! Point location, the containing triangle and the nearest point against exact brute force
//! (rational arithmetic, independent of the crate's kernel), on random, grid, clustered and
//! collinear input.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, Zero};
use proptest::prelude::*;
use wdm_crust::delaunay::Location;
use wdm_crust::{triangulate, TriangleId, Triangulation};
use wdm_crust_testkit::Rng;

mod exact;
use exact::{orient, squared_distance};

/// `q` in the closed triangle `t` (counterclockwise)?
fn in_closed_triangle(tri: &Triangulation, t: TriangleId, q: [f64; 2]) -> bool {
    let [a, b, c] = tri.triangle_points(t);
    [(a, b), (b, c), (c, a)]
        .iter()
        .all(|&(u, v)| !orient(u, v, q).is_negative())
}

/// `q` strictly between `a` and `b` on their segment?
fn strictly_on_segment(a: [f64; 2], b: [f64; 2], q: [f64; 2]) -> bool {
    let within = |k: usize| a[k].min(b[k]) <= q[k] && q[k] <= a[k].max(b[k]);
    orient(a, b, q).is_zero() && within(0) && within(1) && q != a && q != b
}

/// Checks one answer of `locate` and one of `nearest_point` for `q` against brute force.
fn check_query(tri: &Triangulation, q: [f64; 2], location: Location, nearest: Option<u32>) {
    let n = tri.point_count() as u32;
    let coincident = (0..n).find(|&i| tri.point(i) == q);
    match location {
        Location::Triangle(t) => {
            let [a, b, c] = tri.triangle_points(t);
            for (u, v) in [(a, b), (b, c), (c, a)] {
                assert!(
                    orient(u, v, q).is_positive(),
                    "{q:?} not strictly inside {t}"
                );
            }
        }
        Location::Edge(e) => {
            let (a, b) = (
                tri.point(tri.halfedge_origin(e)),
                tri.point(tri.halfedge_destination(e)),
            );
            assert!(strictly_on_segment(a, b, q), "{q:?} not on edge {e}");
        }
        Location::Vertex(i) => {
            assert_eq!(tri.point(i), q);
            assert!(!tri.is_duplicate(i), "a duplicate named for {q:?}");
        }
        Location::OnChain([a, b]) => {
            assert!(tri.is_degenerate());
            assert!(strictly_on_segment(tri.point(a), tri.point(b), q));
            let hull: Vec<u32> = tri.hull().collect();
            let at = hull.iter().position(|&h| h == a).expect("on the chain");
            assert!(hull.get(at + 1) == Some(&b) || (at > 0 && hull[at - 1] == b));
        }
        Location::Outside => {
            assert!(coincident.is_none(), "{q:?} is an input point");
            for t in tri.triangle_ids() {
                assert!(!in_closed_triangle(tri, t, q), "{q:?} is in triangle {t}");
            }
            if tri.is_degenerate() {
                let hull: Vec<u32> = tri.hull().collect();
                for w in hull.windows(2) {
                    assert!(!strictly_on_segment(tri.point(w[0]), tri.point(w[1]), q));
                }
            }
        }
    }
    if coincident.is_some() {
        assert!(
            matches!(location, Location::Vertex(_)),
            "{q:?}: {location:?}"
        );
    }
    match nearest {
        None => assert_eq!(n, 0),
        Some(found) => {
            let best = (0..n).map(|i| squared_distance(tri.point(i), q)).min();
            assert_eq!(Some(squared_distance(tri.point(found), q)), best, "{q:?}");
            assert!(!tri.is_duplicate(found));
        }
    }
}

/// Queries: random in and around the box, on every point, on edge midpoints (exact when the
/// coordinates allow), far outside.
fn queries(points: &[[f64; 2]], tri: &Triangulation, rng: &mut Rng) -> Vec<[f64; 2]> {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let mut out: Vec<[f64; 2]> = (0..60)
        .map(|_| {
            [0, 1].map(|k| {
                let span = (hi[k] - lo[k]).max(1.0);
                rng.range(lo[k] - 0.2 * span, hi[k] + 0.2 * span)
            })
        })
        .collect();
    out.extend(points.iter().take(30));
    for e in tri.halfedge_ids().step_by(7).take(30) {
        let (a, b) = (
            tri.point(tri.halfedge_origin(e)),
            tri.point(tri.halfedge_destination(e)),
        );
        out.push([(a[0] + b[0]) / 2.0, (a[1] + b[1]) / 2.0]);
    }
    out.push([lo[0] - 1e6, hi[1] + 1e6]);
    out
}

/// Every query through the three entry points (remembering, stateless, hinted): the first
/// answer agrees with brute force, the others name the same place and an equally near point.
fn check_all(points: &[[f64; 2]], rng: &mut Rng) {
    let tri = triangulate(points).expect("valid input");
    let mut locator = tri.locator();
    for q in queries(points, &tri, rng) {
        let remembered = locator.locate(q).unwrap();
        let nearest = locator.nearest(q).unwrap();
        check_query(&tri, q, remembered, nearest);
        // A closed triangle holding q exactly when q is not outside the hull (and there
        // are triangles).
        match locator.triangle_containing(q).unwrap() {
            Some(t) => {
                assert!(in_closed_triangle(&tri, t, q), "{q:?}: not in triangle {t}");
                assert_ne!(remembered, Location::Outside);
            }
            None => assert!(
                tri.triangle_count() == 0 || remembered == Location::Outside,
                "{q:?}: no triangle, but {remembered:?}"
            ),
        }
        let hint = Some(TriangleId::new(
            rng.below(tri.triangle_count().max(1)) as u32
        ));
        for other in [tri.locate(q).unwrap(), tri.locate_from(q, hint).unwrap()] {
            // A triangle or vertex is unique; an edge has two half-edges.
            let same = match (remembered, other) {
                (Location::Edge(a), Location::Edge(b)) => a == b || tri.twin(a) == Some(b),
                (a, b) => a == b,
            };
            assert!(same, "{q:?}: {remembered:?} vs {other:?}");
        }
        let distance = |i: Option<u32>| i.map(|i| squared_distance(tri.point(i), q));
        assert_eq!(distance(tri.nearest_point(q).unwrap()), distance(nearest));
    }
}

#[test]
fn random_points() {
    let mut rng = Rng::new(1);
    for _ in 0..10 {
        let n = 3 + rng.below(150);
        let points: Vec<[f64; 2]> = (0..n).map(|_| [rng.f64(), rng.f64()]).collect();
        check_all(&points, &mut rng);
    }
}

#[test]
fn grids_with_duplicates() {
    // Every query on a grid point, edge or cocircular diagonal is degenerate.
    let mut rng = Rng::new(2);
    for (w, h) in [(2, 2), (3, 5), (9, 9), (17, 4)] {
        let mut points: Vec<[f64; 2]> = (0..w * h)
            .map(|k| [(k % w) as f64, (k / w) as f64])
            .collect();
        points.extend_from_slice(&points.clone()[..w]);
        rng.shuffle(&mut points);
        check_all(&points, &mut rng);
        // Grid queries at half steps: on edges, on diagonals, inside cells.
        let tri = triangulate(&points).unwrap();
        let mut locator = tri.locator();
        for i in 0..2 * w + 1 {
            for j in 0..2 * h + 1 {
                let q = [i as f64 / 2.0 - 0.5, j as f64 / 2.0 - 0.5];
                let location = locator.locate(q).unwrap();
                check_query(&tri, q, location, locator.nearest(q).unwrap());
            }
        }
    }
}

#[test]
fn clustered_points() {
    let mut rng = Rng::new(3);
    for _ in 0..4 {
        let centres: Vec<[f64; 2]> = (0..5)
            .map(|_| [rng.range(-1e3, 1e3), rng.range(-1e3, 1e3)])
            .collect();
        let points: Vec<[f64; 2]> = (0..150)
            .map(|k| {
                let c = centres[k % 5];
                [c[0] + 1e-6 * rng.normal(), c[1] + 1e-6 * rng.normal()]
            })
            .collect();
        check_all(&points, &mut rng);
    }
}

#[test]
fn collinear_and_tiny_inputs() {
    let mut rng = Rng::new(4);
    let line: Vec<[f64; 2]> = (0..20)
        .map(|k| [k as f64 * 0.5, k as f64 * -0.25])
        .collect();
    let mut shuffled = line.clone();
    rng.shuffle(&mut shuffled);
    check_all(&shuffled, &mut rng);
    check_all(&[[1.0, 1.0]], &mut rng);
    check_all(&[[1.0, 1.0], [1.0, 1.0], [3.0, 0.0]], &mut rng);
    let tri = triangulate(&[]).unwrap();
    check_query(&tri, [0.0, 0.0], tri.locate([0.0, 0.0]).unwrap(), None);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn agrees_with_brute_force(
        points in prop::collection::vec((-30i32..30, -30i32..30), 1..50),
        scale in prop::sample::select(vec![1.0, 1e-3, 0.1, 7.0, 1e9]),
        queries in prop::collection::vec((-70i32..70, -70i32..70), 1..30),
    ) {
        // Small integer lattices (scaled): many collinear and cocircular configurations, and
        // queries on half-lattice points hit edges and vertices.
        let points: Vec<[f64; 2]> = points
            .iter()
            .map(|&(x, y)| [x as f64 * scale, y as f64 * scale])
            .collect();
        let tri = triangulate(&points).unwrap();
        let mut locator = tri.locator();
        for &(x, y) in &queries {
            let q = [x as f64 * scale / 2.0, y as f64 * scale / 2.0];
            let location = locator.locate(q).unwrap();
            let nearest = locator.nearest(q).unwrap();
            check_query(&tri, q, location, nearest);
        }
    }
}

#[test]
fn rational_reference_sanity() {
    // The reference itself: a counterclockwise turn is positive.
    assert!(orient([0.0, 0.0], [1.0, 0.0], [0.0, 1.0]).is_positive());
    assert_eq!(
        squared_distance([0.0, 0.0], [3.0, 4.0]),
        BigRational::from_integer(BigInt::from(25))
    );
}
