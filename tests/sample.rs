//! Tests of the ground-truth generator `wdm_crust_testkit`: PRNG, lfs against known answers
//! and brute force, the ε-sample property by brute force, determinism, shuffling, noise, SVG.

use std::collections::HashSet;
use std::time::Instant;
use wdm_crust_testkit::*;

/// Brute force: the largest `dist(x, nearest sample) / max(lfs(x), floor)` over all dense x.
fn brute_coverage(set: &CurveSet, samples: &[[f64; 2]], floor: f64) -> f64 {
    let mut worst: f64 = 0.0;
    for (curve, lfs) in set.curves.iter().zip(&set.lfs) {
        for (x, &f) in curve.points.iter().zip(lfs) {
            let d = samples
                .iter()
                .map(|s| (s[0] - x[0]).hypot(s[1] - x[1]))
                .fold(f64::INFINITY, f64::min);
            worst = worst.max(d / f.max(floor));
        }
    }
    worst
}

/// Brute-force O(N²) lfs with the same definition, for cross-checking the k-d tree version.
fn brute_lfs(curves: &[DenseCurve]) -> Vec<f64> {
    let pts: Vec<[f64; 2]> = curves.iter().flat_map(|c| c.points.clone()).collect();
    let nrm: Vec<[f64; 2]> = curves.iter().flat_map(|c| c.normals.clone()).collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &pts {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let cap = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
    let mut centres = Vec::new();
    for (x, n) in pts.iter().zip(&nrm) {
        for s in [1.0, -1.0] {
            let n = [n[0] * s, n[1] * s];
            let mut r = f64::INFINITY;
            for y in &pts {
                let v = [y[0] - x[0], y[1] - x[1]];
                let along = v[0] * n[0] + v[1] * n[1];
                if along > 0.0 {
                    r = r.min((v[0] * v[0] + v[1] * v[1]) / (2.0 * along));
                }
            }
            if r < cap {
                centres.push([x[0] + r * n[0], x[1] + r * n[1]]);
            }
        }
    }
    pts.iter()
        .map(|x| {
            centres
                .iter()
                .map(|c| (c[0] - x[0]).hypot(c[1] - x[1]))
                .fold(cap, f64::min)
        })
        .collect()
}

fn max_rel_err(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs() / y.abs())
        .fold(0.0, f64::max)
}

fn key(p: [f64; 2]) -> (u64, u64) {
    (p[0].to_bits(), p[1].to_bits())
}

/// Ground-truth edges as a set of unordered point pairs (by coordinates, not indices).
fn point_pairs(s: &Sample) -> HashSet<((u64, u64), (u64, u64))> {
    s.edges()
        .iter()
        .map(|&[a, b]| {
            let (p, q) = (key(s.points[a]), key(s.points[b]));
            (p.min(q), p.max(q))
        })
        .collect()
}

#[test]
fn rng_is_deterministic_and_roughly_uniform() {
    let (mut a, mut b, mut c) = (Rng::new(5), Rng::new(5), Rng::new(6));
    let xs: Vec<u64> = (0..100).map(|_| a.next_u64()).collect();
    let ys: Vec<u64> = (0..100).map(|_| b.next_u64()).collect();
    let zs: Vec<u64> = (0..100).map(|_| c.next_u64()).collect();
    assert_eq!(xs, ys);
    assert_ne!(xs, zs);

    let mut rng = Rng::new(1);
    let n = 100_000;
    let mean = (0..n).map(|_| rng.f64()).sum::<f64>() / n as f64;
    assert!((mean - 0.5).abs() < 0.005, "mean {mean}");
    let mut counts = [0usize; 7];
    for _ in 0..70_000 {
        counts[rng.below(7)] += 1;
    }
    assert!(
        counts.iter().all(|&c| (9_500..10_500).contains(&c)),
        "{counts:?}"
    );
    let normals: Vec<f64> = (0..n).map(|_| rng.normal()).collect();
    let m = normals.iter().sum::<f64>() / n as f64;
    let var = normals.iter().map(|z| (z - m) * (z - m)).sum::<f64>() / n as f64;
    assert!(
        m.abs() < 0.02 && (var - 1.0).abs() < 0.02,
        "mean {m} var {var}"
    );

    let mut p = rng.permutation(1000);
    assert_ne!(p, (0..1000).collect::<Vec<_>>());
    p.sort_unstable();
    assert_eq!(p, (0..1000).collect::<Vec<_>>());
}

