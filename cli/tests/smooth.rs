//! Smoothing (`Options::with_smoothing`, `reconstruct --smooth`): the fitted curves are
//! closer to the true curve than the noisy samples, clean samples and corners stay where
//! they are, every curve stays simple (an exact test), and the result depends neither on the
//! input order nor on an exact power-of-two scale; the command line writes the library's
//! coordinates.

mod common;

use wdm_crust::predicates::{orient2d, Orientation};
use wdm_crust::reconstruct::{reconstruct_with, Algorithm, Options};
use wdm_crust::Reconstruction;
use wdm_crust_testkit::{ClosedCurve, CurveSet, Ellipse, Rng, SampleConfig, Similarity, Star};

fn smoothed(points: &[[f64; 2]]) -> Reconstruction {
    reconstruct_with(points, &Options::new().with_smoothing(true)).unwrap()
}

/// `n` points at uniformly random angles on the circle of radius `r` about the origin, with
/// Gaussian noise of `sigma` on each coordinate.
fn noisy_circle(n: usize, r: f64, sigma: f64, rng: &mut Rng) -> Vec<[f64; 2]> {
    (0..n)
        .map(|_| {
            let t = rng.f64() * std::f64::consts::TAU;
            [
                r * t.cos() + sigma * rng.normal(),
                r * t.sin() + sigma * rng.normal(),
            ]
        })
        .collect()
}

fn rms(values: impl Iterator<Item = f64>) -> f64 {
    let (mut sum, mut count) = (0.0, 0usize);
    for v in values {
        sum += v * v;
        count += 1;
    }
    (sum / count.max(1) as f64).sqrt()
}

/// Exactly: does the closed segment `a b` meet the closed segment `c d`?
fn segments_meet(a: [f64; 2], b: [f64; 2], c: [f64; 2], d: [f64; 2]) -> bool {
    let side = |p, q, r| match orient2d(p, q, r) {
        Orientation::CounterClockwise => 1,
        Orientation::Clockwise => -1,
        _ => 0,
    };
    let within = |p: [f64; 2], q: [f64; 2], r: [f64; 2]| {
        (0..2).all(|k| p[k].min(q[k]) <= r[k] && r[k] <= p[k].max(q[k]))
    };
    let (o1, o2, o3, o4) = (side(a, b, c), side(a, b, d), side(c, d, a), side(c, d, b));
    (o1 * o2 < 0 && o3 * o4 < 0)
        || (o1 == 0 && within(a, b, c))
        || (o2 == 0 && within(a, b, d))
        || (o3 == 0 && within(c, d, a))
        || (o4 == 0 && within(c, d, b))
}

/// Every closed curve's fitted ring is simple and counterclockwise, no two curves meet, by
/// brute force over all pairs of segments with exact orientations: segments that share a
/// point only there (and not folded back onto each other).
fn assert_simple(rec: &Reconstruction, what: &str) {
    let mut segments = Vec::new();
    for c in rec.curves() {
        let k = c.points.len();
        let coords = rec.curve_coords(c);
        let count = if c.closed { k } else { k - 1 };
        for i in 0..count {
            let j = (i + 1) % k;
            segments.push(([c.points[i], c.points[j]], [coords[i], coords[j]]));
        }
        if c.closed {
            // Counterclockwise: the turn at the lowest vertex.
            let low = (0..k)
                .min_by(|&x, &y| coords[x].partial_cmp(&coords[y]).unwrap())
                .unwrap();
            let turn = orient2d(
                coords[(low + k - 1) % k],
                coords[low],
                coords[(low + 1) % k],
            );
            assert_eq!(turn, Orientation::CounterClockwise, "{what}: a ring turned");
        }
    }
    for (x, (s, ps)) in segments.iter().enumerate() {
        assert_ne!(ps[0], ps[1], "{what}: a segment of length zero");
        for (t, pt) in &segments[x + 1..] {
            let shared: Vec<u32> = s.iter().filter(|p| t.contains(p)).copied().collect();
            if let [p] = shared[..] {
                // Sharing an end: they may not overlap beyond it.
                let c = if s[0] == p { ps[0] } else { ps[1] };
                let a = if s[0] == p { ps[1] } else { ps[0] };
                let b = if t[0] == p { pt[1] } else { pt[0] };
                let folded = orient2d(c, a, b) == Orientation::Collinear
                    && (segments_meet(c, a, b, b) || segments_meet(c, b, a, a));
                assert!(!folded, "{what}: {s:?} folds over {t:?}");
            } else {
                assert!(
                    !segments_meet(ps[0], ps[1], pt[0], pt[1]),
                    "{what}: {s:?} meets {t:?}"
                );
            }
        }
    }
}

