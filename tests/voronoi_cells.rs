//! Voronoi cells clipped to a box: agreement with an exact brute-force reference, and the
//! tiling properties checked in exact rational arithmetic on random, grid, clustered,
//! collinear, duplicate and cocircular inputs at tiny, ordinary and huge scales.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use proptest::prelude::*;
use wdm_crust::{triangulate, BoundingBox};
use wdm_crust_testkit::Rng;

type Q = BigRational;

fn q(x: f64) -> Q {
    Q::from_float(x).expect("finite")
}

/// `|x − a|² − |x − b|²`.
fn power(x: &[Q; 2], a: &[Q; 2], b: &[Q; 2]) -> Q {
    let d2 = |s: &[Q; 2]| {
        let (dx, dy) = (&x[0] - &s[0], &x[1] - &s[1]);
        &dx * &dx + &dy * &dy
    };
    d2(a) - d2(b)
}

fn cross(o: &[Q; 2], a: &[Q; 2], b: &[Q; 2]) -> Q {
    (&a[0] - &o[0]) * (&b[1] - &o[1]) - (&a[1] - &o[1]) * (&b[0] - &o[0])
}

/// The nearest `f64` to `x`, ties to even: `to_f64` is within an ulp; the neighbours decide.
fn nearest(x: &Q) -> f64 {
    let guess = x.to_f64().expect("in range");
    let step = |v: f64, up: bool| {
        if v == 0.0 {
            return if up {
                f64::from_bits(1)
            } else {
                -f64::from_bits(1)
            };
        }
        let bits = v.to_bits();
        f64::from_bits(if (v > 0.0) == up { bits + 1 } else { bits - 1 })
    };
    let candidates = [step(guess, false), guess, step(guess, true)];
    let mut best = candidates[1];
    let mut best_d = (q(best) - x).abs();
    for c in candidates {
        let d = (q(c) - x).abs();
        if d < best_d || (d == best_d && c.to_bits() & 1 == 0) {
            best = c;
            best_d = d;
        }
    }
    best
}

/// The exact clipped cell of `site`: the box cut by the half-plane of every other distinct
/// point (Sutherland–Hodgman on rationals), vertices in mid-edge dropped, then rounded to the
/// nearest `f64` and put in the library's canonical form.
fn brute_force_cell(points: &[[f64; 2]], site: usize, bbox: &BoundingBox) -> Vec<[f64; 2]> {
    let p = points[site].map(q);
    let (lo, hi) = (bbox.min(), bbox.max());
    let mut poly: Vec<[Q; 2]> = [
        [lo[0], lo[1]],
        [hi[0], lo[1]],
        [hi[0], hi[1]],
        [lo[0], hi[1]],
    ]
    .iter()
    .map(|c| c.map(q))
    .collect();
    for (j, other) in points.iter().enumerate() {
        if *other == points[site] || j == site || poly.is_empty() {
            continue;
        }
        let o = other.map(q);
        let f: Vec<Q> = poly.iter().map(|v| power(v, &o, &p)).collect();
        let mut next = Vec::new();
        for i in 0..poly.len() {
            let k = (i + 1) % poly.len();
            if !f[i].is_negative() {
                next.push(poly[i].clone());
            }
            if (f[i].is_positive() && f[k].is_negative())
                || (f[i].is_negative() && f[k].is_positive())
            {
                let t = &f[i] / (&f[i] - &f[k]);
                next.push([0, 1].map(|a| &poly[i][a] + (&poly[k][a] - &poly[i][a]) * &t));
            }
        }
        poly = next;
    }
    // Drop vertices in the middle of an edge, until none is left.
    loop {
        let n = poly.len();
        let Some(i) =
            (0..n).find(|&i| cross(&poly[(i + n - 1) % n], &poly[i], &poly[(i + 1) % n]).is_zero())
        else {
            break;
        };
        if n < 3 {
            break;
        }
        poly.remove(i);
    }
    if poly.len() < 3 {
        return Vec::new();
    }
    let mut ring: Vec<[f64; 2]> = poly
        .iter()
        .map(|v| [nearest(&v[0]), nearest(&v[1])])
        .collect();
    ring.dedup();
    while ring.len() > 1 && ring.first() == ring.last() {
        ring.pop();
    }
    let start = (0..ring.len())
        .min_by(|&i, &j| {
            ring[i][0]
                .total_cmp(&ring[j][0])
                .then(ring[i][1].total_cmp(&ring[j][1]))
        })
        .unwrap_or(0);
    ring.rotate_left(start);
    ring
}