#[test]
fn derivatives_match_finite_differences() {
    let curves: Vec<Box<dyn ClosedCurve>> = vec![
        Box::new(Ellipse { a: 2.0, b: 0.7 }),
        Box::new(Star { a: 0.25, k: 5 }),
        Box::new(Peanut { a: 0.3, b: 0.15 }),
        Box::new(Superellipse {
            a: 1.5,
            b: 1.0,
            p: 4.0,
        }),
    ];
    for c in &curves {
        for i in 0..50 {
            let t = i as f64 / 50.0 + 0.003;
            let h = 1e-6;
            let (p, q) = (c.point(t + h), c.point(t - h));
            let fd = [(p[0] - q[0]) / (2.0 * h), (p[1] - q[1]) / (2.0 * h)];
            let d = c.derivative(t);
            let scale = d[0].hypot(d[1]);
            assert!(
                (fd[0] - d[0]).abs() + (fd[1] - d[1]).abs() < 1e-5 * scale,
                "t={t}"
            );
        }
        // Period 1.
        let (a, b) = (c.point(0.1), c.point(1.1));
        assert!((a[0] - b[0]).abs() + (a[1] - b[1]).abs() < 1e-12);
    }
}

#[test]
fn circle_lfs_is_radius() {
    let start = Instant::now();
    let circle = Ellipse::circle(3.0)
        .dense(20_000)
        .transformed(&Similarity::translation([5.0, -2.0]));
    let lfs = local_feature_size(std::slice::from_ref(&circle));
    let err = lfs[0].iter().map(|f| (f - 3.0).abs()).fold(0.0, f64::max);
    println!(
        "circle N=20000: max |lfs - R| = {err:e}, {:?}",
        start.elapsed()
    );
    assert!(err < 1e-7 * 3.0);
}

#[test]
fn ellipse_lfs_matches_exact_medial_axis() {
    for (a, b) in [(1.0, 0.5), (2.0, 0.5), (1.0, 0.9)] {
        let e = Ellipse { a, b };
        let start = Instant::now();
        let dense = e.dense(20_000);
        let lfs = local_feature_size(std::slice::from_ref(&dense));
        let elapsed = start.elapsed();
        let exact: Vec<f64> = dense.points.iter().map(|&p| e.exact_lfs(p)).collect();
        let err = max_rel_err(&lfs[0], &exact);
        println!("ellipse a={a} b={b} N=20000: max rel err {err:e}, {elapsed:?}");
        assert!(err < 1e-3, "a={a} b={b}: {err}");
        // Known values at the vertices: b²/a at (a, 0) and b at (0, b).
        assert!((e.exact_lfs([a, 0.0]) - b * b / a).abs() < 1e-12);
        assert!((e.exact_lfs([0.0, b]) - b).abs() < 1e-12);
    }
}

#[test]
fn lfs_matches_brute_force() {
    let square = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
    let sets: Vec<Vec<DenseCurve>> = vec![
        vec![Star { a: 0.3, k: 5 }.dense(1200)],
        vec![Peanut { a: 0.3, b: 0.15 }.dense(1200)],
        vec![Superellipse {
            a: 1.5,
            b: 1.0,
            p: 4.0,
        }
        .dense(1000)],
        vec![DenseCurve::polygon(&square, 800)],
        vec![
            Ellipse::circle(1.0).dense(700),
            Ellipse { a: 0.5, b: 0.3 }.dense(500),
        ],
    ];
    for curves in &sets {
        let fast: Vec<f64> = local_feature_size(curves).concat();
        let slow = brute_lfs(curves);
        let err = max_rel_err(&fast, &slow);
        assert!(err < 3e-5, "fast lfs differs from brute force by {err}");
    }
}

