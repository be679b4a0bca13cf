//! Voronoi cells clipped to a box: agreement with an exact brute-force reference, and the
//! tiling properties checked in exact rational arithmetic on random, grid, clustered,
//! collinear, duplicate and cocircular inputs at tiny, ordinary and huge scales.

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{Signed, ToPrimitive, Zero};
use proptest::prelude::*;
use wdm_crust::{triangulate, BoundingBox};
use wdm_crust_testkit::Rng;

mod exact;
use exact::{rational as q, twice_area};

type Q = BigRational;

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

/// Half a unit in the last place of `x`, exactly.
fn half_ulp(x: f64) -> Q {
    let a = x.abs();
    q(f64::from_bits(a.to_bits() + 1) - a) / Q::from_integer(BigInt::from(2))
}

/// The properties of a tiling, checked exactly. Per cell, on [`clipped_cell`] (each vertex the
/// exact one correctly rounded):
/// * counterclockwise with positive area and convex up to the rounding of its vertices (each
///   turn is left, or right by less than rounding the three vertices can change it);
/// * a site in the box lies in its cell, up to the rounding of the cell's vertices;
/// * every vertex of the cell of `p` is no farther from `p` than from any other site, up to
///   its rounding: `|v − s|² − |v − p|² ≥ −2 Σ_axis |p − s|_axis · ulp(v_axis)/2`
///   (against all sites when `all_sites`, else against the Delaunay neighbours of `p`, which
///   bound its cell).
///
/// On [`clipped_cells`] (short edges contracted):
/// * duplicates have no cell; every other ring has positive area, lies in the box, holds no
///   vertex twice, contains its site if that is in the box, and each of its vertices is within 64 ulps of a vertex of the cell above;
/// * the signed areas add up to the box's area exactly (shared vertices are identical in
///   every cell, box sides keep their coordinate, so the areas telescope).
///
/// [`clipped_cell`]: wdm_crust::Voronoi::clipped_cell
/// [`clipped_cells`]: wdm_crust::Voronoi::clipped_cells
fn check_tiling(points: &[[f64; 2]], bbox: &BoundingBox, all_sites: bool) -> Vec<Vec<[f64; 2]>> {
    let tri = triangulate(points).expect("valid points");
    let vor = tri.voronoi();
    let cells = vor.clipped_cells(bbox);
    assert_eq!(cells.len(), points.len());
    let mut neighbours: Vec<Vec<usize>> = vec![Vec::new(); points.len()];
    for t in tri.triangles() {
        for k in 0..3 {
            neighbours[t[k] as usize].push(t[(k + 1) % 3] as usize);
            neighbours[t[(k + 1) % 3] as usize].push(t[k] as usize);
        }
    }
    for w in tri.hull().collect::<Vec<_>>().windows(2) {
        neighbours[w[0] as usize].push(w[1] as usize);
        neighbours[w[1] as usize].push(w[0] as usize);
    }
    let mut total = Q::zero();
    for (i, merged) in cells.iter().enumerate() {
        if tri.is_duplicate(i as u32) {
            assert!(merged.is_empty(), "duplicate {i} has a cell");
            continue;
        }
        let ring = vor.clipped_cell(i as u32, bbox);
        if bbox.contains(points[i]) {
            assert!(
                merged.len() >= 3,
                "site {i} in the box has no cell: {ring:?}"
            );
        }
        if !ring.is_empty() {
            let others: Vec<usize> = if all_sites {
                (0..points.len()).collect()
            } else {
                neighbours[i].clone()
            };
            check_cell(points, i, &ring, bbox, &others);
        }
        if merged.is_empty() {
            continue;
        }
        assert!(
            twice_area(merged).is_positive(),
            "cell {i} has no area: {merged:?}"
        );
        let mut sorted = merged.clone();
        sorted.sort_by(|a, b| a[0].total_cmp(&b[0]).then(a[1].total_cmp(&b[1])));
        sorted.dedup();
        assert_eq!(
            sorted.len(),
            merged.len(),
            "cell {i} touches itself: {merged:?}"
        );
        let corners: Vec<[Q; 2]> = merged.iter().map(|c| c.map(q)).collect();
        for k in 0..corners.len() {
            let (a, b) = (&corners[k], &corners[(k + 1) % corners.len()]);
            let site = points[i].map(q);
            if bbox.contains(points[i]) {
                assert!(
                    !cross(a, b, &site).is_negative(),
                    "site {i} outside {merged:?}"
                );
            }
        }
        for v in merged {
            assert!(bbox.contains(*v), "cell {i} leaves the box: {merged:?}");
            // Contracted edges are at most 16 ulps of the larger coordinate magnitude long;
            // these inputs chain at most four of them.
            let near = ring.iter().any(|w| {
                let m = v[0].abs().max(v[1].abs()).max(w[0].abs()).max(w[1].abs());
                let ulp = f64::from_bits(m.to_bits() + 1) - m;
                (0..2).all(|a| (v[a] - w[a]).abs() <= 64.0 * ulp)
            });
            assert!(near, "merged vertex {v:?} of cell {i} is far from {ring:?}");
        }
        total += twice_area(merged);
    }
    let (lo, hi) = (bbox.min(), bbox.max());
    let box_area = (q(hi[0]) - q(lo[0])) * (q(hi[1]) - q(lo[1])) * Q::from_integer(BigInt::from(2));
    assert_eq!(total, box_area, "areas do not add up to the box");
    cells
}