/// On a dense noisy circle (1000 points, noise of 0.5 % of the diagonal: about two sample
/// spacings) the fitted vertices are far closer to the circle than the samples: RMS at most
/// 0.6 of the input's, on every seed whose reconstruction is the one
/// circle (most of them; smoothing does not change the curves).
#[test]
fn a_noisy_circle_is_fitted_well_within_its_noise() {
    let mut judged = 0;
    for seed in 0..8 {
        let mut rng = Rng::new(100 + seed);
        let sigma = 0.005 * 2.0 * 2.0f64.sqrt();
        let points = noisy_circle(1000, 1.0, sigma, &mut rng);
        let rec = smoothed(&points);
        assert_simple(&rec, &format!("seed {seed}"));
        if rec.curves().len() != 1 || !rec.curves()[0].closed {
            continue;
        }
        judged += 1;
        let curve = &rec.curves()[0];
        let off = |p: [f64; 2]| (p[0].hypot(p[1]) - 1.0).abs();
        let input = rms(points.iter().map(|&p| off(p)));
        let fitted = rms(rec.curve_coords(curve).into_iter().map(off));
        assert!(
            fitted <= 0.6 * input,
            "seed {seed}: fitted {fitted:.5} against the input's {input:.5}"
        );
    }
    assert!(judged >= 4, "only {judged} seeds reconstructed the circle");
}

/// A dense band of 20 000 points (σ = 1 and 2 % of the diagonal) is thinned to a few
/// dozen representatives, a step apart by hundreds of samples: every vertex of its curve is
/// fitted to them, and the fitted curve lies far closer to the circle than the samples do.
/// The windows of such bands stopped at a fixed cap of samples while still round (no curve
/// piece), and no vertex moved: the curve stayed at the representatives.
#[test]
fn a_band_of_many_points_a_step_is_fitted() {
    for (seed, share) in [(131, 0.01), (132, 0.02)] {
        let mut rng = Rng::new(seed);
        let sigma = share * 2.0 * 2.0f64.sqrt();
        let points = noisy_circle(20_000, 1.0, sigma, &mut rng);
        let rec = smoothed(&points);
        assert!(rec.thinned().is_some(), "σ = {share}");
        assert_eq!(rec.curves().len(), 1, "σ = {share}");
        let curve = &rec.curves()[0];
        let fitted = rec.curve_coords(curve);
        let unmoved = curve
            .points
            .iter()
            .zip(&fitted)
            .filter(|&(&i, &f)| f == points[i as usize])
            .count();
        assert_eq!(unmoved, 0, "σ = {share}");
        let off = |p: [f64; 2]| (p[0].hypot(p[1]) - 1.0).abs();
        let input = rms(points.iter().map(|&p| off(p)));
        let representatives = rms(curve.points.iter().map(|&i| off(points[i as usize])));
        let smoothed = rms(fitted.into_iter().map(off));
        assert!(
            smoothed <= 0.15 * input && smoothed < representatives,
            "σ = {share}: fitted {smoothed:.5}, representatives {representatives:.5}, input {input:.5}"
        );
    }
}