#[test]
fn annulus_lfs_and_interior_medial_axis() {
    let outer = Ellipse::circle(2.0).dense(6000);
    let hole = Ellipse::circle(1.0).dense(3000);
    let curves = vec![outer, hole];
    let lfs = local_feature_size(&curves);
    for f in lfs.concat() {
        assert!((f - 0.5).abs() < 1e-5, "{f}");
    }
    for ball in medial_balls(&curves) {
        let rho = ball.centre[0].hypot(ball.centre[1]);
        if ball.interior {
            assert!((rho - 1.5).abs() < 1e-5 && (ball.radius - 0.5).abs() < 1e-5);
        } else {
            // The hole's own medial axis: its centre.
            assert!(rho < 1e-5 && (ball.radius - 1.0).abs() < 1e-5);
        }
    }
}

fn test_shapes() -> Vec<(&'static str, CurveSet)> {
    let star = Star { a: 0.3, k: 5 }.dense(20_000);
    vec![
        (
            "ellipse",
            CurveSet::new(vec![Ellipse { a: 2.0, b: 0.7 }.dense(20_000)]),
        ),
        ("star", CurveSet::new(vec![star])),
        (
            "peanut",
            CurveSet::new(vec![Peanut { a: 0.3, b: 0.15 }.dense(20_000)]),
        ),
        (
            "superellipse",
            CurveSet::new(vec![Superellipse {
                a: 1.5,
                b: 1.0,
                p: 4.0,
            }
            .dense(20_000)]),
        ),
    ]
}

#[test]
fn eps_samples_cover_every_dense_point() {
    let mut rng = Rng::new(2024);
    for (name, set) in test_shapes() {
        for eps in [0.1, 0.25, 0.39] {
            let sample = set.eps_sample(eps, &mut rng);
            let worst = brute_coverage(&set, &sample.points, 0.0);
            let greedy = set.eps_sample_with(
                &SampleConfig {
                    min_step_fraction: 1.0,
                    ..SampleConfig::new(eps)
                },
                &mut rng,
            );
            println!(
                "{name} eps={eps}: {} samples (greedy {}), coverage {worst:.4}",
                sample.len(),
                greedy.len()
            );
            assert!(worst <= eps * (1.0 + 1e-12), "{name} eps={eps}: {worst}");
            assert!((set.coverage(&sample.points, 0.0) - worst).abs() < 1e-12);
            // Not much denser than needed: close to the bound, and within 2x of greedy.
            assert!(worst > 0.8 * eps, "{name} eps={eps}: too dense ({worst})");
            assert!(sample.len() <= 2 * greedy.len());
            assert!(brute_coverage(&set, &greedy.points, 0.0) <= eps * (1.0 + 1e-12));
            // One closed curve: consecutive samples and the closing pair are the edges.
            assert_eq!(sample.curves.len(), 1);
            assert!(sample.curves[0].closed);
            assert_eq!(sample.edges().len(), sample.len());
            assert_eq!(sample.edge_set().len(), sample.len());
        }
    }
}

#[test]
fn spacing_is_irregular_and_start_is_random() {
    let set = CurveSet::new(vec![Ellipse::circle(1.0).dense(10_000)]);
    let mut rng = Rng::new(9);
    let sample = set.eps_sample(0.2, &mut rng);
    let steps: Vec<f64> = sample
        .edges()
        .iter()
        .map(|&[a, b]| {
            let (p, q) = (sample.points[a], sample.points[b]);
            (p[0] - q[0]).hypot(p[1] - q[1])
        })
        .collect();
    let (lo, hi) = steps
        .iter()
        .fold((f64::INFINITY, 0.0f64), |(l, h), &s| (l.min(s), h.max(s)));
    assert!(hi > 1.4 * lo, "steps too regular: {lo} .. {hi}");
    let other = set.eps_sample(0.2, &mut rng);
    assert_ne!(sample.points[0], other.points[0]);
}

