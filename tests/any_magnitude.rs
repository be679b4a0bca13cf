//! Every finite `f64` input is triangulated, its Voronoi dual built and its curves
//! reconstructed, exactly: the same answers under every exact power-of-two scaling from the
//! subnormals to the top of the range, and on input no single scaling brings into the
//! adaptive predicates' range (`1e-300` beside `1e300`, subnormals beside normal values,
//! coordinates near `f64::MAX` whose differences overflow), checked against a brute-force
//! rational reference.

use num_rational::BigRational;
use num_traits::Signed;
use wdm_crust::predicates::circumcenter_exact;
use wdm_crust::reconstruct::{Algorithm, LabelRule, MedialAxisMode, Options, Reconstruction};
use wdm_crust::{reconstruct_with, triangulate, Triangulation, VertexId};

mod exact;
use exact::{incircle, orient, rational as rat};

type P = [f64; 2];

/// A deterministic stream of uniform numbers in `[0, 1)` (a 64-bit LCG's high bits).
fn uniform(seed: u64) -> impl FnMut() -> f64 {
    let mut s = seed;
    move || {
        s = s
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (s >> 11) as f64 / (1u64 << 53) as f64
    }
}

/// `2^k` for `k` in `-1074..=1023`.
fn pow2(k: i32) -> f64 {
    if k >= -1022 {
        f64::from_bits(((k + 1023) as u64) << 52)
    } else {
        f64::from_bits(1 << (k + 1074))
    }
}

/// `x · 2^k`, in two steps (each exact for the inputs here: multiples of `2^-20` below
/// `2^12`, scaled to at least `2^-1074` and below `2^1024`).
fn ldexp(x: f64, k: i32) -> f64 {
    x * pow2(k / 2) * pow2(k - k / 2)
}

/// Dyadic points with structure: a noisy ellipse (a closed curve to reconstruct), a few
/// points of an integer grid (cocircular and collinear sets), and duplicates. Every
/// coordinate is a multiple of `2^-20` below `2^12` in magnitude, so `2^k` scalings for `k`
/// in `-1054..=1011` are exact.
fn dyadic_points(n: usize, seed: u64) -> Vec<P> {
    let mut next = uniform(seed);
    let snap = |x: f64| (x * 1048576.0).round() / 1048576.0;
    let mut pts: Vec<P> = (0..n)
        .map(|i| {
            let t = i as f64 / n as f64 * std::f64::consts::TAU;
            let r = 1.0 + 0.01 * (next() - 0.5);
            [snap(300.0 * r * t.cos()), snap(200.0 * r * t.sin())]
        })
        .collect();
    for x in -2..=2 {
        for y in -2..=2 {
            pts.push([f64::from(x) * 16.0, f64::from(y) * 16.0]);
        }
    }
    pts.push(pts[3]);
    pts.push(pts[n + 2]);
    pts
}

fn edges_of(points: &[P], algorithm: Algorithm) -> Vec<[u32; 2]> {
    let options = Options::new().with_algorithm(algorithm);
    let mut edges = reconstruct_with(points, &options)
        .expect("finite input")
        .edges()
        .to_vec();
    edges.sort_unstable();
    edges
}

const ALGORITHMS: [Algorithm; 3] = [Algorithm::Wdm, Algorithm::Crust, Algorithm::NnCrust];

/// Every WDM reading the options offer: the three label rules, each with the pruned and the
/// raw medial axis.
fn wdm_options() -> Vec<Options> {
    let rules = [
        LabelRule::WaterReached,
        LabelRule::Literal,
        LabelRule::Complement,
    ];
    let modes = [MedialAxisMode::Pruned, MedialAxisMode::Raw];
    rules
        .iter()
        .flat_map(|&rule| {
            modes
                .iter()
                .map(move |&mode| Options::new().with_label_rule(rule).with_medial_axis(mode))
        })
        .collect()
}

