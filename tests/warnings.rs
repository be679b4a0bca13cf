//! The warnings on a reconstruction: each one speaks on the input that shows its problem,
//! and none speaks on clean samples, the bundled examples and the real sets whose result is
//! right; warnings depend neither on the input order nor on an exact power-of-two scale.

use std::collections::BTreeSet;
use std::f64::consts::TAU;
use std::path::PathBuf;

use wdm_crust::reconstruct::{reconstruct_with, Options};
use wdm_crust::{reconstruct, Reconstruction, WarningCode};
use wdm_crust_testkit::{ClosedCurve, CurveSet, DenseCurve, Ellipse, Peanut, Rng, Star};

fn codes(rec: &Reconstruction) -> Vec<WarningCode> {
    rec.warnings().iter().map(|w| w.code).collect()
}

fn circle(centre: [f64; 2], r: f64, n: usize) -> Vec<[f64; 2]> {
    (0..n)
        .map(|k| {
            let t = k as f64 * TAU / n as f64;
            [centre[0] + r * t.cos(), centre[1] + r * t.sin()]
        })
        .collect()
}

fn uniform(n: usize, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = Rng::new(seed);
    (0..n).map(|_| [rng.f64(), rng.f64()]).collect()
}

fn data(path: &str) -> Vec<[f64; 2]> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(path);
    wdm_crust::io::read_points_from_path(&path).unwrap()
}

#[test]
fn clean_samples_give_no_warning() {
    let shapes: Vec<DenseCurve> = vec![
        Ellipse { a: 2.0, b: 1.0 }.dense(4000),
        Peanut { a: 0.3, b: 0.15 }.dense(4000),
        Star { a: 0.25, k: 5 }.dense(4000),
    ];
    for (s, shape) in shapes.into_iter().enumerate() {
        for (e, &eps) in [0.2, 0.5, 1.0].iter().enumerate() {
            let mut rng = Rng::new(40 + 10 * s as u64 + e as u64);
            let sample = CurveSet::new(vec![shape.clone()]).eps_sample(eps, &mut rng);
            let rec = reconstruct(&sample.points).unwrap();
            assert!(
                rec.warnings().is_empty(),
                "shape {s}, ε = {eps}: {:?}",
                rec.warnings()
            );
        }
    }
    // Open arcs, a polyline with corners, two circles three spacings apart.
    let arc: Vec<[f64; 2]> = (0..120)
        .map(|k| {
            let t = k as f64 / 119.0 * 4.0;
            [t.cos(), t.sin()]
        })
        .collect();
    let polyline = DenseCurve::polyline(
        &[[0.0, 0.0], [4.0, 0.0], [4.0, 3.0], [7.0, 1.0]],
        false,
        160,
    )
    .points;
    let step = TAU / 200.0;
    let mut two = circle([0.0, 0.0], 1.0, 200);
    two.extend(circle([2.0 + 3.0 * step, 0.0], 1.0, 200));
    for (name, points) in [("arc", arc), ("polyline", polyline), ("two circles", two)] {
        let rec = reconstruct(&points).unwrap();
        assert!(rec.warnings().is_empty(), "{name}: {:?}", rec.warnings());
    }
}

#[test]
fn clean_curves_at_random_positions_give_no_warning() {
    // Uniformly random positions along a 5-lobed star: somewhere a gap several mean steps
    // long lies beside four short ones, about once in 200 edges. Such gaps are the curve,
    // not chords: they were warned `long-edge` at 56 edges here.
    for (seed, n) in [(61, 30_000), (62, 8000)] {
        let mut rng = Rng::new(seed);
        let points: Vec<[f64; 2]> = (0..n)
            .map(|_| {
                let t = rng.range(0.0, TAU);
                let r = 1.0 + 0.3 * (5.0 * t).cos();
                [r * t.cos(), r * t.sin()]
            })
            .collect();
        let rec = reconstruct(&points).unwrap();
        assert_eq!(rec.curves().len(), 1, "{n} points");
        assert!(rec.curves()[0].closed);
        assert!(
            rec.warnings().is_empty(),
            "{n} points: {:?}",
            rec.warnings()
        );
    }
}