#[test]
fn sampling_is_deterministic() {
    let set = &test_shapes()[1].1;
    let run = |seed| {
        let mut rng = Rng::new(seed);
        set.eps_sample(0.3, &mut rng)
            .with_outliers(5.0, &mut rng)
            .randomized(&mut rng)
    };
    // Debug output compares NaN lfs (outliers) too, which `==` would not.
    assert_eq!(format!("{:?}", run(11)), format!("{:?}", run(11)));
    assert_ne!(run(11).points, run(12).points);
}

#[test]
fn shuffle_and_transform_preserve_adjacency() {
    let mut rng = Rng::new(3);
    let set = CurveSet::new(vec![Peanut { a: 0.3, b: 0.15 }.dense(8000)]);
    let sample = set.eps_sample(0.3, &mut rng);
    let shuffled = sample.shuffled(&mut rng);
    assert_ne!(shuffled.points, sample.points);
    assert_eq!(point_pairs(&shuffled), point_pairs(&sample));
    for (p, f) in shuffled.points.iter().zip(&shuffled.lfs) {
        let i = sample.points.iter().position(|q| q == p).unwrap();
        assert_eq!(sample.lfs[i], *f);
    }

    // A similarity maps the curve set and the sample alike; the ε-sample property survives.
    let s = Similarity {
        angle: 1.1,
        scale: 3.5,
        offset: [-4.0, 7.0],
    };
    let moved = sample.transformed(&s).shuffled(&mut rng);
    let moved_set = set.transformed(&s);
    let before = set.coverage(&sample.points, 0.0);
    let after = moved_set.coverage(&moved.points, 0.0);
    assert!((before - after).abs() < 1e-9, "{before} vs {after}");
    let expected: HashSet<_> = point_pairs(&sample.transformed(&s));
    assert_eq!(point_pairs(&moved), expected);

    let randomized = sample.randomized(&mut rng);
    assert_eq!(randomized.edge_set().len(), sample.edge_set().len());
    let ratio = randomized.lfs.iter().sum::<f64>() / sample.lfs.iter().sum::<f64>();
    let len = |s: &Sample| {
        s.edges()
            .iter()
            .map(|&[a, b]| {
                let (p, q) = (s.points[a], s.points[b]);
                (p[0] - q[0]).hypot(p[1] - q[1])
            })
            .sum::<f64>()
    };
    assert!((len(&randomized) / len(&sample) - ratio).abs() < 1e-9);
}

#[test]
fn multiple_and_nested_curves() {
    let mut rng = Rng::new(77);
    let outer = Ellipse { a: 3.0, b: 2.0 }.dense(15_000);
    let hole = Star { a: 0.2, k: 4 }.dense(8000);
    let island = Ellipse::circle(0.5)
        .dense(4000)
        .transformed(&Similarity::translation([6.0, 0.0]));
    let set = CurveSet::new(vec![outer, hole, island]);
    // The hole shrinks the outer curve's lfs near it: the union matters.
    let alone = local_feature_size(std::slice::from_ref(&set.curves[0]));
    assert!(set.lfs[0]
        .iter()
        .zip(&alone[0])
        .all(|(u, a)| *u <= a + 1e-12));
    assert!(set.lfs[0].iter().zip(&alone[0]).any(|(u, a)| *u < 0.9 * a));

    let sample = set.eps_sample(0.35, &mut rng);
    assert!(brute_coverage(&set, &sample.points, 0.0) <= 0.35 * (1.0 + 1e-12));
    assert_eq!(sample.curves.len(), 3);
    let mut seen = vec![false; sample.len()];
    let mut offset = 0;
    for c in &sample.curves {
        assert!(c.closed);
        assert_eq!(
            c.indices,
            (offset..offset + c.indices.len()).collect::<Vec<_>>()
        );
        offset += c.indices.len();
        for &i in &c.indices {
            seen[i] = true;
        }
    }
    assert!(seen.iter().all(|&s| s));
    assert_eq!(sample.edges().len(), sample.len());

    // Interior medial balls lie between the outer curve and the hole, or inside the island.
    for ball in medial_balls(&set.curves).iter().filter(|b| b.interior) {
        let [x, y] = ball.centre;
        let in_outer = (x / 3.0).powi(2) + (y / 2.0).powi(2) < 1.0;
        let in_island = (x - 6.0).hypot(y) < 0.5;
        let r = x.hypot(y);
        let in_hole = r < 1.0 + 0.2 * (4.0 * y.atan2(x)).cos();
        assert!((in_outer && !in_hole) || in_island, "{:?}", ball.centre);
    }
}