/// Twice the signed area of a ring, exactly.
fn twice_area(ring: &[[f64; 2]]) -> Q {
    let v: Vec<[Q; 2]> = ring.iter().map(|p| p.map(q)).collect();
    (0..v.len()).fold(Q::zero(), |acc, i| {
        let (a, b) = (&v[i], &v[(i + 1) % v.len()]);
        acc + (&a[0] * &b[1] - &a[1] * &b[0])
    })
}

/// Half a unit in the last place of `x`, exactly.
fn half_ulp(x: f64) -> Q {
    let a = x.abs();
    q(f64::from_bits(a.to_bits() + 1) - a) / Q::from_integer(BigInt::from(2))
}

/// The properties of a tiling, checked exactly:
/// * every cell of a distinct point is counterclockwise with positive area and convex up to
///   the rounding of its vertices (each turn is left, or right by less than rounding the
///   three vertices can change it); duplicates have no cell;
/// * the areas add up to the box's area exactly (shared vertices are rounded identically,
///   box sides keep their coordinate, so the signed areas telescope);
/// * a site in the box lies in its cell;
/// * every vertex of the cell of `p` is no farther from `p` than from any other site, up to
///   the rounding of that vertex: `|v − s|² − |v − p|² ≥ −2 Σ_axis |p − s|_axis · ulp(v)/2`
///   (checked against all sites when `all_sites`, else against every site that has a cell
///   sharing the vertex and the site's Delaunay neighbours — enough for large inputs).
fn check_tiling(points: &[[f64; 2]], bbox: &BoundingBox, all_sites: bool) -> Vec<Vec<[f64; 2]>> {
    let tri = triangulate(points).expect("valid points");
    let vor = tri.voronoi();
    let cells = vor.clipped_cells(bbox);
    assert_eq!(cells.len(), points.len());
    let mut total = Q::zero();
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); points.len()];
    for t in tri.triangles() {
        for k in 0..3 {
            neighbours[t[k] as usize].push(t[(k + 1) % 3] as usize);
            neighbours[t[(k + 1) % 3] as usize].push(t[k] as usize);
        }
    }
    let hull = tri.hull();
    for w in hull.windows(2) {
        neighbours[w[0] as usize].push(w[1] as usize);
        neighbours[w[1] as usize].push(w[0] as usize);
    }
    for (i, ring) in cells.iter().enumerate() {
        if tri.is_duplicate(i as u32) {
            assert!(ring.is_empty(), "duplicate {i} has a cell");
            continue;
        }
        let p = points[i].map(q);
        if bbox.contains(points[i]) {
            assert!(ring.len() >= 3, "site {i} in the box has no cell: {ring:?}");
        }
        if ring.is_empty() {
            continue;
        }
        let v: Vec<[Q; 2]> = ring.iter().map(|c| c.map(q)).collect();
        let n = v.len();
        assert!(
            twice_area(ring).is_positive(),
            "cell {i} has no area: {ring:?}"
        );
        for k in 0..n {
            let (a, b, c) = (&v[k], &v[(k + 1) % n], &v[(k + 2) % n]);
            // The exact vertices turn left; rounding each coordinate by at most h moves
            // every difference by at most e = 2h and the cross product by the bound below.
            let h = [k, k + 1, k + 2]
                .iter()
                .flat_map(|&j| ring[j % n].map(half_ulp))
                .max()
                .expect("six values");
            let e = &h * Q::from_integer(BigInt::from(2));
            let l1 = |u: &[Q; 2], w: &[Q; 2]| (&u[0] - &w[0]).abs() + (&u[1] - &w[1]).abs();
            let bound = &e * (l1(b, a) + l1(c, a)) + &e * &e * Q::from_integer(BigInt::from(2));
            assert!(
                cross(a, b, c) >= -bound,
                "cell {i} not convex at {k}: {ring:?}"
            );
            if bbox.contains(points[i]) {
                assert!(
                    !cross(&v[k], &v[(k + 1) % n], &p).is_negative(),
                    "site {i} outside its cell {ring:?}"
                );
            }
            assert!(bbox.contains(ring[k]), "cell {i} leaves the box: {ring:?}");
        }
        total += twice_area(ring);
        let others: Vec<usize> = if all_sites {
            (0..points.len()).collect()
        } else {
            neighbours[i].clone()
        };
        for (k, vertex) in v.iter().enumerate() {
            let h = ring[k].map(half_ulp);
            for &s in &others {
                if points[s] == points[i] {
                    continue;
                }
                let sq = points[s].map(q);
                let slack = Q::from_integer(BigInt::from(2))
                    * ((&p[0] - &sq[0]).abs() * &h[0] + (&p[1] - &sq[1]).abs() * &h[1]);
                assert!(
                    power(vertex, &sq, &p) >= -slack,
                    "vertex {:?} of cell {i} is nearer to site {s}",
                    ring[k]
                );
            }
        }
    }
    let (lo, hi) = (bbox.min(), bbox.max());
    let box_area = (q(hi[0]) - q(lo[0])) * (q(hi[1]) - q(lo[1])) * Q::from_integer(BigInt::from(2));
    assert_eq!(total, box_area, "areas do not add up to the box");
    cells
}

