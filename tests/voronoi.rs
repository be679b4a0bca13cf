//! Known answers and exact consistency checks of the Voronoi dual.

use num_bigint::BigInt;
use num_rational::BigRational;
use proptest::prelude::*;
use wdm_crust::predicates::{circumcenter_exact, ExactPoint};
use wdm_crust::predicates::{in_circumcircle, CirclePosition};
use wdm_crust::triangulate;
use wdm_crust::voronoi::{EdgeEnd, Voronoi};
use wdm_crust::VertexId;

fn rational(x: f64) -> BigRational {
    BigRational::from_float(x).expect("finite")
}

fn squared_distance(c: &ExactPoint, p: [f64; 2]) -> BigRational {
    let dx = c.x() - rational(p[0]);
    let dy = c.y() - rational(p[1]);
    &dx * &dx + &dy * &dy
}

/// Every structural and metric relation of the dual, checked exactly.
fn check_dual(vor: &Voronoi<'_>) {
    let tri = vor.triangulation();
    let n = tri.point_count();
    let mut degree_sum = 0;
    for v in vor.vertex_ids() {
        let centre = vor.vertex_exact(v);
        let sites: Vec<u32> = vor.vertex_sites(v).collect();
        assert!(sites.len() >= 3, "vertex {v} has {} sites", sites.len());
        let r2 = squared_distance(&centre, tri.point(sites[0]));
        for &p in &sites {
            assert_eq!(
                squared_distance(&centre, tri.point(p)),
                r2,
                "vertex {v} not equidistant"
            );
        }
        // No point strictly inside the circle: it is a Delaunay face.
        for i in 0..n as u32 {
            assert!(
                squared_distance(&centre, tri.point(i)) >= r2,
                "point {i} inside circle of vertex {v}"
            );
        }
        degree_sum += vor.degree(v);
        for (k, edge) in vor.vertex_edges(v).enumerate() {
            assert_eq!(edge.from, v);
            assert_eq!(edge.sites[0], sites[k]);
            assert_eq!(edge.sites[1], sites[(k + 1) % sites.len()]);
            assert!(vor.has_dual(edge.halfedge));
            match edge.to {
                EdgeEnd::Vertex(u) => {
                    assert_ne!(u, v);
                    let back = vor.edge(tri.halfedges()[edge.halfedge.index()]);
                    assert_eq!(back.from, u);
                    assert_eq!(back.to, EdgeEnd::Vertex(v));
                    assert_eq!(back.sites, [edge.sites[1], edge.sites[0]]);
                }
                EdgeEnd::Infinity => assert!(vor.has_ray(v)),
            }
        }
    }
    // Cells: each vertex of p's cell has p among its sites, and the incidences agree.
    let mut cell_sum = 0;
    for p in 0..n as u32 {
        let cell: Vec<VertexId> = vor.cell(p).collect();
        let mut sorted = cell.clone();
        sorted.sort_unstable();
        sorted.dedup();
        assert_eq!(
            sorted.len(),
            cell.len(),
            "cell {p} repeats a vertex: {cell:?}"
        );
        for &v in &cell {
            assert!(
                vor.vertex_sites(v).any(|s| s == p),
                "cell {p} lists vertex {v}"
            );
        }
        cell_sum += cell.len();
    }
    assert_eq!(cell_sum, degree_sum, "cell/vertex incidences disagree");
    let finite = vor.finite_edges().count();
    let rays = vor.rays().count();
    assert_eq!(2 * finite + rays, degree_sum);
    // Merged faces exist exactly when some vertex has degree above 3, and a Delaunay edge
    // lacks a dual exactly when both its sides are in one face.
    let merged = vor.vertex_ids().any(|v| vor.degree(v) > 3);
    assert_eq!(vor.has_merged_faces(), merged);
    for e in tri.halfedge_ids() {
        let twin = tri.halfedges()[e.index()];
        let same_face = twin != wdm_crust::delaunay::NO_TWIN
            && vor.vertex_of_halfedge(e) == vor.vertex_of_halfedge(twin);
        assert_eq!(vor.has_dual(e), !same_face);
    }
    // Positions computed one by one (before the cache exists) equal the cached ones, and
    // round the exact circumcenter.
    let one_by_one: Vec<[f64; 2]> = vor.vertex_ids().map(|v| vor.vertex_position(v)).collect();
    assert_eq!(one_by_one, vor.vertex_positions());
    for (v, position) in vor.vertex_ids().zip(&one_by_one) {
        let exact = vor.vertex_exact(v);
        for (k, x) in [exact.x(), exact.y()].into_iter().enumerate() {
            let error = num_traits::Signed::abs(&(rational(position[k]) - x));
            let scale = rational(position[0].abs().max(position[1].abs()).max(1e-300));
            assert!(error <= scale / BigRational::from_integer(BigInt::from(1u64 << 40)));
        }
    }
    if !tri.is_degenerate() {
        assert_eq!(rays, tri.hull().len());
    }
}