#[test]
fn polygons_keep_their_corners() {
    let mut rng = Rng::new(8);
    let l_shape = [
        [0.0, 0.0],
        [3.0, 0.0],
        [3.0, 1.0],
        [1.0, 1.0],
        [1.0, 2.5],
        [0.0, 2.5],
    ];
    let poly = DenseCurve::polygon(&l_shape, 20_000);
    assert_eq!(poly.corners.len(), 6);
    for (&c, v) in poly.corners.iter().zip(&l_shape) {
        assert_eq!(poly.points[c], *v);
    }
    let set = CurveSet::new(vec![poly]);
    let cfg = SampleConfig {
        lfs_floor: 0.05,
        ..SampleConfig::new(0.3)
    };
    let sample = set.eps_sample_with(&cfg, &mut rng);
    for v in &l_shape {
        assert!(sample.points.contains(v), "corner {v:?} missing");
    }
    assert!(brute_coverage(&set, &sample.points, 0.05) <= 0.3 * (1.0 + 1e-12));
    println!("L-shape: {} samples", sample.len());

    // Open polyline: both ends and the interior corner are samples; edges form a chain.
    let open = DenseCurve::polyline(&[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0]], false, 5000);
    assert_eq!(open.corners.len(), 1);
    let set = CurveSet::new(vec![open]);
    let sample = set.eps_sample_with(&cfg, &mut rng);
    assert!(!sample.curves[0].closed);
    assert_eq!(sample.points[0], [0.0, 0.0]);
    assert_eq!(*sample.points.last().unwrap(), [2.0, 2.0]);
    assert!(sample.points.contains(&[2.0, 0.0]));
    assert_eq!(sample.edges().len(), sample.len() - 1);
    assert!(brute_coverage(&set, &sample.points, 0.05) <= 0.3 * (1.0 + 1e-12));
}

#[test]
fn noise_and_outliers() {
    let mut rng = Rng::new(4);
    let set = CurveSet::new(vec![Ellipse { a: 2.0, b: 1.0 }.dense(8000)]);
    let sample = set.eps_sample(0.1, &mut rng);
    let n = sample.len();
    let noisy = sample.with_outliers(10.0, &mut rng);
    let k = (0.1 * n as f64).round() as usize;
    assert_eq!(noisy.len(), n + k);
    assert_eq!(noisy.edges(), sample.edges());
    for p in &noisy.points[n..] {
        assert!(p[0].abs() <= 2.0 && p[1].abs() <= 1.0);
    }
    assert!(noisy.lfs[n..].iter().all(|f| f.is_nan()));

    let jittered = sample.with_noise(0.01, &mut rng);
    let d2: Vec<f64> = jittered
        .points
        .iter()
        .zip(&sample.points)
        .map(|(p, q)| (p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2))
        .collect();
    // E|δ|² = 2σ²; loose bounds for a few hundred points.
    let mean = d2.iter().sum::<f64>() / n as f64;
    assert!((mean / 2e-4 - 1.0).abs() < 0.3, "{mean}");

    let relative = sample.with_lfs_noise(0.05, &mut rng);
    for ((p, q), f) in relative.points.iter().zip(&sample.points).zip(&sample.lfs) {
        assert!((p[0] - q[0]).hypot(p[1] - q[1]) < 0.05 * f * 8.0);
    }
}