#[test]
fn bundled_examples_and_well_sampled_real_sets_give_no_warning() {
    for path in [
        "examples/data/bean.txt",
        "examples/data/mushroom.p2d",
        "examples/data/crocodile-conf.p2d",
        "examples/data/Circle0.txt",
        "examples/data/apple_2percent_noise.txt",
        "tests/data/stretchdenoise/data/drill.txt",
        "tests/data/stretchdenoise/data/vase.txt",
        "tests/data/stretchdenoise/data/thing.txt",
        "tests/data/fitconnect/data/butterfly_2percent_noise.txt",
        "tests/data/fitconnect/data/Mouse0.txt",
    ] {
        let rec = reconstruct(&data(path)).unwrap();
        assert!(rec.warnings().is_empty(), "{path}: {:?}", rec.warnings());
    }
}

/// A uniform scatter is called a scatter. A lattice is warned about too: its rows lie one
/// spacing apart, and it reads as nested square rings (the passes for clean loops beside
/// curves take the rings between those peeling takes) that pass within the spacing of each
/// other, or where the rings stay unassigned, as a scatter. In a scatter the edge warnings
/// say nothing more and stay quiet.
#[test]
fn a_uniform_scatter_is_called_a_scatter_and_a_lattice_is_warned() {
    let rec = reconstruct(&uniform(1000, 7)).unwrap();
    let found = codes(&rec);
    assert!(found.contains(&WarningCode::MostUnassigned), "{found:?}");
    assert!(found.contains(&WarningCode::Scatter), "{found:?}");
    assert!(found.iter().all(|c| matches!(
        c,
        WarningCode::MostUnassigned | WarningCode::Scatter | WarningCode::PeelingBudget
    )));
    let grid: Vec<[f64; 2]> = (0..30)
        .flat_map(|i| (0..30).map(move |j| [i as f64, j as f64]))
        .collect();
    let rec = reconstruct(&grid).unwrap();
    let found = codes(&rec);
    assert!(
        found.contains(&WarningCode::Scatter) || found.contains(&WarningCode::CurvesTooClose),
        "{:?}",
        rec.warnings()
    );
}

/// A band many spacings wide, reconstructed as it is (thinning off): most of its points are
/// on no curve, and the warning says so. The default thins it to one loop through its
/// middle, and then nothing is to be said about the unassigned points.
#[test]
fn a_wide_band_of_noise_leaves_most_points_unassigned_and_says_so() {
    let mut rng = Rng::new(3);
    let band: Vec<[f64; 2]> = (0..6000)
        .map(|_| {
            let t = rng.f64() * TAU;
            let r = 1.0 + 0.1 * rng.normal();
            [r * t.cos(), r * t.sin()]
        })
        .collect();
    let thinned = reconstruct(&band).unwrap();
    assert!(thinned.thinned().is_some());
    assert_eq!(thinned.curves().len(), 1);
    assert!(thinned.curves()[0].closed);
    assert!(
        !codes(&thinned).contains(&WarningCode::MostUnassigned),
        "{:?}",
        thinned.warnings()
    );
    let rec = reconstruct_with(&band, &Options::new().with_thinning(false)).unwrap();
    assert!(2 * rec.unassigned().len() > band.len());
    let found = codes(&rec);
    assert_eq!(
        found.first(),
        Some(&WarningCode::MostUnassigned),
        "{found:?}"
    );
    let message = &rec.warnings()[0].message;
    assert!(
        message.contains(&format!("{} of 6000 points", rec.unassigned().len())),
        "{message}"
    );
}

#[test]
fn no_curve_at_all_is_said() {
    // Three points of a triangle: too few for a loop, no chain between them.
    let points = [[0.0, 0.5], [1.0, 0.33], [2.0, 1.45]];
    let rec = reconstruct(&points).unwrap();
    assert!(rec.curves().is_empty(), "{:?}", rec.curves());
    assert_eq!(codes(&rec), [WarningCode::MostUnassigned]);
    assert!(rec.warnings()[0].message.starts_with("no curve"));
    // Fewer than three distinct points: nothing to say.
    let rec = reconstruct(&[[0.0, 0.0], [1.0, 0.0], [1.0, 0.0]]).unwrap();
    assert!(rec.warnings().is_empty());
}

