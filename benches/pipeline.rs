//! Phases of the reconstruction pipeline on curve samples, the fitted (`--smooth`) output on
//! clean samples and on dense noisy bands, the reconstruction of one input at three exact
//! power-of-two scales, the baselines beside WDM, and the exact predicates.
//!
//! `cargo bench --bench pipeline` (filter with e.g. `-- pipeline/`, `-- fitted/`, `-- scaled/`,
//! `-- baselines/` or `-- predicates/`).

mod common;

use common::baselines::{incircle_unguarded, orient_unguarded, robust_incircle, robust_orient};
use common::{band_points, curve_points, sizes, Rng};
use criterion::{criterion_group, criterion_main, BenchmarkId, Criterion, Throughput};
use wdm_crust::predicates::{
    circumcenter, circumcenter_exact, incircle, incircle_added_slack, orient2d,
    orient2d_added_slack,
};
use wdm_crust::reconstruct::wdm::label_vertices;
use wdm_crust::reconstruct::{reconstruct_with, Algorithm, MedialAxisMode, Options};

fn bench_phases(c: &mut Criterion) {
    let mut group = c.benchmark_group("pipeline");
    for n in sizes() {
        group.sample_size(if n >= 100_000 { 10 } else { 30 });
        group.throughput(Throughput::Elements(n as u64));
        let points = curve_points(n, &mut Rng::new(7));
        // The triangulation keeps its points in locality order: the phases below see what
        // `reconstruct` sees.
        let local = wdm_crust::triangulate(&points).expect("valid points");
        let vor = local.voronoi();
        group.bench_with_input(BenchmarkId::new("triangulate", n), &points, |b, p| {
            b.iter(|| wdm_crust::triangulate(p).expect("valid points"))
        });
        group.bench_with_input(BenchmarkId::new("voronoi", n), &local, |b, t| {
            b.iter(|| t.voronoi())
        });
        group.bench_with_input(BenchmarkId::new("label_vertices", n), &vor, |b, v| {
            b.iter(|| label_vertices(v, Default::default()))
        });
        group.bench_with_input(BenchmarkId::new("reconstruct", n), &points, |b, p| {
            b.iter(|| wdm_crust::reconstruct(p).expect("valid points"))
        });
        // The curves alone: what a caller who wants no medial axis pays.
        let curves_only = Options::new().with_medial_axis(MedialAxisMode::Omitted);
        group.bench_with_input(
            BenchmarkId::new("reconstruct_curves", n),
            &points,
            |b, p| b.iter(|| reconstruct_with(p, &curves_only).expect("valid points")),
        );
        // The water flow's result alone, without the open-curve stage: what that stage
        // costs on closed curves.
        let closed_only = Options::new().with_open_curves(false);
        group.bench_with_input(
            BenchmarkId::new("reconstruct_closed_only", n),
            &points,
            |b, p| b.iter(|| reconstruct_with(p, &closed_only).expect("valid points")),
        );
        // The warnings on a result (computed on the first call, so on a fresh copy each
        // time; making the copy and dropping it are not measured).
        let rec = wdm_crust::reconstruct(&points).expect("valid points");
        group.bench_with_input(BenchmarkId::new("warnings", n), &rec, |b, rec| {
            b.iter_batched(
                || rec.clone(),
                |fresh| {
                    let count = fresh.warnings().len();
                    (fresh, count)
                },
                criterion::BatchSize::LargeInput,
            )
        });
    }
    group.finish();
}

/// What the fitted output costs, at 10^5 and 10^6 points: the default reconstruction and the
/// same with smoothing, on the clean curve sample of the phases above and on a dense noisy band
/// around the same curve (σ = 1 % of the diagonal: thinned to representatives first), each
/// beside its own triangulation so that the ratios read off one run.
fn bench_fitted(c: &mut Criterion) {
    let mut group = c.benchmark_group("fitted");
    group.sample_size(10);
    let smoothed = Options::new().with_smoothing(true);
    for n in [100_000, 1_000_000] {
        group.throughput(Throughput::Elements(n as u64));
        let inputs = [
            ("curve", curve_points(n, &mut Rng::new(7))),
            ("band", band_points(n, 0.01, &mut Rng::new(7))),
        ];
        for (name, points) in &inputs {
            group.bench_with_input(
                BenchmarkId::new(format!("{name}/triangulate"), n),
                points,
                |b, p| b.iter(|| wdm_crust::triangulate(p).expect("valid points")),
            );
            group.bench_with_input(
                BenchmarkId::new(format!("{name}/reconstruct"), n),
                points,
                |b, p| b.iter(|| wdm_crust::reconstruct(p).expect("valid points")),
            );
            group.bench_with_input(
                BenchmarkId::new(format!("{name}/reconstruct_smoothed"), n),
                points,
                |b, p| b.iter(|| reconstruct_with(p, &smoothed).expect("valid points")),
            );
        }
    }
    group.finish();
}

