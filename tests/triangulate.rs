//! Property and known-answer tests of the Delaunay triangulation.

use proptest::prelude::*;
use wdm_crust::predicates::{in_circumcircle, CirclePosition};
use wdm_crust::{triangulate, Error, Triangulation};

fn checked(points: &[[f64; 2]]) -> Triangulation {
    let tri = triangulate(points).expect("valid input");
    if let Err(e) = tri.validate() {
        panic!("{e} for {points:?}");
    }
    tri
}

/// Brute force: no distinct point lies strictly inside any triangle's circumcircle.
fn assert_empty_circles(tri: &Triangulation) {
    for t in tri.triangle_ids() {
        let [a, b, c] = tri.triangle_points(t);
        for i in 0..tri.point_count() {
            assert_ne!(
                in_circumcircle(a, b, c, tri.point(i as u32)),
                Some(CirclePosition::Inside),
                "point {i} inside circle of triangle {t}"
            );
        }
    }
}

/// Canonical form of the triangle set: each rotated to start at its smallest index, sorted.
fn canonical(tri: &Triangulation) -> Vec<[u32; 3]> {
    let mut v: Vec<[u32; 3]> = tri
        .triangles()
        .map(|[a, b, c]| {
            if a < b && a < c {
                [a, b, c]
            } else if b < c {
                [b, c, a]
            } else {
                [c, a, b]
            }
        })
        .collect();
    v.sort_unstable();
    v
}

#[test]
fn empty_single_and_pair() {
    assert!(checked(&[]).is_degenerate());
    let one = checked(&[[1.0, 2.0]]);
    assert_eq!(one.hull().collect::<Vec<_>>(), &[0]);
    let two = checked(&[[3.0, 0.0], [1.0, 0.0]]);
    assert_eq!(
        two.hull().collect::<Vec<_>>(),
        &[1, 0],
        "hull of a chain is in lexicographic order"
    );
    let same = checked(&[[3.0, 0.0], [3.0, 0.0], [3.0, 0.0]]);
    assert_eq!(same.hull().collect::<Vec<_>>(), &[0]);
    assert_eq!(same.duplicates(), &[[1, 0], [2, 0]]);
}

#[test]
fn single_triangle_is_ccw_whatever_the_input_order() {
    for pts in [
        [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
        [[0.0, 0.0], [0.0, 1.0], [1.0, 0.0]],
    ] {
        let tri = checked(&pts);
        assert_eq!(tri.triangles().len(), 1);
        assert_eq!(tri.hull().len(), 3);
    }
}

#[test]
fn collinear_points_give_the_chain() {
    let pts: Vec<[f64; 2]> = [5, 0, 3, 9, 1, 3]
        .iter()
        .map(|&i| [i as f64, 2.0 * i as f64])
        .collect();
    let tri = checked(&pts);
    assert_eq!(tri.triangles().len(), 0);
    assert_eq!(tri.hull().collect::<Vec<_>>(), &[1, 4, 2, 0, 3]);
    assert_eq!(tri.duplicates(), &[[5, 2]]);
    // Vertical line: sorted by y.
    let vertical = checked(&[[1.0, 3.0], [1.0, -1.0], [1.0, 2.0]]);
    assert_eq!(vertical.hull().collect::<Vec<_>>(), &[1, 2, 0]);
}

#[test]
fn square_with_duplicates_and_negative_zero() {
    let pts = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
        [0.0, 1.0],
        [-0.0, 0.0],
        [1.0, 1.0],
    ];
    let tri = checked(&pts);
    assert_eq!(tri.triangles().len(), 2);
    assert_eq!(tri.duplicates(), &[[4, 0], [5, 2]]);
    assert_eq!(tri.hull().len(), 4);
}

#[test]
fn integer_grid_is_delaunay_with_collinear_hull_points() {
    let k = 12;
    let pts: Vec<[f64; 2]> = (0..k * k)
        .map(|i| [(i % k) as f64, (i / k) as f64])
        .collect();
    let tri = checked(&pts);
    assert_eq!(
        tri.hull().len(),
        4 * (k - 1),
        "every boundary lattice point is on the hull"
    );
    assert_eq!(tri.triangles().len(), 2 * (k - 1) * (k - 1));
    assert_empty_circles(&tri);
}

#[test]
fn lattice_points_on_a_circle() {
    // All integer points with x^2 + y^2 = 5^2 * 13^2: many exactly cocircular points.
    let r2 = 65i64 * 65;
    let mut pts = Vec::new();
    for x in -65i64..=65 {
        for y in -65i64..=65 {
            if x * x + y * y == r2 {
                pts.push([x as f64, y as f64]);
            }
        }
    }
    assert!(pts.len() >= 30);
    pts.push([0.0, 0.0]);
    let tri = checked(&pts);
    assert_eq!(tri.hull().len(), pts.len() - 1);
    assert_empty_circles(&tri);
}