#[test]
fn integer_grid_vertices_are_square_centres() {
    let k = 9;
    let pts: Vec<[f64; 2]> = (0..k * k)
        .map(|i| [(i % k) as f64, (i / k) as f64])
        .collect();
    let tri = triangulate(&pts).unwrap();
    let vor = tri.voronoi();
    assert_eq!(vor.vertex_count(), (k - 1) * (k - 1));
    let mut centres: Vec<(i64, i64)> = vor
        .vertex_positions()
        .iter()
        .map(|c| ((2.0 * c[0]) as i64, (2.0 * c[1]) as i64))
        .collect();
    centres.sort_unstable();
    let mut expected: Vec<(i64, i64)> = (0..(k - 1) * (k - 1))
        .map(|i| (2 * (i % (k - 1)) as i64 + 1, 2 * (i / (k - 1)) as i64 + 1))
        .collect();
    expected.sort_unstable();
    assert_eq!(centres, expected);
    for v in vor.vertex_ids() {
        assert_eq!(vor.degree(v), 4);
    }
    // An interior lattice point's cell is the unit square around it.
    let p = (k / 2 * k + k / 2) as u32;
    assert!(vor.is_cell_bounded(p));
    assert_eq!(vor.cell(p).count(), 4);
    check_dual(&vor);
}

#[test]
fn lattice_points_on_a_circle_make_one_vertex() {
    let r2 = 25i64 * 13 * 13;
    let r = (r2 as f64).sqrt() as i64 + 1;
    let mut pts = Vec::new();
    for x in -r..=r {
        for y in -r..=r {
            if x * x + y * y == r2 {
                pts.push([x as f64 + 3.0, y as f64 - 7.0]);
            }
        }
    }
    assert!(pts.len() > 8);
    let tri = triangulate(&pts).unwrap();
    let vor = tri.voronoi();
    assert_eq!(vor.vertex_count(), 1);
    let centre = VertexId::new(0);
    assert_eq!(vor.vertex_position(centre), [3.0, -7.0]);
    let exact = vor.vertex_exact(centre);
    assert_eq!(exact.x(), &BigRational::from_integer(BigInt::from(3)));
    assert_eq!(exact.y(), &BigRational::from_integer(BigInt::from(-7)));
    assert_eq!(vor.degree(centre), pts.len());
    assert_eq!(vor.rays().count(), pts.len());
    assert_eq!(vor.finite_edges().count(), 0);
    for p in 0..pts.len() as u32 {
        assert!(!vor.is_cell_bounded(p));
        assert_eq!(vor.cell(p).collect::<Vec<_>>(), vec![centre]);
    }
    check_dual(&vor);
}

#[test]
fn collinear_input_has_no_vertices() {
    let pts = [[0.0, 0.0], [2.0, 1.0], [4.0, 2.0], [2.0, 1.0]];
    let tri = triangulate(&pts).unwrap();
    let vor = tri.voronoi();
    assert_eq!(vor.vertex_count(), 0);
    assert_eq!(vor.collinear_bisectors(), vec![[0, 1], [1, 2]]);
    assert!((0..4).all(|p| vor.cell(p).next().is_none()));
}

#[test]
fn duplicates_have_empty_cells() {
    let pts = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [0.3, 0.3], [0.3, 0.3]];
    let tri = triangulate(&pts).unwrap();
    let vor = tri.voronoi();
    assert!(vor.is_cell_bounded(3));
    assert_eq!(vor.cell(3).count(), 3);
    assert_eq!(vor.cell(4).count(), 0);
    check_dual(&vor);
}

/// Brute force: circumcenters of all point triples whose circle has no point strictly inside.
fn brute_force_vertices(pts: &[[f64; 2]]) -> Vec<(BigRational, BigRational)> {
    let mut out = Vec::new();
    for i in 0..pts.len() {
        for j in i + 1..pts.len() {
            for k in j + 1..pts.len() {
                let Some(pos) = (0..pts.len())
                    .map(|m| in_circumcircle(pts[i], pts[j], pts[k], pts[m]))
                    .try_fold((), |_, r| match r {
                        Some(CirclePosition::Inside) | None => Err(()),
                        _ => Ok(()),
                    })
                    .ok()
                else {
                    continue;
                };
                let () = pos;
                let c = circumcenter_exact(pts[i], pts[j], pts[k]).unwrap();
                out.push((c.x().clone(), c.y().clone()));
            }
        }
    }
    out.sort();
    out.dedup();
    out
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(150))]

    #[test]
    fn vertices_match_brute_force_on_lattices(pts in prop::collection::vec((0..7i32, 0..7i32), 3..25)) {
        let mut pts: Vec<[f64; 2]> = pts.into_iter().map(|(x, y)| [x as f64, y as f64]).collect();
        pts.sort_by(|a, b| a.partial_cmp(b).unwrap());
        pts.dedup();
        let tri = triangulate(&pts).unwrap();
        let vor = tri.voronoi();
        check_dual(&vor);
        let mut ours: Vec<(BigRational, BigRational)> = vor.vertex_ids()
            .map(|v| { let c = vor.vertex_exact(v); (c.x().clone(), c.y().clone()) })
            .collect();
        ours.sort();
        prop_assert_eq!(ours.len(), vor.vertex_count(), "a vertex appears twice");
        prop_assert_eq!(ours, brute_force_vertices(&pts));
    }

    #[test]
    fn vertices_match_brute_force_on_random_points(pts in prop::collection::vec((-100.0..100.0f64, -100.0..100.0f64), 3..20)) {
        let pts: Vec<[f64; 2]> = pts.into_iter().map(|(x, y)| [x, y]).collect();
        let tri = triangulate(&pts).unwrap();
        let vor = tri.voronoi();
        check_dual(&vor);
        let mut ours: Vec<(BigRational, BigRational)> = vor.vertex_ids()
            .map(|v| { let c = vor.vertex_exact(v); (c.x().clone(), c.y().clone()) })
            .collect();
        ours.sort();
        prop_assert_eq!(ours, brute_force_vertices(&pts));
    }
}