/// One curve sample of 10^5 points reconstructed at three scales: as given (every
/// coordinate within the adaptive predicates' range) and times `2^-1060` (subnormal) and
/// `2^1000`, exactly. The two out-of-range inputs run in the same rescaled frame as the one
/// in range, so the three should take the same time.
fn bench_scales(c: &mut Criterion) {
    let mut group = c.benchmark_group("scaled");
    group.sample_size(10);
    let n = 100_000;
    group.throughput(Throughput::Elements(n as u64));
    // On a grid of 2^-14 at radius about 2^8: 22 bits, so that both scalings are exact.
    let snap = |x: f64| (x * 256.0 * 16384.0).round() / 16384.0;
    let points: Vec<[f64; 2]> = curve_points(n, &mut Rng::new(7))
        .into_iter()
        .map(|p| p.map(snap))
        .collect();
    // `x · 2^k` in two halves (2^k itself may be outside the range), exact here.
    let times = |x: f64, k: i32| x * 2f64.powi(k / 2) * 2f64.powi(k - k / 2);
    for k in [0, -1060, 1000] {
        let scaled: Vec<[f64; 2]> = points.iter().map(|p| p.map(|x| times(x, k))).collect();
        assert!(
            scaled
                .iter()
                .zip(&points)
                .all(|(s, p)| s.map(|x| times(x, -k)) == *p),
            "2^{k} is exact"
        );
        group.bench_with_input(
            BenchmarkId::new("reconstruct", format!("2^{k}")),
            &scaled,
            |b, p| b.iter(|| wdm_crust::reconstruct(p).expect("valid points")),
        );
    }
    group.finish();
}

/// The two baselines (the crust of Amenta, Bern and Eppstein, the NN-crust of Dey and Kumar)
/// beside the default WDM reconstruction, each from the points (triangulation included), on
/// the noisy curve sample of the phases above at 10^4 and 10^5 points: the ratios read off
/// one run.
fn bench_baselines(c: &mut Criterion) {
    let mut group = c.benchmark_group("baselines");
    group.sample_size(10);
    for n in [10_000, 100_000] {
        group.throughput(Throughput::Elements(n as u64));
        let points = curve_points(n, &mut Rng::new(7));
        for (name, algorithm) in [
            ("wdm", Algorithm::Wdm),
            ("crust", Algorithm::Crust),
            ("nn_crust", Algorithm::NnCrust),
        ] {
            let options = Options::new().with_algorithm(algorithm);
            group.bench_with_input(BenchmarkId::new(name, n), &points, |b, p| {
                b.iter(|| reconstruct_with(p, &options).expect("valid points"))
            });
        }
    }
    group.finish();
}