/// The library's cells equal the brute-force reference, vertex for vertex.
fn check_brute_force(points: &[[f64; 2]], bbox: &BoundingBox) {
    let tri = triangulate(points).expect("valid points");
    let vor = tri.voronoi();
    for i in 0..points.len() {
        let got = vor.clipped_cell(i as u32, bbox);
        if tri.is_duplicate(i as u32) {
            assert!(got.is_empty());
            continue;
        }
        let expected = brute_force_cell(points, i, bbox);
        assert_eq!(got, expected, "cell {i} of {points:?} in {bbox:?}");
    }
}

/// The input kinds of the property tests.
fn generate(kind: u8, n: usize, rng: &mut Rng) -> Vec<[f64; 2]> {
    match kind {
        // Uniform.
        0 => (0..n).map(|_| [rng.f64(), rng.f64()]).collect(),
        // A small lattice: merged cocircular faces, collinear hull runs, duplicates.
        1 => (0..n)
            .map(|_| [rng.below(5) as f64, rng.below(5) as f64])
            .collect(),
        // Tight clusters far apart.
        2 => {
            let centres: Vec<[f64; 2]> = (0..3)
                .map(|_| [rng.range(-100.0, 100.0), rng.range(-100.0, 100.0)])
                .collect();
            (0..n)
                .map(|_| {
                    let c = centres[rng.below(3)];
                    [c[0] + rng.range(-1e-9, 1e-9), c[1] + rng.range(-1e-9, 1e-9)]
                })
                .collect()
        }
        // Collinear, on a line through two random lattice directions, with duplicates.
        3 => {
            let (dx, dy) = (
                [1.0, 0.0, 1.0, 3.0][rng.below(4)],
                [0.0, 1.0, 1.0, -2.0][rng.below(4)],
            );
            let (dx, dy) = if dx == 0.0 && dy == 0.0 {
                (1.0, 0.0)
            } else {
                (dx, dy)
            };
            (0..n)
                .map(|_| {
                    let t = rng.below(2 * n) as f64 - n as f64;
                    [5.0 + t * dx, -3.0 + t * dy]
                })
                .collect()
        }
        // Cocircular: integer points on circles of radius 5, 25 and 65 about the origin, and
        // the centre.
        4 => {
            let base = [
                [3.0, 4.0],
                [5.0, 0.0],
                [7.0, 24.0],
                [15.0, 20.0],
                [25.0, 0.0],
                [16.0, 63.0],
                [33.0, 56.0],
                [39.0, 52.0],
                [25.0, 60.0],
            ];
            let mut pts = vec![[0.0, 0.0]];
            for _ in 0..n {
                let b = base[rng.below(base.len())];
                let (sx, sy) = (
                    if rng.chance(0.5) { -1.0 } else { 1.0 },
                    if rng.chance(0.5) { -1.0 } else { 1.0 },
                );
                let p = if rng.chance(0.5) {
                    [b[0] * sx, b[1] * sy]
                } else {
                    [b[1] * sx, b[0] * sy]
                };
                pts.push(p);
            }
            pts
        }
        // Uniform with many exact duplicates.
        _ => {
            let base: Vec<[f64; 2]> = (0..n.div_ceil(3)).map(|_| [rng.f64(), rng.f64()]).collect();
            (0..n).map(|_| base[rng.below(base.len())]).collect()
        }
    }
}