#[test]
fn two_circles_one_spacing_apart_are_too_close() {
    let n = 200;
    let step = TAU / n as f64;
    let mut points = circle([0.0, 0.0], 1.0, n);
    points.extend(circle([2.0 + step, 0.0], 1.0, n));
    let rec = reconstruct(&points).unwrap();
    let warning = rec
        .warnings()
        .iter()
        .find(|w| w.code == WarningCode::CurvesTooClose)
        .unwrap_or_else(|| panic!("{:?}", rec.warnings()));
    // The points named are a pair of Delaunay neighbours from the two sides of the pinch:
    // within one spacing of each other, near the gap at x = 1.
    let [i, j] = [warning.points[0] as usize, warning.points[1] as usize];
    let d = ((points[i][0] - points[j][0]).powi(2) + (points[i][1] - points[j][1]).powi(2)).sqrt();
    assert!(d <= 1.01 * step, "{d}");
    assert!((points[i][0] - 1.0).abs() < 4.0 * step, "{:?}", points[i]);
}

/// `n` points evenly spaced along the closed polygon `corners`, the first `phase` of a step
/// past the first corner: unlike `DenseCurve::polyline`, the corners need not be samples.
fn around(corners: &[[f64; 2]], n: usize, phase: f64) -> Vec<[f64; 2]> {
    let k = corners.len();
    let length = |i: usize| {
        let (a, b) = (corners[i], corners[(i + 1) % k]);
        (b[0] - a[0]).hypot(b[1] - a[1])
    };
    let total: f64 = (0..k).map(length).sum();
    (0..n)
        .map(|j| {
            let mut t = (j as f64 + phase) * total / n as f64;
            let mut i = 0;
            while t > length(i) && i + 1 < k {
                t -= length(i);
                i += 1;
            }
            let (a, b) = (corners[i], corners[(i + 1) % k]);
            let u = t / length(i);
            [a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])]
        })
        .collect()
}

#[test]
fn squares_a_few_spacings_apart_come_back_as_they_are_or_say_so() {
    // Two unit squares side by side, 2 to 6 spacings apart, the second shifted up: the
    // water reaches a wall point just past a convex corner from around the corner first, and
    // its transition can close the corridor between the squares at that corner. The result
    // is then two closed curves, but the outer envelope of both squares and a loop around
    // the corridor, with the wall samples at the plug on no curve, until the facing-corner
    // swap splits them again. Either the squares come back exactly or `curves-too-close`
    // says where.
    let s = 0.05;
    for (k, (gap, shift)) in [
        (2.0, 0.31),
        (3.0, 0.35),
        (3.0, -0.22),
        (4.0, 0.41),
        (6.0, 0.13),
    ]
    .into_iter()
    .enumerate()
    {
        let x = 1.0 + gap * s;
        let a = around(&[[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]], 80, 0.3);
        let b = around(
            &[
                [x, shift],
                [x + 1.0, shift],
                [x + 1.0, 1.0 + shift],
                [x, 1.0 + shift],
            ],
            80,
            0.7,
        );
        let mut truth: BTreeSet<[u32; 2]> = BTreeSet::new();
        for (offset, m) in [(0u32, a.len() as u32), (a.len() as u32, b.len() as u32)] {
            for i in 0..m {
                let (p, q) = (offset + i, offset + (i + 1) % m);
                truth.insert([p.min(q), p.max(q)]);
            }
        }
        let points: Vec<[f64; 2]> = a.into_iter().chain(b).collect();
        let rec = reconstruct(&points).unwrap();
        let edges: BTreeSet<[u32; 2]> = rec.edges().iter().copied().collect();
        if edges != truth {
            assert!(
                codes(&rec).contains(&WarningCode::CurvesTooClose),
                "case {k}: wrong and silent"
            );
        }
    }
    // The facing-corner swap now makes every case here exact (`tests/reconstruct.rs` pins
    // that on more shapes); the warning stays for what it misses.
}

#[test]
fn a_chord_across_an_open_curve_is_a_long_edge() {
    // A parabola without the open-curve stage: the water flow closes it by a chord.
    let parabola: Vec<[f64; 2]> = (-100..100)
        .map(|k| {
            let x = k as f64 / 100.0;
            [x, x * x]
        })
        .collect();
    let flow_only = Options::new().with_open_curves(false);
    let rec = reconstruct_with(&parabola, &flow_only).unwrap();
    assert!(
        rec.curves().iter().any(|c| c.closed),
        "the flow closes the parabola"
    );
    let found = codes(&rec);
    assert!(
        found.contains(&WarningCode::LongEdge) || found.contains(&WarningCode::LoopAcrossGap),
        "{found:?}"
    );
    // The default opens it: one chain, nothing to say.
    let rec = reconstruct(&parabola).unwrap();
    assert_eq!(rec.curves().len(), 1);
    assert!(!rec.curves()[0].closed);
    assert!(rec.warnings().is_empty(), "{:?}", rec.warnings());
}