#[test]
fn errors_name_the_point() {
    assert!(matches!(
        triangulate(&[[0.0, 0.0], [1.0, f64::NAN]]),
        Err(Error::NotFinite { index: 1, .. })
    ));
    assert!(matches!(
        triangulate(&[[0.0, 0.0], [1.0, 1.0], [1.0, f64::NEG_INFINITY]]),
        Err(Error::NotFinite { index: 2, .. })
    ));
    // Every finite coordinate is accepted.
    assert!(triangulate(&[[0.0, 0.0], [1.0, 1.0], [1e300, 0.0], [5e-324, f64::MAX]]).is_ok());
}

/// Points snapped to a small integer lattice: many duplicates, collinear and cocircular sets.
fn lattice_points(max_len: usize, side: i32) -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec((0..side, 0..side), 0..max_len)
        .prop_map(|v| v.into_iter().map(|(x, y)| [x as f64, y as f64]).collect())
}

/// Nearly coincident clusters: a few centres, each point a handful of ulps away.
fn ulp_clusters() -> impl Strategy<Value = Vec<[f64; 2]>> {
    let centre = (-1e3..1e3f64, -1e3..1e3f64);
    let offset = (-4i64..=4, -4i64..=4);
    (
        prop::collection::vec(centre, 1..4),
        prop::collection::vec((0..4usize, offset), 3..60),
    )
        .prop_map(|(centres, pts)| {
            pts.into_iter()
                .map(|(c, (dx, dy))| {
                    let [x, y] = {
                        let c = centres[c % centres.len()];
                        [c.0, c.1]
                    };
                    [ulp_step(x, dx), ulp_step(y, dy)]
                })
                .collect()
        })
}

fn ulp_step(x: f64, k: i64) -> f64 {
    if x == 0.0 {
        return x;
    }
    f64::from_bits((x.to_bits() as i64 + k) as u64)
}

/// Points on a few lines through lattice points (many collinear runs, also on the hull).
fn points_on_lines() -> impl Strategy<Value = Vec<[f64; 2]>> {
    prop::collection::vec(
        ((-5i32..5, -5i32..5), (-3i32..4, -3i32..4), -20i32..20),
        3..80,
    )
    .prop_map(|v| {
        v.into_iter()
            .map(|((x0, y0), (dx, dy), t)| [(x0 + t * dx) as f64, (y0 + t * dy) as f64])
            .collect()
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn random_points_small(pts in prop::collection::vec((-1e3..1e3f64, -1e3..1e3f64), 0..60)) {
        let pts: Vec<[f64; 2]> = pts.into_iter().map(|(x, y)| [x, y]).collect();
        let tri = checked(&pts);
        assert_empty_circles(&tri);
    }

    #[test]
    fn lattice_small(pts in lattice_points(80, 6)) {
        let tri = checked(&pts);
        assert_empty_circles(&tri);
    }

    #[test]
    fn lattice_dense(pts in lattice_points(400, 20)) {
        checked(&pts);
    }

    #[test]
    fn nearly_coincident_clusters(pts in ulp_clusters()) {
        let tri = checked(&pts);
        assert_empty_circles(&tri);
    }

    #[test]
    fn collinear_runs(pts in points_on_lines()) {
        let tri = checked(&pts);
        assert_empty_circles(&tri);
    }

    #[test]
    fn scaling_by_powers_of_two_keeps_the_combinatorics(
        pts in lattice_points(120, 9),
        k in -130i32..190,
    ) {
        let base = checked(&pts);
        let s = 2f64.powi(k);
        let scaled: Vec<[f64; 2]> = pts.iter().map(|p| [p[0] * s, p[1] * s]).collect();
        let tri = checked(&scaled);
        prop_assert_eq!(canonical(&base), canonical(&tri));
        prop_assert_eq!(base.hull().collect::<Vec<_>>(), tri.hull().collect::<Vec<_>>());
        prop_assert_eq!(base.duplicates(), tri.duplicates());
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20))]

    #[test]
    fn random_points_large(
        seed in any::<u64>(),
        n in 500usize..5000,
    ) {
        let mut s = seed;
        let pts: Vec<[f64; 2]> = (0..n).map(|_| {
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let x = (s >> 11) as f64 / (1u64 << 53) as f64;
            s = s.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
            let y = (s >> 11) as f64 / (1u64 << 53) as f64;
            [x, y]
        }).collect();
        checked(&pts);
    }
}