/// `scaled` is the reconstruction of `base`'s points times `2^k`: the same labels, edges,
/// curves, unassigned points and passes, the same medial-axis segments, and its vertices
/// `base`'s times `2^k`: exactly where that is normal, else rounded once.
fn assert_same_reconstruction(base: &Reconstruction, scaled: &Reconstruction, k: i32, what: &str) {
    assert_eq!(scaled.labels(), base.labels(), "2^{k}, {what}: labels");
    assert_eq!(scaled.edges(), base.edges(), "2^{k}, {what}: edges");
    assert_eq!(scaled.curves(), base.curves(), "2^{k}, {what}: curves");
    assert_eq!(scaled.unassigned(), base.unassigned(), "2^{k}, {what}");
    assert_eq!(scaled.passes(), base.passes(), "2^{k}, {what}: passes");
    let (axis, base_axis) = (scaled.medial_axis(), base.medial_axis());
    assert_eq!(axis.edges, base_axis.edges, "2^{k}, {what}: axis");
    assert_eq!(
        axis.vertices.len(),
        base_axis.vertices.len(),
        "2^{k}, {what}"
    );
    for (s, o) in axis.vertices.iter().zip(&base_axis.vertices) {
        for i in 0..2 {
            let expected = ldexp(o[i], k);
            if expected.is_normal() || expected == 0.0 {
                assert_eq!(s[i], expected, "2^{k}, {what}: axis vertex {o:?}");
            } else {
                // Subnormal: within half a unit of 2^-1074 of the exact product (scaling
                // the result back up is exact).
                let error = (ldexp(s[i], -k) - o[i]).abs();
                assert!(
                    error <= ldexp(f64::from_bits(1), -k) / 2.0,
                    "2^{k}, {what}: axis vertex {o:?} → {s:?}"
                );
            }
        }
    }
}

/// The same triangles, hull, duplicates and reconstructions under every exact scaling by
/// `2^k`, from subnormal coordinates to coordinates near `2^1023`; Voronoi vertex
/// positions scale with the input wherever both are normal. The whole WDM reconstruction
/// is compared, in every label reading, with the pruned and the raw medial axis: its
/// rounded rules run in a frame that is the same for every such scaling.
#[test]
fn power_of_two_scaling_changes_nothing() {
    let base = dyadic_points(120, 3);
    let tri = triangulate(&base).expect("finite input");
    tri.validate().expect("Delaunay");
    let positions = tri.voronoi().vertex_positions().to_vec();
    let edges: Vec<Vec<[u32; 2]>> = ALGORITHMS.iter().map(|&a| edges_of(&base, a)).collect();
    let readings = wdm_options();
    let whole: Vec<Reconstruction> = readings
        .iter()
        .map(|o| reconstruct_with(&base, o).expect("finite input"))
        .collect();
    // The test means something: the pruned axis has pruned, and points lie inside the
    // curve.
    assert!(whole[0].medial_axis().edges.len() < whole[1].medial_axis().edges.len());
    assert!(!whole[0].unassigned().is_empty());
    let mut ks: Vec<i32> = (-1054..=1011).step_by(53).collect();
    ks.extend([
        -1054, -1000, -970, -900, -400, -150, -143, 190, 201, 400, 900, 1011,
    ]);
    for k in ks {
        let scaled: Vec<P> = base.iter().map(|p| p.map(|x| ldexp(x, k))).collect();
        for (p, q) in base.iter().zip(&scaled) {
            assert_eq!(q.map(|x| ldexp(x, -k)), *p, "2^{k} is exact");
        }
        let t = triangulate(&scaled).unwrap_or_else(|e| panic!("2^{k}: {e}"));
        t.validate().unwrap_or_else(|e| panic!("2^{k}: {e}"));
        assert_eq!(
            t.triangles().collect::<Vec<_>>(),
            tri.triangles().collect::<Vec<_>>(),
            "2^{k}"
        );
        assert_eq!(
            t.hull().collect::<Vec<_>>(),
            tri.hull().collect::<Vec<_>>(),
            "2^{k}"
        );
        assert_eq!(t.duplicates(), tri.duplicates(), "2^{k}");
        for i in 0..scaled.len() as u32 {
            assert_eq!(t.point(i), scaled[i as usize], "caller's coordinates");
        }
        let scaled_positions = t.voronoi().vertex_positions().to_vec();
        assert_eq!(scaled_positions.len(), positions.len());
        for (o, s) in positions.iter().zip(&scaled_positions) {
            let expected = o.map(|x| ldexp(x, k));
            if expected.iter().all(|x| x.is_normal() || *x == 0.0)
                && o.iter().all(|x| x.is_normal() || *x == 0.0)
            {
                assert_eq!(*s, expected, "2^{k}: vertex {o:?}");
            }
        }
        for (a, e) in ALGORITHMS.iter().zip(&edges) {
            assert_eq!(&edges_of(&scaled, *a), e, "2^{k}, {a:?}");
        }
        for (options, base_rec) in readings.iter().zip(&whole) {
            let rec = reconstruct_with(&scaled, options).expect("finite input");
            let what = format!("{:?}, {:?}", options.label_rule(), options.medial_axis());
            assert_same_reconstruction(base_rec, &rec, k, &what);
        }
    }
}