#[test]
fn a_loop_closed_across_a_short_gap_is_named() {
    // A 355° arc of 300 points: its two ends about 4 steps apart. The water flow alone closes
    // it; its closing edge is alone in its length, and the warning names the arc's two ends.
    let n = 300;
    let arc: Vec<[f64; 2]> = (0..n)
        .map(|k| {
            let t = k as f64 / (n - 1) as f64 * 355f64.to_radians();
            [t.cos(), t.sin()]
        })
        .collect();
    let flow_only = Options::new().with_open_curves(false);
    let rec = reconstruct_with(&arc, &flow_only).unwrap();
    assert!(
        rec.curves().len() == 1 && rec.curves()[0].closed,
        "{:?}",
        rec.curves()
    );
    {
        let warning = rec
            .warnings()
            .iter()
            .find(|w| w.code == WarningCode::LoopAcrossGap)
            .unwrap_or_else(|| panic!("{:?}", rec.warnings()));
        let mut ends = warning.points.clone();
        ends.sort_unstable();
        assert_eq!(ends, [0, n as u32 - 1]);
    }
    // The default opens the loop at that edge: one chain from end to end, nothing to say.
    let rec = reconstruct(&arc).unwrap();
    assert_eq!(rec.curves().len(), 1, "{:?}", rec.curves());
    let chain = &rec.curves()[0];
    assert!(!chain.closed);
    let mut ends = [chain.points[0], *chain.points.last().unwrap()];
    ends.sort_unstable();
    assert_eq!(ends, [0, n as u32 - 1]);
    assert_eq!(chain.points.len(), n);
    assert!(rec.warnings().is_empty(), "{:?}", rec.warnings());
}

#[test]
fn chains_ending_close_together_are_named() {
    // One noisy open polyline that the default breaks into two chains.
    let points = data("tests/data/regressions/noisy-polyline-broken-in-two.txt");
    let rec = reconstruct(&points).unwrap();
    assert_eq!(rec.curves().len(), 2, "{:?}", rec.curves());
    let warning = rec
        .warnings()
        .iter()
        .find(|w| w.code == WarningCode::ChainEndsClose)
        .unwrap_or_else(|| panic!("{:?}", rec.warnings()));
    // The points named are an end of each chain.
    let ends: Vec<[u32; 2]> = rec
        .curves()
        .iter()
        .map(|c| [c.points[0], *c.points.last().unwrap()])
        .collect();
    let [i, j] = [warning.points[0], warning.points[1]];
    assert!(
        (ends[0].contains(&i) && ends[1].contains(&j))
            || (ends[0].contains(&j) && ends[1].contains(&i)),
        "{:?} {ends:?}",
        warning.points
    );
}

#[test]
fn separate_strokes_do_not_say_their_ends_are_close() {
    // An ellipse with one to three arcs around it at radii half a unit apart, clean and with
    // noise of 0.3 steps: whenever the result has the right loops and chains, no two chains
    // are said to end close together.
    let mut rng = Rng::new(31);
    let mut right = 0;
    for trial in 0..60 {
        let mut pieces = vec![Ellipse {
            a: 1.0,
            b: rng.range(0.5, 1.0),
        }
        .dense(60 + rng.below(100))];
        for k in 0..1 + rng.below(3) {
            let a0 = rng.range(0.0, TAU);
            let r = 1.6 + 0.5 * k as f64;
            let span = rng.range(0.5, 2.5);
            let n = 20 + rng.below(60);
            let arc: Vec<[f64; 2]> = (0..n)
                .map(|i| {
                    let t = a0 + span * i as f64 / (n - 1) as f64;
                    [r * t.cos(), r * t.sin()]
                })
                .collect();
            pieces.push(DenseCurve::from_points(&arc, false, &[]));
        }
        let noise = if trial % 2 == 0 { 0.0 } else { 0.3 };
        let mut points = Vec::new();
        for piece in &pieces {
            let steps = piece.points.len() - usize::from(!piece.closed);
            let step = piece.length() / steps as f64;
            points.extend(piece.points.iter().map(|p| {
                [
                    p[0] + noise * step * rng.normal(),
                    p[1] + noise * step * rng.normal(),
                ]
            }));
        }
        rng.shuffle(&mut points);
        let rec = reconstruct(&points).unwrap();
        let closed = rec.curves().iter().filter(|c| c.closed).count();
        if closed == 1 && rec.curves().len() == pieces.len() {
            right += 1;
            assert!(
                !codes(&rec).contains(&WarningCode::ChainEndsClose),
                "trial {trial}: {:?}",
                rec.warnings()
            );
        }
    }
    assert!(right >= 45, "{right} of 60 right");
}