/// Batches of 1024 predicate calls: on random points (the floating-point filter decides)
/// and on points a few ulps off a line or circle (the exact arithmetic decides).
fn bench_predicates(c: &mut Criterion) {
    const BATCH: usize = 1024;
    let mut rng = Rng::new(11);
    let random: Vec<[[f64; 2]; 4]> = (0..BATCH)
        .map(|_| [0; 4].map(|_| [rng.uniform(), rng.uniform()]))
        .collect();
    let nudge = |x: f64, k: i64| f64::from_bits((x.to_bits() as i64 + k) as u64);
    let near_line: Vec<[[f64; 2]; 3]> = (0..BATCH)
        .map(|_| {
            let (a, b) = (
                [rng.uniform(), rng.uniform()],
                [rng.uniform(), rng.uniform()],
            );
            let t = rng.uniform();
            let k = (rng.next_u64() % 5) as i64 - 2;
            [
                a,
                b,
                [a[0] + t * (b[0] - a[0]), nudge(a[1] + t * (b[1] - a[1]), k)],
            ]
        })
        .collect();
    let near_circle: Vec<[[f64; 2]; 4]> = (0..BATCH)
        .map(|_| {
            let mut on = || {
                let t = rng.uniform() * std::f64::consts::TAU;
                [t.cos(), t.sin()]
            };
            let (a, b, c, d) = (on(), on(), on(), on());
            let k = (rng.next_u64() % 5) as i64 - 2;
            let (a, b) = if orient2d(a, b, c) == wdm_crust::predicates::Orientation::Clockwise {
                (b, a)
            } else {
                (a, b)
            };
            [a, b, c, [d[0], nudge(d[1], k)]]
        })
        .collect();
    let thin = thin_triangles(&mut rng, BATCH);
    let mut group = c.benchmark_group("predicates");
    group.throughput(Throughput::Elements(BATCH as u64));
    group.bench_function("orient2d/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| orient2d(p[0], p[1], p[2]) as u8 == 0)
                .count()
        })
    });
    // The filter as it was: the underflow term added to the bound (same answers).
    group.bench_function("orient2d_added_slack/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| orient2d_added_slack(p[0], p[1], p[2]) as u8 == 0)
                .count()
        })
    });
    // The peer: the `robust` crate's adaptive predicate, which the public `orient2d` called
    // before it accepted every finite input (exact only inside `robust`'s exponent range).
    group.bench_function("orient2d_robust_crate/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| robust_orient(p[0], p[1], p[2]) == 0.0)
                .count()
        })
    });
    group.bench_function("orient2d_unguarded/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| orient_unguarded(p[0], p[1], p[2]) == 0)
                .count()
        })
    });
    group.bench_function("orient2d/near_collinear", |b| {
        b.iter(|| {
            near_line
                .iter()
                .filter(|p| orient2d(p[0], p[1], p[2]) as u8 == 0)
                .count()
        })
    });
    group.bench_function("incircle/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| incircle(p[0], p[1], p[2], p[3]) as u8 == 0)
                .count()
        })
    });
    group.bench_function("incircle_added_slack/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| incircle_added_slack(p[0], p[1], p[2], p[3]) as u8 == 0)
                .count()
        })
    });
    group.bench_function("incircle_robust_crate/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| robust_incircle(p[0], p[1], p[2], p[3]) == 0.0)
                .count()
        })
    });
    group.bench_function("incircle_unguarded/random", |b| {
        b.iter(|| {
            random
                .iter()
                .filter(|p| incircle_unguarded(p[0], p[1], p[2], p[3]) == 0)
                .count()
        })
    });
    group.bench_function("incircle/near_cocircular", |b| {
        b.iter(|| {
            near_circle
                .iter()
                .filter(|p| incircle(p[0], p[1], p[2], p[3]) as u8 == 0)
                .count()
        })
    });
    // Thin triangles, where the circumcenter's `f64` filter fails: the construction as the
    // Voronoi vertices use it, and beside it the exact construction correctly rounded (the
    // `BigInt` path such triangles took before the double-word stage).
    group.bench_function("circumcenter/thin", |b| {
        b.iter(|| {
            thin.iter()
                .filter_map(|t| circumcenter(t[0], t[1], t[2]))
                .fold(0.0, |s, o| s + o[0])
        })
    });
    group.bench_function("circumcenter_exact_rounded/thin", |b| {
        b.iter(|| {
            thin.iter()
                .filter_map(|t| circumcenter_exact(t[0], t[1], t[2]))
                .fold(0.0, |s, o| s + o.to_f64()[0])
        })
    });
    group.finish();
}

/// Three consecutive samples of a curve of radius about 1 with spacing about 1e-6, bent by an
/// angle log-uniform in [1e-9, 1e-4]: nearly collinear, like the triangles of noisy curve
/// samples on which the circumcenter's `f64` filter fails.
fn thin_triangles(rng: &mut Rng, n: usize) -> Vec<[[f64; 2]; 3]> {
    (0..n)
        .map(|_| {
            let at = rng.uniform() * std::f64::consts::TAU;
            let a = [at.cos(), at.sin()];
            let dir = at + std::f64::consts::FRAC_PI_2;
            let h = 1e-6 * (1.0 + rng.uniform());
            let bend = 10f64.powf(-9.0 + 5.0 * rng.uniform());
            let step = |angle: f64, len: f64| [a[0] + len * angle.cos(), a[1] + len * angle.sin()];
            [a, step(dir, h), step(dir + bend, 2.0 * h)]
        })
        .collect()
}

criterion_group!(
    benches,
    bench_phases,
    bench_fitted,
    bench_scales,
    bench_baselines,
    bench_predicates
);
criterion_main!(benches);