/// 500 points scaled to 1e-100 and to 1e150 (not powers of two: the
/// points differ from the unscaled ones) are triangulated, their dual built and their curve
/// reconstructed.
#[test]
fn five_hundred_points_at_1e_minus_100_and_1e150() {
    let base = dyadic_points(500, 11);
    for scale in [1e-100, 1e150] {
        let pts: Vec<P> = base.iter().map(|p| [p[0] * scale, p[1] * scale]).collect();
        let tri = triangulate(&pts).expect("finite input");
        tri.validate().expect("Delaunay");
        assert!(tri.triangle_count() > 900);
        let voronoi = tri.voronoi();
        for (v, o) in voronoi.vertex_ids().zip(voronoi.vertex_positions()) {
            assert_close(*o, &exact_vertex(&tri, v));
        }
        for a in ALGORITHMS {
            let edges = edges_of(&pts, a);
            assert!(edges.len() >= 500, "{a:?} at {scale:e}: {}", edges.len());
        }
        // The ellipse comes back as one closed curve, as it does unscaled.
        let wdm = reconstruct_with(&pts, &Options::new()).unwrap();
        let unscaled = reconstruct_with(&base, &Options::new()).unwrap();
        assert_eq!(wdm.curves().len(), unscaled.curves().len(), "{scale:e}");
    }
}

// ----------------------------------------------------------------------------------------
// Input that no single power of two brings into the adaptive predicates' range, against a
// rational reference.

/// The triangulation is Delaunay by brute force in rationals: every triangle
/// counterclockwise with no point strictly inside its circle, and as many triangles as
/// Euler's formula gives for its hull (so they cover the hull once).
fn assert_delaunay(tri: &Triangulation) {
    let distinct = tri.distinct_point_count();
    assert!(!tri.is_degenerate());
    assert_eq!(tri.triangle_count(), 2 * distinct - 2 - tri.hull().len());
    for t in tri.triangle_ids() {
        let [a, b, c] = tri.triangle_points(t);
        assert!(
            orient(a, b, c).is_positive(),
            "triangle {t} counterclockwise"
        );
        for i in 0..tri.point_count() as u32 {
            assert!(
                !incircle(a, b, c, tri.point(i)).is_positive(),
                "point {i} inside the circle of triangle {t}"
            );
        }
    }
    tri.validate().expect("the crate's own checker agrees");
}

/// The exact circumcenter of a Voronoi vertex, from the reference's triangle.
fn exact_vertex(tri: &Triangulation, v: VertexId) -> [BigRational; 2] {
    let [a, b, c] = tri.voronoi().vertex_triangle(v);
    let o = circumcenter_exact(a, b, c).expect("Delaunay triangles are not collinear");
    [o.x().clone(), o.y().clone()]
}

/// `got` is within 256 ulps (of its larger coordinate) of `exact`, and infinite only where
/// `exact` rounds to infinity.
fn assert_close(got: P, exact: &[BigRational; 2]) {
    let rounded = |x: &BigRational| {
        // Correct rounding, for the infinity test: compare with the largest finite value
        // plus half its ulp.
        let limit = rat(f64::MAX) + rat(pow2(970));
        if x.abs() >= limit {
            f64::INFINITY.copysign(if x.is_negative() { -1.0 } else { 1.0 })
        } else {
            0.0
        }
    };
    let ulp = |x: f64| {
        // The gap above |x| (for f64::MAX, the gap below: the same binade).
        let a = x.abs().min(f64::from_bits(f64::MAX.to_bits() - 1));
        f64::from_bits(a.to_bits() + 1) - a
    };
    let larger = got[0].abs().max(got[1].abs());
    for i in 0..2 {
        let beyond = rounded(&exact[i]);
        if beyond.is_infinite() {
            assert_eq!(got[i], beyond, "beyond the f64 range");
            continue;
        }
        assert!(
            got[i].is_finite(),
            "{got:?}: finite where the exact value is"
        );
        if larger.is_finite() {
            let error = (rat(got[i]) - &exact[i]).abs();
            assert!(error <= rat(256.0 * ulp(larger)), "{got:?}");
        }
    }
}