const SCALES: [f64; 6] = [1.0, 0.1, 1e-30, 1e40, 9.313225746154785e-10, 3.0];

fn scaled(points: &[[f64; 2]], s: f64) -> Vec<[f64; 2]> {
    points.iter().map(|p| [p[0] * s, p[1] * s]).collect()
}

/// A box around the points, or one cutting through them (some sites outside).
fn some_box(points: &[[f64; 2]], rng: &mut Rng, inside: bool) -> BoundingBox {
    let around = BoundingBox::around(points).expect("points");
    if inside {
        return around;
    }
    let (lo, hi) = (around.min(), around.max());
    let pick = |rng: &mut Rng, a: usize| lo[a] + (hi[a] - lo[a]) * rng.range(0.0, 1.0);
    let (x0, x1) = (pick(rng, 0), pick(rng, 0));
    let (y0, y1) = (pick(rng, 1), pick(rng, 1));
    BoundingBox::new([x0.min(x1), y0.min(y1)], [x0.max(x1), y0.max(y1)]).unwrap_or(around)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 100, failure_persistence: None, ..ProptestConfig::default() })]

    #[test]
    fn small_inputs_match_the_brute_force_reference(seed in any::<u64>(), kind in 0u8..6, scale in 0usize..6, inside in any::<bool>()) {
        let mut rng = Rng::new(seed);
        let n = 1 + rng.below(14);
        let points = scaled(&generate(kind, n, &mut rng), SCALES[scale]);
        let bbox = some_box(&points, &mut rng, inside);
        check_brute_force(&points, &bbox);
        check_tiling(&points, &bbox, true);
    }

    #[test]
    fn larger_inputs_tile_the_box(seed in any::<u64>(), kind in 0u8..6, scale in 0usize..6, inside in any::<bool>()) {
        let mut rng = Rng::new(seed);
        let n = 20 + rng.below(200);
        let points = scaled(&generate(kind, n, &mut rng), SCALES[scale]);
        let bbox = some_box(&points, &mut rng, inside);
        check_tiling(&points, &bbox, n <= 50);
    }
}