#[test]
fn path_data_parsing() {
    let id = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0];
    // Relative moveto with implicit linetos, H/V, exponents, "0.5.5" = two numbers, z.
    let subs = parse_path_data("m 1,1 2,0 v 1e0 h-2 z M 10 10 L 11 10 .5.5", &id).unwrap();
    assert_eq!(subs.len(), 2);
    assert!(subs[0].closed && !subs[1].closed);
    let ends: Vec<[f64; 2]> = subs[0].segments.iter().map(|s| s.point(1.0)).collect();
    assert_eq!(ends, vec![[3.0, 1.0], [3.0, 2.0], [1.0, 2.0], [1.0, 1.0]]);
    assert_eq!(subs[1].segments[1].point(1.0), [0.5, 0.5]);
    // Relative cubics with implicit repeats, translated by the transform.
    let m = [1.0, 0.0, 0.0, 1.0, 100.0, 0.0];
    let subs = parse_path_data("M0,0c1,0 1,1 0,1 -1,0-1,-1 0,-1z", &m).unwrap();
    assert_eq!(subs[0].segments.len(), 2);
    assert_eq!(
        subs[0].segments[0],
        Segment::Cubic([[100.0, 0.0], [101.0, 0.0], [101.0, 1.0], [100.0, 1.0]])
    );
    assert_eq!(subs[0].segments[1].point(1.0), [100.0, 0.0]);
    assert!(parse_path_data("M 0 0 A 1 1 0 0 0 1 1", &id).is_err());
    assert!(parse_path_data("0 0", &id).is_err());
}

#[test]
fn svg_transforms_and_groups() {
    let svg = r#"<?xml version="1.0"?>
<!-- <path d="M 9 9 L 8 8"/> is a comment -->
<svg xmlns="http://www.w3.org/2000/svg">
  <defs><path d="M 0 0 L 5 5"/></defs>
  <g transform="translate(10,20)">
    <g transform="matrix(2,0,0,2,0,0)">
      <path id="p" d="M 1 1 L 2 1" transform="scale(3)"/>
    </g>
    <path d='M 0 0 L 1 0'></path>
  </g>
</svg>"#;
    let subs = parse_svg(svg).unwrap();
    assert_eq!(subs.len(), 2);
    assert_eq!(
        subs[0].segments[0],
        Segment::Line([16.0, 26.0], [22.0, 26.0])
    );
    assert_eq!(
        subs[1].segments[0],
        Segment::Line([10.0, 20.0], [11.0, 20.0])
    );
}

#[test]
fn svg_files_parse_and_sample() {
    // The sampling2d drawings (GPL-3.0 data, see tests/data/README.md); missing ones fail.
    let dir = std::path::Path::new(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/tests/data/sampling2d/data"
    ));
    assert!(
        dir.is_dir(),
        "test data {} is missing (the real point sets live in tests/data, see its README.md)",
        dir.display()
    );
    let mut files: Vec<_> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "svg"))
        .collect();
    files.sort();
    assert_eq!(files.len(), 19, "SVG drawings in {}", dir.display());
    for path in &files {
        let text = std::fs::read_to_string(path).unwrap();
        let subs = parse_svg(&text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let closed = subs.iter().filter(|s| s.closed).count();
        let name = path.file_stem().unwrap().to_str().unwrap();
        println!("{name}: {} subpaths, {closed} closed", subs.len());
        assert!(!subs.is_empty());
        if ["simple", "blob2", "complex", "spiral"].contains(&name) {
            assert_eq!((subs.len(), closed), (1, 1), "{name}");
        }
    }

    // Sample the single closed curves and one multi-curve drawing.
    let mut rng = Rng::new(10);
    for name in ["simple", "blob2", "complex", "spiral", "f1"] {
        let text = std::fs::read_to_string(dir.join(format!("{name}.svg"))).unwrap();
        let curves = svg_dense_curves(&text, 20_000).unwrap();
        let set = CurveSet::new(curves);
        // A floor stops the grading at corners and where strokes touch (the drawings are
        // about 100 units across).
        let cfg = SampleConfig {
            lfs_floor: 0.5,
            ..SampleConfig::new(0.3)
        };
        let sample = set.eps_sample_with(&cfg, &mut rng);
        let worst = brute_coverage(&set, &sample.points, cfg.lfs_floor);
        println!(
            "{name}: {} curves, {} samples, coverage {worst:.3}",
            set.curves.len(),
            sample.len()
        );
        assert!(worst <= 0.3 * (1.0 + 1e-12));
        assert_eq!(sample.curves.len(), set.curves.len());
    }
}