#[test]
fn a_spent_peeling_budget_is_a_warning() {
    let rings: Vec<[f64; 2]> = (1..=12)
        .flat_map(|r| circle([0.0, 0.0], r as f64, 200))
        .collect();
    let rec = reconstruct_with(&rings, &Options::new().with_peeling_budget(1)).unwrap();
    assert!(rec.peeling_budget_exhausted());
    assert!(
        codes(&rec).contains(&WarningCode::PeelingBudget),
        "{:?}",
        rec.warnings()
    );
    let rec = reconstruct_with(&rings, &Options::new().with_peeling_budget(100)).unwrap();
    assert!(!codes(&rec).contains(&WarningCode::PeelingBudget));
}

#[test]
fn warnings_do_not_depend_on_order_or_scale() {
    let mut rng = Rng::new(11);
    let n = 200;
    let step = TAU / n as f64;
    let mut inputs = vec![uniform(500, 5)];
    let mut pinch = circle([0.0, 0.0], 1.0, n);
    pinch.extend(circle([2.0 + step, 0.0], 1.0, n));
    inputs.push(pinch);
    for points in inputs {
        let rec = reconstruct(&points).unwrap();
        let order = rng.permutation(points.len());
        let permuted: Vec<[f64; 2]> = order.iter().map(|&i| points[i]).collect();
        let other = reconstruct(&permuted).unwrap();
        assert_eq!(codes(&rec), codes(&other));
        for scale in [2f64.powi(-600), 2f64.powi(600)] {
            let scaled: Vec<[f64; 2]> = points
                .iter()
                .map(|p| [p[0] * scale, p[1] * scale])
                .collect();
            let other = reconstruct(&scaled).unwrap();
            assert_eq!(codes(&rec), codes(&other), "scale {scale:e}");
            let same_points = rec
                .warnings()
                .iter()
                .zip(other.warnings())
                .all(|(a, b)| a.points == b.points);
            assert!(same_points);
        }
    }
}

#[test]
fn codes_are_stable_names() {
    let names: Vec<&str> = WarningCode::ALL.iter().map(|c| c.name()).collect();
    assert_eq!(
        names,
        [
            "most-unassigned",
            "scatter",
            "long-edge",
            "loop-across-gap",
            "chain-ends-close",
            "curves-too-close",
            "peeling-budget"
        ]
    );
}

#[test]
fn an_open_curve_broken_at_a_random_gap_is_warned() {
    // 3 000 to 5 000 points at random positions along a 270° arc, noise of a tenth of the
    // mean step: the largest gaps between neighbours are 7–9 mean steps, and where the
    // open-curve stage leaves the arc in two or three chains they end about as far apart as
    // the longest steps the chains span, far more than 4× the steps at their ends. Such a
    // result came back without a warning; the chains' longest edges now tell.
    let mut broken = 0;
    for seed in 0..24u64 {
        let mut rng = Rng::new(900 + seed);
        let n = 3000 + 1000 * (seed as usize % 3);
        let spacing = 0.75 * TAU / n as f64;
        let points: Vec<[f64; 2]> = (0..n)
            .map(|_| {
                let t = rng.range(0.0, 0.75 * TAU);
                [
                    t.cos() + 0.1 * spacing * rng.normal(),
                    t.sin() + 0.1 * spacing * rng.normal(),
                ]
            })
            .collect();
        let rec = reconstruct(&points).unwrap();
        if rec.curves().len() > 1 {
            broken += 1;
            assert!(
                codes(&rec).contains(&WarningCode::ChainEndsClose),
                "seed {seed}: {} pieces, warnings {:?}",
                rec.curves().len(),
                codes(&rec)
            );
        }
    }
    assert!(broken > 0, "no arc broke: the test exercises nothing");
}