#[test]
fn known_cells() {
    // One point: the whole box.
    let tri = triangulate(&[[1.0, 1.0]]).unwrap();
    let bbox = BoundingBox::new([0.0, 0.0], [3.0, 2.0]).unwrap();
    assert_eq!(
        tri.voronoi().clipped_cell(0, &bbox),
        vec![[0.0, 0.0], [3.0, 0.0], [3.0, 2.0], [0.0, 2.0]]
    );
    // Two points and a duplicate: two half-boxes.
    let pts = [[0.0, 0.0], [2.0, 0.0], [0.0, 0.0]];
    let tri = triangulate(&pts).unwrap();
    let bbox = BoundingBox::new([-1.0, -1.0], [3.0, 1.0]).unwrap();
    let cells = tri.voronoi().clipped_cells(&bbox);
    assert_eq!(
        cells[0],
        vec![[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]]
    );
    assert_eq!(
        cells[1],
        vec![[1.0, -1.0], [3.0, -1.0], [3.0, 1.0], [1.0, 1.0]]
    );
    assert!(cells[2].is_empty());
    // A 3×3 grid: every cell a unit square around its point (merged faces at the corners).
    let grid: Vec<[f64; 2]> = (0..9).map(|i| [(i % 3) as f64, (i / 3) as f64]).collect();
    let tri = triangulate(&grid).unwrap();
    let bbox = BoundingBox::new([-0.5, -0.5], [2.5, 2.5]).unwrap();
    for (i, cell) in tri.voronoi().clipped_cells(&bbox).iter().enumerate() {
        let [x, y] = grid[i];
        assert_eq!(
            cell,
            &vec![
                [x - 0.5, y - 0.5],
                [x + 0.5, y - 0.5],
                [x + 0.5, y + 0.5],
                [x - 0.5, y + 0.5]
            ]
        );
    }
    // A site outside the box whose cell misses it, and one whose cell reaches in.
    let pts = [[0.0, 0.0], [10.0, 0.0], [1.0, 0.0]];
    let tri = triangulate(&pts).unwrap();
    let bbox = BoundingBox::new([-1.0, -1.0], [4.0, 1.0]).unwrap();
    let cells = tri.voronoi().clipped_cells(&bbox);
    assert!(cells[1].is_empty());
    assert_eq!(
        cells[2],
        vec![[0.5, -1.0], [4.0, -1.0], [4.0, 1.0], [0.5, 1.0]]
    );
    let bbox = BoundingBox::new([6.0, -1.0], [9.0, 1.0]).unwrap();
    let cells = tri.voronoi().clipped_cells(&bbox);
    assert_eq!(
        cells[1],
        vec![[6.0, -1.0], [9.0, -1.0], [9.0, 1.0], [6.0, 1.0]]
    );
    assert!(cells[0].is_empty() && cells[2].is_empty());
    // Out of range: empty, no panic.
    assert!(tri.voronoi().clipped_cell(99, &bbox).is_empty());
}

#[test]
fn a_box_side_through_voronoi_vertices_and_along_a_bisector() {
    // Grid cell corners at half-integers: the box sides run along bisectors and through
    // Voronoi vertices of degree 4.
    let grid: Vec<[f64; 2]> = (0..16).map(|i| [(i % 4) as f64, (i / 4) as f64]).collect();
    for bbox in [
        BoundingBox::new([0.5, 0.5], [2.5, 2.5]).unwrap(),
        BoundingBox::new([-0.5, 0.5], [1.5, 3.0]).unwrap(),
        BoundingBox::new([0.0, 0.0], [3.0, 3.0]).unwrap(),
    ] {
        check_brute_force(&grid, &bbox);
        check_tiling(&grid, &bbox, true);
    }
}

#[test]
fn results_do_not_depend_on_the_input_order() {
    let mut rng = Rng::new(7);
    for kind in 0..6 {
        let points = generate(kind, 80, &mut rng);
        let bbox = BoundingBox::around(&points).unwrap();
        let tri = triangulate(&points).unwrap();
        let cells = tri.voronoi().clipped_cells(&bbox);
        let order = rng.permutation(points.len());
        let shuffled: Vec<[f64; 2]> = order.iter().map(|&i| points[i]).collect();
        let tri2 = triangulate(&shuffled).unwrap();
        let vor2 = tri2.voronoi();
        for (k, &i) in order.iter().enumerate() {
            // A duplicate's first occurrence may change; compare kept points only.
            if !tri.is_duplicate(i as u32) && !tri2.is_duplicate(k as u32) {
                assert_eq!(vor2.clipped_cell(k as u32, &bbox), cells[i], "kind {kind}");
            }
        }
    }
}

#[test]
fn real_point_sets_tile_their_default_box() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data/hnn-crust-sgp16");
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{dir}: {e}"))
        .map(|e| e.expect("entry").path())
        .filter(|p| p.is_file())
        .collect();
    files.sort();
    assert!(!files.is_empty(), "no point files in {dir}");
    let mut checked = 0;
    for path in files {
        let Ok(points) = wdm_crust::io::read_points_from_path(&path) else {
            continue;
        };
        let bbox = BoundingBox::around(&points).expect("points");
        check_tiling(&points, &bbox, false);
        checked += 1;
    }
    assert!(checked > 0, "no readable point file in {dir}");
}
