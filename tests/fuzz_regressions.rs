//! Inputs found by the fuzz targets (`fuzz/`), pasted as literals, with the same exact
//! oracles the targets use (`fuzz/src/checks.rs`, included by path).
//!
//! Tests marked `#[ignore]` pin open bugs in core code: they fail until the bug is fixed
//! (run them with `cargo test --test fuzz_regressions -- --ignored`); remove the `ignore`
//! with the fix.

#[allow(dead_code)]
#[path = "../fuzz/src/checks.rs"]
mod checks;

use wdm_crust::reconstruct::{reconstruct_with, MedialAxisMode, Options};

/// The points of `tests/data/regressions/<name>`.
fn regression_points(name: &str) -> Vec<[f64; 2]> {
    let path = format!(
        "{}/tests/data/regressions/{name}",
        env!("CARGO_MANIFEST_DIR")
    );
    wdm_crust::io::read_points_from_path(std::path::Path::new(&path))
        .unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The points of `tests/data/regressions/<name>` and the permutation its
/// `# permutation ...` comment line gives.
fn points_with_permutation(name: &str) -> (Vec<[f64; 2]>, Vec<usize>) {
    let path = format!(
        "{}/tests/data/regressions/{name}",
        env!("CARGO_MANIFEST_DIR")
    );
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let perm = text
        .lines()
        .find_map(|l| l.strip_prefix("# permutation "))
        .unwrap_or_else(|| panic!("{path}: no permutation line"))
        .split_whitespace()
        .map(|k| k.parse().unwrap())
        .collect();
    (regression_points(name), perm)
}

/// Every check of the `triangulate` and `reconstruct` targets, on `points` and on `points`
/// reversed.
fn check_everything(points: &[[f64; 2]]) {
    let result = wdm_crust::triangulate(points);
    checks::check_triangulate(points, &result).unwrap();
    let Ok(tri) = result else { return };
    checks::check_voronoi(&tri.voronoi()).unwrap();
    // The oracles check the paper's WDM_MAT and peeling, without the detour repair (which
    // swaps first-pass edges; its invariants are checked in the pipeline's tests) and
    // without the open-curve stage (which reads the flow's result); the default, both
    // included, is checked under permutation and for points on three edges.
    let raw = Options::new()
        .with_medial_axis(MedialAxisMode::Raw)
        .with_detour_repair(false)
        .with_open_curves(false);
    let single_options = raw.with_peeling(false);
    let single = reconstruct_with(points, &single_options).unwrap();
    let full = reconstruct_with(points, &raw).unwrap();
    checks::check_single_pass(points, &single).unwrap();
    checks::check_peeled(points, &single, &full).unwrap();
    let perm: Vec<usize> = (0..points.len()).rev().collect();
    let reversed = checks::permute(points, &perm);
    let other = reconstruct_with(&reversed, &single_options).unwrap();
    checks::check_permuted(points, &perm, &single, &other, false, true).unwrap();
    let pruned = wdm_crust::reconstruct(points).unwrap();
    checks::check_default(points, &pruned).unwrap();
    let pruned_reversed = wdm_crust::reconstruct(&reversed).unwrap();
    assert_eq!(
        checks::axis_segments(&pruned),
        checks::axis_segments(&pruned_reversed),
        "pruned medial axis under reversal"
    );
}

/// Sorted vertex positions of the Voronoi diagram, as bits.
fn position_bits(points: &[[f64; 2]]) -> Vec<[u64; 2]> {
    let tri = wdm_crust::triangulate(points).unwrap();
    let mut out: Vec<[u64; 2]> = tri
        .voronoi()
        .vertex_positions()
        .iter()
        .map(|p| p.map(f64::to_bits))
        .collect();
    out.sort_unstable();
    out
}

/// Found by `triangulate` (a bug of the oracle, not of the library): a circumcenter whose x
/// is `2.4e-17` while the points are of order 1. `circumcenter` is accurate normwise (within
/// 256 ulps of the larger coordinate), so `0.0` and `1.1e-16` are both right.
#[test]
fn circumcenter_near_an_axis_is_accurate_normwise() {
    let points = [
        [1.0, -1.0],
        [-0.4999999999999998, -0.1339745962155613],
        [-0.5000000000000004, -1.8660254037844384],
    ];
    check_everything(&points);
    let tri = [points[0], points[1], points[2]];
    checks::check_circumcenter(tri).unwrap();
    checks::check_circumcenter([tri[1], tri[2], tri[0]]).unwrap();
    checks::check_circumcenter([tri[2], tri[0], tri[1]]).unwrap();
}

/// Found by `triangulate` (a bug of the oracle's reference circumcenter, off by a factor 2):
/// an equilateral triangle around the origin.
#[test]
fn equilateral_triangle_around_the_origin() {
    check_everything(&[
        [1.0, 0.0],
        [-0.4999999999999998, 0.8660254037844387],
        [-0.5000000000000004, -0.8660254037844384],
    ]);
}

/// Found by `reconstruct` on a working-tree state of src/delaunay/zorder.rs (12:28, between
/// commits; never committed): a stack overflow (unbounded recursion `settle_runs` →
/// `radix_sort`) on 158 copies of one point, a run of more than 64 equal Z-order keys.
#[test]
fn many_copies_of_one_point() {
    let p = [-9.404430815623905e17, -9.40970847143723e17];
    check_everything(&[p; 158]);
    // The same run next to other points, and 10^4 copies each of three points.
    let mut points = vec![p; 158];
    points.extend([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    check_everything(&points);
    let three = [[0.0, 0.0], [1.0, 0.0], [0.25, 0.75]];
    let copies: Vec<[f64; 2]> = (0..30_000).map(|i| three[i % 3]).collect();
    let tri = wdm_crust::triangulate(&copies);
    checks::check_triangulate(&copies, &tri).unwrap();
}

/// Found by `reconstruct` (medial axis compared bitwise under permutation); fixed.
///
/// src/voronoi.rs, `order_face_cycle`: the boundary cycle of a merged (cocircular) face starts
/// at the half-edge whose origin has the smallest *point index*, so permuting the input
/// rotates the cycle. `vertex_triangle(v)` is the triangle of the first boundary half-edge,
/// and `vertex_position(v)` is computed from it: the merged face of the isosceles trapezoid
/// (points 1, 2, 4, 5) is at `[-164.66167381789984, 4.000000000000001]` for one order and
/// `[-164.66167381789984, 3.999999999999999]` for the other (exact: y = 4 to within 1e-16).
/// Both are within the documented accuracy, but the medial-axis output then depends on the
/// input order, and so does the order of `vertex_sites`/`vertex_edges` of merged vertices,
/// which the water flow and the parity walk follow. Starting the cycle at a half-edge chosen
/// independently of point indices (e.g. the smallest half-edge id of the face: the triangle
/// arrays are identical under permutation) fixes it.
#[test]
fn merged_face_position_does_not_depend_on_the_input_order() {
    let points = [
        [1.570784008902847, 4.999976474595966],
        [-162.48185981524023, 4.704677472743322],
        [-166.84776782337477, 4.684947024235719],
        [-228.46147733521087, 4.068539948665641],
        [-166.84776782337477, 3.3150529757642806],
        [-162.48185981524023, 3.295322527256678],
        [228.91380798907963, 3.972565952009143],
    ];
    let reversed: Vec<[f64; 2]> = points.iter().rev().copied().collect();
    assert_eq!(position_bits(&points), position_bits(&reversed));
}

/// Found by `reconstruct` (peeling on, 600 points of rotated grids; reduced to 17 points).
///
/// With peeling, `parity_inside` labelled vertices by the parity of crust edges crossed on a
/// breadth-first walk from the rays; where the crust is not closed the first path found
/// decided, and that path followed the (index-dependent) boundary order of merged faces.
/// Here the medial axis had 16 segments for the input and 13 for the same points reversed
/// (the crust edges are the same). Making the boundary order index-independent hid it; the
/// cause was removed by counting only hole loops in the parity (see
/// [`medial_axis_of_noisy_chains_does_not_depend_on_the_input_order`]).
#[test]
fn peeled_medial_axis_of_rotated_grids_does_not_depend_on_the_input_order() {
    let points = [
        [58.40224834496213, 71.42952742566177],
        [57.71236069786755, 70.70561097027048],
        [57.02247305077298, 69.98169451487918],
        [56.3325854036784, 69.25777805948788],
        [54.092778420911046, 74.15504920574338],
        [53.40289077381647, 73.43113275035208],
        [52.713003126721894, 72.70721629496077],
        [52.644945510128444, 75.53482449993253],
        [51.95505786303387, 74.81090804454122],
        [51.26517021593929, 74.08699158914992],
        [50.57528256884471, 73.36307513375861],
        [51.23114140764257, 75.5007956916358],
        [50.54125376054799, 74.7768792362445],
        [49.85136611345341, 74.05296278085319],
        [72.58362965927778, 99.35600991125202],
        [49.817337305156684, 75.46676688333908],
        [69.10016261550817, 97.1502317367814],
    ];
    let reversed: Vec<[f64; 2]> = points.iter().rev().copied().collect();
    let a = wdm_crust::reconstruct(&points).unwrap();
    let b = wdm_crust::reconstruct(&reversed).unwrap();
    let perm: Vec<usize> = (0..points.len()).rev().collect();
    checks::check_permuted(&points, &perm, &a, &b, false, false).unwrap();
    assert_eq!(a.edges().len(), b.edges().len());
    assert_eq!(a.medial_axis().edges.len(), b.medial_axis().edges.len());
    assert_eq!(checks::axis_segments(&a), checks::axis_segments(&b));
}

/// Found by `parse` (CI smoke run): a UTF-8 byte-order mark before a header-like first line.
/// The reader skipped the mark and took `JX` for a CSV header, while `detect_format` saw the
/// mark as part of the line and said plain text.
#[test]
fn byte_order_mark_before_a_header() {
    use wdm_crust::io::{detect_format, read_points, InputFormat};
    let data: &[u8] = &[0xEF, 0xBB, 0xBF, b'J', b'X'];
    assert_eq!(detect_format(data), InputFormat::Csv);
    let on_the_fly = read_points(data, None).map_err(|e| e.to_string());
    let detected = read_points(data, Some(detect_format(data))).map_err(|e| e.to_string());
    assert_eq!(on_the_fly, detected);
}

/// Found by `reconstruct` (single pass, 507 points: a shifted lattice of order 10^2 plus
/// points of order 10^-42; `tests/data/regressions/tiny-points-sharing-a-zorder-key.txt`);
/// fixed. The tiny points share one Z-order key, so their order in the divide and conquer,
/// hence the first corner of their triangles, followed the input order; the rounded
/// circumcenter, computed from the first corner, moved by an ulp under permutation.
/// Positions are now computed from a triangle chosen and rotated by coordinates alone
/// (`Voronoi::canonical_triangle`).
#[test]
fn tiny_points_sharing_a_zorder_key_give_order_independent_positions() {
    let (points, perm) = points_with_permutation("tiny-points-sharing-a-zorder-key.txt");
    assert_eq!((points.len(), perm.len()), (507, 507));
    let shuffled = checks::permute(&points, &perm);
    assert_eq!(position_bits(&points), position_bits(&shuffled));
    let options = Options::new().with_peeling(false);
    let rec = reconstruct_with(&points, &options).unwrap();
    let other = reconstruct_with(&shuffled, &options).unwrap();
    checks::check_permuted(&points, &perm, &rec, &other, true, true).unwrap();
    check_everything(&points);
}

/// Found by `reconstruct` (25 minutes, `-max_len=4096 -len_control=0`): 600 points,
/// two closed curves at ~1e40 and ~1e58 scale, 157 duplicates, in two orders. The crust was
/// the same; with peeling the medial axis had 435 segments in one order and 436 in the other.
///
/// Cause: with more than one pass, `parity_inside` decided which inner vertices lie in a hole
/// by the parity of crust edges crossed on a breadth-first walk from the rays. The crust here
/// is all open chains, which bound nothing, so the parity depended on the path the walk took,
/// and the walk's order follows vertex and half-edge ids, which follow the input order. Now
/// only hole loops (closed loops of later-pass edges, every edge with a Voronoi dual) are
/// counted; their parity is the same along every path.
#[test]
fn medial_axis_of_noisy_chains_does_not_depend_on_the_input_order() {
    let read = regression_points;
    let points = read("noisy-chains-at-wide-scales.txt");
    let permuted = read("noisy-chains-at-wide-scales-permuted.txt");
    assert_eq!((points.len(), permuted.len()), (600, 600));
    // permuted[i] = points[perm[i]]; among duplicates any index will do, since the checks map
    // every index to the first occurrence of its coordinates.
    let index_of: std::collections::HashMap<[u64; 2], usize> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (p.map(f64::to_bits), i))
        .collect();
    let perm: Vec<usize> = permuted
        .iter()
        .map(|p| index_of[&p.map(f64::to_bits)])
        .collect();
    for peeling in [false, true] {
        let options = Options::new().with_peeling(peeling);
        let rec = reconstruct_with(&points, &options).unwrap();
        let other = reconstruct_with(&permuted, &options).unwrap();
        checks::check_permuted(&points, &perm, &rec, &other, true, true)
            .unwrap_or_else(|e| panic!("peeling {peeling}: {e}"));
        assert_eq!(checks::axis_segments(&rec), checks::axis_segments(&other));
    }
    check_everything(&points);
}

/// Found by `reconstruct` (its permutation check): 83 points of a curve of order 1e190 and
/// one of order 1e-312 in two orders (`tests/data/regressions/flow-junctions-far-apart-in-
/// scale*.txt`; the seed `fuzz/seeds/reconstruct/warnings-at-flow-junctions-order.bin`).
/// Without the open-curve stage the crust has junctions, which end several chains; the
/// warnings read a junction's curve neighbours off the chain listed last, whose split
/// follows the caller's indices, and called the points a scatter in one order only. They
/// read them off the edges now.
#[test]
fn warnings_same_in_any_order_at_junctions() {
    let read = regression_points;
    let points = read("flow-junctions-far-apart-in-scale.txt");
    let permuted = read("flow-junctions-far-apart-in-scale-permuted.txt");
    assert_eq!((points.len(), permuted.len()), (83, 83));
    let flow_only = Options::new()
        .with_medial_axis(MedialAxisMode::Raw)
        .with_detour_repair(false)
        .with_open_curves(false)
        .with_peeling(false);
    let codes = |p: &[[f64; 2]]| {
        let rec = reconstruct_with(p, &flow_only).unwrap();
        let mut degree = vec![0; p.len()];
        for &[a, b] in rec.edges() {
            degree[a as usize] += 1;
            degree[b as usize] += 1;
        }
        let degree_three = degree.iter().any(|&d| d > 2);
        let codes: Vec<_> = rec.warnings().iter().map(|w| w.code).collect();
        (degree_three, codes)
    };
    let (junctions, mine) = codes(&points);
    assert!(junctions, "the crust has a junction");
    assert!(!mine.is_empty());
    assert_eq!(codes(&permuted).1, mine);
}

/// Found by `reconstruct` (its permutation check): 223 subnormal points whose distinct
/// points are the eight points of a 3 × 3 grid without its centre, 1 ulp apart, in two
/// orders (`tests/data/regressions/subnormal-grid-without-centre*.txt`; the seed
/// `fuzz/seeds/reconstruct/pruned-axis-order-subnormal.bin`). The curve and the raw axis
/// agreed; the pruned axis had 1 segment in one order, 2 in the other and 4 on the same
/// points times 2^1074. Its coverage tests and their ties read circumcenters rounded in the
/// caller's coordinates, where distinct ones round to one subnormal value. The stages after
/// the construction run on the points exactly rescaled (`reconstruct::frame`), and the
/// axis's vertices are rounded once into the caller's coordinates.
#[test]
fn pruned_axis_same_in_any_order_at_subnormal_scale() {
    let read = regression_points;
    let points = read("subnormal-grid-without-centre.txt");
    let permuted = read("subnormal-grid-without-centre-permuted.txt");
    assert_eq!((points.len(), permuted.len()), (223, 223));
    // permuted[i] = points[perm[i]], any occurrence of a duplicate (the checks map every
    // index to the first occurrence of its coordinates).
    let index_of: std::collections::HashMap<[u64; 2], usize> = points
        .iter()
        .enumerate()
        .map(|(i, p)| (p.map(f64::to_bits), i))
        .collect();
    let perm: Vec<usize> = permuted
        .iter()
        .map(|p| index_of[&p.map(f64::to_bits)])
        .collect();
    // The same points in units of 2^-1074: the grid {0, 1, 2} × {-45, -44, -43}.
    let (up, down) = (2f64.powi(537), f64::from_bits(1));
    let unit: Vec<[f64; 2]> = points.iter().map(|p| p.map(|x| x * up * up)).collect();
    assert!(unit
        .iter()
        .flatten()
        .all(|x| x.fract() == 0.0 && x.abs() <= 45.0));
    for mode in [MedialAxisMode::Pruned, MedialAxisMode::Raw] {
        let options = Options::new().with_medial_axis(mode);
        let rec = reconstruct_with(&points, &options).unwrap();
        let other = reconstruct_with(&permuted, &options).unwrap();
        let at_unit = reconstruct_with(&unit, &options).unwrap();
        checks::check_permuted(&points, &perm, &rec, &other, true, true)
            .unwrap_or_else(|e| panic!("{mode:?}: {e}"));
        assert_eq!(checks::axis_segments(&rec), checks::axis_segments(&other));
        // The centre's ball and the four corners' balls: nothing is pruned, at any scale.
        let axis = rec.medial_axis();
        assert_eq!(axis.edges.len(), 4, "{mode:?}");
        assert_eq!(axis.edges, at_unit.medial_axis().edges, "{mode:?}");
        for (v, u) in axis.vertices.iter().zip(&at_unit.medial_axis().vertices) {
            // One rounding of the unit-scale vertex: a single product by 2^-1074.
            assert_eq!(*v, u.map(|x| x * down), "{mode:?}");
        }
        assert_eq!(rec.edges(), at_unit.edges());
        assert_eq!(rec.curves(), at_unit.curves());
        assert_eq!(rec.unassigned(), at_unit.unassigned());
        assert_eq!(rec.labels(), at_unit.labels());
    }
    check_everything(&points);
}

/// Found by `reconstruct` (the default options under permutation, 481 points: a curve of
/// order 1e-41 beside points up to 2.5e260, with pairs of points 1 ulp apart;
/// `tests/data/regressions/near-duplicates-in-a-fine-cluster.txt`, the seed
/// `fuzz/seeds/reconstruct/near-duplicates-in-a-fine-cluster-order.bin`). The detour repair
/// drew `130–131–132` in one order and `130–461–132` in the other (131 and 461 are such a
/// pair). Its steps visit points in local order, which follows the coordinates; but the
/// construction re-keys a cluster finer than its grid, and sorted points of one new key by
/// input index, and a leaf of two or three points keeps the order it is given: the pair's
/// local order followed the input order. Points of one new key are now sorted by their
/// coordinates.
#[test]
fn near_duplicates_in_a_fine_cluster_reconstruct_alike_in_any_order() {
    let (points, perm) = points_with_permutation("near-duplicates-in-a-fine-cluster.txt");
    assert_eq!((points.len(), perm.len()), (481, 481));
    let shuffled = checks::permute(&points, &perm);
    for options in [
        Options::default(),
        Options::new().with_peeling(false),
        Options::new().with_medial_axis(MedialAxisMode::Raw),
    ] {
        let rec = reconstruct_with(&points, &options).unwrap();
        let other = reconstruct_with(&shuffled, &options).unwrap();
        checks::check_permuted(&points, &perm, &rec, &other, true, true)
            .unwrap_or_else(|e| panic!("{options:?}: {e}"));
        assert_eq!(checks::axis_segments(&rec), checks::axis_segments(&other));
    }
    check_everything(&points);
}

/// Found by `triangulate` (a bug of the oracle, not of the library): three points near
/// `f64::MAX`, whose hull edges' coordinate differences overflow. The rays' directions are
/// halved there (documented on `Voronoi::rays`, finite always); the oracle still asked for
/// the unhalved difference, infinite, and now asks for its half where it overflows.
#[test]
fn rays_near_the_largest_coordinates_are_halved_normals() {
    let points = [
        [6.741349255733685e307, 8.98846567431158e307],
        [-1.1154914242865094e308, 1.3439468740929016e307],
        [4.4135649871314045e307, -1.0332412548404481e308],
    ];
    check_everything(&points);
    // The case is the one meant: some hull edge's difference overflows.
    let tri = wdm_crust::triangulate(&points).unwrap();
    let vor = tri.voronoi();
    let overflowing = vor
        .rays()
        .filter(|&(e, _, _)| {
            let a = points[tri.halfedge_origin(e) as usize];
            let b = points[tri.halfedge_destination(e) as usize];
            !(b[1] - a[1]).is_finite() || !(a[0] - b[0]).is_finite()
        })
        .count();
    assert!(overflowing > 0, "no ray's difference overflows");
}

/// Found by `predicates` (a bug of the oracle, not of the library): `exact_hull` sorted the
/// points with `total_cmp`, which puts -0.0 before +0.0, so points on the line x = 0 came out
/// of real order and the monotone chain returned a polygon that was no convex hull; the
/// library's answer for a circumcenter against it (`Inside`) then differed from the
/// reference's on the non-convex polygon (`Outside`). -0.0 now counts as +0.0 there.
#[test]
fn hull_oracle_orders_negative_zero_as_zero() {
    let points: Vec<[f64; 2]> = vec![
        [-0.0, -0.0],
        [-0.0, -0.0],
        [f64::NAN, -3.2138760885179802e60],
        [f64::NAN, -3.2138760885179802e60],
        [-2.504231332820263e29, 1.1278055297264741e45],
        [1.127805334898463e45, -3.2138760885179802e60],
        [-3.2138760885179802e60, -3.2138760885179802e60],
        [f64::NAN, -0.0],
        [-0.0, -0.0],
        [-0.0, 1.1596380697588586e45],
        [1.1278055297264741e45, 1.1278055297264741e45],
        [1.1278055297264741e45, 1.1278048491617403e45],
        [1.1278055297264741e45, 1.1278055297264741e45],
        [1.1278055297264741e45, 1.112149211497159e-308],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [2.703745043491132e21, 6.921587311337298e23],
        [-2.6112773869119406e60, -3.2136799290887494e60],
        [-2.7683737545195607e27, -0.0],
        [0.0, -1.276333326995768e-39],
        [-7.136238463530121e44, f64::NAN],
        [-1.276333326995768e-39, -1.276333326995768e-39],
        [-1.276333326995768e-39, -2.5108406941509467e58],
        [-1.793662034335766e-43, -1.793662034335766e-43],
        [-1.0756748933681452e-204, f64::NAN],
        [f64::NAN, -1.8208637983325627e-39],
        [2.1838841125570927e-39, -1.0756753140308857e-204],
        [-1.8139791862685975e-20, -4.735816483112345e16],
        [f64::NAN, f64::NAN],
        [-2.1882057829645276e-39, -2.1838841125570927e-39],
        [-2.1838841125570927e-39, -1.075675313931279e-204],
        [f64::NAN, -172.6745095402002],
        [f64::NAN, 1.276333326995768e-39],
        [-4.860356790845439e16, -5.404319541467545e16],
        [2.352466890196398e-42, -2.2760797479157034e-40],
        [-3.2138760885179806e60, -4.859867050041343e16],
        [-1.793662034335766e-43, -1.0755676480401616e-204],
        [-1.793662034335766e-43, -1.793662034335766e-43],
        [-1.793662034335766e-43, 5e-324],
    ];
    let tri = [
        [2.352466890196398e-42, -2.2760797479157034e-40],
        [-2.7683737545195607e27, -0.0],
        [-1.8139791862685975e-20, -4.735816483112345e16],
    ];
    let hull = checks::exact_hull(&points, true).unwrap();
    let n = hull.len();
    for i in 0..n {
        let (a, b, c) = (hull[i], hull[(i + 1) % n], hull[(i + 2) % n]);
        // Weakly convex: with `keep_collinear` the points inside hull edges stay (every
        // finite point is in the hull's input, some of them collinear).
        assert_ne!(
            wdm_crust::predicates::orient2d(a, b, c),
            wdm_crust::predicates::Orientation::Clockwise,
            "the exact hull turns clockwise at {b:?}"
        );
    }
    for start in 0..n {
        let mut rotated = hull.clone();
        rotated.rotate_left(start);
        checks::check_hull_position(&rotated, tri).unwrap();
    }
}

/// The default pipeline's oracle (`check_default`: edges partitioned into curves and drawn
/// without crossings or through points, every point on a curve or unassigned, a well-formed
/// pruned axis) on the inputs where peeling, the detour repair and the axis's cavities do
/// most: noisy closed curves (0.3 to 1 sample spacing, with and without a hole) and smooth
/// curves with 10 to 70 % uniform outliers, seeded.
#[test]
fn noisy_and_outlier_inputs_give_well_formed_results() {
    use wdm_crust_testkit::{
        noisy_curve_sample, ClosedCurve, CurveSet, Ellipse, Rng, SampleConfig, Similarity, Star,
    };
    let mut rng = Rng::new(2026);
    let outer = Ellipse { a: 1.5, b: 1.0 }.dense(200);
    let hole = Ellipse::circle(0.4)
        .dense(64)
        .transformed(&Similarity::translation([0.3, 0.0]));
    let star = Star { a: 0.25, k: 5 }.dense(200);
    for noise in [0.3, 0.5, 1.0] {
        for curves in [vec![star.clone()], vec![outer.clone(), hole.clone()]] {
            for _ in 0..4 {
                let points = noisy_curve_sample(&curves, noise, &mut rng);
                let rec = wdm_crust::reconstruct(&points).unwrap();
                checks::check_default(&points, &rec).unwrap();
            }
        }
    }
    let set = CurveSet::new(vec![Star { a: 0.25, k: 5 }.dense(20_000)]);
    let config = SampleConfig {
        eps: 0.3,
        min_step_fraction: 0.8,
        lfs_floor: 0.0,
    };
    for percent in [10.0, 20.0, 40.0, 70.0] {
        for _ in 0..6 {
            let sample = set
                .eps_sample_with(&config, &mut rng)
                .with_outliers(percent, &mut rng)
                .shuffled(&mut rng);
            let rec = wdm_crust::reconstruct(&sample.points).unwrap();
            checks::check_default(&sample.points, &rec).unwrap();
        }
    }
}

/// Found by `reconstruct`: 600 points, two closed curves at ~1e182 and ~1e-302 scale. The
/// facing-corner swap (`repairs/facing.rs`) took edges whose squared lengths overflow or
/// underflow for long ones, swapped consecutive edges into loops of two points (duplicate
/// edges), chose among equal swaps in an order that followed the input's, and ran without the
/// open-curve stage (the single pass must be the flow's crust alone). Now such lengths decide
/// nothing, the swaps are ordered by coordinates, and the swap is part of settling the curves.
#[test]
fn facing_swap_at_the_ends_of_the_range() {
    let points = regression_points("facing-swap-at-the-ends-of-the-range.txt");
    check_everything(&points);
    let perm: Vec<usize> = (0..points.len()).rev().collect();
    let reversed = checks::permute(&points, &perm);
    let (rec, other) = (
        wdm_crust::reconstruct(&points).unwrap(),
        wdm_crust::reconstruct(&reversed).unwrap(),
    );
    checks::check_permuted(&points, &perm, &rec, &other, true, true).unwrap();
}

/// Found by `reconstruct` (single pass, warnings compared under permutation): 510 points,
/// open chains of the single pass meeting at junctions. `chain-ends-close` triangulated the
/// chain ends with a junction once per chain ending there; the copies merged, and the one
/// kept (the first in the input) decided which chain the site stood for, so the warning came
/// in one order and not in the other. Now each end point is one site with all its chains.
#[test]
fn chain_ends_at_junctions_warn_in_any_order() {
    let (points, perm) = points_with_permutation("chain-ends-at-junctions.txt");
    let shuffled = checks::permute(&points, &perm);
    let options = Options::new()
        .with_medial_axis(MedialAxisMode::Raw)
        .with_detour_repair(false)
        .with_open_curves(false)
        .with_thinning(false)
        .with_peeling(false);
    let rec = reconstruct_with(&points, &options).unwrap();
    let other = reconstruct_with(&shuffled, &options).unwrap();
    checks::check_permuted(&points, &perm, &rec, &other, false, true).unwrap();
    check_everything(&points);
}