/// The per-cell checks of [`check_tiling`] on one correctly rounded cell of site `i`.
fn check_cell(
    points: &[[f64; 2]],
    i: usize,
    ring: &[[f64; 2]],
    bbox: &BoundingBox,
    others: &[usize],
) {
    let p = points[i].map(q);
    let v: Vec<[Q; 2]> = ring.iter().map(|c| c.map(q)).collect();
    let n = v.len();
    assert!(
        n >= 3 && twice_area(ring).is_positive(),
        "cell {i} has no area: {ring:?}"
    );
    let two = Q::from_integer(BigInt::from(2));
    for k in 0..n {
        let (a, b, c) = (&v[k], &v[(k + 1) % n], &v[(k + 2) % n]);
        // The exact vertices turn left; rounding each coordinate by at most h moves every
        // difference by at most e = 2h and the cross product by the bound below.
        let h = [k, k + 1, k + 2]
            .iter()
            .flat_map(|&j| ring[j % n].map(half_ulp))
            .max()
            .expect("six values");
        let e = &h * &two;
        let l1 = |u: &[Q; 2], w: &[Q; 2]| (&u[0] - &w[0]).abs() + (&u[1] - &w[1]).abs();
        let bound = &e * (l1(b, a) + l1(c, a)) + &e * &e * &two;
        assert!(
            cross(a, b, c) >= -bound,
            "cell {i} not convex at {k}: {ring:?}"
        );
        if bbox.contains(points[i]) {
            let bound = &e * (l1(b, a) + l1(&p, a)) + &e * &e * &two;
            assert!(
                cross(a, b, &p) >= -bound,
                "site {i} outside its cell {ring:?}"
            );
        }
        assert!(bbox.contains(ring[k]), "cell {i} leaves the box: {ring:?}");
    }
    for (k, vertex) in v.iter().enumerate() {
        let h = ring[k].map(half_ulp);
        for &s in others {
            if points[s] == points[i] {
                continue;
            }
            let sq = points[s].map(q);
            let slack = &two * ((&p[0] - &sq[0]).abs() * &h[0] + (&p[1] - &sq[1]).abs() * &h[1]);
            assert!(
                power(vertex, &sq, &p) >= -slack,
                "vertex {:?} of cell {i} is nearer to site {s}",
                ring[k]
            );
        }
    }
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
fn nearly_cocircular_decimal_grids_merge_nearly_coincident_vertices() {
    // stretchdenoise/data/family.p2d: a grid of step 1/11 written to six decimals, so only
    // nearly cocircular. Its Voronoi vertices come in clusters a few 1e-15 apart, which
    // rounding alone turns into rings touching themselves (cell 519).
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/stretchdenoise/data/family.p2d"
    );
    let points = wdm_crust::io::read_points_from_path(std::path::Path::new(path))
        .unwrap_or_else(|e| panic!("{path}: {e}"));
    let bbox = BoundingBox::around(&points).unwrap();
    let cells = check_tiling(&points, &bbox, false);
    let tri = triangulate(&points).unwrap();
    let vor = tri.voronoi();
    let changed = (0..points.len())
        .filter(|&i| vor.clipped_cell(i as u32, &bbox) != cells[i])
        .count();
    assert!(
        changed > 0,
        "no vertex was merged: the test does not exercise merging"
    );
}

#[test]
fn real_point_sets_tile_their_default_box() {
    let dir = concat!(env!("CARGO_MANIFEST_DIR"), "/tests/data");
    let mut files = Vec::new();
    for sub in ["hnn-crust-sgp16", "fitconnect/data", "stretchdenoise/data"] {
        let sub = format!("{dir}/{sub}");
        for entry in std::fs::read_dir(&sub).unwrap_or_else(|e| panic!("{sub}: {e}")) {
            files.push(entry.expect("entry").path());
        }
    }
    files.sort();
    let mut checked = 0;
    for path in files {
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        // family.p2d has its own test above.
        let family = path.file_name().is_some_and(|n| n == "family.p2d");
        if family || !["txt", "xy", "xym", "p2d", "gtn"].contains(&ext) {
            continue;
        }
        let points = wdm_crust::io::read_points_from_path(&path)
            .unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let bbox = BoundingBox::around(&points).expect("points");
        check_tiling(&points, &bbox, false);
        checked += 1;
    }
    assert!(
        checked >= 25,
        "only {checked} point files found under {dir}"
    );
}