/// On clean ε-samples of smooth curves (ε = 0.2 and 0.39) and of polygons, every vertex
/// moves by at most a small share of its spacing.
#[test]
fn clean_samples_stay_where_they_are() {
    let mut rng = Rng::new(7);
    let smooth = [
        Ellipse { a: 2.0, b: 1.0 }.dense(4000),
        Star { a: 0.25, k: 5 }.dense(4000),
    ];
    let square = wdm_crust_testkit::DenseCurve::polygon(
        &[[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
        4000,
    );
    let triangle =
        wdm_crust_testkit::DenseCurve::polygon(&[[0.0, 0.0], [3.0, 0.0], [1.0, 2.0]], 4000);
    let mut worst = 0.0f64;
    for (curve, eps, floor) in [
        (&smooth[0], 0.2, 0.0),
        (&smooth[0], 0.39, 0.0),
        (&smooth[1], 0.2, 0.0),
        (&smooth[1], 0.39, 0.0),
        (&square, 0.3, 0.02),
        (&triangle, 0.3, 0.02),
    ] {
        let set = CurveSet::new(vec![curve.clone()]);
        for _ in 0..3 {
            let config = SampleConfig {
                eps,
                min_step_fraction: 0.5,
                lfs_floor: floor * 3.0,
            };
            let sample = set.eps_sample_with(&config, &mut rng);
            let sample = sample
                .transformed(&Similarity::random(&mut rng))
                .shuffled(&mut rng);
            let points = &sample.points;
            let rec = smoothed(points);
            for c in rec.curves() {
                let k = c.points.len();
                let coords = rec.curve_coords(c);
                for (i, (&p, q)) in c.points.iter().zip(&coords).enumerate() {
                    let at = |j: usize| points[c.points[j % k] as usize];
                    let o = points[p as usize];
                    let step = |x: [f64; 2]| (x[0] - o[0]).hypot(x[1] - o[1]);
                    let spacing = step(at(i + 1)).min(step(at(i + k - 1)));
                    worst = worst.max(step(*q) / spacing);
                }
            }
            assert_simple(&rec, "clean");
        }
    }
    assert!(
        worst <= 0.05,
        "a clean vertex moved {worst:.4} of its spacing"
    );
}

/// Polygons with noise keep their corners: the fitted vertex nearest each corner stays
/// within the noise of it (a square, a triangle with a 30° corner).
#[test]
fn noisy_polygons_keep_their_corners() {
    // A triangle with corners of 30°, 75° and 75°.
    let apex = [
        4.0 * 30f64.to_radians().cos(),
        4.0 * 30f64.to_radians().sin(),
    ];
    for (name, corners) in [
        (
            "square",
            vec![[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]],
        ),
        ("30° triangle", vec![[0.0, 0.0], [4.0, 0.0], apex]),
    ] {
        let mut rng = Rng::new(11);
        let perimeter: f64 = (0..corners.len())
            .map(|i| {
                let (a, b): ([f64; 2], [f64; 2]) = (corners[i], corners[(i + 1) % corners.len()]);
                (b[0] - a[0]).hypot(b[1] - a[1])
            })
            .sum();
        let n = 600;
        let spacing = perimeter / n as f64;
        let sigma = 0.3 * spacing;
        let mut points = Vec::new();
        for i in 0..corners.len() {
            let (a, b) = (corners[i], corners[(i + 1) % corners.len()]);
            let length = (b[0] - a[0]).hypot(b[1] - a[1]);
            let m = (length / spacing).round() as usize;
            for k in 0..m {
                let t = k as f64 / m as f64;
                points.push([
                    a[0] + t * (b[0] - a[0]) + sigma * rng.normal(),
                    a[1] + t * (b[1] - a[1]) + sigma * rng.normal(),
                ]);
            }
        }
        let rec = smoothed(&points);
        assert_eq!(rec.curves().len(), 1, "{name}");
        let coords = rec.curve_coords(&rec.curves()[0]);
        for corner in &corners {
            let nearest = coords
                .iter()
                .map(|q| (q[0] - corner[0]).hypot(q[1] - corner[1]))
                .fold(f64::INFINITY, f64::min);
            assert!(
                nearest <= 3.0 * sigma,
                "{name}: corner {corner:?} nearest vertex {nearest:.4} (σ {sigma:.4})"
            );
        }
        assert_simple(&rec, name);
    }
}

/// Every smoothed curve is simple (exact brute force) on random noisy inputs: single
/// curves, nested ones, curves nearly touching each other, a thin U whose arms almost
/// touch, with every algorithm.
#[test]
fn smoothed_curves_are_simple() {
    let mut rng = Rng::new(5);
    let mut cases: Vec<Vec<[f64; 2]>> = Vec::new();
    for round in 0..12 {
        let n = 100 + rng.below(900);
        let sigma = [0.002, 0.01, 0.02][round % 3];
        let mut points = noisy_circle(n, 1.0, sigma, &mut rng);
        match round % 4 {
            // A hole.
            1 => points.extend(noisy_circle(n / 2, 0.5, sigma, &mut rng)),
            // A neighbour a few noise widths away.
            2 => points.extend(
                noisy_circle(n, 1.0, sigma, &mut rng)
                    .into_iter()
                    .map(|[x, y]| [x + 2.0 + 6.0 * sigma, y]),
            ),
            // A thin U: two arms 4σ apart, joined at one end.
            3 => {
                points.clear();
                let gap = 8.0 * sigma.max(0.005);
                for k in 0..n {
                    let t = k as f64 / n as f64;
                    points.push([3.0 * t, sigma * rng.normal()]);
                    points.push([3.0 * t, gap + sigma * rng.normal()]);
                }
                for k in 0..10 {
                    let t = k as f64 / 10.0 * std::f64::consts::PI;
                    let r = gap / 2.0;
                    points.push([-r * t.sin(), r - r * t.cos()]);
                }
            }
            _ => {}
        }
        rng.shuffle(&mut points);
        cases.push(points);
    }
    for (i, points) in cases.iter().enumerate() {
        for algorithm in [Algorithm::Wdm, Algorithm::Crust, Algorithm::NnCrust] {
            let options = Options::new()
                .with_algorithm(algorithm)
                .with_smoothing(true);
            let rec = reconstruct_with(points, &options).unwrap();
            assert_simple(&rec, &format!("case {i}, {}", algorithm.name()));
        }
    }
}

/// The fitted position of every point is the same in any input order and scales exactly
/// with the input by a power of two; without smoothing the coordinates are the input's.
#[test]
fn smoothing_is_independent_of_order_and_scale() {
    let mut rng = Rng::new(9);
    let mut points = noisy_circle(600, 1.0, 0.01, &mut rng);
    points.extend(noisy_circle(300, 0.5, 0.01, &mut rng));
    let rec = smoothed(&points);
    let fitted = |rec: &Reconstruction, i: u32| rec.curve_vertex(i).unwrap();
    let plain = reconstruct_with(&points, &Options::new()).unwrap();
    assert!(!plain.smoothed() && rec.smoothed());
    for i in 0..points.len() as u32 {
        assert_eq!(plain.curve_vertex(i), Some(points[i as usize]));
    }
    // Noise of a spacing: the vertices of the curves (through all the points, or through
    // representatives where the sample is thinned) nearly all move.
    let on_curves: Vec<u32> = rec.curves().iter().flat_map(|c| c.points.clone()).collect();
    let moved = on_curves
        .iter()
        .filter(|&&i| fitted(&rec, i) != points[i as usize])
        .count();
    assert!(
        on_curves.len() >= 100 && 10 * moved > 9 * on_curves.len(),
        "only {moved} of {} moved",
        on_curves.len()
    );
    for round in 0..3 {
        let order = rng.permutation(points.len());
        let shuffled: Vec<[f64; 2]> = order.iter().map(|&i| points[i]).collect();
        let other = smoothed(&shuffled);
        for (j, &i) in order.iter().enumerate() {
            assert_eq!(
                fitted(&other, j as u32),
                fitted(&rec, i as u32),
                "round {round}: point {i}"
            );
        }
    }
    for k in [-600, -40, 3, 500] {
        let factor = 2.0f64.powi(k);
        let scaled: Vec<[f64; 2]> = points.iter().map(|p| p.map(|x| x * factor)).collect();
        let other = smoothed(&scaled);
        for i in 0..points.len() as u32 {
            let expected = fitted(&rec, i).map(|x| x * factor);
            assert_eq!(fitted(&other, i), expected, "2^{k}: point {i}");
        }
    }
}

/// No panic and finite coordinates at the ends of the `f64` range and on degenerate input.
#[test]
fn any_finite_input_is_smoothed_without_panic() {
    let mut rng = Rng::new(3);
    let base = noisy_circle(200, 1.0, 0.02, &mut rng);
    let inputs = [
        base.iter()
            .map(|p| p.map(|x| x * 1e300))
            .collect::<Vec<_>>(),
        base.iter().map(|p| p.map(|x| x * 1e-310)).collect(),
        base.iter().map(|p| [p[0] * 1e-200, p[1] * 1e200]).collect(),
        (0..50).map(|i| [i as f64, 2.0 * i as f64]).collect(),
        vec![[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]],
        vec![
            [f64::MAX, 0.0],
            [-f64::MAX, 0.0],
            [0.0, f64::MAX],
            [0.0, -f64::MAX],
            [1.0, 1.0],
        ],
    ];
    for points in &inputs {
        let rec = smoothed(points);
        for c in rec.curves() {
            assert!(rec.curve_coords(c).iter().flatten().all(|x| x.is_finite()));
        }
    }
}

/// `reconstruct --smooth` writes the library's fitted coordinates in the JSON.
#[test]
fn the_command_line_writes_the_fitted_coordinates() {
    let mut rng = Rng::new(21);
    let points = noisy_circle(500, 1.0, 0.01, &mut rng);
    let text: String = points
        .iter()
        .map(|p| format!("{} {}\n", p[0], p[1]))
        .collect();
    let dir = tempfile::tempdir().unwrap();
    let run = common::run_in(dir.path(), &["reconstruct", "--smooth"], text.as_bytes());
    assert_eq!(run.code, 0, "{}", run.stderr);
    let json: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let rec = smoothed(&points);
    let curves = json["curves"].as_array().unwrap();
    assert_eq!(curves.len(), rec.curves().len());
    for (c, curve) in curves.iter().zip(rec.curves()) {
        let coords: Vec<[f64; 2]> = c["coords"]
            .as_array()
            .unwrap()
            .iter()
            .map(|p| [p[0].as_f64().unwrap(), p[1].as_f64().unwrap()])
            .collect();
        assert_eq!(coords, rec.curve_coords(curve));
        assert_ne!(
            coords,
            curve
                .points
                .iter()
                .map(|&i| points[i as usize])
                .collect::<Vec<_>>()
        );
    }
    // Without the flag: the input points.
    let run = common::run_in(dir.path(), &["reconstruct"], text.as_bytes());
    let json: serde_json::Value = serde_json::from_str(&run.stdout).unwrap();
    let first = &json["curves"][0];
    let i = first["points"][0].as_u64().unwrap() as usize;
    assert_eq!(first["coords"][0][0].as_f64().unwrap(), points[i][0]);
}

/// With smoothing, the pruned medial axis is that of the fitted curves the result returns:
/// every axis vertex is a Voronoi vertex of the fitted curve vertices (its nearest fitted
/// vertices, two or more, are equally far, up to the circumcentre's rounding), not of the
/// noisy samples. Without smoothing the same holds of the samples on the curve.
#[test]
fn the_smoothed_axis_is_that_of_the_fitted_curves() {
    let mut rng = Rng::new(31);
    let sigma = 0.007;
    let points: Vec<[f64; 2]> = (0..600)
        .map(|i| {
            let t = i as f64 / 600.0 * std::f64::consts::TAU;
            [
                2.0 * t.cos() + sigma * rng.normal(),
                t.sin() + sigma * rng.normal(),
            ]
        })
        .collect();
    // The two nearest distances from `v` to `sites`.
    let nearest_two = |v: [f64; 2], sites: &[[f64; 2]]| {
        let (mut d1, mut d2) = (f64::INFINITY, f64::INFINITY);
        for s in sites {
            let d = (s[0] - v[0]).hypot(s[1] - v[1]);
            if d < d1 {
                (d1, d2) = (d, d1);
            } else if d < d2 {
                d2 = d;
            }
        }
        (d1, d2)
    };
    let equidistant = |rec: &Reconstruction, sites: &[[f64; 2]]| {
        let axis = rec.medial_axis();
        assert!(!axis.edges.is_empty(), "no axis");
        axis.vertices.iter().all(|&v| {
            let (d1, d2) = nearest_two(v, sites);
            d2 - d1 <= 1e-9 * d1.max(1.0)
        })
    };
    let plain = reconstruct_with(&points, &Options::new()).unwrap();
    assert_eq!(plain.curves().len(), 1);
    let samples = plain.curve_coords(&plain.curves()[0]);
    assert!(
        equidistant(&plain, &samples),
        "the plain axis is not the samples'"
    );
    let rec = smoothed(&points);
    assert_eq!(rec.curves().len(), 1);
    let fitted = rec.curve_coords(&rec.curves()[0]);
    assert_ne!(fitted, samples);
    assert!(
        equidistant(&rec, &fitted),
        "the smoothed axis is not the fitted curve's"
    );
    assert!(
        !equidistant(&rec, &samples),
        "the smoothed axis is still the samples'"
    );
}