/// Checks one wide input completely: triangulation against the reference, every Voronoi
/// vertex position against its exact circumcenter, and every reconstruction algorithm
/// running to an answer made of Delaunay edges.
fn check_wide(points: &[P]) {
    let tri = triangulate(points).expect("finite input");
    assert_delaunay(&tri);
    let voronoi = tri.voronoi();
    for v in voronoi.vertex_ids() {
        assert_close(voronoi.vertex_position(v), &exact_vertex(&tri, v));
    }
    // Every ray's direction is finite and a positive multiple of the hull edge's outward
    // normal, up to one rounding per component: exactly perpendicular where the edge is
    // axis-parallel, and never pointing inward.
    for (e, _, d) in voronoi.rays() {
        assert!(d.iter().all(|x| x.is_finite()) && d != [0.0, 0.0], "{d:?}");
        let a = tri.point(tri.halfedge_origin(e));
        let b = tri.point(tri.halfedge_destination(e));
        let (ex, ey) = (rat(b[0]) - rat(a[0]), rat(b[1]) - rat(a[1]));
        let outward = &ex * rat(d[1]) - &ey * rat(d[0]);
        assert!(
            !outward.is_positive(),
            "ray {d:?} of {a:?} → {b:?} points inward"
        );
        let along = &ex * rat(d[0]) + &ey * rat(d[1]);
        let scale = (ex.abs() + ey.abs()) * (rat(d[0]).abs() + rat(d[1]).abs());
        assert!(
            along.abs() * BigRational::from_float(2f64.powi(50)).unwrap() <= scale,
            "ray {d:?} of {a:?} → {b:?} is no normal"
        );
    }
    let mut delaunay_edges = std::collections::HashSet::new();
    for [a, b, c] in tri.triangles() {
        for (p, q) in [(a, b), (b, c), (c, a)] {
            delaunay_edges.insert([p.min(q), p.max(q)]);
        }
    }
    for a in ALGORITHMS {
        let edges = edges_of(points, a);
        assert!(!edges.is_empty(), "{a:?}");
        for [p, q] in edges {
            assert!(
                delaunay_edges.contains(&[p.min(q), p.max(q)]),
                "{a:?} edge {p}–{q} is a Delaunay edge"
            );
        }
    }
}

/// A closed curve at two scales 2^1200 apart: the ellipse near 1e-180, a ring of points
/// near 1e180 around it, and a lattice of duplicates and cocircular points near 1e-300.
#[test]
fn mixed_magnitudes_1e_minus_300_beside_1e300() {
    let base = dyadic_points(24, 5);
    let mut pts: Vec<P> = base[..24]
        .iter()
        .map(|p| p.map(|x| ldexp(x, -600)))
        .collect();
    pts.extend(base[..24].iter().map(|p| p.map(|x| ldexp(x, 600))));
    pts.extend(base[24..].iter().map(|p| p.map(|x| ldexp(x, -1000))));
    pts.push([1e300, -1e300]);
    pts.push([-1e-300, 1e-300]);
    check_wide(&pts);
}

/// Subnormal coordinates beside normal ones: a lattice in units of 2^-1074 (exactly
/// cocircular and collinear subsets) and points of magnitude 1.
#[test]
fn subnormals_beside_normal_values() {
    let unit = f64::from_bits(1);
    let mut pts: Vec<P> = Vec::new();
    for x in -3..=3 {
        for y in -3..=3 {
            pts.push([f64::from(x) * 5.0 * unit, f64::from(y) * 3.0 * unit]);
        }
    }
    let mut next = uniform(9);
    for _ in 0..12 {
        pts.push([next() * 2.0 - 1.0, next() * 2.0 - 1.0]);
    }
    pts.push([f64::MIN_POSITIVE, -f64::MIN_POSITIVE / 3.0]);
    pts.push([0.0, 0.0]);
    check_wide(&pts);
    // All subnormal: one power of two brings them into range, with the same answer.
    let only: Vec<P> = pts[..49].to_vec();
    let tri = triangulate(&only).expect("finite");
    assert_delaunay(&tri);
    let lifted: Vec<P> = only.iter().map(|p| p.map(|x| ldexp(x, 1074))).collect();
    assert_eq!(
        triangulate(&lifted)
            .unwrap()
            .triangles()
            .collect::<Vec<_>>(),
        tri.triangles().collect::<Vec<_>>()
    );
}

/// Coordinates near ±f64::MAX, whose differences overflow, and points a few ulps apart up
/// there (exactly cocircular in units of 2^971).
#[test]
fn values_near_f64_max() {
    let mut next = uniform(21);
    let mut pts: Vec<P> = (0..20)
        .map(|_| {
            [
                (next() * 2.0 - 1.0) * f64::MAX,
                (next() * 2.0 - 1.0) * f64::MAX,
            ]
        })
        .collect();
    pts.extend([
        [f64::MAX, f64::MAX],
        [-f64::MAX, f64::MAX],
        [f64::MAX, -f64::MAX],
        [-f64::MAX, -f64::MAX],
        [0.0, 0.0],
    ]);
    for [x, y] in [[3, 4], [4, 3], [-3, 4], [5, 0], [0, -5], [-4, -3]] {
        pts.push([
            1.5 * pow2(1023) + f64::from(x) * pow2(971),
            -1.5 * pow2(1023) + f64::from(y) * pow2(971),
        ]);
    }
    check_wide(&pts);
}
